#include "thin_parts.h"

#include "boundary.h"
#include "mesh_edges.h"
#include "point_tree.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace fieldcvt {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
//! Two points of one border loop bound a slot (a thin strip of surface between them) when they
//! are more than this many times as far apart along the loop as across: a round hole's opposite
//! points are pi / 2 apart along it.
constexpr double kSlotArcRatio = 3;
//! Shrinking-ball steps: each step at least halves the radius in practice; 40 is far beyond what
//! a ball needs from the edge length down to a face's rounding.
constexpr int kMaxBallSteps = 40;
//! A ball whose closest surface point is this close to its radius (relative) is empty.
constexpr double kEmptyBallTolerance = 1e-9;

Vec3 faceCentroid(const TriMesh& mesh, int f)
{
    return (mesh.vertices[mesh.faces[f][0]] + mesh.vertices[mesh.faces[f][1]] + mesh.vertices[mesh.faces[f][2]]) / 3.0;
}

//! The points of face f whose thickness is measured: its centroid and the midpoints between it
//! and each corner, so that a face larger than a thin part is not judged by its centre alone.
std::array<Vec3, 4> probePoints(const TriMesh& mesh, int f)
{
    const Vec3 centroid = faceCentroid(mesh, f);
    return {centroid, 0.5 * (centroid + mesh.vertices[mesh.faces[f][0]]), 0.5 * (centroid + mesh.vertices[mesh.faces[f][1]]),
            0.5 * (centroid + mesh.vertices[mesh.faces[f][2]])};
}

//! The wanted edge length of every face made graded: along a path of faces it grows by at most
//! `gradation` per unit of centroid distance (a multi-source Dijkstra from the finest faces).
void gradeEdgeLengths(const TriMesh& mesh, double gradation, std::vector<double>& length)
{
    const EdgeTable edges = buildEdgeTable(mesh, RepeatedVertexFaces::Skip);
    std::vector<Vec3> centroid(mesh.faces.size());
    for (int f = 0; f < mesh.faceCount(); ++f) centroid[f] = faceCentroid(mesh, f);
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    for (int f = 0; f < mesh.faceCount(); ++f)
        if (std::isfinite(length[f])) queue.push({length[f], f});
    while (!queue.empty()) {
        const auto [h, f] = queue.top();
        queue.pop();
        if (h > length[f]) continue;  // an older, longer entry
        for (int k = 0; k < 3; ++k) {
            const int e = edges.edgeOf(f, k);
            if (e < 0) continue;
            for (int i = 0; i < edges.faceCount(e); ++i) {
                const int g = edges.face(e, i);
                const double through = h + gradation * (centroid[g] - centroid[f]).norm();
                if (through < length[g]) {
                    length[g] = through;
                    queue.push({through, g});
                }
            }
        }
    }
}

//! ∫ min(μ, cap) dA / area.
double vertexFactor(const std::vector<double>& mu, const std::vector<double>& area, double totalArea, double cap)
{
    double sum = 0;
    for (size_t f = 0; f < mu.size(); ++f) sum += area[f] * std::min(mu[f], cap);
    return sum / totalArea;
}

//! Per face, whether its centroid is within focus.radius of a focus point; empty = all faces.
std::vector<char> facesInFocus(const TriMesh& mesh, const ThinPartFocus& focus)
{
    if (focus.points.empty()) return {};
    PointCloud cloud{&focus.points};
    PointTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    tree.buildIndex();
    std::vector<char> in(mesh.faces.size(), 0);
#pragma omp parallel for schedule(static)
    for (int f = 0; f < mesh.faceCount(); ++f) {
        const Vec3 c = faceCentroid(mesh, f);
        uint32_t index = 0;
        double squared = 0;
        nanoflann::KNNResultSet<double, uint32_t> nearest(1);
        nearest.init(&index, &squared);
        tree.findNeighbors(nearest, c.data(), KnnSearchParams());
        in[f] = squared <= focus.radius * focus.radius;
    }
    return in;
}

//! Per vertex of `mesh`, the width of the strip of surface between its border and another
//! border nearer than `largest`: the distance to the nearest border vertex of another loop, or
//! of the same loop but more than kSlotArcRatio times as far along it as across (a slot); +inf
//! elsewhere. A strip narrower than an edge length between two holes is a thin part the medial
//! balls do not see: the surface there is a sheet, not a solid.
std::vector<double> borderStripWidths(const TriMesh& mesh, double largest)
{
    std::vector<double> width(mesh.vertices.size(), kInfinity);
    const std::vector<std::vector<int>> loops = borderLoops(mesh);
    std::vector<Vec3> points;
    std::vector<int> vertexOf, loopOf;
    std::vector<double> arcOf, loopLength;
    for (int l = 0; l < static_cast<int>(loops.size()); ++l) {
        double arc = 0;
        const std::vector<int>& loop = loops[l];
        for (size_t i = 0; i < loop.size(); ++i) {
            points.push_back(mesh.vertices[loop[i]]);
            vertexOf.push_back(loop[i]);
            loopOf.push_back(l);
            arcOf.push_back(arc);
            arc += (mesh.vertices[loop[(i + 1) % loop.size()]] - mesh.vertices[loop[i]]).norm();
        }
        loopLength.push_back(arc);
    }
    if (points.empty()) return width;
    PointCloud cloud{&points};
    PointTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    tree.buildIndex();
    std::vector<std::pair<double, uint32_t>> found;
    for (size_t i = 0; i < points.size(); ++i) {
        found.clear();
        WithinRadius within(largest * largest, found);
        tree.findNeighbors(within, points[i].data(), KnnSearchParams());
        for (const auto& [squared, j] : found) {
            const double across = std::sqrt(squared);
            if (!(across > 0)) continue;  // the vertex itself, or a pinch
            if (loopOf[j] == loopOf[i]) {
                const double along = std::abs(arcOf[j] - arcOf[i]);
                if (std::min(along, loopLength[loopOf[i]] - along) <= kSlotArcRatio * across) continue;
            }
            width[vertexOf[i]] = std::min(width[vertexOf[i]], across);
        }
    }
    return width;
}

}  // namespace

