#include "closest_point.h"

#include "errors.h"
#include "mesh_edges.h"

#include <Eigen/Geometry>
#include <omp.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

namespace fieldcvt {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

//! Below this sin^2 of the angle at a, the plane projection of a needle/flat triangle loses too
//! many digits to decide "inside or outside" from its barycentric signs; we then take the best
//! of every candidate instead (each candidate is a point of the triangle, so the minimum can only
//! be too large by the rounding of the best one).
constexpr double kNeedleSin2 = 1e-10;

//! Closest point of segment [a, a + ab] to p, as the parameter t in [0, 1]. A zero-length
//! segment gives t = 0 (its only point).
inline double segmentParameter(const Vec3& p, const Vec3& a, const Vec3& ab)
{
    const double length2 = ab.squaredNorm();
    if (!(length2 > 0)) return 0.0;
    const double t = (p - a).dot(ab) / length2;
    return std::clamp(t, 0.0, 1.0);
}

//! Tries edge (from -> to) of the triangle, whose barycentric weights are (1 - t) at corner
//! `from` and t at corner `to`; keeps it in (bestPoint, bestBary) if it is closer.
inline void tryEdge(const Vec3& p, const Vec3& from, const Vec3& to, int fromCorner, int toCorner, double& best2, Vec3& bestPoint,
                    Vec3& bestBary)
{
    const Vec3 edge = to - from;
    const double t = segmentParameter(p, from, edge);
    const Vec3 q = t < 1.0 ? Vec3(from + t * edge) : to;  // from + 1 * edge may differ from `to` by an ulp
    const double d2 = (q - p).squaredNorm();
    if (d2 < best2) {
        best2 = d2;
        bestPoint = q;
        bestBary.setZero();
        bestBary[fromCorner] = 1.0 - t;
        bestBary[toCorner] = t;
    }
}

//! Exact closest point of triangle (a, b, c) to p; returns the squared distance. Shared by the
//! free function and the tree so both give bit-identical answers.
inline double closestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, Vec3& point, Vec3& bary)
{
    // A query exactly at a corner gets that corner exactly (distance 0), whatever the rounding
    // below: the faces around a mesh vertex then tie exactly and the lowest index wins.
    for (int k = 0; k < 3; ++k) {
        const Vec3& corner = k == 0 ? a : (k == 1 ? b : c);
        if (p == corner) {
            point = corner;
            bary = Vec3::Unit(k);
            return 0.0;
        }
    }
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    // The normal from the cross product keeps relative accuracy for thin triangles, unlike the
    // Gram determinant |ab|^2 |ac|^2 - (ab.ac)^2 which cancels catastrophically.
    const Vec3 normal = ab.cross(ac);
    const double normal2 = normal.squaredNorm();
    const bool wellShaped = normal2 > kNeedleSin2 * ab.squaredNorm() * ac.squaredNorm();

    // Edges to examine: index k is the edge opposite corner k (bc, ca, ab).
    bool edgeOpposite[3] = {true, true, true};
    double best2 = kInfinity;
    if (normal2 > 0) {
        // Barycentric coordinates of p's projection on the plane (signed sub-areas / area).
        const double inverseNormal2 = 1.0 / normal2;
        const double v = normal.dot(ap.cross(ac)) * inverseNormal2;
        const double w = normal.dot(ab.cross(ap)) * inverseNormal2;
        const double u = 1.0 - v - w;
        if (u >= 0 && v >= 0 && w >= 0) {
            const Vec3 q = a + v * ab + w * ac;
            const double d2 = (q - p).squaredNorm();
            if (wellShaped) {
                point = q;
                bary = Vec3(u, v, w);
                return d2;
            }
            best2 = d2;
            point = q;
            bary = Vec3(u, v, w);
        } else if (wellShaped) {
            // Outside a convex triangle the closest point lies on an edge whose line separates
            // p from the triangle, i.e. one whose opposite coordinate is negative (1 or 2 edges).
            edgeOpposite[0] = u < 0;
            edgeOpposite[1] = v < 0;
            edgeOpposite[2] = w < 0;
        }
    }
    if (edgeOpposite[2]) tryEdge(p, a, b, 0, 1, best2, point, bary);
    if (edgeOpposite[0]) tryEdge(p, b, c, 1, 2, best2, point, bary);
    if (edgeOpposite[1]) tryEdge(p, c, a, 2, 0, best2, point, bary);
    if (!(best2 < kInfinity)) {
        // Only with NaN or infinite input: still return a point of the triangle, never garbage.
        point = a;
        bary = Vec3(1, 0, 0);
        best2 = (a - p).squaredNorm();
    }
    return best2;
}

}  // namespace

Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, Vec3* barycentric)
{
    Vec3 point, bary;
    closestOnTriangle(p, a, b, c, point, bary);
    if (barycentric) *barycentric = bary;
    return point;
}

