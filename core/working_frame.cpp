#include "working_frame.h"

#include "errors.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fieldcvt {

namespace {

std::string boxText(const Vec3& lo, const Vec3& hi)
{
    std::ostringstream s;
    s << "bounding box (" << lo.x() << ", " << lo.y() << ", " << lo.z() << ") to (" << hi.x() << ", " << hi.y() << ", " << hi.z()
      << ")";
    return s.str();
}

}  // namespace

Normalisation workingFrame(const TriMesh& surface, double cells)
{
    if (surface.vertices.empty()) throw InvalidInputError("the surface has no vertices");
    Vec3 lo = surface.vertices[0], hi = surface.vertices[0];
    for (const Vec3& p : surface.vertices) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    Normalisation frame;
    frame.centre = 0.5 * lo + 0.5 * hi;  // 0.5 (lo + hi), which overflows near the double range
    // Coordinates scaled by 2^-k to at most 1 in magnitude: the area (and so the scale) is a
    // finite double even where the model's own area is not (coordinates beyond ~1e154).
    int k = 0;
    const double largest = std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
    if (largest > 0) std::frexp(largest, &k);
    TriMesh scaled;
    scaled.faces = surface.faces;
    scaled.vertices.reserve(surface.vertices.size());
    for (const Vec3& p : surface.vertices)
        scaled.vertices.emplace_back(std::ldexp(p.x(), -k), std::ldexp(p.y(), -k), std::ldexp(p.z(), -k));
    const double area = surfaceArea(scaled);  // the model's area times 4^-k
    if (!(area > 0)) throw InvalidInputError("the surface has no area (" + boxText(lo, hi) + ")");
    frame.scale = std::ldexp(std::sqrt(cells / area), -k);
    bool finite = std::isfinite(frame.scale) && frame.scale > 0;
    for (std::size_t v = 0; finite && v < surface.vertices.size(); ++v) finite = frame.toWork(surface.vertices[v]).allFinite();
    if (!finite)
        throw InvalidInputError("the surface cannot be scaled to unit cells in double precision (" + boxText(lo, hi) +
                                "): its size is out of range for its distance from the origin");
    return frame;
}

TriMesh inFrame(const TriMesh& mesh, const Normalisation& frame)
{
    TriMesh work = mesh;
    for (Vec3& p : work.vertices) p = frame.toWork(p);
    return work;
}

}  // namespace fieldcvt
