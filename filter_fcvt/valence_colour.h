#pragma once
// Vertex colours by valence, as in the paper's figures: the colour says how far a vertex is from
// its target valence o(v) (6 inside, 4 on an open boundary, the targets of §4.4).
#include <vcg/space/color4.h>

#include <vector>

#include "mesh.h"

namespace fcvt_plugin {

//! The palette (also scripts/render.py's): below target blue, above target pink, on target
//! white; vertices on no face (valence 0) light grey.
inline const vcg::Color4b kValenceLow(30, 90, 235, 255);
inline const vcg::Color4b kValenceHigh(235, 40, 175, 255);
inline const vcg::Color4b kValenceRegular(255, 255, 255, 255);
inline const vcg::Color4b kValenceUnused(160, 160, 160, 255);

struct ValenceColouring {
    std::vector<vcg::Color4b> colours;                           //!< one per vertex of the mesh
    int interiorLow = 0, interiorRegular = 0, interiorHigh = 0;  //!< valence < 6, = 6, > 6
    int boundaryLow = 0, boundaryRegular = 0, boundaryHigh = 0;  //!< valence < 4, = 4, > 4
    int unused = 0;                                              //!< vertices on no face
};

//! Valence = distinct neighbours through edges (like fieldcvt::computeQuality); a vertex is on the
//! boundary when one of its edges has a single face. Non-manifold edges count as interior edges.
ValenceColouring colourByValence(const fieldcvt::TriMesh& mesh);

}  // namespace fcvt_plugin
