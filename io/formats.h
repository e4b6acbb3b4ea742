#pragma once
// The readers and writers of fcvt_io, one per format, each in its own file (read_obj.cpp,
// read_off.cpp, read_ply.cpp, read_vcg.cpp, write_obj.cpp, write_ply.cpp, write_vcg.cpp): what
// readMesh and writeMesh (mesh_io.cpp) dispatch to by extension (not installed, not API).
#include "mesh.h"
#include "mesh_io_types.h"
#include "mesh_texture.h"

#include <string>

namespace fieldcvt::io_detail {

// Readers, one per format. `path` is only used in messages (and by vcglib to open the file).
//! With `texture`, also keeps the `vt` corners, materials and `mtllib` names (dropped with a warning when broken).
TriMesh readObj(const std::string& path, const std::string& text, MeshReadInfo& info, MeshTexture* texture);
TriMesh readOff(const std::string& path, const std::string& text, MeshReadInfo& info);
//! Also fills `attributes` (normals, rosy) from the vertex properties the file has, and with
//! `texture` MeshLab's face `texcoord` lists, `texnumber` and `TextureFile` comments.
TriMesh readPly(const std::string& path, const std::string& bytes, MeshReadInfo& info, VertexAttributes& attributes,
                MeshTexture* texture);
TriMesh readStl(const std::string& path, const std::string& bytes, MeshReadInfo& info);

// Writers, one per format; they never see an attribute vector of the wrong size.
// A non-empty `texture` fits `mesh` (checked by writeMesh).
void writePly(const std::string& path, const TriMesh& mesh, const VertexAttributes& attributes, const MeshTexture& texture);
void writeObj(const std::string& path, const TriMesh& mesh, const VertexAttributes& attributes, const MeshTexture& texture);
void writeOff(const std::string& path, const TriMesh& mesh);
void writeStl(const std::string& path, const TriMesh& mesh);

}  // namespace fieldcvt::io_detail
