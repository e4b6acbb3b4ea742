#pragma once
// Minimisation of the energy over the sample positions: Lloyd warm-up, then L-BFGS (LBFGS++)
// with a fallback when its line search fails (§4.3, §5).
#include "boundary.h"
#include "energy.h"

#include <cstdint>
#include <string>
#include <vector>

namespace fieldcvt {

struct LbfgsParams {
    int iterations = 130;  //!< L-BFGS iterations (the paper's CVT budget, §5)
    int memory = 7;        //!< correction pairs kept
    //! Early stop on convergence: L-BFGS ends when E_tot decreased by less than this fraction
    //! over the last `window` iterations, |E_{k-window} - E_k| < relativeDecrease · |E_k|.
    //! 0 = off (default): the full budget is used, as in the paper's fixed schedule; stopping
    //! earlier costs regularity (docs/tuning.md, "LbfgsParams::relativeDecrease").
    double relativeDecrease = 0;
    int window = 5;  //!< iterations the relative decrease is measured over (>= 1)
};

struct OptimizeStats {
    int iterations = 0;            //!< L-BFGS iterations done
    int restarts = 0;              //!< line-search failures recovered by a restart
    bool stalled = false;          //!< ended early: two restarts in a row without progress
    std::vector<double> energies;  //!< E_tot after each restart segment's end, and at the end
    std::vector<std::string> warnings;
};

//! `iterations` Lloyd steps: every seed moves to the centroid of its restricted cell. A seed
//! whose cell is empty is moved to a random point of the surface (deterministic from `seed`).
void lloydRelaxation(EnergyFunction& energy, const TriMesh& surface, std::vector<Vec3>& seeds, int iterations,
                     std::uint64_t seed);

//! Seeds whose restricted cell is empty (no mass) go to random points of the surface (∝ area ×
//! density, deterministic from `seed`); the energy's frozen ones (EnergyFunction::frozen) stay.
//! L-BFGS cannot move such a seed (its gradient is zero) and the RDT would drop it. Returns how
//! many moved.
int reseedEmptyCells(EnergyFunction& energy, const TriMesh& surface, std::vector<Vec3>& seeds, std::uint64_t seed);

//! L-BFGS on the energy, starting from and updating `seeds`. The best point seen is kept: a
//! line-search failure restarts from it; two failures in a row without progress end it early
//! (OptimizeStats::stalled).
OptimizeStats minimizeLbfgs(EnergyFunction& energy, std::vector<Vec3>& seeds, const LbfgsParams& params);

}  // namespace fieldcvt
