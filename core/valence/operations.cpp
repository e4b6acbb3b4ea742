#include "valence/operations.h"

#include <algorithm>

namespace fieldcvt::valence {

size_t CandidateHash::operator()(const Candidate& k) const
{
    std::uint64_t h = static_cast<std::uint64_t>(k.length);
    for (int i = 0; i < k.length; ++i) {
        const Op& op = k.ops[i];
        for (std::int64_t x :
             {static_cast<std::int64_t>(op.type), static_cast<std::int64_t>(op.a), static_cast<std::int64_t>(op.b),
              static_cast<std::int64_t>(op.c), static_cast<std::int64_t>(op.gain)})
            h = (h ^ static_cast<std::uint64_t>(x)) * 0x100000001B3ull + 0x9E3779B97F4A7C15ull;
    }
    return static_cast<size_t>(h);
}

namespace {

//! ΔR of splitting v, of ring size n, into valences s + 2 (v, keeping ring[i..j]) and n − s + 2
//! (the new vertex), which adds an edge at a = ring[i] and b = ring[j].
int splitGain(const ValenceMesh& mesh, int n, int s, int a, int b)
{
    const int keptValence = s + 2, newValence = n - s + 2;
    const int before = n - 6;
    return (keptValence - 6) * (keptValence - 6) + (newValence - 6) * (newValence - 6) - before * before +
           mesh.valenceDelta(a, +1) + mesh.valenceDelta(b, +1);
}

}  // namespace

bool evaluateFlip(const ValenceMesh& mesh, int a, int b, int& gain, int& c, int& d, int& f1, int& f2)
{
    if (!mesh.data(a).manifold || !mesh.data(b).manifold) return false;
    // Feature chains stay: an edge between two feature-line vertices is a feature edge.
    if (isFeatureLike(mesh.data(a).role) && isFeatureLike(mesh.data(b).role)) return false;
    f1 = f2 = -1;
    int count = 0;
    for (int f : mesh.facesOf(a)) {
        const Face& t = mesh.face(f);
        for (int k = 0; k < 3; ++k) {
            if (t[k] != a) continue;
            if (t[(k + 1) % 3] == b)
                f1 = f, c = t[(k + 2) % 3], ++count;  // (a, b, c)
            else if (t[(k + 2) % 3] == b)
                f2 = f, d = t[(k + 1) % 3], ++count;  // (b, a, d)
        }
    }
    // Border edges (one face) are never flipped.
    if (count != 2 || f1 < 0 || f2 < 0 || c == d) return false;
    if (!mesh.data(c).manifold || !mesh.data(d).manifold) return false;
    if (mesh.hasEdge(c, d)) return false;  // the new edge exists already: the flip would duplicate it
    if (mesh.data(a).valence - 1 < 3 || mesh.data(b).valence - 1 < 3) return false;
    gain = mesh.valenceDelta(a, -1) + mesh.valenceDelta(b, -1) + mesh.valenceDelta(c, +1) + mesh.valenceDelta(d, +1);
    return true;
}

bool evaluateCollapse(const ValenceMesh& mesh, int a, int b, int& gain, int& keep, int& remove)
{
    if (!mesh.data(a).manifold || !mesh.data(b).manifold) return false;
    // At least one Free end; the merged vertex keeps the constrained one's position and role.
    const bool freeA = mesh.data(a).role == VertexRole::Free, freeB = mesh.data(b).role == VertexRole::Free;
    if (!freeA && !freeB) return false;
    keep = !freeA ? a : !freeB ? b : std::min(a, b);
    remove = keep == a ? b : a;
    int count = 0, c = -1, d = -1;
    for (int f : mesh.facesOf(a)) {
        const Face& t = mesh.face(f);
        for (int k = 0; k < 3; ++k) {
            if (t[k] != a) continue;
            if (t[(k + 1) % 3] == b)
                c = t[(k + 2) % 3], ++count;
            else if (t[(k + 2) % 3] == b)
                d = t[(k + 1) % 3], ++count;
        }
    }
    if (count != 2 || c < 0 || d < 0 || c == d) return false;
    if (!mesh.data(c).manifold || !mesh.data(d).manifold) return false;
    // Link condition: the common neighbours of a and b are exactly the two opposite vertices,
    // otherwise the collapse would pinch the surface (non-manifold edge or vertex).
    std::vector<int> neighbours;
    for (int f : mesh.facesOf(a))
        for (int x : mesh.face(f))
            if (x != a && x != b) neighbours.push_back(x);
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
    int common = 0;
    for (int x : neighbours) common += mesh.hasEdge(x, b);
    if (common != 2) return false;
    const int valenceA = mesh.data(a).valence, valenceB = mesh.data(b).valence;
    const int merged = valenceA + valenceB - 4;
    if (merged < 3 || mesh.data(c).valence - 1 < 3 || mesh.data(d).valence - 1 < 3) return false;
    gain = mesh.cost(keep, merged) - mesh.cost(a, valenceA) - mesh.cost(b, valenceB) + mesh.valenceDelta(c, -1) +
           mesh.valenceDelta(d, -1);
    return true;
}

void collectOperations(const ValenceMesh& mesh, int v, bool zeroGainFlips, std::vector<Op>& out)
{
    Ring r;
    mesh.ring(v, r);
    if (!r.ok) return;
    int gain, c, d, f1, f2, keep, remove;
    auto wanted = [&](int g) { return zeroGainFlips ? g == 0 : g < 0; };
    for (int w : r.verts) {
        // Flips of the edges at v (lower its valence).
        if (evaluateFlip(mesh, v, w, gain, c, d, f1, f2) && wanted(gain))
            out.push_back({OpType::Flip, std::min(v, w), std::max(v, w), -1, gain});
        // Collapses of the edges at v.
        if (!zeroGainFlips && evaluateCollapse(mesh, v, w, gain, keep, remove) && gain < 0)
            out.push_back({OpType::Collapse, std::min(v, w), std::max(v, w), -1, gain});
    }
    // Flips of the edges opposite v in its faces (raise its valence).
    for (size_t i = 0; i + 1 < r.verts.size() + (r.closed ? 1 : 0); ++i) {
        const int x = r.verts[i], y = r.verts[(i + 1) % r.verts.size()];
        if (evaluateFlip(mesh, x, y, gain, c, d, f1, f2) && wanted(gain))
            out.push_back({OpType::Flip, std::min(x, y), std::max(x, y), -1, gain});
    }
    if (zeroGainFlips) return;
    // Splits of v (interior Free vertices): v keeps ring[i..j], the new vertex ring[j..i].
    if (mesh.data(v).role == VertexRole::Free && r.closed && !mesh.data(v).onBorder) {
        const int n = static_cast<int>(r.verts.size());
        for (int i = 0; i < n; ++i)
            for (int s = 2; s <= n - 2; ++s) {
                const int a = r.verts[i], b = r.verts[(i + s) % n];
                gain = splitGain(mesh, n, s, a, b);
                if (gain < 0) out.push_back({OpType::Split, v, a, b, gain});
            }
    }
}

void involvedVertices(const ValenceMesh& mesh, const Op& op, std::vector<int>& out)
{
    out.clear();
    Ring r;
    auto addRing = [&](int v) {
        out.push_back(v);
        mesh.ring(v, r);
        out.insert(out.end(), r.verts.begin(), r.verts.end());
    };
    if (op.type == OpType::Flip) {
        out = {op.a, op.b};
        int gain, c, d, f1, f2;
        if (evaluateFlip(mesh, op.a, op.b, gain, c, d, f1, f2)) out.push_back(c), out.push_back(d);
    } else if (op.type == OpType::Collapse) {
        addRing(op.a);
        addRing(op.b);
    } else if (op.type == OpType::Split) {
        addRing(op.a);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

Candidate single(const ValenceMesh& mesh, const Op& op)
{
    Candidate c;
    c.gain = op.gain;
    c.length = 1;
    c.ops[0] = op;
    involvedVertices(mesh, op, c.region);
    return c;
}

namespace {

bool applyFlip(ValenceMesh& mesh, const Op& op, std::vector<int>& smooth)
{
    int gain, c, d, f1, f2;
    if (!evaluateFlip(mesh, op.a, op.b, gain, c, d, f1, f2) || gain != op.gain) return false;
    // (a, b, c) and (b, a, d) become (d, b, c) and (c, a, d): the same orientation.
    mesh.killFace(f1);
    mesh.killFace(f2);
    mesh.addFace({d, op.b, c});
    mesh.addFace({c, op.a, d});
    smooth.insert(smooth.end(), {op.a, op.b, c, d});
    return true;
}

bool applyCollapse(ValenceMesh& mesh, const Op& op, std::vector<int>& smooth, std::vector<int>& changed)
{
    int gain, keep, remove;
    if (!evaluateCollapse(mesh, op.a, op.b, gain, keep, remove) || gain != op.gain) return false;
    const std::vector<int> facesOfRemoved = mesh.facesOf(remove);
    const Vec3 midpoint = 0.5 * (mesh.position(keep) + mesh.position(remove));
    const bool bothFree = mesh.data(keep).role == VertexRole::Free && mesh.data(remove).role == VertexRole::Free;
    for (int f : facesOfRemoved) {
        Face t = mesh.face(f);
        const bool hasKeep = t[0] == keep || t[1] == keep || t[2] == keep;
        mesh.killFace(f);
        if (hasKeep) continue;  // the two faces of the collapsed edge disappear
        for (int& x : t)
            if (x == remove) x = keep;
        mesh.addFace(t);
    }
    mesh.killVertex(remove);
    // The merged vertex keeps a constrained end's position, else starts at the midpoint.
    if (bothFree) mesh.place(keep, mesh.surface().tree.closest(midpoint, mesh.data(keep).closest.face));
    Ring r;
    mesh.ring(keep, r);
    smooth.insert(smooth.end(), r.verts.begin(), r.verts.end());
    smooth.push_back(keep);
    changed.push_back(remove);
    return true;
}

bool applySplit(ValenceMesh& mesh, const Op& op, std::vector<int>& smooth, std::vector<int>& changed)
{
    const int v = op.a;
    Ring r;
    mesh.ring(v, r);
    if (!r.ok || !r.closed || mesh.data(v).role != VertexRole::Free || mesh.data(v).onBorder) return false;
    const std::vector<int> splitRing = r.verts;
    const int n = static_cast<int>(splitRing.size());
    int splitI = -1, splitJ = -1;
    for (int i = 0; i < n; ++i) {
        if (splitRing[i] == op.b) splitI = i;
        if (splitRing[i] == op.c) splitJ = i;
    }
    if (splitI < 0 || splitJ < 0) return false;
    const int s = (splitJ - splitI + n) % n;
    if (s < 2 || s > n - 2) return false;
    if (splitGain(mesh, n, s, op.b, op.c) != op.gain) return false;

    const Vec3 p = mesh.position(v);
    Vec3 keptCentre = Vec3::Zero(), newCentre = Vec3::Zero();
    int keptCount = 0, newCount = 0;
    for (int k = splitI;; k = (k + 1) % n) {
        keptCentre += mesh.position(splitRing[k]), ++keptCount;
        if (k == splitJ) break;
    }
    for (int k = splitJ;; k = (k + 1) % n) {
        newCentre += mesh.position(splitRing[k]), ++newCount;
        if (k == splitI) break;
    }
    keptCentre /= keptCount;
    newCentre /= newCount;
    // Each half starts a third of the way towards the neighbours it keeps; the local smoothing
    // then evens the two fans out.
    const int w = mesh.addSurfaceVertex(p + (newCentre - p) / 3.0, VertexRole::Free);
    mesh.place(w, mesh.data(w).closest);
    // Ring faces (v, ring[k], ring[k+1]) for k = j .. i-1 go to w.
    for (int k = splitJ; k != splitI; k = (k + 1) % n) {
        const int x = splitRing[k], y = splitRing[(k + 1) % n];
        int face = -1;
        for (int f : mesh.facesOf(v)) {
            const Face& t = mesh.face(f);
            for (int q = 0; q < 3; ++q)
                if (t[q] == v && t[(q + 1) % 3] == x && t[(q + 2) % 3] == y) face = f;
        }
        if (face < 0) return false;  // cannot happen on a manifold ring; the caller rolls back
        Face t = mesh.face(face);
        mesh.killFace(face);
        for (int& q : t)
            if (q == v) q = w;
        mesh.addFace(t);
    }
    mesh.addFace({v, splitRing[splitJ], w});
    mesh.addFace({w, splitRing[splitI], v});
    mesh.place(v, mesh.surface().tree.closest(p + (keptCentre - p) / 3.0, mesh.data(v).closest.face));
    smooth.insert(smooth.end(), splitRing.begin(), splitRing.end());
    smooth.push_back(v);
    smooth.push_back(w);
    changed.push_back(w);
    return true;
}

}  // namespace

bool applyTopology(ValenceMesh& mesh, const Op& op, std::vector<int>& smooth, std::vector<int>& changed)
{
    // Re-check the operation on the current mesh: its vertices are unlocked, so nothing has
    // changed around them, but a stale candidate must never be applied.
    if (op.type == OpType::Flip) return applyFlip(mesh, op, smooth);
    if (op.type == OpType::Collapse) return applyCollapse(mesh, op, smooth, changed);
    if (op.type == OpType::Split) return applySplit(mesh, op, smooth, changed);
    return false;
}

}  // namespace fieldcvt::valence
