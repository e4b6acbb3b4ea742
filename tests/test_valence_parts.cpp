// The valence stage's parts: the editable mesh's undo (every array as it was after flips,
// collapses, splits and moves are taken back) and the sag guard (its cached answers are the
// exact sags' answers on a real mesh, before and after its vertices move).
#include "closest_point.h"
#include "editable_mesh.h"
#include "mesh_io.h"
#include "simplify.h"
#include "test_meshes.h"
#include "valence/operations.h"
#include "valence/sag_guard.h"
#include "valence/valence_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>
#include <vector>

using namespace fieldcvt;
using namespace fieldcvt::valence;

namespace {

//! Every array of an editable mesh, for exact comparison.
template <class VertexData, class DataKey>
auto snapshot(const EditableMesh<VertexData>& m, DataKey&& key)
{
    std::vector<Vec3> positions;
    std::vector<decltype(key(m.data(0)))> data;
    std::vector<bool> vertexAlive, faceAlive;
    std::vector<Face> faces;
    std::vector<std::vector<int>> lists;
    for (int v = 0; v < m.vertexCount(); ++v) {
        positions.push_back(m.position(v));
        data.push_back(key(m.data(v)));
        vertexAlive.push_back(m.vertexAlive(v));
        lists.push_back(m.facesOf(v));
    }
    for (int f = 0; f < m.faceCount(); ++f) faces.push_back(m.face(f)), faceAlive.push_back(m.faceAlive(f));
    return std::make_tuple(positions, data, vertexAlive, faces, faceAlive, lists);
}

auto meshVertexKey = [](const MeshVertex& d) {
    return std::make_tuple(d.closest.point, d.closest.face, d.closest.barycentric, d.closest.squaredDistance, d.normal, d.role,
                           d.onBorder, d.manifold, d.valence);
};

//! A torus (R = 1, r = 0.35) of n x m vertices, rows alternating their offset: every vertex of
//! valence 6.
TriMesh torus(int n, int m)
{
    TriMesh t;
    const double pi = 3.14159265358979323846;
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < n; ++i) {
            const double u = 2 * pi * (i + 0.5 * (j % 2)) / n, v = 2 * pi * j / m;
            t.vertices.emplace_back((1 + 0.35 * std::cos(v)) * std::cos(u), (1 + 0.35 * std::cos(v)) * std::sin(u),
                                    0.35 * std::sin(v));
        }
    auto id = [n, m](int i, int j) { return ((j + m) % m) * n + (i + n) % n; };
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < n; ++i) {
            if (j % 2 == 0) {
                t.faces.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
                t.faces.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
            } else {
                t.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
                t.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            }
        }
    return t;
}

}  // namespace

TEST(EditableMesh, RollbackRestoresEveryArrayAndCommitKeepsTheEdits)
{
    const TriMesh start = torus(12, 8);
    EditableMesh<int> mesh(start.vertices, start.faces, 7);
    auto key = [](int d) { return d; };
    const auto before = snapshot(mesh, key);
    EXPECT_EQ(mesh.facesOf(0).size(), 6u);
    EXPECT_TRUE(std::is_sorted(mesh.facesOf(0).begin(), mesh.facesOf(0).end()));

    const auto outer = mesh.begin();
    const int f = mesh.facesOf(5)[0];
    const Face t = mesh.face(f);
    mesh.killFace(f);
    const int w = mesh.addVertex(Vec3(3, 2, 1), 9);
    mesh.addFace({t[0], t[1], w});
    mesh.setVertex(t[2], Vec3(-1, 0, 0), 11);
    const auto inner = mesh.begin();  // a nested edit (a look-ahead step inside a tried operation)
    const int g = mesh.facesOf(20)[1];
    mesh.renameCorner(g, 20, w);
    mesh.killVertex(20);
    mesh.setData(w, 13);
    EXPECT_TRUE(mesh.hasCorner(g, w));
    EXPECT_FALSE(mesh.hasCorner(g, 20));
    EXPECT_TRUE(std::is_sorted(mesh.facesOf(w).begin(), mesh.facesOf(w).end()));
    mesh.rollback(inner);
    EXPECT_TRUE(mesh.logging());  // the outer edit's log is still open
    EXPECT_EQ(mesh.data(w), 9);
    EXPECT_TRUE(mesh.vertexAlive(20));
    EXPECT_FALSE(mesh.faceAlive(f));
    mesh.rollback(outer);
    EXPECT_FALSE(mesh.logging());
    EXPECT_EQ(snapshot(mesh, key), before);

    // Committed edits stay (and are no longer in the log); unlogged edits are not undone.
    const auto kept = mesh.begin();
    mesh.setVertex(3, Vec3(0, 0, 5), 1);
    mesh.commit(kept);
    mesh.setVertex(4, Vec3(0, 0, 6), 2);
    const auto after = snapshot(mesh, key);
    mesh.rollback(mesh.begin());
    EXPECT_EQ(snapshot(mesh, key), after);
    EXPECT_EQ(mesh.position(3), Vec3(0, 0, 5));
    EXPECT_EQ(mesh.data(4), 2);
}

