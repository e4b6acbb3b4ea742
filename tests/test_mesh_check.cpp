// Input validation and repair before any work: clear errors, never a crash.
#include "errors.h"
#include "mesh_check.h"
#include "remesh.h"
#include "surface_gluing.h"
#include "test_meshes.h"
#include "thread_count.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <map>

using namespace fieldcvt;

TEST(MeshCheck, RejectsEmptyMeshAndPointCloud)
{
    EXPECT_NE(testmesh::inputError(TriMesh{}).find("empty"), std::string::npos);
    TriMesh cloud;
    cloud.vertices = {{0, 0, 0}, {1, 0, 0}};
    EXPECT_NE(testmesh::inputError(cloud).find("point cloud"), std::string::npos);
}

TEST(MeshCheck, RejectsFacesWhoseCornersLieOnOneLineUpToRounding)
{
    // Points of one line that doubles cannot place exactly on it: areas of ~1e-17, not 0.
    TriMesh line;
    for (double t : {0.3, 1.1, 2.9, 4.7, 6.1}) line.vertices.push_back(Vec3(0.1, 0.7, 0.3) * t);
    line.faces = {{0, 1, 2}, {1, 2, 3}, {2, 3, 4}};
    EXPECT_NE(testmesh::inputError(line).find("on one line"), std::string::npos) << testmesh::inputError(line);
    // One real face among them is a surface (its needles are kept for the RVD).
    line.vertices.push_back({0, 0, 1});
    line.faces.push_back({0, 4, 5});
    EXPECT_EQ(testmesh::inputError(line), "");
}

TEST(MeshCheck, RejectsNonFiniteCoordinatesAndBadIndices)
{
    TriMesh m = testmesh::planeGrid(2);
    m.vertices[4].x() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_NE(testmesh::inputError(m).find("vertex 4 has a non-finite coordinate"), std::string::npos);
    TriMesh bad = testmesh::planeGrid(2);
    bad.faces[0][1] = 99;
    EXPECT_NE(testmesh::inputError(bad).find("refers to vertex 99"), std::string::npos);
}

TEST(MeshCheck, RejectsNonManifoldEdgeWithCountAndLocation)
{
    TriMesh m = testmesh::planeGrid(1);  // two triangles sharing the diagonal (0, 3)
    m.vertices.emplace_back(0.5, 0.5, 1.0);
    m.faces.push_back({0, 3, 4});
    const std::string error = testmesh::inputError(m);
    EXPECT_NE(error.find("1 non-manifold edge"), std::string::npos) << error;
    EXPECT_NE(error.find("vertices 0"), std::string::npos) << error;
}

TEST(MeshCheck, RemovesUnreferencedDegenerateAndDuplicateFaces)
{
    TriMesh m = testmesh::planeGrid(2);
    m.vertices.emplace_back(5, 5, 5);  // unreferenced
    m.faces.push_back({0, 0, 1});      // repeated corner
    m.faces.push_back({0, 1, 2});      // collinear: zero area
    m.faces.push_back(m.faces[0]);     // duplicate
    InputReport report;
    const TriMesh clean = prepareInput(m, report);
    EXPECT_EQ(report.removedUnreferencedVertices, 1);
    EXPECT_EQ(report.removedDegenerateFaces, 2);
    EXPECT_EQ(report.removedDuplicateFaces, 1);
    EXPECT_EQ(clean.faceCount(), 8);
    EXPECT_EQ(clean.vertexCount(), 9);
    EXPECT_EQ(report.notes.size(), 2u);        // the faces removed: they were in the file
    EXPECT_EQ(report.information.size(), 1u);  // the unreferenced vertex: nothing a user sees
}

// ---------------------------------------------------------------------------------------------
// Repairs (issue 6): each one counted and reported as a note, never silent.

