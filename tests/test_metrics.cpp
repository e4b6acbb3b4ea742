// Table 2 quality figures, topology summaries and surface distances (core/metrics.h).
#include "errors.h"
#include "metrics.h"
#include "test_meshes.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>

namespace fieldcvt {
namespace {

using testmesh::icosphere;
using testmesh::planeGrid;
using testmesh::torus;

TriMesh singleTriangle(const Vec3& a, const Vec3& b, const Vec3& c)
{
    TriMesh m;
    m.vertices = {a, b, c};
    m.faces = {{0, 1, 2}};
    return m;
}

//! Appends `other` to `mesh` (disjoint union), shifted by `offset`.
void append(TriMesh& mesh, const TriMesh& other, const Vec3& offset = Vec3::Zero())
{
    const int base = mesh.vertexCount();
    for (const Vec3& v : other.vertices) mesh.vertices.push_back(v + offset);
    for (const Face& f : other.faces) mesh.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
}

//! Parallelogram patch of the regular triangle lattice (all triangles equilateral, unit edges);
//! every interior vertex has valence 6.
TriMesh triangleLattice(int n)
{
    TriMesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) m.vertices.emplace_back(i + 0.5 * j, std::sqrt(3.0) / 2 * j, 0.0);
    auto id = [n](int i, int j) { return j * (n + 1) + i; };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            m.faces.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
            m.faces.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return m;
}

//! Open tube (a torus' quad pattern without the wrap along the axis): genus 0, two loops.
TriMesh openCylinder(int around, int along)
{
    TriMesh m;
    const double pi = 3.14159265358979323846;
    for (int j = 0; j <= along; ++j)
        for (int i = 0; i < around; ++i)
            m.vertices.emplace_back(std::cos(2 * pi * i / around), std::sin(2 * pi * i / around), double(j) / along);
    auto id = [around](int i, int j) { return j * around + (i + around) % around; };
    for (int j = 0; j < along; ++j)
        for (int i = 0; i < around; ++i) {
            m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return m;
}

// --- Quality (Table 2) ------------------------------------------------------------------------

TEST(MetricsQuality, EquilateralTriangle)
{
    const QualityMetrics q = computeQuality(singleTriangle(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, std::sqrt(3.0), 0)));
    EXPECT_EQ(q.vertices, 3);
    EXPECT_EQ(q.faces, 1);
    EXPECT_NEAR(q.qMin, 1.0, 1e-12);
    EXPECT_NEAR(q.qAvg, 1.0, 1e-12);
    EXPECT_NEAR(q.thetaMin, 60.0, 1e-10);
    EXPECT_NEAR(q.thetaMinAvg, 60.0, 1e-10);
    EXPECT_NEAR(q.thetaMax, 60.0, 1e-10);
    EXPECT_EQ(q.pctLt30, 0.0);
    EXPECT_EQ(q.pctGt90, 0.0);
    EXPECT_EQ(q.v6Pct, 0.0);  // no interior vertex
    EXPECT_TRUE(std::isnan(q.dRms));
    EXPECT_TRUE(std::isnan(q.dH));
}

TEST(MetricsQuality, RightIsoscelesTriangle)
{
    // Legs 1: area 1/2, s = 1 + sqrt(2)/2, h = sqrt(2)  =>  Q = sqrt(3) (sqrt(2) - 1) ~ 0.7174.
    const QualityMetrics q = computeQuality(singleTriangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)));
    const double expected = std::sqrt(3.0) * (std::sqrt(2.0) - 1.0);
    EXPECT_NEAR(q.qMin, expected, 1e-12);
    EXPECT_NEAR(q.qAvg, expected, 1e-12);
    EXPECT_NEAR(q.thetaMin, 45.0, 1e-10);
    EXPECT_NEAR(q.thetaMax, 90.0, 1e-10);
    EXPECT_EQ(q.pctLt30, 0.0);
    EXPECT_EQ(q.pctGt90, 0.0);  // exactly 90 is not obtuse
}

