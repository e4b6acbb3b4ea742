// Adaptive density (issue 5, item 5): ρ in the RVD integrals and the E_CVT gradient, samples
// ∝ area × μ, the curvature and per-vertex sources, and the uniform case unchanged.
#include "density.h"
#include "energy.h"
#include "errors.h"
#include "remesh.h"
#include "rvd.h"
#include "sampling.h"
#include "test_gradient.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace fieldcvt;

namespace {

std::vector<double> randomFaceDensity(const TriMesh& surface, std::uint64_t seed)
{
    std::mt19937_64 rng(seed);
    std::vector<double> rho(surface.faces.size());
    for (double& r : rho) r = 0.5 + 3.5 * unitInterval(rng());
    return rho;
}

RemeshParams smallRun()
{
    RemeshParams p;
    p.vertexCount = 300;
    p.lloydIterations = 5;
    p.cvtIterations = 10;
    p.fcvtIterations = 5;
    p.boundaryIterations = 2;
    p.valenceOptimization = false;
    p.computeDistances = false;
    return p;
}

}  // namespace

TEST(DensityRvd, CellMassesSumToTheIntegralOfRho)
{
    const TriMesh surface = testmesh::torus(48, 24);
    const std::vector<double> rho = randomFaceDensity(surface, 3);
    double integral = 0;
    Vec3 firstMoment = Vec3::Zero();
    for (int f = 0; f < surface.faceCount(); ++f) {
        const Face& t = surface.faces[f];
        const double w = faceArea(surface, f) * rho[f];
        integral += w;
        firstMoment += w * (surface.vertices[t[0]] + surface.vertices[t[1]] + surface.vertices[t[2]]) / 3.0;
    }
    const std::vector<Vec3> seeds = sampleSurfaceUniform(surface, 200, 5);
    RestrictedVoronoiDiagram rvd(surface, rho);
    RvdResult result;
    rvd.compute(seeds, RvdOptions{}, result);
    double mass = 0;
    Vec3 moment = Vec3::Zero();
    for (size_t i = 0; i < seeds.size(); ++i) mass += result.mass[i], moment += result.moment[i];
    EXPECT_NEAR(mass, integral, 1e-10 * integral);
    EXPECT_LT((moment - firstMoment).norm(), 1e-10 * integral);

    // A constant ρ = c scales mass, moment and energy by c; edge lengths stay geometric.
    RestrictedVoronoiDiagram plain(surface), scaled(surface, std::vector<double>(surface.faces.size(), 4.0));
    RvdResult a, b;
    RvdOptions options;
    options.edges = true;
    plain.compute(seeds, options, a);
    scaled.compute(seeds, options, b);
    for (size_t i = 0; i < seeds.size(); ++i) {
        EXPECT_NEAR(b.mass[i], 4 * a.mass[i], 1e-12);
        EXPECT_NEAR(b.energy[i], 4 * a.energy[i], 1e-12);
        EXPECT_LT((b.moment[i] - 4 * a.moment[i]).norm(), 1e-12);
    }
    ASSERT_EQ(a.edges.size(), b.edges.size());
    for (size_t e = 0; e < a.edges.size(); ++e) EXPECT_EQ(a.edges[e].length, b.edges[e].length);
}

TEST(DensityRvd, RejectsBadDensity)
{
    const TriMesh surface = testmesh::torus(12, 8);
    EXPECT_THROW(RestrictedVoronoiDiagram(surface, std::vector<double>(3, 1.0)), InvalidInputError);
    std::vector<double> rho(surface.faces.size(), 1.0);
    rho[5] = 0;
    EXPECT_THROW(RestrictedVoronoiDiagram(surface, rho), InvalidInputError);
}

TEST(DensityEnergy, GradientMatchesCentralFiniteDifferences)
{
    const TriMesh surface = testmesh::torus(48, 24);
    const std::vector<Vec3> seeds = sampleSurfaceUniform(surface, 150, 11);
    EnergyFunction energy(surface, randomFaceDensity(surface, 7));
    EXPECT_LT(testgradient::worstRelativeError(energy, flatten(seeds)), 1e-5);
}

