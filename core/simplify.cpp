#include "simplify.h"

#include "editable_mesh.h"
#include "errors.h"
#include "mesh_edges.h"
#include "morton_order.h"
#include "triangle_shape.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <utility>

namespace fieldcvt {

namespace {

// Garland–Heckbert quadric Σ area · (n·x + d)² over a set of face planes, stored as the
// symmetric 3×3 part, the linear part and the constant, plus the area it covers.
struct Quadric {
    double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
    Vec3 b = Vec3::Zero();
    double c = 0;
    double area = 0;

    static Quadric plane(const Vec3& unitNormal, const Vec3& point, double area)
    {
        Quadric q;
        const Vec3& n = unitNormal;
        const double d = -n.dot(point);
        q.xx = area * n.x() * n.x(), q.xy = area * n.x() * n.y(), q.xz = area * n.x() * n.z();
        q.yy = area * n.y() * n.y(), q.yz = area * n.y() * n.z(), q.zz = area * n.z() * n.z();
        q.b = area * d * n;
        q.c = area * d * d;
        q.area = area;
        return q;
    }
    Quadric& operator+=(const Quadric& o)
    {
        xx += o.xx, xy += o.xy, xz += o.xz, yy += o.yy, yz += o.yz, zz += o.zz;
        b += o.b, c += o.c, area += o.area;
        return *this;
    }
    //! Σ area · distance² of p to the planes (>= 0 up to rounding).
    double error(const Vec3& p) const
    {
        const double x = p.x(), y = p.y(), z = p.z();
        const double e = xx * x * x + yy * y * y + zz * z * z + 2 * (xy * x * y + xz * x * z + yz * y * z) + 2 * b.dot(p) + c;
        return std::max(0.0, e);
    }
};

//! A collapse that leaves a face this much worse than the worst face around the removed vertex,
//! and worse than this, is refused (half-edge collapses on flat parts, where every quadric error
//! is 0, would otherwise make long slivers).
constexpr double kMinMeanRatio = 0.2;
//! A moved face may turn by at most this much (cosine; 45°).
constexpr double kMinNormalCosine = 0.7071;
//! Weight of the squared edge length in the collapse order (times the area the quadrics cover,
//! the units of the quadric error): on flat parts, where the error is 0, short edges go first
//! and the coarse surface stays even.
constexpr double kLengthWeight = 1e-3;

//! The collapse order compares costs on a logarithmic grid of relative step 2^-20 (about 1e-6):
//! on a symmetric or regular mesh many costs are equal but for rounding, and a copy of the model
//! moved or scaled (a working frame computed in other units) must collapse in the same order.
std::int64_t orderKey(double cost)
{
    if (!(cost > 0)) return std::numeric_limits<std::int64_t>::min();
    return static_cast<std::int64_t>(std::floor(std::log2(cost) * 1048576.0));
}

struct Candidate {
    std::int64_t cost;  //!< orderKey of the cost
    int from, to;
    std::uint32_t fromVersion, toVersion;
    // The smallest cost first; ties by indices (deterministic).
    bool operator>(const Candidate& o) const
    {
        if (cost != o.cost) return cost > o.cost;
        if (from != o.from) return from > o.from;
        return to > o.to;
    }
};

const TriMesh& checked(const TriMesh& input, const SimplifyParams& params)
{
    if (!params.locked.empty() && params.locked.size() != size_t(input.vertexCount()))
        throw InvalidInputError("simplify: the locked flags have " + std::to_string(params.locked.size()) + " entries for " +
                                std::to_string(input.vertexCount()) + " vertices");
    return input;
}

class Simplifier {
public:
    //! `quadrics`: the vertices' quadrics when `input` is itself a simplification (the blocks'
    //! merged result), else computed from its faces.
    Simplifier(const TriMesh& input, const SimplifyParams& params, std::vector<Quadric> quadrics = {})
        : params_(params), mesh_(checked(input, params).vertices, input.faces), quadric_(std::move(quadrics))
    {
        const int n = input.vertexCount();
        locked_.assign(n, 0);
        for (int v = 0; v < n && !params.locked.empty(); ++v) locked_[v] = params.locked[v];
        version_.assign(n, 0);
        const bool given = !quadric_.empty();
        if (!given) quadric_.assign(n, {});
        for (int f = 0; f < mesh_.faceCount() && !given; ++f) {
            const Face& t = mesh_.face(f);
            const Vec3 normal = (position(t[1]) - position(t[0])).cross(position(t[2]) - position(t[0]));
            const double length = normal.norm();
            if (length > 0) {
                const Quadric q = Quadric::plane(normal / length, position(t[0]), 0.5 * length);
                for (int v : t) quadric_[v] += q;
            }
        }
        // Vertices on a border edge (or on an edge of more than two faces) stay.
        const EdgeTable edges = buildEdgeTable(input);
        for (int e = 0; e < edges.edgeCount(); ++e)
            if (edges.faceCount(e) != 2) locked_[edges.ends[e][0]] = locked_[edges.ends[e][1]] = 1;
        aliveFaces_ = mesh_.faceCount();
    }