TEST(ValenceMesh, FlipCollapseSplitAndSmoothingAreUndoneExactly)
{
    // A regular torus with planted flips (vertices of valence 5 and 7), on the regular torus.
    const TriMesh surfaceMesh = torus(16, 10);
    TriMesh start = surfaceMesh;
    for (int f : {20, 90, 150}) {
        const Face a = start.faces[f], b = start.faces[f + 1];
        for (int k = 0; k < 3; ++k)
            for (int l = 0; l < 3; ++l)
                if (b[l] == a[(k + 1) % 3] && b[(l + 1) % 3] == a[k]) {
                    start.faces[f] = {b[(l + 2) % 3], a[(k + 1) % 3], a[(k + 2) % 3]};
                    start.faces[f + 1] = {a[(k + 2) % 3], a[k], b[(l + 2) % 3]};
                    k = l = 3;
                }
    }
    const ClosestPointTree tree(surfaceMesh);
    const ValenceSurface surface{surfaceMesh, tree, {}, nullptr, {}};
    ValenceMesh mesh(start, {}, surface, 4, {});
    const auto before = snapshot(mesh, meshVertexKey);
    const long long irregularityBefore = mesh.irregularity();
    EXPECT_GT(irregularityBefore, 0);

    // One operation of each kind, each checked against R measured before and after.
    Op flip, collapse, split;
    for (int a = 0; a < mesh.vertexCount() && (flip.type == OpType::None || collapse.type == OpType::None); ++a) {
        Ring r;
        mesh.ring(a, r);
        for (int b : r.verts) {
            int gain, c, d, f1, f2, keep, remove;
            if (a < b && flip.type == OpType::None && evaluateFlip(mesh, a, b, gain, c, d, f1, f2))
                flip = {OpType::Flip, a, b, -1, gain};
            if (a < b && collapse.type == OpType::None && evaluateCollapse(mesh, a, b, gain, keep, remove) &&
                std::abs(a - flip.a) > 40)
                collapse = {OpType::Collapse, a, b, -1, gain};
        }
    }
    for (int v = 0; v < mesh.vertexCount() && split.type == OpType::None; ++v) {
        Ring r;
        mesh.ring(v, r);
        if (std::abs(v - flip.a) < 40 || std::abs(v - collapse.a) < 40 || r.verts.size() < 6) continue;
        const int n = static_cast<int>(r.verts.size()), s = 3;
        const int a = r.verts[0], b = r.verts[s];
        const int gain = (s + 2 - 6) * (s + 2 - 6) + (n - s + 2 - 6) * (n - s + 2 - 6) - (n - 6) * (n - 6) +
                         mesh.valenceDelta(a, +1) + mesh.valenceDelta(b, +1);
        split = {OpType::Split, v, a, b, gain};
    }
    ASSERT_NE(flip.type, OpType::None);
    ASSERT_NE(collapse.type, OpType::None);
    ASSERT_NE(split.type, OpType::None);

    const auto edit = mesh.begin();
    std::vector<int> smooth, changed;
    long long expected = irregularityBefore;
    for (const Op& op : {flip, collapse, split}) {
        smooth.clear();
        ASSERT_TRUE(applyTopology(mesh, op, smooth, changed)) << static_cast<int>(op.type);
        mesh.refreshValences(smooth);
        expected += op.gain;
        EXPECT_EQ(mesh.irregularity(), expected) << static_cast<int>(op.type);
        mesh.smoothLocally(smooth, 2);
    }
    EXPECT_EQ(mesh.vertexCount(), start.vertexCount() + 1);  // the split's vertex
    EXPECT_FALSE(mesh.vertexAlive(std::max(collapse.a, collapse.b)) && mesh.vertexAlive(std::min(collapse.a, collapse.b)));
    EXPECT_NE(snapshot(mesh, meshVertexKey), before);
    mesh.rollback(edit);
    EXPECT_EQ(snapshot(mesh, meshVertexKey), before);
    EXPECT_EQ(mesh.irregularity(), irregularityBefore);
    // A stale operation (its ΔR no longer the mesh's) is refused.
    Op stale = flip;
    stale.gain += 1;
    smooth.clear();
    const auto refused = mesh.begin();
    EXPECT_FALSE(applyTopology(mesh, stale, smooth, changed));
    mesh.rollback(refused);
    EXPECT_EQ(snapshot(mesh, meshVertexKey), before);
}

