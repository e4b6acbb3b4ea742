// The restricted Voronoi diagram, part 3 of 3: each input triangle clipped to the cells it meets
// and integrated over them (rvd_impl.h).
#include "closest_point.h"
#include "errors.h"
#include "rvd_impl.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace fieldcvt {

using namespace rvd_detail;

inline int RestrictedVoronoiDiagram::Impl::clipByBisector(const Polygon& in, Polygon& out, const Vec3& xi, const Vec3& xj, int j,
                                                          double& radius2)
{
    const Vec3 d = xj - xi;
    const double half = 0.5 * d.squaredNorm();
    double side[kMaxPolygonVertices];
    bool anyOutside = false, anyInside = false;
    const int size = in.size;
    for (int k = 0; k < size; ++k) {
        side[k] = (in.point[k] - xi).dot(d) - half;  // > 0: nearer to x_j
        if (side[k] > 0)
            anyOutside = true;
        else
            anyInside = true;
    }
    if (!anyOutside) return 0;
    if (!anyInside) return 2;
    int count = 0;
    double r2 = 0;
    for (int k = 0; k < size; ++k) {
        const int next = k + 1 == size ? 0 : k + 1;
        const bool inside = side[k] <= 0, nextInside = side[next] <= 0;
        if (inside) {
            out.point[count] = in.point[k];
            out.label[count] = in.label[k];
            r2 = std::max(r2, (out.point[count] - xi).squaredNorm());
            ++count;
        }
        if (inside != nextInside) {
            if (count + 1 >= kMaxPolygonVertices) throw Error("restricted Voronoi cell has too many vertices");
            const double t = side[k] / (side[k] - side[next]);
            out.point[count] = in.point[k] + t * (in.point[next] - in.point[k]);
            // Leaving the half-space: the new edge runs along the bisector of (i, j).
            out.label[count] = inside ? j : in.label[k];
            r2 = std::max(r2, (out.point[count] - xi).squaredNorm());
            ++count;
        }
    }
    out.size = count;
    radius2 = r2;
    return 1;
}

inline double RestrictedVoronoiDiagram::Impl::maxSquaredDistance(const Polygon& poly, const Vec3& x)
{
    double r2 = 0;
    for (int k = 0; k < poly.size; ++k) r2 = std::max(r2, (poly.point[k] - x).squaredNorm());
    return r2;
}

