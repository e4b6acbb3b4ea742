// The optimisation surface (simplify.h): a coarser copy of the input made of input vertices,
// manifold, with the input's border and locked vertices, close to the input.
#include "simplify.h"

#include "closest_point.h"
#include "mesh_check.h"
#include "mesh_io.h"
#include "metrics.h"
#include "remesh.h"
#include "remesh_stages.h"
#include "test_meshes.h"
#include "thread_count.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <set>

using namespace fieldcvt;

namespace {

// Largest distance from the coarse mesh's face centroids and edge midpoints to `input`.
double largestDeviation(const TriMesh& coarse, const TriMesh& input)
{
    const ClosestPointTree tree(input);
    double worst = 0;
    for (const Face& t : coarse.faces) {
        const Vec3& a = coarse.vertices[t[0]];
        const Vec3& b = coarse.vertices[t[1]];
        const Vec3& c = coarse.vertices[t[2]];
        for (const Vec3& p : {Vec3((a + b + c) / 3.0), Vec3(0.5 * (a + b)), Vec3(0.5 * (b + c)), Vec3(0.5 * (c + a))})
            worst = std::max(worst, (tree.closest(p).point - p).norm());
    }
    return worst;
}

std::set<std::pair<int, int>> borderEdges(const TriMesh& mesh, const std::vector<int>& toInput)
{
    std::map<std::pair<int, int>, int> count;
    for (const Face& t : mesh.faces)
        for (int e = 0; e < 3; ++e) {
            int a = t[e], b = t[(e + 1) % 3];
            if (!toInput.empty()) a = toInput[a], b = toInput[b];
            ++count[std::minmax(a, b)];
        }
    std::set<std::pair<int, int>> border;
    for (const auto& [edge, n] : count)
        if (n == 1) border.insert(edge);
    return border;
}

//! A coarse copy of a closed sphere: near the target (at most 2 over, `under` under), closed,
//! manifold, one piece of genus 0, made of input vertices at their places, within 1.5 times
//! the error bound.
void expectCoarseSphere(const SimplifyResult& r, const TriMesh& sphere, int target, int under, double maxError)
{
    EXPECT_LE(r.mesh.faceCount(), target + 2);
    EXPECT_GE(r.mesh.faceCount(), target - under);
    const TopologySummary topology = computeTopology(r.mesh);
    EXPECT_TRUE(topology.manifold());
    EXPECT_EQ(topology.genus, 0);
    EXPECT_EQ(topology.components, 1);
    EXPECT_EQ(topology.boundaryLoops, 0);
    // Half-edge collapses: every coarse vertex is an input vertex, at the same place.
    ASSERT_EQ(r.inputVertex.size(), r.mesh.vertices.size());
    for (size_t v = 0; v < r.inputVertex.size(); ++v) {
        EXPECT_EQ(r.mesh.vertices[v], sphere.vertices[size_t(r.inputVertex[v])]);
        EXPECT_EQ(r.coarseVertex[size_t(r.inputVertex[v])], int(v));
    }
    EXPECT_LT(largestDeviation(r.mesh, sphere), maxError * 1.5);
}

//! A coarse copy of a flat grid: at most 2 faces over the target, the locked vertex kept, the
//! border made of the input's border edges (all of them), the same area, manifold, one border
//! loop, and even (flat parts: the collapse order's length term).
void expectCoarseGrid(const SimplifyResult& r, const TriMesh& grid, int target, int lockedVertex)
{
    EXPECT_LE(r.mesh.faceCount(), target + 2);
    EXPECT_GE(r.coarseVertex[size_t(lockedVertex)], 0);
    EXPECT_EQ(borderEdges(r.mesh, r.inputVertex), borderEdges(grid, {}));
    EXPECT_NEAR(surfaceArea(r.mesh), surfaceArea(grid), 1e-9);
    const TopologySummary topology = computeTopology(r.mesh);
    EXPECT_TRUE(topology.manifold());
    EXPECT_EQ(topology.boundaryLoops, 1);
    EXPECT_GT(computeQuality(r.mesh).qMin, 0.15);
}

//! Shortest and longest edge of `mesh`.
std::pair<double, double> edgeLengthRange(const TriMesh& mesh)
{
    double shortest = std::numeric_limits<double>::infinity(), longest = 0;
    for (const Face& t : mesh.faces)
        for (int k = 0; k < 3; ++k) {
            const double l = (mesh.vertices[size_t(t[k])] - mesh.vertices[size_t(t[(k + 1) % 3])]).norm();
            shortest = std::min(shortest, l);
            longest = std::max(longest, l);
        }
    return {shortest, longest};
}

}  // namespace

