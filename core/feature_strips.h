#pragma once
// Feature lines the run's edge length cannot follow (issue 52, items 4 and 5). Where two feature
// lines run side by side closer than a fraction of the edge length (a chamfer, the rims of a wall
// or of a small hole, a step), samples snapped onto both lines (§5, the two-stage strategy) are
// that close together, and every triangle that spans the strip is a sliver: conrod's chamfers
// gave 5° angles with --feature-angle 45, against 30° without features. Such a strip cannot be
// resolved at that length anyway, so its lines are left to the free optimisation, as the surface
// elsewhere: the output cuts the strip like a surface without features, within its width.
#include "feature_lines.h"
#include "mesh.h"

#include <array>
#include <vector>

namespace fieldcvt {

struct NarrowStripParams {
    //! A feature edge with another feature line beside it closer than this times the edge
    //! length is not kept (RemeshParams::narrowFeatureStripShare).
    double widthShare = 0.75;
    //! Two feature edges run beside each other within this (cosine, 45°) of parallel...
    double parallelCos = 0.7071;
    //! ... and the shortest way across is within this (cosine, 60°) of square to the edge.
    double acrossCos = 0.5;
    //! A point of the same line reached along the line within this times the distance across is
    //! the line bending (a rounded corner), not a strip.
    double alongShare = 1.5;
    //! Feature edges within this many widths along the lines of a wedge's apex are kept: a line
    //! whose two edges leave a vertex between wedgeDegrees and acos(parallelCos) of each other
    //! turns at a corner the user wants (under wedgeDegrees: a line folding back, no corner).
    double wedgeReach = 3.0;
    double wedgeDegrees = 15.0;
    //! What is left of a line (a connected piece of the edges kept) shorter than this many edge
    //! lengths in all is left out too: its two ends, both corners, would be closer than an edge.
    double fragmentShare = 1.0;
};

struct NarrowStrips {
    std::vector<std::array<int, 2>> kept;  //!< the feature edges left (sorted, as FeatureLines::edges)
    int dropped = 0;                       //!< how many were left out
};

//! The feature edges of `lines` (edges of `surface`, as FeatureLines::edges) split into those with
//! another feature line or the open border beside them closer than params.widthShare × `edgeLength`
//! (left out, unless near a wedge's apex) and the others. Deterministic, independent of the thread count.
NarrowStrips findNarrowStrips(const TriMesh& surface, const FeatureLines& lines, double edgeLength,
                              const NarrowStripParams& params = {});

}  // namespace fieldcvt