    //! `keptQuadrics`, if given, receives the quadric of each coarse vertex.
    SimplifyResult run(std::vector<Quadric>* keptQuadrics = nullptr)
    {
        const int n = mesh_.vertexCount();
        std::vector<int> ring;
        // Every edge's candidate first, then one heap made of them (linear time, against a
        // push per edge). The pops come in the same order: the order is total on (cost, from,
        // to), and the only ties, two entries for one edge, are a valid and a stale one.
        std::vector<Candidate> initial;
        initial.reserve(3 * size_t(mesh_.faceCount()) / 2 + 16);
        Candidate c;
        for (int v = 0; v < n; ++v) {
            neighbours(v, ring);
            for (int w : ring)
                if (v < w && edgeCandidate(v, w, c)) initial.push_back(c);
        }
        heap_ = std::move(initial);
        std::make_heap(heap_.begin(), heap_.end(), std::greater<Candidate>());
        size_t pushesSinceCompaction = 0;
        while (aliveFaces_ > params_.targetFaces && !heap_.empty()) {
            std::pop_heap(heap_.begin(), heap_.end(), std::greater<Candidate>());
            const Candidate c = heap_.back();
            heap_.pop_back();
            if (!current(c)) continue;
            if (!collapseAllowed(c.from, c.to)) continue;
            collapse(c.from, c.to);
            neighbours(c.to, ring);
            for (int w : ring) pushesSinceCompaction += pushEdge(c.to, w);
            // Each push makes the edge's previous entry stale (most pops were stale entries).
            // Dropping them in one linear pass once the pushes since the last pass reach half the
            // heap costs less than popping them one by one (docs/tuning.md, "Stale heap entries");
            // the current entries pop in the same order (the order is total on them), so the
            // result is the same.
            if (2 * pushesSinceCompaction > heap_.size()) {
                heap_.erase(std::remove_if(heap_.begin(), heap_.end(), [&](const Candidate& e) { return !current(e); }),
                            heap_.end());
                std::make_heap(heap_.begin(), heap_.end(), std::greater<Candidate>());
                pushesSinceCompaction = 0;
            }
        }
        SimplifyResult result = compact();
        if (keptQuadrics) {
            keptQuadrics->clear();
            for (int v : result.inputVertex) keptQuadrics->push_back(quadric_[v]);
        }
        return result;
    }

private:
    const Vec3& position(int v) const { return mesh_.position(v); }
    //! A vertex is removed with its last face (an input vertex without faces is dropped too).
    bool vertexAlive(int v) const { return !mesh_.facesOf(v).empty(); }

    //! Whether a heap entry still describes its edge: neither end has changed since it was made.
    //! The versions first (4 bytes a vertex, against a face list's 24): most stale entries fail
    //! there, and a removed vertex's version moved on too.
    bool current(const Candidate& c) const
    {
        return version_[c.from] == c.fromVersion && version_[c.to] == c.toVersion && vertexAlive(c.from) && vertexAlive(c.to);
    }

    void neighbours(int v, std::vector<int>& out) const
    {
        out.clear();
        for (int f : mesh_.facesOf(v))
            for (int w : mesh_.face(f))
                if (w != v) out.push_back(w);
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
    }

    // Cost of removing `from` into `to` (infinite when not allowed by the lock or the error
    // bound), given q = the sum of both ends' quadrics (the same either way: the sums commute).
    double cost(int from, int to, const Quadric& q) const
    {
        if (locked_[from]) return std::numeric_limits<double>::infinity();
        const double error = q.error(position(to));
        if (q.area > 0 && error > params_.maxError * params_.maxError * q.area) return std::numeric_limits<double>::infinity();
        return error + kLengthWeight * q.area * (position(from) - position(to)).squaredNorm();
    }