TEST(MetricsQuality, MixedTrianglesGivePercentagesAndAverages)
{
    // An equilateral triangle and a flat obtuse one (base 1, height 0.1).
    TriMesh m = singleTriangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, std::sqrt(0.75), 0));
    append(m, singleTriangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0.1, 0)), Vec3(5, 0, 0));
    const QualityMetrics q = computeQuality(m);
    const double pi = 3.14159265358979323846;
    const double side = std::sqrt(0.25 + 0.01);
    const double flatQ = 2 * std::sqrt(3.0) * 0.05 / (0.5 * (1 + 2 * side) * 1.0);
    const double baseAngle = std::atan(0.2) * 180 / pi;  // ~11.31 degrees
    EXPECT_EQ(q.faces, 2);
    EXPECT_EQ(q.vertices, 6);
    EXPECT_NEAR(q.qMin, flatQ, 1e-12);
    EXPECT_NEAR(q.qAvg, 0.5 * (1 + flatQ), 1e-12);
    EXPECT_NEAR(q.thetaMin, baseAngle, 1e-10);
    EXPECT_NEAR(q.thetaMinAvg, 0.5 * (60 + baseAngle), 1e-10);
    EXPECT_NEAR(q.thetaMax, 180 - 2 * baseAngle, 1e-10);
    EXPECT_DOUBLE_EQ(q.pctLt30, 50.0);
    EXPECT_DOUBLE_EQ(q.pctGt90, 50.0);
}

TEST(MetricsQuality, DegenerateTrianglesGiveZeroNotNaN)
{
    TriMesh m = singleTriangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0));  // collinear
    append(m, singleTriangle(Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, 1)));   // collapsed to a point
    const QualityMetrics q = computeQuality(m);
    for (double value : {q.qMin, q.qAvg, q.thetaMin, q.thetaMinAvg, q.thetaMax, q.pctLt30, q.pctGt90, q.v6Pct})
        EXPECT_TRUE(std::isfinite(value));
    EXPECT_EQ(q.qMin, 0.0);
    EXPECT_EQ(q.qAvg, 0.0);
    EXPECT_EQ(q.thetaMin, 0.0);
    EXPECT_EQ(q.thetaMinAvg, 0.0);
    EXPECT_DOUBLE_EQ(q.pctLt30, 100.0);
}

TEST(MetricsQuality, EmptyMeshIsAllZeros)
{
    const QualityMetrics q = computeQuality(TriMesh{});
    EXPECT_EQ(q.vertices, 0);
    EXPECT_EQ(q.faces, 0);
    for (double value : {q.qMin, q.qAvg, q.thetaMin, q.thetaMinAvg, q.thetaMax, q.pctLt30, q.pctGt90, q.v6Pct})
        EXPECT_EQ(value, 0.0);
}

TEST(MetricsQuality, RegularLatticeIsAllValenceSix)
{
    const TriMesh lattice = triangleLattice(8);
    const QualityMetrics q = computeQuality(lattice);
    EXPECT_EQ(q.vertices, 81);
    EXPECT_EQ(q.faces, 128);
    EXPECT_DOUBLE_EQ(q.v6Pct, 100.0);
    EXPECT_NEAR(q.qMin, 1.0, 1e-12);
    EXPECT_NEAR(q.thetaMin, 60.0, 1e-9);
    EXPECT_NEAR(q.thetaMax, 60.0, 1e-9);
}

TEST(MetricsQuality, IcosphereHasTwelveValenceFiveVertices)
{
    const QualityMetrics q = computeQuality(icosphere(3));
    EXPECT_EQ(q.vertices, 642);
    EXPECT_EQ(q.faces, 1280);
    EXPECT_NEAR(q.v6Pct, 100.0 * 630 / 642, 1e-12);
    EXPECT_GT(q.qMin, 0.8);
    EXPECT_LT(q.qMin, 1.0);
    EXPECT_GT(q.qAvg, q.qMin);
    EXPECT_EQ(q.pctLt30, 0.0);
}

TEST(MetricsQuality, PlaneGridIsRightIsosceles)
{
    const QualityMetrics q = computeQuality(planeGrid(6));
    const double expected = std::sqrt(3.0) * (std::sqrt(2.0) - 1.0);
    EXPECT_NEAR(q.qMin, expected, 1e-12);
    EXPECT_NEAR(q.qAvg, expected, 1e-12);
    EXPECT_NEAR(q.thetaMinAvg, 45.0, 1e-10);
    EXPECT_DOUBLE_EQ(q.v6Pct, 100.0);  // consistent diagonals: interior valence 6
}

// --- Topology -----------------------------------------------------------------------------------

TEST(MetricsTopology, IcosphereIsAClosedSphere)
{
    const TopologySummary t = computeTopology(icosphere(2));
    EXPECT_EQ(t.vertices, 162);
    EXPECT_EQ(t.faces, 320);
    EXPECT_EQ(t.edges, 480);
    EXPECT_EQ(t.components, 1);
    EXPECT_EQ(t.boundaryLoops, 0);
    EXPECT_EQ(t.nonManifoldEdges, 0);
    EXPECT_EQ(t.nonManifoldVertices, 0);
    EXPECT_TRUE(t.manifold());
    EXPECT_TRUE(t.orientable);
    EXPECT_EQ(t.genus, 0);
}

