#pragma once
// Exact restricted Voronoi diagram (RVD) of seeds on a triangle surface (paper §3.1, after
// Yan, Lévy et al. 2009 and Geogram's RVD): every input triangle is clipped by the bisector
// planes of the seeds whose cells meet it. Per cell it integrates mass, first moment and the
// CVT energy (eq. 1); optionally the length of every shared RVD edge (the weights w_ij of §3.5)
// and the restricted Delaunay triangles (RVD vertices equidistant from three seeds).
#include "mesh.h"

#include <array>
#include <memory>
#include <vector>

namespace fieldcvt {

struct RvdOptions {
    bool edges = false;  //!< fill RvdResult::edges
    //! Fill RvdResult::triangles and the connected pieces of the cells (pieceSeed, piecePoint,
    //! pieceTriangles).
    bool triangles = false;
    bool boundary = false;  //!< fill RvdResult::boundaryLength / boundaryMoment
    //! Only the faces with a border edge (the cells' pieces elsewhere are skipped): the border
    //! figures are complete, mass / moment / energy only cover those faces.
    bool borderFacesOnly = false;
    //! Side-aware cells: per seed a unit normal (the surface's at the seed), or null (plain
    //! cells). A seed then owns no part of a face whose unit normal n has n · n_seed <=
    //! `minSideCos` (the far side of a plate or wall thinner than the cells); each face goes to
    //! the nearest seed that may own it (to all, where none near it may). The cells are then
    //! not continuous across an edge between faces whose owners differ (a plate's crease):
    //! there the two sides' sequences of cells are zipped into seam triangles (RvdResult::
    //! triangles), which close the RDT.
    const std::vector<Vec3>* seedNormals = nullptr;
    //! -0.5: more than 120° apart (a plate's two sides, 180°, are; a right-angled crease,
    //! 90°, is not).
    double minSideCos = -0.5;
};

//! An RVD edge shared by the cells of seeds i < j, and its total length on the surface.
struct RvdEdge {
    int i = 0, j = 0;
    double length = 0;
};

//! With a density ρ (piecewise constant per input triangle, RestrictedVoronoiDiagram's
//! constructor) every polygon's mass, moment and energy are multiplied by its triangle's ρ, so
//! c_i is the ρ-weighted centroid and ∂E/∂x_i = 2 m_i (x_i − c_i) still holds. Edge and border
//! lengths stay geometric.
struct RvdResult {
    std::vector<double> mass;    //!< m_i = ∫ ρ dσ over the restricted cell (its area when ρ = 1)
    std::vector<Vec3> moment;    //!< ∫ ρ x dσ over the cell; centroid c_i = moment_i / m_i
    std::vector<double> energy;  //!< ∫ ρ ||x - x_i||² dσ over the cell (eq. 1)
    //! Length and first moment ∫ x ds of the input's border inside each cell (the 1D restricted
    //! Voronoi diagram of the boundary curves; empty unless RvdOptions::boundary).
    std::vector<double> boundaryLength;
    std::vector<Vec3> boundaryMoment;
    std::vector<RvdEdge> edges;  //!< sorted by (i, j), one entry per neighbouring pair
    //! One triangle (i, j, k) per RVD vertex where three cells meet, oriented like the input
    //! surface, listed once (sorted, duplicates removed).
    std::vector<std::array<int, 3>> triangles;
    //! Connected pieces of the restricted cells on the surface (RvdOptions::triangles). A cell
    //! is convex in space but its restriction to the surface can fall apart (thin parts,
    //! near-touching sheets: Geogram's multi-nerve case); its polygons in input triangles that
    //! share an edge are one piece. Pieces are sorted by seed, then by where they first occur
    //! (Morton order of the input triangles), so the numbering does not depend on threads.
    std::vector<int> pieceSeed;
    //! Per piece, the closest point of its seed on the piece.
    std::vector<Vec3> piecePoint;
    //! The restricted Delaunay triangles on pieces (indices into pieceSeed): every piece meeting
    //! an RVD vertex is a corner. Same orientation and order rules as `triangles`, which is
    //! this list with pieces replaced by their seeds.
    std::vector<std::array<int, 3>> pieceTriangles;
    //! Number of (triangle, cell) polygons clipped; a cost figure for benchmarks.
    long long clippedPolygons = 0;
    //! Seeds whose nearest-neighbour list came from the candidate lists of an earlier call (no
    //! k-d tree search); a cost figure for benchmarks and tests.
    int listsFromCandidates = 0;

    double totalEnergy() const;
};

//! Computes the RVD of varying seed sets on one fixed surface. The surface must outlive it.
//! compute() is parallel over triangles (OpenMP); its result does not depend on the thread
//! count (fixed chunks, reduction in chunk order).
class RestrictedVoronoiDiagram {
public:
    //! `faceDensity`: ρ per face of `surface` (finite, > 0), or empty for ρ = 1 (the uniform
    //! case, computed exactly as without a density).
    explicit RestrictedVoronoiDiagram(const TriMesh& surface, std::vector<double> faceDensity = {});
    ~RestrictedVoronoiDiagram();
    RestrictedVoronoiDiagram(const RestrictedVoronoiDiagram&) = delete;
    RestrictedVoronoiDiagram& operator=(const RestrictedVoronoiDiagram&) = delete;

    //! Computes the diagram of `seeds` (at least one). Coincident seeds are allowed: the one
    //! with the larger index gets an empty cell.
    void compute(const std::vector<Vec3>& seeds, const RvdOptions& options, RvdResult& result);

    //! Frees the per-chunk outputs and per-thread work space that compute() keeps between calls
    //! (their capacity is the last diagram's, cell pieces and links included: docs/tuning.md,
    //! "Memory of the diagram"). A later compute() allocates them again.
    void releaseWorkspace();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace fieldcvt
