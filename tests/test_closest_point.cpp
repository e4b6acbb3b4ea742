// Closest point on a triangle and the AABB tree, checked against brute force.
#include "closest_point.h"
#include "errors.h"
#include "test_meshes.h"
#include "thread_count.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <random>

namespace fieldcvt {
namespace {

using testmesh::icosphere;
using testmesh::torus;

//! Brute-force reference: every face, lowest index wins exact ties (as the tree promises).
ClosestPoint bruteForce(const TriMesh& mesh, const Vec3& p)
{
    ClosestPoint best;
    best.squaredDistance = std::numeric_limits<double>::infinity();
    for (int f = 0; f < mesh.faceCount(); ++f) {
        const Face& t = mesh.faces[f];
        Vec3 bary;
        const Vec3 q = closestPointOnTriangle(p, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], &bary);
        const double d2 = (q - p).squaredNorm();
        if (d2 < best.squaredDistance) {
            best.squaredDistance = d2;
            best.point = q;
            best.face = f;
            best.barycentric = bary;
        }
    }
    return best;
}

Vec3 randomPoint(std::mt19937_64& rng, double halfExtent)
{
    std::uniform_real_distribution<double> u(-halfExtent, halfExtent);
    const double x = u(rng), y = u(rng), z = u(rng);
    return Vec3(x, y, z);
}

void expectTreeMatchesBruteForce(const TriMesh& mesh, int queries, double halfExtent, std::uint64_t seed)
{
    const ClosestPointTree tree(mesh);
    std::mt19937_64 rng(seed);
    for (int i = 0; i < queries; ++i) {
        const Vec3 p = randomPoint(rng, halfExtent);
        const ClosestPoint expected = bruteForce(mesh, p);
        const ClosestPoint got = tree.closest(p);
        ASSERT_NEAR(std::sqrt(got.squaredDistance), std::sqrt(expected.squaredDistance), 1e-12) << "query " << i;
        EXPECT_NEAR((got.point - p).squaredNorm(), got.squaredDistance, 1e-12);
        ASSERT_GE(got.face, 0);
        ASSERT_LT(got.face, mesh.faceCount());
        // The reported face and barycentric coordinates reproduce the point.
        const Face& t = mesh.faces[got.face];
        const Vec3 fromBary = got.barycentric[0] * mesh.vertices[t[0]] + got.barycentric[1] * mesh.vertices[t[1]] +
                              got.barycentric[2] * mesh.vertices[t[2]];
        EXPECT_NEAR((fromBary - got.point).norm(), 0.0, 1e-12);
        EXPECT_NEAR(got.barycentric.sum(), 1.0, 1e-14);
        EXPECT_GE(got.barycentric.minCoeff(), 0.0);
    }
}

TEST(ClosestPointTriangle, RegionsOfAPlainTriangle)
{
    const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
    Vec3 bary;
    // Above the interior: orthogonal projection.
    Vec3 q = closestPointOnTriangle(Vec3(0.5, 0.5, 3), a, b, c, &bary);
    EXPECT_NEAR((q - Vec3(0.5, 0.5, 0)).norm(), 0, 1e-15);
    EXPECT_NEAR(bary[0], 0.5, 1e-15);
    EXPECT_NEAR(bary[1], 0.25, 1e-15);
    EXPECT_NEAR(bary[2], 0.25, 1e-15);
    // Vertex regions.
    q = closestPointOnTriangle(Vec3(-1, -1, 1), a, b, c, &bary);
    EXPECT_NEAR((q - a).norm(), 0, 1e-15);
    EXPECT_NEAR(bary[0], 1, 1e-15);
    q = closestPointOnTriangle(Vec3(5, -1, 0), a, b, c, &bary);
    EXPECT_NEAR((q - b).norm(), 0, 1e-15);
    EXPECT_NEAR(bary[1], 1, 1e-15);
    // Edge regions: below ab, and beyond the hypotenuse bc.
    q = closestPointOnTriangle(Vec3(1.5, -3, 2), a, b, c, &bary);
    EXPECT_NEAR((q - Vec3(1.5, 0, 0)).norm(), 0, 1e-15);
    EXPECT_NEAR(bary[1], 0.75, 1e-15);
    EXPECT_NEAR(bary[2], 0, 0);
    q = closestPointOnTriangle(Vec3(2, 2, -1), a, b, c, &bary);
    EXPECT_NEAR((q - Vec3(1, 1, 0)).norm(), 0, 1e-15);
    EXPECT_NEAR(bary[0], 0, 0);
    EXPECT_NEAR(bary.sum(), 1, 1e-15);
}

TEST(ClosestPointTriangle, DegenerateTrianglesGiveSegmentAnswers)
{
    Vec3 bary;
    // Collinear corners: the closest point on the segment they span.
    const Vec3 a(0, 0, 0), b(1, 0, 0), c(3, 0, 0);
    Vec3 q = closestPointOnTriangle(Vec3(2, 1, 0), a, b, c, &bary);
    EXPECT_NEAR((q - Vec3(2, 0, 0)).norm(), 0, 1e-15);
    EXPECT_NEAR(bary.sum(), 1, 1e-15);
    EXPECT_TRUE(bary.allFinite());
    q = closestPointOnTriangle(Vec3(-2, 1, 0), a, b, c, &bary);
    EXPECT_NEAR((q - a).norm(), 0, 1e-15);
    // All corners equal.
    q = closestPointOnTriangle(Vec3(1, 2, 3), Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, 1), &bary);
    EXPECT_NEAR((q - Vec3(1, 1, 1)).norm(), 0, 0);
    EXPECT_NEAR(bary.sum(), 1, 1e-15);
    EXPECT_TRUE(bary.allFinite());
}