namespace {

//! In the notes or the information lines (which only differ in how loudly they are said).
bool hasNote(const InputReport& report, const std::string& text)
{
    for (const auto* lines : {&report.notes, &report.information})
        for (const std::string& note : *lines)
            if (note.find(text) != std::string::npos) return true;
    return false;
}

std::string allNotes(const InputReport& report)
{
    std::string s;
    for (const auto* lines : {&report.notes, &report.information})
        for (const std::string& note : *lines) s += note + "\n";
    return s;
}

// Every input vertex that survives maps to a clean vertex at the same place.
void expectCleanIndexConsistent(const TriMesh& input, const TriMesh& clean, const InputReport& report)
{
    ASSERT_EQ(report.cleanIndex.size(), input.vertices.size());
    for (int v = 0; v < input.vertexCount(); ++v) {
        const int c = report.cleanIndex[v];
        if (c < 0) continue;
        ASSERT_LT(c, clean.vertexCount());
        EXPECT_EQ(clean.vertices[c], input.vertices[v]) << "input vertex " << v;
    }
}

// Across every edge shared by two faces, the faces run in opposite directions.
bool consistentlyOriented(const TriMesh& m)
{
    std::map<std::pair<int, int>, int> directed;
    for (const Face& t : m.faces)
        for (int k = 0; k < 3; ++k)
            if (++directed[{t[k], t[(k + 1) % 3]}] > 1) return false;
    return true;
}

// Closed cone: apex at `apex`, a ring of `k` vertices and a cap centre at height `dir`.
void addCone(TriMesh& m, const Vec3& apex, double dir, int k, int apexIndex = -1)
{
    const double pi = 3.14159265358979323846;
    const int a = apexIndex >= 0 ? apexIndex : m.vertexCount();
    if (apexIndex < 0) m.vertices.push_back(apex);
    const int ring = m.vertexCount();
    for (int i = 0; i < k; ++i)
        m.vertices.push_back(apex + Vec3(0.5 * std::cos(2 * pi * i / k), 0.5 * std::sin(2 * pi * i / k), dir));
    const int cap = m.vertexCount();
    m.vertices.push_back(apex + Vec3(0, 0, dir));
    for (int i = 0; i < k; ++i) {
        const int p = ring + i, q = ring + (i + 1) % k;
        if (dir > 0) {
            m.faces.push_back({a, q, p});
            m.faces.push_back({cap, p, q});
        } else {
            m.faces.push_back({a, p, q});
            m.faces.push_back({cap, q, p});
        }
    }
}

}  // namespace

TEST(MeshCheck, MergesExactlyDuplicateVerticesFirst)
{
    // A triangle soup: every face has its own three vertices.
    const TriMesh grid = testmesh::planeGrid(3);
    TriMesh soup;
    for (const Face& t : grid.faces) {
        Face s;
        for (int k = 0; k < 3; ++k) {
            s[k] = soup.vertexCount();
            soup.vertices.push_back(grid.vertices[t[k]]);
        }
        soup.faces.push_back(s);
    }
    InputReport report;
    const TriMesh clean = prepareInput(soup, report);
    EXPECT_EQ(clean.vertexCount(), grid.vertexCount());
    EXPECT_EQ(clean.faceCount(), grid.faceCount());
    EXPECT_EQ(report.mergedDuplicateVertices, soup.vertexCount() - grid.vertexCount());
    EXPECT_EQ(report.removedUnreferencedVertices, 0);
    EXPECT_EQ(report.components, 1);
    EXPECT_TRUE(hasNote(report, "merged " + std::to_string(report.mergedDuplicateVertices) + " duplicate vertices"))
        << allNotes(report);
    EXPECT_FALSE(hasNote(report, "components")) << allNotes(report);
    expectCleanIndexConsistent(soup, clean, report);
    EXPECT_TRUE(consistentlyOriented(clean));
}

