// The repair stage (issue 17) on generated inputs of each kind real meshes come in: every result
// passes the strict check and is edge- and vertex-manifold and oriented, each step counted.
#include "errors.h"
#include "mesh_check.h"
#include "metrics.h"
#include "remesh.h"
#include "repair.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

using namespace fieldcvt;

namespace {

void append(TriMesh& m, const TriMesh& b)
{
    const int offset = m.vertexCount();
    m.vertices.insert(m.vertices.end(), b.vertices.begin(), b.vertices.end());
    for (Face t : b.faces) m.faces.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

TriMesh combine(TriMesh a, const TriMesh& b)
{
    append(a, b);
    return a;
}

TriMesh moved(TriMesh m, double scale, const Vec3& offset)
{
    for (Vec3& p : m.vertices) p = p * scale + offset;
    return m;
}

// Repairs, then the strict check; the clean surface must be manifold and oriented.
struct Repaired {
    RepairReport repair;
    InputReport check;
    TriMesh mesh;
    TopologySummary topology;
};

Repaired repairOf(const TriMesh& input, int budget = 0)
{
    Repaired r;
    RepairParams params;
    params.vertexBudget = budget;
    r.mesh = repairAndPrepare(input, params, r.repair, r.check);
    r.topology = computeTopology(r.mesh);
    EXPECT_TRUE(r.topology.manifold());
    EXPECT_TRUE(r.topology.orientable);
    EXPECT_EQ(r.check.cleanIndex.size(), input.vertices.size());
    // The strict check takes the repair's word that no two faces have the same corners
    // (prepareInput(…, repaired) does not search): pinned on every repaired mesh here.
    std::vector<std::array<int, 3>> corners;
    for (Face t : r.mesh.faces) {
        std::sort(t.begin(), t.end());
        corners.push_back(t);
    }
    std::sort(corners.begin(), corners.end());
    EXPECT_EQ(std::adjacent_find(corners.begin(), corners.end()), corners.end());
    return r;
}

}  // namespace

TEST(Repair, CleanMeshIsUntouched)
{
    const TriMesh torus = testmesh::torus(16, 8);
    const Repaired r = repairOf(torus, 500);
    EXPECT_TRUE(r.repair.notes.empty());
    EXPECT_EQ(r.mesh.vertices, torus.vertices);
    EXPECT_EQ(r.mesh.faces, torus.faces);
}

TEST(Repair, EveryFaceStoredTwiceKeepsOneSheet)
{
    const TriMesh sphere = testmesh::icosphere(2);
    TriMesh twice = sphere;
    for (size_t f = 0; f < sphere.faces.size(); ++f) {
        const Face& t = sphere.faces[f];
        twice.faces.push_back(f % 2 ? t : Face{t[0], t[2], t[1]});  // half opposite, half the same
    }
    EXPECT_EQ(testmesh::inputError(twice), "");  // the strict check drops them too (without telling which kind)
    const Repaired r = repairOf(twice);
    EXPECT_EQ(r.repair.removedDuplicateFaces + r.repair.removedOppositeFaces, sphere.faceCount());
    EXPECT_GT(r.repair.removedOppositeFaces, 0);
    EXPECT_EQ(r.mesh.faces, sphere.faces);
    EXPECT_EQ(r.topology.boundaryLoops, 0);
}

TEST(Repair, FinOfThreeSheetsOnOneEdgeIsSplit)
{
    // Three unit squares (two triangles each) hanging from the edge (0,0,0)-(0,0,1).
    TriMesh fin;
    fin.vertices = {{0, 0, 0}, {0, 0, 1}};
    for (int s = 0; s < 3; ++s) {
        const double a = 2 * M_PI * s / 3;
        const int p = fin.vertexCount();
        fin.vertices.emplace_back(std::cos(a), std::sin(a), 0);
        fin.vertices.emplace_back(std::cos(a), std::sin(a), 1);
        fin.faces.push_back({0, p, p + 1});
        fin.faces.push_back({0, p + 1, 1});
    }
    EXPECT_NE(testmesh::inputError(fin).find("non-manifold edge"), std::string::npos);
    const Repaired r = repairOf(fin);
    EXPECT_EQ(r.repair.nonManifoldEdges, 1);
    EXPECT_EQ(r.mesh.faceCount(), 6);  // nothing lost
    EXPECT_GE(r.topology.components, 2);
}

TEST(Repair, SphereWithAFinKeepsTheSphereClosed)
{
    TriMesh m = testmesh::icosphere(1);
    const int a = m.faces[0][0], b = m.faces[0][1];
    m.vertices.push_back(2 * m.vertices[a]);
    m.faces.push_back({a, b, m.vertexCount() - 1});
    const Repaired r = repairOf(m);
    EXPECT_EQ(r.repair.nonManifoldEdges, 1);
    EXPECT_EQ(r.topology.components, 2);
    EXPECT_EQ(r.topology.boundaryLoops, 1);  // the fin's; the sphere stays closed
}

TEST(Repair, DoubledFlapOnASphereIsRemovedAndTheSphereStaysClosed)
{
    // A triangle stored twice hanging from one edge of a sphere (conrod.stl has three): nothing
    // on either side of it. Kept once, it made that edge non-manifold, and the split into sheets
    // could open a slit in the sphere. Both orientations of the copy; a doubled triangle on its
    // own (a tiny part, not a flap) keeps one copy.
    for (bool opposite : {false, true}) {
        const TriMesh sphere = testmesh::icosphere(1);
        TriMesh m = sphere;
        const int a = m.faces[0][0], b = m.faces[0][1];
        m.vertices.push_back(1.5 * m.vertices[a]);
        const int tip = m.vertexCount() - 1;
        m.faces.push_back({a, b, tip});
        m.faces.push_back(opposite ? Face{b, a, tip} : Face{a, b, tip});
        TriMesh lone;
        lone.vertices = {{3, 0, 0}, {3.5, 0, 0}, {3, 0.5, 0}};
        lone.faces = {{0, 1, 2}, {0, 1, 2}};
        append(m, lone);
        const Repaired r = repairOf(m);
        EXPECT_EQ(r.repair.removedFlapFaces, 1);
        EXPECT_EQ(r.repair.removedDuplicateFaces + r.repair.removedOppositeFaces, 2);
        EXPECT_EQ(r.repair.nonManifoldEdges, 0);
        EXPECT_EQ(r.mesh.faceCount(), sphere.faceCount() + 1);
        EXPECT_EQ(r.topology.components, 2);
        EXPECT_EQ(r.topology.boundaryLoops, 1);  // the lone triangle's; the sphere stays closed
        EXPECT_EQ(r.topology.genus, 0);
    }
}

TEST(Repair, TwoShellsSharingAnEdgeStayTwoClosedShells)
{
    // Two tetrahedra touching along the edge (0,0,0)-(0,0,1), on either side of it.
    TriMesh m;
    m.vertices = {{0, 0, 0}, {0, 0, 1}, {1, 0.2, 0.5}, {1, -0.2, 0.5}, {-1, 0.2, 0.5}, {-1, -0.2, 0.5}};
    auto tetra = [&](int p, int q, int c, int d) {  // outward for p, q, c, d positively oriented
        m.faces.push_back({p, q, c});
        m.faces.push_back({p, c, d});
        m.faces.push_back({p, d, q});
        m.faces.push_back({q, d, c});
    };
    tetra(0, 1, 3, 2);
    tetra(0, 1, 4, 5);
    // Make each shell's orientation outward (the test needs consistent shells, whatever the sign).
    for (int s = 0; s < 2; ++s) {
        double volume = 0;
        for (int f = 4 * s; f < 4 * s + 4; ++f) {
            const Face& t = m.faces[f];
            volume += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]]));
        }
        if (volume < 0)
            for (int f = 4 * s; f < 4 * s + 4; ++f) std::swap(m.faces[f][1], m.faces[f][2]);
    }
    EXPECT_NE(testmesh::inputError(m).find("non-manifold edge"), std::string::npos);
    const Repaired r = repairOf(m);
    EXPECT_EQ(r.repair.nonManifoldEdges, 1);
    EXPECT_EQ(r.topology.components, 2);
    EXPECT_EQ(r.topology.boundaryLoops, 0);
    EXPECT_EQ(r.mesh.faceCount(), 8);
}

