#include "valence/repairs.h"

#include "boundary.h"
#include "triangle_shape.h"
#include "valence/tuning.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace fieldcvt::valence {

namespace {

//! Whether the repairs may move v: a live Free vertex with a single fan of faces.
bool repairMovable(const ValenceMesh& mesh, int v)
{
    return mesh.vertexAlive(v) && mesh.data(v).role == VertexRole::Free && !mesh.facesOf(v).empty() && mesh.data(v).manifold;
}

//! The repairs' pattern search for a Free vertex v on the surface: 8 directions in its tangent
//! plane, a first step of kAngleRepairStep edge lengths halved when none improves, down to
//! `smallestStepShare` of it, at most `maxSteps` steps, within kAngleRepairDrift edges of where
//! v was. At each trial position (v and its closest point set) `improves()` says whether it is
//! the best so far (and keeps its score); the search stops early once `done()`. v ends at the
//! best position; returns whether it moved.
template <class Improves, class Done>
bool searchOnSurface(ValenceMesh& mesh, int v, int maxSteps, double smallestStepShare, Improves&& improves, Done&& done)
{
    // Tangent directions at v: 8 around its normal.
    const Vec3 n = mesh.data(v).normal;
    const Vec3 t1 = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
    const Vec3 t2 = n.cross(t1);
    const Vec3 start = mesh.position(v);
    const double edgeLength = mesh.edgeLength();
    Vec3 bestPos = start;
    ClosestPoint bestClosest = mesh.data(v).closest;
    double step = kAngleRepairStep * edgeLength;
    for (int iteration = 0; iteration < maxSteps && !done() && step > kAngleRepairStep * edgeLength * smallestStepShare;
         ++iteration) {
        const Vec3 centre = bestPos;
        const ClosestPoint centreClosest = bestClosest;
        bool improved = false;
        for (int k = 0; k < 8; ++k) {
            const double phi = k * kPi / 4;
            const Vec3 q = centre + step * (std::cos(phi) * t1 + std::sin(phi) * t2);
            const ClosestPoint cp = mesh.surface().tree.closest(q, centreClosest.face);
            if ((cp.point - start).norm() > kAngleRepairDrift * edgeLength) continue;
            mesh.place(v, cp);
            if (improves()) {
                bestPos = cp.point, bestClosest = cp;
                improved = true;
            }
        }
        mesh.place(v, bestPos, bestClosest);
        if (!improved) step *= 0.5;
    }
    return bestPos != start;
}

//! What the angle repair asks of a move of v: a larger smallest angle around v than the best so
//! far, no face folding past kMinNormalDot (or past where it started), none sagging over the guard.
struct AngleGoal {
    AngleGoal(ValenceMesh& mesh_, SagGuard& sag_, int v) : mesh(mesh_), sag(sag_), faces(mesh_.facesOf(v))
    {
        double dotBefore;
        mesh.localShape(faces, best, dotBefore);
        sagLimit = sag.repairLimit(faces);
        minDot = std::min(kMinNormalDot, dotBefore);
    }
    //! Whether v where it is now is the best place so far (and keeps its angle if so).
    bool improves()
    {
        double angle, dot;
        mesh.localShape(faces, angle, dot);
        if (!(angle > best + 1e-9 && dot >= minDot && !sag.exceedsAny(faces, sagLimit))) return false;
        best = angle;
        return true;
    }
    ValenceMesh& mesh;
    SagGuard& sag;
    const std::vector<int>& faces;
    double best = 0, sagLimit = 0, minDot = 0;
};

//! One vertex of raiseSmallestAngles; returns whether it moved.
bool raiseAnglesAround(ValenceMesh& mesh, SagGuard& sag, int v)
{
    if (!repairMovable(mesh, v)) return false;
    AngleGoal goal(mesh, sag, v);
    return searchOnSurface(
        mesh, v, kAngleRepairMaxSteps, 1.0 / 32, [&] { return goal.improves(); }, [] { return false; });
}

//! One Boundary vertex of raiseSmallestAngles: slides along the input's border (the pieces of it
//! within reach), a step of kAngleRepairStep edge lengths each way along the nearest piece,
//! halved when neither improves, within kAngleRepairDrift edge lengths of where it was. A trial
//! whose closest border point is far from the trial point (the border of another hole across a
//! narrow strip) is skipped: v stays on its own border. Returns whether it moved.
bool slideAlongBorder(ValenceMesh& mesh, SagGuard& sag, int v)
{
    if (!mesh.vertexAlive(v) || mesh.data(v).role != VertexRole::Boundary || mesh.facesOf(v).empty() || !mesh.data(v).manifold ||
        mesh.surface().border.empty())
        return false;
    const double edgeLength = mesh.edgeLength();
    const Vec3 start = mesh.position(v);
    const double reach = (kAngleRepairDrift + kAngleRepairStep) * edgeLength;
    std::vector<Segment> near;
    for (const Segment& segment : mesh.surface().border) {
        double squared = 0;
        closestPointOnSegment(start, segment, &squared);
        if (squared <= reach * reach) near.push_back(segment);
    }
    if (near.empty()) return false;
    AngleGoal goal(mesh, sag, v);
    Vec3 bestPos = start;
    ClosestPoint bestClosest = mesh.data(v).closest;
    double step = kAngleRepairStep * edgeLength;
    for (int iteration = 0; iteration < kAngleRepairMaxSteps && step > kAngleRepairStep * edgeLength / 32; ++iteration) {
        // The direction of the border piece nearest to where v is now.
        double nearest = std::numeric_limits<double>::infinity();
        Vec3 along = Vec3::Zero();
        for (const Segment& segment : near) {
            double squared = 0;
            closestPointOnSegment(bestPos, segment, &squared);
            if (squared < nearest) nearest = squared, along = segment.second - segment.first;
        }
        if (!(along.norm() > 0)) break;
        along.normalize();
        const Vec3 centre = bestPos;
        const ClosestPoint centreClosest = bestClosest;
        bool improved = false;
        for (double sign : {-1.0, 1.0}) {
            const Vec3 q = centre + sign * step * along;
            const Vec3 onBorder = closestPointOnSegments(q, near);
            if ((onBorder - q).norm() > 0.5 * step || (onBorder - start).norm() > kAngleRepairDrift * edgeLength) continue;
            mesh.place(v, onBorder, mesh.surface().tree.closest(onBorder, centreClosest.face));
            if (goal.improves()) {
                bestPos = mesh.position(v), bestClosest = mesh.data(v).closest;
                improved = true;
            }
        }
        mesh.place(v, bestPos, bestClosest);
        if (!improved) step *= 0.5;
    }
    return bestPos != start;
}

//! One vertex of lowerLargestSags: its faces' largest sag down towards `target`; returns
//! whether it moved.
bool lowerSagAround(ValenceMesh& mesh, SagGuard& sag, const ValenceParams& params, int v, double target)
{
    if (!repairMovable(mesh, v)) return false;
    const std::vector<int>& faces = mesh.facesOf(v);
    double angleBefore, dotBefore;
    mesh.localShape(faces, angleBefore, dotBefore);
    const double minDot = std::min(kMinNormalDot, dotBefore);
    // Per face: no smallest angle under min(35° + margin, its own before). (A vertex of more
    // than 32 faces is left alone: no such fan is worth moving.)
    const double angleBound = (params.minAngleDegrees + kSagRepairAngleMargin) * kPi / 180.0;
    double faceAngleBefore[32];
    const int faceCount = static_cast<int>(faces.size());
    if (faceCount > 32) return false;
    auto angleOf = [&](int f) {
        const Face& t = mesh.face(f);
        return smallestAngle(mesh.position(t[0]), mesh.position(t[1]), mesh.position(t[2]));
    };
    for (int i = 0; i < faceCount; ++i) faceAngleBefore[i] = std::min(angleBound, angleOf(faces[i]));
    auto sharper = [&] {
        for (int i = 0; i < faceCount; ++i)
            if (angleOf(faces[i]) < faceAngleBefore[i]) return true;
        return false;
    };
    // Down to the band's lower edge, no further: the faces' shape pays for every move.
    auto largestSag = [&] {
        double largest = target;
        for (int f : faces) largest = std::max(largest, sag.sag(f));
        return largest;
    };
    auto meanShape = [&] {
        double sum = 0;
        for (int f : faces) {
            const Face& t = mesh.face(f);
            sum += meanRatio(mesh.position(t[0]), mesh.position(t[1]), mesh.position(t[2]));
        }
        return sum / faces.size();
    };
    const double minShape = meanShape() - kSagRepairShapeLoss;
    double best = largestSag();
    int order[32];
    std::copy(faces.begin(), faces.end(), order);
    auto improves = [&] {
        double angle, dot;
        mesh.localShape(faces, angle, dot);  // (the angles per face: sharper())
        if (dot < minDot || sharper() || meanShape() < minShape) return false;
        // largestSag() < limit, face by face: the first face at or over the limit answers (most
        // trial positions are refused, and each face's sag costs four closest-point queries);
        // the face that refused the last one is asked first.
        const double limit = best * (1 - 1e-6);
        if (!(target < limit)) return false;
        double sagHere = target;
        for (int i = 0; i < faceCount; ++i) {
            const double s = sag.sag(order[i]);
            if (s >= limit) {
                std::swap(order[0], order[i]);
                return false;
            }
            sagHere = std::max(sagHere, s);
        }
        best = sagHere;
        return true;
    };
    return searchOnSurface(mesh, v, kSagRepairMaxSteps, 1.0 / 8, improves, [&] { return !(best > target); });
}

//! The faces whose sag is within kSagRepairBand of the largest (at most kSagRepairFaces, the
//! largest first), and that largest sag. `bound` holds each face's SagGuard::bound.
double largestSagFaces(const ValenceMesh& mesh, SagGuard& sag, const std::vector<double>& bound, std::vector<int>& faces)
{
    // The walks' bounds (at least the sag, equal to it where the walk settles: most faces) rank
    // the faces; the exact sag is measured down the ranking only until the bounds fall under
    // the band of the largest sag found, so only a few faces need tree queries.
    std::vector<int> order;
    for (int f = 0; f < mesh.faceCount(); ++f)
        if (mesh.faceAlive(f)) order.push_back(f);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return bound[a] != bound[b] ? bound[a] > bound[b] : a < b; });
    double largest = 0;
    std::vector<std::pair<double, int>> measured;
    for (int f : order) {
        if (bound[f] < (1 - kSagRepairBand) * largest) break;
        const double s = sag.sag(f);
        largest = std::max(largest, s);
        measured.emplace_back(s, f);
    }
    // The largest first, ties by index.
    std::sort(measured.begin(), measured.end(),
              [](const auto& a, const auto& b) { return a.first != b.first ? a.first > b.first : a.second < b.second; });
    faces.clear();
    for (const auto& [s, f] : measured)
        if (s >= (1 - kSagRepairBand) * largest && faces.size() < static_cast<size_t>(kSagRepairFaces)) faces.push_back(f);
    return largest;
}

}  // namespace

