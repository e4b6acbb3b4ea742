#include "boundary.h"

#include <algorithm>
#include <limits>

namespace fieldcvt {

std::vector<Segment> boundarySegments(const TriMesh& mesh)
{
    std::vector<std::pair<int, int>> edges;
    edges.reserve(mesh.faces.size() * 3);
    for (const Face& t : mesh.faces)
        for (int k = 0; k < 3; ++k) edges.push_back(std::minmax(t[k], t[(k + 1) % 3]));
    std::sort(edges.begin(), edges.end());
    std::vector<Segment> segments;
    for (size_t r = 0; r < edges.size();) {
        size_t e = r;
        while (e < edges.size() && edges[e] == edges[r]) ++e;
        if (e - r == 1) segments.push_back({mesh.vertices[edges[r].first], mesh.vertices[edges[r].second]});
        r = e;
    }
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