TEST(Repair, MoebiusBandAmongOtherComponentsIsCutIntoAnOrientablePiece)
{
    const TriMesh m = combine(combine(testmesh::icosphere(1), moved(testmesh::moebius(), 1, {4, 0, 0})),
                              moved(testmesh::torus(12, 6), 1, {-4, 0, 0}));
    EXPECT_NE(testmesh::inputError(m).find("not orientable"), std::string::npos);
    const Repaired r = repairOf(m);
    EXPECT_EQ(r.repair.nonOrientableComponents, 1);
    EXPECT_GE(r.repair.seamEdges, 1);
    EXPECT_EQ(r.mesh.faceCount(), m.faceCount());
    EXPECT_EQ(r.topology.components, 3);
}

namespace {

// A grid whose right half has its own vertices along x = 0.5, `gap` to the right of the left
// half's (a seam, or a real gap); `fine` puts twice as many on the right side of the seam.
TriMesh splitGrid(double gap, bool fine = false)
{
    TriMesh left = testmesh::planeGrid(4);  // [0, 1]^2, 4 x 4 cells
    for (Vec3& p : left.vertices) p.x() *= 0.5;
    TriMesh right = fine ? testmesh::planeGrid(8) : testmesh::planeGrid(4);
    for (Vec3& p : right.vertices) p.x() = 0.5 + gap + 0.5 * p.x();
    return combine(left, right);
}

}  // namespace

