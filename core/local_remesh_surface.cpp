// The input surface side of the local remesher (local_remesh_surface.h).
#include "local_remesh_surface.h"

#include "boundary.h"
#include "errors.h"
#include "mesh_edges.h"
#include "metrics.h"

#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace fieldcvt::local_remesh_detail {
namespace {

//! A projection is refused on a face turned more than 90° from the vertex's normal: on a plate
//! thinner than an edge that is the far side.
constexpr double kMinNormalDot = 0.0;
//! A point this close to the surface (a fraction of the target length) is on it, whichever
//! side it came from.
constexpr double kAlreadyThere = 0.01;
//! Steps of the walk over the surface's faces that projects a vertex: a smoothing step moves a
//! vertex by a fraction of an edge, a few faces of a surface as fine as the output.
constexpr int kWalkSteps = 32;
//! Curve edges looked at each way from a vertex's own (the search also ends at its radius).
constexpr int kCurveSteps = 512;

//! CSR lists per vertex of `count` items, item i at the vertices endsOf(i) (-1: none).
template <class Ends>
void buildCsr(int vertexCount, std::vector<int>& first, std::vector<int>& items, int count, Ends&& endsOf)
{
    first.assign(vertexCount + 1, 0);
    for (int i = 0; i < count; ++i)
        for (int v : endsOf(i))
            if (v >= 0) ++first[v + 1];
    for (int v = 0; v < vertexCount; ++v) first[v + 1] += first[v];
    items.resize(first[vertexCount]);
    std::vector<int> fill(first.begin(), first.end() - 1);
    for (int i = 0; i < count; ++i)
        for (int v : endsOf(i))
            if (v >= 0) items[fill[v]++] = i;
}

}  // namespace

Surface::Surface(const TriMesh& surface, const ClosestPointTree& tree, const std::vector<char>& selected,
                 const std::vector<double>& targetPerFace, double target)
    : mesh(surface), selected_(selected), tree_(tree), perFace_(targetPerFace), uniform_(target)
{
    const int nf = mesh.faceCount();
    normals_.resize(nf);
    for (int f = 0; f < nf; ++f) normals_[f] = faceNormal(mesh, f).normalized();
    const EdgeTable edges = buildEdgeTable(mesh);
    component = faceComponents(edges, nf, componentCount);
    across_.assign(3 * nf, -1);
    for (int e = 0; e < edges.edgeCount(); ++e) {
        int count = 0, h = -1;
        for (int i = 0; i < edges.faceCount(e); ++i)
            if (selected[edges.face(e, i)]) ++count, h = edges.halfEdge(e, i);
        if (count == 1) curves.push_back({edges.ends[e][0], edges.ends[e][1], h / 3, true});
        if (count == 2 && edges.faceCount(e) == 2) {
            across_[edges.halfEdge(e, 0)] = edges.face(e, 1);
            across_[edges.halfEdge(e, 1)] = edges.face(e, 0);
        }
    }
    buildCsr(mesh.vertexCount(), fanFirst, fan, nf, [&](int f) { return selected[f] ? mesh.faces[f] : Face{-1, -1, -1}; });
}

void Surface::addCurves(const std::vector<std::array<int, 2>>& featureEdges, const std::vector<int>& corners)
{
    const int nv = mesh.vertexCount();
    const std::vector<char>& selected = selected_;
    const EdgeTable edges = buildEdgeTable(mesh);
    for (const auto& fe : featureEdges) {
        const int e = edges.find(fe[0], fe[1]);
        if (e < 0 || edges.faceCount(e) != 2 || !selected[edges.face(e, 0)] || !selected[edges.face(e, 1)]) continue;
        if (curves.empty() || curves.back().border || curves.back().u != edges.ends[e][0] || curves.back().v != edges.ends[e][1])
            curves.push_back({edges.ends[e][0], edges.ends[e][1], edges.face(e, 0), false});
    }
    buildCsr(nv, curveFirst, curveOf, static_cast<int>(curves.size()), [&](int i) {
        return std::array<int, 2>{curves[i].u, curves[i].v};
    });
    stop.assign(nv, 0);
    for (int c : corners) stop[c] = 1;
    for (int v = 0; v < nv; ++v) {
        int border = 0, feature = 0;
        for (int k = curveFirst[v]; k < curveFirst[v + 1]; ++k) ++(curves[curveOf[k]].border ? border : feature);
        if ((border && feature) || (feature && feature != 2) || (border && border != 2)) stop[v] = 1;
    }
}