TEST(ValenceSagGuard, CachedAnswersAreTheExactSagsAnswers)
{
    // A coarse copy of fertility lies on it with real sags (its vertices are input vertices).
    const TriMesh input = readMesh(testmesh::resource("fertility.off"));
    SimplifyParams simplify;
    simplify.targetFaces = 1200;
    simplify.maxError = 1e9;
    const TriMesh coarse = simplifyMesh(input, simplify).mesh;
    const ClosestPointTree tree(input);
    const ValenceSurface surface{input, tree, {}, nullptr, {}};
    ValenceMesh mesh(coarse, {}, surface, 4, {});
    SagGuard guard(mesh);

    // The uncached answer: the largest exact distance of the centroid and edge midpoints.
    auto exactSag = [&](int f) {
        const Face& t = mesh.face(f);
        const Vec3 &a = mesh.position(t[0]), &b = mesh.position(t[1]), &c = mesh.position(t[2]);
        double sag = 0;
        for (const Vec3& p : {Vec3((a + b + c) / 3.0), Vec3(0.5 * (a + b)), Vec3(0.5 * (b + c)), Vec3(0.5 * (c + a))})
            sag = std::max(sag, (tree.closest(p).point - p).norm());
        return sag;
    };
    int checked = 0, over = 0;
    auto compareAll = [&](bool measureFirst) {
        for (int f = 0; f < mesh.faceCount(); ++f) {
            const double sag = exactSag(f);
            if (measureFirst) EXPECT_EQ(guard.sag(f), sag) << f;
            EXPECT_GE(guard.bound(f), sag) << f;
            for (double share : {0.0, 0.5, 1 - 1e-9, 1.0, 1 + 1e-9, 2.0}) {
                const double limit = share * sag + (share == 0 ? 1e-3 * mesh.edgeLength() : 0.0);
                EXPECT_EQ(guard.exceeds(f, limit), sag > limit) << f << " " << share;
                ++checked, over += sag > limit;
            }
        }
    };
    compareAll(false);  // the first answers from walks and tree queries
    compareAll(true);   // then from what the guard remembers

    // The vertices move (as the relaxation moves them): bounds carried over by the moves,
    // measured again where they may decide.
    const std::vector<double> limits = guard.relaxationLimits();
    ASSERT_EQ(static_cast<int>(limits.size()), mesh.faceCount());
    std::mt19937 random(5);
    std::uniform_real_distribution<double> jitter(-0.15, 0.15);
    for (int round = 0; round < 3; ++round) {
        for (int v = 0; v < mesh.vertexCount(); v += 3) {
            const Vec3 p = mesh.position(v) + mesh.edgeLength() * Vec3(jitter(random), jitter(random), jitter(random));
            mesh.place(v, tree.closest(p));
        }
        for (int f = 0; f < mesh.faceCount(); ++f) {
            EXPECT_EQ(guard.exceeds(f, limits[f]), exactSag(f) > limits[f]) << f;
            ++checked, over += exactSag(f) > limits[f];
        }
        compareAll(round == 2);
    }
    EXPECT_GT(over, checked / 10);  // both answers were asked for
    EXPECT_LT(over, checked);
}