TEST(Simplify, SphereReachesTheTargetStaysManifoldAndClose)
{
    const TriMesh sphere = testmesh::icosphere(5);  // 20 480 faces
    SimplifyParams params;
    params.targetFaces = 2000;
    params.maxError = 0.01;
    const SimplifyResult r = simplifyMesh(sphere, params);
    expectCoarseSphere(r, sphere, 2000, 100, 0.01);
    // No collapse makes a sliver: the input's triangles are all fine, so the coarse ones are.
    const QualityMetrics q = computeQuality(r.mesh);
    EXPECT_GT(q.qMin, 0.15);
}

TEST(Simplify, ErrorBoundStopsBeforeTheTarget)
{
    const TriMesh sphere = testmesh::icosphere(4);
    SimplifyParams params;
    params.targetFaces = 50;  // far below what the bound allows
    params.maxError = 0.002;
    const SimplifyResult r = simplifyMesh(sphere, params);
    EXPECT_GT(r.mesh.faceCount(), 500);
    EXPECT_LT(largestDeviation(r.mesh, sphere), 0.002 * 1.5);
}

TEST(Simplify, OpenBorderAndLockedVerticesStay)
{
    const TriMesh grid = testmesh::planeGrid(40);  // flat: every quadric error is 0
    SimplifyParams params;
    params.targetFaces = 700;
    params.maxError = 0.01;
    params.locked.assign(grid.vertices.size(), 0);
    const int lockedVertex = 20 * 41 + 20;  // the centre of the grid
    params.locked[lockedVertex] = 1;
    expectCoarseGrid(simplifyMesh(grid, params), grid, 700, lockedVertex);
}

TEST(Simplify, DeterministicAndCheckedParameters)
{
    const TriMesh torus = testmesh::torus(60, 30);
    SimplifyParams params;
    params.targetFaces = 800;
    params.maxError = 0.02;
    const SimplifyResult a = simplifyMesh(torus, params), b = simplifyMesh(torus, params);
    EXPECT_EQ(a.mesh.faces, b.mesh.faces);
    EXPECT_EQ(a.inputVertex, b.inputVertex);
    EXPECT_EQ(computeTopology(a.mesh).genus, 1);
    params.locked.assign(3, 0);  // wrong size
    EXPECT_THROW(simplifyMesh(torus, params), InvalidInputError);
    params.locked.clear();
    params.targetFaces = -1;
    EXPECT_THROW(simplifyMesh(torus, params), InvalidInputError);
}

// Large inputs are simplified in blocks first (in parallel), then in one pass over the merged
// blocks: the same kind of surface as one pass (manifold, close, no slivers, as even), the
// border and the locked vertices kept, and the same result on any thread count.
TEST(Simplify, BlocksGiveTheSameSurfaceAsOnePass)
{
    const TriMesh sphere = testmesh::icosphere(6);  // 81 920 faces
    SimplifyParams params;
    params.targetFaces = 4000;
    params.maxError = 0.01;
    params.blockFaces = 10000;
    // Blocks whose share of the target is small against their frontier band: one pass.
    ASSERT_EQ(simplifyBlockCount(sphere.faceCount(), params), 1);
    params.targetFaces = 10000;
    params.blockFaces = 20000;
    ASSERT_EQ(simplifyBlockCount(sphere.faceCount(), params), 4);
    const SimplifyResult blocks = simplifyMesh(sphere, params);
    expectCoarseSphere(blocks, sphere, 10000, 200, 0.01);
    params.blockFaces = 0;
    ASSERT_EQ(simplifyBlockCount(sphere.faceCount(), params), 1);
    const SimplifyResult onePass = simplifyMesh(sphere, params);
    // The frontier bands are coarsened by the last pass: the blocks' surface as even as one
    // pass's (0.694 against 0.695).
    const QualityMetrics a = computeQuality(blocks.mesh), b = computeQuality(onePass.mesh);
    EXPECT_GT(a.qMin, 0.15);
    EXPECT_GT(a.qAvg, b.qAvg - 0.01);
    const auto [shortest, longest] = edgeLengthRange(blocks.mesh);
    const double longestOnePass = edgeLengthRange(onePass.mesh).second;
    EXPECT_GT(shortest, 0.1 * longestOnePass);  // no band left at the input's resolution
    EXPECT_LT(longest, 1.5 * longestOnePass);
}

