#pragma once
// Polygons into triangles without zero-area ones, and zero-area triangles that others made
// (MeshLab's importers fan-triangulate polygons) flipped away. A fan over a polygon with a
// straight corner (a cube face with a vertex on its edge) makes a triangle of zero area; the
// input check would remove it and tear the surface open along the polygon's edge.
#include "mesh.h"

#include <vector>

namespace fieldcvt {

//! Polygons with more corners than this are fan-triangulated (ear clipping is quadratic).
constexpr int kMaxEarClippingCorners = 256;

//! Appends the polygon's corners.size() − 2 triangles to `faces`, oriented like the polygon:
//! ear clipping in the plane of its Newell normal (scanned from the second corner, so a convex
//! polygon without straight corners gets the fan from its first corner), taking only corners
//! that turn (not straight) and whose triangle holds no other corner, so no triangle has zero
//! area where the polygon allows it. Corners are indices into `points`; a polygon with no
//! such ear left (flat or self-intersecting) gets its most convex corners, then a fan.
void triangulatePolygon(const std::vector<Vec3>& points, const std::vector<int>& corners, std::vector<Face>& faces);

//! Flips away zero-area triangles whose middle corner lies inside their longest edge: each and
//! the neighbour across that edge become two triangles through the middle corner (the surface
//! and its orientation are unchanged). A triangle is skipped when that edge is not shared by
//! exactly one other face, the neighbour has zero area too, or the new edge already exists.
//! Returns the number of triangles flipped away; the vertices are not changed.
int flipZeroAreaTriangles(TriMesh& mesh);

}  // namespace fieldcvt
