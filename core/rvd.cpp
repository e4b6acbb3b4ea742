#include "rvd.h"

#include "errors.h"
#include "morton_order.h"
#include "rvd_impl.h"

#include <Eigen/Geometry>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <mutex>
#include <string>

namespace fieldcvt {

using namespace rvd_detail;

double RvdResult::totalEnergy() const
{
    double e = 0;
    for (double v : energy) e += v;
    return e;
}

namespace {

}  // namespace

std::array<int, 3> canonicalTriangleOf(int a, int b, int c)
{
    if (a < b && a < c) return {a, b, c};
    if (b < a && b < c) return {b, c, a};
    return {c, a, b};
}

namespace {

std::array<int, 3> canonicalTriangle(int a, int b, int c)
{
    // Rotate so the smallest index comes first; the cyclic order (orientation) is kept.
    if (a < b && a < c) return {a, b, c};
    if (b < a && b < c) return {b, c, a};
    return {c, a, b};
}

}  // namespace

RestrictedVoronoiDiagram::Impl::Impl(const TriMesh& s, const std::vector<double>& faceDensity)
{
    if (!faceDensity.empty()) {
        if (faceDensity.size() != s.faces.size())
            throw InvalidInputError("the density has " + std::to_string(faceDensity.size()) + " values for " +
                                    std::to_string(s.faces.size()) + " faces");
        for (double rho : faceDensity)
            if (!std::isfinite(rho) || !(rho > 0)) throw InvalidInputError("the density must be finite and > 0");
    }
    const std::vector<int> vertexOrder = mortonIndexOrder(s.vertices);
    std::vector<int> vertexRank(s.vertices.size());
    position.resize(s.vertices.size());
    for (size_t k = 0; k < vertexOrder.size(); ++k) {
        vertexRank[vertexOrder[k]] = static_cast<int>(k);
        position[k] = s.vertices[vertexOrder[k]];
    }
    std::vector<Vec3> centroids(s.faces.size());
    for (int f = 0; f < s.faceCount(); ++f)
        centroids[f] = (s.vertices[s.faces[f][0]] + s.vertices[s.faces[f][1]] + s.vertices[s.faces[f][2]]) / 3.0;
    const std::vector<int> faceOrder = mortonIndexOrder(centroids);
    faces.resize(s.faces.size());
    unitNormals.resize(s.faces.size());
    for (size_t k = 0; k < faceOrder.size(); ++k) {
        const Face& f = s.faces[faceOrder[k]];
        faces[k] = {vertexRank[f[0]], vertexRank[f[1]], vertexRank[f[2]]};
        const Vec3 n = faceNormal(s, faceOrder[k]);
        const double len = n.norm();
        unitNormals[k] = len > 0 ? Vec3(n / len) : Vec3::Zero();
    }
    if (!faceDensity.empty()) {  // follows the faces into Morton order
        density.resize(faces.size());
        for (size_t k = 0; k < faceOrder.size(); ++k) density[k] = faceDensity[faceOrder[k]];
    }
    chunks.resize((faces.size() + kTrianglesPerChunk - 1) / kTrianglesPerChunk);

    std::vector<std::pair<std::pair<int, int>, int>> edges;  // (sorted corners) -> face * 3 + e
    edges.reserve(faces.size() * 3);
    for (int f = 0; f < static_cast<int>(faces.size()); ++f)
        for (int e = 0; e < 3; ++e) edges.push_back({std::minmax(faces[f][e], faces[f][(e + 1) % 3]), 3 * f + e});
    std::sort(edges.begin(), edges.end());
    borderEdges.assign(faces.size(), 0);
    neighbourFace.assign(3 * faces.size(), -1);
    for (size_t r = 0; r < edges.size();) {
        size_t q = r;
        while (q < edges.size() && edges[q].first == edges[r].first) ++q;
        if (q - r == 1) borderEdges[edges[r].second / 3] |= static_cast<unsigned char>(1u << (edges[r].second % 3));
        if (q - r == 2) {
            neighbourFace[edges[r].second] = edges[r + 1].second / 3;
            neighbourFace[edges[r + 1].second] = edges[r].second / 3;
        }
        r = q;
    }
    for (int f = 0; f < static_cast<int>(faces.size()); ++f)
        if (borderEdges[f]) borderFaceVertices.insert(borderFaceVertices.end(), faces[f].begin(), faces[f].end());
    std::sort(borderFaceVertices.begin(), borderFaceVertices.end());
    borderFaceVertices.erase(std::unique(borderFaceVertices.begin(), borderFaceVertices.end()), borderFaceVertices.end());
}

RestrictedVoronoiDiagram::RestrictedVoronoiDiagram(const TriMesh& surface, std::vector<double> faceDensity)
    : impl_(std::make_unique<Impl>(surface, faceDensity))
{
}
RestrictedVoronoiDiagram::~RestrictedVoronoiDiagram() = default;

void RestrictedVoronoiDiagram::compute(const std::vector<Vec3>& seeds, const RvdOptions& options, RvdResult& result)
{
    if (seeds.empty()) throw InvalidInputError("restricted Voronoi diagram needs at least one seed");
    Impl& m = *impl_;
    m.seeds = &seeds;
    m.seedNormals = options.seedNormals;
    m.minSideCos = options.minSideCos;
    const int fromCandidates = m.buildNeighbourLists();
    m.computeVertexSeeds(options.borderFacesOnly);

    if (options.triangles && !options.edges) {
        // The extraction's diagram needs no RVD edges: the capacity the optimisation's
        // evaluations left for them goes before its fragments and links are made, at the run's
        // peak (docs/tuning.md, "Memory of the diagram").
        for (ChunkOutput& out : m.chunks) std::vector<RvdEdge>().swap(out.edges);
        std::vector<RvdEdge>().swap(m.edgeBuffer);
        std::vector<int>().swap(m.edgeStart);
        std::vector<RvdEdge>().swap(result.edges);
    }
    const int faceCount = static_cast<int>(m.faces.size());
    const int chunkCount = static_cast<int>(m.chunks.size());
    m.scratch.resize(std::max(1, omp_get_max_threads()));
#pragma omp parallel
    {
        Scratch& scratch = m.scratch[omp_get_thread_num()];
#pragma omp for schedule(dynamic, 1)
        for (int c = 0; c < chunkCount; ++c) {
            ChunkOutput& out = m.chunks[c];
            out.clear();
            const int end = std::min(faceCount, (c + 1) * kTrianglesPerChunk);
            for (int k = c * kTrianglesPerChunk; k < end; ++k)
                if (!options.borderFacesOnly || m.borderEdges[k]) m.processTriangle(k, options, out, scratch);
        }
    }

    // Reduction in chunk order: identical sums whatever the thread count.
    const size_t n = seeds.size();
    result.mass.assign(n, 0.0);
    result.moment.assign(n, Vec3::Zero());
    result.energy.assign(n, 0.0);
    result.boundaryLength.assign(options.boundary ? n : 0, 0.0);
    result.boundaryMoment.assign(options.boundary ? n : 0, Vec3::Zero());
    result.edges.clear();
    result.triangles.clear();
    result.clippedPolygons = 0;
    result.listsFromCandidates = fromCandidates;
    for (const ChunkOutput& out : m.chunks) {
        for (const CellPiece& p : out.pieces) {
            result.mass[p.seed] += p.mass;
            result.moment[p.seed] += p.moment;
            result.energy[p.seed] += p.energy;
        }
        if (options.boundary)
            for (const BorderPiece& p : out.borderPieces) {
                result.boundaryLength[p.seed] += p.length;
                result.boundaryMoment[p.seed] += p.moment;
            }
        result.clippedPolygons += out.clipped;
    }
    // The extraction's diagram (once or a few times a run) needs the chunks' fragments, links
    // and triangles next; their pieces, summed, go, at the run's peak (docs/tuning.md, "Memory of
    // the diagram"). Later evaluations allocate them again.
    if (options.triangles)
        for (ChunkOutput& out : m.chunks) std::vector<CellPiece>().swap(out.pieces);
    if (options.edges) {
        // Sum the pieces of each shared edge (an RVD edge crosses several input triangles):
        // bucket the pieces by their first seed (counting sort straight from the chunks, chunk
        // order kept), then merge each seed's few pieces by second seed, then gather the merged
        // buckets in parallel. Linear time and deterministic.
        std::vector<int>& start = m.edgeStart;
        start.assign(n + 1, 0);
        for (const ChunkOutput& out : m.chunks)
            for (const RvdEdge& e : out.edges) ++start[e.i + 1];
        for (size_t i = 0; i < n; ++i) start[i + 1] += start[i];
        std::vector<RvdEdge>& bucketed = m.edgeBuffer;
        bucketed.resize(static_cast<size_t>(start[n]));
        std::vector<int> fill(start.begin(), start.end() - 1);
        for (const ChunkOutput& out : m.chunks)
            for (const RvdEdge& e : out.edges) bucketed[fill[e.i]++] = e;
        std::vector<int> kept(n + 1, 0);
#pragma omp parallel for schedule(static)
        for (long long i = 0; i < static_cast<long long>(n); ++i) {
            RvdEdge* first = bucketed.data() + start[i];
            RvdEdge* last = bucketed.data() + start[i + 1];
            // Pieces with the same second seed summed in chunk order (into the first of them),
            // then the few merged edges sorted by second seed (insertion sort: a seed has a
            // dozen pieces or so, half a dozen edges).
            RvdEdge* w = first;
            for (RvdEdge* r = first; r != last; ++r) {
                RvdEdge* same = first;
                while (same != w && same->j != r->j) ++same;
                if (same != w)
                    same->length += r->length;
                else
                    *w++ = *r;
            }
            for (RvdEdge* r = first; r != w; ++r) {  // (not first + 1: `first` is null when no seed has an edge)
                const RvdEdge moving = *r;
                RvdEdge* to = r;
                for (; to != first && (to - 1)->j > moving.j; --to) *to = *(to - 1);
                *to = moving;
            }
            kept[i + 1] = static_cast<int>(w - first);
        }
        for (size_t i = 0; i < n; ++i) kept[i + 1] += kept[i];  // now where each seed's edges go
        result.edges.resize(static_cast<size_t>(kept[n]));
#pragma omp parallel for schedule(static)
        for (long long i = 0; i < static_cast<long long>(n); ++i)
            std::copy(bucketed.begin() + start[i], bucketed.begin() + start[i] + (kept[i + 1] - kept[i]),
                      result.edges.begin() + kept[i]);
    }
    result.pieceSeed.clear();
    result.piecePoint.clear();
    result.pieceTriangles.clear();
    if (options.triangles) m.buildPieces(result);
}

void RestrictedVoronoiDiagram::Impl::buildPieces(RvdResult& result)
{
    // Global fragment numbering: chunk order, then order within the chunk.
    std::vector<int> chunkStart(chunks.size() + 1, 0);
    for (size_t c = 0; c < chunks.size(); ++c) chunkStart[c + 1] = chunkStart[c] + static_cast<int>(chunks[c].fragments.size());
    const int fragmentCount = chunkStart.back();
    std::vector<Fragment> fragments;
    fragments.reserve(fragmentCount);
    for (ChunkOutput& out : chunks) {  // moved, not copied: one copy of the largest array at a time
        fragments.insert(fragments.end(), out.fragments.begin(), out.fragments.end());
        std::vector<Fragment>().swap(out.fragments);
    }
    // The fragments of one input triangle are consecutive.
    std::vector<int> faceFirst(faces.size(), -1), faceEnd(faces.size(), -1);
    for (int g = 0; g < fragmentCount; ++g) {
        const int f = fragments[g].face;
        if (faceFirst[f] < 0) faceFirst[f] = g;
        faceEnd[f] = g + 1;
    }

    // Union-find of the fragments of one cell across shared input edges.
    std::vector<int> parent(fragmentCount);
    for (int g = 0; g < fragmentCount; ++g) parent[g] = g;
    auto find = [&](int g) {
        while (parent[g] != g) g = parent[g] = parent[parent[g]];
        return g;
    };
    for (size_t c = 0; c < chunks.size(); ++c)
        for (const FragmentLink& link : chunks[c].links) {
            const int g = chunkStart[c] + link.fragment;
            for (int h = faceFirst[link.face]; h >= 0 && h < faceEnd[link.face]; ++h)
                if (fragments[h].seed == fragments[g].seed) {
                    const int a = find(g), b = find(h);
                    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the root is the first fragment
                    break;
                }
        }

    // Pieces sorted by seed, then by first fragment; each at its fragment nearest to the seed.
    const int seedCount = static_cast<int>(seeds->size());
    std::vector<int> pieceOfRoot(fragmentCount, -1);
    std::vector<int> firstOfSeed(seedCount + 1, 0);
    for (int g = 0; g < fragmentCount; ++g)
        if (find(g) == g) ++firstOfSeed[fragments[g].seed + 1];
    for (int s = 0; s < seedCount; ++s) firstOfSeed[s + 1] += firstOfSeed[s];
    const int pieceCount = firstOfSeed.back();
    result.pieceSeed.resize(pieceCount);
    result.piecePoint.resize(pieceCount);
    std::vector<int> fill(firstOfSeed.begin(), firstOfSeed.end() - 1);
    std::vector<double> nearest(pieceCount);
    for (int g = 0; g < fragmentCount; ++g) {
        const int root = find(g);
        if (root == g) {
            const int p = fill[fragments[g].seed]++;
            pieceOfRoot[g] = p;
            result.pieceSeed[p] = fragments[g].seed;
            result.piecePoint[p] = fragments[g].point;
            nearest[p] = fragments[g].distance2;
        } else {
            const int p = pieceOfRoot[root];  // the root comes first, so it is numbered
            if (fragments[g].distance2 < nearest[p])
                result.piecePoint[p] = fragments[g].point, nearest[p] = fragments[g].distance2;
        }
    }

    // RDT triangles on pieces. A corner without a fragment in the triangle of its RVD vertex
    // (the vertex is on the triangle's border) takes its seed's piece in a neighbouring triangle,
    // else the seed's first piece.
    auto pieceNear = [&](int seed, int face) {
        for (int e = 0; e < 3; ++e) {
            const int across = neighbourFace[3 * face + e];
            for (int h = across >= 0 ? faceFirst[across] : -1; h >= 0 && h < faceEnd[across]; ++h)
                if (fragments[h].seed == seed) return pieceOfRoot[find(h)];
        }
        return firstOfSeed[seed];
    };
    for (size_t c = 0; c < chunks.size(); ++c)
        for (const RawTriangle& raw : chunks[c].triangles) {
            std::array<int, 3> t;
            for (int k = 0; k < 3; ++k)
                t[k] = raw.corner[k] >= 0 ? pieceOfRoot[find(chunkStart[c] + raw.corner[k])]
                                          : pieceNear(-1 - raw.corner[k], raw.face);
            result.pieceTriangles.push_back(canonicalTriangle(t[0], t[1], t[2]));
        }
    if (seedNormals)
        addSeamTriangles(
            chunkStart, fragments, [&](int g) { return pieceOfRoot[find(g)]; }, result);
    for (ChunkOutput& out : chunks) {  // used: their memory back before the sorts below allocate
        std::vector<FragmentLink>().swap(out.links);
        std::vector<LinkSpan>().swap(out.linkSpans);
        std::vector<RawTriangle>().swap(out.triangles);
    }
    std::sort(result.pieceTriangles.begin(), result.pieceTriangles.end());
    result.pieceTriangles.erase(std::unique(result.pieceTriangles.begin(), result.pieceTriangles.end()),
                                result.pieceTriangles.end());
    for (const std::array<int, 3>& t : result.pieceTriangles)
        result.triangles.push_back(canonicalTriangle(result.pieceSeed[t[0]], result.pieceSeed[t[1]], result.pieceSeed[t[2]]));
    std::sort(result.triangles.begin(), result.triangles.end());
    result.triangles.erase(std::unique(result.triangles.begin(), result.triangles.end()), result.triangles.end());
}

}  // namespace fieldcvt

