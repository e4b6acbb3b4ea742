#include "repair.h"

#include "disjoint_sets.h"
#include "errors.h"
#include "mesh_edges.h"
#include "parallel_sort.h"
#include "point_tree.h"
#include "surface_gluing.h"
#include "triple_hash.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iomanip>
#include <numeric>
#include <sstream>
#include <unordered_map>

namespace fieldcvt {

namespace {

int cornerOf(const Face& t, int v) { return t[0] == v ? 0 : t[1] == v ? 1 : 2; }

using Cell = std::array<std::int64_t, 3>;

// Points hashed into cubic cells of side `size`: the candidates within `size` of a point are in
// the 27 cells around its own.
class PointGrid {
public:
    PointGrid(double size, size_t expected) : size_(size) { cells_.reserve(expected); }
    Cell cellOf(const Vec3& p) const
    {
        return {std::int64_t(std::floor(p.x() / size_)), std::int64_t(std::floor(p.y() / size_)),
                std::int64_t(std::floor(p.z() / size_))};
    }
    void insert(const Vec3& p, int id) { cells_[cellOf(p)].push_back(id); }
    template <class Visit>
    void around(const Vec3& p, Visit&& visit) const
    {
        const Cell c = cellOf(p);
        for (std::int64_t dx = -1; dx <= 1; ++dx)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                for (std::int64_t dz = -1; dz <= 1; ++dz) {
                    const auto it = cells_.find({c[0] + dx, c[1] + dy, c[2] + dz});
                    if (it != cells_.end())
                        for (int id : it->second) visit(id);
                }
    }

private:
    double size_;
    std::unordered_map<Cell, std::vector<int>, TripleHash> cells_;
};

// Whether cells of side `size` can index every point of the box (no int64 overflow).
bool gridFits(const std::vector<Vec3>& points, double size)
{
    double extent = 0;
    for (const Vec3& p : points) extent = std::max(extent, p.cwiseAbs().maxCoeff());
    return size > 0 && std::isfinite(extent / size) && extent / size < 1e15;
}

std::vector<char> borderVertices(const std::vector<Face>& faces, int n, EdgeTable* table = nullptr)
{
    EdgeTable edges = buildEdgeTable(faces, n, RepeatedVertexFaces::Skip);
    std::vector<char> border(n, 0);
    for (int e = 0; e < edges.edgeCount(); ++e)
        if (edges.isBorder(e)) border[edges.ends[e][0]] = border[edges.ends[e][1]] = 1;
    if (table) *table = std::move(edges);
    return border;
}

bool degenerate(const std::vector<Vec3>& p, const Face& t)
{
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return true;
    const Vec3 normal = (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]);
    return (normal.array() == 0.0).all();
}

// Border vertices within `tol` of the inside of a border edge are inserted into it (the faces on
// the edge are split from their opposite corner). One edge per face and pass; three passes.
int insertTJunctions(const std::vector<Vec3>& pos, std::vector<Face>& faces, double tol, double cell)
{
    int inserted = 0;
    const int n = static_cast<int>(pos.size());
    for (int pass = 0; pass < 3; ++pass) {
        EdgeTable edges;
        const std::vector<char> border = borderVertices(faces, n, &edges);
        PointGrid grid(cell, size_t(n / 4 + 1));
        for (int v = 0; v < n; ++v)
            if (border[v]) grid.insert(pos[v], v);
        // Per face: the side that gets points, and the points with their parameter along it.
        std::vector<int> sideOf(faces.size(), -1);
        std::vector<std::vector<std::pair<double, int>>> points(faces.size());
        for (int e = 0; e < edges.edgeCount(); ++e) {
            if (!edges.isBorder(e)) continue;
            const int h = edges.halfEdge(e, 0), f = h / 3;
            if (sideOf[f] >= 0) continue;  // the next pass
            const int a = faces[f][h % 3], b = faces[f][(h % 3 + 1) % 3];
            const Vec3 d = pos[b] - pos[a];
            const double length2 = d.squaredNorm();
            std::vector<std::pair<double, int>> found;
            const int steps = static_cast<int>(std::min(1e6, std::ceil(std::sqrt(length2) / cell))) + 1;
            for (int i = 0; i <= steps; ++i)
                grid.around(pos[a] + (double(i) / steps) * d, [&](int p) {
                    if (p == a || p == b || p == faces[f][(h % 3 + 2) % 3]) return;
                    const double t = (pos[p] - pos[a]).dot(d) / length2;
                    if (!(t > 0 && t < 1)) return;
                    if ((pos[p] - pos[a] - t * d).norm() > tol) return;
                    if ((pos[p] - pos[a]).norm() <= tol || (pos[p] - pos[b]).norm() <= tol) return;
                    found.push_back({t, p});
                });
            if (found.empty()) continue;
            std::sort(found.begin(), found.end());
            found.erase(std::unique(found.begin(), found.end()), found.end());
            sideOf[f] = h % 3;
            points[f] = std::move(found);
        }
        const size_t before = faces.size();
        for (size_t f = 0; f < before; ++f) {
            if (sideOf[f] < 0) continue;
            const int k = sideOf[f];
            const int a = faces[f][k], b = faces[f][(k + 1) % 3], c = faces[f][(k + 2) % 3];
            int from = a;
            for (size_t i = 0; i < points[f].size(); ++i) {
                const int p = points[f][i].second;
                if (i == 0)
                    faces[f] = {from, p, c};
                else
                    faces.push_back({from, p, c});
                from = p;
                ++inserted;
            }
            faces.push_back({from, b, c});
        }
        if (faces.size() == before) break;
    }
    return inserted;
}

std::string percent(double fraction)
{
    std::ostringstream s;
    s << std::setprecision(3) << 100 * fraction << " %";
    return s.str();
}

//! The input scaled by a power of two (exact), so that squared lengths, cross products and areas
//! neither overflow nor underflow at any model size (1e300, 1e-300); the output takes the input's
//! own coordinates, and lengths and areas are reported in input units (toInputLength).
struct ScaledCopy {
    std::vector<Vec3> pos;
    double toInputLength = 1;
};

ScaledCopy scaledCopy(const TriMesh& input, const std::vector<char>& referenced)
{
    const int n = input.vertexCount();
    int exponent = 0;
    double largest = 0;
    for (int v = 0; v < n; ++v)
        if (referenced[v]) largest = std::max(largest, input.vertices[v].cwiseAbs().maxCoeff());
    if (largest > 0) std::frexp(largest, &exponent);
    ScaledCopy copy;
    copy.pos = input.vertices;
    for (Vec3& p : copy.pos)
        for (int k = 0; k < 3; ++k) p[k] = std::ldexp(p[k], -exponent);
    copy.toInputLength = std::ldexp(1.0, exponent);
    return copy;
}

//! Step 1: vertices at the same coordinates (-0 = +0) merged, then border vertices within the
//! weld tolerance welded and T-junctions split. Returns the faces on the representatives; `rep`
//! maps every input vertex to its representative.
std::vector<Face> weldVertices(const TriMesh& input, std::vector<Vec3>& pos, const std::vector<char>& referenced,
                               double toInputLength, const RepairParams& params, std::vector<int>& rep, RepairReport& report)
{
    const int n = input.vertexCount();
    if (!params.mergeVertices) {
        rep.resize(size_t(n));
        std::iota(rep.begin(), rep.end(), 0);
        return input.faces;
    }
    rep = exactDuplicateRepresentatives(pos, referenced, report.mergedDuplicateVertices);
    std::vector<Face> faces;
    faces.reserve(input.faces.size());
    for (const Face& t : input.faces) faces.push_back({rep[t[0]], rep[t[1]], rep[t[2]]});
    double edgeSum = 0;
    long long edgeCount = 0;
    for (const Face& t : faces)
        for (int k = 0; k < 3; ++k)
            if (t[k] != t[(k + 1) % 3]) edgeSum += (pos[t[k]] - pos[t[(k + 1) % 3]]).norm(), ++edgeCount;
    const double meanEdge = edgeCount > 0 ? edgeSum / double(edgeCount) : 0.0;
    const double tol = params.weldTolerance * meanEdge;
    report.weldDistance = tol * toInputLength;
    if (tol > 0 && gridFits(pos, tol) && gridFits(pos, meanEdge)) {
        EdgeTable edges;
        const std::vector<char> border = borderVertices(faces, n, &edges);
        // Both the weld and the T-junctions act on border vertices only: a closed surface (the
        // common large input) has nothing to do here.
        if (std::find(border.begin(), border.end(), 1) == border.end()) return faces;
        DisjointSets weld(n);
        PointGrid grid(tol, size_t(n / 4 + 1));
        for (int v = 0; v < n; ++v) {
            if (!border[v] || rep[v] != v) continue;
            grid.around(pos[v], [&](int u) {
                if ((pos[u] - pos[v]).norm() <= tol && edges.find(u, v) < 0) weld.unite(u, v);
            });
            grid.insert(pos[v], v);
        }
        for (int v = 0; v < n; ++v)
            if (rep[v] == v && weld.find(v) != v) ++report.weldedVertices;
        for (int v = 0; v < n; ++v) rep[v] = weld.find(rep[v]);
        for (Face& t : faces)
            for (int& c : t) c = rep[c];
        report.tJunctions = insertTJunctions(pos, faces, tol, meanEdge);
    }

    return faces;
}

//! A face repeated (same corners, either orientation) whose copies are the only faces on two of
//! its edges hangs from its third edge as a flap with nothing on either side: no surface. Keeping
//! one copy leaves that edge with three faces, which the split into manifold sheets turns into a
//! slit in a closed part (conrod.stl's three, opened as boundary loops once the sampling is fine
//! enough). Every copy of such a face goes. `keyed` is sorted by corner set; `keep` marks the
//! first face of each set.
template <class Keyed>
void removeDoubledFlaps(const std::vector<Keyed>& keyed, std::vector<char>& keep, RepairReport& report)
{
    using Edge = std::pair<int, int>;
    auto edgesOf = [](const std::array<int, 3>& c) {  // c sorted
        return std::array<Edge, 3>{Edge{c[0], c[1]}, Edge{c[1], c[2]}, Edge{c[0], c[2]}};
    };
    // The repeated corner sets (first index and count in `keyed`) and their edges.
    std::vector<std::pair<size_t, size_t>> groups;
    std::vector<Edge> watched;
    for (size_t i = 0; i < keyed.size();) {
        size_t j = i + 1;
        while (j < keyed.size() && keyed[j].corners == keyed[i].corners) ++j;
        if (j - i >= 2) {
            groups.push_back({i, j - i});
            for (const Edge& e : edgesOf(keyed[i].corners)) watched.push_back(e);
        }
        i = j;
    }
    if (groups.empty()) return;
    std::sort(watched.begin(), watched.end());
    watched.erase(std::unique(watched.begin(), watched.end()), watched.end());
    auto watchedIndex = [&](const Edge& e) {  // -1 if not watched
        const auto it = std::lower_bound(watched.begin(), watched.end(), e);
        return it != watched.end() && *it == e ? static_cast<int>(it - watched.begin()) : -1;
    };
    std::vector<int> uses(watched.size(), 0);
    for (const Keyed& k : keyed)
        for (const Edge& e : edgesOf(k.corners))
            if (const int i = watchedIndex(e); i >= 0) ++uses[size_t(i)];
    for (const auto& [first, count] : groups) {
        int own = 0;  // edges no face outside the group uses
        for (const Edge& e : edgesOf(keyed[first].corners)) own += uses[size_t(watchedIndex(e))] == int(count);
        if (own != 2) continue;  // 3: a lone doubled triangle, kept once as before
        keep[size_t(keyed[first].face)] = 0;
        ++report.removedFlapFaces;
    }
}

//! Step 2: degenerate, duplicate and opposite faces removed. A face whose corner set an earlier
//! face has is dropped: found by sorting (corner set, face) pairs, not a hash map of millions of
//! triples; the first face of each set is kept, the rest compared with it.
void removeBadFaces(const std::vector<Vec3>& pos, std::vector<Face>& faces, RepairReport& report)
{
    struct Keyed {
        std::array<int, 3> corners;  // sorted
        int face;
        bool operator<(const Keyed& o) const { return corners != o.corners ? corners < o.corners : face < o.face; }
    };
    std::vector<Keyed> keyed;
    keyed.reserve(faces.size());
    for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
        if (degenerate(pos, faces[f])) {
            ++report.removedDegenerateFaces;
            continue;
        }
        Keyed k{faces[f], f};
        std::sort(k.corners.begin(), k.corners.end());
        keyed.push_back(k);
    }
    parallelSort(keyed.begin(), keyed.end(), std::less<Keyed>());  // (corners, face): no ties
    std::vector<char> keep(faces.size(), 0);
    size_t first = 0;  // the first entry of the current corner set: its earliest face
    for (size_t i = 0; i < keyed.size(); ++i) {
        if (i == 0 || keyed[i].corners != keyed[i - 1].corners) {
            first = i;
            keep[size_t(keyed[i].face)] = 1;
            continue;
        }
        // Same cyclic order as the kept face: a duplicate; otherwise its opposite.
        const Face& other = faces[size_t(keyed[first].face)];
        const Face& t = faces[size_t(keyed[i].face)];
        const int k = cornerOf(other, t[0]);
        if (other[(k + 1) % 3] == t[1])
            ++report.removedDuplicateFaces;
        else
            ++report.removedOppositeFaces;
    }
    removeDoubledFlaps(keyed, keep, report);
    std::vector<Face> kept;
    kept.reserve(keyed.size());
    for (size_t f = 0; f < faces.size(); ++f)
        if (keep[f]) kept.push_back(faces[f]);
    faces.swap(kept);
}

