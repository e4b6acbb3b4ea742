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

#include <algorithm>
#include <cmath>

namespace fieldcvt {
namespace {

std::vector<Face> triangulate(const std::vector<Vec3>& points)
{
    std::vector<int> corners(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) corners[i] = static_cast<int>(i);
    std::vector<Face> faces;
    triangulatePolygon(points, corners, faces);
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
    for (const Face& t : triangulate(huge)) EXPECT_GT(triangleArea(huge[t[0]], huge[t[1]], huge[t[2]]), 1e300);  // the area overflows: inf, never 0
}

TEST(Triangulate, NonConvexPolygonStaysInside)
{
    // An L whose first corner is reflex: a fan from it would cover the notch.
    expectGoodTriangulation({{1, 1, 0}, {1, 2, 0}, {0, 2, 0}, {0, 0, 0}, {2, 0, 0}, {2, 1, 0}}, 3);
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

}  // namespace
}  // namespace fieldcvt
