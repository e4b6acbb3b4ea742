#pragma once
// The optimisation surface: a coarser copy of the input that the Lloyd, CVT and FCVT iterations,
// the field and the valence optimisation run on when the input has many more triangles than the
// output will have (a scan of 70 000 faces remeshed to 5000 vertices). Every RVD evaluation
// clips all input triangles, so its cost follows the input's size, not the output's; a surface
// with a few triangles per output vertex carries the same shape at the output's resolution.
//
// Garland–Heckbert quadric error metrics with half-edge collapses: a vertex is only ever removed,
// never moved, so the coarse surface's vertices are input vertices (per-vertex data — a user
// field, a density — carries over by index) and its triangles span points of the input surface.
// Vertices on the open border and on feature edges are kept, so the border and the feature lines
// are the input's own edges. remesh() puts the output vertices back on the input surface and
// measures d_RMS / d_H against the input, not against this copy.
#include "mesh.h"

#include <vector>

namespace fieldcvt {

struct SimplifyParams {
    int targetFaces = 0;  //!< stop at this many faces (or when no collapse is allowed)
    //! A collapse is refused when the quadric error of the kept vertex, as a distance (the root
    //! of the error over the area the quadric covers), exceeds this. Working units: remesh()
    //! passes a fraction of the output's edge length, so thin parts and small pieces stay.
    double maxError = 0;
    //! Vertices never removed (one per input vertex, or empty = none): remesh() keeps the open
    //! border's and the feature lines' vertices. Vertices on a border edge are always kept.
    std::vector<char> locked;
    //! Inputs of at least twice this many faces are first simplified in blocks of about this
    //! many faces (runs of a Morton curve of face centroids), in parallel, each block's frontier
    //! and its neighbours kept, then in one pass over the merged blocks to the target. The blocks
    //! depend on the input only: the same result on any thread count. 0 = one pass always.
    //! 250 000: a 1.6M-face input in 6 blocks (docs/tuning.md, "SimplifyParams::blockFaces").
    int blockFaces = 250000;
};

struct SimplifyResult {
    TriMesh mesh;                   //!< the coarse surface (same orientation)
    std::vector<int> inputVertex;   //!< per coarse vertex: its index in the input
    std::vector<int> coarseVertex;  //!< per input vertex: its coarse index, -1 if removed
};

//! Simplifies a manifold, oriented triangle mesh towards params.targetFaces faces; keeps it
//! manifold (link condition), refuses collapses that flip or nearly flip a face or make a sliver
//! worse than the ones already there. Deterministic (single-threaded, ties broken by index).
SimplifyResult simplifyMesh(const TriMesh& input, const SimplifyParams& params);

//! How many blocks simplifyMesh() cuts an input of `faceCount` faces into (1: a single pass).
int simplifyBlockCount(int faceCount, const SimplifyParams& params);

}  // namespace fieldcvt
