#pragma once
// The input's open boundary as a set of segments, and the closest point on it. Samples of the
// cells that meet the border are kept on it (feature_lines.h: relaxConstrainedSamples). And a
// mesh's border as half-edges and directed loops (hole closing, thin parts, a region's seam).
#include "mesh.h"

#include <utility>
#include <vector>

namespace fieldcvt {

using Segment = std::pair<Vec3, Vec3>;

//! The edges of `mesh` that have exactly one face, as segments.
std::vector<Segment> boundarySegments(const TriMesh& mesh);

//! Closest point to p on one segment; `squaredDistance` receives its squared distance to p.
Vec3 closestPointOnSegment(const Vec3& p, const Segment& segment, double* squaredDistance = nullptr);

//! Closest point to p on a set of segments (p itself if the set is empty).
Vec3 closestPointOnSegments(const Vec3& p, const std::vector<Segment>& segments);

//! The border half-edges a -> b of `faces`, in half-edge order: no face has b -> a and one face
//! has a -> b.
std::vector<std::pair<int, int>> borderHalfEdges(const std::vector<Face>& faces);

//! The directed border loops of a mesh (edges a -> b of one face each, the mesh on their left),
//! as vertex indices, in a fixed order; a vertex the loops pass twice appears twice.
std::vector<std::vector<int>> borderLoops(const TriMesh& mesh);

}  // namespace fieldcvt
