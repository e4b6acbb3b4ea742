// The field-alignment energy (eq. 2–3) and its gradient (appendix).
#include "energy.h"
#include "field.h"
#include "sampling.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace fieldcvt;

namespace {

Vec3 randomUnit(std::mt19937_64& rng)
{
    std::normal_distribution<double> g;
    return Vec3(g(rng), g(rng), g(rng)).normalized();
}

// A random frame: unit n and unit d ⟂ n.
void randomFrame(std::mt19937_64& rng, Vec3& n, Vec3& d)
{
    n = randomUnit(rng);
    d = n.cross(randomUnit(rng)).normalized();
}

}  // namespace

TEST(DirectionDistance, IsZeroOnFieldDirectionsAndOneAlongTheNormal)
{
    const Vec3 n(0, 0, 1), d(1, 0, 0);
    for (int k = 0; k < 6; ++k) {
        const double phi = k * kPi / 3;
        EXPECT_NEAR(directionDistance(2.5 * Vec3(std::cos(phi), std::sin(phi), 0), n, d), 0.0, 1e-14);
    }
    EXPECT_NEAR(directionDistance(Vec3(0, 0, 3), n, d), 1.0, 1e-14);
    // Half-way between two field directions (φ = 30°) in the plane: cos 6φ = −1, D = 1.
    EXPECT_NEAR(directionDistance(Vec3(std::cos(kPi / 6), std::sin(kPi / 6), 0), n, d), 1.0, 1e-14);
}

TEST(DirectionDistance, StaysInUnitIntervalIsPeriodicAndScaleFree)
{
    std::mt19937_64 rng(3);
    for (int trial = 0; trial < 2000; ++trial) {
        Vec3 n, d;
        randomFrame(rng, n, d);
        const Vec3 e = randomUnit(rng) * (0.1 + 3.0 * (trial % 7));
        const double value = directionDistance(e, n, d);
        EXPECT_GE(value, -1e-15);
        EXPECT_LE(value, 1 + 1e-15);
        // Another representative of the 6-RoSy (d rotated by 60° about n) gives the same D.
        const Vec3 d60 = std::cos(kPi / 3) * d + std::sin(kPi / 3) * n.cross(d);
        EXPECT_NEAR(directionDistance(e, n, d60), value, 1e-12);
        EXPECT_NEAR(directionDistance(7.0 * e, n, d), value, 1e-12);
    }
}

TEST(DirectionDistance, MatchesTheTrigonometricFormula)
{
    std::mt19937_64 rng(5);
    for (int trial = 0; trial < 500; ++trial) {
        Vec3 n, d;
        randomFrame(rng, n, d);
        const Vec3 e = randomUnit(rng);
        const double theta = std::acos(e.dot(n));
        const double phi = std::atan2(e.dot(n.cross(d)), e.dot(d));
        EXPECT_NEAR(directionDistance(e, n, d), 1 - (1 + std::cos(6 * phi)) / 2 * std::sin(theta), 1e-12);
    }
}

TEST(DirectionDistance, GradientMatchesCentralDifferences)
{
    std::mt19937_64 rng(7);
    for (int trial = 0; trial < 300; ++trial) {
        Vec3 n, d;
        randomFrame(rng, n, d);
        const Vec3 e = randomUnit(rng) * 1.3;
        Vec3 gradient;
        directionDistance(e, n, d, &gradient);
        const double h = 1e-6;
        for (int k = 0; k < 3; ++k) {
            Vec3 plus = e, minus = e;
            plus[k] += h;
            minus[k] -= h;
            const double numeric = (directionDistance(plus, n, d) - directionDistance(minus, n, d)) / (2 * h);
            EXPECT_NEAR(gradient[k], numeric, 1e-6 * std::max(1.0, std::abs(numeric)));
        }
    }
}

TEST(FieldEnergy, GradientMatchesCentralDifferencesWithFrozenFramesAndWeights)
{
    // Random samples on a torus, its real RVD edges as weights, random frames: E_field as a
    // function of the positions alone (eq. 2 with n, d, w frozen, as in the appendix).
    const TriMesh surface = testmesh::torus(40, 20);
    const std::vector<Vec3> seeds = sampleSurfaceUniform(surface, 120, 4);
    RestrictedVoronoiDiagram rvd(surface);
    RvdResult diagram;
    RvdOptions options;
    options.edges = true;
    rvd.compute(seeds, options, diagram);
    ASSERT_GT(diagram.edges.size(), 200u);

    std::mt19937_64 rng(9);
    FieldFrames frames;
    for (size_t i = 0; i < seeds.size(); ++i) {
        Vec3 n, d;
        randomFrame(rng, n, d);
        frames.normals.push_back(n);
        frames.directions.push_back(d);
    }
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(3 * seeds.size());
    fieldEnergy(seeds, diagram.edges, frames, &gradient);

    double worst = 0;
    const double h = 1e-6;
    for (size_t i = 0; i < seeds.size(); i += 3)
        for (int k = 0; k < 3; ++k) {
            std::vector<Vec3> plus = seeds, minus = seeds;
            plus[i][k] += h;
            minus[i][k] -= h;
            const double numeric =
                (fieldEnergy(plus, diagram.edges, frames, nullptr) - fieldEnergy(minus, diagram.edges, frames, nullptr)) /
                (2 * h);
            worst = std::max(worst, std::abs(numeric - gradient[3 * i + k]) / std::max(1e-3, std::abs(numeric)));
        }
    EXPECT_LT(worst, 1e-5);
}

TEST(FieldEnergy, TotalGradientMatchesFrozenConnectivityDifferences)
{
    // E_tot = E_CVT + λ E_field through EnergyFunction: its gradient against central
    // differences of E_CVT (exact RVD) plus λ E_field with the RDT edges, weights and frames of
    // the base point frozen — what the appendix differentiates.
    const TriMesh surface = testmesh::torus(48, 24);
    FieldParams fieldParams;
    const DirectionField field = computeField(surface, fieldParams);
    const ClosestPointTree tree(surface);
    const std::vector<Vec3> seeds = sampleSurfaceUniform(surface, 150, 8);
    const double lambda = 0.5;

    EnergyFunction energy(surface);
    energy.setField(&field, &tree, lambda);
    Eigen::VectorXd gradient, unused;
    energy.evaluate(flatten(seeds), gradient);
    const std::vector<RvdEdge> edges = energy.lastDiagram().edges;
    const FieldFrames frames = energy.framesAt(seeds);

    EnergyFunction cvtOnly(surface);
    auto frozenTotal = [&](const std::vector<Vec3>& x) {
        return cvtOnly.evaluate(flatten(x), unused).cvt + lambda * fieldEnergy(x, edges, frames, nullptr);
    };
    std::mt19937_64 rng(2);
    double worst = 0;
    const double h = 1e-6;
    for (int trial = 0; trial < 40; ++trial) {
        const size_t i = rng() % seeds.size();
        const int k = static_cast<int>(rng() % 3);
        std::vector<Vec3> plus = seeds, minus = seeds;
        plus[i][k] += h;
        minus[i][k] -= h;
        const double numeric = (frozenTotal(plus) - frozenTotal(minus)) / (2 * h);
        worst = std::max(worst, std::abs(numeric - gradient[3 * i + k]) / std::max(1e-3, std::abs(numeric)));
    }
    EXPECT_LT(worst, 1e-5);
}
