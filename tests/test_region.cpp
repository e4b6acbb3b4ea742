// Remeshing a region (region.h): extraction, pinning, stitching, and the whole of remeshRegion on
// a sphere cap: the rest kept bit for bit, the seam watertight, the inside well shaped.
#include "errors.h"
#include "metrics.h"
#include "region.h"
#include "test_meshes.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <set>

#include <gtest/gtest.h>

using namespace fieldcvt;
using namespace fieldcvt::testmesh;

namespace {

//! Faces whose centroid is within `angle` radians of direction `axis` (a cap on the sphere).
std::vector<char> capSelection(const TriMesh& mesh, const Vec3& axis, double angle)
{
    std::vector<char> selected(mesh.faces.size(), 0);
    for (size_t f = 0; f < mesh.faces.size(); ++f) {
        const Face& t = mesh.faces[f];
        const Vec3 c = (mesh.vertices[size_t(t[0])] + mesh.vertices[size_t(t[1])] + mesh.vertices[size_t(t[2])]) / 3;
        selected[f] = c.normalized().dot(axis.normalized()) > std::cos(angle);
    }
    return selected;
}

bool sameBits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0; }

//! The guarantees of a region remesh: kept faces and vertices identical, bit for bit and in order;
//! every edge with one face where the input had one and two elsewhere (no crack, no T-junction);
//! no two vertices at the same place; manifold; the Euler characteristic of the input.
void expectStitched(const TriMesh& input, const std::vector<char>& selected, const RegionRemeshResult& out)
{
    const TriMesh& mesh = out.result.mesh;
    ASSERT_EQ(out.vertexOrigin.size(), mesh.vertices.size());
    ASSERT_EQ(out.faceOrigin.size(), mesh.faces.size());
    int keptFaces = 0, lastFace = -1, lastVertex = -1;
    for (size_t v = 0; v < mesh.vertices.size(); ++v)
        if (out.vertexOrigin[v] >= 0) {
            EXPECT_GT(out.vertexOrigin[v], lastVertex);  // input order
            lastVertex = out.vertexOrigin[v];
            EXPECT_TRUE(sameBits(mesh.vertices[v], input.vertices[size_t(out.vertexOrigin[v])]));
        }
    for (size_t f = 0; f < mesh.faces.size(); ++f) {
        const int origin = out.faceOrigin[f];
        if (origin < 0) continue;
        ++keptFaces;
        EXPECT_GT(origin, lastFace);
        lastFace = origin;
        for (int k = 0; k < 3; ++k) EXPECT_EQ(out.vertexOrigin[size_t(mesh.faces[f][k])], input.faces[size_t(origin)][k]);
    }
    int unselected = 0;
    for (char s : selected) unselected += !s;
    EXPECT_GE(keptFaces, unselected);
    // Seam: every edge keeps the input's face count (closed stays closed), none has three faces.
    std::map<std::pair<int, int>, int> inputEdges, outputEdges;
    for (const Face& t : input.faces)
        for (int k = 0; k < 3; ++k) ++inputEdges[std::minmax(t[k], t[(k + 1) % 3])];
    for (const Face& t : mesh.faces)
        for (int k = 0; k < 3; ++k) ++outputEdges[std::minmax(t[k], t[(k + 1) % 3])];
    for (const auto& [edge, count] : outputEdges) {
        const int a = out.vertexOrigin[size_t(edge.first)], b = out.vertexOrigin[size_t(edge.second)];
        if (count == 1) {
            ASSERT_TRUE(a >= 0 && b >= 0) << "a new edge on the border: a crack";
            EXPECT_EQ(inputEdges[std::minmax(a, b)], 1) << "an edge open in the output, closed in the input";
        } else {
            EXPECT_EQ(count, 2);
        }
    }
    std::set<std::array<double, 3>> places;
    for (const Vec3& p : mesh.vertices) EXPECT_TRUE(places.insert({p.x(), p.y(), p.z()}).second) << "duplicate vertex";
    const TopologySummary in = computeTopology(input), got = computeTopology(mesh);
    EXPECT_TRUE(got.manifold());
    EXPECT_EQ(got.vertices - got.edges + got.faces, in.vertices - in.edges + in.faces);
    EXPECT_EQ(got.boundaryLoops, in.boundaryLoops);
    EXPECT_EQ(got.components, in.components);
}