TEST(MeshCheck, MergedVerticesCanMakeFacesDegenerateOrDuplicate)
{
    TriMesh m = testmesh::planeGrid(1);  // 0 (0,0)  1 (1,0)  2 (0,1)  3 (1,1)
    m.vertices.emplace_back(1, 0, 0);    // 4: copy of 1
    m.vertices.emplace_back(1, 1, 0);    // 5: copy of 3
    m.faces.push_back({0, 4, 5});        // the first face again, through the copies
    m.faces.push_back({1, 4, 3});        // repeated corner once merged
    InputReport report;
    const TriMesh clean = prepareInput(m, report);
    EXPECT_EQ(clean.faceCount(), 2);
    EXPECT_EQ(clean.vertexCount(), 4);
    EXPECT_EQ(report.mergedDuplicateVertices, 2);
    EXPECT_EQ(report.removedDuplicateFaces, 1);
    EXPECT_EQ(report.removedDegenerateFaces, 1);
    EXPECT_EQ(report.cleanIndex[4], report.cleanIndex[1]);
    EXPECT_EQ(report.cleanIndex[5], report.cleanIndex[3]);
    expectCleanIndexConsistent(m, clean, report);
}

TEST(MeshCheck, FlipsInconsistentFacesPerComponent)
{
    TriMesh m = testmesh::torus(12, 8);
    int flipped = 0;
    for (int f = 1; f < m.faceCount(); f += 3) {
        std::swap(m.faces[f][1], m.faces[f][2]);
        ++flipped;
    }
    InputReport report;
    TriMesh clean = prepareInput(m, report);
    EXPECT_EQ(report.flippedFaces, flipped);
    EXPECT_TRUE(consistentlyOriented(clean));
    EXPECT_EQ(clean.faces, testmesh::torus(12, 8).faces);  // back to the original orientation
    EXPECT_TRUE(hasNote(report, "flipped " + std::to_string(flipped) + " faces")) << allNotes(report);

    // The first face decides: flipping it flips the rest of its component instead.
    TriMesh first = testmesh::torus(12, 8);
    std::swap(first.faces[0][1], first.faces[0][2]);
    InputReport firstReport;
    clean = prepareInput(first, firstReport);
    EXPECT_EQ(firstReport.flippedFaces, first.faceCount() - 1);
    EXPECT_TRUE(consistentlyOriented(clean));
    EXPECT_EQ(clean.faces[0], first.faces[0]);
}

TEST(MeshCheck, OrientsEachComponentOnItsOwn)
{
    // Two tori, the second one entirely reversed: each is consistent on its own, nothing flips.
    TriMesh m = testmesh::torus(12, 8);
    const TriMesh second = testmesh::torus(12, 8, 1.0, 0.35);
    const int offset = m.vertexCount();
    for (const Vec3& p : second.vertices) m.vertices.push_back(p + Vec3(5, 0, 0));
    for (const Face& t : second.faces) m.faces.push_back({t[0] + offset, t[2] + offset, t[1] + offset});
    // ... and one face of the second torus flipped against its neighbours.
    std::swap(m.faces[second.faceCount() + 7][1], m.faces[second.faceCount() + 7][2]);
    InputReport report;
    const TriMesh clean = prepareInput(m, report);
    EXPECT_EQ(report.flippedFaces, 1);
    EXPECT_EQ(report.components, 2);
    ASSERT_EQ(report.componentAreas.size(), 2u);
    EXPECT_NEAR(report.componentAreas[0], report.componentAreas[1], 1e-9 * report.componentAreas[0]);
    EXPECT_TRUE(hasNote(report, "2 connected components")) << allNotes(report);
    EXPECT_TRUE(consistentlyOriented(clean));
}

TEST(MeshCheck, RejectsMoebiusStrip)
{
    const TriMesh m = testmesh::moebius();
    const std::string error = testmesh::inputError(m);
    EXPECT_NE(error.find("not orientable"), std::string::npos) << error;
    EXPECT_NE(error.find("Moebius"), std::string::npos) << error;
    EXPECT_NE(error.find("between vertices"), std::string::npos) << error;
}

