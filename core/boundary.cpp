#include "boundary.h"

#include "mesh_edges.h"

#include <algorithm>
#include <limits>
#include <map>

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

// Through the edge table (a counting sort), not a hash map of directed edges: this runs on whole
// inputs (hole closing), millions of faces.
std::vector<std::pair<int, int>> borderHalfEdges(const std::vector<Face>& faces)
{
    int vertexCount = 0;
    for (const Face& f : faces) vertexCount = std::max({vertexCount, f[0] + 1, f[1] + 1, f[2] + 1});
    const EdgeTable edges = buildEdgeTable(faces, vertexCount);
    std::vector<std::pair<int, int>> out;
    for (int h = 0; h < 3 * static_cast<int>(faces.size()); ++h) {
        const int a = halfEdgeOrigin(faces, h), b = faces[size_t(h / 3)][size_t((h % 3 + 1) % 3)];
        const int e = edges.halfEdgeEdge[size_t(h)];
        if (a == b || edges.faceCount(e) != 1) continue;  // one half-edge on the edge: h itself
        out.push_back({a, b});
    }
    return out;
}

std::vector<std::vector<int>> borderLoops(const TriMesh& mesh)
{
    std::map<int, std::vector<int>> outgoing;  // ordered: the loops in a fixed order
    for (const auto& [a, b] : borderHalfEdges(mesh.faces)) outgoing[a].push_back(b);
    std::vector<std::vector<int>> loops;
    for (auto& [first, ends] : outgoing)
        while (!ends.empty()) {
            std::vector<int> loop{first};
            int at = first;
            while (true) {
                auto& next = outgoing[at];
                if (next.empty()) break;
                const int b = next.front();
                next.erase(next.begin());
                if (b == first) break;
                loop.push_back(b);
                at = b;
            }
            loops.push_back(std::move(loop));
        }
    return loops;
}

}  // namespace fieldcvt