std::string warnings(const RegionRemeshResult& out)
{
    std::string all;
    for (const std::string& w : out.result.warnings) all += w + "\n";
    return all;
}

RemeshParams params(int vertices)
{
    RemeshParams p;
    p.vertexCount = vertices;
    p.seed = 1;
    return p;
}

}  // namespace

TEST(Region, ComponentsAreEdgeConnectedPieces)
{
    const TriMesh grid = planeGrid(4);  // faces 2c, 2c + 1 share the diagonal of cell c
    std::vector<char> selected(grid.faces.size(), 0);
    selected[0] = selected[1] = 1;    // cell (0, 0)
    selected[10] = selected[11] = 1;  // cell (1, 1): meets cell (0, 0) at a corner only
    const auto pieces = regionComponents(grid, selected);
    ASSERT_EQ(pieces.size(), 2u);
    EXPECT_EQ(pieces[0], (std::vector<int>{0, 1}));
    EXPECT_EQ(pieces[1], (std::vector<int>{10, 11}));
    selected[2] = selected[3] = 1;  // cell (1, 0) joins them through edges
    EXPECT_EQ(regionComponents(grid, selected).size(), 1u);
}

TEST(Region, ExtractionKeepsCoordinatesAndFindsTheBorder)
{
    const TriMesh sphere = icosphere(3);
    const std::vector<char> selected = capSelection(sphere, Vec3(0, 0, 1), 0.6);
    const auto pieces = regionComponents(sphere, selected);
    ASSERT_EQ(pieces.size(), 1u);
    const RegionSubmesh region = extractRegion(sphere, pieces[0]);
    ASSERT_EQ(region.mesh.faceCount(), int(pieces[0].size()));
    for (size_t v = 0; v < region.originalVertex.size(); ++v)
        EXPECT_TRUE(sameBits(region.mesh.vertices[v], sphere.vertices[size_t(region.originalVertex[v])]));
    const auto loops = borderLoops(region.mesh);
    ASSERT_EQ(loops.size(), 1u);
    int border = 0;
    for (char b : region.border) border += b;
    EXPECT_EQ(border, int(loops[0].size()));
    // The loop runs with the region on its left: against the cap's outward normal, counter-clockwise.
    Vec3 turn = Vec3::Zero();
    for (size_t i = 0; i < loops[0].size(); ++i)
        turn +=
            region.mesh.vertices[size_t(loops[0][i])].cross(region.mesh.vertices[size_t(loops[0][(i + 1) % loops[0].size()])]);
    EXPECT_GT(turn.z(), 0);
}

TEST(Region, StitchingSharesBorderVerticesByIndex)
{
    const TriMesh grid = planeGrid(3);
    std::vector<char> selected(grid.faces.size(), 0);
    selected[8] = selected[9] = 1;  // the middle cell
    const RegionSubmesh region = extractRegion(grid, regionComponents(grid, selected)[0]);
    // The cell split at a new centre vertex: four faces around it.
    RegionPatch patch;
    const auto loop = borderLoops(region.mesh)[0];
    ASSERT_EQ(loop.size(), 4u);
    Vec3 centre = Vec3::Zero();
    for (int v : loop) {
        patch.mesh.vertices.push_back(region.mesh.vertices[size_t(v)]);
        patch.original.push_back(region.originalVertex[size_t(v)]);
        centre += region.mesh.vertices[size_t(v)] / 4;
    }
    patch.mesh.vertices.push_back(centre);
    patch.original.push_back(-1);
    for (int i = 0; i < 4; ++i) patch.mesh.faces.push_back({i, (i + 1) % 4, 4});
    EXPECT_TRUE(patchMatchesBorder(region, patch));
    const StitchedMesh out = stitchRegions(grid, selected, {patch});
    EXPECT_EQ(out.mesh.vertexCount(), grid.vertexCount() + 1);
    EXPECT_EQ(out.mesh.faceCount(), grid.faceCount() - 2 + 4);
    RegionRemeshResult result;
    result.result.mesh = out.mesh;
    result.vertexOrigin = out.vertexOrigin;
    result.faceOrigin = out.faceOrigin;
    expectStitched(grid, selected, result);
    // A patch whose border is not the region's is refused.
    patch.mesh.faces.pop_back();
    EXPECT_FALSE(patchMatchesBorder(region, patch));
}