TEST(Repair, SeamWithVerticesOneEMinus12ApartIsWelded)
{
    const Repaired r = repairOf(splitGrid(1e-12));
    EXPECT_EQ(r.repair.weldedVertices, 5);
    EXPECT_EQ(r.topology.components, 1);
    EXPECT_EQ(r.topology.boundaryLoops, 1);
}

TEST(Repair, NarrowRealGapStaysOpen)
{
    // A gap of 1 % of the edge length: ten times the welding tolerance.
    const Repaired r = repairOf(splitGrid(0.01 * 0.125));
    EXPECT_EQ(r.repair.weldedVertices, 0);
    EXPECT_EQ(r.repair.tJunctions, 0);
    EXPECT_EQ(r.topology.components, 2);
}

TEST(Repair, TJunctionCrackIsClosed)
{
    // The right half has 8 rows of cells against the left half's 4: every other vertex of its
    // seam sits (1e-13 off) on the inside of an edge of the left half.
    const Repaired r = repairOf(splitGrid(1e-13, true));
    EXPECT_EQ(r.repair.weldedVertices, 5);
    EXPECT_EQ(r.repair.tJunctions, 4);
    EXPECT_EQ(r.topology.components, 1);
    EXPECT_EQ(r.topology.boundaryLoops, 1);
    EXPECT_NEAR(surfaceArea(r.mesh), 1.0, 1e-9);
}

TEST(Repair, FloatersBesideOneLargeComponentAreDroppedWithTheirArea)
{
    TriMesh m = testmesh::icosphere(3);
    const double sphereArea = surfaceArea(m);
    const TriMesh tiny = moved(testmesh::icosphere(0), 1e-3, {0, 0, 0});
    for (int i = 0; i < 1000; ++i) append(m, moved(tiny, 1, {2.0 + 0.01 * (i % 10), 0.01 * (i / 10), 0}));
    const Repaired r = repairOf(m, 500);
    EXPECT_EQ(r.repair.droppedComponents, 1000);
    EXPECT_NEAR(r.repair.droppedArea, 1000 * surfaceArea(tiny), 1e-9);
    EXPECT_NEAR(surfaceArea(r.mesh), sphereArea, 1e-9);
    EXPECT_EQ(r.topology.components, 1);
    bool said = false;
    for (const std::string& n : r.check.notes) said |= n.find("1000 connected components too small") != std::string::npos;
    EXPECT_TRUE(said);
}

