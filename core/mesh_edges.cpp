#include "mesh_edges.h"

#include "disjoint_sets.h"
#include "errors.h"

#include <algorithm>
#include <cstdint>
#include <string>

namespace fieldcvt {

int EdgeTable::find(int a, int b) const
{
    const std::array<int, 2> key{std::min(a, b), std::max(a, b)};
    const auto it = std::lower_bound(ends.begin(), ends.end(), key);
    return it != ends.end() && *it == key ? static_cast<int>(it - ends.begin()) : -1;
}

bool EdgeTable::firstTwoSameDirection(const std::vector<Face>& faces, int e) const
{
    return faceCount(e) >= 2 && halfEdgeOrigin(faces, halfEdge(e, 0)) == halfEdgeOrigin(faces, halfEdge(e, 1));
}

int EdgeTable::firstHalfEdgeFrom(const std::vector<Face>& faces, int e, int origin) const
{
    for (int i = 0; i < faceCount(e); ++i)
        if (halfEdgeOrigin(faces, halfEdge(e, i)) == origin) return halfEdge(e, i);
    return -1;
}

namespace {

//! Half-edges from which the buckets are sorted and filled on threads (the counting pass stays
//! serial; docs/tuning.md, "kMinEntriesForThreads").
constexpr size_t kMinEntriesForThreads = 200000;

}  // namespace

EdgeTable buildEdgeTable(const std::vector<Face>& faces, int vertexCount, RepeatedVertexFaces repeated)
{
    const int faceCount = static_cast<int>(faces.size());
    auto used = [&](const Face& t) {
        return repeated == RepeatedVertexFaces::Keep || (t[0] != t[1] && t[1] != t[2] && t[2] != t[0]);
    };
    // Counting sort of the half-edges by their smaller vertex (in half-edge order within a
    // bucket), then each bucket sorted by (larger vertex, half-edge): edges come out in
    // (smaller, larger) order and their half-edges in increasing order, without a global sort.
    std::vector<int> bucketStart(static_cast<size_t>(vertexCount) + 1, 0);
    for (int f = 0; f < faceCount; ++f) {
        const Face& t = faces[f];
        for (int v : t)
            if (v < 0 || v >= vertexCount)
                throw InvalidInputError("edge table: face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                                        ", the mesh has " + std::to_string(vertexCount) + " vertices");
        if (!used(t)) continue;
        for (int k = 0; k < 3; ++k) ++bucketStart[std::min(t[k], t[(k + 1) % 3]) + 1];
    }
    for (int v = 0; v < vertexCount; ++v) bucketStart[v + 1] += bucketStart[v];
    // Entry = (larger vertex << 32) | half-edge: sorting the integers sorts by both.
    std::vector<std::uint64_t> entries(bucketStart[vertexCount]);
    {
        std::vector<int> fill(bucketStart.begin(), bucketStart.end() - 1);
        for (int f = 0; f < faceCount; ++f) {
            const Face& t = faces[f];
            if (!used(t)) continue;
            for (int k = 0; k < 3; ++k) {
                const int a = t[k], b = t[(k + 1) % 3];
                entries[fill[std::min(a, b)]++] =
                    (static_cast<std::uint64_t>(std::max(a, b)) << 32) | static_cast<std::uint32_t>(3 * f + k);
            }
        }
    }

    // Per bucket (smaller vertex): sorted, then its edges counted; the edges' numbers are the
    // prefix sums of the counts, so the buckets fill their parts of the table independently.
    // Threads over buckets only on big meshes; the table is the same on any thread count.
    EdgeTable table;
    table.halfEdgeEdge.assign(3 * static_cast<size_t>(faceCount), -1);
    table.halfEdges.resize(entries.size());
    std::vector<int> edgeStart(static_cast<size_t>(vertexCount) + 1, 0);
    const bool threads = entries.size() >= kMinEntriesForThreads;
#pragma omp parallel for schedule(dynamic, 4096) if (threads)
    for (int lo = 0; lo < vertexCount; ++lo) {
        const auto begin = entries.begin() + bucketStart[lo], end = entries.begin() + bucketStart[lo + 1];
        std::sort(begin, end);
        int edges = 0;
        for (auto it = begin; it != end; ++it) edges += it == begin || (*(it - 1) >> 32) != (*it >> 32);
        edgeStart[lo + 1] = edges;
    }
    for (int v = 0; v < vertexCount; ++v) edgeStart[v + 1] += edgeStart[v];
    table.ends.resize(edgeStart[vertexCount]);
    table.first.resize(edgeStart[vertexCount] + size_t(1));
#pragma omp parallel for schedule(dynamic, 4096) if (threads)
    for (int lo = 0; lo < vertexCount; ++lo) {
        const auto begin = entries.begin() + bucketStart[lo], end = entries.begin() + bucketStart[lo + 1];
        int edge = edgeStart[lo] - 1;
        for (auto it = begin; it != end; ++it) {
            const int hi = static_cast<int>(*it >> 32), h = static_cast<int>(*it & 0xffffffffu);
            if (it == begin || (*(it - 1) >> 32) != (*it >> 32)) {
                ++edge;
                table.first[edge] = static_cast<int>(it - entries.begin());
                table.ends[edge] = {lo, hi};
            }
            table.halfEdges[it - entries.begin()] = h;
            table.halfEdgeEdge[h] = edge;
        }
    }
    table.first.back() = static_cast<int>(entries.size());
    return table;
}

std::vector<int> faceComponents(const EdgeTable& edges, int faceCount, int& count)
{
    DisjointSets sets(faceCount);
    for (int e = 0; e < edges.edgeCount(); ++e)
        for (int i = 1; i < edges.faceCount(e); ++i) sets.unite(edges.face(e, 0), edges.face(e, i));
    std::vector<int> label(faceCount, -1), component(faceCount);
    count = 0;
    for (int f = 0; f < faceCount; ++f) {
        const int root = sets.find(f);
        if (label[root] < 0) label[root] = count++;
        component[f] = label[root];
    }
    return component;
}

}  // namespace fieldcvt
