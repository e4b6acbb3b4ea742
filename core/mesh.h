#pragma once
// The indexed triangle mesh every core stage reads and writes (double precision; the MeshLab
// adapter converts from CMeshO's float). Validation and repair live in mesh_check.h.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products on Vec3 everywhere
#include <array>
#include <vector>

namespace fieldcvt {

using Vec3 = Eigen::Vector3d;
using Face = std::array<int, 3>;

struct TriMesh {
    std::vector<Vec3> vertices;
    std::vector<Face> faces;  //!< counter-clockwise seen from outside

    int vertexCount() const { return static_cast<int>(vertices.size()); }
    int faceCount() const { return static_cast<int>(faces.size()); }
};

//! Area of face f.
double faceArea(const TriMesh& mesh, int f);
//! Unnormalised face normal (length = 2 * area).
Vec3 faceNormal(const TriMesh& mesh, int f);
//! Total surface area.
double surfaceArea(const TriMesh& mesh);
//! Length of the bounding-box diagonal.
double boundingBoxDiagonal(const TriMesh& mesh);

}  // namespace fieldcvt