TEST(Simplify, BlocksKeepBorderAndLockedVerticesWhateverTheThreads)
{
    const TriMesh grid = testmesh::planeGrid(120);  // 28 800 faces, flat
    SimplifyParams params;
    params.targetFaces = 10000;
    params.maxError = 0.01;
    params.blockFaces = 7000;
    ASSERT_EQ(simplifyBlockCount(grid.faceCount(), params), 4);
    params.locked.assign(grid.vertices.size(), 0);
    const int lockedVertex = 60 * 121 + 60;  // the centre: on the frontier of the Morton blocks
    params.locked[lockedVertex] = 1;
    const SimplifyResult one = testthreads::withThreadCount(1, [&] { return simplifyMesh(grid, params); });
    const SimplifyResult three = testthreads::withThreadCount(3, [&] { return simplifyMesh(grid, params); });
    EXPECT_EQ(one.mesh.faces, three.mesh.faces);
    EXPECT_EQ(one.inputVertex, three.inputVertex);
    expectCoarseGrid(one, grid, 10000, lockedVertex);
    params.blockFaces = -1;
    EXPECT_THROW(simplifyMesh(grid, params), InvalidInputError);
}

// remesh() on a dense input optimises on the coarse copy and puts the result back on the input:
// every output vertex on the input surface, the same figures as on the input itself.
TEST(Simplify, RemeshOfADenseInputMatchesTheFullSurfaceRun)
{
    const TriMesh dense = testmesh::torus(100, 50);  // 10 000 faces for 500 vertices
    RemeshParams params;
    params.vertexCount = 500;
    params.threads = 2;
    const RemeshResult coarse = remesh(dense, params);
    ASSERT_GT(coarse.optimisationFaces, 0);
    EXPECT_LE(coarse.optimisationFaces, params.optimisationFacesPerSample * params.vertexCount + 2);
    params.optimisationFacesPerSample = 0;
    const RemeshResult full = remesh(dense, params);
    EXPECT_EQ(full.optimisationFaces, dense.faceCount());

    const ClosestPointTree tree(dense);
    const double diagonal = boundingBoxDiagonal(dense);
    for (const Vec3& p : coarse.mesh.vertices) EXPECT_LT((tree.closest(p).point - p).norm(), 1e-9 * diagonal);
    EXPECT_EQ(coarse.outputTopology.genus, 1);
    EXPECT_TRUE(coarse.outputTopology.manifold());
    EXPECT_GT(coarse.metrics.qAvg, full.metrics.qAvg - 0.01);
    EXPECT_GT(coarse.metrics.v6Pct, full.metrics.v6Pct - 3);
    EXPECT_GT(coarse.metrics.thetaMin, 30);
    EXPECT_LT(coarse.metrics.dH, 1.2 * full.metrics.dH);
}

// The coarse surface's size: 4 faces a sample below the cap, the cap above it, never fewer
// than 2 a sample; a cap of 0 gives 2 a sample, a per-sample count of 0 no coarse surface.
TEST(Simplify, OptimisationFaceTargetCapsLargeRuns)
{
    RemeshParams params;
    EXPECT_EQ(optimisationFaceTarget(params, 5000), 20000);     // the shared rows: 4 a sample
    EXPECT_EQ(optimisationFaceTarget(params, 50000), 200000);   // at the cap
    EXPECT_EQ(optimisationFaceTarget(params, 75000), 200000);   // capped: 2.7 a sample
    EXPECT_EQ(optimisationFaceTarget(params, 400000), 800000);  // 2 a sample, over the cap
    EXPECT_EQ(optimisationFaceTarget(params, 5000000), 10000000);
    params.optimisationFacesCap = 0;
    EXPECT_EQ(optimisationFaceTarget(params, 5000), 10000);
    params.optimisationFacesPerSample = 1;  // fewer than 2 asked for: as asked
    EXPECT_EQ(optimisationFaceTarget(params, 5000), 5000);
    params.optimisationFacesPerSample = 0;
    EXPECT_EQ(optimisationFaceTarget(params, 5000), 0);
    params.optimisationFacesCap = -1;
    params.vertexCount = 100;
    EXPECT_THROW(remesh(testmesh::icosphere(2), params), InvalidInputError);
}