// ---------------------------------------------------------------------------------------------
// AABB tree

struct ClosestPointTree::Impl {
    //! 32 bytes with single-precision bounds rounded outwards (still a conservative box, so
    //! the search stays exact); siblings are stored as one 64-byte-aligned pair, so a descent
    //! step reads exactly one cache line.
    struct Node {
        float lo[3];
        float hi[3];
        int first;  //!< leaf: first triangle; internal: index of the pair holding its children
        int count;  //!< leaf: number of triangles; 0 for internal nodes
    };
    struct alignas(64) NodePair {
        Node child[2];
    };
    //! Triangles copied in leaf order so that a leaf's triangles are contiguous in memory.
    struct Triangle {
        Vec3 a, b, c;
        //! For planeFartherThan, computed once at build time with the same expressions it used
        //! per query (so the same values): ab x ac, its squared norm, and the needle test.
        Vec3 normal;
        double normal2;
        int face;
        bool wellShaped;
    };

    static constexpr int kLeafSize = 4;
    //! The build's top levels run on one thread, the 2^kTopLevels subtrees below them on all,
    //! from this many faces on.
    static constexpr int kTopLevels = 3;
    static constexpr int kMinFacesForThreads = 20000;
    //! The traversal descends into the nearer child and pushes at most the farther one per
    //! level, so the stack never holds more than `depth` entries; a median split bounds the
    //! depth by log2(faces) + 1 <= 32 for any int face count.
    static constexpr int kStackSize = 64;

    Node root{};
    bool empty = true;
    std::vector<NodePair> pairs;
    std::vector<Triangle> triangles;
    std::vector<int> slotOfFace;  //!< face -> its index in `triangles`

    static double boxDistance2(const Node& node, const Vec3& p)
    {
        double d2 = 0;
        for (int k = 0; k < 3; ++k) {
            const double below = double(node.lo[k]) - p[k], above = p[k] - double(node.hi[k]);
            const double gap = std::max(std::max(below, above), 0.0);
            d2 += gap * gap;
        }
        return d2;
    }

    //! Cheap rejection before the exact test: true when the distance from p to the triangle's
    //! plane (a lower bound of the distance to the triangle) certainly exceeds sqrt(best2).
    //! Certainly: the computed n.ap may be off by ~1e-11 |n| |ap| for a triangle that passes the
    //! needle test, so we only reject when |n.ap| exceeds twice both sqrt(best2 |n|^2) and that
    //! error, which keeps exact ties (p on a shared vertex or edge, best2 = 0) for the
    //! lowest-face rule. Needles are never rejected here.
    static bool planeFartherThan(const Vec3& p, const Triangle& t, double best2)
    {
        if (!t.wellShaped) return false;
        const Vec3 ap = p - t.a;
        const double height = t.normal.dot(ap);
        return height * height > 4.0 * t.normal2 * std::max(best2, 1e-22 * ap.squaredNorm());
    }
    static Triangle makeTriangle(const Vec3& a, const Vec3& b, const Vec3& c, int face)
    {
        const Vec3 ab = b - a, ac = c - a;
        const Vec3 normal = ab.cross(ac);
        const double normal2 = normal.squaredNorm();
        return Triangle{a, b, c, normal, normal2, face, normal2 > kNeedleSin2 * ab.squaredNorm() * ac.squaredNorm()};
    }

    //! A subtree left for the parallel part of the build: faces order[begin, end), its node
    //! to be stored as child `slot` of pair `pair` (or as the root when pair < 0).
    struct Subtree {
        int pair, slot, begin, end;
    };