TEST(DensitySampling, SamplesFollowAreaTimesMu)
{
    // Unit square, left half ρ = 16 (μ = 4), right half ρ = 1: 4/5 of the samples on the left.
    const TriMesh plane = testmesh::planeGrid(20);
    std::vector<double> rho(plane.faces.size());
    for (int f = 0; f < plane.faceCount(); ++f) {
        const Face& t = plane.faces[f];
        const double cx = (plane.vertices[t[0]].x() + plane.vertices[t[1]].x() + plane.vertices[t[2]].x()) / 3;
        rho[f] = cx < 0.5 ? 16.0 : 1.0;
    }
    const int count = 20000;
    const std::vector<Vec3> points = sampleSurface(plane, count, 42, rho);
    int left = 0;
    for (const Vec3& p : points) left += p.x() < 0.5;
    // Binomial standard deviation sqrt(0.8 · 0.2 / 20000) = 0.0028: 4 of them.
    EXPECT_NEAR(double(left) / count, 0.8, 0.0113);

    // No density: exactly the uniform samples.
    const std::vector<Vec3> uniform = sampleSurfaceUniform(plane, 500, 9), none = sampleSurface(plane, 500, 9, {});
    ASSERT_EQ(uniform.size(), none.size());
    for (size_t i = 0; i < uniform.size(); ++i) EXPECT_EQ(uniform[i], none[i]);
}

TEST(DensitySampling, SmallComponentsAreToppedUpToTheMinimum)
{
    // A square with 100 points and a far small square with 1: the small one gets 2 more, on it.
    TriMesh surface = testmesh::planeGrid(10);
    const TriMesh small = testmesh::planeGrid(2, 0.05);
    const int base = surface.vertexCount();
    for (const Vec3& p : small.vertices) surface.vertices.push_back(p + Vec3(3, 0, 0));
    for (Face t : small.faces) surface.faces.push_back({t[0] + base, t[1] + base, t[2] + base});
    std::vector<Vec3> points = sampleSurfaceUniform(testmesh::planeGrid(10), 100, 3);
    points.push_back(Vec3(3.01, 0.01, 0));
    // The face lookup needs only to tell the squares apart: the big one's first face, the small one's.
    const int smallFace = testmesh::planeGrid(10).faceCount();
    const auto faceOf = [smallFace](const Vec3& x) { return x.x() > 2 ? smallFace : 0; };
    const std::vector<Vec3> before = points;
    EXPECT_EQ(topUpSmallComponents(surface, faceOf, 3, 7, points), 2);
    ASSERT_EQ(points.size(), before.size() + 2);
    for (size_t i = 0; i < before.size(); ++i) EXPECT_EQ(points[i], before[i]);
    for (size_t i = before.size(); i < points.size(); ++i) {
        EXPECT_GE(points[i].x(), 3.0);
        EXPECT_LE(points[i].x(), 3.05);
    }
    // Nothing short: nothing added; one component: the face lookup is not even called.
    EXPECT_EQ(topUpSmallComponents(surface, faceOf, 3, 7, points), 0);
    std::vector<Vec3> one = sampleSurfaceUniform(testmesh::planeGrid(10), 2, 3);
    int calls = 0;
    EXPECT_EQ(topUpSmallComponents(
                  testmesh::planeGrid(10), [&](const Vec3&) { return ++calls, 0; }, 3, 7, one),
              0);
    EXPECT_EQ(calls, 0);
}

TEST(DensitySources, PerVertexDensityIsValidated)
{
    const TriMesh surface = testmesh::torus(24, 12);
    RemeshParams p = smallRun();
    p.density = DensitySource::PerVertex;
    p.vertexDensity.assign(surface.vertices.size() - 1, 1.0);  // one short
    EXPECT_THROW(remesh(surface, p), InvalidInputError);
    for (double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        p.vertexDensity.assign(surface.vertices.size(), 1.0);
        p.vertexDensity[7] = bad;
        try {
            remesh(surface, p);
            ADD_FAILURE() << "density " << bad << " accepted";
        } catch (const InvalidInputError& e) {
            EXPECT_NE(std::string(e.what()).find("vertex 7"), std::string::npos) << e.what();
        }
    }
    p.density = DensitySource::Curvature;
    p.gradation = -1;
    EXPECT_THROW(remesh(surface, p), InvalidInputError);
}

