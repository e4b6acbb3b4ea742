#include "valence/sag_guard.h"

#include "mesh_edges.h"
#include "valence/tuning.h"

#include <algorithm>
#include <limits>

namespace fieldcvt::valence {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

void SagGuard::sagPoints(int f, Vec3 (&points)[4], int (&starts)[4]) const
{
    // The centroid and the edge midpoints: an edge across a crease sags most at its middle.
    // The queries start from a corner's closest face (same answers, fewer tree nodes visited).
    const Face& t = mesh_.face(f);
    const Vec3 &p0 = mesh_.position(t[0]), &p1 = mesh_.position(t[1]), &p2 = mesh_.position(t[2]);
    points[0] = (p0 + p1 + p2) / 3.0;
    points[1] = 0.5 * (p0 + p1);
    points[2] = 0.5 * (p1 + p2);
    points[3] = 0.5 * (p2 + p0);
    starts[0] = starts[1] = mesh_.data(t[0]).closest.face;
    starts[2] = mesh_.data(t[1]).closest.face;
    starts[3] = mesh_.data(t[2]).closest.face;
}

double SagGuard::exactDistance(const Vec3& point, int start) const
{
    return (mesh_.surface().tree.closest(point, start).point - point).norm();
}

double SagGuard::floor() const { return kMaxSag * mesh_.edgeLength(); }

SagGuard::Entry& SagGuard::entry(int f)
{
    if (f >= static_cast<int>(cache_.size())) cache_.resize(mesh_.faceCount());
    Entry& e = cache_[f];
    const Face& t = mesh_.face(f);
    if (e.face != t) {
        e.face = t;
        e.corners = {mesh_.position(t[0]), mesh_.position(t[1]), mesh_.position(t[2])};
        e.bound.fill(kInfinity);
        e.walkStart.fill(-1);
        e.exact = 0;
    }
    return e;
}

bool SagGuard::unmoved(const Entry& e) const
{
    const Face& t = e.face;
    return e.corners == std::array<Vec3, 3>{mesh_.position(t[0]), mesh_.position(t[1]), mesh_.position(t[2])};
}

double SagGuard::sag(int f)
{
    Entry& e = entry(f);
    if (!unmoved(e)) {
        const Face& t = e.face;
        e.corners = {mesh_.position(t[0]), mesh_.position(t[1]), mesh_.position(t[2])};
        e.exact = 0;
    }
    if (e.exact != kAllExact) {
        Vec3 points[4];
        int starts[4];
        sagPoints(f, points, starts);
        for (int k = 0; k < 4; ++k)
            if (!(e.exact >> k & 1)) e.bound[k] = exactDistance(points[k], starts[k]);
        e.exact = kAllExact;
    }
    double sag = 0;
    for (int k = 0; k < 4; ++k) sag = std::max(sag, e.bound[k]);
    return sag;
}

double SagGuard::bound(int f) const
{
    Vec3 points[4];
    int starts[4];
    sagPoints(f, points, starts);
    double sag = 0;
    for (int k = 0; k < 4; ++k) sag = std::max(sag, mesh_.walk().distanceBound(points[k], starts[k]));
    return sag;
}

double SagGuard::knownBound(int f)
{
    Entry& e = entry(f);
    if (!unmoved(e)) {  // a bound from the walks, not from the corners' moves: it may decide more
        const Face& t = e.face;
        e.corners = {mesh_.position(t[0]), mesh_.position(t[1]), mesh_.position(t[2])};
        e.bound.fill(kInfinity);
        e.exact = 0;
    }
    Vec3 points[4];
    int starts[4];
    bool measured = false;
    double sag = 0;
    for (int k = 0; k < 4; ++k) {
        if (e.bound[k] == kInfinity && !(e.exact >> k & 1)) {
            if (!measured) sagPoints(f, points, starts), measured = true;
            int& start = e.walkStart[k];
            if (start < 0) start = starts[k];
            e.bound[k] = mesh_.walk().distanceBound(points[k], start, &start);
        }
        sag = std::max(sag, e.bound[k]);
    }
    return sag;
}

bool SagGuard::exceeds(int f, double limit)
{
    Entry& e = entry(f);
    const Face& t = e.face;
    double m[3];
    for (int k = 0; k < 3; ++k) m[k] = (mesh_.position(t[k]) - e.corners[k]).norm();
    // A sag point moves by at most the mean of its corners' moves.
    const double moved[4] = {(m[0] + m[1] + m[2]) / 3, 0.5 * (m[0] + m[1]), 0.5 * (m[1] + m[2]), 0.5 * (m[2] + m[0])};
    const double safe = limit * (1 - 1e-9);  // the moves' rounding
    bool within = true;
    for (int k = 0; k < 4; ++k) within = within && e.bound[k] + moved[k] <= safe;
    if (within) return false;
    const bool same = unmoved(e);
    if (!same) {
        e.corners = {mesh_.position(t[0]), mesh_.position(t[1]), mesh_.position(t[2])};
        e.exact = 0;
    }
    Vec3 points[4];
    int starts[4];
    sagPoints(f, points, starts);
    bool exceeds = false;
    for (int k = 0; k < 4; ++k) {
        if (e.bound[k] + moved[k] <= safe) {
            e.bound[k] += moved[k];  // still a bound at the corners now
            continue;
        }
        if (same && (e.exact >> k & 1)) {
            exceeds = exceeds || e.bound[k] > limit;
            continue;
        }
        int& start = e.walkStart[k];
        if (start < 0) start = starts[k];
        e.bound[k] = mesh_.walk().distanceBound(points[k], start, &start);
        if (e.bound[k] <= limit || exceeds) continue;  // one point over the limit answers
        e.bound[k] = exactDistance(points[k], starts[k]);
        e.exact |= 1 << k;
        exceeds = e.bound[k] > limit;
    }
    return exceeds;
}

bool SagGuard::exceedsAny(const std::vector<int>& faces, double limit)
{
    for (int f : faces)
        if (exceeds(f, limit)) return true;
    return false;
}

double SagGuard::operationLimit(const std::vector<int>& faces)
{
    // The limit is monotone in the sag, so a face whose upper bound cannot lift it above the
    // floor needs no exact measure: the same limit, bit for bit, with tree queries only where a
    // face may set it.
    const double floor = this->floor();
    const double step = kOperationSagStep * mesh_.edgeLength();
    auto grown = [&](double sag) { return std::min(kOperationSagGrowth * sag, sag + step); };
    double limit = floor;
    for (int f : faces) {
        if (grown(knownBound(f)) <= floor) continue;  // (a NaN bound is measured)
        limit = std::max(limit, grown(sag(f)));
    }
    return limit;
}

double SagGuard::repairLimit(const std::vector<int>& faces)
{
    double largest = 0;
    for (int f : faces) largest = std::max(largest, sag(f));
    return std::max(kRelaxSagGrowth * largest, floor());
}

std::vector<double> SagGuard::relaxationLimits()
{
    // The sag points (centroids, and edge midpoints once for their two faces) get a walk's upper
    // bound first; the exact distance (tree) only where it can decide something: the points that
    // may hold the largest sag, and those whose bound could lift their face's limit above the
    // floor. Elsewhere the limit is the floor either way: the same limits, bit for bit, from ~a
    // fifth of the tree queries.
    const int faceCount = mesh_.faceCount();
    std::vector<Face> liveFaces;
    std::vector<int> liveFace(faceCount, -1);
    for (int f = 0; f < faceCount; ++f)
        if (mesh_.faceAlive(f)) liveFace[f] = static_cast<int>(liveFaces.size()), liveFaces.push_back(mesh_.face(f));
    const EdgeTable liveEdges = buildEdgeTable(liveFaces, mesh_.vertexCount());
    // Sag points: the live edges' midpoints (as sagPoints computes them for the edge's first
    // face; the sum commutes, so its other face gets the same point), then the live faces' centroids.
    const int edgePoints = liveEdges.edgeCount(), pointCount = edgePoints + static_cast<int>(liveFaces.size());
    auto sagPoint = [&](int q, Vec3& x, int& start) {
        if (q < edgePoints) {
            const int h = liveEdges.halfEdge(q, 0);
            const Face& t = liveFaces[h / 3];
            const int k = h % 3;
            x = 0.5 * (mesh_.position(t[k]) + mesh_.position(t[(k + 1) % 3]));
            start = mesh_.data(t[k]).closest.face;
        } else {
            const Face& t = liveFaces[q - edgePoints];
            x = (mesh_.position(t[0]) + mesh_.position(t[1]) + mesh_.position(t[2])) / 3.0;
            start = mesh_.data(t[0]).closest.face;
        }
    };
    std::vector<double> startSag(pointCount);  // a bound, exact where `exact`
    std::vector<char> exact(pointCount, 0);
    auto measureExactly = [&](int q) {
        Vec3 x;
        int start;
        sagPoint(q, x, start);
        startSag[q] = exactDistance(x, start);
        exact[q] = 1;
    };
    auto measureExactlyWhere = [&](auto&& needed) {
#pragma omp parallel for schedule(static)
        for (int q = 0; q < pointCount; ++q)
            if (!exact[q] && needed(q)) measureExactly(q);
    };
#pragma omp parallel for schedule(static)
    for (int q = 0; q < pointCount; ++q) {
        Vec3 x;
        int start;
        sagPoint(q, x, start);
        startSag[q] = mesh_.walk().distanceBound(x, start);
    }
    // The largest sag: exact at the point of the largest bound, then wherever a bound exceeds it.
    double largestStartSag = 0;
    if (pointCount > 0) {
        const int top = static_cast<int>(std::max_element(startSag.begin(), startSag.end()) - startSag.begin());
        measureExactly(top);
        const double reached = startSag[top];
        measureExactlyWhere([&](int q) { return startSag[q] > reached; });
        for (int q = 0; q < pointCount; ++q)
            if (exact[q]) largestStartSag = std::max(largestStartSag, startSag[q]);
    }
    const double sagFloor = std::max(floor(), kRelaxSagShareOfLargest * largestStartSag);
    measureExactlyWhere([&](int q) { return kRelaxSagGrowth * startSag[q] > sagFloor; });
    // Per face: its points' bounds become its cache entry, and its limit comes from the largest
    // (exact where it lifts the limit above the floor, a bound under the floor elsewhere).
    std::vector<double> limits(faceCount, sagFloor);
    cache_.resize(faceCount);
    for (int f = 0; f < faceCount; ++f) {
        const int g = liveFace[f];
        if (g < 0) continue;
        const int points[4] = {edgePoints + g, liveEdges.edgeOf(g, 0), liveEdges.edgeOf(g, 1), liveEdges.edgeOf(g, 2)};
        Entry& e = cache_[f];
        const Face& t = mesh_.face(f);
        e.face = t;
        e.corners = {mesh_.position(t[0]), mesh_.position(t[1]), mesh_.position(t[2])};
        e.walkStart.fill(-1);
        e.exact = 0;
        for (int k = 0; k < 4; ++k) {
            e.bound[k] = startSag[points[k]];
            e.exact |= exact[points[k]] << k;
        }
        limits[f] = std::max(kRelaxSagGrowth * *std::max_element(e.bound.begin(), e.bound.end()), sagFloor);
    }
    return limits;
}

}  // namespace fieldcvt::valence