    void build(const TriMesh& mesh);
    //! The box of faces order[begin, end) into `node`; a leaf when they are few (returns -1),
    //! else the split: the faces reordered about the median of the centroids (returns it).
    static int splitNode(Node& node, int begin, int end, std::vector<int>& order, const std::vector<Vec3>& centroids,
                         const TriMesh& mesh);
    //! The subtree of order[begin, end) into `node`, its pairs into pairs[next, ...) (`next`
    //! moves past them; `pairs` is sized beforehand: pairCountOf); its depth.
    int buildNode(Node& node, int begin, int end, std::vector<int>& order, const std::vector<Vec3>& centroids,
                  const TriMesh& mesh, int& next);
    //! The top `levels` levels the same way; the subtrees below them into `subtrees`; its depth.
    int buildTop(Node& node, int begin, int end, int levels, std::vector<int>& order, const std::vector<Vec3>& centroids,
                 const TriMesh& mesh, int& next, std::vector<Subtree>& subtrees);
};

namespace {

//! Largest float <= x (and <= FLT_MAX), so a float box encloses the double one.
float roundDown(double x)
{
    constexpr float kMax = std::numeric_limits<float>::max();
    if (x < -double(kMax)) return -std::numeric_limits<float>::infinity();
    if (x > double(kMax)) return kMax;
    float f = static_cast<float>(x);
    if (double(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
}

//! Smallest float >= x.
float roundUp(double x) { return -roundDown(-x); }

//! Internal nodes (pairs of children) of the tree over `faces` faces: median splits down to
//! leaves of at most `leafSize`. A level has subtrees of at most two sizes (m and m + 1), so
//! the counts per size are remembered: a few dozen calls, not one per node.
int pairCountOf(int faces, int leafSize, std::map<int, int>& known)
{
    if (faces <= leafSize) return 0;
    const auto it = known.find(faces);
    if (it != known.end()) return it->second;
    const int count = 1 + pairCountOf(faces / 2, leafSize, known) + pairCountOf(faces - faces / 2, leafSize, known);
    known[faces] = count;
    return count;
}

int pairCountOf(int faces, int leafSize)
{
    std::map<int, int> known;
    return pairCountOf(faces, leafSize, known);
}

}  // namespace

void ClosestPointTree::Impl::build(const TriMesh& mesh)
{
    const int faceCount = mesh.faceCount();
    const int vertexCount = mesh.vertexCount();
    for (int f = 0; f < faceCount; ++f)
        for (int k = 0; k < 3; ++k)
            if (mesh.faces[f][k] < 0 || mesh.faces[f][k] >= vertexCount)
                throw InvalidInputError("closest-point tree: face " + std::to_string(f) + " refers to vertex " +
                                        std::to_string(mesh.faces[f][k]) + ", the mesh has " + std::to_string(vertexCount) +
                                        " vertices");
    if (faceCount == 0) return;

    std::vector<Vec3> centroids(faceCount);
    std::vector<int> order(faceCount);
    for (int f = 0; f < faceCount; ++f) {
        const Face& t = mesh.faces[f];
        centroids[f] = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
        order[f] = f;
    }
    // The top levels here, the subtrees below them in parallel, each into its own range of
    // `pairs` (a subtree's pair count follows from its face count), so nothing is copied. The
    // tree is the same whatever the threads.
    pairs.resize(size_t(pairCountOf(faceCount, kLeafSize)));
    const bool threads = faceCount >= kMinFacesForThreads;
    std::vector<Subtree> subtrees;
    int next = 0;
    int depth = buildTop(root, 0, faceCount, threads ? kTopLevels : kStackSize + 1, order, centroids, mesh, next, subtrees);
    std::vector<int> first(subtrees.size() + 1, next);
    for (size_t i = 0; i < subtrees.size(); ++i)
        first[i + 1] = first[i] + pairCountOf(subtrees[i].end - subtrees[i].begin, kLeafSize);
    std::vector<int> subtreeDepth(subtrees.size(), 0);
#pragma omp parallel for schedule(dynamic, 1) if (threads)
    for (int i = 0; i < static_cast<int>(subtrees.size()); ++i) {
        const Subtree& subtree = subtrees[size_t(i)];
        Node top{};
        int cursor = first[size_t(i)];
        subtreeDepth[size_t(i)] = buildNode(top, subtree.begin, subtree.end, order, centroids, mesh, cursor);
        pairs[size_t(subtree.pair)].child[subtree.slot] = top;
    }
    for (int d : subtreeDepth) depth = std::max(depth, kTopLevels + d);
    if (first.back() != static_cast<int>(pairs.size())) throw Error("closest-point tree: node count mismatch");
    if (depth > kStackSize) throw Error("closest-point tree: depth exceeds the traversal stack");
    empty = false;

    triangles.resize(faceCount);
    slotOfFace.resize(faceCount);
#pragma omp parallel for schedule(static) if (threads)
    for (int i = 0; i < faceCount; ++i) {
        const Face& t = mesh.faces[order[i]];
        triangles[i] = makeTriangle(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], order[i]);
        slotOfFace[order[i]] = i;
    }
}

int ClosestPointTree::Impl::splitNode(Node& node, int begin, int end, std::vector<int>& order, const std::vector<Vec3>& centroids,
                                      const TriMesh& mesh)
{
    Vec3 lo = Vec3::Constant(kInfinity), hi = Vec3::Constant(-kInfinity);
    Vec3 centroidLo = lo, centroidHi = hi;
    for (int i = begin; i < end; ++i) {
        const Face& t = mesh.faces[order[i]];
        for (int k = 0; k < 3; ++k) {
            lo = lo.cwiseMin(mesh.vertices[t[k]]);
            hi = hi.cwiseMax(mesh.vertices[t[k]]);
        }
        centroidLo = centroidLo.cwiseMin(centroids[order[i]]);
        centroidHi = centroidHi.cwiseMax(centroids[order[i]]);
    }
    for (int k = 0; k < 3; ++k) {
        node.lo[k] = roundDown(lo[k]);
        node.hi[k] = roundUp(hi[k]);
    }
    if (end - begin <= kLeafSize) {
        node.first = begin;
        node.count = end - begin;
        return -1;
    }
    // Split on the longest axis of the centroids' box rather than of the triangles' box: one
    // long triangle must not decide the axis for all the others.
    int axis = 0;
    const Vec3 extent = centroidHi - centroidLo;
    if (extent[1] > extent[axis]) axis = 1;
    if (extent[2] > extent[axis]) axis = 2;
    const int mid = begin + (end - begin) / 2;
    // Ties broken by face index: a strict total order makes the tree (and so the traversal
    // order) independent of the standard library's nth_element.
    std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end, [&](int f, int g) {
        const double cf = centroids[f][axis], cg = centroids[g][axis];
        return cf < cg || (cf == cg && f < g);
    });
    node.count = 0;
    return mid;
}

