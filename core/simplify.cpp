#include "simplify.h"

#include "editable_mesh.h"
#include "errors.h"
#include "mesh_edges.h"
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

class Simplifier {
public:
    Simplifier(const TriMesh& input, const SimplifyParams& params)
        : params_(params), mesh_(checked(input, params).vertices, input.faces)
    {
        const int n = input.vertexCount();
        locked_.assign(n, 0);
        for (int v = 0; v < n && !params.locked.empty(); ++v) locked_[v] = params.locked[v];
        quadric_.assign(n, {});
        version_.assign(n, 0);
        for (int f = 0; f < mesh_.faceCount(); ++f) {
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

    SimplifyResult run()
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
            // Each push makes the edge's previous entry stale (bunny 5000: 158 000 of 184 000
            // pops were stale entries). Dropping them in one linear pass once the pushes since
            // the last pass reach half the heap costs less than popping them one by one; the
            // current entries pop in the same order (the order is total on them), so the result
            // is the same. Bunny 5000's simplification 111 -> 74 ms (medians of 9, one thread;
            // a pass at a quarter of the heap 91 ms, at the whole heap 82 ms).
            if (2 * pushesSinceCompaction > heap_.size()) {
                heap_.erase(std::remove_if(heap_.begin(), heap_.end(), [&](const Candidate& e) { return !current(e); }),
                            heap_.end());
                std::make_heap(heap_.begin(), heap_.end(), std::greater<Candidate>());
                pushesSinceCompaction = 0;
            }
        }
        return compact();
    }

private:
    static const TriMesh& checked(const TriMesh& input, const SimplifyParams& params)
    {
        if (!params.locked.empty() && params.locked.size() != size_t(input.vertexCount()))
            throw InvalidInputError("simplify: the locked flags have " + std::to_string(params.locked.size()) + " entries for " +
                                    std::to_string(input.vertexCount()) + " vertices");
        return input;
    }
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

}  // namespace

SimplifyResult simplifyMesh(const TriMesh& input, const SimplifyParams& params)
{
    if (params.targetFaces < 0) throw InvalidInputError("simplify: the target face count must be >= 0");
    if (!(params.maxError >= 0)) throw InvalidInputError("simplify: the error bound must be >= 0");
    return Simplifier(input, params).run();
}

}  // namespace fieldcvt
