#pragma once
// Mesh files <-> fieldcvt::TriMesh, through vcglib's wrap/io_trimesh (PLY, OFF, STL) and a tolerant
// OBJ reader. Kept out of core/ so the engine has no vcglib dependency.
#include "mesh.h"

#include <string>
#include <vector>

namespace fieldcvt {

//! What the reader noticed and did (reported by the CLI, never silent).
struct MeshReadInfo {
    int polygonsTriangulated = 0;  //!< faces with more than 3 corners split into triangles
    std::vector<std::string> notes;
};

//! Optional per-vertex data written next to the geometry (PLY writes all, others what they can).
struct VertexAttributes {
    std::vector<Vec3> normals;  //!< "nx ny nz"
    std::vector<Vec3> rosy;     //!< "rosy_x rosy_y rosy_z" (PLY only)
};

//! Reads PLY/OBJ/OFF/STL by extension (case-insensitive). Throws IOError with one clear line
//! for a missing, unreadable, truncated or malformed file, or one with no triangles.
TriMesh readMesh(const std::string& path, MeshReadInfo* info = nullptr);

//! Writes by extension (PLY binary, OBJ, OFF, STL). Throws IOError on failure.
void writeMesh(const std::string& path, const TriMesh& mesh, const VertexAttributes* attributes = nullptr);

}  // namespace fieldcvt
