#pragma once
// Central finite differences of an energy against its analytic gradient (shared by the energy
// and density tests).
#include "energy.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <random>

namespace fieldcvt::testgradient {

//! The largest relative error, over `trials` random coordinates of `x`, between the gradient of
//! `energy` at `x` and central differences of E_tot with step `step` (relative to
//! max(1e-3, |∂E/∂x_k|)).
inline double worstRelativeError(EnergyFunction& energy, const Eigen::VectorXd& x, int trials = 60, double step = 1e-6)
{
    Eigen::VectorXd gradient, unused;
    energy.evaluate(x, gradient);
    std::mt19937_64 rng(1);
    double worst = 0;
    for (int trial = 0; trial < trials; ++trial) {
        const int k = static_cast<int>(rng() % static_cast<std::uint64_t>(x.size()));
        Eigen::VectorXd plus = x, minus = x;
        plus[k] += step;
        minus[k] -= step;
        const double numeric = (energy.evaluate(plus, unused).total - energy.evaluate(minus, unused).total) / (2 * step);
        const double scale = std::max(1e-3, std::abs(gradient[k]));
        worst = std::max(worst, std::abs(numeric - gradient[k]) / scale);
    }
    return worst;
}

}  // namespace fieldcvt::testgradient
