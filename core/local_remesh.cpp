// Isotropic remeshing by local operations that keep the topology (local_remesh.h). The input
// surface side (projections on the own sheet, the border loops and feature lines as curves) is
// class Surface; the mesh being remeshed and its operations are class Remesher.
#include "local_remesh.h"

#include "local_remesh_surface.h"

#include "editable_mesh.h"
#include "boundary.h"
#include "closest_point.h"
#include "errors.h"
#include "triangle_shape.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>

namespace fieldcvt {
namespace {

using local_remesh_detail::Spot;
using local_remesh_detail::StartMesh;
using local_remesh_detail::Surface;
using local_remesh_detail::VertexInfo;

constexpr double kSplitRatio = 4.0 / 3.0;
constexpr double kCollapseRatio = 4.0 / 5.0;
//! A collapse may turn a face's normal by at most 60° (the cosine).
constexpr double kMaxTurnCos = 0.5;
//! A collapse whose new triangles have a smaller angle than this (radians, 10°) and than half
//! the smallest angle around the removed vertex is refused: it would make a sliver. (20° and
//! 3/4 left a thin torus, r = target, at its input's 8000 vertices: no collapse passed.)
constexpr double kCollapseAngle = 10.0 * kPi / 180.0;
//! A collapse may leave the removed vertex at most this far (a fraction of the target length)
//! from the new triangles.
constexpr double kCollapseSag = 0.1;
//! A flip may not make the fold between its two triangles sharper than this (cos 60°) unless
//! it was already.
constexpr double kFlipFoldCos = 0.5;
//! Two triangles around a vertex turned more than 60° from each other make it a crease vertex.
constexpr double kCreaseCos = 0.5;
//! removeSlivers' threshold (radians, 15°: issue 52 item 4's smallest angle).
constexpr double kSliverAngle = 15.0 * kPi / 180.0;
//! clipEar cuts off a border spike whose tip is at most this far (a fraction of the target
//! length) from the edges opposite it: what the border loses there. lato180's two spikes, 10.3°
//! and 12.8°, are 1.1 and 0.9 targets high; issue 52 item 2 keeps every input point within 2
//! edge lengths of the output.
constexpr double kEarHeight = 1.5;
//! Meshes smaller than this are smoothed on one thread: a parallel region costs more there
//! (idle threads spin at its barriers, worse on a busy machine).
constexpr int kParallelVertices = 2000;
//! Smoothing steps per round (as pmp-library's uniform remeshing).
constexpr int kSmoothingSteps = 5;

Vec3 triangleNormal(const Vec3& a, const Vec3& b, const Vec3& c) { return (b - a).cross(c - a); }

double unitDot(const Vec3& u, const Vec3& v)
{
    const double n = u.norm() * v.norm();
    return n > 0 ? u.dot(v) / n : -1.0;
}

//! The corner k of face t whose side k -> k + 1 is the edge a - b (either way).
int sideOf(const Face& t, int a, int b)
{
    for (int k = 0; k < 2; ++k)
        if ((t[k] == a || t[k] == b) && (t[k + 1] == a || t[k + 1] == b)) return k;
    return 2;
}

void replaceIn(std::vector<int>& list, int from, int to)
{
    for (int& x : list)
        if (x == from) x = to;
}

//! The mesh being remeshed (the selected faces at the start) and the operations on it. Every
//! pass runs over its vertices, faces or candidate edges in index order and only the smoothing
//! runs in parallel (each vertex computed from the positions before the step): the result does
//! not depend on the thread count.
class Remesher {
public:
    explicit Remesher(const Surface& surface);
    void run(int iterations);
    LocalRemeshResult takeResult();

private:
    using Mesh = EditableMesh<VertexInfo>;
    struct Candidate {
        double length;
        int a, b;
    };

