// The seam of a remeshed region (region.h): its border put exactly on the region's own border
// vertices, so that the new faces meet the kept ones edge to edge.
#include "boundary.h"
#include "mesh_edges.h"
#include "region.h"
#include "triangle_shape.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace fieldcvt {

namespace {

std::uint64_t edgeKey(int a, int b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); }

//! Directed edge a -> b -> how many faces have it.
std::unordered_map<std::uint64_t, int> directedEdges(const std::vector<Face>& faces)
{
    std::unordered_map<std::uint64_t, int> edges;
    for (const Face& f : faces)
        for (int k = 0; k < 3; ++k) ++edges[edgeKey(f[k], f[(k + 1) % 3])];
    return edges;
}

//! In degrees: the flips compare it with the caller's bounds (triangle_shape.h's, converted).
double smallestAngleDegrees(const Vec3& a, const Vec3& b, const Vec3& c) { return smallestAngle(a, b, c) * 180 / kPi; }

//! Where a point of the patch's border lies on the region's border: loop, and position along it
//! (segment index + fraction).
struct BorderPlace {
    int loop = -1;
    double position = 0;
    int vertex = -1;  //!< the loop position of the region border vertex it is at (claimed), or -1
};

//! Patch border vertices closer than this share of a border edge to one of its ends become that
//! vertex (moved onto it) instead of being removed next to an inserted copy.
constexpr double kClaimShare = 1e-3;

//! The patch being edited: faces (killed ones marked), the faces around each vertex.
struct PatchEdit {
    std::vector<Vec3> vertices;
    std::vector<Face> faces;
    std::vector<char> alive;
    std::vector<std::vector<int>> facesOf;

    void add(const Face& f)
    {
        faces.push_back(f);
        alive.push_back(1);
        for (int v : f) facesOf[size_t(v)].push_back(faceCount() - 1);
    }
    void kill(int f)
    {
        alive[size_t(f)] = 0;
        for (int v : faces[size_t(f)]) {
            auto& list = facesOf[size_t(v)];
            list.erase(std::remove(list.begin(), list.end(), f), list.end());
        }
    }
    int addVertex(const Vec3& p)
    {
        vertices.push_back(p);
        facesOf.emplace_back();
        return int(vertices.size()) - 1;
    }
    int faceCount() const { return int(faces.size()); }
    //! The alive face with the directed edge a -> b, or -1.
    int faceWith(int a, int b) const
    {
        for (int f : facesOf[size_t(a)]) {
            const Face& t = faces[size_t(f)];
            for (int k = 0; k < 3; ++k)
                if (t[k] == a && t[(k + 1) % 3] == b) return f;
        }
        return -1;
    }
    bool hasEdge(int a, int b) const { return faceWith(a, b) >= 0 || faceWith(b, a) >= 0; }
};