//! Step 3: which face continues which across each edge (partner[h]: the half-edge glued to h);
//! the faces around a non-manifold edge are paired by angle into manifold sheets.
std::vector<int> glueEdges(const std::vector<Vec3>& pos, const std::vector<Face>& faces, const EdgeTable& edges,
                           RepairReport& report)
{
    const int faceCount = static_cast<int>(faces.size());
    auto origin = [&](int h) { return faces[h / 3][h % 3]; };
    std::vector<int> partner = glueTwoSidedEdges(edges, faceCount);
    for (int e = 0; e < edges.edgeCount(); ++e) {
        const int k = edges.faceCount(e);
        if (k <= 2) continue;
        // Around the edge lo -> hi, by angle: a face running lo -> hi faces the larger angles,
        // one running hi -> lo the smaller; two consecutive faces enclosing the same side (the
        // first running hi -> lo, the next lo -> hi) make one manifold sheet.
        ++report.nonManifoldEdges;
        const auto [lo, hi] = edges.ends[e];
        const Vec3 axis = (pos[hi] - pos[lo]).normalized();
        const Vec3 u = axis.unitOrthogonal(), w = axis.cross(u);
        std::vector<std::pair<double, int>> around;
        for (int i = 0; i < k; ++i) {
            const int h = edges.halfEdge(e, i);
            const Vec3 d = pos[faces[h / 3][(h % 3 + 2) % 3]] - pos[lo];
            around.push_back({std::atan2(d.dot(w), d.dot(u)), h});
        }
        std::sort(around.begin(), around.end());
        for (int i = 0; i < k; ++i) {
            const int h = around[i].second, next = around[(i + 1) % k].second;
            if (origin(h) == hi && origin(next) == lo && partner[h] < 0 && partner[next] < 0)
                partner[h] = next, partner[next] = h;
        }
    }

    return partner;
}

