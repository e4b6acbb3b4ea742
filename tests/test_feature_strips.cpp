// Feature lines on strips narrower than the edge length (core/feature_strips.h): a thin plate's
// rims, a small hole's rim and a crease beside the open border are left to the free optimisation;
// wider strips, one line bending round and a wedge are kept; the end-to-end gain on the plate
// with sharp features on.
#include "feature_strips.h"
#include "metrics.h"
#include "remesh.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace fieldcvt;

namespace {

constexpr double kLength = 1.0746;  // the working frame's edge length (remesh_stages.h)

// A closed polyline of `pieces` edges round a circle of radius `radius` (vertices only: the
// strips are measured on the lines).
std::pair<TriMesh, FeatureLines> circleLine(double radius, int pieces)
{
    TriMesh m;
    FeatureLines lines;
    for (int i = 0; i < pieces; ++i) {
        const double a = 2 * kPi * i / pieces;
        m.vertices.emplace_back(radius * std::cos(a), radius * std::sin(a), 0.0);
        lines.edges.push_back({std::min(i, (i + 1) % pieces), std::max(i, (i + 1) % pieces)});
    }
    return {m, lines};
}

}  // namespace

TEST(FeatureStrips, ThinPlateRimsAreDroppedThenTheirShortCornerEdges)
{
    const TriMesh plate = testmesh::scaledThinBox(12.0, 0.24);  // rims 0.24 wide: under 0.75 of the length
    const FeatureLines lines = detectFeatures(plate, 45);
    ASSERT_EQ(lines.edges.size(), 8u * 8u + 4u);  // 8 rim lines of 8 edges, 4 short corner edges
    // The rims go; the corner edges across the thickness are left as pieces 0.24 long, shorter
    // than an edge: they go too.
    const NarrowStrips narrow = findNarrowStrips(plate, lines, kLength);
    EXPECT_EQ(narrow.dropped, 68);
    EXPECT_TRUE(narrow.kept.empty());
    NarrowStripParams noFragments;
    noFragments.fragmentShare = 0;
    const NarrowStrips rimsOnly = findNarrowStrips(plate, lines, kLength, noFragments);
    EXPECT_EQ(rimsOnly.dropped, 64);
    ASSERT_EQ(rimsOnly.kept.size(), 4u);
    for (const auto& [a, b] : rimsOnly.kept)
        EXPECT_NEAR((plate.vertices[size_t(a)] - plate.vertices[size_t(b)]).norm(), 0.24, 1e-9);
    // A shorter length resolves the rims: nothing is dropped.
    const NarrowStrips resolved = findNarrowStrips(plate, lines, 0.24 / 0.8);
    EXPECT_EQ(resolved.kept, lines.edges);
    EXPECT_EQ(resolved.dropped, 0);
    // Nor on a thick box.
    const TriMesh box = testmesh::scaledThinBox(12.0, 3.0);
    const FeatureLines boxLines = detectFeatures(box, 45);
    EXPECT_EQ(findNarrowStrips(box, boxLines, kLength).kept, boxLines.edges);
}

TEST(FeatureStrips, SmallHoleRimIsDroppedALineBendingRoundIsKept)
{
    // A rim 0.6 across (under 0.75 of the length): its far side is a line beside it.
    const auto [smallRim, smallLines] = circleLine(0.3, 24);
    const NarrowStrips small = findNarrowStrips(smallRim, smallLines, kLength);
    EXPECT_TRUE(small.kept.empty());
    EXPECT_EQ(small.dropped, 24);
    // 2 across: wider than the strip limit, kept; its near parts bend round, not beside.
    const auto [largeRim, largeLines] = circleLine(1.0, 48);
    EXPECT_EQ(findNarrowStrips(largeRim, largeLines, kLength).kept.size(), 48u);
    // Off: a share of 0 keeps every line.
    NarrowStripParams off;
    off.widthShare = 0;
    EXPECT_EQ(findNarrowStrips(smallRim, smallLines, kLength, off).kept.size(), 24u);
}