//! Each region border vertex inserted into the patch border edge it falls on (a fan from the
//! edge's opposite corner). `place` is per patch vertex; returns false when the patch's border
//! does not go once around each of the region's loops.
bool insertBorderVertices(const RegionSubmesh& region, const std::vector<std::vector<int>>& loops,
                          const std::vector<BorderPlace>& place, PatchEdit& edit, std::vector<int>& original,
                          std::string& failure)
{
    const auto halfEdges = borderHalfEdges(edit.faces);
    std::vector<std::vector<int>> claimed(loops.size());  // loop position -> the patch vertex at it
    for (size_t l = 0; l < loops.size(); ++l) claimed[l].assign(loops[l].size(), -1);
    for (size_t v = 0; v < place.size(); ++v)
        if (place[v].vertex >= 0) {
            int& owner = claimed[size_t(place[v].loop)][size_t(place[v].vertex)];
            if (owner >= 0) {
                failure = "two remeshed border vertices are at one border vertex of the region";
                return false;
            }
            owner = int(v);
            const int regionVertex = loops[size_t(place[v].loop)][size_t(place[v].vertex)];
            edit.vertices[v] = region.mesh.vertices[size_t(regionVertex)];
            original[v] = region.originalVertex[size_t(regionVertex)];
        }
    std::vector<double> turned(loops.size(), 0.0);
    struct Insert {
        int a, b;
        std::vector<int> between;  // positions on the region's loop
    };
    std::vector<Insert> inserts;
    for (const auto& [a, b] : halfEdges) {
        const BorderPlace pa = place[size_t(a)], pb = place[size_t(b)];
        if (pa.loop != pb.loop) {
            failure = "the remeshed border joins two different border loops of the region";
            return false;
        }
        const int n = int(loops[size_t(pa.loop)].size());
        double gap = pb.position - pa.position;
        if (gap <= 0) gap += n;
        turned[size_t(pa.loop)] += gap;
        std::vector<int> between;
        for (int j = int(std::ceil(pa.position)); j < pa.position + gap; ++j)
            if (claimed[size_t(pa.loop)][size_t(j % n)] < 0) between.push_back(j % n);
        if (!between.empty()) inserts.push_back({a, b, std::move(between)});
    }
    for (size_t l = 0; l < loops.size(); ++l)
        if (std::abs(turned[l] - double(loops[l].size())) > 0.5) {
            failure =
                "the remeshed border does not go once around each border loop of the region (vertex count too "
                "low for the region's shape?)";
            return false;
        }
    for (const auto& [a, b, between] : inserts) {
        // Looked up now: an earlier insertion may have split this face (two border edges).
        const int f = edit.faceWith(a, b);
        const Face& t = edit.faces[size_t(f)];
        const int c = t[0] != a && t[0] != b ? t[0] : t[1] != a && t[1] != b ? t[1] : t[2];
        edit.kill(f);
        int previous = a;
        for (int j : between) {
            const int regionVertex = loops[size_t(place[size_t(a)].loop)][size_t(j)];
            const int v = edit.addVertex(region.mesh.vertices[size_t(regionVertex)]);
            original.push_back(region.originalVertex[size_t(regionVertex)]);
            edit.add({previous, v, c});
            previous = v;
        }
        edit.add({previous, b, c});
    }
    return true;
}

//! Removes border vertex s of the patch: its fan's outline triangulated with the largest
//! smallest angle, without an edge the patch already has (else false).
bool removeBorderVertex(PatchEdit& edit, int s)
{
    const std::vector<int> fan = edit.facesOf[size_t(s)];
    if (fan.empty()) return true;
    // The outline next, x1, ..., prev, counter-clockwise around s (faces (s, next, x1), ...).
    auto corner = [&](int f, int after) {
        const Face& t = edit.faces[size_t(f)];
        for (int k = 0; k < 3; ++k)
            if (t[k] == after) return t[(k + 1) % 3];
        return -1;
    };
    int start = -1;
    for (int f : fan) {
        const int next = corner(f, s);
        if (edit.faceWith(next, s) < 0) start = f;
    }
    if (start < 0) return false;
    std::vector<int> outline{corner(start, s)};
    Vec3 normal = Vec3::Zero();
    for (int f = start, steps = 0;; ++steps) {
        const Face& t = edit.faces[size_t(f)];
        normal += (edit.vertices[size_t(t[1])] - edit.vertices[size_t(t[0])])
                      .cross(edit.vertices[size_t(t[2])] - edit.vertices[size_t(t[0])]);
        const int x = corner(f, outline.back());
        outline.push_back(x);
        f = edit.faceWith(s, x);
        if (f < 0) break;
        if (steps > int(fan.size())) return false;
    }
    if (int(outline.size()) != int(fan.size()) + 1) return false;  // a fan that is not one disk sector
    const int m = int(outline.size()) - 1;
    for (int i = 0; i <= m; ++i)
        for (int j = i + 1; j <= m; ++j)
            if (outline[size_t(i)] == outline[size_t(j)]) return false;
    for (int f : fan) edit.kill(f);
    auto undo = [&] {
        for (int f : fan) {
            edit.alive[size_t(f)] = 1;
            for (int v : edit.faces[size_t(f)]) edit.facesOf[size_t(v)].push_back(f);
        }
        return false;
    };
    if (m == 1) {
        // One face: its far edge becomes border; it must still have a face.
        if (!edit.hasEdge(outline[0], outline[1])) return undo();
        return true;
    }
    const auto p = [&](int i) -> const Vec3& { return edit.vertices[size_t(outline[size_t(i)])]; };
    auto usable = [&](int i, int j) { return j == i + 1 || !edit.hasEdge(outline[size_t(i)], outline[size_t(j)]); };
    if (!usable(0, m)) return undo();
    const double none = -1e9;
    std::vector<double> best(size_t((m + 1) * (m + 1)), none);
    std::vector<int> split(best.size(), -1);
    for (int i = 0; i < m; ++i) best[size_t(i * (m + 1) + i + 1)] = 180;
    for (int width = 2; width <= m; ++width)
        for (int i = 0; i + width <= m; ++i) {
            const int j = i + width;
            if (!usable(i, j)) continue;
            for (int k = i + 1; k < j; ++k) {
                const double left = best[size_t(i * (m + 1) + k)], right = best[size_t(k * (m + 1) + j)];
                if (left <= none || right <= none) continue;
                // A triangle facing away from the fan scores below every other, the least turned
                // best: a jagged border may leave no other way (the seam optimisation then moves it).
                const Vec3 n = (p(k) - p(i)).cross(p(j) - p(i));
                const double facing = n.norm() > 0 ? n.normalized().dot(normal.normalized()) : -1;
                const double shape = facing > 0 ? smallestAngleDegrees(p(i), p(k), p(j)) : facing - 2;
                const double score = std::min({shape, left, right});
                if (score > best[size_t(i * (m + 1) + j)])
                    best[size_t(i * (m + 1) + j)] = score, split[size_t(i * (m + 1) + j)] = k;
            }
        }
    if (!(best[size_t(m)] > none)) return undo();
    std::vector<std::pair<int, int>> stack{{0, m}};
    while (!stack.empty()) {
        const auto [i, j] = stack.back();
        stack.pop_back();
        if (j - i < 2) continue;
        const int k = split[size_t(i * (m + 1) + j)];
        edit.add({outline[size_t(i)], outline[size_t(k)], outline[size_t(j)]});
        stack.push_back({i, k});
        stack.push_back({k, j});
    }
    return true;
}

}  // namespace