// Always inlined into processTriangle, as when it was defined in the class: in this smaller file
// GCC's unit-growth limit kept it apart, at a cost (docs/tuning.md, "RVD: inlining").
[[gnu::always_inline]] inline const Polygon& RestrictedVoronoiDiagram::Impl::clipToCell(Polygon& poly, Polygon& spare, int i,
                                                                                        Scratch& scratch, long long& clipped,
                                                                                        const Vec3* faceNormal) const
{
    const Vec3& xi = (*seeds)[i];
    if (duplicate[i]) {
        poly.size = 0;
        return poly;
    }
    Polygon* current = &poly;
    Polygon* other = &spare;
    double radius2 = maxSquaredDistance(poly, xi);
    auto visit = [&](uint32_t j, double d2) {
        if (d2 > 4.0 * radius2) return false;  // security radius reached: done
        // Coincident seeds: the lowest index keeps the cell, the others are ignored.
        if (duplicate[j]) return true;
        if (faceNormal && !sideOk(j, *faceNormal)) return true;  // owns nothing of this face
        ++clipped;
        const int status = clipByBisector(*current, *other, xi, (*seeds)[j], static_cast<int>(j), radius2);
        if (status == 2) {
            current->size = 0;
            return false;
        }
        if (status == 1) std::swap(current, other);
        return true;
    };
    const uint32_t* idx = neighbourIndex.data() + static_cast<size_t>(i) * storedNeighbours;
    const double* d2 = neighbourDist2.data() + static_cast<size_t>(i) * storedNeighbours;
    for (int q = 0; q < storedNeighbours; ++q)
        if (!visit(idx[q], d2[q])) return *current;
    // Rare: the stored neighbours did not reach the security radius. The candidates beyond
    // them next (they continue the stored list, nearest first), as far as they are complete,
    // then the k-d tree; each seed is visited once (`covered`: the largest distance visited,
    // `atCovered`: the seeds visited at exactly that distance).
    double covered = -1.0;
    std::vector<uint32_t>& atCovered = scratch.atCovered;
    atCovered.clear();
    auto visitOnce = [&](uint32_t j, double dj) {
        if (dj < covered || (dj == covered && std::find(atCovered.begin(), atCovered.end(), j) != atCovered.end()))
            return true;  // visited already
        if (!visit(j, dj)) return false;
        if (dj > covered) covered = dj, atCovered.clear();
        atCovered.push_back(j);
        return true;
    };
    for (int q = 0; q < storedNeighbours; ++q) {  // the stored list, visited above (nearest first)
        if (d2[q] > covered) covered = d2[q], atCovered.clear();
        atCovered.push_back(idx[q]);
    }
    if (!visitCertifiedCandidates(i, visitOnce)) return *current;
    const size_t n = seeds->size();
    for (size_t k = 4 * static_cast<size_t>(storedNeighbours) + 1;; k *= 4) {
        k = std::min(k, n);
        scratch.extraIndex.resize(k);
        scratch.extraDist.resize(k);
        const size_t found = seedTree().knnSearch(xi.data(), k, scratch.extraIndex.data(), scratch.extraDist.data());
        for (size_t q = 0; q < found; ++q) {
            const uint32_t j = scratch.extraIndex[q];
            if (static_cast<int>(j) != i && !visitOnce(j, scratch.extraDist[q])) return *current;
        }
        if (k == n) return *current;
    }
}

bool RestrictedVoronoiDiagram::Impl::sideAwareStart(const Vec3& normal, const Vec3& centroid, int& s0, int& s1, int& s2) const
{
    int facing[3] = {s0, s1, s2};
    bool any = false;
    for (int& s : facing) {
        if (s >= 0 && !sideOk(static_cast<uint32_t>(s), normal)) s = -1;
        any = any || s >= 0;
    }
    if (any) {
        s0 = facing[0], s1 = facing[1], s2 = facing[2];
        return true;
    }
    constexpr int kSideSearch = 32;
    uint32_t nearest[kSideSearch];
    double nearestDist2[kSideSearch];
    const int found = static_cast<int>(seedTree().knnSearch(centroid.data(), kSideSearch, nearest, nearestDist2));
    for (int q = 0; q < found; ++q)
        if (sideOk(nearest[q], normal)) {
            s0 = static_cast<int>(nearest[q]), s1 = -1, s2 = -1;
            return true;
        }
    return false;  // none faces it: plain cells, the corners' seeds as they were
}

