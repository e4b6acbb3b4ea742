// Polygon triangulation without zero-area triangles and the flips that remove zero-area
// triangles made by MeshLab's fans (core/triangulate.h), and the scale-robust working frame
// (core/working_frame.h), issue 14.
#include "errors.h"
#include "mesh_check.h"
#include "metrics.h"
#include "test_meshes.h"
#include "triangulate.h"
#include "working_frame.h"

#include <gtest/gtest.h>

#include <limits>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace fieldcvt {
namespace {

//! 0, 1, ..., n - 1: a polygon whose corners are the points in order.
std::vector<int> allCorners(std::size_t n)
{
    std::vector<int> corners(n);
    std::iota(corners.begin(), corners.end(), 0);
    return corners;
}

//! The polygon through `points` in order, its triangles appended to `faces`.
PolygonShape triangulateInOrder(const std::vector<Vec3>& points, std::vector<Face>& faces)
{
    return triangulatePolygon(points, allCorners(points.size()), faces);
}

std::vector<Face> triangulate(const std::vector<Vec3>& points)
{
    std::vector<Face> faces;
    triangulateInOrder(points, faces);
    return faces;
}

//! Every triangle of non-zero area, oriented like the polygon (normal +z), areas summing to `area`.
void expectGoodTriangulation(const std::vector<Vec3>& points, double area)
{
    const std::vector<Face> faces = triangulate(points);
    ASSERT_EQ(faces.size(), points.size() - 2);
    double sum = 0;
    for (const Face& t : faces) {
        const Vec3 n = (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]);
        EXPECT_GT(n.z(), 1e-9) << t[0] << " " << t[1] << " " << t[2];
        sum += 0.5 * n.norm();
    }
    EXPECT_NEAR(sum, area, 1e-12);
}

TEST(Triangulate, ConvexPolygonGetsTheFanFromItsFirstCorner)
{
    const std::vector<Vec3> pentagon = {{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {1, 2, 0}, {-1, 1, 0}};
    EXPECT_EQ(triangulate(pentagon), (std::vector<Face>{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
}

TEST(Triangulate, StraightCornersMakeNoZeroAreaTriangle)
{
    // Vertices on the square's edges, next to the first corner and opposite it.
    expectGoodTriangulation({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 2, 0}, {0, 2, 0}}, 4);
    expectGoodTriangulation({{0, 0, 0}, {0.5, 0, 0}, {1, 0, 0}, {1.5, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {0, 0.5, 0}}, 2);
    // The same at 1e300 (no overflow in the plane's orientation tests).
    std::vector<Vec3> huge = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 2, 0}, {0, 2, 0}};
    for (Vec3& p : huge) p *= 1e300;
    for (const Face& t : triangulate(huge))
        EXPECT_GT(triangleArea(huge[t[0]], huge[t[1]], huge[t[2]]), 1e300);  // the area overflows: inf, never 0
}

TEST(Triangulate, NonConvexPolygonStaysInside)
{
    // An L whose first corner is reflex: a fan from it would cover the notch.
    expectGoodTriangulation({{1, 1, 0}, {1, 2, 0}, {0, 2, 0}, {0, 0, 0}, {2, 0, 0}, {2, 1, 0}}, 3);
}

//! The shoelace area of a polygon in the z = 0 plane (positive counter-clockwise).
double shoelace(const std::vector<Vec3>& p)
{
    double twice = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Vec3 &a = p[i], &b = p[(i + 1) % p.size()];
        twice += a.x() * b.y() - a.y() * b.x();
    }
    return 0.5 * twice;
}

//! Triangulated as simple: n - 2 triangles, none reversed or of zero area, no overlap (their
//! areas add up to the polygon's), every corner used.
void expectSimpleTriangulation(const std::vector<Vec3>& points)
{
    std::vector<Face> faces;
    ASSERT_EQ(triangulateInOrder(points, faces), PolygonShape::Simple);
    ASSERT_EQ(faces.size(), points.size() - 2);
    double sum = 0;
    int reversed = 0;
    for (const Face& t : faces) {
        const double z = (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]).z();
        reversed += !(z > 0);
        sum += 0.5 * std::abs(z);
    }
    EXPECT_EQ(reversed, 0);
    EXPECT_NEAR(sum, shoelace(points), 1e-9 * shoelace(points));
}

