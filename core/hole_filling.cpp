#include "hole_filling.h"

#include "boundary.h"
#include "disjoint_sets.h"
#include "triangulate.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_set>
#include <vector>

namespace fieldcvt {

namespace {

std::uint64_t edgeKey(int a, int b)
{
    if (a > b) std::swap(a, b);
    return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
}

double boxDiagonal(const std::vector<Vec3>& points, const std::vector<int>& indices)
{
    Vec3 lo = points[size_t(indices[0])], hi = lo;
    for (int v : indices) {
        lo = lo.cwiseMin(points[size_t(v)]);
        hi = hi.cwiseMax(points[size_t(v)]);
    }
    return (hi - lo).norm();
}

//! Per vertex, the first vertex of its piece (edge-connected faces).
std::vector<int> pieceRoots(const TriMesh& mesh)
{
    DisjointSets pieces(mesh.vertexCount());
    for (const Face& f : mesh.faces) pieces.unite(f[0], f[1]), pieces.unite(f[0], f[2]);
    std::vector<int> root(mesh.vertices.size());
    for (int v = 0; v < mesh.vertexCount(); ++v) root[size_t(v)] = pieces.find(v);
    return root;
}

//! Per vertex, the bounding-box diagonal of its piece (edge-connected faces; 0 on no face).
std::vector<double> pieceExtents(const TriMesh& mesh)
{
    const std::vector<int> root = pieceRoots(mesh);
    std::vector<Vec3> lo(mesh.vertices.size(), Vec3::Constant(1e300)), hi(mesh.vertices.size(), Vec3::Constant(-1e300));
    for (const Face& f : mesh.faces)
        for (int v : f) {
            const size_t r = size_t(root[size_t(v)]);
            lo[r] = lo[r].cwiseMin(mesh.vertices[size_t(v)]);
            hi[r] = hi[r].cwiseMax(mesh.vertices[size_t(v)]);
        }
    std::vector<double> extent(mesh.vertices.size(), 0.0);
    for (int v = 0; v < mesh.vertexCount(); ++v) {
        const size_t r = size_t(root[size_t(v)]);
        if (hi[r].x() >= lo[r].x()) extent[size_t(v)] = (hi[r] - lo[r]).norm();
    }
    return extent;
}

}  // namespace

HoleFillReport closeSmallHoles(TriMesh& mesh, double maxAcross)
{
    HoleFillReport report;
    if (!(maxAcross > 0) || mesh.faces.empty()) return report;
    const std::vector<std::vector<int>> loops = borderLoops(mesh);
    if (loops.empty()) return report;
    const std::vector<double> pieceExtent = pieceExtents(mesh);
    // The mesh's edges, gathered when a first loop is small enough to close (most inputs have none).
    std::unordered_set<std::uint64_t> edges;
    bool edgesGathered = false;

    std::vector<Face> patch;
    for (const std::vector<int>& loop : loops) {
        if (loop.size() < 3) continue;
        // Across: the diameter of a round hole with the loop's bounding box (its diagonal / sqrt 2).
        const double extent = boxDiagonal(mesh.vertices, loop);
        if (extent / std::sqrt(2.0) >= maxAcross || pieceExtent[size_t(loop[0])] <= 2 * extent) continue;
        if (!edgesGathered) {
            for (const Face& f : mesh.faces)
                for (int k = 0; k < 3; ++k) edges.insert(edgeKey(f[size_t(k)], f[size_t((k + 1) % 3)]));
            edgesGathered = true;
        }
        std::vector<int> sorted = loop;
        std::sort(sorted.begin(), sorted.end());
        // The loop runs with the surface on its left; the hole's triangles run the other way.
        const std::vector<int> corners(loop.rbegin(), loop.rend());
        patch.clear();
        bool closable = std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end() &&
                        triangulatePolygon(mesh.vertices, corners, patch) == PolygonShape::Simple;
        // Only the loop's own edges may exist already; a chord the mesh has would be a third face's.
        std::unordered_set<std::uint64_t> loopEdges;
        for (size_t i = 0; i < corners.size(); ++i) loopEdges.insert(edgeKey(corners[i], corners[(i + 1) % corners.size()]));
        for (const Face& f : patch)
            for (int k = 0; k < 3 && closable; ++k) {
                const std::uint64_t key = edgeKey(f[size_t(k)], f[size_t((k + 1) % 3)]);
                closable = loopEdges.count(key) > 0 || edges.count(key) == 0;
            }
        if (!closable) {
            ++report.leftOpen;
            continue;
        }
        for (const Face& f : patch) {
            for (int k = 0; k < 3; ++k) edges.insert(edgeKey(f[size_t(k)], f[size_t((k + 1) % 3)]));
            report.area += triangleArea(mesh.vertices[size_t(f[0])], mesh.vertices[size_t(f[1])], mesh.vertices[size_t(f[2])]);
            mesh.faces.push_back(f);
        }
        ++report.closed;
    }
    return report;
}

}  // namespace fieldcvt
