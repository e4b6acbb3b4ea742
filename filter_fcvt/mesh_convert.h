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

//! toTriMesh for the filters that remesh or compute a field. MeshLab 2020.09's OFF and PLY
//! importers split a polygon into a fan from its first corner, which makes a zero-area triangle
//! at each straight corner (a vertex on the polygon's edge); the core's input check would remove
//! those and tear the surface open, so they are flipped into their neighbours instead
//! (fieldcvt::flipZeroAreaTriangles; vertices unchanged). `flipped` counts them.
fieldcvt::TriMesh toSurfaceMesh(const CMeshO& in, int& flipped);

//! Replaces the content of `out` with `mesh` (float coordinates, vertex/face order kept).
//! Bounding box and normals are left to the caller (MeshModel::UpdateBoxAndNormals).
void fromTriMesh(const fieldcvt::TriMesh& mesh, CMeshO& out);

}  // namespace fcvt_plugin
