// Valence optimisation (§4.4): R goes down and V6% up, the mesh stays manifold, oriented and on
// the surface, borders and feature lines are kept, and the result is deterministic.
#include "boundary.h"
#include "closest_point.h"
#include "errors.h"
#include "field.h"
#include "mesh_io.h"
#include "metrics.h"
#include "remesh.h"
#include "test_meshes.h"
#include "triangle_shape.h"
#include "valence.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <utility>

using namespace fieldcvt;

namespace {

//! Equilateral triangulation of a cols x rows patch of the plane z = 0 (every interior vertex
//! has valence 6); rows alternate their offset by half an edge.
TriMesh hexPlane(int cols, int rows)
{
    TriMesh m;
    const double h = std::sqrt(3.0) / 2;
    for (int j = 0; j <= rows; ++j)
        for (int i = 0; i <= cols; ++i) m.vertices.emplace_back(i + 0.5 * (j % 2), j * h, 0.0);
    auto id = [cols](int i, int j) { return j * (cols + 1) + i; };
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < cols; ++i) {
            if (j % 2 == 0) {
                m.faces.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
                m.faces.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
            } else {
                m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
                m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            }
        }
    return m;
}

//! Torus (R = 1, r = 0.3) triangulated like hexPlane, rows alternating their offset (m even):
//! closed, every vertex of valence 6, angles between about 44° and 74°.
TriMesh hexTorus(int n, int m)
{
    TriMesh t;
    const double pi = 3.14159265358979323846;
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < n; ++i) {
            const double u = 2 * pi * (i + 0.5 * (j % 2)) / n, v = 2 * pi * j / m;
            t.vertices.emplace_back((1 + 0.3 * std::cos(v)) * std::cos(u), (1 + 0.3 * std::cos(v)) * std::sin(u),
                                    0.3 * std::sin(v));
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

//! Flips the interior edge shared by faces f and g (which must be adjacent), in place.
void flipShared(TriMesh& m, int f, int g)
{
    const Face a = m.faces[f], b = m.faces[g];
    for (int k = 0; k < 3; ++k) {
        const int p = a[k], q = a[(k + 1) % 3], c = a[(k + 2) % 3];
        for (int l = 0; l < 3; ++l)
            if (b[l] == q && b[(l + 1) % 3] == p) {
                const int d = b[(l + 2) % 3];
                m.faces[f] = {d, q, c};
                m.faces[g] = {c, p, d};
                return;
            }
    }
    FAIL() << "faces " << f << " and " << g << " share no edge";
}

//! R = Σ (d − o)², o = 4 on the border and 6 inside, from an independent edge count.
long long irregularity(const TriMesh& m)
{
    std::map<std::pair<int, int>, int> edges;
    for (const Face& f : m.faces)
        for (int k = 0; k < 3; ++k) ++edges[std::minmax(f[k], f[(k + 1) % 3])];
    std::vector<int> valence(m.vertexCount(), 0);
    std::vector<char> border(m.vertexCount(), 0);
    for (const auto& [e, count] : edges) {
        ++valence[e.first], ++valence[e.second];
        if (count == 1) border[e.first] = border[e.second] = 1;
    }
    long long r = 0;
    for (int v = 0; v < m.vertexCount(); ++v) {
        const int d = valence[v] - (border[v] ? 4 : 6);
        r += d * d;
    }
    return r;
}

//! Every vertex on `surface` and every face facing the same side as the surface there.
void expectOnSurfaceAndOriented(const TriMesh& m, const TriMesh& surface, const ClosestPointTree& tree, double tolerance)
{
    int offSurface = 0, reversed = 0;
    for (const Vec3& p : m.vertices) offSurface += tree.closest(p).squaredDistance > tolerance * tolerance;
    for (int f = 0; f < m.faceCount(); ++f) {
        const Face& t = m.faces[f];
        const Vec3 c = (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3;
        const ClosestPoint cp = tree.closest(c);
        reversed += faceNormal(m, f).dot(faceNormal(surface, cp.face)) <= 0;
    }
    EXPECT_EQ(offSurface, 0);
    EXPECT_EQ(reversed, 0);
}

//! A remeshed model without valence optimisation (the input of optimizeValence in remesh()).
TriMesh remeshedWithoutValence(const TriMesh& input, int vertices)
{
    RemeshParams p;
    p.vertexCount = vertices;
    p.lloydIterations = 10;
    p.cvtIterations = 30;
    p.fcvtIterations = 20;
    p.valenceOptimization = false;
    p.computeDistances = false;
    // Random starts: these tests need meshes with 5-7 pairs for the optimiser to remove (the
    // lattice start leaves the cylinder with none).
    p.latticeStart = false;
    // The starting meshes these tests were measured on: optimised on the input itself (camelhead
    // 1500 on the coarse copy starts with a border where weight 4 gives 86.8 % of valence 4 and
    // weight 1 91.8 %).
    p.optimisationFacesPerSample = 0;
    return remesh(input, p).mesh;
}

//! `start` optimised with `params` (without roles: derived), checked to stay manifold.
TriMesh optimizedCopy(const TriMesh& start, const ValenceSurface& surface, const ValenceParams& params,
                      ValenceStats* stats = nullptr)
{
    TriMesh mesh = start;
    std::vector<VertexRole> roles;
    const ValenceStats s = optimizeValence(mesh, roles, surface, params);
    EXPECT_TRUE(computeTopology(mesh).manifold());
    if (stats) *stats = s;
    return mesh;
}

}  // namespace

TEST(Valence, PlantedFlipsInARegularTorusAreUndone)
{
    // A closed valence-6 triangulation (no border irregularity): flipping a few well separated
    // diagonals makes two valence-5 and two valence-7 vertices each (R grows by 4, V6 drops).
    const int n = 46, m = 16;
    const TriMesh torus = hexTorus(n, m);
    TriMesh mesh = torus;
    ASSERT_EQ(irregularity(mesh), 0);
    ASSERT_GT(computeQuality(mesh).thetaMin, 40.0);
    for (int j : {2, 10})
        for (int i : {4, 20, 36}) {
            const int f = 2 * (j * n + i);
            flipShared(mesh, f, f + 1);
        }
    const QualityMetrics before = computeQuality(mesh);
    ASSERT_LT(before.v6Pct, 97.0);
    ASSERT_EQ(irregularity(mesh), 6 * 4);

    ClosestPointTree tree(torus);
    const ValenceSurface surface{torus, tree, {}, nullptr};
    std::vector<VertexRole> roles;
    const ValenceStats stats = optimizeValence(mesh, roles, surface, ValenceParams{});

    EXPECT_EQ(stats.irregularityBefore, 6 * 4);
    EXPECT_EQ(stats.irregularityAfter, irregularity(mesh));
    EXPECT_EQ(stats.irregularityAfter, 0);
    EXPECT_NEAR(stats.v6Before, before.v6Pct, 1e-9);
    EXPECT_EQ(stats.v6After, 100.0);
    EXPECT_EQ(computeQuality(mesh).v6Pct, 100.0);
    EXPECT_GE(stats.flips, 6);
    EXPECT_EQ(stats.verticesAfter, stats.verticesBefore);
    EXPECT_EQ(roles.size(), mesh.vertices.size());
    const TopologySummary topo = computeTopology(mesh);
    EXPECT_TRUE(topo.manifold());
    EXPECT_TRUE(topo.orientable);
    EXPECT_EQ(topo.genus, 1);
    expectOnSurfaceAndOriented(mesh, torus, tree, 1e-9);
}

TEST(Valence, RemeshedTorusStaysManifoldOrientedOnTheSurfaceAndGetsMoreRegular)
{
    const TriMesh input = readMesh(testmesh::resource("torus.obj"));
    TriMesh mesh = remeshedWithoutValence(input, 800);
    const QualityMetrics before = computeQuality(mesh);
    const TopologySummary topoBefore = computeTopology(mesh);

    ClosestPointTree tree(input);
    const ValenceSurface surface{input, tree, {}, nullptr};
    std::vector<VertexRole> roles(mesh.vertices.size(), VertexRole::Free);
    const ValenceStats stats = optimizeValence(mesh, roles, surface, ValenceParams{});
    const QualityMetrics after = computeQuality(mesh);
    const TopologySummary topo = computeTopology(mesh);

    EXPECT_TRUE(topo.manifold());
    EXPECT_TRUE(topo.orientable);
    EXPECT_EQ(topo.genus, topoBefore.genus);
    EXPECT_EQ(topo.components, topoBefore.components);
    EXPECT_EQ(topo.boundaryLoops, 0);
    EXPECT_EQ(topo.vertices, mesh.vertexCount());  // compacted: no unreferenced vertex
    EXPECT_EQ(roles.size(), mesh.vertices.size());
    expectOnSurfaceAndOriented(mesh, input, tree, 1e-6 * boundingBoxDiagonal(input));

    EXPECT_LT(stats.irregularityAfter, stats.irregularityBefore);
    EXPECT_EQ(stats.irregularityAfter, irregularity(mesh));
    EXPECT_NEAR(stats.v6Before, before.v6Pct, 1e-9);
    EXPECT_NEAR(stats.v6After, after.v6Pct, 1e-9);
    EXPECT_GT(after.v6Pct, before.v6Pct + 2.0);
    EXPECT_GT(after.thetaMin, before.thetaMin - 1.0);
    EXPECT_GT(after.qAvg, before.qAvg - 0.005);
    EXPECT_NEAR(mesh.vertexCount(), before.vertices, 0.03 * before.vertices);
}

TEST(Valence, DeeperLookAheadRemovesTheDislocationsAShallowOneLeaves)
{
    // The 5–7 pairs left after the greedy rounds move by R-neutral flips until they meet another
    // defect: chains of up to 5 operations leave fewer defects than one flip + one operation.
    const TriMesh input = readMesh(testmesh::resource("torus.obj"));
    const TriMesh start = remeshedWithoutValence(input, 800);
    ClosestPointTree tree(input);
    const ValenceSurface surface{input, tree, {}, nullptr};
    auto run = [&](int depth) {
        ValenceParams params;
        params.lookAheadDepth = depth;
        params.relaxIterations = 0;
        ValenceStats stats;
        optimizedCopy(start, surface, params, &stats);
        return stats;
    };
    const ValenceStats shallow = run(2), deep = run(5);
    EXPECT_EQ(shallow.irregularityBefore, deep.irregularityBefore);
    EXPECT_LT(deep.irregularityAfter, shallow.irregularityAfter);
    EXPECT_GT(deep.v6After, shallow.v6After + 0.5);
}

// A disk's valences owe 6 in total (Euler); with border vertices weighted like interior ones the
// deficit stays at the border's turns (valence 3). Weight 4 moves it to interior vertices: more
// border vertices of valence 4, the interior about as regular, no worse angles.
TEST(Valence, BorderWeightMovesTheDisksValenceDeficitInside)
{
    const TriMesh input = readMesh(testmesh::resource("camelhead.off"));
    const TriMesh start = remeshedWithoutValence(input, 1500);
    ClosestPointTree tree(input);
    const ValenceSurface surface{input, tree, {}, nullptr};
    auto run = [&](int weight) {
        ValenceParams params;
        params.borderWeight = weight;
        return computeQuality(optimizedCopy(start, surface, params));
    };
    const QualityMetrics flat = run(1), weighted = run(4);
    EXPECT_GT(weighted.boundaryV4Pct, flat.boundaryV4Pct + 5.0);
    EXPECT_GE(weighted.boundaryV4Pct, 85.0);
    EXPECT_GT(weighted.v6Pct, flat.v6Pct - 1.0);
    EXPECT_GT(weighted.thetaMin, flat.thetaMin - 2.0);
}

// The final relaxation alone (no operation): a valence-6 lattice whose interior vertices were
// pushed about becomes equilateral again; its fixed border stays where it is.
TEST(Valence, RelaxationMakesAJitteredLatticeEquilateral)
{
    const TriMesh plane = hexPlane(14, 12);
    TriMesh mesh = plane;
    const int cols = 14, rows = 12;
    unsigned state = 12345;
    auto jitter = [&state] {
        state = state * 1664525u + 1013904223u;
        return 0.18 * ((state >> 8) / double(1u << 24) - 0.5) * 2;
    };
    for (int j = 1; j < rows; ++j)
        for (int i = 1; i < cols; ++i) {
            Vec3& p = mesh.vertices[j * (cols + 1) + i];
            p.x() += jitter();
            p.y() += jitter();
        }
    const QualityMetrics before = computeQuality(mesh);
    ASSERT_LT(before.qAvg, 0.95);
    ASSERT_LT(before.thetaMin, 45.0);

    ClosestPointTree tree(plane);
    const ValenceSurface surface{plane, tree, {}, nullptr};
    ValenceParams params;
    params.maxRounds = 0;
    ValenceStats stats;
    const TriMesh relaxed = optimizedCopy(mesh, surface, params, &stats);
    ASSERT_EQ(relaxed.faces, mesh.faces);
    EXPECT_EQ(stats.flips + stats.collapses + stats.splits, 0);
    const QualityMetrics after = computeQuality(relaxed);
    EXPECT_GT(after.qAvg, 0.99);
    EXPECT_GT(after.thetaMin, 52.0);
    for (int v = 0; v < relaxed.vertexCount(); ++v) {
        const int i = v % (cols + 1), j = v / (cols + 1);
        EXPECT_NEAR(relaxed.vertices[v].z(), 0.0, 1e-12);
        if (i == 0 || j == 0 || i == cols || j == rows) EXPECT_EQ(relaxed.vertices[v], mesh.vertices[v]);
    }
}

// Issue 5's bars through the whole pipeline (seed 1, defaults), with a small margin under the
// measured figures: V6% >= 94, θ_min >= 32°, Q_avg >= 0.95 (issue 13: higher), no angle under
// 30°; the vertex count within 1.5 % of the target and the edges about as aligned to the field as
// before.
TEST(Valence, PipelineOnClosedMeshesReachesTheBars)
{
    struct Case {
        const char* file;
        int vertices;
        // Measured with the default 10 + 10 + 40 schedule and look-ahead 8: 96.6 / 94.5 / 94.2
        // (fandisk, a CAD part without --feature-angle, seeds 1-4: 94.2 / 94.3 / 94.5 / 94.4).
        double minV6;
        // Issue 13: the relaxation down the shape energy; measured 0.962 / 0.962 / 0.951 (with
        // the paper's schedule 0.965 / 0.965 / 0.958, where the mean-of-neighbours step it
        // replaced gave 0.958 / 0.956 / 0.951).
        double minQAvg;
    };
    for (const Case& c : {Case{"torus.obj", 1000, 95.0, 0.960}, Case{"fertility.off", 3000, 94.2, 0.960},
                          Case{"fandisk.off", 5000, 94.0, 0.950}}) {
        SCOPED_TRACE(c.file);
        RemeshParams params;
        params.vertexCount = c.vertices;
        params.computeDistances = false;
        const RemeshResult r = remesh(readMesh(testmesh::resource(c.file)), params);
        EXPECT_GE(r.metrics.v6Pct, c.minV6);
        EXPECT_GE(r.metrics.thetaMin, 32.0);
        EXPECT_GE(r.metrics.qAvg, c.minQAvg);
        EXPECT_EQ(r.metrics.pctLt30, 0.0);
        // Within 1.5 %: the lattice start's count moves by whole rows (torus: 989).
        EXPECT_NEAR(r.mesh.vertexCount(), c.vertices, 0.015 * c.vertices);
        // The relaxation's field step brings most of the alignment back (the operations alone
        // leave it ~23 % worse). Measured after the relaxation against before the stage: from
        // the random start torus +0.7 %, fertility +8.4 %, fandisk -5.7 %; from the lattice
        // start, whose mesh before the stage is better aligned, torus +0.4 %, fertility +7.6 %,
        // fandisk +11.8 %.
        std::printf("%s: field distance before the stage %.4f, after the operations %.4f, after %.4f\n", c.file,
                    r.valence.fieldDistanceBefore, r.valence.fieldDistanceOperations, r.valence.fieldDistanceAfter);
        EXPECT_LE(r.valence.fieldDistanceAfter, 1.15 * r.valence.fieldDistanceBefore);
        EXPECT_LT(r.valence.fieldDistanceAfter, 0.95 * r.valence.fieldDistanceOperations);
        EXPECT_TRUE(computeTopology(r.mesh).manifold());
    }
}

TEST(Valence, OpenCylinderKeepsItsBorder)
{
    const TriMesh input = readMesh(testmesh::resource("cylinder.off"));
    TriMesh mesh = remeshedWithoutValence(input, 500);
    const TopologySummary topoBefore = computeTopology(mesh);
    const std::vector<Segment> border = boundarySegments(input);
    ASSERT_GT(topoBefore.boundaryLoops, 0);
    auto borderVertices = [](const TriMesh& m) {
        std::map<std::pair<int, int>, int> edges;
        for (const Face& f : m.faces)
            for (int k = 0; k < 3; ++k) ++edges[std::minmax(f[k], f[(k + 1) % 3])];
        std::set<int> onBorder;
        for (const auto& [e, count] : edges)
            if (count == 1) onBorder.insert(e.first), onBorder.insert(e.second);
        return onBorder;
    };
    const size_t borderCount = borderVertices(mesh).size();

    ClosestPointTree tree(input);
    const ValenceSurface surface{input, tree, {}, nullptr};
    std::vector<VertexRole> roles;  // derived: border vertices become Boundary
    const ValenceStats stats = optimizeValence(mesh, roles, surface, ValenceParams{});

    const TopologySummary topo = computeTopology(mesh);
    EXPECT_TRUE(topo.manifold());
    EXPECT_EQ(topo.boundaryLoops, topoBefore.boundaryLoops);
    EXPECT_EQ(topo.genus, topoBefore.genus);
    const std::set<int> onBorder = borderVertices(mesh);
    EXPECT_EQ(onBorder.size(), borderCount);
    const double tolerance = 1e-9 * boundingBoxDiagonal(input);
    for (int v : onBorder) {
        EXPECT_EQ(roles[v], VertexRole::Boundary);
        EXPECT_LT((closestPointOnSegments(mesh.vertices[v], border) - mesh.vertices[v]).norm(), tolerance);
    }
    expectOnSurfaceAndOriented(mesh, input, tree, 1e-6 * boundingBoxDiagonal(input));
    EXPECT_LT(stats.irregularityAfter, stats.irregularityBefore);
}

TEST(Valence, FeatureLinesAndCornersAreKept)
{
    // A feature line along the middle row of a perturbed grid: its vertices stay on it, its
    // edges stay, its end vertices (corners) do not move.
    const TriMesh plane = hexPlane(12, 12);
    TriMesh mesh = plane;
    for (int j : {3, 8})
        for (int i : {2, 7}) flipShared(mesh, 2 * (j * 12 + i), 2 * (j * 12 + i) + 1);
    const int row = 6;
    std::vector<VertexRole> roles(mesh.vertices.size(), VertexRole::Free);
    std::vector<Segment> features;
    for (int i = 0; i <= 12; ++i) {
        const int v = row * 13 + i;
        roles[v] = i == 0 || i == 12 ? VertexRole::Corner : VertexRole::Feature;
        if (i < 12) features.push_back({plane.vertices[v], plane.vertices[v + 1]});
    }
    // The middle of the line is irregular too: flip one edge onto it.
    flipShared(mesh, 2 * (row * 12 + 5), 2 * (row * 12 + 5) + 1);
    const Vec3 corner0 = mesh.vertices[row * 13], corner1 = mesh.vertices[row * 13 + 12];

    ClosestPointTree tree(plane);
    const ValenceSurface surface{plane, tree, features, nullptr};
    ValenceParams params;
    const ValenceStats stats = optimizeValence(mesh, roles, surface, params);
    EXPECT_LT(stats.irregularityAfter, stats.irregularityBefore);

    std::vector<int> line;
    for (int v = 0; v < mesh.vertexCount(); ++v)
        if (roles[v] == VertexRole::Feature || roles[v] == VertexRole::Corner) line.push_back(v);
    ASSERT_EQ(line.size(), 13u);  // never collapsed together, never split
    std::sort(line.begin(), line.end(), [&](int a, int b) { return mesh.vertices[a].x() < mesh.vertices[b].x(); });
    EXPECT_EQ(mesh.vertices[line.front()], corner0);
    EXPECT_EQ(mesh.vertices[line.back()], corner1);
    std::set<std::pair<int, int>> edges;
    for (const Face& f : mesh.faces)
        for (int k = 0; k < 3; ++k) edges.insert(std::minmax(f[k], f[(k + 1) % 3]));
    for (size_t k = 0; k < line.size(); ++k) {
        EXPECT_NEAR(mesh.vertices[line[k]].y(), row * std::sqrt(3.0) / 2, 1e-12);
        if (k + 1 < line.size()) EXPECT_TRUE(edges.count(std::minmax(line[k], line[k + 1]))) << "feature edge " << k;
    }
    EXPECT_TRUE(computeTopology(mesh).manifold());
}

TEST(Valence, DeterministicWhateverTheThreadCount)
{
    const TriMesh input = readMesh(testmesh::resource("torus.obj"));
    // Enough vertices that the look-ahead rounds have the 64 irregular vertices from which their
    // chains are searched on several threads (collectAllChains).
    const TriMesh start = remeshedWithoutValence(input, 1500);
    ClosestPointTree tree(input);
    // A field makes the final relaxation use it too.
    FieldParams fieldParams;
    const DirectionField field = computeField(input, fieldParams);
    const ValenceSurface surface{input, tree, {}, &field};

    auto run = [&](int threads) {
        const int previous = omp_get_max_threads();
        omp_set_num_threads(threads);
        TriMesh mesh = start;
        std::vector<VertexRole> roles;
        optimizeValence(mesh, roles, surface, ValenceParams{});
        omp_set_num_threads(previous);
        return mesh;
    };
    const TriMesh a = run(1), b = run(1), c = run(2), d = run(3);
    EXPECT_EQ(a.vertices, b.vertices);
    EXPECT_EQ(a.faces, b.faces);
    EXPECT_EQ(a.vertices, c.vertices);
    EXPECT_EQ(a.faces, c.faces);
    EXPECT_EQ(a.vertices, d.vertices);
    EXPECT_EQ(a.faces, d.faces);
}

// The default pipeline on a bundled mesh, with one seed, from the random start the valence
// stage's figures below were measured on (with the lattice start every seed gives the same
// mesh; test_lattice.cpp pins that pipeline's figures).
RemeshResult remeshWithDefaults(const std::string& resource, int vertexCount, std::uint64_t seed)
{
    RemeshParams params;
    params.vertexCount = vertexCount;
    params.seed = seed;
    params.latticeStart = false;
    return remesh(readMesh(testmesh::resource(resource)), params);
}

// An operation may grow the sag around it by at most 0.1 edge length on top of the 1.5× rule:
// where the mesh already sags (an ear tip), a run of operations each within 1.5× cuts the tip
// off. Measured, bunny 5000 with the defaults, d_H % of the diagonal, seeds 1-4: 0.62 / 0.68 /
// 0.57 / 0.55 with the cap, 0.64 / 0.84 / 0.73 / 0.55 without it.
TEST(Valence, SagGrowthCapKeepsBunnysEarTips)
{
    const RemeshResult r = remeshWithDefaults("bunny.obj", 5000, 3);
    EXPECT_LE(r.metrics.dH, 0.0065);
    EXPECT_GE(r.valence.v6After, 94.0);
}

// After the relaxation, the corners of faces still under 35° move to raise the smallest angle
// around them (raiseSmallestAngles). Those faces sit in clusters of irregular vertices (here a
// 7-6-6 face) where the relaxation's shape energy is already at its minimum. Measured, seed 4:
// θ_min 35.4° with the repair, 32.1° without; the other figures unchanged (Q_avg 0.960, V6 94.2 %).
TEST(Valence, AngleRepairLiftsTheSmallestAngle)
{
    const RemeshResult r = remeshWithDefaults("fertility.off", 3000, 4);
    EXPECT_GE(r.metrics.thetaMin, 35.0);
    EXPECT_GE(r.metrics.qAvg, 0.955);
    EXPECT_GE(r.valence.v6After, 94.0);
}

// The relaxation lets faces sag up to half the largest sag at its start, and folds up to ~45°
// (kRelaxSagShareOfLargest, kRelaxMinNormalDot): at fandisk's rounded creases the stricter
// limits (1.25× a face's own sag, 32°) froze a few hundred faces at every step. Measured, seed 1:
// Q_avg 0.958 (0.951 with the old limits), θ_min 35.3°, d_H 0.95 % (0.94 %); with the sag
// repair after it, 35.6° and 0.93 %.
TEST(Valence, RelaxationMovesThroughRoundedCreases)
{
    const RemeshResult r = remeshWithDefaults("fandisk.off", 5000, 1);
    EXPECT_GE(r.metrics.qAvg, 0.956);
    EXPECT_GE(r.metrics.thetaMin, 35.0);
    EXPECT_LE(r.metrics.dH, 0.0100);
    EXPECT_GE(r.valence.v6After, 94.0);
}

// d_H sits at a handful of faces: after the angle repair, the corners of the faces within 5 % of
// the largest sag move to bring it down (lowerLargestSags). Measured, seed 1: d_H 0.62 % of the
// diagonal with the repair, 0.72 % without; Q_avg 0.965 either way.
TEST(Valence, SagRepairLowersTheLargestDistance)
{
    const RemeshResult r = remeshWithDefaults("fertility.off", 3000, 1);
    EXPECT_LE(r.metrics.dH, 0.0067);
    EXPECT_GE(r.metrics.qAvg, 0.963);
    EXPECT_GE(r.metrics.thetaMin, 35.0);
}

TEST(Valence, RejectsMismatchedRoles)
{
    const TriMesh plane = hexPlane(4, 4);
    TriMesh mesh = plane;
    ClosestPointTree tree(plane);
    const ValenceSurface surface{plane, tree, {}, nullptr};
    std::vector<VertexRole> roles(3, VertexRole::Free);
    EXPECT_THROW(optimizeValence(mesh, roles, surface, ValenceParams{}), InvalidInputError);
}

// A sample whose cell reached the open border during the FCVT iterations is a border vertex of the
// RDT but not a border sample (camelhead 3000: 1.1 % of the diagonal inside): given the input's
// border, the optimiser puts such a Free vertex on it before treating it as Boundary.
TEST(Valence, FreeVertexOnTheMeshBorderIsPutOnTheInputBorder)
{
    const TriMesh input = readMesh(testmesh::resource("cylinder.off"));
    TriMesh mesh = remeshedWithoutValence(input, 500);
    const std::vector<Segment> border = boundarySegments(input);
    std::vector<VertexRole> roles(mesh.vertices.size(), VertexRole::Free);
    // One vertex of the mesh's border moved 0.2 edge lengths inside, along the surface's axis
    // (the cylinder's rims are at its z extremes).
    std::map<std::pair<int, int>, int> edges;
    for (const Face& f : mesh.faces)
        for (int k = 0; k < 3; ++k) ++edges[std::minmax(f[k], f[(k + 1) % 3])];
    int moved = -1;
    double edge = 0;
    for (const auto& [e, count] : edges)
        if (count == 1) {
            moved = e.first;
            edge = (mesh.vertices[e.first] - mesh.vertices[e.second]).norm();
            break;
        }
    ASSERT_GE(moved, 0);
    const double zMid = 0.5 * (input.vertices[0].z() + input.vertices.back().z());
    Vec3& p = mesh.vertices[moved];
    p.z() += (p.z() > zMid ? -0.2 : 0.2) * edge;
    const double before = (closestPointOnSegments(p, border) - p).norm();
    ASSERT_GT(before, 0.1 * edge);

    ClosestPointTree tree(input);
    const ValenceSurface surface{input, tree, {}, nullptr, border};
    optimizeValence(mesh, roles, surface, ValenceParams{});
    const double tolerance = 1e-9 * boundingBoxDiagonal(input);
    int onMeshBorder = 0;
    edges.clear();
    for (const Face& f : mesh.faces)
        for (int k = 0; k < 3; ++k) ++edges[std::minmax(f[k], f[(k + 1) % 3])];
    for (const auto& [e, count] : edges)
        if (count == 1)
            for (int v : {e.first, e.second}) {
                ++onMeshBorder;
                EXPECT_EQ(roles[v], VertexRole::Boundary);
                EXPECT_LT((closestPointOnSegments(mesh.vertices[v], border) - mesh.vertices[v]).norm(), tolerance);
            }
    EXPECT_GT(onMeshBorder, 0);
}

// Border vertices slide along the input's border in the angle repair (issue 32 item 1: the
// border triangles of dense strips on scans): a rim vertex of the cylinder moved 0.6 edge
// lengths along the rim, so that its faces are sharp, moves back along it, on it, and the
// smallest angle around it rises; with the operations and the relaxation off, only the repair
// moves it.
TEST(Valence, AngleRepairSlidesBorderVerticesAlongTheBorder)
{
    const TriMesh input = readMesh(testmesh::resource("cylinder.off"));
    TriMesh mesh = remeshedWithoutValence(input, 500);
    const std::vector<Segment> border = boundarySegments(input);
    std::map<std::pair<int, int>, int> edges;
    for (const Face& f : mesh.faces)
        for (int k = 0; k < 3; ++k) ++edges[std::minmax(f[k], f[(k + 1) % 3])];
    std::vector<VertexRole> roles(mesh.vertices.size(), VertexRole::Free);
    int moved = -1, neighbour = -1;
    for (const auto& [e, count] : edges)
        if (count == 1) {
            roles[e.first] = roles[e.second] = VertexRole::Boundary;
            if (moved < 0) moved = e.first, neighbour = e.second;
        }
    ASSERT_GE(moved, 0);
    // Towards its neighbour along the rim, then back onto the rim.
    const Vec3 start = mesh.vertices[moved];
    const double edge = (mesh.vertices[neighbour] - start).norm();
    mesh.vertices[moved] = closestPointOnSegments(start + 0.6 * (mesh.vertices[neighbour] - start), border);
    auto smallestAround = [&](const TriMesh& m, int v) {
        double smallest = 180;
        for (const Face& f : m.faces)
            if (f[0] == v || f[1] == v || f[2] == v)
                smallest = std::min(smallest, smallestAngle(m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]) * 180 / kPi);
        return smallest;
    };
    const double before = smallestAround(mesh, moved);
    const Vec3 shifted = mesh.vertices[moved];
    ASSERT_LT(before, 30.0);

    ClosestPointTree tree(input);
    const ValenceSurface surface{input, tree, {}, nullptr, border};
    ValenceParams params;
    params.maxRounds = 0;
    params.lookAheadDepth = 0;
    params.relaxIterations = 0;
    optimizeValence(mesh, roles, surface, params);
    const Vec3& after = mesh.vertices[moved];
    EXPECT_GT((after - shifted).norm(), 0.05 * edge);
    EXPECT_LT((closestPointOnSegments(after, border) - after).norm(), 1e-9 * boundingBoxDiagonal(input));
    EXPECT_GT(smallestAround(mesh, moved), before + 5.0);
}

