// Local remeshing (core/local_remesh.h): the topology of every selected component is kept
// exactly, on thin bars, thin plates with narrow holes, tiny shells and triangle soups; the
// vertices stay on the surface, the feature lines and corners are kept; the triangles are well
// shaped on smooth surfaces; the result does not depend on the thread count; bad inputs throw.
#include "feature_lines.h"
#include "local_remesh.h"
#include "metrics.h"
#include "test_meshes.h"
#include "thread_count.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cmath>
#include <functional>
#include <map>
#include <vector>

using namespace fieldcvt;

namespace {

constexpr double kTarget = 1.0746;

//! The boundary of a union of boxes of a grid with the given cell boundaries per axis
//! (`occupied(i, j, k)` says which cells are solid), each square split into two triangles,
//! oriented outwards. Manifold as long as no two solid cells touch along an edge only.
TriMesh voxelSurface(const std::array<std::vector<double>, 3>& coords, const std::function<bool(int, int, int)>& occupied)
{
    const int n[3] = {int(coords[0].size()) - 1, int(coords[1].size()) - 1, int(coords[2].size()) - 1};
    auto solid = [&](int i, int j, int k) {
        return i >= 0 && j >= 0 && k >= 0 && i < n[0] && j < n[1] && k < n[2] && occupied(i, j, k);
    };
    TriMesh m;
    std::map<std::array<int, 3>, int> index;
    auto vertex = [&](std::array<int, 3> g) {
        auto [it, added] = index.emplace(g, m.vertexCount());
        if (added) m.vertices.emplace_back(coords[0][g[0]], coords[1][g[1]], coords[2][g[2]]);
        return it->second;
    };
    for (int i = 0; i < n[0]; ++i)
        for (int j = 0; j < n[1]; ++j)
            for (int k = 0; k < n[2]; ++k) {
                if (!solid(i, j, k)) continue;
                for (int axis = 0; axis < 3; ++axis)
                    for (int side = 0; side < 2; ++side) {
                        std::array<int, 3> next{i, j, k};
                        next[axis] += side ? 1 : -1;
                        if (solid(next[0], next[1], next[2])) continue;
                        // The square's corners counter-clockwise seen from outside.
                        const int u = (axis + 1) % 3, w = (axis + 2) % 3;
                        std::array<int, 4> quad;
                        const int offsets[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
                        for (int c = 0; c < 4; ++c) {
                            std::array<int, 3> g{i, j, k};
                            g[axis] += side;
                            g[u] += offsets[side ? c : 3 - c][0];
                            g[w] += offsets[side ? c : 3 - c][1];
                            quad[c] = vertex(g);
                        }
                        m.faces.push_back({quad[0], quad[1], quad[2]});
                        m.faces.push_back({quad[0], quad[2], quad[3]});
                    }
            }
    return m;
}

//! Alternating widths: solid, gap, solid, ..., solid (`gaps` gaps), as cell boundaries.
std::vector<double> alternating(int gaps, double solid, double gap)
{
    std::vector<double> c{0.0};
    for (int i = 0; i < 2 * gaps + 1; ++i) c.push_back(c.back() + (i % 2 ? gap : solid));
    return c;
}

//! A planar grid of 4 x 5 square cells made of bars `width` wide and thick: genus 20.
TriMesh barGrid(double width, double cell)
{
    return voxelSurface({alternating(4, width, cell), alternating(5, width, cell), std::vector<double>{0.0, width}},
                        [](int i, int j, int) { return i % 2 == 0 || j % 2 == 0; });
}

//! A plate `thickness` thick with 6 x 5 square holes `hole` wide, `spacing` apart: genus 30.
TriMesh perforatedPlate(double thickness, double hole, double spacing)
{
    return voxelSurface({alternating(6, spacing, hole), alternating(5, spacing, hole), std::vector<double>{0.0, thickness}},
                        [](int i, int j, int) { return i % 2 == 0 || j % 2 == 0; });
}

TriMesh scaled(TriMesh m, double factor, const Vec3& shift = Vec3::Zero())
{
    for (Vec3& v : m.vertices) v = v * factor + shift;
    return m;
}

void append(TriMesh& to, const TriMesh& from)
{
    const int base = to.vertexCount();
    to.vertices.insert(to.vertices.end(), from.vertices.begin(), from.vertices.end());
    for (Face f : from.faces) to.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
}

//! Remeshes the whole of `surface` (every face selected).
LocalRemeshResult remeshAll(const TriMesh& surface, LocalRemeshParams params = {}, std::vector<std::array<int, 2>> features = {},
                            std::vector<int> corners = {})
{
    const ClosestPointTree tree(surface);
    const std::vector<char> all(surface.faces.size(), 1);
    return remeshLocally({surface, tree, all, std::move(features), std::move(corners), {}}, params);
}

//! The largest distance from an output vertex to `surface`.
double largestDistance(const TriMesh& mesh, const TriMesh& surface)
{
    const ClosestPointTree tree(surface);
    double largest = 0;
    for (const Vec3& v : mesh.vertices) largest = std::max(largest, std::sqrt(tree.closest(v).squaredDistance));
    return largest;
}

//! The result's mesh has the topology `expected` has (components, loops, genus), is manifold and
//! oriented, and its roles and hints match it.
void expectSameTopology(const LocalRemeshResult& result, const TopologySummary& expected)
{
    const TopologySummary topology = computeTopology(result.mesh);
    EXPECT_TRUE(topology.manifold());
    EXPECT_TRUE(topology.orientable);
    EXPECT_EQ(topology.components, expected.components);
    EXPECT_EQ(topology.boundaryLoops, expected.boundaryLoops);
    EXPECT_EQ(topology.genus, expected.genus);
    EXPECT_EQ(topology.vertices, result.mesh.vertexCount());  // no vertex left unreferenced
    EXPECT_EQ(result.roles.size(), result.mesh.vertices.size());
    EXPECT_EQ(result.vertexFaceHints.size(), result.mesh.vertices.size());
}

//! Prints the output's triangle figures (thin parts force small angles: reported, not asserted).
void printFigures(const LocalRemeshResult& result, const TriMesh& surface)
{
    const QualityMetrics quality = computeQuality(result.mesh);
    std::printf("[ figures  ] %d vertices: theta_min %.2f, %%<30 %.3f, mean edge / target %.3f, V6 %.1f%%, area / input %.4f\n",
                result.mesh.vertexCount(), quality.thetaMin, quality.pctLt30, meanEdgeLength(result.mesh) / kTarget,
                quality.v6Pct, surfaceArea(result.mesh) / surfaceArea(surface));
}

//! Each triangle of `mesh` split into four at its edges' midpoints, `levels` times.
TriMesh subdivided(TriMesh mesh, int levels)
{
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<int, int>, int> middle;
        auto at = [&](int a, int b) {
            const auto [it, added] = middle.try_emplace(std::minmax(a, b), mesh.vertexCount());
            if (added) mesh.vertices.push_back(0.5 * (mesh.vertices[a] + mesh.vertices[b]));
            return it->second;
        };
        std::vector<Face> faces;
        for (const Face& f : mesh.faces) {
            const int ab = at(f[0], f[1]), bc = at(f[1], f[2]), ca = at(f[2], f[0]);
            faces.insert(faces.end(), {Face{f[0], ab, ca}, Face{ab, f[1], bc}, Face{ca, bc, f[2]}, Face{ab, bc, ca}});
        }
        mesh.faces = std::move(faces);
    }
    return mesh;
}

//! A flat 6 x 6 square whose top border has a spike `height` high and `base` wide in the middle
//! (a scan's ragged border): a fan from the square's centre, subdivided to edges under half
//! the target.
TriMesh spikedSquare(double height, double base)
{
    TriMesh m;
    m.vertices = {{3, 3, 0}, {0, 0, 0}, {6, 0, 0}, {6, 6, 0}, {3 + 0.5 * base, 6, 0}, {3, 6 + height, 0}, {3 - 0.5 * base, 6, 0},
                  {0, 6, 0}};
    for (int k = 1; k <= 7; ++k) m.faces.push_back({0, k, k % 7 + 1});
    return subdivided(m, 4);
}

//! Whether some vertex of `mesh` is within 1e-9 of p.
bool hasVertexAt(const TriMesh& mesh, const Vec3& p)
{
    for (const Vec3& v : mesh.vertices)
        if ((v - p).norm() < 1e-9) return true;
    return false;
}

}  // namespace