TEST(Region, SphereCapKeepsTheRestAndIsWellShaped)
{
    const TriMesh sphere = icosphere(4);  // edges about 0.062
    const std::vector<char> selected = capSelection(sphere, Vec3(0, 0, 1), kPi / 3);
    // About the border's edge length inside: the cap's area over the triangles of that edge.
    double area = 0;
    for (int f = 0; f < sphere.faceCount(); ++f) area += selected[size_t(f)] ? faceArea(sphere, f) : 0;
    const double edge = meanEdgeLength(sphere);
    const int vertices = int(std::lround(2 * area / (std::sqrt(3.0) * edge * edge)));
    const RegionRemeshResult out = remeshRegion(sphere, selected, params(vertices));
    expectStitched(sphere, selected, out);
    EXPECT_EQ(out.regions, 1);
    EXPECT_EQ(out.keptRegions, 0) << warnings(out);
    EXPECT_LT(out.worstBorderRatio, 2.0);
    const QualityMetrics& m = out.result.metrics;
    std::printf(
        "cap: %d vertices asked, border ratio %.2f; new faces: theta_min %.1f, Q_avg %.3f, V6 %.1f %%, d_H %.3g; "
        "interior theta_min %.1f\n",
        vertices, out.worstBorderRatio, m.thetaMin, m.qAvg, m.v6Pct, m.dH, out.interiorMetrics.thetaMin);
    EXPECT_GE(m.thetaMin, 20.0) << "border edges within 2x of the target: no angle under 20 degrees";
    EXPECT_GT(m.qAvg, 0.85);
    EXPECT_GT(out.interiorMetrics.thetaMin, 30.0);
    EXPECT_GT(m.v6Pct, 80.0);
    EXPECT_LT(m.dH, 0.01);
}

TEST(Region, EverythingSelectedIsTheFullRemesh)
{
    const TriMesh sphere = icosphere(3);
    const RemeshParams p = params(300);
    const RegionRemeshResult out = remeshRegion(sphere, std::vector<char>(sphere.faces.size(), 1), p);
    const RemeshResult full = remesh(sphere, p);
    EXPECT_TRUE(out.wholeMesh);
    ASSERT_EQ(out.result.mesh.vertices.size(), full.mesh.vertices.size());
    for (size_t v = 0; v < full.mesh.vertices.size(); ++v)
        EXPECT_TRUE(sameBits(out.result.mesh.vertices[v], full.mesh.vertices[v]));
    EXPECT_EQ(out.result.mesh.faces, full.mesh.faces);
}

TEST(Region, BadSelectionsHaveClearMessages)
{
    const TriMesh sphere = icosphere(2);
    try {
        remeshRegion(sphere, std::vector<char>(sphere.faces.size(), 0), params(100));
        FAIL() << "an empty selection was accepted";
    } catch (const InvalidInputError& e) {
        EXPECT_NE(std::string(e.what()).find("empty"), std::string::npos) << e.what();
    }
    EXPECT_THROW(remeshRegion(sphere, std::vector<char>(3, 1), params(100)), InvalidInputError);
    RegionParams bad;
    bad.grading = 0;
    EXPECT_THROW(remeshRegion(sphere, capSelection(sphere, Vec3(0, 0, 1), 0.5), params(100), bad), InvalidInputError);
}