void raiseSmallestAngles(ValenceMesh& mesh, SagGuard& sag, const ValenceParams& params)
{
    const double minAngle = params.minAngleDegrees * kPi / 180.0;
    std::vector<int> verts;
    for (int round = 0; round < kAngleRepairRounds; ++round) {
        verts.clear();
        for (int f = 0; f < mesh.faceCount(); ++f) {
            if (!mesh.faceAlive(f)) continue;
            const Face& t = mesh.face(f);
            if (smallestAngle(mesh.position(t[0]), mesh.position(t[1]), mesh.position(t[2])) < minAngle)
                verts.insert(verts.end(), t.begin(), t.end());
        }
        if (verts.empty()) return;
        std::sort(verts.begin(), verts.end());
        verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
        bool moved = false;
        for (int v : verts)  // Gauss–Seidel, index order
            moved =
                (mesh.data(v).role == VertexRole::Boundary ? slideAlongBorder(mesh, sag, v) : raiseAnglesAround(mesh, sag, v)) ||
                moved;
        if (!moved) return;
    }
}

void lowerLargestSags(ValenceMesh& mesh, SagGuard& sag, const ValenceParams& params)
{
    const int faceCount = mesh.faceCount();
    std::vector<double> bound(faceCount, -1.0);
    std::vector<int> faces, verts;
    std::vector<int> movedVertices;  // by the last round
    for (int round = 0; round < params.sagRepairRounds; ++round) {
        // After the first round only the faces of the vertices it moved are walked again (a
        // face whose corners and their closest points are as they were has the same bound).
        if (round == 0) {
#pragma omp parallel for schedule(static)
            for (int f = 0; f < faceCount; ++f) bound[f] = mesh.faceAlive(f) ? sag.bound(f) : -1.0;
        } else {
            for (int v : movedVertices)
                for (int f : mesh.facesOf(v)) bound[f] = mesh.faceAlive(f) ? sag.bound(f) : -1.0;
        }
        const double largest = largestSagFaces(mesh, sag, bound, faces);
        // A flat mesh's sags are rounding noise: nothing to gain, and its shape to lose.
        if (!(largest > kSagRepairMinSag * mesh.edgeLength())) return;
        verts.clear();
        for (int f : faces) verts.insert(verts.end(), mesh.face(f).begin(), mesh.face(f).end());
        std::sort(verts.begin(), verts.end());
        verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
        bool moved = false;
        movedVertices.clear();
        for (int v : verts) {  // Gauss–Seidel
            const Vec3 position = mesh.position(v);
            const int face = mesh.data(v).closest.face;
            moved = lowerSagAround(mesh, sag, params, v, (1 - kSagRepairBand) * largest) || moved;
            if (mesh.position(v) != position || mesh.data(v).closest.face != face) movedVertices.push_back(v);
        }
        if (!moved) return;
    }
}

}  // namespace fieldcvt::valence
