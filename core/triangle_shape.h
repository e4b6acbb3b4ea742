#pragma once
// Shape measures of one triangle, shared by the stages that judge the triangles they make.
#include "mesh.h"

#include <algorithm>
#include <cmath>

namespace fieldcvt {

//! Mean ratio 4√3 A / (l0² + l1² + l2²): 1 for an equilateral triangle, 0 for a degenerate one.
inline double meanRatio(const Vec3& a, const Vec3& b, const Vec3& c)
{
    const double sum = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
    if (!(sum > 0)) return 0;
    return 2 * std::sqrt(3.0) * (b - a).cross(c - a).norm() / sum;
}

//! The smallest angle of triangle (p0, p1, p2) in radians, atan2(|u × w|, u · w) at each corner
//! (as computeQuality measures it).
inline double smallestAngle(const Vec3& p0, const Vec3& p1, const Vec3& p2)
{
    const Vec3 p[3] = {p0, p1, p2};
    double smallest = kPi;
    for (int k = 0; k < 3; ++k) {
        const Vec3 u = p[(k + 1) % 3] - p[k], w = p[(k + 2) % 3] - p[k];
        smallest = std::min(smallest, std::atan2(u.cross(w).norm(), u.dot(w)));
    }
    return smallest;
}

}  // namespace fieldcvt