StartMesh Surface::startMesh() const
{
    StartMesh start;
    std::vector<int> index(mesh.vertexCount(), -1);
    for (int v = 0; v < mesh.vertexCount(); ++v) {
        if (fanFirst[v + 1] == fanFirst[v]) continue;
        index[v] = static_cast<int>(start.positions.size());
        start.positions.push_back(mesh.vertices[v]);
    }
    for (int f = 0; f < mesh.faceCount(); ++f)
        if (selected_[f]) start.faces.push_back({index[mesh.faces[f][0]], index[mesh.faces[f][1]], index[mesh.faces[f][2]]});
    start.featureNbrs.resize(start.positions.size());
    for (int v = 0; v < mesh.vertexCount(); ++v) {
        if (index[v] < 0) continue;
        VertexInfo info;
        info.face = fan[fanFirst[v]];
        info.component = component[info.face];
        bool feature = false;
        for (int k = curveFirst[v]; k < curveFirst[v + 1]; ++k) {
            const CurveEdge& c = curves[curveOf[k]];
            if (c.border) info.onBorder = true;
            if (!c.border) feature = true, start.featureNbrs[index[v]].push_back(index[c.u == v ? c.v : c.u]);
            if (info.curve < 0) info.curve = curveOf[k];
        }
        info.role = stop[v] ? VertexRole::Corner
                            : (info.onBorder ? VertexRole::Boundary : (feature ? VertexRole::Feature : VertexRole::Free));
        if (info.role == VertexRole::Corner) info.corner = v;
        info.target = targetAt(mesh.vertices[v], info.face);
        start.info.push_back(info);
    }
    return start;
}

bool Surface::walk(const Vec3& p, int face, ClosestPoint& out) const
{
    auto distance2 = [&](int f, Vec3& point, Vec3& bary) {
        const Face& t = mesh.faces[f];
        point = closestPointOnTriangle(p, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], &bary);
        return (point - p).squaredNorm();
    };
    Vec3 point, bary;
    double best2 = distance2(face, point, bary);
    int previous = -1;
    bool settled = false;
    for (int step = 0; step < kWalkSteps && !settled; ++step) {
        int next = -1;
        double next2 = best2;
        Vec3 nextPoint = point, nextBary = bary, candidatePoint, candidateBary;
        auto consider = [&](int g) {
            if (g < 0 || g == face || g == previous) return;
            const double d2 = distance2(g, candidatePoint, candidateBary);
            if (d2 < next2) next = g, next2 = d2, nextPoint = candidatePoint, nextBary = candidateBary;
        };
        // Inside the face, a face across an edge may still be nearer where the surface is
        // concave; on an edge, the face across it; on a corner, any face around that vertex.
        const int zeros = (bary[0] == 0.0) + (bary[1] == 0.0) + (bary[2] == 0.0);
        if (zeros == 0) {
            for (int k = 0; k < 3; ++k) consider(across_[3 * face + k]);
        } else if (zeros == 1) {
            for (int k = 0; k < 3; ++k)
                if (bary[k] == 0.0) consider(across_[3 * face + (k + 1) % 3]);
        } else {
            const int v = mesh.faces[face][bary[0] != 0.0 ? 0 : (bary[1] != 0.0 ? 1 : 2)];
            for (int k = fanFirst[v]; k < fanFirst[v + 1]; ++k) consider(fan[k]);
        }
        if (next < 0) {
            settled = true;
        } else {
            previous = face, face = next, best2 = next2, point = nextPoint, bary = nextBary;
        }
    }
    out.point = point, out.face = face, out.barycentric = bary, out.squaredDistance = best2;
    return settled;
}

