#pragma once
// A nanoflann kd-tree over a vector of points (the adaptor nanoflann asks for), shared by the
// stages that look up nearby points: the RVD (each seed's nearest seeds), feature lines (seeds
// near a curve) and the lattice start (coinciding lattice points).
#include "mesh.h"

#include <nanoflann.hpp>

#include <cstdint>
#include <utility>
#include <vector>

namespace fieldcvt {

struct PointCloud {
    const std::vector<Vec3>* points = nullptr;
    size_t kdtree_get_point_count() const { return points->size(); }
    double kdtree_get_pt(size_t i, size_t dim) const { return (*points)[i][static_cast<int>(dim)]; }
    template <class BBox>
    bool kdtree_get_bbox(BBox&) const
    {
        return false;
    }
};
using PointTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>, PointCloud, 3, uint32_t>;

// nanoflann 1.5 renamed SearchParams (Debian 12 has 1.4.2, Debian 13 1.7.1).
#if defined(NANOFLANN_VERSION) && NANOFLANN_VERSION >= 0x150
using KnnSearchParams = nanoflann::SearchParameters;
#else
using KnnSearchParams = nanoflann::SearchParams;
#endif

//! A nanoflann result set that keeps the points strictly nearer than a squared radius, in the
//! order the search meets them (PointTree::findNeighbors).
class WithinRadius {
public:
    using DistanceType = double;  // nanoflann >= 1.5 reads these
    using IndexType = uint32_t;
    WithinRadius(double radius2, std::vector<std::pair<double, uint32_t>>& found) : radius2_(radius2), found_(found) {}
    size_t size() const { return found_.size(); }
    bool full() const { return true; }
    double worstDist() const { return radius2_; }
    bool addPoint(double dist, uint32_t index)
    {
        if (dist < radius2_) found_.emplace_back(dist, index);
        return true;
    }
    void sort() {}  // nanoflann >= 1.5 asks; the caller orders them

private:
    double radius2_;
    std::vector<std::pair<double, uint32_t>>& found_;
};

}  // namespace fieldcvt