int ClosestPointTree::Impl::buildNode(Node& node, int begin, int end, std::vector<int>& order, const std::vector<Vec3>& centroids,
                                      const TriMesh& mesh, int& next)
{
    const int mid = splitNode(node, begin, end, order, centroids, mesh);
    if (mid < 0) return 0;
    const int pair = next++;
    node.first = pair;
    Node left{}, right{};
    const int depthLeft = buildNode(left, begin, mid, order, centroids, mesh, next);
    const int depthRight = buildNode(right, mid, end, order, centroids, mesh, next);
    pairs[size_t(pair)].child[0] = left;
    pairs[size_t(pair)].child[1] = right;
    return 1 + std::max(depthLeft, depthRight);
}

int ClosestPointTree::Impl::buildTop(Node& node, int begin, int end, int levels, std::vector<int>& order,
                                     const std::vector<Vec3>& centroids, const TriMesh& mesh, int& next,
                                     std::vector<Subtree>& subtrees)
{
    const int mid = splitNode(node, begin, end, order, centroids, mesh);
    if (mid < 0) return 0;
    const int pair = next++;
    node.first = pair;
    if (levels == 1) {  // the children's subtrees: later, in parallel
        subtrees.push_back({pair, 0, begin, mid});
        subtrees.push_back({pair, 1, mid, end});
        return 1;
    }
    Node left{}, right{};
    const int depthLeft = buildTop(left, begin, mid, levels - 1, order, centroids, mesh, next, subtrees);
    const int depthRight = buildTop(right, mid, end, levels - 1, order, centroids, mesh, next, subtrees);
    pairs[size_t(pair)].child[0] = left;
    pairs[size_t(pair)].child[1] = right;
    return 1 + std::max(depthLeft, depthRight);
}