//! Unglues half-edge h from its partner.
void cutEdge(std::vector<int>& partner, int h)
{
    if (partner[h] >= 0) partner[partner[h]] = -1;
    partner[h] = -1;
}

//! Step 5: one vertex per fan of corners glued across edges (cornerVertex; vertex n + i is a
//! copy of copySource[i]).
void splitVertexFans(const std::vector<Face>& faces, const EdgeTable& edges, int n, std::vector<int>& partner,
                     std::vector<int>& cornerVertex, std::vector<int>& copySource, RepairReport& report)
{
    auto cut = [&](int h) { cutEdge(partner, h); };
    // 5. One vertex per fan of corners glued across edges. A face cut from faces that still
    // share both ends of the edge (a cut that splits neither end) is detached at one corner:
    // its other edge at that corner is cut too.
    for (int round = 0;; ++round) {
        splitIntoFans(faces, partner, n, {}, cornerVertex, copySource);
        bool detached = false;
        std::vector<std::pair<std::array<int, 2>, int>> ends;
        for (int e = 0; e < edges.edgeCount(); ++e) {
            if (edges.faceCount(e) < 2) continue;
            ends.clear();
            for (int i = 0; i < edges.faceCount(e); ++i) {
                const int h = edges.halfEdge(e, i);
                const int a = cornerVertex[h], b = cornerVertex[3 * (h / 3) + (h % 3 + 1) % 3];
                ends.push_back({{std::min(a, b), std::max(a, b)}, h});
            }
            std::sort(ends.begin(), ends.end());
            for (size_t i = 0, j; i < ends.size(); i = j) {
                for (j = i + 1; j < ends.size() && ends[j].first == ends[i].first; ++j) {
                }
                if (j - i == 1 || (j - i == 2 && partner[ends[i].second] == ends[i + 1].second)) continue;
                int keep = ends[i].second;  // a glued pair if there is one, else the first face
                for (size_t m = i; m < j; ++m)
                    if (partner[ends[m].second] >= 0) {
                        keep = ends[m].second;
                        break;
                    }
                for (size_t m = i; m < j; ++m) {
                    const int h = ends[m].second;
                    if (h == keep || h == partner[keep]) continue;
                    cut(h);
                    cut(3 * (h / 3) + (h % 3 + 2) % 3);
                    detached = true;
                }
            }
        }
        if (!detached || round == 8) break;
    }
    {
        std::vector<char> split(n, 0);
        for (int s : copySource) split[s] = 1;
        report.splitVertices = static_cast<int>(std::count(split.begin(), split.end(), 1));
        report.addedVertexCopies = static_cast<int>(copySource.size());
    }
}

