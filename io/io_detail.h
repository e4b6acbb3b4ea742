#pragma once
// Internals of fcvt_io shared by the per-format readers and writers (not installed, not API).
#include "mesh.h"
#include "mesh_texture.h"
#include "mesh_io.h"

#include <string>
#include <vector>

namespace fieldcvt::io_detail {

//! Throws IOError("<path>: <what>"): every I/O message names its file, on one line.
[[noreturn]] void fail(const std::string& path, const std::string& what);

//! The whole file as bytes; throws IOError if it cannot be read.
std::string readFileBytes(const std::string& path);
//! Adds a face with corners `polygon` (indices of `mesh`'s vertices, read before it): a
//! triangle as it is, a polygon triangulated without zero-area triangles (triangulate.h) and
//! counted in `info`.
void addPolygon(TriMesh& mesh, const std::vector<int>& polygon, MeshReadInfo& info);
//! Appends the coordinates of the faces from `firstFace` on, made from `polygon` (whose corners
//! have coordinates `polygonUv`; empty: none, NaN is stored and the texture dropped later), and their material.
void appendCornerTexture(const TriMesh& mesh, std::size_t firstFace, const std::vector<int>& polygon,
                         const std::vector<Vec2>& polygonUv, int material, MeshTexture& texture);
//! Whether a write of `path` goes to a temporary file renamed over it (a regular file, a link or
//! nothing there) rather than into it (a device or a FIFO, e.g. /dev/null).
bool replacedOnWrite(const std::string& path);
//! Writes `bytes` to `path` (replacing it, see replacedOnWrite); throws IOError on any failure.
void writeFileBytes(const std::string& path, const std::string& bytes);

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
