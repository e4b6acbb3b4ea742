// Part coverage (issue 32, item 3): lost parts show a gap, cut parts more than one piece, and
// components under the area share are counted apart.
#include "part_coverage.h"

#include "remesh.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fieldcvt {
namespace {

//! `b` appended to `a`, `b` moved by `offset`.
TriMesh joined(const TriMesh& a, TriMesh b, const Vec3& offset)
{
    TriMesh out = a;
    const int base = a.vertexCount();
    for (Vec3& v : b.vertices) out.vertices.push_back(v + offset);
    for (Face f : b.faces) {
        for (int& i : f) i += base;
        out.faces.push_back(f);
    }
    return out;
}

//! The faces of `mesh` whose centroid satisfies `keep`, with all the vertices (unreferenced
//! ones do not matter to the measure).
template <class Keep>
TriMesh facesWhere(const TriMesh& mesh, Keep keep)
{
    TriMesh out;
    out.vertices = mesh.vertices;
    for (const Face& f : mesh.faces)
        if (keep((mesh.vertices[f[0]] + mesh.vertices[f[1]] + mesh.vertices[f[2]]) / 3.0)) out.faces.push_back(f);
    return out;
}

TEST(PartCoverage, SurfaceAgainstItselfIsOnePartWithoutGap)
{
    const TriMesh sphere = testmesh::icosphere(3);
    const PartCoverage c = measurePartCoverage(sphere, sphere);
    ASSERT_EQ(c.parts.size(), 1u);
    EXPECT_NEAR(c.parts[0].areaFraction, 1.0, 1e-12);
    EXPECT_LT(c.largestGap, 1e-9);
    EXPECT_EQ(c.mostPieces, 1);
    EXPECT_EQ(c.smallParts, 0);
}

TEST(PartCoverage, LostPartShowsItsDistanceInEdgeLengths)
{
    const TriMesh sphere = testmesh::icosphere(3);
    const TriMesh input = joined(sphere, sphere, Vec3(5, 0, 0));
    const PartCoverage c = measurePartCoverage(sphere, input);
    ASSERT_EQ(c.parts.size(), 2u);
    // The lost sphere's farthest point (x = 6) is 5 units from the kept unit sphere: about 30 of
    // its edge lengths (0.15 or so); its nearest point is 3 units away.
    EXPECT_GT(c.largestGap, 3.0 / 0.15);
    EXPECT_EQ(c.mostPieces, 1);
}

TEST(PartCoverage, PartCutInTwoCountsTwoPieces)
{
    const TriMesh grid = testmesh::planeGrid(20);
    // The output: the grid without a band one cell wide across it, so two pieces.
    const TriMesh cut = facesWhere(grid, [](const Vec3& c) { return std::abs(c.x() - 0.5) > 0.05; });
    const PartCoverage c = measurePartCoverage(cut, grid);
    ASSERT_EQ(c.parts.size(), 1u);
    EXPECT_EQ(c.parts[0].pieces, 2);
    // The band's middle is half a cell (half an edge length or so) from either side.
    EXPECT_GT(c.largestGap, 0.2);
    EXPECT_LT(c.largestGap, 1.5);
}

TEST(PartCoverage, ComponentsUnderTheShareAreCountedApart)
{
    const TriMesh big = testmesh::planeGrid(20, 10.0);
    const TriMesh tiny = testmesh::planeGrid(2, 0.5);  // 0.25 % of the area
    const TriMesh input = joined(big, tiny, Vec3(0, 0, 3));
    const PartCoverage c = measurePartCoverage(big, input);
    ASSERT_EQ(c.parts.size(), 1u);
    EXPECT_EQ(c.smallParts, 1);
    EXPECT_NEAR(c.smallAreaFraction, 0.25 / 100.25, 1e-9);
    EXPECT_LT(c.largestGap, 1e-9);
    EXPECT_GT(c.smallPartsGap, 3.0 / 0.6);  // 3 units above the big grid, edge length 0.57 or so
}

TEST(PartCoverage, NoOutputFacesLeaveEveryGapInfinite)
{
    const TriMesh sphere = testmesh::icosphere(2);
    const PartCoverage c = measurePartCoverage(TriMesh{}, sphere);
    ASSERT_EQ(c.parts.size(), 1u);
    EXPECT_TRUE(std::isinf(c.largestGap));
    EXPECT_EQ(c.mostPieces, 0);
}

// A fragmentary scan (issue 32, item 4): a patch and five fragments of 1.15-1.75 samples' area
// at 400 vertices (under the 0.5 % that makes a part), 0.5-1.5 units (about 4-13 edge lengths)
// beyond its border. They are too small for the 8 samples that make a surface, but dropping them
// would leave gaps of that size: each comes back as a piece of its own (the 3 samples each gets
// add 7.75, within 2 % of 400), with well-shaped triangles. Before, they were dropped.
TEST(PartCoverage, FragmentsFarFromTheScanComeBackAsPiecesOfTheirOwn)
{
    const TriMesh patch = testmesh::planeGrid(30, 2.0);  // area 4: 0.01 per sample at 400
    TriMesh input = patch;
    for (int i = 0; i < 5; ++i) {
        const double side = std::sqrt(0.01 * (1.15 + 0.15 * i));
        input = joined(input, testmesh::planeGrid(2, side), Vec3(2.5 + 0.25 * i, 0.25 * i, 0.05 * i));
    }
    RemeshParams params;
    params.vertexCount = 400;
    const RemeshResult result = remesh(input, params);
    const PartCoverage c = measurePartCoverage(result.mesh, input);
    ASSERT_EQ(c.parts.size(), 1u);
    EXPECT_EQ(c.smallParts, 5);
    EXPECT_LT(c.largestGap, 2.0);
    EXPECT_EQ(c.mostPieces, 1);
    EXPECT_LT(c.smallPartsGap, 2.0);
    EXPECT_EQ(result.repair.keptFarComponents, 5);
    EXPECT_EQ(result.repair.droppedComponents, 0);
    EXPECT_GE(result.metrics.thetaMin, 15.0);
    EXPECT_LE(result.metrics.pctLt30, 0.5);
}

}  // namespace
}  // namespace fieldcvt