namespace fieldcvt {

void RestrictedVoronoiDiagram::Impl::addSeamTriangles(const std::vector<int>& chunkStart, const std::vector<Fragment>& fragments,
                                                      const std::function<int(int)>& pieceOf, RvdResult& result) const
{
    // Side-aware cells are not continuous across an input edge between faces whose seeds
    // differ (a plate's crease): the cells on either side meet along the edge without a
    // bisector, so no RVD vertex joins them. Each change of cell along such an edge, on
    // either side, is such a junction: zip the two sides' sequences of cells into triangles.
    struct Span {
        int face, edge;
        double from, to;
        int fragment;  // global
    };
    std::vector<Span> spans;
    for (size_t c = 0; c < chunks.size(); ++c)
        for (size_t k = 0; k < chunks[c].links.size(); ++k) {
            const int g = chunkStart[c] + chunks[c].links[k].fragment;
            const LinkSpan& span = chunks[c].linkSpans[k];
            spans.push_back({fragments[g].face, span.edge, std::min(span.from, span.to), std::max(span.from, span.to), g});
        }
    std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) {
        if (a.face != b.face) return a.face < b.face;
        if (a.edge != b.edge) return a.edge < b.edge;
        return a.from < b.from;
    });
    // Index: (face, edge) -> first span.
    std::vector<int> first(3 * faces.size() + 1, -1);
    for (int k = static_cast<int>(spans.size()) - 1; k >= 0; --k) first[3 * spans[k].face + spans[k].edge] = k;
    auto range = [&](int face, int edge, int& begin, int& end) {
        begin = first[3 * face + edge];
        end = begin;
        while (end >= 0 && end < static_cast<int>(spans.size()) && spans[end].face == face && spans[end].edge == edge) ++end;
    };
    std::vector<std::pair<double, int>> sideB;
    for (int t = 0; t < static_cast<int>(faces.size()); ++t)
        for (int e = 0; e < 3; ++e) {
            const int u = neighbourFace[3 * t + e];
            if (u < t) continue;  // each shared edge once (u < 0: a border)
            int eu = -1;
            for (int k = 0; k < 3; ++k)
                if (neighbourFace[3 * u + k] == t) eu = k;
            if (eu < 0) continue;
            int a0, a1, b0, b1;
            range(t, e, a0, a1);
            range(u, eu, b0, b1);
            if (a0 < 0 || b0 < 0) continue;
            // Side B along t's direction (u runs the edge the other way).
            sideB.clear();
            for (int k = b1 - 1; k >= b0; --k) sideB.push_back({1.0 - spans[k].from, spans[k].fragment});
            bool same = a1 - a0 == static_cast<int>(sideB.size());
            for (int k = 0; same && k < a1 - a0; ++k)
                same = fragments[spans[a0 + k].fragment].seed == fragments[sideB[k].second].seed;
            if (same) continue;
            int ia = a0, ib = 0;
            const int nb = static_cast<int>(sideB.size());
            auto emit = [&](int p, int q, int r) {
                const int sp = fragments[p].seed, sq = fragments[q].seed, sr = fragments[r].seed;
                if (sp == sq || sq == sr || sp == sr) return;
                const int x = pieceOf(p), y = pieceOf(q), z = pieceOf(r);
                result.pieceTriangles.push_back(canonicalTriangleOf(x, y, z));
            };
            while (ia + 1 < a1 || ib + 1 < nb) {
                const double breakA = ia + 1 < a1 ? spans[ia].to : 2.0;
                const double breakB = ib + 1 < nb ? sideB[ib].first : 2.0;  // B's span ib ends where it started, reversed
                if (breakA <= breakB) {
                    emit(spans[ia + 1].fragment, spans[ia].fragment, sideB[ib].second);
                    ++ia;
                } else {
                    emit(spans[ia].fragment, sideB[ib].second, sideB[ib + 1].second);
                    ++ib;
                }
            }
        }
}

void RestrictedVoronoiDiagram::releaseWorkspace()
{
    for (ChunkOutput& chunk : impl_->chunks) chunk = ChunkOutput{};
    std::vector<Scratch>().swap(impl_->scratch);
    std::vector<RvdEdge>().swap(impl_->edgeBuffer);
    std::vector<int>().swap(impl_->edgeStart);
}

}  // namespace fieldcvt