    double targetAt(int v) const { return mesh_.data(v).target; }
    double edgeTarget(int a, int b) const { return 0.5 * (targetAt(a) + targetAt(b)); }
    double length(int a, int b) const { return (mesh_.position(a) - mesh_.position(b)).norm(); }
    Vec3 faceNormal(int f) const
    {
        const Face& t = mesh_.face(f);
        return triangleNormal(mesh_.position(t[0]), mesh_.position(t[1]), mesh_.position(t[2]));
    }
    bool isFeatureEdge(int a, int b) const
    {
        return std::find(featureNbrs_[a].begin(), featureNbrs_[a].end(), b) != featureNbrs_[a].end();
    }
    //! v's neighbour along its feature line other than `other` (-1 if none).
    int otherFeature(int v, int other) const
    {
        for (int x : featureNbrs_[v])
            if (x != other) return x;
        return -1;
    }
    //! The two neighbours of border vertex v along its loop (an edge with one face each).
    void borderNeighbours(int v, int& u, int& w) const;
    //! The distinct neighbours of v, sorted.
    void ring(int v, std::vector<int>& out) const;
    //! The edges (smaller vertex first) whose length `keep(length, a, b)` accepts.
    template <class Keep>
    void collectEdges(Keep keep);

    void splitLongEdges();
    void split(int a, int b);
    void collapseShortEdges();
    //! The smallest angle of the triangles a collapse of a into b would make; -1 if the collapse
    //! would change the topology, a border loop or feature line, or fold or spoil a triangle.
    double collapseQuality(int a, int b);
    void collapse(int a, int b);
    void flipEdges();
    //! Collapses an edge of each triangle with an angle under kSliverAngle whatever its length,
    //! where collapseQuality allows it and the new triangles' smallest angle is larger: the
    //! slivers the length-driven passes leave (a vertex of valence 3 inside a flat triangle,
    //! a needle between two strips); first, a sliver at a spike of the border is cut off
    //! (clipEar).
    void removeSlivers();
    //! Cuts off the border spike at `tip`: a border vertex (a sharp turn of the border is a
    //! corner, which no collapse moves) whose triangles together turn under kSliverAngle, no
    //! more than kEarHeight targets from the edges opposite it. Every triangulation that keeps
    //! such a tip keeps that angle. The tip and its triangles go, the edges opposite it become
    //! the border: the loop, genus and parts stay. `clippedAt` marks the vertices of the spikes
    //! cut so far: none of them is cut as a tip in turn, so a long spike loses one ear, not one
    //! after another.
    bool clipEar(int tip, std::vector<char>& clippedAt);
    bool tryFlip(int a, int b);
    //! Whether flipping a - b into c - d makes the smaller angle of its two triangles larger (the
    //! Delaunay flip, on a surface). Measured against Botsch & Kobbelt's valence flips (6 inside,
    //! 4 on the border) before the same smoothing: θ_min 30.6° against 12.5° on a torus of minor
    //! radius about the target, 41.9° against 26.5° (0 % against 3 % of triangles under 30°) on
    //! a 50 000-face torus; the valences are the valence stage's job afterwards.
    bool flipImproves(int a, int b, int c, int d) const;
    //! One step of tangential smoothing (or, `move` false, the projection alone), then the moves
    //! that would fold a face taken back.
    void smooth(bool move);
    bool moveVertex(int v, bool move, Vec3& p, VertexInfo& info) const;
    //! Whether two triangles around v are turned more than 60° from each other: a sharp edge
    //! the caller gave no feature line for, e.g. the rim of a plate thinner than an edge. Such
    //! a vertex is not smoothed: its one ring lies to one side of it, so its centroid would
    //! pull the rim inwards step after step.
    bool onCrease(int v) const;
    //! Surface::projectFree from v's face, else (refused: e.g. v's face is on the far side of a
    //! thin plate from p's side) from its neighbours' faces, the nearest answer.
    bool projectAround(const Vec3& p, int v, const Vec3& normal, double radius, Spot& out) const;
    //! Drops the dead vertices and faces (indices renumbered in order).
    void compact();

