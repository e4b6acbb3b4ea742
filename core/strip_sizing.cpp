#include "strip_sizing.h"

#include "boundary.h"
#include "mesh_edges.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace fieldcvt {

namespace {

//! A crease edge of the surface: its ends and unit direction.
struct Crease {
    int u, v;
    Vec3 a, b, direction;
};

//! The edges of two selected faces turned more than acos(creaseCos) from each other.
std::vector<Crease> findCreases(const TriMesh& surface, const std::vector<char>& selected, double creaseCos)
{
    const EdgeTable edges = buildEdgeTable(surface);
    std::vector<Crease> creases;
    for (int e = 0; e < edges.edgeCount(); ++e) {
        if (edges.faceCount(e) != 2 || !selected[edges.face(e, 0)] || !selected[edges.face(e, 1)]) continue;
        const Vec3 n1 = faceNormal(surface, edges.face(e, 0)), n2 = faceNormal(surface, edges.face(e, 1));
        const auto [u, v] = edges.ends[e];
        const Vec3 &a = surface.vertices[u], &b = surface.vertices[v];
        const double norms = n1.norm() * n2.norm(), length = (b - a).norm();
        if (norms > 0 && length > 0 && n1.dot(n2) < creaseCos * norms) creases.push_back({u, v, a, b, (b - a) / length});
    }
    return creases;
}

}  // namespace

StripSizing::StripSizing(const TriMesh& surface, const std::vector<char>& selectedFaces, double length,
                         const StripSizingParams& params)
    : length_(length), gradation_(params.gradation), smallest_(length)
{
    const std::vector<Crease> creases = findCreases(surface, selectedFaces, params.creaseCos);
    if (creases.size() < 2) return;
    // Points along every crease, a quarter of the length apart at most, each knowing its crease.
    std::vector<Vec3> samples;
    std::vector<int> ofSample;
    const double spacing = 0.25 * length;
    for (int c = 0; c < static_cast<int>(creases.size()); ++c) {
        const Crease& e = creases[c];
        const int pieces = static_cast<int>(std::min(1e6, std::ceil((e.b - e.a).norm() / spacing)));
        for (int i = 0; i < std::max(1, pieces); ++i) {
            samples.push_back(e.a + (i + 0.5) / std::max(1, pieces) * (e.b - e.a));
            ofSample.push_back(c);
        }
    }
    PointCloud sampleCloud{&samples};
    PointTree sampleTree(3, sampleCloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    sampleTree.buildIndex();
    // Each sample's width: the distance to the nearest crease that runs beside it (parallel,
    // straight across, no end shared) within the length. Samples in index order: deterministic.
    std::vector<std::pair<double, uint32_t>> found;
    std::vector<int> seen;
    const double floor = params.floorShare * length;
    for (std::size_t s = 0; s < samples.size(); ++s) {
        const Vec3& p = samples[s];
        const Crease& own = creases[ofSample[s]];
        found.clear();
        WithinRadius within(length * length, found);
        sampleTree.findNeighbors(within, p.data(), KnnSearchParams());
        seen.clear();
        double width = length;
        for (const auto& hit : found) seen.push_back(ofSample[hit.second]);
        std::sort(seen.begin(), seen.end());
        seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
        for (int c : seen) {
            const Crease& other = creases[c];
            if (other.u == own.u || other.u == own.v || other.v == own.u || other.v == own.v) continue;
            if (std::abs(other.direction.dot(own.direction)) < params.parallelCos) continue;
            const Vec3 across = closestPointOnSegment(p, {other.a, other.b}) - p;
            const double distance = across.norm();
            if (!(distance > 0) || std::abs(across.dot(own.direction)) > params.acrossCos * distance) continue;
            width = std::min(width, distance);
        }
        if (width >= length) continue;
        points_.push_back(p);
        sizes_.push_back(std::max(floor, params.widthShare * width));
        smallest_ = std::min(smallest_, sizes_.back());
    }
    if (points_.empty()) return;
    cloud_.points = &points_;
    tree_ = std::make_unique<PointTree>(3, cloud_, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    tree_->buildIndex();
}

double StripSizing::at(const Vec3& p) const
{
    if (!tree_) return length_;
    // Only strips within this distance can make the length shorter than the run's.
    const double reach = (length_ - smallest_) / gradation_;
    thread_local std::vector<std::pair<double, uint32_t>> found;  // no allocation per call
    found.clear();
    WithinRadius within(reach * reach, found);
    tree_->findNeighbors(within, p.data(), KnnSearchParams());
    double size = length_;
    for (const auto& hit : found) size = std::min(size, sizes_[hit.second] + gradation_ * std::sqrt(hit.first));
    return size;
}

}  // namespace fieldcvt
