#pragma once
// Internals of fcvt_io shared by the per-format readers and writers (not installed, not API).
#include "mesh.h"
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
//! Writes `bytes` to `path` (replacing it); throws IOError on any failure.
void writeFileBytes(const std::string& path, const std::string& bytes);

// Readers, one per format. `path` is only used in messages (and by vcglib to open the file).
TriMesh readObj(const std::string& path, const std::string& text, MeshReadInfo& info);
TriMesh readOff(const std::string& path, const std::string& text, MeshReadInfo& info);
//! Also fills `attributes` (normals, rosy) from the vertex properties the file has.
TriMesh readPly(const std::string& path, const std::string& bytes, MeshReadInfo& info, VertexAttributes& attributes);
TriMesh readStl(const std::string& path, const std::string& bytes, MeshReadInfo& info);

// Writers, one per format; they never see an attribute vector of the wrong size.
void writePly(const std::string& path, const TriMesh& mesh, const VertexAttributes& attributes);
void writeObj(const std::string& path, const TriMesh& mesh, const VertexAttributes& attributes);
void writeOff(const std::string& path, const TriMesh& mesh);
void writeStl(const std::string& path, const TriMesh& mesh);

}  // namespace fieldcvt::io_detail