    const Surface& surface_;
    Mesh mesh_;
    std::vector<std::vector<int>> featureNbrs_;  //!< per vertex: its neighbours along feature lines
    std::vector<int> componentVertices_;         //!< per surface component: the vertices it has now
    std::vector<char> componentClosed_;          //!< per surface component: no open border
    std::vector<Vec3> normals_, newPositions_;
    std::vector<VertexInfo> newInfo_;
    std::vector<char> moved_;
    std::vector<int> faces_, ringA_, ringB_, scratch_;
    std::vector<Candidate> candidates_;
    LocalRemeshResult counts_;
};

Remesher::Remesher(const Surface& s) : surface_(s)
{
    StartMesh start = s.startMesh();
    mesh_ = Mesh(std::move(start.positions), std::move(start.faces));
    featureNbrs_ = std::move(start.featureNbrs);
    componentVertices_.assign(s.componentCount, 0);
    componentClosed_.assign(s.componentCount, 1);
    for (int v = 0; v < mesh_.vertexCount(); ++v) {
        const VertexInfo& info = start.info[v];
        if (info.onBorder) componentClosed_[info.component] = 0;
        ++componentVertices_[info.component];
        mesh_.setData(v, info);
    }
}

void Remesher::borderNeighbours(int v, int& u, int& w) const
{
    u = w = -1;
    const std::vector<int>& faces = mesh_.facesOf(v);
    for (int f : faces)
        for (int x : mesh_.face(f)) {
            if (x == v || x == u) continue;
            int count = 0;
            for (int g : faces) count += mesh_.hasCorner(g, x);
            if (count == 1) (u < 0 ? u : w) = x;
        }
}

void Remesher::ring(int v, std::vector<int>& out) const
{
    out.clear();
    for (int f : mesh_.facesOf(v))
        for (int x : mesh_.face(f))
            if (x != v) out.push_back(x);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

template <class Keep>
void Remesher::collectEdges(Keep keep)
{
    candidates_.clear();
    for (int f = 0; f < mesh_.faceCount(); ++f) {
        if (!mesh_.faceAlive(f)) continue;
        const Face t = mesh_.face(f);
        for (int k = 0; k < 3; ++k) {
            const int a = t[k], b = t[(k + 1) % 3];
            // An interior edge once (from the face that runs it from the smaller vertex), a
            // border edge from its only face.
            if (a > b) {
                int count = 0;
                for (int g : mesh_.facesOf(a)) count += mesh_.hasCorner(g, b);
                if (count != 1) continue;
            }
            const double len = length(a, b);
            if (keep(len, a, b)) candidates_.push_back({len, std::min(a, b), std::max(a, b)});
        }
    }
}

void Remesher::splitLongEdges()
{
    for (int pass = 0; pass < 16; ++pass) {
        collectEdges([&](double len, int a, int b) { return len > kSplitRatio * edgeTarget(a, b); });
        if (candidates_.empty()) return;
        // Longest first, ties by index: the same order on every run.
        std::sort(candidates_.begin(), candidates_.end(), [](const Candidate& x, const Candidate& y) {
            return x.length != y.length ? x.length > y.length : std::make_pair(x.a, x.b) < std::make_pair(y.a, y.b);
        });
        for (const Candidate& c : candidates_)
            if (mesh_.hasEdge(c.a, c.b)) split(c.a, c.b);
    }
}

void Remesher::split(int a, int b)
{
    mesh_.edgeFaces(a, b, faces_);
    const VertexInfo A = mesh_.data(a), B = mesh_.data(b);
    const Vec3 pa = mesh_.position(a), pb = mesh_.position(b), mid = 0.5 * (pa + pb);
    const double radius = (pb - pa).norm() + targetAt(a);
    const bool border = faces_.size() == 1, feature = !border && isFeatureEdge(a, b);
    VertexInfo info;
    info.component = A.component;
    info.face = A.face;
    Spot spot;
    bool found;
    if (border || feature) {
        // A new vertex of a border loop or a feature line lies on that curve, found from an end
        // that is not a corner (it lies on one curve), else from the corner's curves.
        info.role = border ? VertexRole::Boundary : VertexRole::Feature;
        info.onBorder = border;
        const VertexInfo& from = A.role != VertexRole::Corner ? A : B;
        if (from.role != VertexRole::Corner) {
            surface_.projectOnCurve(mid, from.curve, radius, spot);
            found = true;
        } else {
            found = surface_.projectFromCorner(mid, A.corner, border, radius, spot);
        }
        info.curve = found ? spot.curve : from.curve;
    } else {
        Vec3 normal = Vec3::Zero();
        for (int f : faces_) normal += faceNormal(f);
        found = projectAround(mid, a, normal, radius, spot);
    }
    Vec3 p = found ? spot.point : mid;
    if (found) info.face = spot.face;
    // The point on the surface must not fold the new triangles over (the midpoint never does).
    for (int f : faces_) {
        const Face& t = mesh_.face(f);
        const int k = sideOf(t, a, b);
        const Vec3 &x = mesh_.position(t[k]), &y = mesh_.position(t[(k + 1) % 3]), &c = mesh_.position(t[(k + 2) % 3]);
        const Vec3 old = triangleNormal(x, y, c);
        if (triangleNormal(x, p, c).dot(old) <= 0 || triangleNormal(p, y, c).dot(old) <= 0) p = mid;
    }
    info.target = surface_.targetAt(p, info.face);
    const int v = mesh_.addVertex(p, info);
    featureNbrs_.emplace_back();
    for (int f : faces_) {
        const Face t = mesh_.face(f);
        const int k = sideOf(t, a, b);
        const int y = t[(k + 1) % 3], c = t[(k + 2) % 3];
        mesh_.renameCorner(f, y, v);  // (x, y, c) -> (x, v, c)
        mesh_.addFace({v, y, c});
    }
    if (feature) {
        replaceIn(featureNbrs_[a], b, v);
        replaceIn(featureNbrs_[b], a, v);
        featureNbrs_[v] = {a, b};
    }
    ++componentVertices_[info.component];
    ++counts_.splits;
}
void Remesher::collapseShortEdges()
{
    for (int pass = 0; pass < 16; ++pass) {
        collectEdges([&](double len, int a, int b) { return len < kCollapseRatio * edgeTarget(a, b); });
        // Shortest first, ties by index.
        std::sort(candidates_.begin(), candidates_.end(), [](const Candidate& x, const Candidate& y) {
            return x.length != y.length ? x.length < y.length : std::make_pair(x.a, x.b) < std::make_pair(y.a, y.b);
        });
        int done = 0;
        for (const Candidate& c : candidates_) {
            if (!mesh_.vertexAlive(c.a) || !mesh_.vertexAlive(c.b) || !mesh_.hasEdge(c.a, c.b)) continue;
            if (length(c.a, c.b) >= kCollapseRatio * edgeTarget(c.a, c.b)) continue;
            // The direction whose triangles come out better.
            const double intoB = collapseQuality(c.a, c.b), intoA = collapseQuality(c.b, c.a);
            if (intoB < 0 && intoA < 0) continue;
            intoB >= intoA ? collapse(c.a, c.b) : collapse(c.b, c.a);
            ++done;
        }
        if (done == 0) return;
    }
}

double Remesher::collapseQuality(int a, int b)
{
    const VertexInfo& A = mesh_.data(a);
    if (A.role == VertexRole::Corner) return -1;
    mesh_.edgeFaces(a, b, faces_);
    const int opposite = static_cast<int>(faces_.size());
    // A border vertex moves only along its loop: never over an interior edge (which, between two
    // border vertices, would pinch the surface or join two loops), never shrinking a loop of 3.
    if (A.onBorder) {
        if (opposite != 1) return -1;
        int u, w, x, y;
        borderNeighbours(a, u, w);
        borderNeighbours(b, x, y);
        const int c = u == b ? w : u, d = x == a ? y : x;
        if (c == d) return -1;
    }
    // A feature vertex moves only along its line, into the next vertex of the same line, and a
    // closed line keeps 3 edges.
    if (A.role == VertexRole::Feature) {
        if (!isFeatureEdge(a, b)) return -1;
        const int c = otherFeature(a, b);
        if (c >= 0 && isFeatureEdge(b, c)) return -1;
    }
    if (componentClosed_[A.component] && componentVertices_[A.component] <= 4) return -1;  // a tetrahedron
    // The link condition: a and b share exactly the opposite vertices of their edge.
    ring(a, ringA_);
    ring(b, ringB_);
    int common = 0;
    for (auto i = ringA_.begin(), j = ringB_.begin(); i != ringA_.end() && j != ringB_.end();)
        if (*i < *j) {
            ++i;
        } else if (*j < *i) {
            ++j;
        } else {
            ++common, ++i, ++j;
        }
    if (common != opposite) return -1;
    const Vec3& pb = mesh_.position(b);
    for (int x : ringA_)
        if (x != b && (mesh_.position(x) - pb).norm() > kSplitRatio * edgeTarget(b, x)) return -1;
    double oldMin = kPi, newMin = kPi, sag2 = std::numeric_limits<double>::infinity();
    const Vec3& pa = mesh_.position(a);
    for (int f : mesh_.facesOf(a)) {
        const Face& t = mesh_.face(f);
        const Vec3 &p0 = mesh_.position(t[0]), &p1 = mesh_.position(t[1]), &p2 = mesh_.position(t[2]);
        oldMin = std::min(oldMin, smallestAngle(p0, p1, p2));
        if (mesh_.hasCorner(f, b)) continue;
        const Vec3& q0 = t[0] == a ? pb : p0;
        const Vec3& q1 = t[1] == a ? pb : p1;
        const Vec3& q2 = t[2] == a ? pb : p2;
        if (unitDot(triangleNormal(p0, p1, p2), triangleNormal(q0, q1, q2)) < kMaxTurnCos) return -1;
        newMin = std::min(newMin, smallestAngle(q0, q1, q2));
        sag2 = std::min(sag2, (closestPointOnTriangle(pa, q0, q1, q2) - pa).squaredNorm());
    }
    // The removed vertex stays near the new triangles: no corner of a thin plate's rim cut off.
    const double sag = kCollapseSag * edgeTarget(a, b);
    if (sag2 > sag * sag) return -1;
    if (newMin < std::min(kCollapseAngle, 0.5 * oldMin)) return -1;
    return newMin;
}

void Remesher::collapse(int a, int b)
{
    const VertexInfo& A = mesh_.data(a);
    mesh_.edgeFaces(a, b, faces_);
    for (int f : faces_) mesh_.killFace(f);
    scratch_ = mesh_.facesOf(a);
    for (int f : scratch_) mesh_.renameCorner(f, a, b);
    if (A.role == VertexRole::Feature) {
        // The line runs c - a - b: now c - b.
        const int c = otherFeature(a, b);
        featureNbrs_[b].erase(std::find(featureNbrs_[b].begin(), featureNbrs_[b].end(), a));
        if (c >= 0) {
            featureNbrs_[b].push_back(c);
            replaceIn(featureNbrs_[c], a, b);
        }
    }
    featureNbrs_[a].clear();
    --componentVertices_[A.component];
    mesh_.killVertex(a);
    ++counts_.collapses;
}

void Remesher::flipEdges()
{
    for (int pass = 0; pass < 8; ++pass) {
        int flipped = 0;
        for (int f = 0; f < mesh_.faceCount(); ++f) {
            if (!mesh_.faceAlive(f)) continue;
            const Face t = mesh_.face(f);
            for (int k = 0; k < 3; ++k)
                if (t[k] < t[(k + 1) % 3]) flipped += tryFlip(t[k], t[(k + 1) % 3]);
        }
        if (flipped == 0) return;
    }
}

bool Remesher::tryFlip(int a, int b)
{
    if (isFeatureEdge(a, b)) return false;
    mesh_.edgeFaces(a, b, faces_);
    if (faces_.size() != 2) return false;
    // f1 = (a, b, c) runs a -> b, f2 = (b, a, d); after the flip (a, d, c) and (d, b, c).
    int f1 = faces_[0], f2 = faces_[1];
    auto third = [&](int f) { return mesh_.face(f)[0] + mesh_.face(f)[1] + mesh_.face(f)[2] - a - b; };
    {
        const Face& t = mesh_.face(f1);
        const int k = t[0] == a ? 0 : (t[1] == a ? 1 : 2);
        if (t[(k + 1) % 3] != b) std::swap(f1, f2);
    }
    const int c = third(f1), d = third(f2);
    if (c == d || mesh_.hasEdge(c, d)) return false;
    const Vec3 &pa = mesh_.position(a), &pb = mesh_.position(b), &pc = mesh_.position(c), &pd = mesh_.position(d);
    const Vec3 o1 = triangleNormal(pa, pb, pc), o2 = triangleNormal(pb, pa, pd);
    const Vec3 n1 = triangleNormal(pa, pd, pc), n2 = triangleNormal(pd, pb, pc);
    // Neither new triangle turned over, and no sharper fold between them than there was.
    // The two faces' normals weighted by area: a face flat to rounding (a split's midpoint left
    // on its edge) has no direction of its own to hold the flip that mends it.
    const Vec3 o = o1 + o2;
    if (n1.dot(o) <= 0 || n2.dot(o) <= 0) return false;
    if (unitDot(n1, n2) < std::min(unitDot(o1, o2), kFlipFoldCos)) return false;
    if (!flipImproves(a, b, c, d)) return false;
    mesh_.renameCorner(f1, b, d);
    mesh_.renameCorner(f2, a, c);
    ++counts_.flips;
    return true;
}

bool Remesher::flipImproves(int a, int b, int c, int d) const
{
    const Vec3 &pa = mesh_.position(a), &pb = mesh_.position(b), &pc = mesh_.position(c), &pd = mesh_.position(d);
    const double oldMin = std::min(smallestAngle(pa, pb, pc), smallestAngle(pb, pa, pd));
    const double newMin = std::min(smallestAngle(pa, pd, pc), smallestAngle(pd, pb, pc));
    return newMin > oldMin * (1 + 1e-9);
}

void Remesher::smooth(bool move)
{
    const int n = mesh_.vertexCount();
    normals_.assign(n, Vec3::Zero());
    newPositions_.resize(n);
    newInfo_.resize(n);
    moved_.assign(n, 0);
#pragma omp parallel for schedule(static) if (n >= kParallelVertices)
    for (int v = 0; v < n; ++v)
        for (int f : mesh_.facesOf(v)) normals_[v] += faceNormal(f);
#pragma omp parallel for schedule(dynamic, 256) if (n >= kParallelVertices)
    for (int v = 0; v < n; ++v)
        if (mesh_.vertexAlive(v)) moved_[v] = moveVertex(v, move, newPositions_[v], newInfo_[v]);
    // Take back the moves of any face that would turn over (then its neighbours are checked
    // again with it where it was): at worst every vertex stays, which folds nothing.
    for (bool again = true; again;) {
        again = false;
        for (int f = 0; f < mesh_.faceCount(); ++f) {
            if (!mesh_.faceAlive(f)) continue;
            const Face& t = mesh_.face(f);
            if (!moved_[t[0]] && !moved_[t[1]] && !moved_[t[2]]) continue;
            auto at = [&](int v) -> const Vec3& { return moved_[v] ? newPositions_[v] : mesh_.position(v); };
            if (triangleNormal(at(t[0]), at(t[1]), at(t[2])).dot(faceNormal(f)) > 0) continue;
            moved_[t[0]] = moved_[t[1]] = moved_[t[2]] = 0;
            again = true;
        }
    }
    for (int v = 0; v < n; ++v)
        if (moved_[v]) mesh_.setVertex(v, newPositions_[v], newInfo_[v]);
}

bool Remesher::moveVertex(int v, bool move, Vec3& p, VertexInfo& info) const
{
    const VertexInfo& own = mesh_.data(v);
    const Vec3& x = mesh_.position(v);
    info = own;
    if (own.role == VertexRole::Corner) return false;
    Spot spot;
    if (own.role == VertexRole::Free) {
        // Towards the area-weighted centroid of its triangles, in its tangent plane.
        Vec3 q = x;
        if (move && !onCrease(v)) {
            Vec3 sum = Vec3::Zero();
            double area = 0;
            for (int f : mesh_.facesOf(v)) {
                const Face& t = mesh_.face(f);
                const double w = faceNormal(f).norm();
                sum += w * (mesh_.position(t[0]) + mesh_.position(t[1]) + mesh_.position(t[2])) / 3.0;
                area += w;
            }
            if (area > 0) {
                const Vec3 normal = normals_[v].normalized(), d = sum / area - x;
                q = x + d - normal * normal.dot(d);
            }
        }
        if (!projectAround(q, v, normals_[v], (q - x).norm() + 0.5 * targetAt(v), spot)) return false;
    } else {
        // Towards the middle of its two neighbours along its border loop or feature line.
        int u = -1, w = -1;
        if (own.role == VertexRole::Boundary) {
            borderNeighbours(v, u, w);
        } else if (featureNbrs_[v].size() == 2) {
            u = featureNbrs_[v][0], w = featureNbrs_[v][1];
        }
        const Vec3 q = move && u >= 0 && w >= 0 ? Vec3(0.5 * (mesh_.position(u) + mesh_.position(w))) : x;
        surface_.projectOnCurve(q, own.curve, (q - x).norm() + targetAt(v), spot);
        info.curve = spot.curve;
    }
    p = spot.point;
    info.face = spot.face;
    info.target = surface_.targetAt(p, info.face);
    return true;
}

bool Remesher::onCrease(int v) const
{
    const std::vector<int>& faces = mesh_.facesOf(v);
    for (std::size_t i = 0; i < faces.size(); ++i)
        for (std::size_t j = i + 1; j < faces.size(); ++j)
            if (unitDot(faceNormal(faces[i]), faceNormal(faces[j])) < kCreaseCos) return true;
    return false;
}

bool Remesher::projectAround(const Vec3& p, int v, const Vec3& normal, double radius, Spot& out) const
{
    const int own = mesh_.data(v).face;
    if (surface_.projectFree(p, own, normal, radius, out)) return true;
    double best2 = std::numeric_limits<double>::infinity();
    for (int f : mesh_.facesOf(v))
        for (int x : mesh_.face(f)) {
            const int face = mesh_.data(x).face;
            Spot spot;
            if (face == own || !surface_.projectFree(p, face, normal, radius, spot)) continue;
            if ((spot.point - p).squaredNorm() < best2) best2 = (spot.point - p).squaredNorm(), out = spot;
        }
    return best2 < std::numeric_limits<double>::infinity();
}

void Remesher::compact()
{
    const int n = mesh_.vertexCount();
    std::vector<int> index(n, -1);
    std::vector<Vec3> positions;
    std::vector<VertexInfo> infos;
    std::vector<std::vector<int>> nbrs;
    for (int v = 0; v < n; ++v) {
        if (!mesh_.vertexAlive(v)) continue;
        index[v] = static_cast<int>(positions.size());
        positions.push_back(mesh_.position(v));
        infos.push_back(mesh_.data(v));
    }
    for (int v = 0; v < n; ++v) {
        if (index[v] < 0) continue;
        nbrs.push_back(featureNbrs_[v]);
        for (int& x : nbrs.back()) x = index[x];
    }
    std::vector<Face> faces;
    for (int f = 0; f < mesh_.faceCount(); ++f)
        if (mesh_.faceAlive(f)) faces.push_back({index[mesh_.face(f)[0]], index[mesh_.face(f)[1]], index[mesh_.face(f)[2]]});
    mesh_ = Mesh(std::move(positions), std::move(faces));
    for (int v = 0; v < mesh_.vertexCount(); ++v) mesh_.setData(v, infos[v]);
    featureNbrs_ = std::move(nbrs);
}

void Remesher::run(int iterations)
{
    for (int round = 0; round < iterations; ++round) {
        splitLongEdges();
        collapseShortEdges();
        flipEdges();
        for (int step = 0; step < kSmoothingSteps; ++step) smooth(true);
        compact();
    }
    smooth(false);  // every vertex that moved by a split and no smoothing since onto the surface
    flipEdges();    // the last smoothing steps may have left a face flat that a flip mends
    removeSlivers();
    flipEdges();
}

void Remesher::removeSlivers()
{
    std::vector<char> clippedAt(mesh_.vertexCount(), 0);
    for (int pass = 0; pass < 4; ++pass) {
        int done = 0;
        for (int f = 0; f < mesh_.faceCount(); ++f) {
            if (!mesh_.faceAlive(f)) continue;
            const Face t = mesh_.face(f);
            const double smallest = smallestAngle(mesh_.position(t[0]), mesh_.position(t[1]), mesh_.position(t[2]));
            if (smallest >= kSliverAngle) continue;
            if (clipEar(t[0], clippedAt) || clipEar(t[1], clippedAt) || clipEar(t[2], clippedAt)) {
                ++done;
                continue;
            }
            // The collapse of one of its edges, either way, whose triangles come out best.
            double best = smallest;
            int from = -1, into = -1;
            for (int k = 0; k < 3; ++k) {
                const int a = t[k], b = t[(k + 1) % 3];
                const double intoB = collapseQuality(a, b), intoA = collapseQuality(b, a);
                if (intoB > best) best = intoB, from = a, into = b;
                if (intoA > best) best = intoA, from = b, into = a;
            }
            if (from < 0) continue;
            collapse(from, into);
            ++done;
        }
        if (done == 0) return;
    }
}

bool Remesher::clipEar(int tip, std::vector<char>& clippedAt)
{
    const VertexInfo info = mesh_.data(tip);
    if (!info.onBorder || !featureNbrs_[tip].empty() || clippedAt[tip]) return false;
    int a, b;
    borderNeighbours(tip, a, b);
    if (a < 0 || b < 0) return false;
    // The whole turn of the border at the tip, over all its triangles.
    const Vec3& pt = mesh_.position(tip);
    double turn = 0, height2 = std::numeric_limits<double>::infinity();
    for (int f : mesh_.facesOf(tip)) {
        const Face& t = mesh_.face(f);
        const int k = t[0] == tip ? 0 : t[1] == tip ? 1 : 2;
        const Vec3 &p = mesh_.position(t[(k + 1) % 3]), &q = mesh_.position(t[(k + 2) % 3]);
        turn += std::atan2((p - pt).cross(q - pt).norm(), (p - pt).dot(q - pt));
        double d2 = 0;
        closestPointOnSegment(pt, {p, q}, &d2);
        height2 = std::min(height2, d2);  // to the new border: the edges opposite the tip
    }
    if (turn >= kSliverAngle || height2 > std::pow(kEarHeight * targetAt(tip), 2)) return false;
    // The tip's other neighbours join the border: none may be on it already (that would pinch
    // it), and with none, the ear's third edge must have a face beyond (not a lone triangle).
    ring(tip, ringA_);
    for (int m : ringA_) {
        if (m == a || m == b) continue;
        int u, w;
        borderNeighbours(m, u, w);
        if (u >= 0) return false;
    }
    if (ringA_.size() == 2) {
        mesh_.edgeFaces(a, b, faces_);
        if (faces_.size() != 2) return false;
    }
    scratch_ = mesh_.facesOf(tip);
    for (int f : scratch_) mesh_.killFace(f);
    for (int m : ringA_) {
        clippedAt[m] = 1;
        VertexInfo joined = mesh_.data(m);
        if (joined.onBorder) continue;
        joined.role = VertexRole::Boundary;
        joined.onBorder = true;
        joined.curve = info.curve;
        mesh_.setData(m, joined);
    }
    --componentVertices_[info.component];
    mesh_.killVertex(tip);
    ++counts_.collapses;
    return true;
}

LocalRemeshResult Remesher::takeResult()
{
    compact();
    LocalRemeshResult result = counts_;
    result.mesh.vertices = mesh_.positions();
    result.mesh.faces.resize(mesh_.faceCount());
    for (int f = 0; f < mesh_.faceCount(); ++f) result.mesh.faces[f] = mesh_.face(f);
    for (int v = 0; v < mesh_.vertexCount(); ++v) {
        result.roles.push_back(mesh_.data(v).role);
        result.vertexFaceHints.push_back(mesh_.data(v).face);
    }
    return result;
}

void validate(const LocalRemeshInput& input, const LocalRemeshParams& params)
{
    auto fail = [](const std::string& what) { throw InvalidInputError("local remeshing: " + what); };
    const TriMesh& surface = input.surface;
    const int nv = surface.vertexCount(), nf = surface.faceCount();
    if (!(params.targetLength > 0) || !std::isfinite(params.targetLength))
        fail("the target edge length must be positive and finite (it is " + std::to_string(params.targetLength) + ")");
    if (params.iterations < 0) fail("the number of iterations is negative (" + std::to_string(params.iterations) + ")");
    const std::vector<double>& lengths = input.targetLengthPerFace;
    if (!lengths.empty() && lengths.size() != surface.faces.size())
        fail("there are " + std::to_string(lengths.size()) + " target lengths per face for a surface of " + std::to_string(nf) +
             " faces");
    for (double l : lengths)
        if (!(l > 0) || !std::isfinite(l))
            fail("a target length per face is not positive and finite (" + std::to_string(l) + ")");
    for (const auto& e : input.featureEdges)
        if (e[0] < 0 || e[0] >= nv || e[1] < 0 || e[1] >= nv) fail("a feature edge has a vertex index out of range");
    for (int c : input.corners)
        if (c < 0 || c >= nv) fail("a corner has a vertex index out of range (" + std::to_string(c) + ")");
    local_remesh_detail::checkSelection(surface, input.selectedFaces);
}

}  // namespace

LocalRemeshResult remeshLocally(const LocalRemeshInput& input, const LocalRemeshParams& params)
{
    validate(input, params);
    if (std::find(input.selectedFaces.begin(), input.selectedFaces.end(), 1) == input.selectedFaces.end()) return {};
    Surface surface(input.surface, input.tree, input.selectedFaces, input.targetLengthPerFace, params.targetLength);
    surface.addCurves(input.featureEdges, input.corners);
    std::unique_ptr<StripSizing> strips;
    if (params.refineStrips) {
        strips = std::make_unique<StripSizing>(input.surface, input.selectedFaces, params.targetLength, params.strips);
        if (strips->sources() > 0) surface.setStripSizing(strips.get());
    }
    Remesher remesher(surface);
    remesher.run(params.iterations);
    return remesher.takeResult();
}

}  // namespace fieldcvt
