#pragma once
// The valence stage's tuning constants, by the part that uses them (the measurements behind each:
// docs/tuning.md, "The valence stage"). The defaults a caller may change are ValenceParams'.

namespace fieldcvt::valence {

// The operations and the repairs (operations.cpp, chains.cpp, apply.cpp, repairs.cpp).
//! Operations and repairs: a face turned more than ~32° from the surface normal counts as folded.
constexpr double kMinNormalDot = 0.85;

// The sag guard (sag_guard.cpp).
//! A face may always sag this many mean edge lengths: the floor of every limit.
constexpr double kMaxSag = 0.1;
//! An operation may let the faces around it sag 1.5× their largest sag before...
constexpr double kOperationSagGrowth = 1.5;
//! ... but by at most this many edge lengths more: a run of operations must not ratchet a tip off.
constexpr double kOperationSagStep = 0.1;
//! The relaxation and the angle repair let a face sag 1.25× its sag at their start.
constexpr double kRelaxSagGrowth = 1.25;
//! In the relaxation any face may sag up to half the largest start sag (about what d_H measures).
constexpr double kRelaxSagShareOfLargest = 0.5;

// The relaxation (relax.cpp).
//! A vertex moves at most this many mean edge lengths from where it started (off ridges and tips).
constexpr double kMaxDrift = 1.0;
//! ... and at most this fraction of the mean edge length per step.
constexpr double kMaxRelaxStep = 0.25;
//! Step down the shape energy, in mean incident face areas times its gradient (~ a Newton step).
constexpr double kShapeStep = 0.25;
//! Heavy-ball momentum: the shape energy's smooth modes converge slowly under plain Jacobi steps.
constexpr double kRelaxMomentum = 0.8;
//! The fold limit (~45°): looser than the operations', the moves are small and the connectivity fixed.
constexpr double kRelaxMinNormalDot = 0.7;

// The repairs (repairs.cpp).
//! Angle repair: rounds over the corners still under the minimum angle.
constexpr int kAngleRepairRounds = 8;
//! The repairs' pattern search: first step in mean edge lengths (halved when nothing improves)...
constexpr double kAngleRepairStep = 0.1;
//! ... within this many edge lengths of where the vertex was...
constexpr double kAngleRepairDrift = 0.3;
//! ... and at most this many steps for the angle repair (each accepted one raises the angle).
constexpr int kAngleRepairMaxSteps = 64;
//! Sag repair (rounds: ValenceParams::sagRepairRounds, the largest sag measured again before each).
//! The faces whose sag is within this fraction of the largest are repaired, down to the band's lower edge.
constexpr double kSagRepairBand = 0.05;
//! At most this many faces per round.
constexpr int kSagRepairFaces = 64;
//! Pattern steps per vertex (down to 1/8 of the first).
constexpr int kSagRepairMaxSteps = 12;
//! The mean of the vertex's faces' mean ratio may drop by at most this much.
constexpr double kSagRepairShapeLoss = 0.003;
//! No face's smallest angle under min(minAngleDegrees + this, its own before): room for the
//! projection onto the input that follows.
constexpr double kSagRepairAngleMargin = 3.0;
//! Only where the largest sag is at least this many edge lengths (a flat mesh's sags are rounding).
constexpr double kSagRepairMinSag = 0.005;

}  // namespace fieldcvt::valence