//! Step 6, the components kept although too small for the budget because they are parts of
//! their own (RepairParams::farComponentEdges): `small[root]` marks the components too small,
//! `area[root]` holds each component's area. Nearest input vertices stand for the surface: the
//! input's edges are short against the output's, so the distance is over-estimated by little.
std::vector<char> farComponentsToKeep(const std::vector<Vec3>& pos, const std::vector<Face>& faces, DisjointSets& sets,
                                      const std::vector<double>& area, double total, const std::vector<char>& small,
                                      const RepairParams& params)
{
    const int faceCount = static_cast<int>(faces.size());
    std::vector<char> keep(faceCount, 0);
    const double budget = params.vertexBudget;
    // Equilateral triangles, two per vertex, over the whole area.
    const double edge = std::sqrt(2 * total / (std::sqrt(3.0) * budget));
    std::vector<char> keptVertex(pos.size(), 0), candidate(faceCount, 0);
    bool anyCandidate = false;
    for (int f = 0; f < faceCount; ++f) {
        const int root = sets.find(f);
        if (!small[root])
            for (int v : faces[f]) keptVertex[size_t(v)] = 1;
        else if (budget * area[root] / total >= params.minFarComponentSamples)
            candidate[root] = 1, anyCandidate = true;
    }
    if (!anyCandidate) return keep;
    std::vector<Vec3> keptPoints;
    for (size_t v = 0; v < pos.size(); ++v)
        if (keptVertex[v]) keptPoints.push_back(pos[v]);
    if (keptPoints.empty()) return keep;
    PointCloud cloud{&keptPoints};
    PointTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    tree.buildIndex();
    std::vector<double> gap(faceCount, 0.0);  // per candidate root: its farthest vertex's distance
    for (int f = 0; f < faceCount; ++f) {
        const int root = sets.find(f);
        if (!candidate[root]) continue;
        for (int v : faces[f]) {
            uint32_t nearest = 0;
            double d2 = 0;
            tree.knnSearch(pos[size_t(v)].data(), 1, &nearest, &d2);
            gap[root] = std::max(gap[root], std::sqrt(d2));
        }
    }
    std::vector<int> far;
    for (int root = 0; root < faceCount; ++root)
        if (candidate[root] && gap[root] > params.farComponentEdges * edge) far.push_back(root);
    std::stable_sort(far.begin(), far.end(), [&](int a, int b) { return area[a] > area[b]; });
    double added = 0;  // samples the kept ones are short of the floor
    for (int root : far) {
        const double shortOf = std::max(0.0, params.minFarComponentFloor - budget * area[root] / total);
        if (added + shortOf > params.farComponentBudget * budget) break;
        added += shortOf;
        keep[root] = 1;
    }
    return keep;
}

