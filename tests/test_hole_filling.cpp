// core/hole_filling.h: small holes closed before remeshing (issue 32 item 1).
#include "hole_filling.h"
#include "metrics.h"
#include "remesh.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>

namespace fieldcvt {
namespace {

//! `mesh` without the faces around each vertex of `centres` (one hole per vertex, its ring).
TriMesh withHolesAt(const TriMesh& mesh, const std::set<int>& centres)
{
    TriMesh out;
    out.vertices = mesh.vertices;
    for (const Face& f : mesh.faces)
        if (!centres.count(f[0]) && !centres.count(f[1]) && !centres.count(f[2])) out.faces.push_back(f);
    return out;
}

//! Every edge has two faces that run it in opposite directions.
bool closedAndConsistentlyOriented(const TriMesh& mesh)
{
    std::map<std::pair<int, int>, int> directed;
    for (const Face& f : mesh.faces)
        for (int k = 0; k < 3; ++k) ++directed[{f[size_t(k)], f[size_t((k + 1) % 3)]}];
    for (const auto& [edge, count] : directed)
        if (count != 1 || directed.count({edge.second, edge.first}) == 0) return false;
    return true;
}

TEST(HoleFilling, ClosesTheSmallHolesOnlyWithTheSurfacesOrientation)
{
    const TriMesh sphere = testmesh::icosphere(4);   // edges about 0.08 long
    TriMesh holed = withHolesAt(sphere, {0, 1, 2});  // three one-ring holes, about 0.16 across
    const int removed = sphere.faceCount() - holed.faceCount();
    ASSERT_EQ(computeTopology(holed).boundaryLoops, 3);
    TriMesh keep = holed;
    EXPECT_EQ(closeSmallHoles(keep, 0.1).closed, 0);  // all three are larger than 0.1 across
    EXPECT_EQ(keep.faceCount(), holed.faceCount());

    const HoleFillReport report = closeSmallHoles(holed, 0.3);
    EXPECT_EQ(report.closed, 3);
    EXPECT_EQ(report.leftOpen, 0);
    // A hole of a k-vertex ring gets k - 2 triangles where its vertex had k.
    EXPECT_EQ(holed.faceCount(), sphere.faceCount() - removed + (removed - 2 * 3));
    EXPECT_TRUE(closedAndConsistentlyOriented(holed));
    const TopologySummary t = computeTopology(holed);
    EXPECT_EQ(t.boundaryLoops, 0);
    EXPECT_EQ(t.genus, 0);
    EXPECT_GT(report.area, 0);
    EXPECT_LT(report.area, surfaceArea(sphere) - surfaceArea(withHolesAt(sphere, {0, 1, 2})) + 1e-12);
}

TEST(HoleFilling, LeavesASmallPieceAndAnOpenSurfacesOwnBorderAlone)
{
    // A small disk is a piece no larger than its border: closing it would make a pillow.
    TriMesh disk = testmesh::disk(3);
    for (Vec3& p : disk.vertices) p *= 0.05;
    EXPECT_EQ(closeSmallHoles(disk, 1.0).closed, 0);
    // A large open surface's own border is larger than the limit: it stays open.
    TriMesh grid = testmesh::planeGrid(20);
    EXPECT_EQ(closeSmallHoles(grid, 0.5).closed, 0);
    EXPECT_EQ(computeTopology(grid).boundaryLoops, 1);
}

TEST(HoleFilling, RemeshClosesSmallHolesUnlessAskedToKeepThem)
{
    // A sphere with 12 holes of one input ring each, far under the output's edge length.
    const TriMesh sphere = testmesh::icosphere(4);
    const TriMesh holed = withHolesAt(sphere, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11});
    RemeshParams p;
    p.vertexCount = 300;
    const RemeshResult closed = remesh(holed, p);
    EXPECT_EQ(closed.outputTopology.boundaryLoops, 0);
    EXPECT_EQ(closed.outputTopology.components, 1);
    EXPECT_GE(closed.metrics.thetaMin, 30.0);
    bool warned = false;
    for (const std::string& w : closed.warnings) warned |= w.find("12 holes under 2 edge lengths across closed") == 0;
    EXPECT_TRUE(warned);

    p.closeHolesUnder = 0;
    const RemeshResult kept = remesh(holed, p);
    EXPECT_GT(kept.outputTopology.boundaryLoops, 0);
}

}  // namespace
}  // namespace fieldcvt