TEST(Repair, CountsAndOutputDoNotDependOnTheModelsScale)
{
    // A seam, a T-junction crack and floaters at 1 and at 1e300 / 1e-300 (squared lengths and
    // areas would overflow / underflow there): the same steps, the input's own coordinates out.
    TriMesh base = splitGrid(1e-13, true);
    const TriMesh tiny = moved(testmesh::icosphere(0), 1e-3, {0, 0, 0});
    for (int i = 0; i < 20; ++i) append(base, moved(tiny, 1, {2.0 + 0.01 * i, 0, 0}));
    const Repaired unit = repairOf(base, 300);
    ASSERT_EQ(unit.repair.droppedComponents, 20);
    for (double scale : {1e300, 1e-300}) {
        const Repaired r = repairOf(moved(base, scale, {0, 0, 0}), 300);
        EXPECT_EQ(r.repair.weldedVertices, unit.repair.weldedVertices) << scale;
        EXPECT_EQ(r.repair.tJunctions, unit.repair.tJunctions) << scale;
        EXPECT_EQ(r.repair.droppedComponents, unit.repair.droppedComponents) << scale;
        EXPECT_NEAR(r.repair.droppedAreaFraction, unit.repair.droppedAreaFraction, 1e-12) << scale;
        EXPECT_NEAR(r.repair.weldDistance / scale, unit.repair.weldDistance, 1e-9 * unit.repair.weldDistance) << scale;
        ASSERT_EQ(r.mesh.vertexCount(), unit.mesh.vertexCount()) << scale;
        for (int v = 0; v < r.mesh.vertexCount(); ++v)
            ASSERT_EQ(r.mesh.vertices[v], moved(unit.mesh, scale, {0, 0, 0}).vertices[v]) << scale;
    }
}

TEST(Repair, NothingLeftFailsWithTheVertexCountNeeded)
{
    TriMesh m;
    const TriMesh tiny = testmesh::icosphere(0);
    for (int i = 0; i < 1000; ++i) append(m, moved(tiny, 0.1, {double(i % 10), double(i / 10), 0}));
    RepairParams params;
    params.vertexBudget = 300;
    RepairReport report;
    try {
        repairMesh(m, params, report);
        FAIL() << "no error";
    } catch (const InvalidInputError& e) {
        EXPECT_NE(std::string(e.what()).find("all 1000 connected components are too small for 300 vertices"), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("use at least 8000 vertices"), std::string::npos) << e.what();
    }
}

TEST(Repair, ComponentOverOnePercentIsKeptEvenWhenSmallForTheBudget)
{
    // 2 % of the area at 100 vertices: 2 samples expected, kept with a note.
    TriMesh big = testmesh::icosphere(2);
    const double share = 0.02, scale = std::sqrt(share / (1 - share));
    const Repaired r = repairOf(combine(big, moved(big, scale, {3, 0, 0})), 100);
    EXPECT_EQ(r.repair.droppedComponents, 0);
    EXPECT_EQ(r.repair.keptSmallComponents, 1);
    EXPECT_EQ(r.topology.components, 2);
}