TEST(LocalRemesh, ThinBarGridKeepsItsTwentyHandles)
{
    // Bars a quarter of the target wide: the RDT of samples a target apart cannot resolve them.
    const TriMesh surface = barGrid(0.25, 3.0);
    const TopologySummary input = computeTopology(surface);
    ASSERT_EQ(input.genus, 20);
    const LocalRemeshResult result = remeshAll(surface);
    expectSameTopology(result, input);
    EXPECT_GT(result.splits, 0);
    EXPECT_GT(result.collapses, 0);
    EXPECT_LT(largestDistance(result.mesh, surface), 1e-6);
    printFigures(result, surface);
}

TEST(LocalRemesh, ThinPlateKeepsItsThirtyNarrowHoles)
{
    const TriMesh surface = perforatedPlate(0.2, 0.4, 2.0);
    const TopologySummary input = computeTopology(surface);
    ASSERT_EQ(input.genus, 30);
    LocalRemeshParams uniform;
    uniform.refineStrips = false;
    const LocalRemeshResult result = remeshAll(surface, uniform);
    expectSameTopology(result, input);
    EXPECT_LT(largestDistance(result.mesh, surface), 1e-6);
    // The plate's vertices are not all on its rims: its faces were remeshed to the target.
    EXPECT_GT(meanEdgeLength(result.mesh), 0.5 * kTarget);
    // And it still covers the plate: its rims, sharp edges without feature lines, are not cut
    // off round after round.
    EXPECT_GT(surfaceArea(result.mesh), 0.97 * surfaceArea(surface));
    printFigures(result, surface);
}

