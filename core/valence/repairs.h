#pragma once
// The valence stage's repairs after the relaxation: single Free vertices moved on the surface by
// a pattern search to raise the smallest angles (faces still under
// ValenceParams::minAngleDegrees), then to lower the largest sags (the faces that make d_H).
#include "valence/sag_guard.h"
#include "valence/valence_mesh.h"

namespace fieldcvt::valence {

//! Rounds over the corners of the faces still under the minimum angle: each moves to the
//! position with the largest smallest angle over its faces, without folding or sagging more.
void raiseSmallestAngles(ValenceMesh& mesh, SagGuard& sag, const ValenceParams& params);
//! Rounds over the Free corners of the faces whose sag is near the largest: each moves to bring
//! the largest sag of its faces down, without a fold, a sharper face or a worse shape.
void lowerLargestSags(ValenceMesh& mesh, SagGuard& sag, const ValenceParams& params);

}  // namespace fieldcvt::valence