// A border sample that the mesh has inside (the RDT covered a hole smaller than its cells) is
// not held on the input's border: returned as Free, it moves like any interior vertex, and a
// sharp corner beside it is repaired (conrod.stl at 402 vertices, seed 4: an 11.2° sliver beside
// such a vertex and a fixed corner).
TEST(Valence, BoundaryVertexInsideTheMeshMovesAsAnInteriorOne)
{
    const TriMesh input = testmesh::icosphere(3);
    TriMesh mesh = input;
    std::vector<VertexRole> roles(mesh.vertices.size(), VertexRole::Free);
    const int moved = 0;
    roles[moved] = VertexRole::Boundary;
    // Towards a neighbour, so that its faces are sharp.
    int neighbour = -1;
    for (const Face& f : mesh.faces)
        for (int k = 0; k < 3; ++k)
            if (f[k] == moved) neighbour = f[(k + 1) % 3];
    ASSERT_GE(neighbour, 0);
    mesh.vertices[moved] = (0.35 * mesh.vertices[moved] + 0.65 * mesh.vertices[neighbour]).normalized();
    const double before = computeQuality(mesh).thetaMin;
    ASSERT_LT(before, 30.0);

    ClosestPointTree tree(input);
    const ValenceSurface surface{input, tree, {}, nullptr, {}};
    ValenceParams params;
    params.maxRounds = 0;
    params.lookAheadDepth = 0;
    params.relaxIterations = 0;
    optimizeValence(mesh, roles, surface, params);
    EXPECT_EQ(std::count(roles.begin(), roles.end(), VertexRole::Boundary), 0);
    EXPECT_GT(computeQuality(mesh).thetaMin, before + 5.0);
}
