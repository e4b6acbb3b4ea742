#pragma once
// Points in Morton (Z-order) along their bounding box: consecutive entries are close in space.
// The RVD orders the surface's vertices and faces by it (cache-friendly passes), the energy its
// seeds, the bake its atlas cells, the simplification its blocks.
#include "mesh.h"

#include <vector>

namespace fieldcvt {

//! Indices of `points` sorted along a Morton curve over their bounding box (21 bits a
//! coordinate; ties by index).
std::vector<int> mortonIndexOrder(const std::vector<Vec3>& points);

}  // namespace fieldcvt
