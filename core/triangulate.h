#pragma once
// Polygons into triangles without overlap or zero-area ones, and zero-area triangles that others
// made (MeshLab's importers fan-triangulate polygons) flipped away. A fan over a polygon with a
// straight corner (a cube face with a vertex on its edge) makes a triangle of zero area; the
// input check would remove it and tear the surface open along the polygon's edge. A fan over a
// concave polygon folds over itself.
#include "mesh.h"

#include <vector>

namespace fieldcvt {

//! Polygons with more corners than this get a constrained Delaunay triangulation (O(n log n));
//! smaller ones ear clipping, whose O(n^2) is cheaper for the quads and small polygons of most files.
constexpr int kMaxEarClippingCorners = 64;

//! What triangulatePolygon found the polygon to be, in the plane of its Newell normal.
enum class PolygonShape {
    Simple,     //!< no two edges meet but at their shared corner: triangulated exactly, without overlap
    NotSimple,  //!< edges cross or touch, corners repeat, or no plane (all corners on a line):
                //!< triangulated as well as possible (the caller says so)
};

//! Appends the polygon's corners.size() − 2 triangles to `faces`, oriented like the polygon.
//! Corners are indices into `points`. In the plane of the Newell normal, with exact orientation
//! tests: ear clipping (scanned from the second corner, so a convex polygon without straight
//! corners gets the fan from its first corner) taking only corners that turn and whose triangle
//! holds no other corner, or above kMaxEarClippingCorners a constrained Delaunay triangulation
//! (CGAL); either way no zero-area triangle where the polygon allows it. A polygon that is not
//! simple gets ear clipping's best effort (its most convex corners, then a fan).
PolygonShape triangulatePolygon(const std::vector<Vec3>& points, const std::vector<int>& corners, std::vector<Face>& faces);

//! Flips away zero-area triangles whose middle corner lies inside their longest edge: each and
//! the neighbour across that edge become two triangles through the middle corner (the surface
//! and its orientation are unchanged). A triangle is skipped when that edge is not shared by
//! exactly one other face, the neighbour has zero area too, or the new edge already exists.
//! Returns the number of triangles flipped away; the vertices are not changed.
int flipZeroAreaTriangles(TriMesh& mesh);

}  // namespace fieldcvt