//! The issue-30 C: an annulus cut open, outer radius 1 and inner radius exactly 0.5, corners every
//! 20 degrees: its reflex corners lie on diagonals between others (to rounding).
std::vector<Vec3> cShape(int step = 20)
{
    std::vector<Vec3> p;
    for (int deg = 0; deg <= 300; deg += step) p.push_back({std::cos(deg * M_PI / 180), std::sin(deg * M_PI / 180), 0});
    for (int deg = 300; deg >= 0; deg -= step)
        p.push_back({0.5 * std::cos(deg * M_PI / 180), 0.5 * std::sin(deg * M_PI / 180), 0});
    return p;
}

TEST(Triangulate, ReflexCornersOnDiagonalsFoldNothing)
{
    const std::vector<Vec3> c = cShape();
    ASSERT_EQ(c.size(), 32u);
    // 15 steps of 20 degrees between the chords of radius 1 and 0.5: the 1.92.
    EXPECT_NEAR(shoelace(c), 15 * 0.5 * std::sin(20 * M_PI / 180) * 0.75, 1e-12);
    expectSimpleTriangulation(c);
    // Many corners: past ear clipping, the constrained Delaunay triangulation.
    expectSimpleTriangulation(cShape(2));
}

TEST(Triangulate, ConcavePolygonsOfAnySizeTriangulateWithoutOverlap)
{
    // A cap of 300 corners with 150 spikes inward (every other corner reflex): fanned before.
    for (int n : {20, 300, 100000}) {
        std::vector<Vec3> star;
        for (int i = 0; i < n; ++i) {
            const double a = 2 * M_PI * i / n, r = i % 2 ? 0.6 : 1.0;
            star.push_back({r * std::cos(a), r * std::sin(a), 0});
        }
        expectSimpleTriangulation(star);
    }
    // A comb: 200 long thin teeth over a base, each gap a deep concavity.
    std::vector<Vec3> comb{{-1, -1, 0}, {201, -1, 0}, {201, 0, 0}};
    for (int t = 199; t >= 0; --t)
        for (const Vec3& c : {Vec3(t + 0.75, 0, 0), Vec3(t + 0.75, 10, 0), Vec3(t + 0.25, 10, 0), Vec3(t + 0.25, 0, 0)})
            comb.push_back(c);
    comb.push_back({-1, 0, 0});
    expectSimpleTriangulation(comb);
}

TEST(Triangulate, RandomStarShapedPolygonsAddUpToTheirArea)
{
    std::mt19937 rng(30);
    std::uniform_real_distribution<double> radius(0.05, 1.0);
    for (int n : {5, 17, 64, 65, 500}) {
        for (int trial = 0; trial < 20; ++trial) {
            std::vector<Vec3> p;
            for (int i = 0; i < n; ++i) {
                const double a = 2 * M_PI * i / n, r = radius(rng);
                p.push_back({r * std::cos(a), r * std::sin(a), 0});
            }
            expectSimpleTriangulation(p);
        }
    }
}

TEST(Triangulate, SelfIntersectingPolygonsAreSaidAndStillTriangulated)
{
    for (const std::vector<Vec3>& bad :
         std::vector<std::vector<Vec3>>{{{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}},                // a bow tie
                                        {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 0, 0}, {0, 2, 0}},     // a corner on another edge
                                        {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {0, 1, 0}}}) {  // a repeated corner
        std::vector<Face> faces;
        EXPECT_EQ(triangulateInOrder(bad, faces), PolygonShape::NotSimple);
        EXPECT_EQ(faces.size(), bad.size() - 2);
    }
    // Large: a star of 1000 corners whose last corner crosses to the other side.
    std::vector<Vec3> star;
    for (int i = 0; i < 1000; ++i) star.push_back({std::cos(2 * M_PI * i / 1000), std::sin(2 * M_PI * i / 1000), 0});
    std::swap(star[10], star[500]);
    std::vector<Face> faces;
    EXPECT_EQ(triangulateInOrder(star, faces), PolygonShape::NotSimple);
    EXPECT_EQ(faces.size(), star.size() - 2);
}

