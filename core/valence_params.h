#pragma once
// The parameters and the report of the valence optimisation (valence.h), which remesh()'s
// parameters and result carry.

namespace fieldcvt {

//! The defaults' measurements: docs/tuning.md, "ValenceParams::...".
struct ValenceParams {
    int maxRounds = 30;      //!< rounds of "choose per irregular vertex, apply the best non-conflicting"
    int localSmoothing = 3;  //!< tangential smoothing steps around each applied operation
    //! An operation (or relaxation step) that leaves a smaller angle around it, and a smaller one
    //! than there was, is refused; after the relaxation, the corners of faces still under it move
    //! to raise the smallest angle around them (angle repair). 35: θ_min stays above ~32°.
    double minAngleDegrees = 35;
    //! Final fixed-connectivity relaxation steps (0 = none); 20 bring Q_avg back after the look-ahead's operations.
    int relaxIterations = 20;
    //! Weight w of a border vertex's term in R (interior vertices: 1). From w = 4 on, splitting the
    //! interior neighbour of a valence-3 border vertex (ΔR = 3 − w) moves a disk's valence deficit
    //! (Σ(o − d) = 6, Euler) inside, so the border gets valence 4.
    int borderWeight = 4;
    //! When no single operation lowers R: chains of up to this many operations, R-neutral flips
    //! (each moves a 5–7 pair by one edge) ending in one that lowers R (the pair met another
    //! defect); 0 or 1 = off, 2 = one flip then the operation it enables, at most 8.
    int lookAheadDepth = 8;
    //! The look-ahead rounds stop after one that applied fewer chains than this (1 = they go on
    //! while any applies); 2: the last rounds' searches find the same few chains and apply one or none.
    int minChainsPerRound = 2;
    //! Weight of the field-alignment term in the final relaxation, on the scale of
    //! RemeshParams::lambda (E_field against E_CVT at mean cell area 1); 0 = smoothing only. 0.01
    //! brings the mean direction distance back to about its value before the operations.
    double fieldWeight = 0.01;
    //! Rounds of the last step, which moves the vertices of the faces farthest from the input (the
    //! largest sags, within 5 % of the largest) closer to it (0 = off): d_H's own repair.
    int sagRepairRounds = 4;
};

struct ValenceStats {
    double v6Before = 0, v6After = 0;                         //!< % of interior vertices of valence 6
    long long irregularityBefore = 0, irregularityAfter = 0;  //!< R (weighted, see borderWeight)
    int flips = 0, collapses = 0, splits = 0, rounds = 0;
    int verticesBefore = 0, verticesAfter = 0;
    //! Mean direction distance D (eq. 3) over the (directed) mesh edges with the field at their
    //! first vertex: before, after the operations, after the relaxation (0 without a field).
    double fieldDistanceBefore = 0, fieldDistanceOperations = 0, fieldDistanceAfter = 0;
};

}  // namespace fieldcvt
