// core/thin_parts.h: the local thickness (medial balls) and the density thin parts need, and
// remesh()'s second pass where the first one's topology differs from the input's (issue 32 item 2).
#include "closest_point.h"
#include "metrics.h"
#include "part_coverage.h"
#include "remesh.h"
#include "test_meshes.h"
#include "thin_parts.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace fieldcvt {
namespace {

using testmesh::torus;

constexpr double kPiValue = 3.14159265358979323846;

//! A ring (major radius 1) whose tube has radius `thick` except in a neck around angle 0, where
//! it narrows to `neck`: genus 1, thin in one place only.
TriMesh neckedRing(int n, int m, double thick, double neck)
{
    TriMesh t;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j) {
            const double u = 2 * kPiValue * i / n, v = 2 * kPiValue * j / m;
            const double fromNeck = std::abs(std::remainder(u, 2 * kPiValue));
            const double r = fromNeck > 0.6 ? thick : neck + (thick - neck) * (fromNeck / 0.6) * (fromNeck / 0.6);
            t.vertices.emplace_back((1 + r * std::cos(v)) * std::cos(u), (1 + r * std::cos(v)) * std::sin(u), r * std::sin(v));
        }
    auto id = [n, m](int i, int j) { return ((i + n) % n) * m + (j + m) % m; };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j) {
            t.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            t.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return t;
}

//! The thickness measured at face f's centroid on the given side.
double thicknessAtFace(const TriMesh& mesh, const ClosestPointTree& tree, int f, int side, double largest)
{
    const Vec3 centroid =
        (mesh.vertices[mesh.faces[f][0]] + mesh.vertices[mesh.faces[f][1]] + mesh.vertices[mesh.faces[f][2]]) / 3.0;
    return localThickness(tree, centroid, faceNormal(mesh, f).normalized(), f, side, largest, 150);
}

TEST(ThinParts, ATubesThicknessIsItsDiameterInsideAndNothingOutside)
{
    const TriMesh tube = torus(96, 24, 1.0, 0.1);  // outward normals
    const ClosestPointTree tree(tube);
    for (int f = 0; f < tube.faceCount(); f += 37) {
        // Inside: the tube's diameter, less the facets' sag (cos(pi / 24) of the radius).
        EXPECT_NEAR(thicknessAtFace(tube, tree, f, -1, 1.0), 0.2, 0.01) << "face " << f;
        // Outside, within 0.5 of the surface: no ball touches it again.
        EXPECT_EQ(thicknessAtFace(tube, tree, f, +1, 1.0), std::numeric_limits<double>::infinity()) << "face " << f;
    }
    // A ball larger than `largest` is not looked for: nothing is thinner than 0.1 here.
    EXPECT_EQ(thicknessAtFace(tube, tree, 0, -1, 0.1), std::numeric_limits<double>::infinity());
}

