#include "boundary.h"

#include "mesh_edges.h"

#include <algorithm>
#include <limits>

namespace fieldcvt {

std::vector<Segment> boundarySegments(const TriMesh& mesh)
{
    const EdgeTable edges = buildEdgeTable(mesh);
    std::vector<Segment> segments;
    for (int e = 0; e < edges.edgeCount(); ++e)
        if (edges.isBorder(e)) segments.push_back({mesh.vertices[edges.ends[e][0]], mesh.vertices[edges.ends[e][1]]});
    return segments;
}

Vec3 closestPointOnSegment(const Vec3& p, const Segment& segment, double* squaredDistance)
{
    const auto& [a, b] = segment;
    const Vec3 ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    const Vec3 q = a + t * ab;
    if (squaredDistance) *squaredDistance = (q - p).squaredNorm();
    return q;
}

Vec3 closestPointOnSegments(const Vec3& p, const std::vector<Segment>& segments)
{
    Vec3 best = p;
    double bestDist2 = std::numeric_limits<double>::infinity();
    for (const Segment& s : segments) {
        double d2 = 0;
        const Vec3 q = closestPointOnSegment(p, s, &d2);
        if (d2 < bestDist2) bestDist2 = d2, best = q;
    }
    return best;
}

}  // namespace fieldcvt