TEST(LocalRemesh, ThinBoxWithoutFeatureLinesKeepsItsRim)
{
    const TriMesh surface = scaled(testmesh::thinBox(20, 0.02), 12.0);  // 12 x 0.24 x 12
    LocalRemeshParams uniform;
    uniform.refineStrips = false;
    const LocalRemeshResult result = remeshAll(surface, uniform);
    expectSameTopology(result, computeTopology(surface));
    EXPECT_GT(surfaceArea(result.mesh), 0.97 * surfaceArea(surface));
    Vec3 lo = result.mesh.vertices[0], hi = lo;
    for (const Vec3& p : result.mesh.vertices) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    EXPECT_LT(lo.x(), 1e-9);
    EXPECT_GT(hi.x(), 12 - 1e-9);
    EXPECT_LT(lo.z(), 1e-9);
    EXPECT_GT(hi.z(), 12 - 1e-9);
    EXPECT_NEAR(meanEdgeLength(result.mesh) / kTarget, 1.0, 0.15);
    printFigures(result, surface);
}

TEST(LocalRemesh, ThinBoxRimGetsWellShapedTrianglesFromTheStripSizing)
{
    // The same 12 x 0.24 x 12 box, with the default strip sizing: edges about 1.5 times the rim's
    // width on the rims, graded back to the target across the faces (issue 52, item 4).
    const TriMesh surface = scaled(testmesh::thinBox(20, 0.02), 12.0);
    LocalRemeshParams uniform;
    uniform.refineStrips = false;
    const LocalRemeshResult refined = remeshAll(surface), flat = remeshAll(surface, uniform);
    expectSameTopology(refined, computeTopology(surface));
    EXPECT_LT(largestDistance(refined.mesh, surface), 1e-6);
    EXPECT_GT(surfaceArea(refined.mesh), 0.99 * surfaceArea(surface));
    // Alone (before the valence stage's repairs) the rims' triangles are already far less thin,
    // and the rims are no longer cut off.
    const QualityMetrics quality = computeQuality(refined.mesh), before = computeQuality(flat.mesh);
    EXPECT_GT(quality.thetaMin, before.thetaMin + 5.0);
    EXPECT_GT(surfaceArea(refined.mesh), surfaceArea(flat.mesh));
    // Shorter edges only where the rims need them: more vertices, but far from a mesh at the
    // rims' length everywhere (about (12 / 0.36)^2 * 2.3 = 2 600 vertices).
    EXPECT_GT(refined.mesh.vertexCount(), flat.mesh.vertexCount());
    EXPECT_LT(refined.mesh.vertexCount(), 3 * flat.mesh.vertexCount());
    printFigures(flat, surface);
    printFigures(refined, surface);
}