    //! The cheaper direction of collapsing edge (u, w); false when neither is allowed.
    bool edgeCandidate(int u, int w, Candidate& out) const
    {
        if (locked_[u] && locked_[w]) return false;
        Quadric q = quadric_[u];
        q += quadric_[w];
        const double uw = cost(u, w, q), wu = cost(w, u, q);
        const bool forward = uw < wu || (uw == wu && u < w);
        const double best = forward ? uw : wu;
        if (!std::isfinite(best)) return false;
        const int from = forward ? u : w, to = forward ? w : u;
        out = {orderKey(best), from, to, version_[from], version_[to]};
        return true;
    }
    bool pushEdge(int u, int w)
    {
        Candidate c;
        if (!edgeCandidate(u, w, c)) return false;
        heap_.push_back(c);
        std::push_heap(heap_.begin(), heap_.end(), std::greater<Candidate>());
        return true;
    }

    bool collapseAllowed(int from, int to)
    {
        // The two faces of edge (from, to) and their opposite corners.
        int shared = 0;
        int opposite[2] = {-1, -1};
        for (int f : mesh_.facesOf(from)) {
            const Face& t = mesh_.face(f);
            if (!mesh_.hasCorner(f, to)) continue;
            if (shared == 2) return false;
            for (int v : t)
                if (v != from && v != to) opposite[shared] = v;
            ++shared;
        }
        if (shared != 2) return false;  // a border edge (its ends are locked anyway) or not an edge
        // Link condition: the only common neighbours are the two opposite corners, else the
        // collapse pinches the surface.
        neighbours(from, ringFrom_);
        neighbours(to, ringTo_);
        int common = 0;
        for (size_t i = 0, j = 0; i < ringFrom_.size() && j < ringTo_.size();) {
            if (ringFrom_[i] < ringTo_[j])
                ++i;
            else if (ringFrom_[i] > ringTo_[j])
                ++j;
            else {
                if (ringFrom_[i] != opposite[0] && ringFrom_[i] != opposite[1]) return false;
                ++common, ++i, ++j;
            }
        }
        if (common != 2) return false;
        // The opposite corners lose a face: keep at least three around each (no fins).
        for (int v : opposite)
            if (mesh_.facesOf(v).size() < 4) return false;
        // The moved faces: no flip, no sharp turn, no new sliver.
        double worstBefore = 1;
        for (int f : mesh_.facesOf(from)) {
            const Face& t = mesh_.face(f);
            worstBefore = std::min(worstBefore, meanRatio(position(t[0]), position(t[1]), position(t[2])));
        }
        for (int f : mesh_.facesOf(from)) {
            Face t = mesh_.face(f);
            if (t[0] == to || t[1] == to || t[2] == to) continue;
            const Vec3 before = (position(t[1]) - position(t[0])).cross(position(t[2]) - position(t[0]));
            for (int& v : t)
                if (v == from) v = to;
            const Vec3 after = (position(t[1]) - position(t[0])).cross(position(t[2]) - position(t[0]));
            const double lengths = before.norm() * after.norm();
            if (!(lengths > 0) || before.dot(after) < kMinNormalCosine * lengths) return false;
            const double ratio = meanRatio(position(t[0]), position(t[1]), position(t[2]));
            if (ratio < kMinMeanRatio && ratio < worstBefore * (1 - 1e-6))
                return false;  // margin: equal shapes of a regular mesh
        }
        return true;
    }

    void collapse(int from, int to)
    {
        // The two faces of the edge go, the others of `from` take `to` in its place.
        faces_ = mesh_.facesOf(from);
        for (int f : faces_) {
            if (mesh_.hasCorner(f, to)) {
                mesh_.killFace(f);
                --aliveFaces_;
            } else {
                mesh_.renameCorner(f, from, to);
            }
        }
        quadric_[to] += quadric_[from];
        ++version_[to];
        ++version_[from];
    }

    SimplifyResult compact() const
    {
        SimplifyResult result;
        const int n = mesh_.vertexCount();
        result.coarseVertex.assign(n, -1);
        for (int v = 0; v < n; ++v) {
            if (!vertexAlive(v)) continue;
            result.coarseVertex[v] = static_cast<int>(result.inputVertex.size());
            result.inputVertex.push_back(v);
            result.mesh.vertices.push_back(position(v));
        }
        for (int f = 0; f < mesh_.faceCount(); ++f) {
            if (!mesh_.faceAlive(f)) continue;
            const Face& t = mesh_.face(f);
            result.mesh.faces.push_back({result.coarseVertex[t[0]], result.coarseVertex[t[1]], result.coarseVertex[t[2]]});
        }
        return result;
    }