void RestrictedVoronoiDiagram::Impl::processTriangle(int t, const RvdOptions& options, ChunkOutput& out, Scratch& scratch) const
{
    const Face& f = faces[t];
    const Vec3& nrm = unitNormals[t];
    if (nrm.isZero()) return;  // zero-area face: nothing to integrate
    const Vec3 a = position[f[0]], b = position[f[1]], c = position[f[2]];
    // Convex cell, convex triangle: when one seed's cell holds all three corners it holds
    // the whole triangle, and no clipping is needed. This is most triangles.
    int s0 = vertexSeed[f[0]], s1 = vertexSeed[f[1]], s2 = vertexSeed[f[2]];
    // Side-aware cells: seeds facing away from the face own none of it, so they do not start
    // the walk; when no seed near it faces it, all do (the face is never left uncovered).
    const Vec3* sideNormal = seedNormals && sideAwareStart(nrm, (a + b + c) / 3.0, s0, s1, s2) ? &nrm : nullptr;
    if (s0 >= 0 && s0 == s1 && s1 == s2) {
        Polygon whole;
        whole.size = 3;
        whole.point[0] = a, whole.point[1] = b, whole.point[2] = c;
        whole.label[0] = -1, whole.label[1] = -2, whole.label[2] = -3;
        integrate(whole, s0, t, out);
        if (options.triangles) recordFragment(whole, s0, t, out);
        return;
    }
    // Otherwise start from a seed whose cell meets the triangle: the cells of its corners,
    // then (only on exact ties) the seeds nearest to the centroid.
    const Vec3 centroid = (a + b + c) / 3.0;
    constexpr int kStartCandidates = 8;
    uint32_t candidate[kStartCandidates];
    double candidateDist2[kStartCandidates];
    int candidates = 0;
    for (int sv : {s0, s1, s2})
        if (sv >= 0) candidate[candidates++] = static_cast<uint32_t>(sv);
    bool treeQueried = false;
    int nextCandidate = 0;
    bool anyPiece = false;
    const int firstFragment = static_cast<int>(out.fragments.size());
    const int firstTriangle = static_cast<int>(out.triangles.size());

    scratch.stack.clear();
    scratch.visited.clear();
    while (true) {
        if (scratch.stack.empty()) {
            if (anyPiece) break;
            if (nextCandidate >= candidates) {
                if (treeQueried) break;
                candidates = static_cast<int>(seedTree().knnSearch(centroid.data(), kStartCandidates, candidate, candidateDist2));
                nextCandidate = 0;
                treeQueried = true;
            }
            const int start = static_cast<int>(candidate[nextCandidate++]);
            if (sideNormal && !sideOk(static_cast<uint32_t>(start), nrm)) continue;
            if (std::find(scratch.visited.begin(), scratch.visited.end(), start) != scratch.visited.end()) continue;
            scratch.stack.push_back(start);
            scratch.visited.push_back(start);
        }
        const int i = scratch.stack.back();
        scratch.stack.pop_back();
        Polygon start, spare;
        start.size = 3;
        start.point[0] = a, start.point[1] = b, start.point[2] = c;
        start.label[0] = -1, start.label[1] = -2, start.label[2] = -3;
        const Polygon& poly = clipToCell(start, spare, i, scratch, out.clipped, sideNormal);
        if (poly.size < 3) continue;
        anyPiece = true;

        integrate(poly, i, t, out);
        const int fragment = options.triangles ? recordFragment(poly, i, t, out) : -1;
        for (int k = 0; k < poly.size; ++k) {
            const int j = poly.label[k];
            if (j < 0) continue;
            if (std::find(scratch.visited.begin(), scratch.visited.end(), j) == scratch.visited.end()) {
                scratch.visited.push_back(j);
                scratch.stack.push_back(j);
            }
            if (options.edges && i < j) {
                const double len = (poly.point[(k + 1) % poly.size] - poly.point[k]).norm();
                out.edges.push_back({i, j, len});
            }
            // Vertex k+1 ends edge k (bisector i|j) and starts edge k+1 (bisector i|l):
            // it is equidistant from i, j, l, and j, l follow each other counter-clockwise
            // around i, so (i, j, l) is a restricted Delaunay triangle with the input's
            // orientation.
            const int l = poly.label[(k + 1) % poly.size];
            if (options.triangles && l >= 0 && l != j) out.triangles.push_back({{fragment, -1 - j, -1 - l}, t});
        }
    }
    // The other two corners of each RDT triangle: the fragments of their seeds in this
    // input triangle (the RVD vertex is inside it, so they exist but in degenerate cases).
    const int fragmentEnd = static_cast<int>(out.fragments.size());
    for (size_t r = firstTriangle; r < out.triangles.size(); ++r)
        for (int c = 1; c < 3; ++c) {
            const int seed = -1 - out.triangles[r].corner[c];
            for (int g = firstFragment; g < fragmentEnd; ++g)
                if (out.fragments[g].seed == seed) {
                    out.triangles[r].corner[c] = g;
                    break;
                }
        }
}