TEST(LocalRemesh, BorderSpikeUnderFifteenDegreesLosesOneEarAtMost)
{
    // A spike of the border, one target high: at a 10.3° tip every triangle there has an angle of
    // at most 10.3°, so its ear is cut off (issue 52 item 4: no angle under 15°); at 20° it
    // stays. The spike's tip and base are corners, as sharp turns of a scan's ragged border are:
    // no collapse or smoothing moves them. The square keeps its one loop and its vertices stay
    // on the input.
    const std::vector<int> corners = {1, 2, 3, 4, 5, 6, 7};
    auto spike = [](double height, double tipDegrees) {
        return spikedSquare(height, 2 * height * std::tan(0.5 * tipDegrees * kPi / 180));
    };
    const TriMesh sharp = spike(kTarget, 10.3), blunt = spike(kTarget, 20);
    const LocalRemeshResult cut = remeshAll(sharp, {}, {}, corners), kept = remeshAll(blunt, {}, {}, corners);
    for (const LocalRemeshResult* result : {&cut, &kept}) {
        expectSameTopology(*result, computeTopology(sharp));
        EXPECT_EQ(computeTopology(result->mesh).boundaryLoops, 1);
    }
    EXPECT_FALSE(hasVertexAt(cut.mesh, Vec3(3, 6 + kTarget, 0)));
    EXPECT_TRUE(hasVertexAt(kept.mesh, Vec3(3, 6 + kTarget, 0)));
    EXPECT_LT(largestDistance(cut.mesh, sharp), 1e-6);
    EXPECT_GT(surfaceArea(cut.mesh), 0.995 * 36);
    // Three targets high, the spike loses its tip's ear and no more: what is left of it reaches
    // within 1.5 targets of the tip.
    const TriMesh tall = spike(3 * kTarget, 10.3);
    const LocalRemeshResult shortened = remeshAll(tall, {}, {}, {1, 2, 3, 5, 7});
    expectSameTopology(shortened, computeTopology(tall));
    double highest = 0;
    for (const Vec3& p : shortened.mesh.vertices) highest = std::max(highest, p.y());
    EXPECT_LT(highest, 6 + 3 * kTarget - 1e-6);
    EXPECT_GT(highest, 6 + 1.5 * kTarget);
}

TEST(LocalRemesh, HundredTinyShellsStayHundredSpheres)
{
    TriMesh surface;
    for (int i = 0; i < 100; ++i) append(surface, scaled(testmesh::icosphere(i % 2), 0.15, Vec3(i % 10, i / 10, 0.0)));
    const TopologySummary input = computeTopology(surface);
    ASSERT_EQ(input.components, 100);
    const LocalRemeshResult result = remeshAll(surface);
    expectSameTopology(result, input);
    EXPECT_EQ(computeTopology(result.mesh).genus, 0);
    EXPECT_GT(result.collapses, 0);
    EXPECT_GE(result.mesh.vertexCount(), 400);  // at least a tetrahedron each
    EXPECT_LT(largestDistance(result.mesh, surface), 1e-6);
}

TEST(LocalRemesh, TriangleSoupKeepsEachTriangleADisk)
{
    TriMesh surface;
    for (int i = 0; i < 40; ++i) {
        const double size = 0.2 + 0.15 * i;  // from far under the target to several times it
        const Vec3 o(5.0 * (i % 8), 5.0 * (i / 8), 0.1 * i);
        surface.vertices.insert(surface.vertices.end(), {o, o + Vec3(size, 0, 0.2 * size), o + Vec3(0.3 * size, size, 0)});
        surface.faces.push_back({3 * i, 3 * i + 1, 3 * i + 2});
    }
    const TopologySummary input = computeTopology(surface);
    const LocalRemeshResult result = remeshAll(surface);
    expectSameTopology(result, input);
    EXPECT_EQ(computeTopology(result.mesh).boundaryLoops, 40);
    EXPECT_GT(result.splits, 0);
    // A vertex is Boundary exactly when it lies on a border edge; triangle corners stay Boundary
    // (none is a corner here: none was given).
    std::map<std::pair<int, int>, int> edgeFaces;
    for (const Face& f : result.mesh.faces)
        for (int k = 0; k < 3; ++k) ++edgeFaces[std::minmax(f[k], f[(k + 1) % 3])];
    std::vector<char> onBorder(result.mesh.vertexCount(), 0);
    for (const auto& [edge, count] : edgeFaces)
        if (count == 1) onBorder[edge.first] = onBorder[edge.second] = 1;
    for (int v = 0; v < result.mesh.vertexCount(); ++v)
        EXPECT_EQ(result.roles[v] == VertexRole::Boundary, onBorder[v] != 0) << "vertex " << v;
    EXPECT_LT(largestDistance(result.mesh, surface), 1e-6);
}