TEST(MeshCheck, SplitsNonManifoldVertexIntoOneVertexPerFan)
{
    // Two closed cones touching at their apex (vertex 0).
    TriMesh m;
    addCone(m, Vec3(0, 0, 0), 1.0, 8);
    addCone(m, Vec3(0, 0, 0), -1.0, 8, 0);
    InputReport report;
    const TriMesh clean = prepareInput(m, report);
    EXPECT_EQ(report.splitNonManifoldVertices, 1);
    EXPECT_EQ(report.addedVertexCopies, 1);
    EXPECT_EQ(clean.vertexCount(), m.vertexCount() + 1);
    EXPECT_EQ(clean.faceCount(), m.faceCount());
    EXPECT_EQ(report.components, 2);
    EXPECT_TRUE(hasNote(report, "split 1 non-manifold vertices")) << allNotes(report);
    EXPECT_TRUE(hasNote(report, "2 connected components")) << allNotes(report);
    // The apex maps to the copy of its first fan (the upper cone); the lower cone uses the new,
    // last vertex, at the same place.
    EXPECT_EQ(report.cleanIndex[0], 0);
    EXPECT_EQ(clean.faces[0][0], 0);
    EXPECT_EQ(clean.faces[m.faceCount() / 2][0], clean.vertexCount() - 1);
    EXPECT_EQ(clean.vertices.back(), m.vertices[0]);
    expectCleanIndexConsistent(m, clean, report);
    // Idempotent: the copies coincide, so a second pass merges and splits them again, to the
    // same mesh.
    InputReport again;
    const TriMesh twice = prepareInput(clean, again);
    EXPECT_EQ(again.mergedDuplicateVertices, 1);
    EXPECT_EQ(again.splitNonManifoldVertices, 1);
    EXPECT_EQ(twice.vertices, clean.vertices);
    EXPECT_EQ(twice.faces, clean.faces);
}

TEST(MeshCheck, SplitsBowtieVertexOfAnOpenPatch)
{
    // Two triangles sharing only vertex 0, the second given through a duplicate of vertex 0:
    // merging comes first, then the split.
    TriMesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {-1, 0, 0}, {-1, -1, 0}};
    m.faces = {{0, 1, 2}, {3, 4, 5}};
    InputReport report;
    const TriMesh clean = prepareInput(m, report);
    EXPECT_EQ(report.mergedDuplicateVertices, 1);
    EXPECT_EQ(report.splitNonManifoldVertices, 1);
    EXPECT_EQ(clean.vertexCount(), 6);
    EXPECT_EQ(report.cleanIndex[0], 0);
    EXPECT_EQ(report.cleanIndex[3], 0);  // merged into 0, whose first fan is face 0's
    expectCleanIndexConsistent(m, clean, report);
}

TEST(MeshCheck, KeepsNeedleFacesAndTinyFaces)
{
    TriMesh needle;
    needle.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1e-9, 0}};
    needle.faces = {{0, 1, 2}, {1, 0, 3}};
    InputReport report;
    EXPECT_EQ(prepareInput(needle, report).faceCount(), 2);
    EXPECT_EQ(report.removedDegenerateFaces, 0);
    EXPECT_TRUE(report.notes.empty()) << allNotes(report);

    // Faces whose squared area underflows are still not zero-area.
    InputReport tinyReport;
    EXPECT_EQ(prepareInput(testmesh::planeGrid(2, 1e-150), tinyReport).faceCount(), 8);
    EXPECT_EQ(tinyReport.removedDegenerateFaces, 0);
}

TEST(MeshCheck, ReportsComponentsAndTheSmallestShare)
{
    TriMesh m = testmesh::icosphere(1);
    const TriMesh tiny = testmesh::icosphere(0);
    const int offset = m.vertexCount();
    for (const Vec3& p : tiny.vertices) m.vertices.push_back(p * 1e-3 + Vec3(3, 0, 0));
    for (const Face& t : tiny.faces) m.faces.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    InputReport report;
    const TriMesh clean = prepareInput(m, report);
    EXPECT_EQ(report.components, 2);
    EXPECT_EQ(clean.faceCount(), m.faceCount());
    EXPECT_TRUE(hasNote(report, "2 connected components (kept; the smallest has")) << allNotes(report);
    EXPECT_LT(report.componentAreas[1], 1e-5 * report.componentAreas[0]);
}