TEST(MetricsTopology, TorusHasGenusOne)
{
    const TopologySummary t = computeTopology(torus(24, 12));
    EXPECT_EQ(t.vertices, 288);
    EXPECT_EQ(t.edges, 864);
    EXPECT_EQ(t.boundaryLoops, 0);
    EXPECT_TRUE(t.manifold());
    EXPECT_TRUE(t.orientable);
    EXPECT_EQ(t.genus, 1);
}

TEST(MetricsTopology, PlaneGridIsADisk)
{
    const TopologySummary t = computeTopology(planeGrid(4));
    EXPECT_EQ(t.vertices, 25);
    EXPECT_EQ(t.faces, 32);
    EXPECT_EQ(t.edges, 56);
    EXPECT_EQ(t.components, 1);
    EXPECT_EQ(t.boundaryLoops, 1);
    EXPECT_TRUE(t.manifold());
    EXPECT_TRUE(t.orientable);
    EXPECT_EQ(t.genus, 0);
}

TEST(MetricsTopology, AnnulusAndTubeHaveTwoLoops)
{
    // Grid 4x4 without its 2x2 central cells: the centre vertex is no longer referenced.
    TriMesh annulus = planeGrid(4);
    std::vector<Face> kept;
    for (size_t i = 0; i < annulus.faces.size(); ++i) {
        const int cell = static_cast<int>(i) / 2, ci = cell % 4, cj = cell / 4;
        if (!(ci >= 1 && ci <= 2 && cj >= 1 && cj <= 2)) kept.push_back(annulus.faces[i]);
    }
    annulus.faces = kept;
    TopologySummary t = computeTopology(annulus);
    EXPECT_EQ(t.vertices, 24);
    EXPECT_EQ(t.boundaryLoops, 2);
    EXPECT_EQ(t.components, 1);
    EXPECT_TRUE(t.manifold());
    EXPECT_EQ(t.genus, 0);

    t = computeTopology(openCylinder(16, 5));
    EXPECT_EQ(t.boundaryLoops, 2);
    EXPECT_TRUE(t.manifold());
    EXPECT_TRUE(t.orientable);
    EXPECT_EQ(t.genus, 0);
}

TEST(MetricsTopology, FlippedFaceIsNotOrientable)
{
    TriMesh m = icosphere(1);
    std::swap(m.faces[7][1], m.faces[7][2]);
    const TopologySummary t = computeTopology(m);
    EXPECT_FALSE(t.orientable);
    EXPECT_TRUE(t.manifold());
    EXPECT_EQ(t.boundaryLoops, 0);
    EXPECT_EQ(t.genus, 0);
}

TEST(MetricsTopology, ThreeFacesOnAnEdgeAreNonManifold)
{
    // The diagonal (0,0)-(1,1) of the first cell gets a third face.
    TriMesh m = planeGrid(2);
    m.vertices.emplace_back(0.25, 0.25, 1.0);
    m.faces.push_back({0, 4, m.vertexCount() - 1});
    const TopologySummary t = computeTopology(m);
    EXPECT_EQ(t.nonManifoldEdges, 1);
    EXPECT_FALSE(t.manifold());
    EXPECT_EQ(t.components, 1);
}

TEST(MetricsTopology, DisjointComponentsAreCountedAndGeneraAdd)
{
    TriMesh spheres = icosphere(1);
    append(spheres, icosphere(1), Vec3(5, 0, 0));
    TopologySummary t = computeTopology(spheres);
    EXPECT_EQ(t.components, 2);
    EXPECT_EQ(t.vertices, 84);
    EXPECT_EQ(t.genus, 0);
    EXPECT_TRUE(t.manifold());

    TriMesh tori = torus(16, 8);
    append(tori, torus(16, 8), Vec3(5, 0, 0));
    t = computeTopology(tori);
    EXPECT_EQ(t.components, 2);
    EXPECT_EQ(t.genus, 2);
}

TEST(MetricsTopology, BowtieVertexKeepsTwoLoops)
{
    // Two triangles sharing only vertex 0: a non-manifold vertex with two separate fans.
    TriMesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
    m.faces = {{0, 1, 2}, {0, 3, 4}};
    const TopologySummary t = computeTopology(m);
    EXPECT_EQ(t.components, 2);
    EXPECT_EQ(t.nonManifoldVertices, 1);
    EXPECT_EQ(t.nonManifoldEdges, 0);
    EXPECT_EQ(t.boundaryLoops, 2);
    EXPECT_EQ(t.genus, 0);
}