TEST(DensitySources, PerVertexDensityFollowsTheCleanIndex)
{
    // Input vertices 0 and 2 were merged into surface vertex 0; vertex 3 was dropped.
    const std::vector<int> cleanIndex = {0, 1, 0, -1};
    const std::vector<double> mu = densityOnSurface({1.0, 5.0, 3.0, 9.0}, cleanIndex, 2);
    ASSERT_EQ(mu.size(), 2u);
    EXPECT_DOUBLE_EQ(mu[0], 2.0);
    EXPECT_DOUBLE_EQ(mu[1], 5.0);
}

TEST(DensitySources, CurvatureDensityIsGradedAndClamped)
{
    const TriMesh surface = testmesh::torus(64, 32, 1.0, 0.8);
    const std::vector<double> flat = curvatureDensity(surface, 0.0, 0.1);
    for (double m : flat) EXPECT_EQ(m, 1.0);
    std::vector<double> mu = curvatureDensity(surface, 2.0, 0.1);
    const double lo = *std::min_element(mu.begin(), mu.end()), hi = *std::max_element(mu.begin(), mu.end());
    EXPECT_GE(lo, 1.0);
    EXPECT_LE(hi, 25 * lo * (1 + 1e-12));
    // |k| is larger on the inner equator (distance R - r = 0.2 from the axis) than on the outer one.
    double inner = 0, outer = 0;
    for (size_t v = 0; v < surface.vertices.size(); ++v) {
        const double radius = surface.vertices[v].head<2>().norm();
        if (radius < 0.25) inner = std::max(inner, mu[v]);
        if (radius > 1.75) outer = std::max(outer, mu[v]);
    }
    EXPECT_GT(inner, outer);
    normaliseDensity(surface, mu);
    double weighted = 0, area = 0;
    for (int f = 0; f < surface.faceCount(); ++f) {
        const Face& t = surface.faces[f];
        weighted += faceArea(surface, f) * (mu[t[0]] + mu[t[1]] + mu[t[2]]) / 3;
        area += faceArea(surface, f);
    }
    EXPECT_NEAR(weighted / area, 1.0, 1e-12);
}

TEST(DensityRemesh, UnitDensityGivesExactlyTheUniformResult)
{
    const TriMesh surface = testmesh::torus(48, 24);
    RemeshParams p = smallRun();
    const RemeshResult uniform = remesh(surface, p);
    p.density = DensitySource::PerVertex;
    p.vertexDensity.assign(surface.vertices.size(), 1.0);
    const RemeshResult unit = remesh(surface, p);
    ASSERT_EQ(uniform.mesh.vertices.size(), unit.mesh.vertices.size());
    ASSERT_EQ(uniform.mesh.faces, unit.mesh.faces);
    for (size_t v = 0; v < uniform.mesh.vertices.size(); ++v) EXPECT_EQ(uniform.mesh.vertices[v], unit.mesh.vertices[v]);
    // Gradation 0 is uniform too.
    p.density = DensitySource::Curvature;
    p.gradation = 0;
    const RemeshResult flat = remesh(surface, p);
    ASSERT_EQ(uniform.mesh.faces, flat.mesh.faces);
    for (size_t v = 0; v < uniform.mesh.vertices.size(); ++v) EXPECT_EQ(uniform.mesh.vertices[v], flat.mesh.vertices[v]);
}

TEST(DensityRemesh, CurvatureDensityPutsMoreVerticesWhereCurved)
{
    // Torus: the inner half (towards the axis) is more curved; more vertices there than with
    // the uniform density, and the vertex count is kept.
    const TriMesh surface = testmesh::torus(64, 32, 1.0, 0.8);
    RemeshParams p = smallRun();
    p.vertexCount = 600;
    auto innerCount = [](const TriMesh& m) {
        int inner = 0;
        for (const Vec3& v : m.vertices) inner += v.head<2>().norm() < 1.0;
        return inner;
    };
    const RemeshResult uniform = remesh(surface, p);
    p.density = DensitySource::Curvature;
    p.gradation = 3;
    const RemeshResult adaptive = remesh(surface, p);
    EXPECT_NEAR(double(adaptive.mesh.vertexCount()), 600.0, 12.0);
    EXPECT_GT(innerCount(adaptive.mesh), innerCount(uniform.mesh) + 30);
}