TEST(MeshCheck, CleanMeshPassesUntouched)
{
    const TriMesh m = testmesh::torus(10, 6);
    InputReport report;
    const TriMesh clean = prepareInput(m, report);
    EXPECT_EQ(clean.vertices, m.vertices);
    EXPECT_EQ(clean.faces, m.faces);
    EXPECT_TRUE(report.notes.empty()) << allNotes(report);
    EXPECT_EQ(report.components, 1);
    std::vector<int> identity(m.vertexCount());
    for (int v = 0; v < m.vertexCount(); ++v) identity[v] = v;
    EXPECT_EQ(report.cleanIndex, identity);
}

// ---------------------------------------------------------------------------------------------
// Scale invariance (issue 6): far from the origin or tiny, the result is the unit-scale one.

namespace {

RemeshParams scaleParams(int vertices)
{
    RemeshParams p;
    p.vertexCount = vertices;
    p.lloydIterations = 5;
    p.cvtIterations = 5;
    p.fcvtIterations = 0;
    p.lambda = 0;
    p.computeDistances = false;
    // The same faces: on the input itself. The coarse optimisation surface (simplify.h) breaks the
    // ties of a symmetric mesh's equal collapse costs by rounding, so a moved copy can simplify
    // differently; ScaleInvariance.CoarseSurfaceGivesTheSameFigures covers that path.
    p.optimisationFacesPerSample = 0;
    return p;
}

TriMesh transformed(const TriMesh& m, double scale, const Vec3& offset)
{
    TriMesh t = m;
    for (Vec3& p : t.vertices) p = p * scale + offset;
    return t;
}

// Same faces; vertices equal after undoing the transform, to 1e-6 of the bounding-box diagonal.
void expectSameResult(const TriMesh& input, double scale, const Vec3& offset, int vertices)
{
    const RemeshParams params = scaleParams(vertices);
    const RemeshResult unit = remesh(input, params);
    const RemeshResult moved = remesh(transformed(input, scale, offset), params);
    ASSERT_EQ(moved.mesh.vertexCount(), unit.mesh.vertexCount());
    EXPECT_EQ(moved.mesh.faces, unit.mesh.faces);
    const double tolerance = 1e-6 * boundingBoxDiagonal(input);
    double worst = 0;
    for (int v = 0; v < unit.mesh.vertexCount(); ++v)
        worst = std::max(worst, ((moved.mesh.vertices[v] - offset) / scale - unit.mesh.vertices[v]).norm());
    std::printf("scale %g offset %g: worst %.3g of diagonal\n", scale, offset.norm(), worst / boundingBoxDiagonal(input));
    EXPECT_LE(worst, tolerance) << "scale " << scale << ", offset " << offset.transpose();
    EXPECT_EQ(moved.warnings, unit.warnings);
}

}  // namespace

TEST(ScaleInvariance, ClosedMeshFarFromOriginOrTinyGivesTheUnitResult)
{
    const TriMesh input = testmesh::torus(32, 12);
    expectSameResult(input, 1.0, Vec3(1e6, 1e6, 1e6), 80);
    expectSameResult(input, 1e-6, Vec3::Zero(), 80);
}

TEST(ScaleInvariance, OpenMeshFarFromOriginOrTinyGivesTheUnitResult)
{
    const TriMesh input = testmesh::disk(8);
    expectSameResult(input, 1.0, Vec3(1e6, -1e6, 1e6), 60);
    expectSameResult(input, 1e-6, Vec3::Zero(), 60);
}