TEST(Region, SeparatePiecesAreEachRemeshed)
{
    const TriMesh sphere = icosphere(4);
    std::vector<char> selected = capSelection(sphere, Vec3(0, 0, 1), 0.7);
    const std::vector<char> south = capSelection(sphere, Vec3(0, 0, -1), 0.5);
    for (size_t f = 0; f < selected.size(); ++f) selected[f] |= south[f];
    const RegionRemeshResult out = remeshRegion(sphere, selected, params(600));
    expectStitched(sphere, selected, out);
    EXPECT_EQ(out.regions, 2);
    EXPECT_EQ(out.keptRegions, 0) << warnings(out);
    int newFaces = 0;
    for (int origin : out.faceOrigin) newFaces += origin < 0;
    EXPECT_GT(newFaces, 600);
}

TEST(Region, VertexContactsMakeSeparateRegions)
{
    const TriMesh grid = planeGrid(12);
    std::vector<char> selected(grid.faces.size(), 0);
    auto cell = [&](int x, int y) { selected[size_t(2 * (y * 12 + x))] = selected[size_t(2 * (y * 12 + x) + 1)] = 1; };
    for (int x = 2; x < 6; ++x)
        for (int y = 2; y < 6; ++y) cell(x, y);
    for (int x = 6; x < 10; ++x)
        for (int y = 6; y < 10; ++y) cell(x, y);  // meets the first block at the vertex (6, 6)
    const RegionRemeshResult out = remeshRegion(grid, selected, params(200));
    EXPECT_EQ(out.regions, 2);
    expectStitched(grid, selected, out);
}

TEST(Region, RegionOnTheMeshBoundaryKeepsThatBoundary)
{
    const TriMesh grid = planeGrid(10);
    std::vector<char> selected(grid.faces.size(), 0);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 10; ++x) selected[size_t(2 * (y * 10 + x))] = selected[size_t(2 * (y * 10 + x) + 1)] = 1;
    const RegionRemeshResult out = remeshRegion(grid, selected, params(150));
    EXPECT_EQ(out.keptRegions, 0) << warnings(out);
    expectStitched(grid, selected, out);
}

TEST(Region, OneFaceRegion)
{
    const TriMesh sphere = icosphere(3);
    std::vector<char> selected(sphere.faces.size(), 0);
    selected[7] = 1;
    const RegionRemeshResult out = remeshRegion(sphere, selected, params(30));
    expectStitched(sphere, selected, out);
    EXPECT_EQ(out.regions, 1);
    EXPECT_EQ(out.keptRegions, 0) << warnings(out);
    EXPECT_GT(out.result.mesh.faceCount(), sphere.faceCount());
    EXPECT_NE(warnings(out).find("times longer or shorter than the target length"), std::string::npos) << warnings(out);
}

TEST(Region, APieceTouchingItselfAtAVertexIsClosedThere)
{
    const int n = 16;
    const TriMesh grid = planeGrid(n);
    std::vector<char> selected(grid.faces.size(), 0);
    auto block = [&](int bx, int by) {  // 2 x 2 cells
        for (int y = 2 * by; y < 2 * by + 2; ++y)
            for (int x = 2 * bx; x < 2 * bx + 2; ++x)
                selected[size_t(2 * (y * n + x))] = selected[size_t(2 * (y * n + x) + 1)] = 1;
    };
    // A hook from block (2, 2) round to block (3, 3): they meet at the vertex (6, 6) only.
    for (const auto& [x, y] : std::vector<std::pair<int, int>>{{2, 2}, {2, 1}, {3, 1}, {4, 1}, {4, 2}, {4, 3}, {3, 3}})
        block(x, y);
    std::vector<char> closed = selected;
    EXPECT_GT(closePinches(grid, closed), 0);
    EXPECT_EQ(closePinches(grid, closed), 0) << "closed once and for all";
    EXPECT_EQ(regionComponents(grid, closed).size(), 1u);
    const RegionRemeshResult out = remeshRegion(grid, selected, params(40));
    EXPECT_GT(out.addedFaces, 0);
    EXPECT_EQ(out.keptRegions, 0) << warnings(out);
    expectStitched(grid, closed, out);
}

