#pragma once
// Validation and light repair of an input mesh before any work (clear errors, never a crash
// or a silently wrong result later in the pipeline). Every repair is counted and reported as
// one line of InputReport::notes.
#include "mesh.h"

#include <string>
#include <vector>

namespace fieldcvt {

struct InputReport {
    int mergedDuplicateVertices = 0;  //!< referenced vertices merged into an earlier one at the same coordinates
    int removedUnreferencedVertices = 0;
    int removedDegenerateFaces = 0;      //!< repeated corner or zero area (needle faces of non-zero area are kept)
    int removedDuplicateFaces = 0;       //!< same three corners as an earlier face
    int flippedFaces = 0;                //!< faces reversed to agree with their component's first face
    int splitNonManifoldVertices = 0;    //!< vertices whose faces formed several fans
    int addedVertexCopies = 0;           //!< copies added by those splits (one per fan after the first)
    int components = 0;                  //!< connected components of the clean mesh (through shared edges)
    std::vector<double> componentAreas;  //!< per component (ordered by first face), in input units
    std::vector<std::string> notes;      //!< one human-readable line per repair that changed the surface
    //! One line per change nobody sees (unreferenced vertices, exact duplicates, components kept).
    std::vector<std::string> information;
    //! Per input vertex: its index in the clean mesh, -1 if removed. A merged duplicate maps to
    //! the vertex it was merged into; a split vertex to the copy of its first fan (the fan of its
    //! first face in input order).
    std::vector<int> cleanIndex;
};

//! Returns a clean copy of `input`, in this order: exactly duplicate vertices (same coordinates)
//! merged; degenerate (repeated corner, zero area) and duplicate faces removed; the orientation
//! of each connected component made consistent with its first face; vertices whose faces form
//! several fans split into one vertex per fan; unreferenced vertices removed (the clean mesh
//! keeps the input's vertex order, split copies come last). Throws InvalidInputError (one line:
//! what and where) for an empty mesh, a point cloud, an out-of-range index or a non-finite
//! coordinate, and SurfaceTopologyError (errors.h) for a non-manifold edge or a non-orientable
//! component. `repaired`: the input is repairMesh's output (repair.h), which has merged
//! duplicate vertices (and split some again on purpose: not merged here) and removed duplicate
//! faces (not searched for here).
TriMesh prepareInput(const TriMesh& input, InputReport& report, bool repaired = false);

}  // namespace fieldcvt
