#pragma once
// Validation and light repair of an input mesh before any work (clear errors, never a crash
// or a silently wrong result later in the pipeline).
#include "mesh.h"

#include <string>
#include <vector>

namespace fieldcvt {

struct InputReport {
    int removedUnreferencedVertices = 0;
    int removedDegenerateFaces = 0;  //!< repeated corner or zero area
    int removedDuplicateFaces = 0;   //!< same three corners as an earlier face
    std::vector<std::string> notes; //!< one human-readable line per repair
    std::vector<int> cleanIndex;     //!< per input vertex: its index in the clean mesh, -1 if removed
};

//! Returns a clean copy of `input`: unreferenced vertices, degenerate and duplicate faces
//! removed. Throws InvalidInputError (one line: what and where) for an empty mesh, a point
//! cloud, an out-of-range index, a non-finite coordinate or a non-manifold edge.
TriMesh prepareInput(const TriMesh& input, InputReport& report);

}  // namespace fieldcvt
