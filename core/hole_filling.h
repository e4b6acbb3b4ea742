#pragma once
// Small holes closed before remeshing. A scan's holes of a few input triangles are far below
// the output's edge length: its cells cannot follow such a border, so the output got slivers
// around it, torn pieces and lost samples (docs/tuning.md, "RemeshParams::closeHolesUnder"). A
// hole under about two edge lengths across is closed instead, with triangles over its own border
// vertices, and the surface remeshed whole.
#include "mesh.h"

namespace fieldcvt {

//! What closeSmallHoles did.
struct HoleFillReport {
    int closed = 0;    //!< border loops closed
    double area = 0;   //!< the area of the triangles added
    int leftOpen = 0;  //!< small loops left open: not simple, or closing them would add an edge the mesh has
};

//! Closes each border loop of `mesh` under `maxAcross` across (the diameter of a round hole
//! with the same bounding box: the box diagonal / sqrt 2) whose piece (edge-connected faces) is
//! more than twice as large as the loop's box diagonal (a small piece, e.g. a loose disk, is left as it is: closing its border would turn
//! it into a closed pillow). The loop is triangulated in its own plane (triangulate.h: exact
//! ear clipping or a constrained Delaunay triangulation), oriented like the faces around it; no
//! vertex is added or moved. A loop that passes a vertex twice, is not simple in its plane, or
//! whose triangles would add an edge the mesh already has is left open (HoleFillReport::leftOpen).
HoleFillReport closeSmallHoles(TriMesh& mesh, double maxAcross);

}  // namespace fieldcvt