TEST(LocalRemesh, SmoothSurfacesGetWellShapedTriangles)
{
    for (const TriMesh& surface : {scaled(testmesh::icosphere(3), 5.0), testmesh::torus(60, 24, 6.0, 2.0)}) {
        const TopologySummary input = computeTopology(surface);
        const LocalRemeshResult result = remeshAll(surface);
        expectSameTopology(result, input);
        const QualityMetrics quality = computeQuality(result.mesh);
        const double meanEdge = meanEdgeLength(result.mesh);
        printFigures(result, surface);
        EXPECT_GE(quality.thetaMin, 15.0);
        EXPECT_LE(quality.pctLt30, 0.5);
        EXPECT_NEAR(meanEdge / kTarget, 1.0, 0.15);
        EXPECT_LT(largestDistance(result.mesh, surface), 1e-6);
    }
}

TEST(LocalRemesh, TargetLengthPerFaceIsFollowed)
{
    // A 12 x 12 square: half the target on its x < 6 half.
    const TriMesh surface = scaled(testmesh::planeGrid(24), 12.0);
    std::vector<double> lengths(surface.faces.size(), kTarget);
    for (int f = 0; f < surface.faceCount(); ++f)
        if (surface.vertices[surface.faces[f][0]].x() < 6 - 1e-9 || surface.vertices[surface.faces[f][1]].x() < 6 - 1e-9)
            lengths[f] = 0.5 * kTarget;
    const ClosestPointTree tree(surface);
    const std::vector<char> all(surface.faces.size(), 1);
    const LocalRemeshResult result = remeshLocally({surface, tree, all, {}, {}, lengths}, {});
    expectSameTopology(result, computeTopology(surface));
    int fine = 0, coarse = 0;
    for (const Vec3& p : result.mesh.vertices) (p.x() < 5 ? fine : p.x() > 7 ? coarse : fine) += p.x() < 5 || p.x() > 7;
    // Edges half as long: up to four times as many vertices per area (5 x 12 on each side
    // counted); the input's own edges, half a target, are not short enough there to collapse.
    EXPECT_GT(fine, 2 * coarse);
    EXPECT_LT(fine, 5 * coarse);
}

TEST(LocalRemesh, CubeKeepsItsEdgesAndCorners)
{
    std::vector<double> c{0, 1, 2, 3, 4};
    const TriMesh cube = voxelSurface({c, c, c}, [](int, int, int) { return true; });
    const FeatureLines lines = detectFeatures(cube, 60.0);
    ASSERT_EQ(lines.corners.size(), 8u);
    const LocalRemeshResult result = remeshAll(cube, {}, lines.edges, lines.corners);
    expectSameTopology(result, computeTopology(cube));
    // On a cube edge: two coordinates at 0 or 4.
    auto extremes = [](const Vec3& p) {
        int count = 0;
        for (int k = 0; k < 3; ++k) count += std::abs(p[k]) < 1e-9 || std::abs(p[k] - 4) < 1e-9;
        return count;
    };
    int corners = 0;
    for (int v = 0; v < result.mesh.vertexCount(); ++v) {
        const Vec3& p = result.mesh.vertices[v];
        const VertexRole role = result.roles[v];
        if (extremes(p) >= 2) EXPECT_TRUE(role == VertexRole::Feature || role == VertexRole::Corner) << "vertex " << v;
        if (role == VertexRole::Feature) EXPECT_EQ(extremes(p), 2) << "vertex " << v;
        if (role == VertexRole::Corner) EXPECT_EQ(extremes(p), 3) << "vertex " << v;
        corners += extremes(p) == 3;
    }
    EXPECT_EQ(corners, 8);
    // The 12 edges of length 4 are chains of output edges: the output edges along them add up.
    double along = 0;
    for (const Face& f : result.mesh.faces)
        for (int k = 0; k < 3; ++k) {
            const Vec3 &a = result.mesh.vertices[f[k]], &b = result.mesh.vertices[f[(k + 1) % 3]];
            int shared = 0;  // coordinates at the same extreme in both ends
            for (int i = 0; i < 3; ++i)
                shared +=
                    (std::abs(a[i]) < 1e-9 && std::abs(b[i]) < 1e-9) || (std::abs(a[i] - 4) < 1e-9 && std::abs(b[i] - 4) < 1e-9);
            if (shared >= 2) along += 0.5 * (a - b).norm();  // each edge seen from its two faces
        }
    EXPECT_NEAR(along, 48.0, 1e-6);
}

