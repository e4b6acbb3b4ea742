#pragma once
// The working frame (§5): a surface centred on its bounding box and scaled so that its mean cell
// has area 1. remesh() and the field commands (CLI, MeshLab filter) compute there, so energies,
// thresholds and floating-point ranges are the same whatever the model's units and size: a
// model at 1e300 or 1e-300 is computed like one at 1.
#include "mesh.h"

namespace fieldcvt {

struct Normalisation {
    Vec3 centre = Vec3::Zero();
    double scale = 1;
    Vec3 toWork(const Vec3& p) const { return (p - centre) * scale; }
    Vec3 fromWork(const Vec3& p) const { return p / scale + centre; }
};

//! The frame in which `cells` equal cells of area 1 cover `surface` (a clean mesh with finite
//! coordinates, mesh_check.h). The area is measured on a copy scaled by a power of two (exact),
//! so it is right at any scale; where plain doubles suffice the frame is bit for bit
//! centre = 0.5 (lo + hi), scale = sqrt(cells / area). Throws InvalidInputError when the surface
//! has no measurable area or its working coordinates would not be finite.
Normalisation workingFrame(const TriMesh& surface, double cells);

//! `mesh` with every vertex taken to `frame` (toWork).
TriMesh inFrame(const TriMesh& mesh, const Normalisation& frame);

}  // namespace fieldcvt