//! Step 6: the faces kept once components (through glued edges) too small for the vertex budget
//! are dropped.
std::vector<char> keptFaces(const std::vector<Vec3>& pos, const std::vector<Face>& faces, const std::vector<int>& partner,
                            double toInputLength, const RepairParams& params, RepairReport& report)
{
    const int faceCount = static_cast<int>(faces.size());
    std::vector<char> keepFace(faceCount, 1);
    {
        DisjointSets sets(faceCount);
        for (int h = 0; h < 3 * faceCount; ++h)
            if (partner[h] > h) sets.unite(h / 3, partner[h] / 3);
        std::vector<double> area(faceCount, 0.0);
        double total = 0;
        for (int f = 0; f < faceCount; ++f) {
            const Face& t = faces[f];
            const double a = 0.5 * (pos[t[1]] - pos[t[0]]).cross(pos[t[2]] - pos[t[0]]).norm();
            area[sets.find(f)] += a;
            total += a;
        }
        if (params.vertexBudget > 0 && total > 0) {
            std::vector<char> drop(faceCount, 0);
            int components = 0;
            double largest = 0, droppedArea = 0;  // droppedArea in the scaled copy's units
            for (int f = 0; f < faceCount; ++f) {
                if (sets.find(f) != f) continue;
                ++components;
                largest = std::max(largest, area[f]);
                const double share = area[f] / total;
                if (params.vertexBudget * share >= params.minComponentSamples) continue;
                if (share >= params.keepAreaFraction) {
                    ++report.keptSmallComponents;
                    continue;
                }
                drop[f] = 1;
            }
            const std::vector<char> far = farComponentsToKeep(pos, faces, sets, area, total, drop, params);
            for (int f = 0; f < faceCount; ++f) {
                if (!drop[f]) continue;
                if (far[f]) {
                    drop[f] = 0;
                    ++report.keptFarComponents;
                    continue;
                }
                ++report.droppedComponents;
                droppedArea += area[f];
            }
            report.droppedArea = droppedArea * toInputLength * toInputLength;
            report.droppedAreaFraction = droppedArea / total;
            if (report.droppedComponents == components) {
                std::ostringstream s;
                s << "all " << components << " connected components are too small for " << params.vertexBudget
                  << " vertices: the largest holds " << percent(largest / total) << " of the area and would get "
                  << std::setprecision(3) << params.vertexBudget * largest / total << " samples (at least "
                  << params.minComponentSamples << " make a surface); use at least "
                  << static_cast<long long>(std::ceil(params.minComponentSamples * total / largest - 1e-6)) << " vertices";
                throw InvalidInputError(s.str());
            }
            for (int f = 0; f < faceCount; ++f) keepFace[f] = !drop[sets.find(f)];
        }
    }

    return keepFace;
}

