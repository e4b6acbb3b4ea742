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
#include "valence/surface.h"
#include "valence_params.h"

#include <vector>

namespace fieldcvt {

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
