#include "valence/relax.h"

#include "boundary.h"
#include "energy.h"
#include "interpolation.h"
#include "valence/tuning.h"

#include <algorithm>
#include <cmath>

namespace fieldcvt::valence {

namespace {

//! What the relaxation carries from one step to the next.
struct Relaxation {
    std::vector<int> neighbourFirst, neighbours;  //!< CSR: each alive vertex's ring (fixed connectivity)
    double fieldFactor = 0;                       //!< E_field's gradient in mesh units
    double maxStep = 0, maxDrift = 0, minAngle = 0;
    std::vector<double> sagLimit;  //!< per face (SagGuard::relaxationLimits)
    std::vector<Vec3> startPos;
    std::vector<Vec3> lastMove;  //!< momentum; zero after a revert
    //! The field at each vertex, and where it was interpolated (face -1: not yet): a vertex whose
    //! closest point has not changed since (it stopped, or was put back) keeps its frame.
    std::vector<Vec3> frameN, frameD, frameBarycentric;
    std::vector<int> frameFace;
    //! Per face, smallest angle and normal agreement before the step and after it (the safety
    //! net measures every face after a step: the next step's "before").
    std::vector<double> angleBefore, dotBefore, angleAfter, dotAfter;
    std::vector<int> aliveFaces;  //!< the faces the safety net checks first (fixed connectivity)
    //! Work space of each step, kept across steps (400 000 vertices: ~90 MB a step otherwise).
    std::vector<Vec3> newPos;
    std::vector<ClosestPoint> newClosest;
    std::vector<char> moves, wrong;
};

Relaxation setUp(const ValenceMesh& mesh, SagGuard& sag, const ValenceParams& params)
{
    Relaxation s;
    const int n = mesh.vertexCount();
    s.neighbourFirst.assign(n + 1, 0);
    Ring r;
    for (int v = 0; v < n; ++v) {
        if (mesh.vertexAlive(v)) {
            mesh.ring(v, r);
            s.neighbours.insert(s.neighbours.end(), r.verts.begin(), r.verts.end());
        }
        s.neighbourFirst[v + 1] = static_cast<int>(s.neighbours.size());
    }
    double area = 0;
    int alive = 0;
    for (int f = 0; f < mesh.faceCount(); ++f) {
        if (!mesh.faceAlive(f)) continue;
        const Face& t = mesh.face(f);
        area += 0.5 * (mesh.position(t[1]) - mesh.position(t[0])).cross(mesh.position(t[2]) - mesh.position(t[0])).norm();
    }
    for (int v = 0; v < n; ++v) alive += mesh.vertexAlive(v);
    // Working scale of remesh(): mean cell area 1. E_field's gradient converted to mesh units.
    const double workScale = area > 0 ? std::sqrt(alive / area) : 1.0;
    s.fieldFactor = params.fieldWeight / (2.0 * std::sqrt(3.0) * workScale);
    s.maxStep = kMaxRelaxStep * mesh.edgeLength();
    s.maxDrift = kMaxDrift * mesh.edgeLength();
    s.minAngle = params.minAngleDegrees * kPi / 180.0;
    s.sagLimit = sag.relaxationLimits();
    s.startPos = mesh.positions();
    s.lastMove.assign(n, Vec3::Zero());
    s.frameN.assign(n, Vec3::UnitZ());
    s.frameD.assign(n, Vec3::UnitX());
    s.frameBarycentric.resize(n);
    s.frameFace.assign(n, -1);
    const int faceCount = mesh.faceCount();
    for (auto* measure : {&s.angleBefore, &s.dotBefore, &s.angleAfter, &s.dotAfter}) measure->resize(faceCount);
#pragma omp parallel for schedule(static)
    for (int f = 0; f < faceCount; ++f)
        if (mesh.faceAlive(f)) mesh.faceShape(f, s.angleBefore[f], s.dotBefore[f]);
    for (int f = 0; f < faceCount; ++f)
        if (mesh.faceAlive(f)) s.aliveFaces.push_back(f);
    s.newPos.resize(n);
    s.newClosest.resize(n);
    s.moves.resize(n);
    s.wrong.resize(faceCount);
    return s;
}

void updateFrames(const ValenceMesh& mesh, Relaxation& s)
{
    const ValenceSurface& surface = mesh.surface();
#pragma omp parallel for schedule(static)
    for (int v = 0; v < mesh.vertexCount(); ++v) {
        const ClosestPoint& c = mesh.data(v).closest;
        if (!mesh.vertexAlive(v) || c.face < 0 || (c.face == s.frameFace[v] && c.barycentric == s.frameBarycentric[v])) continue;
        const FieldSample sample = interpolateField(surface.input, *surface.field, c.face, c.barycentric);
        s.frameN[v] = sample.normal;
        s.frameD[v] = sample.direction;
        s.frameFace[v] = c.face;
        s.frameBarycentric[v] = c.barycentric;
    }
}

//! Where v's step takes it (and its closest point); false where it stays.
bool stepOf(const ValenceMesh& mesh, const Relaxation& s, bool withField, int v, Vec3& to, ClosestPoint& toClosest)
{
    const MeshVertex& vertex = mesh.data(v);
    if (!mesh.vertexAlive(v) || isFixed(vertex.role) || mesh.facesOf(v).empty()) return false;
    if (s.neighbourFirst[v + 1] == s.neighbourFirst[v]) return false;  // not a single fan: left alone
    // Down the shape energy of the incident faces (what Q_avg and the angles measure), not to the
    // mean of the neighbours (see docs/tuning.md, "Relaxation step").
    const Vec3& p = mesh.position(v);
    Vec3 shapeGradient = Vec3::Zero();
    double areaSum = 0;
    for (int f : mesh.facesOf(v)) {
        const Face& t = mesh.face(f);
        const int k = t[0] == v ? 0 : t[1] == v ? 1 : 2;
        double faceArea;
        shapeGradient += shapeEnergyGradient(p, mesh.position(t[(k + 1) % 3]), mesh.position(t[(k + 2) % 3]), faceArea);
        areaSum += faceArea;
    }
    Vec3 u = -kShapeStep * (areaSum / mesh.facesOf(v).size()) * shapeGradient;
    if (withField) {
        Vec3 gradient = Vec3::Zero(), g;
        for (int k = s.neighbourFirst[v]; k < s.neighbourFirst[v + 1]; ++k) {
            const int w = s.neighbours[k];
            const Vec3 e = mesh.position(w) - p;
            const double length = e.norm();
            directionDistance(e, s.frameN[v], s.frameD[v], &g);
            gradient -= length * g;
            directionDistance(-e, s.frameN[w], s.frameD[w], &g);
            gradient += length * g;
        }
        u -= s.fieldFactor * gradient;
    }
    u += kRelaxMomentum * s.lastMove[v];
    u -= u.dot(vertex.normal) * vertex.normal;
    const double length = u.norm();
    if (length > s.maxStep) u *= s.maxStep / length;
    const Vec3 q = p + u;
    const ValenceSurface& surface = mesh.surface();
    if (vertex.role == VertexRole::Free) {
        // A short walk over the input from the vertex's face (a step moves it by at most a
        // quarter edge): the nearest point of the surface around it, which is the closest point
        // but where another sheet of the surface comes nearer; the tree where the walk does not
        // settle within its steps.
        bool settled = false;
        ClosestPoint cp = mesh.walk().closestFrom(q, vertex.closest.face, &settled);
        if (!settled) cp = surface.tree.closest(q, vertex.closest.face);
        // A vertex drifting far from where it started can slide off ridges and tips it covered.
        if ((cp.point - s.startPos[v]).norm() > s.maxDrift) return false;
        toClosest = cp;
        to = cp.point;
        return true;
    }
    if (surface.features.empty()) return false;
    to = closestPointOnSegments(q, surface.features);
    toClosest = surface.tree.closest(to, vertex.closest.face);
    return true;
}

//! One Jacobi step: every vertex computed from the previous positions, so the result does not
//! depend on the thread count. `old` receives the positions and data before it.
void step(ValenceMesh& mesh, Relaxation& s, bool withField, std::vector<Vec3>& oldPos, std::vector<MeshVertex>& oldData)
{
    const int n = mesh.vertexCount();
    oldPos.resize(n);
    oldData.resize(n);
    std::vector<Vec3>& newPos = s.newPos;
    std::vector<ClosestPoint>& newClosest = s.newClosest;
    std::vector<char>& moves = s.moves;
#pragma omp parallel for schedule(static)
    for (int v = 0; v < n; ++v) {
        oldPos[v] = newPos[v] = mesh.position(v);
        oldData[v] = mesh.data(v);
        moves[v] = stepOf(mesh, s, withField, v, newPos[v], newClosest[v]);
        s.lastMove[v] = newPos[v] - oldPos[v];
    }
#pragma omp parallel for schedule(static)
    for (int v = 0; v < n; ++v)
        if (moves[v]) mesh.place(v, newPos[v], newClosest[v]);
}

//! A face that folds, gets a smaller angle than allowed (and than before) or leaves the surface
//! (sag) puts its corners back; then the faces of those corners are checked again, until no
//! face is worse (the old state is valid).
void safetyNet(ValenceMesh& mesh, SagGuard& sag, Relaxation& s, const std::vector<Vec3>& oldPos,
               const std::vector<MeshVertex>& oldData)
{
    std::vector<int> check = s.aliveFaces;
    std::vector<char>& wrong = s.wrong;
    for (;;) {
#pragma omp parallel for schedule(static)
        for (int k = 0; k < static_cast<int>(check.size()); ++k) {
            const int f = check[k];
            double& angle = s.angleAfter[f];
            double& dot = s.dotAfter[f];
            mesh.faceShape(f, angle, dot);
            const bool folded = dot < std::min(kRelaxMinNormalDot, s.dotBefore[f]);
            const bool sharper = angle < s.minAngle && angle < s.angleBefore[f] - 1e-9;
            const bool offSurface = sag.exceeds(f, s.sagLimit[f]);
            wrong[f] = folded || sharper || offSurface;
        }
        std::vector<int> revert;
        for (int f : check)
            if (wrong[f]) revert.insert(revert.end(), mesh.face(f).begin(), mesh.face(f).end());
        if (revert.empty()) break;
        std::sort(revert.begin(), revert.end());
        revert.erase(std::unique(revert.begin(), revert.end()), revert.end());
        check.clear();
        for (int v : revert) {
            mesh.setVertex(v, oldPos[v], oldData[v]);
            s.lastMove[v] = Vec3::Zero();
            check.insert(check.end(), mesh.facesOf(v).begin(), mesh.facesOf(v).end());
        }
        std::sort(check.begin(), check.end());
        check.erase(std::unique(check.begin(), check.end()), check.end());
    }
}

}  // namespace

Vec3 shapeEnergyGradient(const Vec3& v, const Vec3& a, const Vec3& b, double& area)
{
    const Vec3 twiceAreaNormal = (a - v).cross(b - v);
    const double twiceArea = twiceAreaNormal.norm();
    area = 0.5 * twiceArea;
    if (!(twiceArea > 0)) return Vec3::Zero();
    const double c = 4 * std::sqrt(3.0);
    const double lengths = (a - v).squaredNorm() + (b - v).squaredNorm() + (a - b).squaredNorm();
    // d|t|/dv = (n x (b - a)) / 2: moving v away from the edge ab grows the triangle.
    const Vec3 areaGradient = 0.5 * (twiceAreaNormal / twiceArea).cross(b - a);
    return 2 * (2 * v - a - b) / (c * area) - lengths / (c * area * area) * areaGradient;
}

void relax(ValenceMesh& mesh, SagGuard& sag, const ValenceParams& params)
{
    // The connectivity is fixed (the regularity gained stays); with heavy-ball momentum.
    Relaxation s = setUp(mesh, sag, params);
    const bool withField = mesh.surface().field && params.fieldWeight > 0;
    std::vector<Vec3> oldPos;
    std::vector<MeshVertex> oldData;
    for (int iteration = 0; iteration < params.relaxIterations; ++iteration) {
        if (withField) updateFrames(mesh, s);
        if (iteration > 0) {
            s.angleBefore.swap(s.angleAfter);
            s.dotBefore.swap(s.dotAfter);
        }
        step(mesh, s, withField, oldPos, oldData);
        safetyNet(mesh, sag, s, oldPos, oldData);
    }
}

}  // namespace fieldcvt::valence