TEST(FeatureStrips, CreaseBesideTheOpenBorderIsDroppedFarFromItKept)
{
    // An open sheet 4 x 4 in 0.1 cells, bent up square along y = 4 - flange: a crease `flange`
    // from the open border (a sheet-metal flange).
    auto bentSheet = [](double flange) {
        TriMesh m;
        const int n = 40;
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const double x = 0.1 * i, y = 0.1 * j, bend = 4.0 - flange;
                m.vertices.push_back(y <= bend + 1e-9 ? Vec3(x, y, 0) : Vec3(x, bend, y - bend));
            }
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
                m.faces.push_back({a, b, d});
                m.faces.push_back({a, d, c});
            }
        return m;
    };
    const TriMesh narrow = bentSheet(0.3);
    const FeatureLines narrowLines = detectFeatures(narrow, 45);
    ASSERT_EQ(narrowLines.edges.size(), 40u);
    EXPECT_EQ(findNarrowStrips(narrow, narrowLines, kLength).dropped, 40);
    const TriMesh wide = bentSheet(1.5);
    const FeatureLines wideLines = detectFeatures(wide, 45);
    ASSERT_EQ(wideLines.edges.size(), 40u);
    EXPECT_EQ(findNarrowStrips(wide, wideLines, kLength).dropped, 0);
}

TEST(FeatureStrips, WedgeIsKeptAFoldIsNot)
{
    // Two lines leaving (0, 0, 0) `degrees` apart, 4 long in 8 edges: near the apex closer than
    // any width.
    auto lines = [](double degrees) {
        TriMesh m;
        FeatureLines out;
        m.vertices.emplace_back(0, 0, 0);
        for (int side = 0; side < 2; ++side) {
            const double a = (side ? 0.5 : -0.5) * degrees * kPi / 180;
            for (int i = 1; i <= 8; ++i) {
                m.vertices.emplace_back(0.5 * i * std::cos(a), 0.5 * i * std::sin(a), 0.0);
                const int v = static_cast<int>(m.vertices.size()) - 1;
                out.edges.push_back({i == 1 ? 0 : v - 1, v});
            }
        }
        std::sort(out.edges.begin(), out.edges.end());
        return std::make_pair(m, out);
    };
    // A 25° wedge (fandisk has one of 22°): its lines stay, with the apex between them.
    const auto [wedge, wedgeLines] = lines(25);
    const NarrowStrips keptWedge = findNarrowStrips(wedge, wedgeLines, kLength);
    EXPECT_EQ(keptWedge.dropped, 0);
    EXPECT_EQ(keptWedge.kept, wedgeLines.edges);
    // A 5° fold (a line doubling back, as in a CAD export's slivers): its narrow part goes; the
    // far ends, 0.35 apart, are still narrow, so all of it.
    const auto [fold, foldLines] = lines(5);
    EXPECT_EQ(findNarrowStrips(fold, foldLines, kLength).dropped, 16);
}

TEST(FeatureStrips, ThinPlateWithSharpFeaturesGetsNoSlivers)
{
    // A 12 x 0.3 x 12 plate at 400 vertices: edges about 1.4 long, rims 0.3 wide. Its rim lines
    // kept, the samples on both sides of every rim make slivers; left free, none.
    const TriMesh plate = testmesh::scaledThinBox(12.0, 0.3);
    RemeshParams params;
    params.vertexCount = 400;
    params.featureAngleDegrees = 45;
    params.threads = 2;
    const RemeshResult result = remesh(plate, params);
    const QualityMetrics m = computeQuality(result.mesh);
    EXPECT_GE(m.thetaMin, 15.0);
    EXPECT_LE(m.pctLt30, 0.5);
    const TopologySummary topology = computeTopology(result.mesh);
    EXPECT_TRUE(topology.manifold());
    EXPECT_EQ(topology.boundaryLoops, 0);
    EXPECT_EQ(topology.genus, 0);
    bool noted = false;
    for (const std::string& note : result.notes) noted = noted || note.find("narrower than") != std::string::npos;
    EXPECT_TRUE(noted);

    params.narrowFeatureStripShare = 0;  // every line kept: the slivers this change removes
    const QualityMetrics kept = computeQuality(remesh(plate, params).mesh);
    EXPECT_LT(kept.thetaMin, m.thetaMin);
}