TEST(ClosestPointTriangle, NeedleTriangleMatchesItsLongEdges)
{
    // A needle of width 1e-9 and length 1: the distance from a point beside it is the distance
    // to its long side, to rounding.
    const Vec3 a(0, 0, 0), b(1, 0, 0), c(0.5, 1e-9, 0);
    Vec3 bary;
    const Vec3 p(0.3, 0.2, 0.1);
    const Vec3 q = closestPointOnTriangle(p, a, b, c, &bary);
    const double expected = std::sqrt(0.2 * 0.2 + 0.1 * 0.1);  // to the line y = 0 (at most 1e-9 off)
    EXPECT_NEAR((q - p).norm(), expected, 2e-9);
    EXPECT_NEAR(bary.sum(), 1, 1e-15);
    EXPECT_GE(bary.minCoeff(), 0.0);
    // A point above the needle's interior projects into it.
    const Vec3 above(0.5, 0.5e-9, 1.0);
    const Vec3 qa = closestPointOnTriangle(above, a, b, c, &bary);
    EXPECT_NEAR((qa - above).norm(), 1.0, 1e-12);
}

TEST(ClosestPointTree, MatchesBruteForceOnIcosphere) { expectTreeMatchesBruteForce(icosphere(3), 3000, 1.6, 11); }

TEST(ClosestPointTree, MatchesBruteForceOnTorus) { expectTreeMatchesBruteForce(torus(40, 24), 3000, 1.6, 12); }

// From 100 000 faces the tree's subtrees are built on threads: still exact, and the same answers
// (faces, points) as built on one thread.
TEST(ClosestPointTree, BuiltOnThreadsMatchesBruteForceAndOneThread)
{
    const TriMesh mesh = torus(400, 130);  // 104 000 faces
    expectTreeMatchesBruteForce(mesh, 40, 1.6, 13);
    const auto one = testthreads::withThreadCount(1, [&] { return std::make_unique<ClosestPointTree>(mesh); });
    const auto three = testthreads::withThreadCount(3, [&] { return std::make_unique<ClosestPointTree>(mesh); });
    std::mt19937_64 rng(14);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 p = randomPoint(rng, 1.6);
        const ClosestPoint a = one->closest(p), b = three->closest(p);
        ASSERT_EQ(a.face, b.face) << i;
        ASSERT_EQ(a.point, b.point) << i;
    }
}

TEST(ClosestPointTree, PointsOnTheSurfaceHaveZeroDistance)
{
    const TriMesh mesh = icosphere(2);
    const ClosestPointTree tree(mesh);
    for (int f = 0; f < mesh.faceCount(); ++f) {
        const Face& t = mesh.faces[f];
        const Vec3 centroid = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
        const ClosestPoint cp = tree.closest(centroid);
        EXPECT_EQ(cp.face, f);
        EXPECT_LT(cp.squaredDistance, 1e-28);
        EXPECT_NEAR(cp.barycentric[0], 1.0 / 3, 1e-12);
    }
}

TEST(ClosestPointTree, ExactTiesGoToTheLowestFace)
{
    // A mesh vertex belongs to 5 or 6 faces at distance 0: the lowest index must be reported.
    const TriMesh mesh = icosphere(2);
    const ClosestPointTree tree(mesh);
    for (int v = 0; v < mesh.vertexCount(); ++v) {
        int lowest = -1;
        for (int f = 0; f < mesh.faceCount() && lowest < 0; ++f)
            for (int k : mesh.faces[f])
                if (k == v) lowest = f;
        const ClosestPoint cp = tree.closest(mesh.vertices[v]);
        EXPECT_EQ(cp.squaredDistance, 0.0);
        EXPECT_EQ(cp.face, lowest) << "vertex " << v;
    }
}

