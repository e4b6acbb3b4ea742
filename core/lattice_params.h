#pragma once
// The parameters and the report of the lattice start (lattice.h), which remesh()'s result carries.
#include <cstdint>

namespace fieldcvt {

struct LatticeParams {
    //! Gauss–Seidel sweeps of the position field per hierarchy level: 4 and 8 gave the same
    //! figures within the seeds' spread (README: the lattice start), 4 in half the time.
    int iterations = 4;
    //! The lattice is solved again with a corrected spacing while its point count is further
    //! than this (relative) from the count asked for, at most maxPasses times in all; the pass
    //! closest to the count is kept.
    double countTolerance = 0.005;
    int maxPasses = 3;
    //! Shifts the coarsest level's lattices by a random fraction of a cell: the lattice's phase.
    std::uint64_t seed = 1;
};

struct LatticeReport {
    int levels = 0;      //!< hierarchy levels the position field was smoothed on
    double spacing = 0;  //!< edge length ρ of the lattice kept
    int passes = 0;      //!< lattices solved (1 to LatticeParams::maxPasses)
    int candidates = 0;  //!< lattice points found from the face corners before merging (lattice kept)
    int samples = 0;     //!< lattice points after merging (the samples returned)
};

}  // namespace fieldcvt
