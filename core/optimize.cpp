#include "optimize.h"

#include "errors.h"
#include "sampling.h"
#include "boundary.h"

#include <LBFGS.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace fieldcvt {

namespace {
// Lloyd warm-up: cells below this fraction of the mean cell are re-seeded at random.
constexpr double kTinyCellFraction = 1.0 / 16;
// ... when more than this fraction of all cells are that small.
constexpr double kUnevenFraction = 0.01;

// Moves the seeds listed in `indices` to random points of the surface, ∝ area × μ (density.h),
// all drawn in one pass over the faces.
void moveToRandomPoints(const EnergyFunction& energy, const TriMesh& surface, const std::vector<int>& indices, std::uint64_t seed,
                        std::vector<Vec3>& seeds)
{
    if (indices.empty()) return;
    const std::vector<Vec3> points = sampleSurface(surface, static_cast<int>(indices.size()), seed, energy.faceDensity());
    for (size_t k = 0; k < indices.size(); ++k) seeds[size_t(indices[k])] = points[k];
}
}  // namespace

void lloydRelaxation(EnergyFunction& energy, const TriMesh& surface, std::vector<Vec3>& seeds, int iterations, std::uint64_t seed)
{
    Eigen::VectorXd x, gradient;
    std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ULL);
    std::vector<int> reseed;
    // With a density a cell's mass varies like μ at the optimum (area ~ 1/μ, mass ~ ρ·area = μ):
    // the tiny-cell test allows for the density's range, so graded cells are not taken for a
    // cluster.
    const std::vector<double>& rho = energy.faceDensity();
    double densityRange = 1;
    if (!rho.empty()) {
        const auto [lo, hi] = std::minmax_element(rho.begin(), rho.end());
        if (*lo > 0) densityRange = std::sqrt(*hi / *lo);
    }
    for (int it = 0; it < iterations; ++it) {
        x = flatten(seeds);
        energy.evaluate(x, gradient);
        const RvdResult& rvd = energy.lastDiagram();
        double totalMass = 0;
        for (double m : rvd.mass) totalMass += m;
        // A seed whose cell is empty goes to a random point of the surface. So does a seed whose
        // cell is tiny when many are (a clustered start): random points land in the large cells,
        // in proportion to their size, which spreads the cluster in a few steps where plain Lloyd
        // steps would take hundreds (§5, "Uneven initial sampling"). An area-uniform start has
        // almost no such cells and is left to plain Lloyd steps.
        const double tiny = kTinyCellFraction * totalMass / double(seeds.size()) / densityRange;
        const auto tinyCells = std::count_if(rvd.mass.begin(), rvd.mass.end(), [&](double m) { return m <= tiny; });
        const bool uneven = double(tinyCells) > kUnevenFraction * double(seeds.size());
        reseed.clear();
        for (size_t i = 0; i < seeds.size(); ++i) {
            if (rvd.mass[i] > (uneven ? tiny : 0.0))
                seeds[i] = rvd.moment[i] / rvd.mass[i];
            else
                reseed.push_back(static_cast<int>(i));
        }
        if (!reseed.empty()) moveToRandomPoints(energy, surface, reseed, rng(), seeds);
    }
}

int reseedEmptyCells(EnergyFunction& energy, const TriMesh& surface, std::vector<Vec3>& seeds, std::uint64_t seed)
{
    const RvdResult& rvd = energy.diagramAt(seeds);
    const std::vector<char>& frozen = energy.frozen();
    std::vector<int> empty;
    for (size_t i = 0; i < seeds.size(); ++i)
        if (!(rvd.mass[i] > 0) && !(i < frozen.size() && frozen[i])) empty.push_back(static_cast<int>(i));
    moveToRandomPoints(energy, surface, empty, seed, seeds);
    return static_cast<int>(empty.size());
}

