#pragma once
// Valence optimisation of the output mesh (§4.4): lower the irregularity
// R = Σ_v (d(v) − o(v))² (o = 6 inside, 4 on the boundary) with edge flips, edge collapses and
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
    Boundary,  //!< on the input's open border: moves only along it; target valence 4
    Feature,   //!< on a sharp feature line: moves only along it
    Corner,    //!< fixed (feature corner, end of a feature curve)
};

struct ValenceParams {
    int maxRounds = 30;             //!< rounds of "choose per irregular vertex, apply the best non-conflicting"
    int localSmoothing = 3;         //!< tangential smoothing steps around each applied operation
    double minAngleDegrees = 25;    //!< an operation that leaves a smaller angle around it is refused
    int relaxIterations = 10;       //!< final fixed-connectivity relaxation steps (0 = none)
};

struct ValenceStats {
    double v6Before = 0, v6After = 0;                  //!< % of interior vertices of valence 6
    long long irregularityBefore = 0, irregularityAfter = 0;  //!< R
    int flips = 0, collapses = 0, splits = 0, rounds = 0;
};

//! The input surface the optimised mesh lives on (all at the working scale).
struct ValenceSurface {
    const TriMesh& input;                //!< the input surface
    const ClosestPointTree& tree;        //!< closest points on `input`
    std::vector<Segment> border;         //!< the input's open boundary (Boundary vertices stay on it)
    std::vector<Segment> features;       //!< sharp feature lines (Feature vertices stay on them)
    const DirectionField* field = nullptr;  //!< 6-RoSy field on `input` for the final relaxation (null: none)
};

//! Optimises `mesh` in place: vertices may be added and removed; the mesh stays edge- and
//! vertex-manifold and oriented, its vertices on the input surface. `roles` has one entry per
//! vertex of `mesh` and is kept in step with the vertices (a split vertex inherits Free, a
//! collapse keeps the more constrained role). V6% before and after are measured like
//! computeQuality does.
ValenceStats optimizeValence(TriMesh& mesh, std::vector<VertexRole>& roles, const ValenceSurface& surface,
                             const ValenceParams& params);

}  // namespace fieldcvt