//! What the repair did, as the log's information (changes nothing a user sees) and notes.
void describeRepair(const RepairParams& params, RepairReport& report)
{
    auto note = [&](int count, const std::string& text) {
        if (count > 0) report.notes.push_back("repair: " + std::to_string(count) + " " + text);
    };
    auto inform = [&](int count, const std::string& text) {
        if (count > 0) report.information.push_back("repair: " + std::to_string(count) + " " + text);
    };
    inform(report.removedUnreferencedVertices, "unreferenced vertices removed");
    inform(report.mergedDuplicateVertices, "vertices merged with another at the same coordinates");
    {
        std::ostringstream s;
        s << std::setprecision(3) << report.weldDistance << " (" << params.weldTolerance << " x the mean edge length)";
        note(report.weldedVertices, "border vertices welded to another within " + s.str() + " (cracks, seams)");
        note(report.tJunctions, "border vertices inserted into a border edge within " + s.str() + " (T-junctions)");
    }
    note(report.removedDegenerateFaces, "degenerate faces removed (repeated corner or no area)");
    note(report.removedDuplicateFaces, "duplicate faces removed (same corners, same orientation)");
    note(report.removedOppositeFaces, "opposite duplicate faces removed (same corners, reversed)");
    note(report.removedFlapFaces, "doubled faces hanging from one edge removed with their copies (flaps, no surface)");
    note(report.nonManifoldEdges, "non-manifold edges (more than two faces) split into manifold sheets");
    if (report.nonOrientableComponents > 0)
        note(report.nonOrientableComponents, "non-orientable components cut along a seam of " + std::to_string(report.seamEdges) +
                                                 " edges into orientable pieces");
    note(report.splitVertices, "vertices split into one vertex per fan (non-manifold vertices and the ends of cuts; " +
                                   std::to_string(report.addedVertexCopies) + " vertices added)");
    if (report.droppedComponents > 0) {
        std::ostringstream s;
        s << "connected components too small for " << params.vertexBudget << " vertices dropped (fewer than "
          << params.minComponentSamples << " samples each): area " << std::setprecision(4) << report.droppedArea << ", "
          << percent(report.droppedAreaFraction) << " of the surface";
        note(report.droppedComponents, s.str());
    }
    if (report.keptFarComponents > 0)
        inform(report.keptFarComponents, "small connected components kept: each lies over " +
                                             std::to_string(int(params.farComponentEdges)) +
                                             " edge lengths from the rest (dropping them would leave a gap)");
    if (report.keptSmallComponents > 0)
        note(report.keptSmallComponents, "connected components get fewer than " +
                                             std::to_string(int(params.minComponentSamples)) + " samples but hold over " +
                                             percent(params.keepAreaFraction) + " of the area each: kept (use more vertices)");
}

}  // namespace