bool pinBorder(const RegionSubmesh& region, TriMesh& patch, std::vector<int>& original, std::string& failure)
{
    const std::vector<std::vector<int>> loops = borderLoops(region.mesh);
    if (loops.empty()) {
        failure = "the region has no border";
        return false;
    }
    PatchEdit edit;
    edit.vertices = patch.vertices;
    edit.facesOf.resize(patch.vertices.size());
    for (const Face& f : patch.faces) edit.add(f);
    original.assign(patch.vertices.size(), -1);
    // Each patch border vertex's place on the region's border (its nearest segment).
    std::vector<BorderPlace> place(patch.vertices.size());
    std::vector<int> patchBorder;
    for (const auto& [a, b] : borderHalfEdges(patch.faces)) patchBorder.push_back(a);
    std::sort(patchBorder.begin(), patchBorder.end());
    patchBorder.erase(std::unique(patchBorder.begin(), patchBorder.end()), patchBorder.end());
    for (int v : patchBorder) {
        double nearest = std::numeric_limits<double>::infinity();
        const Vec3& x = patch.vertices[size_t(v)];
        for (size_t l = 0; l < loops.size(); ++l) {
            const int n = int(loops[l].size());
            for (int i = 0; i < n; ++i) {
                const Vec3& a = region.mesh.vertices[size_t(loops[l][size_t(i)])];
                const Vec3& b = region.mesh.vertices[size_t(loops[l][size_t((i + 1) % n)])];
                const Vec3 d = b - a;
                const double t = d.squaredNorm() > 0 ? std::clamp((x - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
                const double distance = (a + t * d - x).squaredNorm();
                if (distance < nearest) {
                    nearest = distance;
                    const double claim = kClaimShare * std::sqrt(d.squaredNorm());
                    const int at = (x - a).norm() <= claim ? i : (x - b).norm() <= claim ? (i + 1) % n : -1;
                    place[size_t(v)] = {int(l), at >= 0 ? double(at) : std::min(i + t, double(n) - 1e-12), at};
                }
            }
        }
    }
    if (!insertBorderVertices(region, loops, place, edit, original, failure)) return false;
    // Removed in passes: a hole that cannot be filled yet may be once its neighbours are gone.
    std::vector<int> left;
    for (int s : patchBorder)
        if (place[size_t(s)].vertex < 0) left.push_back(s);
    for (size_t before = left.size() + 1; !left.empty() && left.size() < before;) {
        before = left.size();
        left.erase(std::remove_if(left.begin(), left.end(), [&](int s) { return removeBorderVertex(edit, s); }), left.end());
    }
    if (!left.empty()) {
        failure = std::to_string(left.size()) +
                  " hole(s) left by moving the remeshed border onto the region's border could "
                  "not be filled";
        return false;
    }
    // Compact: the removed vertices go.
    std::vector<int> index(edit.vertices.size(), -1);
    TriMesh out;
    std::vector<int> outOriginal;
    for (int f = 0; f < edit.faceCount(); ++f) {
        if (!edit.alive[size_t(f)]) continue;
        Face t = edit.faces[size_t(f)];
        for (int& v : t) {
            if (index[size_t(v)] < 0) {
                index[size_t(v)] = out.vertexCount();
                out.vertices.push_back(edit.vertices[size_t(v)]);
                outOriginal.push_back(original[size_t(v)]);
            }
            v = index[size_t(v)];
        }
        out.faces.push_back(t);
    }
    patch = std::move(out);
    original = std::move(outOriginal);
    return true;
}

int flipForAngles(RegionPatch& patch, int maxPasses)
{
    PatchEdit edit;
    edit.vertices = patch.mesh.vertices;
    edit.facesOf.resize(edit.vertices.size());
    for (const Face& f : patch.mesh.faces) edit.add(f);
    const auto at = [&](int v) -> const Vec3& { return edit.vertices[size_t(v)]; };
    int flips = 0;
    for (int pass = 0; pass < maxPasses; ++pass) {
        int flipped = 0;
        for (int f = 0; f < edit.faceCount(); ++f)
            for (int k = 0; k < 3 && edit.alive[size_t(f)]; ++k) {
                // Edge a -> b of f = (a, b, c), and g = (b, a, d) on its other side.
                const Face t = edit.faces[size_t(f)];
                const int a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
                const int g = edit.faceWith(b, a);
                if (g < 0) continue;
                const Face u = edit.faces[size_t(g)];
                const int d = u[0] != a && u[0] != b ? u[0] : u[1] != a && u[1] != b ? u[1] : u[2];
                if (c == d || edit.hasEdge(c, d)) continue;
                const double before =
                    std::min(smallestAngleDegrees(at(a), at(b), at(c)), smallestAngleDegrees(at(b), at(a), at(d)));
                const double after =
                    std::min(smallestAngleDegrees(at(c), at(d), at(b)), smallestAngleDegrees(at(d), at(c), at(a)));
                // The two new triangles must face the way the old ones did (a convex quadrilateral).
                const Vec3 n = (at(b) - at(a)).cross(at(c) - at(a)) + (at(a) - at(b)).cross(at(d) - at(b));
                const bool facing =
                    (at(d) - at(c)).cross(at(b) - at(c)).dot(n) > 0 && (at(c) - at(d)).cross(at(a) - at(d)).dot(n) > 0;
                if (!(after > before + 1e-9) || !facing) continue;
                edit.kill(f);
                edit.kill(g);
                edit.add({c, d, b});
                edit.add({d, c, a});
                ++flipped;
            }
        flips += flipped;
        if (flipped == 0) break;
    }
    patch.mesh.faces.clear();
    for (int f = 0; f < edit.faceCount(); ++f)
        if (edit.alive[size_t(f)]) patch.mesh.faces.push_back(edit.faces[size_t(f)]);
    return flips;
}

bool patchMatchesBorder(const RegionSubmesh& region, const RegionPatch& patch)
{
    std::vector<std::pair<int, int>> want, got;
    for (const auto& [a, b] : borderHalfEdges(region.mesh.faces))
        want.push_back({region.originalVertex[size_t(a)], region.originalVertex[size_t(b)]});
    for (const auto& [a, b] : borderHalfEdges(patch.mesh.faces))
        got.push_back({patch.original[size_t(a)], patch.original[size_t(b)]});
    std::sort(want.begin(), want.end());
    std::sort(got.begin(), got.end());
    if (want != got) return false;
    // No new vertex on the border, every pinned vertex where the region has it, and the patch
    // manifold along its edges (each directed edge once).
    for (size_t v = 0; v < patch.original.size(); ++v)
        if (patch.original[v] >= 0) {
            const auto it = std::find(region.originalVertex.begin(), region.originalVertex.end(), patch.original[v]);
            if (it == region.originalVertex.end() ||
                !(region.mesh.vertices[size_t(it - region.originalVertex.begin())].array() == patch.mesh.vertices[v].array())
                     .all())
                return false;
        }
    for (const auto& [key, count] : directedEdges(patch.mesh.faces))
        if (count != 1) return false;
    return true;
}

}  // namespace fieldcvt