bool Surface::projectFree(const Vec3& p, int face, const Vec3& normal, double radius, Spot& out) const
{
    ClosestPoint found;
    if (!walk(p, face, found)) {
        const ClosestPoint exact = tree_.closest(p, face);
        if (component[exact.face] != component[face] || (exact.point - found.point).norm() > radius) return false;
        found = exact;
    }
    // The far side is refused unless p is there already (a split's midpoint on a thin part).
    const double near = kAlreadyThere * target(found.face);
    if (normals_[found.face].dot(normal) <= kMinNormalDot * normal.norm() && found.squaredDistance > near * near) return false;
    out.point = found.point, out.face = found.face, out.curve = -1;
    return true;
}

void Surface::projectOnCurve(const Vec3& p, int edge, double radius, Spot& out) const
{
    double best2 = std::numeric_limits<double>::infinity();
    auto consider = [&](int e) {
        double d2;
        const Vec3 q = closestPointOnSegment(p, {mesh.vertices[curves[e].u], mesh.vertices[curves[e].v]}, &d2);
        if (d2 < best2) best2 = d2, out.point = q, out.face = curves[e].face, out.curve = e;
    };
    consider(edge);
    for (int side = 0; side < 2; ++side) {
        int e = edge, x = side == 0 ? curves[edge].u : curves[edge].v;
        double arc = 0;
        for (int step = 0; step < kCurveSteps && !stop[x] && arc < radius; ++step) {
            int next = -1;
            for (int k = curveFirst[x]; k < curveFirst[x + 1] && next < 0; ++k)
                if (curveOf[k] != e && curves[curveOf[k]].border == curves[edge].border) next = curveOf[k];
            if (next < 0 || next == edge) break;
            e = next;
            x = curves[e].u == x ? curves[e].v : curves[e].u;
            arc += (mesh.vertices[curves[e].u] - mesh.vertices[curves[e].v]).norm();
            consider(e);
        }
    }
}

bool Surface::projectFromCorner(const Vec3& p, int corner, bool border, double radius, Spot& out) const
{
    double best2 = std::numeric_limits<double>::infinity();
    for (int k = curveFirst[corner]; k < curveFirst[corner + 1]; ++k) {
        if (curves[curveOf[k]].border != border) continue;
        Spot spot;
        projectOnCurve(p, curveOf[k], radius, spot);
        if ((spot.point - p).squaredNorm() < best2) best2 = (spot.point - p).squaredNorm(), out = spot;
    }
    return best2 < std::numeric_limits<double>::infinity();
}

void checkSelection(const TriMesh& surface, const std::vector<char>& selectedFaces)
{
    auto fail = [](const std::string& what) { throw InvalidInputError("local remeshing: " + what); };
    const int nv = surface.vertexCount(), nf = surface.faceCount();
    if (selectedFaces.size() != surface.faces.size())
        fail("the face mask has " + std::to_string(selectedFaces.size()) + " entries for a surface of " + std::to_string(nf) +
             " faces");
    TriMesh selected;
    selected.vertices = surface.vertices;
    for (int f = 0; f < nf; ++f) {
        if (!selectedFaces[f]) continue;
        const Face& t = surface.faces[f];
        for (int v : t)
            if (v < 0 || v >= nv) fail("face " + std::to_string(f) + " has a vertex index out of range");
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) fail("face " + std::to_string(f) + " repeats a vertex");
        for (int v : t)
            if (!surface.vertices[v].allFinite()) fail("vertex " + std::to_string(v) + " is not finite");
        selected.faces.push_back(t);
    }
    const TopologySummary topology = computeTopology(selected);
    if (!topology.manifold() || !topology.orientable)
        fail("the selected faces are not a manifold, oriented surface (" + std::to_string(topology.nonManifoldEdges) +
             " non-manifold edges, " + std::to_string(topology.nonManifoldVertices) + " non-manifold vertices" +
             (topology.orientable ? ")" : ", not oriented)"));
}

}  // namespace fieldcvt::local_remesh_detail
