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
