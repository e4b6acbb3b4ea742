// Topology first (remesh_topology.cpp, keepTopology): with the default options every shell comes
// back with its genus and boundary loops, one piece each, the vertex count yielding to it with a
// warning; --exact-count (RemeshParams::exactCount) keeps the count.
#include "errors.h"
#include "metrics.h"
#include "remesh.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <string>

using namespace fieldcvt;

namespace {

//! `copies` tori of tube radius `tube` side by side along x (separate shells).
TriMesh tori(int copies, double tube, int n = 48, int m = 12)
{
    TriMesh out;
    for (int c = 0; c < copies; ++c) {
        TriMesh t = testmesh::torus(n, m, 1.0, tube);
        const int offset = out.vertexCount();
        for (Vec3 p : t.vertices) out.vertices.push_back(p + Vec3(3.0 * c, 0, 0));
        for (Face f : t.faces) out.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
    }
    return out;
}

bool warned(const RemeshResult& r, const std::string& words)
{
    for (const std::string& w : r.warnings)
        if (w.find(words) != std::string::npos) return true;
    return false;
}

}  // namespace

// A torus whose tube is far thinner than the edge length at N: the triangulation of the samples
// alone tears it; the output keeps genus 1 and one piece, says how many vertices it has beyond N.
TEST(RemeshTopology, ThinTubeKeepsGenusAndSaysWhyItHasMoreVertices)
{
    const TriMesh input = tori(1, 0.02);
    RemeshParams p;
    p.vertexCount = 100;
    const RemeshResult r = remesh(input, p);
    const TopologySummary t = computeTopology(r.mesh);
    EXPECT_TRUE(t.manifold());
    EXPECT_EQ(t.components, 1);
    EXPECT_EQ(t.genus, 1);
    EXPECT_EQ(t.boundaryLoops, 0);
    if (r.mesh.vertexCount() > 103) EXPECT_TRUE(warned(r, "beyond the 100 asked for")) << r.mesh.vertexCount();
    EXPECT_TRUE(r.thinParts.added > 0 || r.localShells.shells > 0);
}

// Several thin tori, separate shells: none lost, none merged, none torn.
TEST(RemeshTopology, EveryShellComesBackWithItsGenus)
{
    const TriMesh input = tori(4, 0.03);
    RemeshParams p;
    p.vertexCount = 200;
    const RemeshResult r = remesh(input, p);
    const TopologySummary t = computeTopology(r.mesh);
    EXPECT_TRUE(t.manifold());
    EXPECT_EQ(t.components, 4);
    EXPECT_EQ(t.genus, 4);
    EXPECT_EQ(t.boundaryLoops, 0);
    const QualityMetrics q = computeQuality(r.mesh);
    EXPECT_GT(q.thetaMin, 0);
}

// exactCount: the count asked for (within 3 %), no shell remeshed locally, no vertex added; on
// a tube too thin for any triangle at N, the error of before (the count is not raised).
TEST(RemeshTopology, ExactCountKeepsTheCount)
{
    RemeshParams p;
    p.vertexCount = 200;
    p.exactCount = true;
    const RemeshResult r = remesh(tori(1, 0.08), p);
    EXPECT_EQ(r.localShells.shells, 0);
    EXPECT_EQ(r.thinParts.added, 0);
    EXPECT_NEAR(r.mesh.vertexCount(), 200, 6);
    EXPECT_FALSE(warned(r, "vertices added beyond"));
    p.vertexCount = 100;
    EXPECT_THROW(remesh(tori(1, 0.02), p), SolverError);
}

// A well-sampled shell needs nothing: no shell is remeshed locally, the count is N's.
TEST(RemeshTopology, NothingToKeepChangesNothing)
{
    RemeshParams p;
    p.vertexCount = 400;
    const RemeshResult r = remesh(testmesh::torus(48, 16, 1.0, 0.4), p);
    EXPECT_EQ(r.localShells.shells, 0);
    EXPECT_FALSE(warned(r, "vertices added beyond"));
    EXPECT_EQ(computeTopology(r.mesh).genus, 1);
}
