#pragma once
// The 6-RoSy field of an input mesh as `fcvt field` and MeshLab's "Compute 6-RoSy Field" compute
// it, in one place: the input checked, the field computed on the surface centred and scaled to
// one unit cell per vertex (working_frame.h, as remesh() does), so the model's size does not
// matter, and its singularities counted there.
#include "field.h"
#include "mesh.h"
#include "mesh_check.h"

#include <vector>

namespace fieldcvt {

struct InputField {
    TriMesh clean;                           //!< the checked input (input coordinates); the field is per its vertex
    InputReport report;                      //!< what the check did; report.cleanIndex: input -> clean vertex
    DirectionField field;                    //!< normals and directions per clean vertex
    std::vector<Singularity> singularities;  //!< positions in the input's coordinates
};

//! The field of `input` (prepareInput's strict check: throws InvalidInputError as it does). With
//! `userVectors` (one per input vertex: FieldSource::User), the field follows them instead.
InputField fieldOfInput(const TriMesh& input, const FieldParams& params, const std::vector<Vec3>* userVectors = nullptr);

}  // namespace fieldcvt