double localThickness(const ClosestPointTree& tree, const Vec3& p, const Vec3& normal, int face, int side, double largest,
                      double minObjectAngleDegrees)
{
    const Vec3 direction = double(side) * normal;  // from p towards the ball's centre
    // The angle, seen from the centre of the ball of radius r tangent at p, between p and q.
    auto objectCosine = [&](double r, const Vec3& q) {
        const Vec3 centre = p + r * direction;
        const Vec3 toP = p - centre, toQ = q - centre;
        const double norms = toP.norm() * toQ.norm();
        return norms > 0 ? toP.dot(toQ) / norms : 1.0;
    };
    const double opposite = std::cos(minObjectAngleDegrees * kPi / 180);
    double radius = 0.5 * largest;
    Vec3 touch;  // where the ball touches the surface away from p
    bool shrunk = false;
    for (int step = 0; step < kMaxBallSteps; ++step) {
        const Vec3 centre = p + radius * direction;
        const Vec3 q = tree.closest(centre, face).point;
        if ((centre - q).norm() >= radius * (1 - kEmptyBallTolerance)) break;  // empty: the medial ball
        // The ball through p, tangent there, with q on its sphere: |p + r d − q| = r.
        const Vec3 w = q - p;
        const double along = w.dot(direction);
        if (!(along > 0)) break;  // rounding: q is not in front of p
        const double next = w.squaredNorm() / (2 * along);
        if (!(next < radius)) break;
        // Only contacts roughly opposite p shrink the ball: one nearer p (a facet of the same
        // curved wall, a crease) would shrink it to the facets' size; the ball stays as it is.
        if (objectCosine(next, q) > opposite) break;
        radius = next;
        touch = q;
        shrunk = true;
    }
    return shrunk ? 2 * radius : kInfinity;
}

ThinPartDensity thinPartDensity(const TriMesh& surface, const ClosestPointTree& tree, double edgeLength,
                                const ThinPartParams& params, const ThinPartFocus& focus)
{
    ThinPartDensity out;
    const int faceCount = surface.faceCount();
    // A part is thin for the output when it is thinner than this; its faces want edges of
    // edgePerThickness × their thickness.
    const double thinUnder = edgeLength / params.edgePerThickness;
    std::vector<double> thickness(faceCount, kInfinity);
    const std::vector<char> inFocus = facesInFocus(surface, focus);
#pragma omp parallel for schedule(dynamic, 256)
    for (int f = 0; f < faceCount; ++f) {
        if (!inFocus.empty() && !inFocus[f]) continue;
        const Vec3 n = faceNormal(surface, f);
        const double length = n.norm();
        if (!(length > 0) || !std::isfinite(length)) continue;  // no plane: its neighbours decide
        const Vec3 unit = n / length;
        double thinnest = kInfinity;
        for (const Vec3& p : probePoints(surface, f))
            for (int side : {-1, 1})
                thinnest = std::min(thinnest, localThickness(tree, p, unit, f, side, thinUnder, params.minObjectAngleDegrees));
        thickness[f] = thinnest;
    }
    // Strips of surface between borders (holes closer than an edge length): the faces at their
    // border vertices.
    const std::vector<double> strip = borderStripWidths(surface, thinUnder);
    std::vector<double> length(faceCount, kInfinity);
    for (int f = 0; f < faceCount; ++f) {
        double width = kInfinity;
        if (inFocus.empty() || inFocus[f])
            for (int v : surface.faces[f]) width = std::min(width, strip[v]);
        if (thickness[f] < thinUnder || width < thinUnder) {
            length[f] = std::min(params.edgePerThickness * thickness[f], params.edgePerStripWidth * width);
            ++out.thinFaces;
            const double thinnest = std::min(thickness[f], width);
            out.thinnest = out.thinFaces == 1 ? thinnest : std::min(out.thinnest, thinnest);
        }
    }
    if (out.thinFaces == 0) return out;
    gradeEdgeLengths(surface, params.gradation, length);
    std::vector<double> area(faceCount);
    double totalArea = 0;
    out.mu.assign(faceCount, 1.0);
    for (int f = 0; f < faceCount; ++f) {
        area[f] = faceArea(surface, f);
        totalArea += area[f];
        if (length[f] < edgeLength) out.mu[f] = std::pow(edgeLength / std::max(length[f], edgeLength / params.maxEdgeRatio), 2);
    }
    if (!(totalArea > 0)) return ThinPartDensity{};
    out.vertexFactor = vertexFactor(out.mu, area, totalArea, kInfinity);
    if (out.vertexFactor > params.maxVertexFactor) {
        // The cap on μ that spends exactly the allowed vertices (bisection: the factor grows with it).
        double low = 1, high = *std::max_element(out.mu.begin(), out.mu.end());
        for (int i = 0; i < 60; ++i) {
            const double mid = 0.5 * (low + high);
            (vertexFactor(out.mu, area, totalArea, mid) > params.maxVertexFactor ? high : low) = mid;
        }
        for (double& m : out.mu) m = std::min(m, low);
        out.vertexFactor = vertexFactor(out.mu, area, totalArea, kInfinity);
        out.capped = true;
    }
    return out;
}

}  // namespace fieldcvt