// Issue 50, item 4: a selection that is not a manifold, oriented surface is repaired as the whole
// mesh would be, or refused; the kept faces' own faults are kept, and said.
namespace {

//! `mesh` with a fin of `rows` strips of two faces standing out of its edge a-b (which then has
//! three faces), each fin face selected as `finSelected` in `selected` (grown to match).
TriMesh withFin(TriMesh mesh, int a, int b, int rows, std::vector<char>& selected, char finSelected)
{
    int prevA = a, prevB = b;
    for (int r = 1; r <= rows; ++r) {
        mesh.vertices.push_back(mesh.vertices[size_t(a)] * (1 + 0.15 * r));
        mesh.vertices.push_back(mesh.vertices[size_t(b)] * (1 + 0.15 * r));
        const int na = mesh.vertexCount() - 2, nb = mesh.vertexCount() - 1;
        mesh.faces.push_back({prevA, prevB, nb});
        mesh.faces.push_back({prevA, nb, na});
        selected.push_back(finSelected);
        selected.push_back(finSelected);
        prevA = na, prevB = nb;
    }
    return mesh;
}

//! An edge of the face nearest to `direction` (inside a cap around it).
std::pair<int, int> edgeToward(const TriMesh& mesh, const Vec3& direction)
{
    size_t best = 0;
    double nearest = 1e300;
    for (size_t f = 0; f < mesh.faces.size(); ++f) {
        const Face& t = mesh.faces[f];
        const Vec3 c = (mesh.vertices[size_t(t[0])] + mesh.vertices[size_t(t[1])] + mesh.vertices[size_t(t[2])]) / 3;
        if ((c.normalized() - direction).norm() < nearest) nearest = (c.normalized() - direction).norm(), best = f;
    }
    return {mesh.faces[best][0], mesh.faces[best][1]};
}

//! No fault at all, and every face not selected kept bit for bit.
void expectCleanAndKept(const TriMesh& input, const std::vector<char>& selected, const RegionRemeshResult& out)
{
    const TopologySummary got = computeTopology(out.result.mesh);
    EXPECT_EQ(got.nonManifoldEdges, 0);
    EXPECT_EQ(got.nonManifoldVertices, 0);
    EXPECT_TRUE(got.orientable);
    std::vector<char> seen(input.faces.size(), 0);
    for (size_t f = 0; f < out.faceOrigin.size(); ++f) {
        if (out.faceOrigin[f] < 0) continue;
        seen[size_t(out.faceOrigin[f])] = 1;
        for (int k = 0; k < 3; ++k)
            EXPECT_TRUE(sameBits(out.result.mesh.vertices[size_t(out.result.mesh.faces[f][k])],
                                 input.vertices[size_t(input.faces[size_t(out.faceOrigin[f])][k])]));
    }
    for (size_t f = 0; f < selected.size(); ++f)
        if (!selected[f]) EXPECT_TRUE(seen[f]) << "face " << f << " was not selected but is gone";
}

}  // namespace

