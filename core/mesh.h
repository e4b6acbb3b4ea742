#pragma once
// The indexed triangle mesh every core stage reads and writes (double precision; the MeshLab
// adapter converts from CMeshO's float). Validation and repair live in mesh_check.h.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products on Vec3 everywhere
#include <array>
#include <vector>

namespace fieldcvt {

using Vec3 = Eigen::Vector3d;

//! π, for the angles the stages measure and bound (C++17 has no std::numbers::pi).
constexpr double kPi = 3.14159265358979323846;
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
//! (b − a) × (c − a) on the edges scaled by 2^−k (exact), with k from the longest edge
//! component, so it neither overflows nor underflows at any scale: the true product is the
//! result times 2^(2k) (`exponent` = 2k). Exactly zero iff the plain product is, where that one
//! does not underflow.
Vec3 scaledCross(const Vec3& a, const Vec3& b, const Vec3& c, int& exponent);
//! Area of the triangle through scaledCross: finite wherever the area is a finite double, and
//! bit for bit 0.5 |(b − a) × (c − a)| where that does not overflow or underflow.
double triangleArea(const Vec3& a, const Vec3& b, const Vec3& c);
//! Total surface area (triangleArea per face: right at any scale, e.g. coordinates ~1e100).
double surfaceArea(const TriMesh& mesh);
//! Length of the bounding-box diagonal.
double boundingBoxDiagonal(const TriMesh& mesh);

}  // namespace fieldcvt