    const SimplifyParams& params_;
    EditableMesh<> mesh_;  //!< collapses rename corners in place: a face keeps its index
    std::vector<char> locked_;
    std::vector<Quadric> quadric_;
    std::vector<std::uint32_t> version_;
    std::vector<Candidate> heap_;  //!< a binary min-heap (std::greater) of collapses, stale ones included
    std::vector<int> ringFrom_, ringTo_, faces_;
    int aliveFaces_ = 0;
};

//! The blocks stop this much above their share of the target: the last, whole-mesh pass has
//! that many collapses left for the bands along the blocks' frontiers, which the blocks keep at
//! the input's resolution (their edges are the shortest, so they go first there).
constexpr double kBlockTargetSlack = 0.15;

//! Each block's share of the target is at least this many faces: the frontier band a block
//! keeps at the input's resolution must stay small against what the block gives (an icosphere
//! of 81 920 faces to 4 000 in 8 blocks: Q_avg 0.64 against one pass's 0.72; in 4 blocks of
//! 2 500 faces each, to 10 000, 0.694 against 0.695).
constexpr int kMinBlockTargetFaces = 2500;

//! Per face, its block: `blocks` runs of equal length along a Morton curve of face centroids.
std::vector<int> faceBlocks(const TriMesh& input, int blocks)
{
    std::vector<Vec3> centroids(input.faces.size());
    for (size_t f = 0; f < input.faces.size(); ++f) {
        const Face& t = input.faces[f];
        centroids[f] = (input.vertices[size_t(t[0])] + input.vertices[size_t(t[1])] + input.vertices[size_t(t[2])]) / 3.0;
    }
    const std::vector<int> order = mortonIndexOrder(centroids);
    std::vector<int> block(input.faces.size());
    for (size_t i = 0; i < order.size(); ++i) block[size_t(order[i])] = static_cast<int>(i * size_t(blocks) / order.size());
    return block;
}

//! Vertices no block may remove: those with faces in several blocks (the frontier) and their
//! neighbours. A removed vertex then has its whole neighbourhood in its block, where the link
//! condition and the flip checks see all of it, and the frontier's vertices stay untouched.
struct BlockLocks {
    std::vector<char> locked;    //!< per input vertex: the caller's locks, the frontier and its neighbours
    std::vector<char> frontier;  //!< per input vertex: it has faces in several blocks
};

BlockLocks blockLocks(const TriMesh& input, const std::vector<int>& block, const std::vector<char>& locked)
{
    const size_t n = input.vertices.size();
    std::vector<int> owner(n, -1);
    BlockLocks locks{locked.empty() ? std::vector<char>(n, 0) : locked, std::vector<char>(n, 0)};
    for (size_t f = 0; f < input.faces.size(); ++f)
        for (int v : input.faces[f]) {
            if (owner[size_t(v)] < 0) owner[size_t(v)] = block[f];
            if (owner[size_t(v)] != block[f]) locks.frontier[size_t(v)] = 1;
        }
    for (const Face& t : input.faces)
        if (locks.frontier[size_t(t[0])] || locks.frontier[size_t(t[1])] || locks.frontier[size_t(t[2])])
            for (int v : t) locks.locked[size_t(v)] = 1;
    return locks;
}

//! Large inputs: each block simplified on its own (in parallel), then one pass over their
//! merged result, continuing with their quadrics, to the target. The blocks depend on the input
//! only, and the merge is in block order: the result does not depend on the thread count.
SimplifyResult simplifyInBlocks(const TriMesh& input, const SimplifyParams& params, int blocks)
{
    const std::vector<int> block = faceBlocks(input, blocks);
    const BlockLocks locks = blockLocks(input, block, params.locked);
    const size_t n = input.vertices.size();
    std::vector<std::vector<int>> blockFaces(static_cast<size_t>(blocks));
    for (size_t f = 0; f < input.faces.size(); ++f) blockFaces[size_t(block[f])].push_back(static_cast<int>(f));

    std::vector<SimplifyResult> parts(static_cast<size_t>(blocks));
    std::vector<std::vector<int>> partVertices(static_cast<size_t>(blocks));  // per part vertex: its input vertex
    std::vector<std::vector<Quadric>> partQuadrics(static_cast<size_t>(blocks));
#pragma omp parallel for schedule(dynamic, 1)
    for (int b = 0; b < blocks; ++b) {
        const std::vector<int>& faces = blockFaces[size_t(b)];
        std::vector<int>& vertices = partVertices[size_t(b)];
        for (int f : faces) vertices.insert(vertices.end(), input.faces[size_t(f)].begin(), input.faces[size_t(f)].end());
        std::sort(vertices.begin(), vertices.end());
        vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
        auto local = [&](int v) {
            return static_cast<int>(std::lower_bound(vertices.begin(), vertices.end(), v) - vertices.begin());
        };
        TriMesh sub;
        SimplifyParams subParams = params;
        subParams.blockFaces = 0;
        subParams.locked.resize(vertices.size());
        for (size_t i = 0; i < vertices.size(); ++i) {
            sub.vertices.push_back(input.vertices[size_t(vertices[i])]);
            subParams.locked[i] = locks.locked[size_t(vertices[i])];
        }
        int band = 0;  // faces at the frontier: no collapse in the block can remove them
        for (int f : faces) {
            const Face& t = input.faces[size_t(f)];
            sub.faces.push_back({local(t[0]), local(t[1]), local(t[2])});
            band += locks.frontier[size_t(t[0])] || locks.frontier[size_t(t[1])] || locks.frontier[size_t(t[2])];
        }
        // The rest of the block goes to the input's ratio (plus the slack); the band to the last pass.
        const double ratio = double(params.targetFaces) / double(input.faces.size());
        subParams.targetFaces = band + static_cast<int>(std::ceil((int(faces.size()) - band) * ratio * (1 + kBlockTargetSlack)));
        parts[size_t(b)] = Simplifier(sub, subParams).run(&partQuadrics[size_t(b)]);
    }

    // Merged: the kept vertices in input order, a frontier vertex's quadric summed over its blocks
    // (each block's holds the block's faces around it; no block removes or extends it).
    std::vector<int> mergedIndex(n, -1);
    for (int b = 0; b < blocks; ++b)
        for (int v : parts[size_t(b)].inputVertex) mergedIndex[size_t(partVertices[size_t(b)][size_t(v)])] = 0;
    std::vector<int> mergedToInput;
    for (size_t v = 0; v < n; ++v)
        if (mergedIndex[v] == 0) {
            mergedIndex[v] = static_cast<int>(mergedToInput.size());
            mergedToInput.push_back(static_cast<int>(v));
        }
    TriMesh merged;
    std::vector<Quadric> quadrics(mergedToInput.size());
    SimplifyParams mergedParams = params;
    mergedParams.blockFaces = 0;
    mergedParams.locked.assign(mergedToInput.size(), 0);
    for (size_t i = 0; i < mergedToInput.size(); ++i) {
        merged.vertices.push_back(input.vertices[size_t(mergedToInput[i])]);
        if (!params.locked.empty()) mergedParams.locked[i] = params.locked[size_t(mergedToInput[i])];
    }
    for (int b = 0; b < blocks; ++b) {
        const SimplifyResult& part = parts[size_t(b)];
        auto toMerged = [&](int v) { return mergedIndex[size_t(partVertices[size_t(b)][size_t(part.inputVertex[size_t(v)])])]; };
        for (const Face& t : part.mesh.faces) merged.faces.push_back({toMerged(t[0]), toMerged(t[1]), toMerged(t[2])});
        for (size_t v = 0; v < part.inputVertex.size(); ++v)
            quadrics[size_t(toMerged(static_cast<int>(v)))] += partQuadrics[size_t(b)][v];
    }
    parts.clear();

    SimplifyResult result = Simplifier(merged, mergedParams, std::move(quadrics)).run();
    for (int& v : result.inputVertex) v = mergedToInput[size_t(v)];
    result.coarseVertex.assign(n, -1);
    for (size_t v = 0; v < result.inputVertex.size(); ++v)
        result.coarseVertex[size_t(result.inputVertex[v])] = static_cast<int>(v);
    return result;
}

}  // namespace

SimplifyResult simplifyMesh(const TriMesh& input, const SimplifyParams& params)
{
    if (params.targetFaces < 0) throw InvalidInputError("simplify: the target face count must be >= 0");
    if (!(params.maxError >= 0)) throw InvalidInputError("simplify: the error bound must be >= 0");
    if (params.blockFaces < 0) throw InvalidInputError("simplify: the block size must be >= 0");
    const int blocks = simplifyBlockCount(input.faceCount(), params);
    if (blocks >= 2) return simplifyInBlocks(checked(input, params), params, blocks);
    return Simplifier(input, params).run();
}

int simplifyBlockCount(int faceCount, const SimplifyParams& params)
{
    const int blocks =
        params.blockFaces > 0 ? std::min(faceCount / params.blockFaces, params.targetFaces / kMinBlockTargetFaces) : 1;
    return blocks >= 2 && faceCount > params.targetFaces ? blocks : 1;
}

}  // namespace fieldcvt
