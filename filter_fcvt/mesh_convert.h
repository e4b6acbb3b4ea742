#pragma once
// CMeshO (MeshLab, float, with deleted-element tombstones) <-> fieldcvt::TriMesh (core, double,
// compact). Pure translation: no cleaning, no repair; the core validates what it receives.
#include "meshlab_types.h"

#include "mesh.h"

#include <string>

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

//! What fullPrecisionCoordinates did.
enum class FilePrecision {
    Restored,    //!< the file's double coordinates replaced the layer's float ones
    Same,        //!< the file holds nothing finer than the layer (float coordinates)
    NotTheFile,  //!< the layer differs from its file (edited since, or read otherwise)
    NoFile,      //!< no file, or not one the core's readers take (PLY, OBJ, OFF)
};

//! MeshLab keeps coordinates in single precision; a file may hold doubles, which the command
//! line reads whole. When `path` (the layer's file) has exactly the layer's vertices once rounded
//! to float, in the same order, their double coordinates replace `mesh`'s (toTriMesh of the
//! layer): the filter then computes on the surface the CLI computes on, and gives its result.
//! With `fileFaces`, a file of polygons gives its triangles there too (the readers' triangulation,
//! where MeshLab's PLY importer fans them, folding concave ones, and loses some); empty when the
//! file has triangles only or the layer is not the file's.
FilePrecision fullPrecisionCoordinates(const std::string& path, fieldcvt::TriMesh& mesh,
                                       std::vector<fieldcvt::Face>* fileFaces = nullptr);

//! Replaces the content of `out` with `mesh` (float coordinates, vertex/face order kept).
//! Bounding box and normals are left to the caller (MeshModel::UpdateBoxAndNormals).
void fromTriMesh(const fieldcvt::TriMesh& mesh, CMeshO& out);

}  // namespace fcvt_plugin