TEST(ThinParts, TheHoleOfARingCountsFromOutsideAndACreaseDoesNot)
{
    // The ring's hole, 2 (1 - 0.3) = 1.4 across at the inner equator, seen from outside.
    const TriMesh ring = torus(96, 24, 1.0, 0.3);
    const ClosestPointTree tree(ring);
    int innerFaces = 0;
    for (int f = 0; f < ring.faceCount(); ++f) {
        const Vec3 c =
            (ring.vertices[ring.faces[f][0]] + ring.vertices[ring.faces[f][1]] + ring.vertices[ring.faces[f][2]]) / 3.0;
        if (std::hypot(c.x(), c.y()) > 0.72 || std::abs(c.z()) > 0.05) continue;  // the inner equator
        ++innerFaces;
        EXPECT_NEAR(thicknessAtFace(ring, tree, f, +1, 4.0), 1.4, 0.03) << "face " << f;
    }
    EXPECT_GT(innerFaces, 0);
    // A cube's faces meet at right angles: a ball inside one corner is stopped by the next face
    // at 90 degrees, a crease, not a thin part, and its thickness is the cube's (1).
    const TriMesh cube = [] {
        TriMesh c;
        for (int i = 0; i < 8; ++i) c.vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
        c.faces = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                   {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
        return c;
    }();
    const ClosestPointTree cubeTree(cube);
    for (int f = 0; f < cube.faceCount(); ++f) {
        const double t = thicknessAtFace(cube, cubeTree, f, -1, 4.0);
        EXPECT_TRUE(t == std::numeric_limits<double>::infinity() || std::abs(t - 1.0) < 1e-6) << "face " << f << ": " << t;
    }
}

TEST(ThinParts, DensityOnlyWhereThinGradedAndCapped)
{
    const TriMesh ring = neckedRing(240, 16, 0.25, 0.03);
    const ClosestPointTree tree(ring);
    ThinPartParams params;
    const ThinPartDensity thin = thinPartDensity(ring, tree, 0.2, params);
    ASSERT_EQ(thin.mu.size(), size_t(ring.faceCount()));
    EXPECT_GT(thin.thinFaces, 0);
    EXPECT_NEAR(thin.thinnest, 0.06, 0.01);
    EXPECT_GT(thin.vertexFactor, 1.0);
    EXPECT_LE(thin.vertexFactor, params.maxVertexFactor + 1e-9);
    double neckMu = 0, farMu = 0;
    for (int f = 0; f < ring.faceCount(); ++f) {
        const Vec3 c = ring.vertices[ring.faces[f][0]];
        const double u = std::abs(std::atan2(c.y(), c.x()));
        EXPECT_GE(thin.mu[f], 1.0);
        EXPECT_LE(thin.mu[f], params.maxEdgeRatio * params.maxEdgeRatio * (1 + 1e-9));
        if (u < 0.02) neckMu = std::max(neckMu, thin.mu[f]);
        if (u > 2.0) farMu = std::max(farMu, thin.mu[f]);
    }
    EXPECT_GT(neckMu, 4.0);  // edges at least twice shorter in the neck
    EXPECT_EQ(farMu, 1.0);   // the thick part as it was
    // A thick ring needs nothing.
    const TriMesh thick = torus(64, 16, 1.0, 0.3);
    EXPECT_TRUE(thinPartDensity(thick, ClosestPointTree(thick), 0.2, params).mu.empty());
    // The cap: asked for edges far below the thickness everywhere, the factor stays at the cap.
    params.edgePerThickness = 0.01;
    const ThinPartDensity capped = thinPartDensity(thick, ClosestPointTree(thick), 0.2, params);
    EXPECT_TRUE(capped.capped);
    EXPECT_NEAR(capped.vertexFactor, params.maxVertexFactor, 1e-6);
}

//! A unit grid (40 x 40 cells) without the cells of two square holes, 8 cells wide, `gap`
//! cells apart (centred in x, at mid-height).
TriMesh gridWithTwoHoles(int gap)
{
    const TriMesh grid = testmesh::planeGrid(40, 1.0);
    TriMesh out;
    out.vertices = grid.vertices;
    const int left = 20 - gap / 2 - 8, right = 20 + (gap + 1) / 2;
    for (const Face& f : grid.faces) {
        const Vec3 c = (grid.vertices[f[0]] + grid.vertices[f[1]] + grid.vertices[f[2]]) / 3.0;
        const int i = int(c.x() * 40), j = int(c.y() * 40);
        const bool inHole = j >= 16 && j < 24 && ((i >= left && i < left + 8) || (i >= right && i < right + 8));
        if (!inHole) out.faces.push_back(f);
    }
    return out;
}

TEST(ThinParts, AStripBetweenTwoHolesIsThinAndTwoHolesFarApartAreNot)
{
    // Edges 0.1 long: a strip of one cell (0.025) between the holes is thin, one of 12 cells
    // (0.3) is not, nor the strips to the outer border (0.15); the holes themselves (0.2 across)
    // are not.
    const TriMesh near = gridWithTwoHoles(1), far = gridWithTwoHoles(12);
    const ThinPartDensity strip = thinPartDensity(near, ClosestPointTree(near), 0.1);
    ASSERT_FALSE(strip.mu.empty());
    EXPECT_NEAR(strip.thinnest, 0.025, 1e-9);
    for (int f = 0; f < near.faceCount(); ++f) {
        const Vec3 c =
            (near.vertices[near.faces[f][0]] + near.vertices[near.faces[f][1]] + near.vertices[near.faces[f][2]]) / 3.0;
        if (std::abs(c.x() - 0.5) < 0.01 && std::abs(c.y() - 0.5) < 0.05) EXPECT_GT(strip.mu[f], 4.0) << "face " << f;
        if (c.y() < 0.1) EXPECT_EQ(strip.mu[f], 1.0) << "face " << f;
    }
    EXPECT_TRUE(thinPartDensity(far, ClosestPointTree(far), 0.1).mu.empty());
}

TEST(ThinParts, RemeshAddsVerticesWhereTheNeckWouldTearAndKeepsTheGenus)
{
    const TriMesh ring = neckedRing(240, 16, 0.25, 0.03);
    RemeshParams params;
    params.vertexCount = 150;
    params.threads = 2;
    const RemeshResult result = remesh(ring, params);
    const TopologySummary out = computeTopology(result.mesh);
    EXPECT_EQ(out.genus, 1);
    EXPECT_EQ(out.boundaryLoops, 0);
    EXPECT_EQ(out.components, 1);
    EXPECT_GT(result.thinParts.added, 0);
    EXPECT_LE(result.mesh.vertexCount(), 2 * params.vertexCount);
    EXPECT_GE(result.metrics.thetaMin, 15.0);
    bool warned = false;
    for (const std::string& w : result.warnings)
        warned |= w.find("vertices added where the surface is thinner") != std::string::npos;
    EXPECT_TRUE(warned);
    // --exact-count: the count asked for, and the neck is lost.
    params.exactCount = true;
    const RemeshResult exact = remesh(ring, params);
    EXPECT_EQ(exact.thinParts.added, 0);
    EXPECT_NE(computeTopology(exact.mesh).genus, 1);
    EXPECT_LE(std::abs(exact.mesh.vertexCount() - params.vertexCount), params.vertexCount / 10);
}

TEST(ThinParts, ModelsWhoseTopologyComesOutRightAreNotTouched)
{
    const TriMesh ring = torus(64, 16, 1.0, 0.3);
    RemeshParams params;
    params.vertexCount = 400;
    params.threads = 2;
    const RemeshResult first = remesh(ring, params);
    params.exactCount = true;
    const RemeshResult exact = remesh(ring, params);
    EXPECT_EQ(first.thinParts.added, 0);
    EXPECT_EQ(first.mesh.vertices, exact.mesh.vertices);
    EXPECT_EQ(first.mesh.faces, exact.mesh.faces);
}

//! A scan-like plate, [0, 1]², with a peninsula of `width` and `length` along +x from the middle
//! of its right border (a ragged border's spike), on a grid of `cell`-sized squares.
TriMesh plateWithPeninsula(double width, double length, double cell)
{
    TriMesh grid;
    const int nx = static_cast<int>(std::lround((1 + length) / cell)), ny = static_cast<int>(std::lround(1 / cell));
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) grid.vertices.emplace_back(i * cell, j * cell, 0.0);
    auto id = [nx](int i, int j) { return j * (nx + 1) + i; };
    auto inside = [&](double x, double y) { return x < 1 || std::abs(y - 0.5) < 0.5 * width; };
    std::vector<int> index(grid.vertices.size(), -1);
    TriMesh out;
    auto use = [&](int v) {
        if (index[v] < 0) index[v] = out.vertexCount(), out.vertices.push_back(grid.vertices[v]);
        return index[v];
    };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            if (inside((i + 0.5) * cell, (j + 0.5) * cell)) {
                out.faces.push_back({use(id(i, j)), use(id(i + 1, j)), use(id(i + 1, j + 1))});
                out.faces.push_back({use(id(i, j)), use(id(i + 1, j + 1)), use(id(i, j + 1))});
            }
    return out;
}

TEST(ThinParts, APeninsulaNarrowerThanTheEdgesIsKeptWholeWithGoodTriangles)
{
    // 300 vertices: edges about 0.06 long; the peninsula is 0.04 wide (2 grid cells) and 0.4
    // long. Without more vertices on it the output loses it: its tip is 6 edge lengths away.
    const TriMesh plate = plateWithPeninsula(0.04, 0.4, 0.02);
    RemeshParams params;
    params.vertexCount = 300;
    params.threads = 2;
    const RemeshResult result = remesh(plate, params);
    const PartCoverage parts = measurePartCoverage(result.mesh, plate);
    ASSERT_EQ(parts.parts.size(), 1u);
    EXPECT_LE(parts.largestGap, 2.0);
    EXPECT_EQ(parts.mostPieces, 1);
    EXPECT_GT(result.thinParts.added, 0);
    EXPECT_GE(result.metrics.thetaMin, 15.0);
    EXPECT_LE(result.metrics.pctLt30, 0.5);
    params.exactCount = true;
    const RemeshResult exact = remesh(plate, params);
    EXPECT_GT(measurePartCoverage(exact.mesh, plate).largestGap, 2.0);
}

}  // namespace
}  // namespace fieldcvt