inline int RestrictedVoronoiDiagram::Impl::recordFragment(const Polygon& poly, int i, int t, ChunkOutput& out) const
{
    const Vec3& xi = (*seeds)[i];
    Fragment fragment{i, t, poly.point[0], (poly.point[0] - xi).squaredNorm()};
    for (int k = 1; k + 1 < poly.size; ++k) {
        const Vec3 q = closestPointOnTriangle(xi, poly.point[0], poly.point[k], poly.point[k + 1]);
        const double d2 = (q - xi).squaredNorm();
        if (d2 < fragment.distance2) fragment.point = q, fragment.distance2 = d2;
    }
    const int index = static_cast<int>(out.fragments.size());
    out.fragments.push_back(fragment);
    for (int k = 0; k < poly.size; ++k) {
        if (poly.label[k] >= 0) continue;
        const int e = -1 - poly.label[k];
        const int across = neighbourFace[3 * t + e];
        if (across < 0) continue;
        out.links.push_back({index, across});
        if (!seedNormals) continue;
        const Vec3& v0 = position[faces[t][e]];
        const Vec3 along = position[faces[t][(e + 1) % 3]] - v0;
        const double len2 = along.squaredNorm();
        const double from = len2 > 0 ? (poly.point[k] - v0).dot(along) / len2 : 0;
        const double to = len2 > 0 ? (poly.point[(k + 1) % poly.size] - v0).dot(along) / len2 : 0;
        out.linkSpans.push_back({e, from, to});
    }
    return index;
}

inline void RestrictedVoronoiDiagram::Impl::integrate(const Polygon& poly, int i, int face, ChunkOutput& out) const
{
    const Vec3& nrm = unitNormals[face];
    const Vec3& xi = (*seeds)[i];
    const Vec3 q0 = poly.point[0] - xi;
    double mass = 0, energy = 0;
    Vec3 moment = Vec3::Zero();
    for (int k = 1; k + 1 < poly.size; ++k) {
        const Vec3 q1 = poly.point[k] - xi, q2 = poly.point[k + 1] - xi;
        const double area = 0.5 * nrm.dot((q1 - q0).cross(q2 - q0));
        mass += area;
        moment += area / 3.0 * (q0 + q1 + q2);
        energy += area / 6.0 * (q0.squaredNorm() + q1.squaredNorm() + q2.squaredNorm() + q0.dot(q1) + q1.dot(q2) + q2.dot(q0));
    }
    moment += mass * xi;
    if (!density.empty()) {
        const double rho = density[face];
        mass *= rho;
        moment *= rho;
        energy *= rho;
    }
    // Consecutive triangles (Morton order) are mostly in the same cell: one piece for them.
    if (!out.pieces.empty() && out.pieces.back().seed == i) {
        CellPiece& last = out.pieces.back();
        last.mass += mass;
        last.moment += moment;
        last.energy += energy;
    } else {
        out.pieces.push_back({i, mass, moment, energy});
    }
    if (borderEdges[face]) {
        double borderLength = 0;
        Vec3 borderMoment = Vec3::Zero();
        for (int k = 0; k < poly.size; ++k) {
            const int label = poly.label[k];
            if (label >= 0 || !(borderEdges[face] & (1u << (-1 - label)))) continue;
            const Vec3& p0 = poly.point[k];
            const Vec3& p1 = poly.point[(k + 1) % poly.size];
            const double len = (p1 - p0).norm();
            borderLength += len;
            borderMoment += 0.5 * len * (p0 + p1);
        }
        if (borderLength > 0) out.borderPieces.push_back({i, borderLength, borderMoment});
    }
}

}  // namespace fieldcvt
