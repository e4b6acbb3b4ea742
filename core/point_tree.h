#pragma once
// A nanoflann kd-tree over a vector of points (the adaptor nanoflann asks for), shared by the
// stages that look up nearby points: the RVD (each seed's nearest seeds), feature lines (seeds
// near a curve) and the lattice start (coinciding lattice points).
#include "mesh.h"

#include <nanoflann.hpp>

#include <cstdint>
#include <vector>

namespace fieldcvt {

struct PointCloud {
    const std::vector<Vec3>* points = nullptr;
    size_t kdtree_get_point_count() const { return points->size(); }
    double kdtree_get_pt(size_t i, size_t dim) const { return (*points)[i][static_cast<int>(dim)]; }
    template <class BBox>
    bool kdtree_get_bbox(BBox&) const { return false; }
};
using PointTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>, PointCloud, 3, uint32_t>;

}  // namespace fieldcvt