TEST(RegionRepair, ANonManifoldEdgeInsideTheSelectionIsRepaired)
{
    // Fins of one and three rows, 0.6 % and more of the region's area: parts (RepairParams::
    // keepAreaFraction, 0.5 %), kept however few vertices the target gives them.
    for (int rows : {1, 3}) {
        const TriMesh sphere = icosphere(3);
        std::vector<char> selected = capSelection(sphere, Vec3(0, 0, 1), kPi / 3);
        const auto [a, b] = edgeToward(sphere, Vec3(0, 0, 1));
        const TriMesh mesh = withFin(sphere, a, b, rows, selected, 1);
        ASSERT_EQ(computeTopology(mesh).nonManifoldEdges, 1);
        const RegionRemeshResult out = remeshRegion(mesh, selected, params(300));
        EXPECT_EQ(out.keptRegions, 0) << warnings(out);
        EXPECT_NE(warnings(out).find("non-manifold edges (more than two faces) split"), std::string::npos) << warnings(out);
        expectCleanAndKept(mesh, selected, out);
        // Kept, the fin is one border loop of its own.
        EXPECT_EQ(computeTopology(out.result.mesh).boundaryLoops, 1) << warnings(out);
    }
}

TEST(RegionRepair, ANonManifoldEdgeOnTheBorderIsTakenIn)
{
    const TriMesh sphere = icosphere(3);
    std::vector<char> selected = capSelection(sphere, Vec3(0, 0, 1), kPi / 3);
    // A fin, not selected, on an edge inside the cap; and one on an edge of the cap's border.
    const auto [a, b] = edgeToward(sphere, Vec3(0, 0, 1));
    TriMesh mesh = withFin(sphere, a, b, 2, selected, 0);
    std::map<std::pair<int, int>, std::vector<int>> faces;
    for (int f = 0; f < sphere.faceCount(); ++f)
        for (int k = 0; k < 3; ++k)
            faces[std::minmax(sphere.faces[size_t(f)][k], sphere.faces[size_t(f)][(k + 1) % 3])].push_back(f);
    for (const auto& [edge, two] : faces)
        if (selected[size_t(two[0])] != selected[size_t(two[1])]) {
            mesh = withFin(mesh, edge.first, edge.second, 2, selected, 1);
            break;
        }
    std::vector<char> grown = selected;
    EXPECT_EQ(takeInNonManifoldEdges(mesh, grown), 2) << "the first fin's face on the edge, the border's other face";
    EXPECT_EQ(takeInNonManifoldEdges(mesh, grown), 0);
    const RegionRemeshResult out = remeshRegion(mesh, selected, params(300));
    EXPECT_GE(out.addedFaces, 2);
    EXPECT_EQ(out.keptRegions, 0) << warnings(out);
    std::vector<char> closed = selected;
    closePinches(mesh, closed);
    takeInNonManifoldEdges(mesh, closed);
    closePinches(mesh, closed);
    expectCleanAndKept(mesh, closed, out);
}

TEST(RegionRepair, RepairKeepsTheSeamVerticesAndNumbersTheCopies)
{
    const TriMesh sphere = icosphere(3);
    std::vector<char> selected = capSelection(sphere, Vec3(0, 0, 1), kPi / 3);
    const auto [a, b] = edgeToward(sphere, Vec3(0, 0, 1));
    const TriMesh mesh = withFin(sphere, a, b, 3, selected, 1);
    RegionSubmesh region = extractRegion(mesh, regionComponents(mesh, selected)[0]);
    EXPECT_FALSE(regionIsClean(region));
    const KeptEdges kept = keptEdges(mesh, selected);
    int nextCopyId = mesh.vertexCount();
    const RepairReport report = repairRegion(region, kept, 0, nextCopyId);
    EXPECT_EQ(report.nonManifoldEdges, 1);
    EXPECT_TRUE(regionIsClean(region));
    EXPECT_TRUE(region.repaired);
    EXPECT_EQ(nextCopyId, mesh.vertexCount() + 2) << "the fin's copies of a and b";
    std::set<int> ids;
    for (size_t v = 0; v < region.originalVertex.size(); ++v) {
        EXPECT_TRUE(ids.insert(region.originalVertex[v]).second);
        EXPECT_TRUE(sameBits(region.mesh.vertices[v], mesh.vertices[size_t(region.sourceVertex[v])]));
    }
    // Every border edge that meets the kept faces is between whole-mesh vertices, not copies:
    // the seam, run the other way than the kept faces run it.
    int seam = 0;
    for (const std::vector<int>& loop : borderLoops(region.mesh))
        for (size_t i = 0; i < loop.size(); ++i) {
            const size_t u = size_t(loop[i]), w = size_t(loop[(i + 1) % loop.size()]);
            if (!kept.touches(region.sourceVertex[u], region.sourceVertex[w])) continue;
            ++seam;
            EXPECT_EQ(region.originalVertex[u], region.sourceVertex[u]);
            EXPECT_EQ(region.originalVertex[w], region.sourceVertex[w]);
            EXPECT_TRUE(kept.runs(region.originalVertex[w], region.originalVertex[u]));
        }
    EXPECT_GT(seam, 20);
    EXPECT_EQ(regionParts(region).size(), 2u) << "the cap and the fin";
}

