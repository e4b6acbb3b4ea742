#pragma once
// CMeshO (MeshLab, float, with deleted-element tombstones) <-> fieldcvt::TriMesh (core, double,
// compact). Pure translation: no cleaning, no repair; the core validates what it receives.
#include "meshlab_types.h"

#include "mesh.h"

namespace fcvt_plugin {

//! Copies the live (non-deleted) vertices and faces of `in`, with compact indices, in the
//! order they appear in `in`. Coordinates are taken as stored (cm.Tr is not applied: the new
//! layer gets the same Tr, so both layers stay in the same place).
fieldcvt::TriMesh toTriMesh(const CMeshO& in);

//! Replaces the content of `out` with `mesh` (float coordinates, vertex/face order kept).
//! Bounding box and normals are left to the caller (MeshModel::UpdateBoxAndNormals).
void fromTriMesh(const fieldcvt::TriMesh& mesh, CMeshO& out);

}  // namespace fcvt_plugin
