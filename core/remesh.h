#pragma once
// The one public entry point of the engine: input mesh + parameters (remesh_params.h) -> remeshed
// mesh + report (remesh_result.h).
#include "mesh.h"
#include "progress.h"
#include "remesh_params.h"
#include "remesh_result.h"

namespace fieldcvt {

//! Remeshes `input` after checking it and `params` (InvalidInputError, with a clear message);
//! reports its stages through `progress`.
RemeshResult remesh(const TriMesh& input, const RemeshParams& params, const Progress& progress = {});

}  // namespace fieldcvt
