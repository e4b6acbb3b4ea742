#include "valence/valence_mesh.h"

#include "boundary.h"
#include "energy.h"
#include "field.h"
#include "interpolation.h"

#include <algorithm>
#include <cmath>

namespace fieldcvt::valence {

namespace {

// A Free vertex on the mesh's border is not put on the input's border where that leaves one of
// its faces under this angle (radians) and sharper than it was.
constexpr double kBorderPlacementAngle = 20 * kPi / 180;

}  // namespace

Vec3 ValenceMesh::placeOnBorder(int v, const std::vector<Vec3>& at, const std::vector<Segment>& border) const
{
    // On a border with detail below the edge length (a ragged scan border, a notch) the closest
    // border point can lie across a notch, in line with v's border neighbours: v then stays at
    // its sample's closest point, on the surface next to the border (which its cell reached).
    const Vec3 closest = closestPointOnSegments(at[v], border);
    double before = kPi, after = kPi;
    for (int f : facesOf(v)) {
        Vec3 corner[3], moved[3];
        for (int k = 0; k < 3; ++k) {
            corner[k] = at[face(f)[k]];
            moved[k] = face(f)[k] == v ? closest : corner[k];
        }
        const bool turned =
            (corner[1] - corner[0]).cross(corner[2] - corner[0]).dot((moved[1] - moved[0]).cross(moved[2] - moved[0])) <= 0;
        before = std::min(before, smallestAngle(corner[0], corner[1], corner[2]));
        after = std::min(after, turned ? 0.0 : smallestAngle(moved[0], moved[1], moved[2]));
    }
    return after >= kBorderPlacementAngle || after >= before ? closest : at[v];
}

ValenceMesh::ValenceMesh(const TriMesh& mesh, const std::vector<VertexRole>& roles, const ValenceSurface& surface,
                         int borderWeight, const std::vector<int>& faceHints)
    : EditableMesh<MeshVertex>(mesh.vertices, mesh.faces),
      surface_(&surface),
      walk_(std::make_shared<const SurfaceWalk>(surface.input)),
      inputNormals_(std::make_shared<const std::vector<Vec3>>(vertexNormals(surface.input))),
      borderWeight_(borderWeight)
{
    // Border vertices (on an edge with one face) aim at valence 4 (§4.4). They keep the places
    // the border's 1D CVT gave them, so a Free one is promoted to Boundary: the border is never
    // flipped, collapsed or split, hence a vertex's border status never changes. A Boundary one
    // that is not on the mesh's border is demoted to Free.
    const int n = vertexCount();
    std::vector<MeshVertex> vertex(n);
    std::vector<int> shared;
    double lengthSum = 0;
    long long edgeCount = 0;
    for (int f = 0; f < faceCount(); ++f)
        for (int k = 0; k < 3; ++k) {
            const int a = face(f)[k], b = face(f)[(k + 1) % 3];
            edgeFaces(a, b, shared);
            if (shared.size() == 1) vertex[a].onBorder = vertex[b].onBorder = true;
            if (a < b || shared.size() == 1) lengthSum += (position(a) - position(b)).norm(), ++edgeCount;
        }
    if (edgeCount > 0 && lengthSum > 0) edgeLength_ = lengthSum / edgeCount;
    std::vector<Vec3> start = positions();
    for (int v = 0; v < n; ++v) {
        vertex[v].role = roles.empty() ? VertexRole::Free : roles[v];
        if (vertex[v].onBorder && vertex[v].role == VertexRole::Free) {
            // (a sample whose cell reached the border during the FCVT iterations can sit inside it)
            if (!surface.border.empty()) start[v] = placeOnBorder(v, start, surface.border);
            vertex[v].role = VertexRole::Boundary;
        } else if (!vertex[v].onBorder && vertex[v].role == VertexRole::Boundary) {
            // A border sample inside the mesh (the RDT covered a hole smaller than its cells):
            // held on the input's border it kept a sliver at a fixed corner beside it (docs/tuning.md,
            // "Border samples inside the mesh"), so it moves as an interior vertex.
            vertex[v].role = VertexRole::Free;
        }
    }
#pragma omp parallel for schedule(static)
    for (int v = 0; v < n; ++v) {
        vertex[v].closest = surface.tree.closest(start[v], faceHints.empty() ? -1 : faceHints[v]);  // the hint: speed only
        vertex[v].normal = surfaceNormal(vertex[v].closest);
    }
    Ring r;
    for (int v = 0; v < n; ++v) {
        setVertex(v, start[v], vertex[v]);
        ring(v, r);
        vertex[v].manifold = r.ok && !facesOf(v).empty();
        vertex[v].valence = static_cast<int>(r.verts.size());
        setData(v, vertex[v]);
    }
}

long long ValenceMesh::irregularity() const
{
    long long sum = 0;
    for (int v = 0; v < vertexCount(); ++v) {
        if (!vertexAlive(v) || facesOf(v).empty()) continue;
        sum += cost(v, data(v).valence);
    }
    return sum;
}

void ValenceMesh::refreshValences(const std::vector<int>& verts)
{
    Ring r;
    for (int v : verts) {
        if (!vertexAlive(v)) continue;
        ring(v, r);
        MeshVertex d = data(v);
        d.manifold = r.ok && !facesOf(v).empty();
        d.valence = static_cast<int>(r.verts.size());
        setData(v, d);
    }
}

void ValenceMesh::ring(int v, Ring& r) const
{
    r.verts.clear();
    r.faces.clear();
    r.closed = true;
    r.ok = true;
    const auto& list = facesOf(v);
    const int k = static_cast<int>(list.size());
    if (k == 0) return;
    // Face (v, next, prev) turns counter-clockwise from `next` to `prev`.
    auto nextOf = [&](int f) {
        const Face& t = face(f);
        const int i = t[0] == v ? 0 : t[1] == v ? 1 : 2;
        return std::make_pair(t[(i + 1) % 3], t[(i + 2) % 3]);
    };
    // The start: the `next` of a face that is no face's `prev` (border), else the smallest
    // neighbour (a canonical start, so the ring does not depend on the face order).
    int startFace = -1, openStarts = 0;
    for (int f : list) {
        const int nxt = nextOf(f).first;
        bool isPrev = false;
        for (int g : list) isPrev |= nextOf(g).second == nxt;
        if (!isPrev) {
            ++openStarts;
            startFace = f;
        }
    }
    if (openStarts > 1) {
        r.ok = false;
        return;
    }
    r.closed = openStarts == 0;
    if (r.closed) {
        startFace = list[0];
        for (int f : list)
            if (nextOf(f).first < nextOf(startFace).first) startFace = f;
    }
    int f = startFace;
    r.verts.push_back(nextOf(f).first);
    for (int step = 0; step < k; ++step) {
        r.faces.push_back(f);
        const int prv = nextOf(f).second;
        int following = -1, matches = 0;
        for (int g : list)
            if (nextOf(g).first == prv) following = g, ++matches;
        if (matches > 1) {
            r.ok = false;
            return;
        }
        if (following < 0) {  // the end of an open fan
            r.verts.push_back(prv);
            if (step != k - 1) r.ok = false;
            break;
        }
        if (step == k - 1) {
            if (following != startFace) r.ok = false;
            break;
        }
        if (following == startFace) {  // closed before visiting every face: several fans
            r.ok = false;
            return;
        }
        r.verts.push_back(prv);
        f = following;
    }
    if (static_cast<int>(r.faces.size()) != k) r.ok = false;
    // Repeated neighbours (two faces over the same edge on the same side) are not manifold.
    // Pairwise: a ring has a few neighbours, and ring() runs for every candidate operation (no
    // allocation).
    for (size_t a = 1; a < r.verts.size() && r.ok; ++a)
        r.ok = std::find(r.verts.begin(), r.verts.begin() + a, r.verts[a]) == r.verts.begin() + a;
}

Vec3 ValenceMesh::surfaceNormal(const ClosestPoint& cp) const
{
    if (cp.face < 0) return Vec3::UnitZ();
    const Face& t = surface_->input.faces[cp.face];
    const std::vector<Vec3>& normals = *inputNormals_;
    Vec3 n = cp.barycentric[0] * normals[t[0]] + cp.barycentric[1] * normals[t[1]] + cp.barycentric[2] * normals[t[2]];
    if (!(n.squaredNorm() > 1e-24)) n = faceNormal(surface_->input, cp.face);
    const double length = n.norm();
    return length > 0 ? Vec3(n / length) : Vec3(Vec3::UnitZ());
}

Vec3 ValenceMesh::faceUnitNormal(int f) const
{
    const Face& t = face(f);
    const Vec3 n = (position(t[1]) - position(t[0])).cross(position(t[2]) - position(t[0]));
    const double length = n.norm();
    return length > 0 ? Vec3(n / length) : Vec3(Vec3::Zero());
}

void ValenceMesh::faceShape(int f, double& angle, double& dot) const
{
    const Face& t = face(f);
    angle = smallestAngle(position(t[0]), position(t[1]), position(t[2]));
    const Vec3 reference = data(t[0]).normal + data(t[1]).normal + data(t[2]).normal;
    const double length = reference.norm();
    dot = length > 0 ? faceUnitNormal(f).dot(reference) / length : -1.0;
}

void ValenceMesh::localShape(const std::vector<int>& faces, double& minAngle, double& minDot) const
{
    minAngle = kPi;
    minDot = 1;
    for (int f : faces) {
        double angle, dot;
        faceShape(f, angle, dot);
        minAngle = std::min(minAngle, angle);
        minDot = std::min(minDot, dot);
    }
}

void ValenceMesh::facesAround(const std::vector<int>& verts, std::vector<int>& faces) const
{
    faces.clear();
    for (int v : verts)
        if (vertexAlive(v)) faces.insert(faces.end(), facesOf(v).begin(), facesOf(v).end());
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
}

void ValenceMesh::place(int v, const Vec3& p, const ClosestPoint& cp)
{
    MeshVertex d = data(v);
    d.closest = cp;
    d.normal = surfaceNormal(cp);
    setVertex(v, p, d);
}

int ValenceMesh::addSurfaceVertex(const Vec3& p, VertexRole role)
{
    MeshVertex d;
    d.closest = surface_->tree.closest(p);
    d.normal = surfaceNormal(d.closest);
    d.role = role;
    return addVertex(p, d);
}

void ValenceMesh::moveTowards(int v, const Vec3& goal)
{
    const VertexRole role = data(v).role;
    if (isFixed(role)) return;
    const Vec3& normal = data(v).normal;
    Vec3 u = goal - position(v);
    u -= u.dot(normal) * normal;  // tangential
    const Vec3 q = position(v) + u;
    if (role == VertexRole::Free) {
        const ClosestPoint cp = surface_->tree.closest(q, data(v).closest.face);
        place(v, cp);
        return;
    }
    if (surface_->features.empty()) return;  // a Feature vertex with nothing to slide along: stays
    const Vec3 p = closestPointOnSegments(q, surface_->features);
    place(v, p, surface_->tree.closest(p, data(v).closest.face));
}

Vec3 ValenceMesh::oneRingCentroid(int v) const
{
    // Area-weighted mean of the one-ring triangles' centroids: the centroid of the union of the
    // triangles, a cheap stand-in for v's Voronoi cell centroid (CVT-like smoothing).
    Vec3 sum = Vec3::Zero();
    double area = 0;
    for (int f : facesOf(v)) {
        const Face& t = face(f);
        const Vec3 &p0 = position(t[0]), &p1 = position(t[1]), &p2 = position(t[2]);
        const double a = 0.5 * (p1 - p0).cross(p2 - p0).norm();
        sum += a * (p0 + p1 + p2) / 3.0;
        area += a;
    }
    return area > 0 ? Vec3(sum / area) : position(v);
}

void ValenceMesh::smoothLocally(const std::vector<int>& verts, int steps)
{
    for (int step = 0; step < steps; ++step)
        for (int v : verts)
            if (vertexAlive(v) && !facesOf(v).empty()) moveTowards(v, oneRingCentroid(v));
}

double ValenceMesh::meanFieldDistance() const
{
    if (!surface_->field) return 0;
    // Per vertex on the threads, summed in vertex order: the same figure on any thread count.
    const int n = vertexCount();
    std::vector<double> sums(size_t(n), 0.0);
    std::vector<int> counts(size_t(n), 0);
#pragma omp parallel
    {
        Ring r;
#pragma omp for schedule(static)
        for (int v = 0; v < n; ++v) {
            const ClosestPoint& c = data(v).closest;
            if (!vertexAlive(v) || c.face < 0) continue;
            const FieldSample s = interpolateField(surface_->input, *surface_->field, c.face, c.barycentric);
            ring(v, r);
            for (int w : r.verts) sums[size_t(v)] += directionDistance(position(w) - position(v), s.normal, s.direction);
            counts[size_t(v)] = static_cast<int>(r.verts.size());
        }
    }
    double sum = 0;
    long long count = 0;
    for (int v = 0; v < n; ++v) sum += sums[size_t(v)], count += counts[size_t(v)];
    return count > 0 ? sum / count : 0;
}

void ValenceMesh::compact(TriMesh& mesh, std::vector<VertexRole>& roles) const
{
    std::vector<int> index(vertexCount(), -1);
    TriMesh out;
    std::vector<VertexRole> outRoles;
    for (int v = 0; v < vertexCount(); ++v)
        if (vertexAlive(v)) {
            index[v] = out.vertexCount();
            out.vertices.push_back(position(v));
            outRoles.push_back(data(v).role);
        }
    for (int f = 0; f < faceCount(); ++f)
        if (faceAlive(f)) out.faces.push_back({index[face(f)[0]], index[face(f)[1]], index[face(f)[2]]});
    mesh = std::move(out);
    roles = std::move(outRoles);
}

}  // namespace fieldcvt::valence
