// The shared edge table (mesh_edges.h) on small meshes, pinned edge by edge.
#include "errors.h"
#include "mesh_edges.h"
#include "test_meshes.h"
#include "thread_count.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>

using namespace fieldcvt;

namespace {

TriMesh meshOf(int vertexCount, std::vector<Face> faces)
{
    TriMesh m;
    for (int v = 0; v < vertexCount; ++v) m.vertices.emplace_back(double(v), double(v * v % 7), double(v % 3));
    m.faces = std::move(faces);
    return m;
}

using Ends = std::vector<std::array<int, 2>>;

//! Per edge, its faces in order.
std::vector<std::vector<int>> facesOfEdges(const EdgeTable& t)
{
    std::vector<std::vector<int>> out(t.edgeCount());
    for (int e = 0; e < t.edgeCount(); ++e)
        for (int i = 0; i < t.faceCount(e); ++i) out[e].push_back(t.face(e, i));
    return out;
}

//! Every half-edge h lies on the edge of its two vertices and is listed under it.
void expectConsistent(const std::vector<Face>& faces, const EdgeTable& t)
{
    ASSERT_EQ(t.first.size(), t.ends.size() + 1);
    EXPECT_TRUE(std::is_sorted(t.ends.begin(), t.ends.end()));
    EXPECT_TRUE(std::adjacent_find(t.ends.begin(), t.ends.end()) == t.ends.end());
    for (int f = 0; f < static_cast<int>(faces.size()); ++f)
        for (int k = 0; k < 3; ++k) {
            const int e = t.edgeOf(f, k);
            ASSERT_GE(e, 0);
            const auto [a, b] = std::minmax(faces[f][k], faces[f][(k + 1) % 3]);
            EXPECT_EQ(t.ends[e], (std::array<int, 2>{a, b}));
            EXPECT_EQ(halfEdgeOrigin(faces, 3 * f + k), faces[f][k]);
            bool listed = false;
            for (int i = 0; i < t.faceCount(e); ++i) listed |= t.halfEdge(e, i) == 3 * f + k;
            EXPECT_TRUE(listed);
        }
    for (int e = 0; e < t.edgeCount(); ++e)
        for (int i = 1; i < t.faceCount(e); ++i) EXPECT_LT(t.halfEdge(e, i - 1), t.halfEdge(e, i));
}

}  // namespace

TEST(MeshEdges, SingleTriangle)
{
    const TriMesh m = meshOf(3, {{0, 1, 2}});
    const EdgeTable t = buildEdgeTable(m);
    expectConsistent(m.faces, t);
    EXPECT_EQ(t.ends, (Ends{{0, 1}, {0, 2}, {1, 2}}));
    for (int e = 0; e < 3; ++e) {
        EXPECT_EQ(t.faceCount(e), 1);
        EXPECT_TRUE(t.isBorder(e));
        EXPECT_FALSE(t.isNonManifold(e));
        EXPECT_EQ(t.face(e, 0), 0);
        EXPECT_FALSE(t.firstTwoSameDirection(m.faces, e));
    }
    // Side k runs from corner k to k + 1: (0,1), (1,2), (2,0).
    EXPECT_EQ(t.edgeOf(0, 0), 0);
    EXPECT_EQ(t.edgeOf(0, 1), 2);
    EXPECT_EQ(t.edgeOf(0, 2), 1);
    EXPECT_EQ(t.halfEdge(1, 0), 2);
}

TEST(MeshEdges, TwoTrianglesSharingAnEdge)
{
    const TriMesh m = meshOf(4, {{0, 1, 2}, {2, 1, 3}});
    const EdgeTable t = buildEdgeTable(m);
    expectConsistent(m.faces, t);
    EXPECT_EQ(t.ends, (Ends{{0, 1}, {0, 2}, {1, 2}, {1, 3}, {2, 3}}));
    EXPECT_EQ(facesOfEdges(t), (std::vector<std::vector<int>>{{0}, {0}, {0, 1}, {1}, {1}}));
    const int shared = t.find(2, 1);
    EXPECT_EQ(shared, 2);
    EXPECT_EQ(t.find(1, 2), 2);
    EXPECT_FALSE(t.isBorder(shared));
    EXPECT_EQ(t.face(shared, 0), 0);
    EXPECT_EQ(t.face(shared, 1), 1);
    EXPECT_FALSE(t.firstTwoSameDirection(m.faces, shared));  // consistently oriented
    EXPECT_EQ(t.find(0, 3), -1);
    EXPECT_EQ(t.find(7, 9), -1);
    EXPECT_EQ(t.edgeOf(1, 0), shared);

    // The second face flipped: both run 1 -> 2.
    const TriMesh flipped = meshOf(4, {{0, 1, 2}, {1, 2, 3}});
    const EdgeTable tf = buildEdgeTable(flipped);
    EXPECT_TRUE(tf.firstTwoSameDirection(flipped.faces, tf.find(1, 2)));
}