ClosestPointTree::ClosestPointTree(const TriMesh& mesh) : impl_(std::make_unique<Impl>()) { impl_->build(mesh); }

ClosestPointTree::~ClosestPointTree() = default;

//! Branch and bound: descend into the nearer child first so the bound shrinks early, and skip
//! every box farther than the best triangle so far. Boxes at exactly the best distance are still
//! visited so that an exact tie goes to the lowest face index, whatever the tree shape.
//! An empty mesh gives face -1 and an infinite squared distance.
ClosestPoint ClosestPointTree::closest(const Vec3& p) const { return closest(p, -1); }

ClosestPoint ClosestPointTree::closest(const Vec3& p, int hintFace) const
{
    ClosestPoint result;
    result.point = p;
    result.barycentric.setZero();
    result.squaredDistance = kInfinity;
    if (impl_->empty) return result;
    const Impl::NodePair* pairs = impl_->pairs.data();
    const Impl::Triangle* triangles = impl_->triangles.data();

    struct Entry {
        const Impl::Node* node;
        double distance2;
    };
    Entry stack[Impl::kStackSize];
    int top = 0;

    double best2 = kInfinity;
    int bestFace = std::numeric_limits<int>::max();
    Vec3 point = Vec3::Zero(), bary = Vec3::Zero();
    if (hintFace >= 0 && hintFace < static_cast<int>(impl_->slotOfFace.size())) {
        // Every face at most as far as the hint is still visited (boxes at exactly the best
        // distance are), so the answer is the one found without the hint.
        const Impl::Triangle& t = triangles[impl_->slotOfFace[hintFace]];
        const double d2 = closestOnTriangle(p, t.a, t.b, t.c, point, bary);
        if (d2 == d2) {  // not NaN
            best2 = d2;
            bestFace = t.face;
            result.point = point;
            result.barycentric = bary;
        }
    }
    const Impl::Node* node = &impl_->root;
    for (;;) {
        if (node->count > 0) {
            for (int i = node->first, last = node->first + node->count; i < last; ++i) {
                const Impl::Triangle& t = triangles[i];
                if (Impl::planeFartherThan(p, t, best2)) continue;
                const double d2 = closestOnTriangle(p, t.a, t.b, t.c, point, bary);
                if (d2 < best2 || (d2 == best2 && t.face < bestFace)) {
                    best2 = d2;
                    bestFace = t.face;
                    result.point = point;
                    result.barycentric = bary;
                }
            }
        } else {
            const Impl::NodePair& pair = pairs[node->first];
            const Impl::Node* nearNode = &pair.child[0];
            const Impl::Node* farNode = &pair.child[1];
            double nearDistance2 = Impl::boxDistance2(*nearNode, p);
            double farDistance2 = Impl::boxDistance2(*farNode, p);
            if (farDistance2 < nearDistance2) {
                std::swap(nearNode, farNode);
                std::swap(nearDistance2, farDistance2);
            }
            if (nearDistance2 <= best2) {
                if (farDistance2 <= best2) stack[top++] = Entry{farNode, farDistance2};
                node = nearNode;
                continue;
            }
        }
        // Next pending subtree that can still hold something as close as the best so far.
        node = nullptr;
        while (top > 0) {
            const Entry& entry = stack[--top];
            if (entry.distance2 <= best2) {
                node = entry.node;
                break;
            }
        }
        if (!node) break;
    }
    if (bestFace == std::numeric_limits<int>::max()) return result;  // NaN query or coordinates
    result.face = bestFace;
    result.squaredDistance = best2;
    return result;
}

// ---------------------------------------------------------------------------------------------
// Walk

