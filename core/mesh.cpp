#include "mesh.h"

#include <Eigen/Geometry>
#include <limits>

namespace fieldcvt {

Vec3 faceNormal(const TriMesh& mesh, int f)
{
    const Face& t = mesh.faces[f];
    const Vec3& a = mesh.vertices[t[0]];
    return (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
}

double faceArea(const TriMesh& mesh, int f) { return 0.5 * faceNormal(mesh, f).norm(); }

double surfaceArea(const TriMesh& mesh)
{
    double area = 0;
    for (int f = 0; f < mesh.faceCount(); ++f) area += faceArea(mesh, f);
    return area;
}

double boundingBoxDiagonal(const TriMesh& mesh)
{
    if (mesh.vertices.empty()) return 0;
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max());
    Vec3 hi = -lo;
    for (const Vec3& p : mesh.vertices) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    return (hi - lo).norm();
}

}  // namespace fieldcvt
