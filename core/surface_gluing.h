#pragma once
// How the faces of a triangle soup join into a surface, shared by the strict input check
// (mesh_check.h: refuses what is not a manifold, orientable surface) and the repair (repair.h:
// cuts and splits until it is one): exact duplicate vertices, the half-edges glued across
// edges, the orientation walk and the split of a vertex into one vertex per fan of faces.
#include "mesh.h"
#include "mesh_edges.h"

#include <functional>
#include <vector>

namespace fieldcvt {

//! Per vertex, the first (lowest-index) referenced vertex at exactly its coordinates (-0 = +0);
//! unreferenced vertices map to themselves. `merged` counts the vertices mapped to another. The
//! referenced points must be finite (found by sorting them).
std::vector<int> exactDuplicateRepresentatives(const std::vector<Vec3>& points, const std::vector<char>& referenced, int& merged);

//! Per half-edge 3 f + k, the half-edge glued to it: the other side of an edge with exactly two
//! (`edges` built from the same faces); -1 on borders and non-manifold edges.
std::vector<int> glueTwoSidedEdges(const EdgeTable& edges, int faceCount);

//! The result of orientByWalk.
struct Orientation {
    std::vector<int> component;  //!< per face, its connected component (through glued half-edges)
    std::vector<char> flip;      //!< per face, reverse it to agree with its component's first face
    int components = 0;
    int nonOrientable = 0;  //!< components in which the walk met a conflict
};

//! A breadth-first walk per component from its first face (kept as it is) over the glued
//! half-edges, in half-edge order: each face reached gets the orientation of the face it was
//! reached from. A glued pair that disagrees with what the walk already chose closes an
//! orientation-reversing loop (a Moebius-like piece): `conflict(h)` is called with the half-edge
//! of the face being walked (the repair cuts the pair, the strict check throws).
Orientation orientByWalk(const std::vector<Face>& faces, const std::vector<int>& partner,
                         const std::function<void(int h)>& conflict);

//! One vertex per fan of corners glued across edges. cornerVertex[3 f + k] is faces[f][k] for
//! the fan of the vertex's first corner, else a copy: vertexCount + i with copySource[i] its
//! vertex, numbered as the corners are met. Corners are met face by face, corner 0, 1, 2, or
//! 0, 2, 1 for a face with `flipped[f]` (the order of the face once reversed); `flipped` may be
//! empty.
void splitIntoFans(const std::vector<Face>& faces, const std::vector<int>& partner, int vertexCount,
                   const std::vector<char>& flipped, std::vector<int>& cornerVertex, std::vector<int>& copySource);

}  // namespace fieldcvt