TEST(Triangulate, SpiralOfAHundredThousandCornersTriangulatesWithoutOverlap)
{
    // A strip wound 10 times (arms 1 apart, 0.5 wide): every corner sees only a thin channel.
    constexpr int kArm = 50000;
    constexpr double kTurns = 10;
    std::vector<Vec3> spiral;
    for (int i = 0; i < kArm; ++i) {
        const double a = 2 * M_PI * kTurns * i / (kArm - 1), r = 1 + a / (2 * M_PI);
        spiral.push_back({r * std::cos(a), r * std::sin(a), 0});
    }
    for (int i = kArm - 1; i >= 0; --i) {
        const double a = 2 * M_PI * kTurns * i / (kArm - 1), r = 0.5 + a / (2 * M_PI);
        spiral.push_back({r * std::cos(a), r * std::sin(a), 0});
    }
    ASSERT_GT(shoelace(spiral), 0);
    expectSimpleTriangulation(spiral);
}

TEST(Triangulate, StraightCornersOfLargePolygonsMakeNoZeroAreaTriangle)
{
    // An L of 420 corners, most of them straight (70 along each of its six sides), and a comb's base
    // with 50 straight corners between each pair of teeth.
    std::vector<Vec3> l;
    const Vec3 ends[6] = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
    for (int side = 0; side < 6; ++side)
        for (int k = 0; k < 70; ++k) l.push_back(ends[side] + (ends[(side + 1) % 6] - ends[side]) * (k / 70.0));
    expectSimpleTriangulation(l);  // reversed counts zero-area triangles too
    std::vector<Vec3> comb{{-1, -1, 0}, {21, -1, 0}, {21, 0, 0}};
    for (int t = 19; t >= 0; --t) {
        for (const Vec3& c : {Vec3(t + 0.75, 0, 0), Vec3(t + 0.75, 10, 0), Vec3(t + 0.25, 10, 0), Vec3(t + 0.25, 0, 0)})
            comb.push_back(c);
        for (int k = 1; k < 50; ++k) comb.push_back({t + 0.25 - 0.5 * k / 50, 0, 0});
    }
    comb.push_back({-1, 0, 0});
    expectSimpleTriangulation(comb);
}

TEST(Triangulate, CornersAreKeptByIndexEvenAtRepeatedPositions)
{
    // A 100-corner C whose corners are the second copies of an unwelded point list, in reverse
    // storage order: the triangles name exactly the given indices.
    const std::vector<Vec3> c = cShape(4);
    const int n = static_cast<int>(c.size());
    std::vector<Vec3> points(2 * n);
    std::vector<int> corners(n);
    for (int i = 0; i < n; ++i) {
        points[n - 1 - i] = c[i];
        points[2 * n - 1 - i] = c[i];
        corners[i] = 2 * n - 1 - i;
    }
    for (int small : {0, 1}) {
        std::vector<int> used = corners;
        std::vector<Vec3> polygonPoints = c;
        if (small) {  // the 32-gon by ear clipping too
            const std::vector<Vec3> c32 = cShape();
            used.assign(corners.begin(), corners.begin() + 32);
            for (int i = 0; i < 32; ++i) points[used[i]] = c32[i];
            polygonPoints = c32;
        }
        std::vector<Face> faces;
        ASSERT_EQ(triangulatePolygon(points, used, faces), PolygonShape::Simple);
        ASSERT_EQ(faces.size(), used.size() - 2);
        double sum = 0;
        std::vector<int> seen;
        for (const Face& t : faces) {
            for (int k : t) seen.push_back(k);
            const double z = (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]).z();
            EXPECT_GT(z, 0);
            sum += 0.5 * z;
        }
        std::sort(seen.begin(), seen.end());
        seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
        std::vector<int> expected = used;
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(seen, expected);
        EXPECT_NEAR(sum, shoelace(polygonPoints), 1e-12);
    }
    // Two squares touching at a corner, written as one polygon through it twice (two indices at
    // one position): not simple, yet every index is in a triangle and none is lost.
    const std::vector<Vec3> pinched = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}, {1, 1, 0}, {0, 1, 0}};
    const std::vector<int> all = allCorners(pinched.size());
    std::vector<Face> faces;
    EXPECT_EQ(triangulatePolygon(pinched, all, faces), PolygonShape::NotSimple);
    ASSERT_EQ(faces.size(), pinched.size() - 2);
    std::vector<int> seen;
    for (const Face& t : faces) seen.insert(seen.end(), t.begin(), t.end());
    for (int i : all) EXPECT_NE(std::find(seen.begin(), seen.end(), i), seen.end()) << i;
}