TEST(LocalRemesh, OnlyTheSelectedComponentComesOut)
{
    TriMesh surface = scaled(testmesh::icosphere(2), 3.0);
    const int sphereFaces = surface.faceCount();
    append(surface, testmesh::torus(48, 16, 6.0, 1.5));
    std::vector<char> selected(surface.faces.size(), 0);
    for (int f = sphereFaces; f < surface.faceCount(); ++f) selected[f] = 1;
    const ClosestPointTree tree(surface);
    const LocalRemeshResult result = remeshLocally({surface, tree, selected, {}, {}, {}}, {});
    const TopologySummary topology = computeTopology(result.mesh);
    EXPECT_EQ(topology.components, 1);
    EXPECT_EQ(topology.genus, 1);
    for (const Vec3& p : result.mesh.vertices) {
        // On the torus: distance to its core circle is its minor radius.
        const double ring = std::hypot(p.x(), p.y()) - 6.0;
        EXPECT_NEAR(std::hypot(ring, p.z()), 1.5, 0.05);
    }
    for (int hint : result.vertexFaceHints) EXPECT_TRUE(selected[hint]);
}

TEST(LocalRemesh, SameResultOnAnyThreadCount)
{
    const TriMesh surface = barGrid(0.3, 2.5);
    std::vector<double> c{0, 1, 2, 3};
    TriMesh withCube = surface;
    append(withCube, scaled(voxelSurface({c, c, c}, [](int, int, int) { return true; }), 1.0, Vec3(0, 0, 5)));
    const FeatureLines lines = detectFeatures(withCube, 60.0);
    LocalRemeshParams params;
    params.targetLength = 0.3;  // some thousand vertices: the smoothing runs in parallel
    auto run = [&] { return remeshAll(withCube, params, lines.edges, lines.corners); };
    const LocalRemeshResult one = testthreads::withThreadCount(1, run);
    const LocalRemeshResult three = testthreads::withThreadCount(3, run);
    EXPECT_GT(one.mesh.vertexCount(), 3000);
    EXPECT_EQ(one.mesh.vertices, three.mesh.vertices);
    EXPECT_EQ(one.mesh.faces, three.mesh.faces);
    EXPECT_EQ(one.roles, three.roles);
    EXPECT_EQ(one.vertexFaceHints, three.vertexFaceHints);
}

TEST(LocalRemesh, BadInputsThrow)
{
    const TriMesh surface = testmesh::icosphere(1);
    const ClosestPointTree tree(surface);
    const std::vector<char> all(surface.faces.size(), 1), short_(surface.faces.size() - 1, 1);
    LocalRemeshParams zero, negative;
    zero.targetLength = 0;
    negative.targetLength = -1;
    EXPECT_THROW(remeshLocally({surface, tree, short_, {}, {}, {}}, {}), InvalidInputError);
    EXPECT_THROW(remeshLocally({surface, tree, all, {}, {}, {}}, zero), InvalidInputError);
    EXPECT_THROW(remeshLocally({surface, tree, all, {}, {}, {}}, negative), InvalidInputError);
    EXPECT_THROW(remeshLocally({surface, tree, all, {}, {}, {1.0, 2.0}}, {}), InvalidInputError);
    EXPECT_THROW(remeshLocally({surface, tree, all, {}, {}, std::vector<double>(surface.faces.size(), 0.0)}, {}),
                 InvalidInputError);
    EXPECT_THROW(remeshLocally({surface, tree, all, {{0, 1000}}, {}, {}}, {}), InvalidInputError);
    EXPECT_THROW(remeshLocally({surface, tree, all, {}, {-1}, {}}, {}), InvalidInputError);
    // Three faces on one edge.
    TriMesh fin = surface;
    fin.vertices.emplace_back(3, 3, 3);
    fin.faces.push_back({fin.faces[0][0], fin.faces[0][1], fin.vertexCount() - 1});
    const ClosestPointTree finTree(fin);
    const std::vector<char> finAll(fin.faces.size(), 1);
    EXPECT_THROW(remeshLocally({fin, finTree, finAll, {}, {}, {}}, {}), InvalidInputError);
    // Nothing selected: nothing out, no error.
    const std::vector<char> none(surface.faces.size(), 0);
    EXPECT_EQ(remeshLocally({surface, tree, none, {}, {}, {}}, {}).mesh.faceCount(), 0);
}
