#pragma once
// The output mesh: the restricted Delaunay triangulation (RDT), dual of the RVD (§3.1).
#include "closest_point.h"
#include "mesh.h"
#include "rvd.h"

#include <array>
#include <string>
#include <vector>

namespace fieldcvt {

struct RdtResult {
    TriMesh mesh;
    std::vector<int> seedOfVertex;  //!< sample index of each output vertex
    //! Per output vertex, the input face its closest point lies on (-1: placed on a piece of its
    //! cell instead): a hint for later closest-point queries at the vertex.
    std::vector<int> faceOfVertex;
    int droppedSeeds = 0;     //!< samples in no triangle (empty or isolated cells)
    int removedFaces = 0;     //!< faces removed to keep the output edge-manifold
    int splitVertices = 0;    //!< extra vertices made by splitting non-manifold vertices
    int multiPieceSeeds = 0;  //!< samples whose restricted cell is in several pieces (one vertex each)
    //! Lens pieces dropped: a piece of a cell across the border of two other cells only (a fold
    //! of the input or a thin part crossing their Voronoi edge twice), whose two faces are the same
    //! triangle with both orientations; kept, they would tear the edge of the two cells open.
    int lensPieces = 0;
    //! Slit pieces dropped: a piece of a cell, not the one nearest to its sample, in one triangle
    //! only, a sliver (a cell reaching across a gap of the border narrower than a cell); kept, its
    //! vertex would lie on the border in line with the triangle's two others.
    int slitPieces = 0;
    int debrisPieces = 0;  //!< pieces dropped by dropDebris
    std::vector<std::string> warnings;
};

//! Drops debris: connected pieces of the output (through edges) of at most `maxFaces` faces
//! whose every vertex lies within `reach` of the rest of the output. Cells cut by a part
//! narrower than the edge length leave such crumbs beside the part's own mesh: a part in
//! pieces for the user, and nothing the rest does not cover within `reach`.
//! An isolated small piece (a small part of the input of its own) is kept. Vertices no face
//! uses any more are removed with their seedOfVertex and faceOfVertex. Returns the pieces dropped
//! (also added to debrisPieces).
int dropDebris(RdtResult& rdt, int maxFaces, double reach);

//! Builds the output mesh from the RVD's triangles: drops lens pieces (RdtResult::lensPieces),
//! removes faces that would make an edge non-manifold (more than two faces, or two faces with
//! the same orientation), drops samples
//! that no face uses and places each vertex at its sample's closest point on the input surface
//! (which keeps the approximation error at CVT level).
//! Gives every fan of faces around a vertex its own vertex (same position and sample), so the
//! mesh is vertex-manifold; `seedOfVertex` (and `alongside`, if given: any other per-vertex
//! values) grows with the copies. Returns the copies made.
int splitNonManifoldVertices(TriMesh& mesh, std::vector<int>& seedOfVertex, std::vector<int>* alongside = nullptr);

RdtResult extractRdt(const std::vector<Vec3>& seeds, const std::vector<std::array<int, 3>>& triangles,
                     const ClosestPointTree& surface);

//! The same from the RVD's triangles on cell pieces (RvdOptions::triangles): every connected
//! piece of a restricted cell is its own vertex (Geogram's multi-nerve case), so a cell that
//! falls apart on thin parts or near-touching sheets does not glue them together. A sample with
//! one piece is placed at its closest point on the surface; a sample with several, at its
//! closest point on each piece.
//! `seedFaceHints` (optional, one per seed or empty): a face near each seed's closest point,
//! which only speeds the queries up (ClosestPointTree::closest's hint: the same answers).
RdtResult extractRdt(const std::vector<Vec3>& seeds, const RvdResult& rvd, const ClosestPointTree& surface,
                     const std::vector<int>& seedFaceHints = {});

}  // namespace fieldcvt
