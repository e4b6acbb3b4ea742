#pragma once
// Remeshing a region (issue 34): the selected faces are remeshed, the rest is kept bit for bit.
// Each edge-connected piece of the selection is cut out (extractRegion), remeshed by remesh()
// with a density that grades from its border's edge lengths to the target (regionDensity), its
// new border put exactly on the region's own border vertices (pinBorder), and the pieces put
// back among the kept faces, sharing the border vertices by index (stitchRegions).
#include "mesh.h"
#include "metrics.h"
#include "remesh.h"

#include <string>
#include <vector>

namespace fieldcvt {

struct RegionParams {
    //! How fast the target edge length may change away from the region's border, per unit of
    //! distance: from a border edge of length b the length goes to the target h as
    //! b ± grading · distance (a mesh-size gradation: 0.4 keeps neighbouring cells within ~1.4×).
    double grading = 0.4;
    //! Border edges all within this factor of the target length: a uniform density (the
    //! field-aligned lattice start of a full remesh) instead of the graded one.
    double uniformWithin = 1.25;
    //! Border edges beyond this factor of the target (longer or shorter): a warning naming the
    //! ratio (the triangles along the border may then have angles under 20°).
    double warnRatio = 2.0;
    //! After the border is pinned: the valence optimisation (§4.4, valence.h) with the border
    //! vertices fixed, which also repairs the small angles the pinning left.
    bool seamOptimisation = true;
};

//! The one check of RegionParams (remeshRegion runs it): InvalidInputError naming the field.
void checkRegionParams(const RegionParams& params);

//! Edge-connected pieces of the faces with selected[f] != 0 (faces meeting at a vertex only are
//! separate pieces), each a sorted list of face indices, ordered by their first face.
std::vector<std::vector<int>> regionComponents(const TriMesh& mesh, const std::vector<char>& selected);

//! Selects every face around each vertex where one edge-connected piece of the selection touches
//! itself at a vertex only (its border passes there twice, as a brush selection often does): such
//! a piece is not a disk with holes around that vertex and cannot be remeshed as one. Pieces of
//! the selection that meet at a vertex only stay separate. Returns the faces added.
int closePinches(const TriMesh& mesh, std::vector<char>& selected);

//! One region cut out of its mesh.
struct RegionSubmesh {
    TriMesh mesh;                     //!< the region's faces, vertices renumbered in first-use order
    std::vector<int> originalVertex;  //!< region vertex -> vertex of the whole mesh
    std::vector<int> originalFace;    //!< region face -> face of the whole mesh
    //! Per region vertex: on the region's border (an edge with one region face: next to a kept
    //! face or on the mesh's own boundary). These vertices are kept where they are.
    std::vector<char> border;
};

//! The region made of `faces` (indices into mesh.faces).
RegionSubmesh extractRegion(const TriMesh& mesh, const std::vector<int>& faces);

//! The directed border loops of a region (edges a -> b of one region face each, the region on
//! their left), as region vertex indices; a vertex the loops pass twice appears twice.
std::vector<std::vector<int>> borderLoops(const TriMesh& region);

//! A remeshed region ready to be stitched: its vertices are either border vertices of the whole
//! mesh (original[v] >= 0, at exactly that vertex's coordinates) or new ones (original[v] = -1).
struct RegionPatch {
    TriMesh mesh;
    std::vector<int> original;
};

//! Puts the border of `patch` (a remesh of `region` whose border vertices lie on the region's
//! border segments, e.g. remesh()'s output) onto the region's border vertices: each border
//! vertex of the region is inserted into the patch edge it falls on, then each border vertex of
//! the patch is removed and its hole re-triangulated (the triangulation with the largest smallest
//! angle). Returns the patch on success; on failure (the patch's border does not follow the
//! region's, or a hole cannot be filled) returns false with `failure` saying why, and `patch`
//! is unspecified.
bool pinBorder(const RegionSubmesh& region, TriMesh& patch, std::vector<int>& original, std::string& failure);

//! Edge flips inside the patch (never of its border edges) that raise the smaller of the two
//! faces' smallest angles, in up to `maxPasses` passes: a corner of the region's border under
//! 40° is best one triangle, which the valence optimisation's border valence 4 may have split.
//! Returns the flips made.
int flipForAngles(RegionPatch& patch, int maxPasses = 10);

//! True when the patch's border edges are exactly the region's (as whole-mesh vertex pairs,
//! same direction): no crack, no T-junction at the seam.
bool patchMatchesBorder(const RegionSubmesh& region, const RegionPatch& patch);

//! The stitched mesh and where its parts come from.
struct StitchedMesh {
    TriMesh mesh;
    std::vector<int> vertexOrigin;  //!< output vertex -> input vertex, -1 for a new one
    std::vector<int> faceOrigin;    //!< output face -> input face, -1 for a new one
};

//! The input without its selected faces and the vertices only they used, then the patches'
//! new vertices and faces. Kept vertices and faces stay in input order (vertices compacted),
//! bit for bit; new vertices and faces come after them, in patch order.
StitchedMesh stitchRegions(const TriMesh& input, const std::vector<char>& selected, const std::vector<RegionPatch>& patches);

//! The vertex density μ of one region (RemeshParams::vertexDensity, per region vertex): the
//! target edge length `target` inside, graded from the border's edge lengths (RegionParams::
//! grading, along the region's edges); empty when the border's edges are all within
//! RegionParams::uniformWithin of the target (then uniform). `borderRatio` receives the worst
//! border edge length over target (or its inverse, if larger).
std::vector<double> regionDensity(const RegionSubmesh& region, double target, const RegionParams& params,
                                  double* borderRatio = nullptr);

struct RegionRemeshResult {
    //! The whole mesh in `result.mesh`; `result.metrics` are Table 2's figures of the new faces
    //! only (d_RMS / d_H against the selected input faces); warnings and notes of every region.
    RemeshResult result;
    std::vector<int> vertexOrigin;   //!< output vertex -> input vertex, -1 for a new one
    std::vector<int> faceOrigin;     //!< output face -> input face, -1 for a new one
    QualityMetrics interiorMetrics;  //!< the new faces that have no border vertex
    int regions = 0;                 //!< edge-connected pieces of the selection
    int keptRegions = 0;             //!< pieces left as they were (too small, or remeshing failed: a warning says why)
    int borderVertices = 0;          //!< vertices on the regions' borders (kept)
    double targetLength = 0;         //!< the uniform target edge length over the selected area
    double worstBorderRatio = 1;     //!< worst border edge length / target (or its inverse)
    bool wholeMesh = false;          //!< every face was selected: a plain remesh()
    int addedFaces = 0;              //!< faces added to the selection where it touched itself (closePinches)
};

//! Remeshes the faces with selected[f] != 0 (one flag per face of `input`): params.vertexCount
//! applies to the selected area (split between the pieces by their area, the border's grading
//! adding or removing some), the rest of the mesh is kept. Everything selected: exactly
//! remesh(input, params). Throws InvalidInputError for a flag count that is not the face count,
//! an empty selection, a bad index, or parameters out of range (checkRemeshParams).
RegionRemeshResult remeshRegion(const TriMesh& input, const std::vector<char>& selected, const RemeshParams& params,
                                const RegionParams& regionParams = {}, const Progress& progress = {});

}  // namespace fieldcvt
