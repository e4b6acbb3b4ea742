#pragma once
// Mesh files <-> fieldcvt::TriMesh, through vcglib's wrap/io_trimesh (PLY, OFF, STL) and a tolerant
// OBJ reader. Kept out of core/ so the engine has no vcglib dependency.
#include "mesh.h"
#include "mesh_io_types.h"
#include "mesh_texture.h"

#include <string>
#include <vector>

namespace fieldcvt {

//! Reads PLY/OBJ/OFF/STL by extension (case-insensitive). Throws IOError with one clear line
//! for a missing, unreadable, truncated or malformed file, or one with no triangles.
//! With `attributes`, a PLY file's per-vertex `nx ny nz` and `rosy_x rosy_y rosy_z` properties
//! (all three of a group, scalar) fill `normals` and `rosy`, one per vertex; a group the file
//! does not have (and every group, for other formats) is left empty. attributes->faceProperty
//! names a face property to read (IOError if the file is not PLY or its faces lack it).
//! With `texture`, an OBJ file's per-corner `vt` (materials: `usemtl` names, `mtllib` file names,
//! images not looked up) or a PLY file's MeshLab `texcoord` face lists (materials: `TextureFile`
//! comments, `texnumber`) fill it; left empty without them, and emptied with a warning in `info`
//! when they are broken (not finite, index out of range, on some faces only): the mesh is read.
TriMesh readMesh(const std::string& path, MeshReadInfo* info = nullptr, VertexAttributes* attributes = nullptr,
                 MeshTexture* texture = nullptr);

//! Writes by extension (PLY binary, OBJ, OFF, STL). Throws IOError on failure. A non-empty
//! `texture` (it must fit the mesh) is written by OBJ (`vt` per corner, `mtllib`, `usemtl`: the
//! .mtl files themselves are the caller's) and PLY (`texcoord`, `texnumber`, `TextureFile`).
void writeMesh(const std::string& path, const TriMesh& mesh, const VertexAttributes* attributes = nullptr,
               const MeshTexture* texture = nullptr);

}  // namespace fieldcvt
