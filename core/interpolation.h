#pragma once
// Interpolation of the 6-RoSy field at any point of the surface (paper §4.2).
#include "field.h"
#include "mesh.h"

namespace fieldcvt {

struct FieldSample {
    Vec3 normal;     //!< unit
    Vec3 direction;  //!< unit, orthogonal to normal
};

//! The field at the point of `face` with barycentric coordinates `barycentric` (§4.2): n is the
//! normalised barycentric combination of the corner normals; d is the normalised
//! (I − nnᵀ)(w_A d_A + w_B d_B + w_C d_C) for the representatives of the three corners
//! (rotations by k·60° of d_B and d_C about their normals) that maximise its norm. The result
//! does not depend on which representative each vertex stores. (A's three lines d_A, R60·d_A,
//! R120·d_A are searched too, 3 × 6 × 6 combinations: when the corner normals differ, keeping
//! A's stored representative would make the result depend on it; its sign never matters.)
FieldSample interpolateField(const TriMesh& mesh, const DirectionField& field, int face, const Vec3& barycentric);

//! Rotates the representative d by k·60° about the unit normal n.
Vec3 rotateRepresentative(const Vec3& d, const Vec3& n, int k);

}  // namespace fieldcvt
