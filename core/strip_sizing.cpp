#include "strip_sizing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
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
    struct HalfEdge {
        int lo, hi, face;
    };
    std::vector<HalfEdge> halves;
    for (int f = 0; f < surface.faceCount(); ++f) {
        if (!selected[f]) continue;
        const Face& t = surface.faces[f];
        for (int k = 0; k < 3; ++k) {
            const int a = t[k], b = t[(k + 1) % 3];
            halves.push_back({std::min(a, b), std::max(a, b), f});
        }
    }
    std::sort(halves.begin(), halves.end(),
              [](const HalfEdge& x, const HalfEdge& y) { return std::tie(x.lo, x.hi, x.face) < std::tie(y.lo, y.hi, y.face); });
    std::vector<Crease> creases;
    for (std::size_t i = 0; i < halves.size();) {
        std::size_t j = i;
        while (j < halves.size() && halves[j].lo == halves[i].lo && halves[j].hi == halves[i].hi) ++j;
        if (j - i == 2) {
            const Vec3 n1 = faceNormal(surface, halves[i].face), n2 = faceNormal(surface, halves[i + 1].face);
            const double norms = n1.norm() * n2.norm();
            const Vec3 &a = surface.vertices[halves[i].lo], &b = surface.vertices[halves[i].hi];
            const double length = (b - a).norm();
            if (norms > 0 && length > 0 && n1.dot(n2) < creaseCos * norms)
                creases.push_back({halves[i].lo, halves[i].hi, a, b, (b - a) / length});
        }
        i = j;
    }
    return creases;
}

Vec3 closestOnSegment(const Vec3& p, const Vec3& a, const Vec3& b)
{
    const Vec3 d = b - a;
    const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    return a + t * d;
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
            const Vec3 across = closestOnSegment(p, other.a, other.b) - p;
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