TEST(RegionRepair, AFlippedSelectionIsOrientedAsTheKeptFaces)
{
    TriMesh sphere = icosphere(3);
    const std::vector<char> selected = capSelection(sphere, Vec3(0, 0, 1), kPi / 3);
    int flipped = 0;
    for (size_t f = 0; f < sphere.faces.size(); ++f)
        if (selected[f]) std::swap(sphere.faces[f][1], sphere.faces[f][2]), ++flipped;
    RegionSubmesh region = extractRegion(sphere, regionComponents(sphere, selected)[0]);
    EXPECT_TRUE(regionIsClean(region)) << "consistent in itself";
    int against = -1;
    EXPECT_EQ(orientRegionToKept(region, keptEdges(sphere, selected), &against), flipped);
    EXPECT_EQ(against, 0);
    const RegionRemeshResult out = remeshRegion(sphere, selected, params(300));
    EXPECT_NE(warnings(out).find("reversed"), std::string::npos) << warnings(out);
    expectCleanAndKept(sphere, selected, out);
}

TEST(RegionRepair, FaultsOfTheKeptFacesAreTheInputsOwn)
{
    const TriMesh sphere = icosphere(3);
    std::vector<char> selected = capSelection(sphere, Vec3(0, 0, 1), kPi / 3);
    const auto [a, b] = edgeToward(sphere, Vec3(0, 0, -1));  // far from the cap
    const TriMesh mesh = withFin(sphere, a, b, 2, selected, 0);
    const RegionRemeshResult out = remeshRegion(mesh, selected, params(300));
    EXPECT_EQ(computeTopology(out.result.mesh).nonManifoldEdges, 1);
    EXPECT_NE(warnings(out).find("the output keeps the input's own 1 non-manifold edge"), std::string::npos) << warnings(out);
    SurfaceFaults kept, elsewhere;
    stitchedFaults(mesh, selected, {out.result.mesh, out.vertexOrigin, out.faceOrigin}, kept, elsewhere);
    EXPECT_EQ(kept.nonManifoldEdges, 1);
    EXPECT_FALSE(elsewhere.any());
}

TEST(RegionRepair, AResultThatCannotBeOrientedIsRefused)
{
    // The band's one orientation fault lies inside the selection; the kept half cannot agree with
    // both ends of any orientation of it.
    const TriMesh band = moebius(48);
    std::vector<char> selected(band.faces.size(), 0);
    for (size_t f = 0; f < selected.size(); ++f) selected[f] = f < 16 || f >= selected.size() - 16;
    try {
        remeshRegion(band, selected, params(120));
        FAIL() << "a result with an orientation fault was returned";
    } catch (const InvalidInputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("edge between faces of opposite orientation"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "one line";
    }
}

TEST(RegionRepair, FaultsAreDescribedInWords)
{
    EXPECT_EQ((SurfaceFaults{1, 2, 0}.describe()), "1 non-manifold edge and 2 edges between faces of opposite orientation");
    EXPECT_EQ((SurfaceFaults{2, 0, 1}.describe()), "2 non-manifold edges and 1 non-manifold vertex");
    EXPECT_FALSE(SurfaceFaults{}.any());
}