TEST(Repair, SmallComponentFarFromTheRestIsKeptAndOneBesideItDropped)
{
    // A unit sphere (area 4π) and two copies of a patch with 0.5 % of its area: 1.5 samples each
    // at 300 vertices, fewer than the 8 that make a surface. Edge length at 300 vertices: 0.22.
    // One copy floats 0.05 off the sphere (a crumb beside it: dropped), the other 4 units away
    // (a part of its own, whose loss would leave a gap of 4: kept).
    const TriMesh sphere = testmesh::icosphere(3);
    const double side = std::sqrt(0.005 * surfaceArea(sphere));
    const TriMesh patch = testmesh::planeGrid(4, side);
    const TriMesh input = combine(combine(sphere, moved(patch, 1, {-0.5 * side, -0.5 * side, 1.05})), moved(patch, 1, {5, 0, 0}));
    const Repaired r = repairOf(input, 300);
    EXPECT_EQ(r.repair.keptFarComponents, 1);
    EXPECT_EQ(r.repair.droppedComponents, 1);
    EXPECT_EQ(r.topology.components, 2);
    double farthest = 0;
    for (const Vec3& p : r.mesh.vertices) farthest = std::max(farthest, p.x());
    EXPECT_GT(farthest, 5.0);
    // Under a quarter of a sample (less than half an output triangle's area): dropped, far or not.
    const Repaired fewer = repairOf(input, 40);
    EXPECT_EQ(fewer.repair.keptFarComponents, 0);
    EXPECT_EQ(fewer.repair.droppedComponents, 2);
}

TEST(Repair, FarSmallComponentsAreKeptLargestFirstWithinTheirShareOfTheBudget)
{
    // 20 far patches of 1 to 1.95 expected samples each at 300 vertices (0.33 to 0.65 % of the
    // area): the 10 from 0.5 % on (RepairParams::keepAreaFraction, parts) are kept for their size;
    // the other 10 are short of the 3 samples a kept one gets by 1.55 to 2; the 2 % of 300 (6
    // samples) they may add keep the largest 3 (1.55 + 1.60 + 1.65 = 4.8; a fourth, 6.5).
    const TriMesh sphere = testmesh::icosphere(3);
    TriMesh input = sphere;
    // The total area T such that patch i's share of it is exactly (1 + 0.05 i) / 300: the
    // patches hold 29.5 / 300 of T.
    const double total = surfaceArea(sphere) / (1 - 29.5 / 300);
    for (int i = 0; i < 20; ++i) {
        const double samples = 1.0 + 0.05 * i;
        const double side = std::sqrt(samples / 300 * total);
        append(input, moved(testmesh::planeGrid(2, side), 1, {3.0 + 0.5 * i, 0, 0}));
    }
    const Repaired r = repairOf(input, 300);
    EXPECT_EQ(r.repair.keptSmallComponents, 10);
    EXPECT_EQ(r.repair.keptFarComponents, 3);
    EXPECT_EQ(r.repair.droppedComponents, 7);
    double nearest = 1e9;  // the kept patches are the last thirteen (the largest), from x = 6.5 on
    for (const Vec3& p : r.mesh.vertices)
        if (p.x() > 2) nearest = std::min(nearest, p.x());
    EXPECT_GE(nearest, 6.5);
    EXPECT_LT(nearest, 7.0);
}

TEST(Repair, BadInputIsLeftToTheStrictCheck)
{
    TriMesh m = testmesh::planeGrid(2);
    m.faces[0][1] = 99;
    RepairReport repair;
    InputReport report;
    EXPECT_THROW(repairAndPrepare(m, RepairParams{}, repair, report), InvalidInputError);
    EXPECT_TRUE(repair.skipped);
}

TEST(Repair, RemeshRepairsByDefaultAndRefusesWithoutRepair)
{
    TriMesh m = testmesh::icosphere(2);
    const int a = m.faces[0][0], b = m.faces[0][1];
    m.vertices.push_back(1.5 * m.vertices[a]);
    m.faces.push_back({a, b, m.vertexCount() - 1});
    RemeshParams params;
    params.vertexCount = 100;
    params.cvtIterations = 5;
    params.fcvtIterations = 0;
    params.lambda = 0;
    params.valenceOptimization = false;
    params.computeDistances = false;
    const RemeshResult result = remesh(m, params);
    EXPECT_EQ(result.repair.nonManifoldEdges, 1);
    EXPECT_TRUE(result.outputTopology.manifold());
    params.repair = false;
    EXPECT_THROW(remesh(m, params), InvalidInputError);
}