TEST(Triangulate, FlipsRemoveZeroAreaFanTrianglesAndKeepTheSurfaceClosed)
{
    // A cube whose faces are octagons (corners and edge midpoints), each fanned from its first
    // corner as MeshLab's importers do: two zero-area triangles per face.
    TriMesh cube;
    auto vertex = [&](const Vec3& p) {
        for (int v = 0; v < cube.vertexCount(); ++v)
            if (cube.vertices[v] == p) return v;
        cube.vertices.push_back(p);
        return cube.vertexCount() - 1;
    };
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            std::vector<int> ring;
            const int walk[8][2] = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
            for (const auto& ij : walk) {
                Vec3 p;
                p[axis] = side ? 1 : -1;
                p[(axis + 1) % 3] = ij[0] - 1;
                p[(axis + 2) % 3] = ij[1] - 1;
                ring.push_back(vertex(p));
            }
            if (!side) std::reverse(ring.begin() + 1, ring.end());  // from the same (cube) corner
            for (int i = 1; i + 1 < 8; ++i) cube.faces.push_back({ring[0], ring[i], ring[i + 1]});
        }
    InputReport before;
    prepareInput(cube, before);
    EXPECT_EQ(before.removedDegenerateFaces, 12);  // what tore the surface

    TriMesh flipped = cube;
    EXPECT_EQ(flipZeroAreaTriangles(flipped), 12);
    InputReport after;
    const TriMesh clean = prepareInput(flipped, after);
    EXPECT_EQ(after.removedDegenerateFaces, 0);
    EXPECT_EQ(after.flippedFaces, 0);  // the neighbours' orientation kept
    const TopologySummary t = computeTopology(clean);
    EXPECT_EQ(t.boundaryLoops, 0);
    EXPECT_EQ(t.components, 1);
    EXPECT_EQ(t.genus, 0);
    EXPECT_NEAR(surfaceArea(clean), 24, 1e-12);
}

TEST(WorkingFrame, SameAsThePlainFormulaWhereDoublesSufficeAndFiniteAtAnyScale)
{
    const TriMesh base = testmesh::torus(16, 8);
    Vec3 lo = base.vertices[0], hi = lo;
    for (const Vec3& p : base.vertices) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const Normalisation unit = workingFrame(base, 1000);
    EXPECT_EQ(unit.scale, std::sqrt(1000 / surfaceArea(base)));  // bit for bit: results unchanged
    EXPECT_EQ(unit.centre, 0.5 * (lo + hi));
    for (const double scale : {1e-300, 1e-160, 1e100, 1e160, 1e300}) {
        SCOPED_TRACE(scale);
        TriMesh m = base;
        for (Vec3& p : m.vertices) p *= scale;
        const TriMesh work = inFrame(m, workingFrame(m, 1000));
        EXPECT_NEAR(surfaceArea(work), 1000, 1e-9);
        InputReport report;
        prepareInput(m, report);  // no face of a tiny model taken for a zero-area one
        EXPECT_EQ(report.removedDegenerateFaces, 0);
    }
}

// fuzz_read_mesh found a PLY quad with a -inf corner that kept the exact segment tests busy past
// the fuzzer's 20 s limit (the reader refuses the vertex only after its faces are read). A corner
// that is not finite has no plane: the fan, at once, said as not simple.
TEST(Triangulate, NonFiniteCornerGetsTheFanAtOnce)
{
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    for (const Vec3& bad : {Vec3(-1, -inf, -64), Vec3(nan, 0, 0), Vec3(inf, inf, inf)}) {
        const std::vector<Vec3> points = {Vec3(-1, -1, -1), Vec3(1, -1, -1), bad, Vec3(1, 1, 1.25), Vec3(-1, 1, 1)};
        std::vector<Face> faces;
        EXPECT_EQ(triangulatePolygon(points, {0, 1, 2, 3, 4}, faces), PolygonShape::NotSimple);
        EXPECT_EQ(faces.size(), 3u);
        for (const Face& f : faces) EXPECT_EQ(f[0], 0);
    }
}

}  // namespace
}  // namespace fieldcvt