TEST(ClosestPointTree, EmptyMeshAndBadIndices)
{
    const TriMesh empty;
    const ClosestPointTree tree(empty);
    const ClosestPoint cp = tree.closest(Vec3(1, 2, 3));
    EXPECT_EQ(cp.face, -1);
    EXPECT_TRUE(std::isinf(cp.squaredDistance));

    TriMesh bad = icosphere(0);
    bad.faces[3][1] = 99;
    EXPECT_THROW(ClosestPointTree{bad}, InvalidInputError);
}

// SurfaceWalk: starts a sample spacing away from the answer, as the valence stage's sag checks
// do (a corner's closest face for an edge midpoint or a face centroid).
struct WalkCounts {
    int queries = 0, exact = 0, settled = 0, startExact = 0;  //!< startExact: the start face holds the answer
};

WalkCounts walkFromNeighbourhood(const TriMesh& mesh, double offset, std::uint64_t seed)
{
    const ClosestPointTree tree(mesh);
    const SurfaceWalk walk(mesh);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    WalkCounts counts;
    for (int f = 0; f < mesh.faceCount(); ++f) {
        const Face& t = mesh.faces[f];
        const Vec3 centroid = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
        const double edge = (mesh.vertices[t[1]] - mesh.vertices[t[0]]).norm();
        // Up to about two faces away from f along the surface, a little off it.
        const Vec3 ab = mesh.vertices[t[1]] - mesh.vertices[t[0]], ac = mesh.vertices[t[2]] - mesh.vertices[t[0]];
        const Vec3 normal = ab.cross(ac).normalized();
        Vec3 along(u(rng), u(rng), u(rng));
        along -= along.dot(normal) * normal;
        const Vec3 p = centroid + 1.5 * edge * along + offset * edge * u(rng) * normal;
        const ClosestPoint exact = tree.closest(p);
        const double exactDistance = (exact.point - p).norm();
        const double bound = walk.distanceBound(p, f);
        EXPECT_GE(bound, exactDistance) << "face " << f;  // never below the exact distance
        // closestFrom is the same walk's point: on its face, at the bound's distance, and where
        // it settled at the tree's distance it is the tree's point (on a shared edge or corner
        // the face may be the other one: the tree takes the lowest index).
        bool settled = false;
        const ClosestPoint local = walk.closestFrom(p, f, &settled);
        EXPECT_EQ((local.point - p).norm(), bound) << "face " << f;
        EXPECT_EQ(local.squaredDistance, (local.point - p).squaredNorm()) << "face " << f;
        const Face& g = mesh.faces[local.face];
        const Vec3 fromBarycentric = local.barycentric[0] * mesh.vertices[g[0]] + local.barycentric[1] * mesh.vertices[g[1]] +
                                     local.barycentric[2] * mesh.vertices[g[2]];
        EXPECT_LT((fromBarycentric - local.point).norm(), 1e-12 * (1 + p.norm())) << "face " << f;
        if (settled && bound == exactDistance)
            EXPECT_LT((local.point - exact.point).norm(), 1e-12 * (1 + p.norm())) << "face " << f;
        ++counts.queries;
        counts.exact += bound == exactDistance;
        counts.settled += settled;
        counts.startExact += exact.face == f;
    }
    return counts;
}

TEST(SurfaceWalk, BoundsTheDistanceAndUsuallyEqualsIt)
{
    for (const TriMesh& mesh : {icosphere(3), torus(40, 24)}) {
        const WalkCounts near = walkFromNeighbourhood(mesh, 0.2, 21);
        // Bit for bit the tree's answer on almost every query (the same triangle test), though the
        // start face holds the answer only for a few: the walk does the work.
        EXPECT_GE(near.exact, 0.97 * near.queries) << near.exact << " of " << near.queries;
        EXPECT_LE(near.startExact, 0.2 * near.queries);
        EXPECT_GE(near.settled, 0.97 * near.queries);  // within its steps from two faces away
    }
}

TEST(SurfaceWalk, StopsAtTheBorderAndRejectsBadStarts)
{
    const TriMesh grid = testmesh::planeGrid(8);
    const SurfaceWalk walk(grid);
    const ClosestPointTree tree(grid);
    // Beyond the border: the bound is still a surface point's distance, at least the exact one.
    for (int f = 0; f < grid.faceCount(); f += 7) {
        const Vec3 p(1.7, -0.4, 0.3);
        EXPECT_GE(walk.distanceBound(p, f), (tree.closest(p).point - p).norm());
    }
    EXPECT_TRUE(std::isinf(walk.distanceBound(Vec3::Zero(), -1)));
    bool settled = true;
    EXPECT_EQ(walk.closestFrom(Vec3::Zero(), -1, &settled).face, -1);
    EXPECT_FALSE(settled);
    EXPECT_TRUE(std::isinf(walk.distanceBound(Vec3::Zero(), grid.faceCount())));
}

}  // namespace
}  // namespace fieldcvt