namespace {

// Wraps the energy for LBFGS++ and remembers the best point evaluated.
struct TrackedObjective {
    explicit TrackedObjective(EnergyFunction& e) : energy(e) {}
    EnergyFunction& energy;
    double bestValue = std::numeric_limits<double>::infinity();
    Eigen::VectorXd best;

    double operator()(const Eigen::VectorXd& x, Eigen::VectorXd& gradient)
    {
        const double value = energy.evaluate(x, gradient).total;
        if (!std::isfinite(value) || !gradient.allFinite())
            throw SolverError("the energy is not finite (a sample left the surface's neighbourhood)");
        if (value < bestValue) {
            bestValue = value;
            best = x;
        }
        return value;
    }
};

// A restart segment that lowers E_tot by less than this fraction makes no progress (docs/tuning.md,
// "kStallDecrease").
constexpr double kStallDecrease = 1e-6;

}  // namespace

OptimizeStats minimizeLbfgs(EnergyFunction& energy, std::vector<Vec3>& seeds, const LbfgsParams& params)
{
    OptimizeStats stats;
    if (params.iterations <= 0) return stats;
    Eigen::VectorXd x = flatten(seeds);
    TrackedObjective objective(energy);

    LBFGSpp::LBFGSParam<double> solverParams;
    solverParams.m = params.memory;
    // Iterate for the full budget, as the paper's fixed schedule does: the gradient test only
    // stops at a numerically exact minimum.
    solverParams.epsilon = 1e-12 * std::sqrt(static_cast<double>(x.size()));
    solverParams.epsilon_rel = 0;
    solverParams.past = params.relativeDecrease > 0 ? std::max(1, params.window) : 0;
    solverParams.delta = params.relativeDecrease;
    // A line search that needs more than a few halvings sits at a jump of E_field (an RDT edge
    // that appears or vanishes between two trial points): it then only creeps, at many
    // evaluations per iteration (docs/tuning.md, "Line search: at most 10 steps"). It fails
    // instead, and the restart below decides whether L-BFGS still makes progress.
    solverParams.max_linesearch = 10;

    int failuresWithoutProgress = 0;
    while (stats.iterations < params.iterations) {
        solverParams.max_iterations = params.iterations - stats.iterations;
        LBFGSpp::LBFGSSolver<double> solver(solverParams);
        const double before = objective.bestValue;
        const int evaluationsBefore = energy.evaluations();
        double fx = 0;
        try {
            stats.iterations += solver.minimize(objective, x, fx);
            stats.energies.push_back(fx);
            break;  // budget used up or converged
        } catch (const SolverError&) {
            throw;
        } catch (const CancelledError&) {
            throw;
        } catch (const TimeLimitReached&) {
            // Out of time: hand back the best point seen, then let the caller stop.
            if (objective.best.size() == x.size()) seeds = unflatten(objective.best);
            throw;
        } catch (const std::exception&) {
            // Line search failed (non-smooth point of the RVD energy, or converged to round-off):
            // restart L-BFGS from the best point, which forgets the curvature pairs.
            ++stats.restarts;
            // LBFGS++ does not say how far it got; count its evaluations against the budget
            // (at least one iteration each), which keeps the loop bounded.
            stats.iterations += std::max(1, energy.evaluations() - evaluationsBefore);
            x = objective.best;
            stats.energies.push_back(objective.bestValue);
            // Progress: a relative decrease of E_tot of at least kStallDecrease since the last
            // restart. Two restarts without it: L-BFGS has converged as far as the piecewise
            // smooth energy lets it (a stall, not an error: no warning).
            const bool progress = before - objective.bestValue >= kStallDecrease * std::abs(objective.bestValue);
            failuresWithoutProgress = progress ? 0 : failuresWithoutProgress + 1;
            if (failuresWithoutProgress >= 2) {
                stats.stalled = true;
                break;
            }
        }
    }
    if (objective.best.size() == x.size() && objective.bestValue < std::numeric_limits<double>::infinity()) x = objective.best;
    seeds = unflatten(x);
    return stats;
}

}  // namespace fieldcvt
