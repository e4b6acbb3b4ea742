#pragma once
// A sizing field for the local remeshing (local_remesh.h): shorter edges on narrow strips between
// two sharp edges of the surface, graded back to the run's length around them. A CAD part's rim
// 3 mm wide against 20 mm edges, a step, the wall of a small hole: at the run's length the only
// triangles that span such a strip and keep its two creases are slivers (issue 52, item 4). Each
// strip gets edges about as long as it is wide, and the length grows by `gradation` per unit of
// distance from it, so the triangles around stay well shaped and the flat faces stay coarse.
#include "mesh.h"
#include "point_tree.h"

#include <memory>
#include <vector>

namespace fieldcvt {

struct StripSizingParams {
    //! An edge between two faces turned more than this from each other (cosine, 60°) is a crease.
    double creaseCos = 0.5;
    //! Two creases are the sides of a strip where they run within this (cosine, 45°) of parallel...
    double parallelCos = 0.7071;
    //! ... and the shortest way across is within this (cosine, 60°) of square to the crease.
    double acrossCos = 0.5;
    //! The length on a strip: this times its width...
    double widthShare = 1.5;
    //! ... but at least this share of the run's length (a sliver chamfer is not resolved).
    double floorShare = 0.125;
    //! The length grows by this per unit of distance from a strip (MMG's -hgrad 1.3 is about 0.3).
    double gradation = 0.5;
};

//! The target edge length at any point: the run's length `length`, or less near a strip narrower
//! than it (between two creases of the selected faces of `surface`).
class StripSizing {
public:
    StripSizing(const TriMesh& surface, const std::vector<char>& selectedFaces, double length,
                const StripSizingParams& params = {});
    //! min(length, min over strips s of (size_s + gradation |p - s|)). Thread-safe.
    double at(const Vec3& p) const;
    //! How many points of strips narrower than the length were found (0: the field is the length).
    int sources() const { return static_cast<int>(points_.size()); }
    //! The smallest size on a strip (the length if none).
    double smallest() const { return smallest_; }

private:
    double length_, gradation_, smallest_;
    std::vector<Vec3> points_;
    std::vector<double> sizes_;
    PointCloud cloud_;
    std::unique_ptr<PointTree> tree_;
};

}  // namespace fieldcvt
