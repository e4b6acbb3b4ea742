#pragma once
// The types that readMesh and writeMesh (mesh_io.h) share with the per-format readers and writers:
// what a reader noticed and did, and the per-vertex data beside the geometry.
#include "mesh.h"

#include <string>
#include <vector>

namespace fieldcvt {

//! What the reader noticed and did (reported by the CLI, never silent).
struct MeshReadInfo {
    int polygonsTriangulated = 0;       //!< faces with more than 3 corners split into triangles
    int polygonsNotSimple = 0;          //!< of the faces, those whose edges cross or touch (triangulate.h)
    std::vector<std::string> notes;     //!< information: the mesh is what the file says
    std::vector<std::string> warnings;  //!< the mesh read differs from what the file says
};

//! Optional per-vertex data next to the geometry (PLY writes all, others what they can; only
//! PLY files are read back with them).
struct VertexAttributes {
    std::vector<Vec3> normals;  //!< "nx ny nz"
    std::vector<Vec3> rosy;     //!< "rosy_x rosy_y rosy_z" (PLY only): the 6-RoSy field's representative
    //! Reading: the name of a scalar PLY face property to read into faceValues (empty: none);
    //! writing (PLY): the name faceValues is written under ("quality" when empty).
    std::string faceProperty;
    //! One value per triangle (a polygon's value on each of its triangles), e.g. MeshLab's face
    //! quality; written as a float face property when not empty.
    std::vector<double> faceValues;
};

}  // namespace fieldcvt
