// Output mesh extraction from the restricted Delaunay triangles.
#include "metrics.h"
#include "rdt.h"

#include <gtest/gtest.h>

using namespace fieldcvt;

TEST(Rdt, BowtieVertexIsSplitIntoOneVertexPerFan)
{
    // Two triangles touching only at vertex 0 (a restricted cell in two pieces).
    TriMesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
    m.faces = {{0, 1, 2}, {0, 3, 4}};
    std::vector<int> seedOfVertex = {10, 11, 12, 13, 14};
    EXPECT_EQ(computeTopology(m).nonManifoldVertices, 1);
    EXPECT_EQ(splitNonManifoldVertices(m, seedOfVertex), 1);
    EXPECT_EQ(computeTopology(m).nonManifoldVertices, 0);
    ASSERT_EQ(m.vertexCount(), 6);
    EXPECT_EQ(m.vertices[5], m.vertices[0]);
    EXPECT_EQ(seedOfVertex[5], 10);
    EXPECT_EQ(m.faces[1][0], 5);
}

TEST(Rdt, ManifoldFanIsLeftAlone)
{
    TriMesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
    m.faces = {{0, 1, 2}, {0, 2, 3}};
    std::vector<int> seedOfVertex = {0, 1, 2, 3};
    EXPECT_EQ(splitNonManifoldVertices(m, seedOfVertex), 0);
    EXPECT_EQ(m.vertexCount(), 4);
}

TEST(Rdt, FacesOnOverfullEdgesAreRemovedAndUnusedSamplesDropped)
{
    // Three triangles on edge (0, 1) cannot all stay; sample 5 is in no triangle.
    std::vector<Vec3> seeds = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}, {9, 9, 9}};
    TriMesh surface;
    surface.vertices = {{-5, -5, 0}, {5, -5, 0}, {0, 5, 0}};
    surface.faces = {{0, 1, 2}};
    ClosestPointTree tree(surface);
    const RdtResult r = extractRdt(seeds, {{0, 1, 2}, {1, 0, 3}, {0, 4, 1}}, tree);
    EXPECT_EQ(r.removedFaces, 3);  // every face touches the over-full edge
    EXPECT_GE(r.droppedSeeds, 1);
    EXPECT_FALSE(r.warnings.empty());
}
