#pragma once
// The valence stage's final relaxation (stand-in for §4.4's "several FCVT iterations after
// valence optimization"): on the fixed connectivity, every vertex moves down the shape energy
// of its faces and, with a field, down the field-alignment energy of its edges (eq. 2–3), then
// back onto the surface; a safety net puts back the corners of faces that fold, sharpen or sag.
#include "valence/sag_guard.h"
#include "valence/valence_mesh.h"

namespace fieldcvt::valence {

//! ValenceParams::relaxIterations Jacobi steps (the result does not depend on the thread count).
void relax(ValenceMesh& mesh, SagGuard& sag, const ValenceParams& params);

//! Gradient with respect to v of the shape energy of triangle (v, a, b) (counter-clockwise
//! seen from its normal): e = (|a - v|^2 + |b - v|^2 + |a - b|^2) / (4 sqrt3 |t|), the inverse
//! of the mean ratio [Liu & Joe 1994; Knupp 2001]: 1 for an equilateral triangle, growing
//! without bound as it degenerates, independent of its size. Zero (and area 0) for a
//! degenerate triangle, which has no direction to offer.
Vec3 shapeEnergyGradient(const Vec3& v, const Vec3& a, const Vec3& b, double& area);

}  // namespace fieldcvt::valence