TEST(MetricsTopology, PinchedVertexInsideOneComponent)
{
    // Two cones (fans) glued only at their apex through a strip: one component, the apex has
    // two fans. Built as two open disks around vertex 0 joined by a triangle strip elsewhere.
    TriMesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
    m.faces = {{0, 1, 2}, {0, 3, 4}, {1, 4, 3}, {1, 3, 2}};
    const TopologySummary t = computeTopology(m);
    EXPECT_EQ(t.components, 1);
    EXPECT_EQ(t.nonManifoldVertices, 1);
    EXPECT_FALSE(t.manifold());
}

TEST(MetricsTopology, EmptyMesh)
{
    const TopologySummary t = computeTopology(TriMesh{});
    EXPECT_EQ(t.vertices, 0);
    EXPECT_EQ(t.components, 0);
    EXPECT_EQ(t.genus, 0);
}

// --- Distances ----------------------------------------------------------------------------------

TEST(MetricsDistance, MeshAgainstItselfIsZero)
{
    const TriMesh mesh = torus(32, 16);
    const DistanceMetrics d = computeDistance(mesh, mesh, 20000);
    EXPECT_LT(d.rms, 1e-12);
    EXPECT_LT(d.hausdorff, 1e-12);
}

TEST(MetricsDistance, ScaledSphereHausdorffIsTheOffset)
{
    const TriMesh reference = icosphere(4);
    TriMesh scaled = reference;
    for (Vec3& v : scaled.vertices) v *= 1.01;
    const double diagonal = boundingBoxDiagonal(reference);
    const DistanceMetrics d = computeDistance(scaled, reference, 50000);
    // Vertices sit on the spheres, so the farthest pairs are corresponding vertices, 0.01 apart.
    EXPECT_NEAR(d.hausdorff, 0.01 / diagonal, 0.03 * 0.01 / diagonal);
    EXPECT_GT(d.rms, 0.9 * 0.01 / diagonal);
    EXPECT_LE(d.rms, d.hausdorff);
}

TEST(MetricsDistance, OneRaisedVertexSetsTheHausdorffDistance)
{
    const TriMesh flat = planeGrid(8);
    TriMesh bumped = flat;
    bumped.vertices[4 * 9 + 4].z() = 0.1;  // centre vertex
    const DistanceMetrics d = computeDistance(bumped, flat, 10000);
    EXPECT_NEAR(d.hausdorff, 0.1 / std::sqrt(2.0), 1e-12);
    EXPECT_GT(d.rms, 0.0);
    EXPECT_LT(d.rms, 0.5 * d.hausdorff);
}

TEST(MetricsDistance, SameResultForAnyThreadCount)
{
    const TriMesh reference = torus(40, 20);
    TriMesh moved = reference;
    for (Vec3& v : moved.vertices) v += 0.01 * Vec3(std::sin(7 * v.x()), std::cos(5 * v.y()), v.z());
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    const DistanceMetrics one = computeDistance(moved, reference, 30000);
    omp_set_num_threads(std::max(2, threads));
    const DistanceMetrics many = computeDistance(moved, reference, 30000);
    omp_set_num_threads(threads);
    EXPECT_EQ(one.rms, many.rms);
    EXPECT_EQ(one.hausdorff, many.hausdorff);
    EXPECT_GT(one.hausdorff, 0.0);
}

TEST(MetricsDistance, RejectsEmptyMeshes)
{
    EXPECT_THROW(computeDistance(TriMesh{}, icosphere(1)), InvalidInputError);
    EXPECT_THROW(computeDistance(icosphere(1), TriMesh{}), InvalidInputError);
}

}  // namespace
}  // namespace fieldcvt

TEST(MetricsTopology, TestDiskIsAManifoldDisk)
{
    const fieldcvt::TopologySummary t = fieldcvt::computeTopology(fieldcvt::testmesh::disk(5));
    EXPECT_TRUE(t.manifold());
    EXPECT_TRUE(t.orientable);
    EXPECT_EQ(t.boundaryLoops, 1);
    EXPECT_EQ(t.genus, 0);
    EXPECT_EQ(t.faces, 6 * 25);
}

// The valence stage's V6% before and after (v6Percent) is computeQuality's, without the angles.
TEST(Metrics, V6PercentIsComputeQualitys)
{
    for (const fieldcvt::TriMesh& m :
         {fieldcvt::testmesh::torus(24, 12), fieldcvt::testmesh::disk(6), fieldcvt::testmesh::icosphere(2)}) {
        fieldcvt::TriMesh irregular = m;
        irregular.faces.pop_back();  // a hole: border vertices, and some irregular ones
        for (const fieldcvt::TriMesh& mesh : {m, irregular})
            EXPECT_EQ(fieldcvt::v6Percent(mesh), fieldcvt::computeQuality(mesh).v6Pct);
    }
    EXPECT_EQ(fieldcvt::v6Percent(fieldcvt::TriMesh{}), 0.0);
}