// The default path through the coarse optimisation surface at 1e6 from the origin and at 1e-6:
// same figures as at unit scale (the faces may differ where equal collapse costs tie).
TEST(ScaleInvariance, CoarseSurfaceGivesTheSameFigures)
{
    const TriMesh input = testmesh::torus(48, 16);  // 1536 faces for 100 samples: simplified
    RemeshParams params;
    params.vertexCount = 100;
    params.lloydIterations = 5;
    params.cvtIterations = 10;
    params.fcvtIterations = 10;
    const RemeshResult unit = remesh(input, params);
    ASSERT_GT(unit.optimisationFaces, 0);
    ASSERT_LT(unit.optimisationFaces, input.faceCount());
    for (const auto& [scale, offset] : {std::pair{1.0, Vec3(1e6, -1e6, 1e6)}, std::pair{1e-6, Vec3(0, 0, 0)}}) {
        const RemeshResult moved = remesh(transformed(input, scale, offset), params);
        EXPECT_NEAR(moved.optimisationFaces, unit.optimisationFaces, 0.02 * unit.optimisationFaces);
        // The lattice start's count moves by whole rows of points (lattice.h), and at 100
        // vertices a row is a few per cent of them: measured 101 / 96 / 95.
        EXPECT_NEAR(moved.mesh.vertexCount(), unit.mesh.vertexCount(), 0.08 * unit.mesh.vertexCount());
        EXPECT_EQ(moved.outputTopology.genus, 1);
        EXPECT_TRUE(moved.outputTopology.manifold());
        // 100 vertices, 25 iterations: the lattice start on the coarse surfaces (which differ
        // where collapse costs tie) differs by whole rows (measured Q_avg 0.900 / 0.930 / 0.930).
        EXPECT_NEAR(moved.metrics.qAvg, unit.metrics.qAvg, 0.04);
        EXPECT_NEAR(moved.metrics.dH, unit.metrics.dH, 0.3 * unit.metrics.dH);
        EXPECT_GT(moved.metrics.thetaMin, 20);
    }
}

TEST(MeshCheck, ExactDuplicatesMapToTheirLowestIndexOnAnyThreadCount)
{
    // 6 000 points drawn from 1 500 positions (parallel sorting starts at 1 000 elements), every
    // tenth with its zero coordinates negated, every seventh unreferenced.
    std::vector<Vec3> points;
    std::vector<char> referenced;
    unsigned state = 7;
    auto next = [&] { return state = state * 1103515245u + 12345u, (state >> 16) % 1500; };
    for (int v = 0; v < 6000; ++v) {
        const unsigned k = next();
        Vec3 p(double(k % 10), double(k / 10 % 10) * 0.5, double(k / 100));
        if (v % 10 == 0) p = Vec3(p.x() == 0 ? -0.0 : p.x(), p.y() == 0 ? -0.0 : p.y(), p.z() == 0 ? -0.0 : p.z());
        points.push_back(p);
        referenced.push_back(v % 7 != 0);
    }
    // What the representatives must be: the first referenced vertex at each position.
    std::map<std::array<double, 3>, int> first;
    std::vector<int> expected(points.size());
    int expectedMerged = 0;
    for (int v = 0; v < static_cast<int>(points.size()); ++v) {
        expected[v] = v;
        if (!referenced[v]) continue;
        const auto [it, added] = first.insert({{points[v].x() + 0.0, points[v].y() + 0.0, points[v].z() + 0.0}, v});
        if (!added) expected[v] = it->second, ++expectedMerged;
    }
    for (int threads : {1, 2, 3}) {
        int merged = -1;
        const std::vector<int> rep =
            testthreads::withThreadCount(threads, [&] { return exactDuplicateRepresentatives(points, referenced, merged); });
        EXPECT_EQ(rep, expected) << threads << " threads";
        EXPECT_EQ(merged, expectedMerged) << threads << " threads";
    }
    EXPECT_GT(expectedMerged, 3000);
}
