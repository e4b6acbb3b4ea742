#pragma once
// The undirected edges of a triangle mesh and the faces around each: border edges (one face),
// interior edges (two), non-manifold edges (more), the two faces of an interior edge, and per
// face its three edges. One table for every stage that needs them (topology and valence
// metrics, the field's constraints and singularities, input checks, the RDT's manifold filter,
// border and feature lines).
//
// Half-edge h = 3 f + k is face f's side from faces[f][k] to faces[f][(k + 1) % 3].
// The table is built by a counting sort on the smaller vertex and a sort of each (short) bucket:
// O(faces + vertices), a handful of flat arrays, and the same numbering on every run and thread
// count.
#include "mesh.h"

#include <array>
#include <vector>

namespace fieldcvt {

struct EdgeTable {
    //! Per edge, its (smaller, larger) vertex index. Edges are numbered in increasing
    //! lexicographic order of these pairs, so `ends` is sorted and has no duplicates.
    std::vector<std::array<int, 2>> ends;
    //! CSR offsets into `halfEdges`, size edgeCount() + 1.
    std::vector<int> first;
    //! The half-edges of every edge, grouped by edge, increasing within an edge (so in face
    //! order: a face that runs along an edge twice, like {a, b, a}, appears there twice).
    std::vector<int> halfEdges;
    //! Per half-edge 3 f + k, its edge; -1 for the half-edges of skipped faces.
    std::vector<int> halfEdgeEdge;

    int edgeCount() const { return static_cast<int>(ends.size()); }
    //! Number of half-edges on edge e: its faces, a face counted once per side it has on e.
    int faceCount(int e) const { return first[e + 1] - first[e]; }
    //! The i-th half-edge of edge e (0 <= i < faceCount(e)), in increasing order.
    int halfEdge(int e, int i) const { return halfEdges[first[e] + i]; }
    //! The face of the i-th half-edge of edge e: face(e, 0) and face(e, 1) are the two faces of
    //! an interior edge, smaller index first.
    int face(int e, int i) const { return halfEdge(e, i) / 3; }
    bool isBorder(int e) const { return faceCount(e) == 1; }
    bool isNonManifold(int e) const { return faceCount(e) > 2; }
    //! The edge of face f from corner k to corner k + 1 (-1 if f was skipped).
    int edgeOf(int f, int k) const { return halfEdgeEdge[3 * f + k]; }
    //! Edge index of {a, b} (either order), -1 if no face has it (binary search).
    int find(int a, int b) const;
    //! Whether the first two half-edges of e run the same way (an orientation conflict between
    //! its first two faces); false for an edge with fewer than two. `faces` as given to the build.
    bool firstTwoSameDirection(const std::vector<Face>& faces, int e) const;
    //! The first (smallest) half-edge of e that starts at vertex `origin`, -1 if none: for a
    //! half-edge from a to b, firstHalfEdgeFrom(faces, e, b) is its opposite (b, a) in a
    //! neighbouring face, the first one if e has several. `faces` as given to the build.
    int firstHalfEdgeFrom(const std::vector<Face>& faces, int e, int origin) const;
};

//! Origin vertex of half-edge h (= faces[h / 3][h % 3]).
inline int halfEdgeOrigin(const std::vector<Face>& faces, int h) { return faces[h / 3][h % 3]; }

//! Faces that repeat a vertex index ({a, b, a}) have no proper edges: kept, they add an edge
//! {a, a} and two sides on {a, b}; skipped, they get -1 in halfEdgeEdge and add nothing.
enum class RepeatedVertexFaces { Keep, Skip };

//! The edge table of `faces`, whose indices must lie in [0, vertexCount)
//! (throws InvalidInputError otherwise).
EdgeTable buildEdgeTable(const std::vector<Face>& faces, int vertexCount,
                         RepeatedVertexFaces repeated = RepeatedVertexFaces::Keep);

inline EdgeTable buildEdgeTable(const TriMesh& mesh, RepeatedVertexFaces repeated = RepeatedVertexFaces::Keep)
{
    return buildEdgeTable(mesh.faces, mesh.vertexCount(), repeated);
}

//! Per face, its connected component through shared edges (non-manifold ones included),
//! numbered 0..count-1 in order of first face; `count` receives the number of components.
//! Faces skipped by the table (a repeated corner) are components of their own.
std::vector<int> faceComponents(const EdgeTable& edges, int faceCount, int& count);

}  // namespace fieldcvt