SurfaceWalk::SurfaceWalk(const TriMesh& mesh) : mesh_(mesh), across_(3 * mesh.faces.size(), -1)
{
    const EdgeTable edges = buildEdgeTable(mesh);
    for (int e = 0; e < edges.edgeCount(); ++e) {
        if (edges.faceCount(e) != 2) continue;
        const int h0 = edges.halfEdge(e, 0), h1 = edges.halfEdge(e, 1);
        across_[h0] = h1 / 3;
        across_[h1] = h0 / 3;
    }
    fanFirst_.assign(mesh.vertices.size() + 1, 0);
    for (const Face& t : mesh.faces)
        for (int v : t) ++fanFirst_[v + 1];
    for (size_t v = 0; v < mesh.vertices.size(); ++v) fanFirst_[v + 1] += fanFirst_[v];
    fan_.resize(fanFirst_.back());
    std::vector<int> fill(fanFirst_.begin(), fanFirst_.end() - 1);
    for (int f = 0; f < mesh.faceCount(); ++f)
        for (int v : mesh.faces[f]) fan_[fill[v]++] = f;
}

double SurfaceWalk::distanceBound(const Vec3& p, int startFace, int* endFace) const
{
    const ClosestPoint local = closestFrom(p, startFace);
    if (local.face < 0) return kInfinity;
    if (endFace) *endFace = local.face;
    return std::sqrt(local.squaredDistance);
}

ClosestPoint SurfaceWalk::closestFrom(const Vec3& p, int startFace, bool* settled, bool throughFaces) const
{
    ClosestPoint result;
    result.point = p;
    result.barycentric.setZero();
    result.squaredDistance = kInfinity;
    if (settled) *settled = false;
    if (startFace < 0 || startFace >= mesh_.faceCount()) return result;
    // A few steps reach the answer from a face a sample spacing away; more would only cost.
    constexpr int kMaxSteps = 8;
    auto distance2 = [&](int f, Vec3& bary, Vec3& point) {
        const Face& t = mesh_.faces[f];
        return closestOnTriangle(p, mesh_.vertices[t[0]], mesh_.vertices[t[1]], mesh_.vertices[t[2]], point, bary);
    };
    Vec3 bary, point;
    int face = startFace, previous = -1;
    double best2 = distance2(face, bary, point);
    bool stopped = false;
    for (int step = 0; step < kMaxSteps; ++step) {
        // On the edge opposite a zero barycentric coordinate the face across it may hold a
        // nearer point; on a corner (two zeros), any face around that vertex.
        const int zeros = (bary[0] == 0.0) + (bary[1] == 0.0) + (bary[2] == 0.0);
        if (zeros == 0 && !throughFaces) {  // inside the face: the nearest point of its neighbourhood
            stopped = true;
            break;
        }
        int next = -1;
        double next2 = best2;
        Vec3 nextBary, nextPoint, candidateBary, candidatePoint;
        auto consider = [&](int g) {
            if (g < 0 || g == face || g == previous) return;
            const double d2 = distance2(g, candidateBary, candidatePoint);
            if (d2 < next2) next = g, next2 = d2, nextBary = candidateBary, nextPoint = candidatePoint;
        };
        if (zeros == 0) {  // where the surface is concave, a face across an edge may be nearer
            for (int k = 0; k < 3; ++k) consider(across_[3 * face + k]);
        } else if (zeros == 1) {
            for (int k = 0; k < 3; ++k)
                if (bary[k] == 0.0) consider(across_[3 * face + (k + 1) % 3]);
        } else {
            const int corner = bary[0] != 0.0 ? 0 : (bary[1] != 0.0 ? 1 : 2);
            const int v = mesh_.faces[face][corner];
            for (int k = fanFirst_[v]; k < fanFirst_[v + 1]; ++k) consider(fan_[k]);
        }
        if (next < 0) {  // no neighbour is nearer: a local minimum on an edge or a corner
            stopped = true;
            break;
        }
        best2 = next2;
        bary = nextBary;
        point = nextPoint;
        previous = face;
        face = next;
    }
    if (!(best2 == best2)) return result;  // NaN query
    result.point = point;
    result.face = face;
    result.barycentric = bary;
    result.squaredDistance = best2;
    if (settled) *settled = stopped;
    return result;
}

}  // namespace fieldcvt
