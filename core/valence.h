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

struct ValenceParams {
    int maxRounds = 30;             //!< rounds of "choose per irregular vertex, apply the best non-conflicting"
    int localSmoothing = 3;         //!< tangential smoothing steps around each applied operation
    //! An operation (or relaxation step) that leaves a smaller angle around it, and a smaller one
    //! than there was, is refused. 35 rather than 25: the mesh keeps θ_min ≥ ~32° (measured).
    //! After the relaxation, the corners of faces still under it move to raise the smallest angle
    //! around them (angle repair): seeds 1–4 on the nine bench rows, closed meshes' lowest θ_min
    //! 31.2° -> 34.7°, every other figure unchanged.
    double minAngleDegrees = 35;
    //! Final fixed-connectivity relaxation steps (0 = none). 20 rather than 10: the longer
    //! look-ahead's extra operations leave Q_avg 0.001–0.003 lower after 10 steps (fandisk 5000
    //! 0.949, camelhead 3000 0.949); 20 steps bring it back (0.951 / 0.951, fertility 0.956,
    //! bunny 0.954) for about a second more on a 3000-vertex mesh on a loaded machine (figures
    //! of the earlier mean-of-neighbours step).
    int relaxIterations = 20;
    //! Weight w of a border vertex's term in R (interior vertices: 1). A disk's valences owe
    //! Σ(o − d) = 6 (Euler): the deficit sits either at border vertices of valence 3 (where the
    //! border turns) or at interior vertices of valence 5. With w = 1 both cost the same and
    //! nothing moves it; from w = 4 on, splitting the interior neighbour of a valence-3 border
    //! vertex (ΔR = 3 − w) moves it inside. 4 by measurement (seed 1, defaults): boundary
    //! vertices of valence 4 on camelhead 3000 84.9 -> 92.5 %, bunny 5000 69.8 -> 91.5 %, bunny
    //! adaptive 66.0 -> 85.4 %, mask and cylinder stay at 100 %; V6% 94.8 -> 94.6 and
    //! 94.7 -> 94.4, Q_avg and θ_min unchanged (3: no change; 6 and 10: the same as 4).
    int borderWeight = 4;
    //! When no single operation lowers R: chains of up to this many operations, R-neutral flips
    //! (each moves a 5–7 pair by one edge) ending in one that lowers R (the pair met another
    //! defect); 0 or 1 = off, 2 = one flip then the operation it enables, at most 8. Measured
    //! (seed 1, with relaxIterations 20, the paper's 65 + 65 schedule): depth 2 -> 5 -> 6 gives
    //! V6% 93.3 -> 95.2 -> 95.2 on torus 1000, 93.2 -> 94.8 -> 95.4 on fertility 3000, bunny 5000
    //! 94.1 -> 94.7, fandisk 5000 93.7 -> 94.0, mask 4000 96.4 -> 96.8. 8 since the short
    //! schedule (RemeshParams::lloydIterations), which leaves ~3 V6 points more to this stage:
    //! with 10 + 10 + 40 iterations, depth 6 -> 8 gives fandisk 5000 94.0 -> 94.6, fertility
    //! 3000 93.8 -> 94.6 (seeds 1–4: lowest 93.4 -> 94.0 / 93.8 -> 94.3), bunny 94.3 -> 95.0,
    //! Q_avg -0.001 to -0.002, the stage +10 to 25 % of its time.
    int lookAheadDepth = 8;
    //! The look-ahead rounds stop after one that applied fewer chains than this (1 = they go on
    //! while any applies). 2: the searches of the last rounds find the same few dozen chains and
    //! apply one or none each (bunny 5000: rounds 10-13, ~7 ms each, 1 / 1 / 1 / 0 chains).
    //! Measured on the nine bench rows, seeds 1-4: only bunny's outputs change (and one
    //! fandisk seed's by a vertex), its valence stage 266 -> 241 ms (2 threads, medians of 7);
    //! seed 1 Q_avg 0.9681 -> 0.9676, V6 95.6 -> 95.5 %, d_H 0.569 -> 0.486 %, the seeds' lowest
    //! Q_avg 0.9670 and θ_min 33.3° unchanged.
    int minChainsPerRound = 2;
    //! Weight of the field-alignment term in the final relaxation, on the scale of
    //! RemeshParams::lambda (E_field against E_CVT at mean cell area 1); 0 = smoothing only.
    //! 0.01 by measurement: brings the mean direction distance back to about its value before
    //! the operations (fertility 3000: 0.132 -> 0.161 after the operations -> 0.135; torus 1000:
    //! 0.169 -> 0.194 -> 0.158) with Q_avg 0.956 / 0.953; 0.0125 gives D 0.130 but Q_avg 0.949 on
    //! bunny 5000, 0.1 is unstable.
    double fieldWeight = 0.01;
};

struct ValenceStats {
    double v6Before = 0, v6After = 0;                  //!< % of interior vertices of valence 6
    long long irregularityBefore = 0, irregularityAfter = 0;  //!< R (weighted, see borderWeight)
    int flips = 0, collapses = 0, splits = 0, rounds = 0;
    int verticesBefore = 0, verticesAfter = 0;
    //! Mean direction distance D (eq. 3) over the (directed) mesh edges with the field at their
    //! first vertex: before, after the operations, after the relaxation (0 without a field).
    double fieldDistanceBefore = 0, fieldDistanceOperations = 0, fieldDistanceAfter = 0;
};

//! The input surface the optimised mesh lives on (all at the working scale).
struct ValenceSurface {
    const TriMesh& input;                //!< the input surface
    const ClosestPointTree& tree;        //!< closest points on `input`
    std::vector<Segment> features;       //!< sharp feature lines (Feature vertices stay on them)
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
//! Boundary. Boundary and Corner vertices do not move; Feature vertices slide along
//! `surface.features`, Free ones on the input surface. Border edges are never flipped or collapsed,
//! nor edges between two Feature / Corner vertices; only Free vertices are split, and a
//! collapse needs a Free end. V6% before and after are measured like computeQuality does.
//! Deterministic, whatever the thread count. Throws InvalidInputError on a size mismatch.
//! `faceHints` (optional, one per vertex or empty): a face of `surface.input` near each vertex
//! (RdtResult::faceOfVertex), which only speeds up the first closest-point queries.
ValenceStats optimizeValence(TriMesh& mesh, std::vector<VertexRole>& roles, const ValenceSurface& surface,
                             const ValenceParams& params, const std::vector<int>& faceHints = {});

}  // namespace fieldcvt