TEST(MeshEdges, ClosedTetrahedron)
{
    const TriMesh m = meshOf(4, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}});
    const EdgeTable t = buildEdgeTable(m);
    expectConsistent(m.faces, t);
    EXPECT_EQ(t.ends, (Ends{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}));
    EXPECT_EQ(facesOfEdges(t), (std::vector<std::vector<int>>{{0, 1}, {0, 3}, {1, 3}, {0, 2}, {1, 2}, {2, 3}}));
    for (int e = 0; e < t.edgeCount(); ++e) {
        EXPECT_EQ(t.faceCount(e), 2);
        EXPECT_FALSE(t.firstTwoSameDirection(m.faces, e));
    }
    EXPECT_EQ(t.halfEdges.size(), 12u);
}

TEST(MeshEdges, NonManifoldFanOfThreeTriangles)
{
    // Three triangles on edge {0, 1}.
    const TriMesh m = meshOf(5, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
    const EdgeTable t = buildEdgeTable(m);
    expectConsistent(m.faces, t);
    const int e = t.find(0, 1);
    ASSERT_EQ(e, 0);
    EXPECT_EQ(t.faceCount(e), 3);
    EXPECT_TRUE(t.isNonManifold(e));
    EXPECT_EQ(facesOfEdges(t)[e], (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(t.halfEdge(e, 0), 0);
    EXPECT_EQ(t.halfEdge(e, 1), 3);
    EXPECT_EQ(t.halfEdge(e, 2), 6);
    EXPECT_FALSE(t.firstTwoSameDirection(m.faces, e));  // faces 0 and 1 are opposed
    int border = 0;
    for (int k = 0; k < t.edgeCount(); ++k) border += t.isBorder(k);
    EXPECT_EQ(border, 6);
    EXPECT_EQ(t.edgeCount(), 7);
}

TEST(MeshEdges, OpenStrip)
{
    // Four triangles in a row: 0-1-2-3 along the bottom, 4-5-6 along the top.
    //   4---5---6
    //   | \ | \ |
    //   0---1---2
    const TriMesh m = meshOf(7, {{0, 1, 4}, {1, 5, 4}, {1, 2, 5}, {2, 6, 5}});
    const EdgeTable t = buildEdgeTable(m);
    expectConsistent(m.faces, t);
    EXPECT_EQ(t.ends, (Ends{{0, 1}, {0, 4}, {1, 2}, {1, 4}, {1, 5}, {2, 5}, {2, 6}, {4, 5}, {5, 6}}));
    Ends border, interior;
    for (int e = 0; e < t.edgeCount(); ++e) (t.isBorder(e) ? border : interior).push_back(t.ends[e]);
    EXPECT_EQ(border, (Ends{{0, 1}, {0, 4}, {1, 2}, {2, 6}, {4, 5}, {5, 6}}));
    EXPECT_EQ(interior, (Ends{{1, 4}, {1, 5}, {2, 5}}));
    EXPECT_EQ(facesOfEdges(t)[t.find(1, 5)], (std::vector<int>{1, 2}));
}

TEST(MeshEdges, FacesRepeatingAVertexAreKeptOrSkipped)
{
    const TriMesh m = meshOf(4, {{0, 1, 2}, {1, 2, 1}, {2, 1, 3}});
    const EdgeTable kept = buildEdgeTable(m);
    expectConsistent(m.faces, kept);
    EXPECT_EQ(kept.ends, (Ends{{0, 1}, {0, 2}, {1, 1}, {1, 2}, {1, 3}, {2, 3}}));
    // {1, 2}: face 0, face 1 twice (1->2 and 2->1), face 2.
    EXPECT_EQ(facesOfEdges(kept)[kept.find(1, 2)], (std::vector<int>{0, 1, 1, 2}));

    const EdgeTable skipped = buildEdgeTable(m, RepeatedVertexFaces::Skip);
    EXPECT_EQ(skipped.ends, (Ends{{0, 1}, {0, 2}, {1, 2}, {1, 3}, {2, 3}}));
    EXPECT_EQ(facesOfEdges(skipped)[skipped.find(1, 2)], (std::vector<int>{0, 2}));
    for (int k = 0; k < 3; ++k) EXPECT_EQ(skipped.edgeOf(1, k), -1);
}

TEST(MeshEdges, FirstHalfEdgeFromAVertex)
{
    // Edge {0, 1} in four faces: 0->1 (face 0), 1->0 (face 1), 0->1 (face 2), 1->0 (face 3).
    const TriMesh m = meshOf(6, {{0, 1, 2}, {1, 0, 3}, {4, 0, 1}, {5, 1, 0}});
    const EdgeTable t = buildEdgeTable(m);
    const int e = t.find(0, 1);
    EXPECT_EQ(t.firstHalfEdgeFrom(m.faces, e, 0), 0);   // face 0, corner 0
    EXPECT_EQ(t.firstHalfEdgeFrom(m.faces, e, 1), 3);   // face 1, corner 0
    EXPECT_EQ(t.firstHalfEdgeFrom(m.faces, e, 4), -1);  // not an end of e
    // A border edge has no opposite half-edge.
    const int border = t.find(1, 2);
    EXPECT_EQ(t.firstHalfEdgeFrom(m.faces, border, 1), 1);
    EXPECT_EQ(t.firstHalfEdgeFrom(m.faces, border, 2), -1);
    // The opposite of a half-edge from a to b is the first half-edge from b on its edge.
    for (int f = 0; f < m.faceCount(); ++f)
        for (int k = 0; k < 3; ++k) {
            const int h = t.firstHalfEdgeFrom(m.faces, t.edgeOf(f, k), m.faces[f][(k + 1) % 3]);
            if (h >= 0) EXPECT_EQ(m.faces[h / 3][(h % 3 + 1) % 3], m.faces[f][k]);
        }
}

TEST(MeshEdges, EmptyMeshAndOutOfRangeIndex)
{
    const EdgeTable empty = buildEdgeTable(TriMesh{});
    EXPECT_EQ(empty.edgeCount(), 0);
    EXPECT_EQ(empty.first, (std::vector<int>{0}));
    EXPECT_THROW(buildEdgeTable(meshOf(3, {{0, 1, 3}})), InvalidInputError);
    EXPECT_THROW(buildEdgeTable(meshOf(3, {{0, -1, 2}})), InvalidInputError);
}

TEST(MeshEdges, MatchesAPlainSortOnATorus)
{
    // Reference: sort (smaller, larger, half-edge) triples.
    const TriMesh m = testmesh::torus(23, 17);
    std::vector<std::tuple<int, int, int>> sides;
    for (int f = 0; f < m.faceCount(); ++f)
        for (int k = 0; k < 3; ++k) {
            const auto [a, b] = std::minmax(m.faces[f][k], m.faces[f][(k + 1) % 3]);
            sides.emplace_back(a, b, 3 * f + k);
        }
    std::sort(sides.begin(), sides.end());
    const EdgeTable t = buildEdgeTable(m);
    expectConsistent(m.faces, t);
    ASSERT_EQ(t.halfEdges.size(), sides.size());
    for (size_t i = 0; i < sides.size(); ++i) EXPECT_EQ(t.halfEdges[i], std::get<2>(sides[i]));
    EXPECT_EQ(t.edgeCount(), 3 * 23 * 17);  // V - E + F = 0
    for (int e = 0; e < t.edgeCount(); ++e) EXPECT_EQ(t.faceCount(e), 2);
}

// Big tables are filled on threads (by buckets of the smaller vertex): the same table on any
// thread count.
TEST(EdgeTable, SameOnAnyThreadCount)
{
    const TriMesh m = testmesh::icosphere(6);  // 245 760 half-edges: above the threads' threshold
    const EdgeTable one = testthreads::withThreadCount(1, [&] { return buildEdgeTable(m); });
    const EdgeTable three = testthreads::withThreadCount(3, [&] { return buildEdgeTable(m); });
    EXPECT_EQ(one.ends, three.ends);
    EXPECT_EQ(one.first, three.first);
    EXPECT_EQ(one.halfEdges, three.halfEdges);
    EXPECT_EQ(one.halfEdgeEdge, three.halfEdgeEdge);
    EXPECT_EQ(one.edgeCount(), 3 * m.faceCount() / 2);
    expectConsistent(m.faces, three);
}
