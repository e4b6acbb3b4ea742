#pragma once
// Internals of fcvt_io that the per-format readers and writers (formats.h) and the dispatch
// (mesh_io.cpp) share: file bytes in and out, polygons and their texture corners (not installed,
// not API). Defined in io_detail.cpp.
#include "mesh.h"
#include "mesh_io_types.h"
#include "mesh_texture.h"

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

}  // namespace fieldcvt::io_detail
