#include "mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace fieldcvt {

Vec3 faceNormal(const TriMesh& mesh, int f)
{
    const Face& t = mesh.faces[f];
    const Vec3& a = mesh.vertices[t[0]];
    return (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
}

double faceArea(const TriMesh& mesh, int f) { return 0.5 * faceNormal(mesh, f).norm(); }

Vec3 scaledCross(const Vec3& a, const Vec3& b, const Vec3& c, int& exponent)
{
    const Vec3 e1 = b - a, e2 = c - a;
    const double longest = std::max(e1.cwiseAbs().maxCoeff(), e2.cwiseAbs().maxCoeff());
    int k = 0;
    if (longest > 0 && std::isfinite(longest)) std::frexp(longest, &k);
    exponent = 2 * k;
    // ldexp per coordinate, not a multiplication by 2^-k, which overflows for subnormal edges.
    const auto scaled = [k](const Vec3& e) { return Vec3(std::ldexp(e.x(), -k), std::ldexp(e.y(), -k), std::ldexp(e.z(), -k)); };
    return scaled(e1).cross(scaled(e2));
}

double triangleArea(const Vec3& a, const Vec3& b, const Vec3& c)
{
    int exponent = 0;
    const Vec3 n = scaledCross(a, b, c, exponent);
    return 0.5 * std::ldexp(n.norm(), exponent);
}

double surfaceArea(const TriMesh& mesh)
{
    double area = 0;
    for (const Face& t : mesh.faces) area += triangleArea(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
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