TriMesh repairMesh(const TriMesh& input, const RepairParams& params, RepairReport& report)
{
    report = RepairReport{};
    const int n = input.vertexCount();
    report.vertexMap.resize(n);
    std::iota(report.vertexMap.begin(), report.vertexMap.end(), 0);
    std::vector<char> referenced(n, 0);
    for (const Face& t : input.faces)
        for (int c : t) {
            if (c < 0 || c >= n || !input.vertices[c].allFinite()) {
                report.skipped = true;  // the strict check says what and where
                return input;
            }
            referenced[c] = 1;
        }
    if (input.faces.empty()) {
        report.skipped = true;
        return input;
    }
    report.removedUnreferencedVertices = n - static_cast<int>(std::count(referenced.begin(), referenced.end(), 1));
    ScaledCopy scaled = scaledCopy(input, referenced);  // 1.-2. on the scaled copy
    std::vector<Vec3>& pos = scaled.pos;
    std::vector<int> rep;
    std::vector<Face> faces = weldVertices(input, pos, referenced, scaled.toInputLength, params, rep, report);
    removeBadFaces(pos, faces, report);
    if (faces.empty()) {
        report.skipped = true;  // every face degenerate: the strict check's message
        return input;
    }
    const int faceCount = static_cast<int>(faces.size());
    const EdgeTable edges = buildEdgeTable(faces, n);
    std::vector<int> partner = glueEdges(pos, faces, edges, report);  // 3.
    // 4. Orientation: a breadth-first walk per component; a glued edge whose faces disagree
    // with the orientation reached so far is cut (the seam of a Moebius-like piece).
    report.nonOrientableComponents = orientByWalk(faces, partner, [&](int h) {
                                         cutEdge(partner, h);
                                         ++report.seamEdges;
                                     }).nonOrientable;

    std::vector<int> cornerVertex(3 * size_t(faceCount));
    std::vector<int> copySource;
    splitVertexFans(faces, edges, n, partner, cornerVertex, copySource, report);                              // 5.
    const std::vector<char> keepFace = keptFaces(pos, faces, partner, scaled.toInputLength, params, report);  // 6.

    // 7. The repaired mesh: referenced vertices in input order, then the copies.
    const int working = n + static_cast<int>(copySource.size());
    std::vector<int> index(working, -1);
    for (int c = 0; c < 3 * faceCount; ++c)
        if (keepFace[c / 3]) index[cornerVertex[c]] = 0;
    TriMesh out;
    for (int v = 0; v < working; ++v)
        if (index[v] == 0) {
            index[v] = out.vertexCount();
            report.vertexSource.push_back(v < n ? v : copySource[v - n]);
            out.vertices.push_back(input.vertices[size_t(report.vertexSource.back())]);
        }
    for (int f = 0; f < faceCount; ++f)
        if (keepFace[f])
            out.faces.push_back({index[cornerVertex[3 * f]], index[cornerVertex[3 * f + 1]], index[cornerVertex[3 * f + 2]]});
    for (int v = 0; v < n; ++v) report.vertexMap[v] = referenced[v] ? index[rep[v]] : -1;

    describeRepair(params, report);
    return out;
}

TriMesh repairAndPrepare(const TriMesh& input, const RepairParams& params, RepairReport& repair, InputReport& report)
{
    const TriMesh repaired = repairMesh(input, params, repair);
    if (repair.skipped) return prepareInput(input, report);
    TriMesh clean = prepareInput(repaired, report, true);
    std::vector<int> cleanIndex(input.vertices.size(), -1);
    for (size_t v = 0; v < cleanIndex.size(); ++v)
        if (repair.vertexMap[v] >= 0) cleanIndex[v] = report.cleanIndex[size_t(repair.vertexMap[v])];
    report.cleanIndex = std::move(cleanIndex);
    report.notes.insert(report.notes.begin(), repair.notes.begin(), repair.notes.end());
    report.information.insert(report.information.begin(), repair.information.begin(), repair.information.end());
    return clean;
}

}  // namespace fieldcvt
