#pragma once
// Valence optimisation of the output mesh (§4.4): lower the irregularity
// R = Σ_v w(v)·(d(v) − o(v))² (o = 6 inside, 4 on the boundary; w = 1 inside,
// ValenceParams::borderWeight on the boundary) with edge flips, edge collapses and
// vertex splits, each followed by local tangential smoothing projected on the input surface;
// then a relaxation on the fixed connectivity so the edges follow the field again.
#include "boundary.h"
#include "closest_point.h"
#include "field.h"
#include "mesh.h"

#include <vector>

namespace fieldcvt {

//! What a vertex of the mesh being optimised may do.
enum class VertexRole : char {
    Free,      //!< interior vertex: moves tangentially, projected on the input surface
    Boundary,  //!< on the input's open border: stays where it is (see optimizeValence); target valence 4
    Feature,   //!< on a sharp feature line: moves only along it
    Corner,    //!< fixed (feature corner, end of a feature curve)
};

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

//! The input surface the optimised mesh lives on (all at the working scale).
struct ValenceSurface {
    const TriMesh& input;                   //!< the input surface
    const ClosestPointTree& tree;           //!< closest points on `input`
    std::vector<Segment> features;          //!< sharp feature lines (Feature vertices stay on them)
    const DirectionField* field = nullptr;  //!< 6-RoSy field on `input` for the final relaxation (null: none)
    //! The input's open border. A Free vertex that the mesh has on its border (a sample whose cell
    //! reached the border during the FCVT iterations) is put on it before it becomes Boundary;
    //! empty: left where it is.
    std::vector<Segment> border;
};

//! Optimises `mesh` in place: vertices may be added and removed; the mesh stays edge- and
//! vertex-manifold and oriented, its vertices on the input surface. `roles` has one entry per
//! vertex of `mesh` (or is empty: then derived, Boundary on the mesh's border, Free elsewhere)
//! and is kept in step with the vertices (a split vertex is Free, a collapse keeps the
//! constrained end). A Free vertex on an edge of the mesh's border is treated, and returned, as
//! Boundary; a Boundary one on no border edge of the mesh as Free. Boundary and Corner vertices do not move; Feature vertices slide along
//! `surface.features`, Free ones on the input surface. Border edges are never flipped or collapsed,
//! nor edges between two Feature / Corner vertices; only Free vertices are split, and a
//! collapse needs a Free end. V6% before and after are measured like computeQuality does.
//! Deterministic, whatever the thread count. Throws InvalidInputError on a size mismatch.
//! `faceHints` (optional, one per vertex or empty): a face of `surface.input` near each vertex
//! (RdtResult::faceOfVertex), which only speeds up the first closest-point queries.
ValenceStats optimizeValence(TriMesh& mesh, std::vector<VertexRole>& roles, const ValenceSurface& surface,
                             const ValenceParams& params, const std::vector<int>& faceHints = {});

}  // namespace fieldcvt
