#pragma once
// Remeshing a region: the selected faces are remeshed, the rest is kept bit for bit.
// Each edge-connected piece of the selection is cut out (extractRegion), remeshed by remesh()
// with a density that grades from its border's edge lengths to the target (regionDensity), its
// new border put exactly on the region's own border vertices (pinBorder), and the pieces put
// back among the kept faces, sharing the border vertices by index (stitchRegions).
//
// A selection that is not a manifold, oriented surface is repaired first, as remesh() repairs a
// whole mesh (repair.h): the selection takes in every face of a non-manifold edge it touches
// (takeInNonManifoldEdges), a piece with a non-manifold edge or vertex or a non-orientable part
// is repaired on its own (repairRegion), and each piece is oriented as the kept faces around it
// (orientRegionToKept). What remeshRegion returns is manifold and oriented except where the
// faces kept outside the selection were not (a warning says so); otherwise it throws.
#include "boundary.h"  // borderLoops, which the region's seam works along
#include "mesh.h"
#include "metrics.h"
#include "remesh.h"
#include "repair.h"  // repairRegion repairs as repairMesh does

#include <cstdint>
#include <string>
#include <unordered_set>
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

//! Adds to the selection the other faces of every non-manifold edge (more than two faces) that
//! has both selected faces and others: a region's border then never runs along such an edge,
//! which is repaired inside the region instead (repairRegion). Returns the faces added.
int takeInNonManifoldEdges(const TriMesh& mesh, std::vector<char>& selected);

//! One region cut out of its mesh.
struct RegionSubmesh {
    TriMesh mesh;  //!< the region's faces, vertices renumbered in first-use order
    //! Region vertex -> vertex of the whole mesh. A copy that repairRegion made where it split a
    //! vertex has an id past the whole mesh's vertices instead: a new vertex of the output, at
    //! the coordinates of the vertex it copies.
    std::vector<int> originalVertex;
    std::vector<int> originalFace;  //!< region face -> face of the whole mesh (empty once repaired)
    //! Per region vertex: on the region's border (an edge with one region face: next to a kept
    //! face, on the mesh's own boundary, or where repairRegion split the surface). These vertices
    //! are kept where they are.
    std::vector<char> border;
    //! Region vertex -> the whole-mesh vertex it is or copies: where its per-vertex data (density,
    //! field) come from.
    std::vector<int> sourceVertex;
    //! Made by repairRegion: remesh() must not merge its split copies again, nor drop a part.
    bool repaired = false;
};

//! The region made of `faces` (indices into mesh.faces).
RegionSubmesh extractRegion(const TriMesh& mesh, const std::vector<int>& faces);

//! The directed edges a -> b (whole-mesh vertices) of the faces kept around the regions, those
//! between two vertices of selected faces (the others meet no region).
struct KeptEdges {
    std::unordered_set<std::uint64_t> directed;
    bool runs(int a, int b) const;  //!< a kept face has the edge a -> b
    bool touches(int a, int b) const { return runs(a, b) || runs(b, a); }
};

//! The edges of the faces with selected[f] == 0.
KeptEdges keptEdges(const TriMesh& mesh, const std::vector<char>& selected);

//! True when the region is a manifold, consistently oriented surface: no edge of more than two
//! faces, none that two faces run the same way, no vertex whose faces form several fans.
bool regionIsClean(const RegionSubmesh& region);

//! Repairs the region as remesh() repairs a whole mesh (repair.h: degenerate and duplicate faces
//! removed, non-manifold edges split into manifold sheets, non-orientable parts cut, vertices of
//! several fans split, components too small for `vertexBudget` vertices dropped), except that no
//! vertex is merged with another (its vertices are the whole mesh's) and no component that
//! meets the kept faces is dropped (a hole). A split vertex stays the whole mesh's on the copy
//! whose border edges meet the kept faces (the seam is shared by index); its other copies get
//! ids from `nextCopyId` on. Returns the repair's report (its notes say what changed).
RepairReport repairRegion(RegionSubmesh& region, const KeptEdges& kept, int vertexBudget, int& nextCopyId);

//! The edge-connected parts of a region, each a region of its own (in order of first face):
//! remeshed one by one, a part too small for the target may be kept as repaired while the rest
//! is remeshed.
std::vector<RegionSubmesh> regionParts(const RegionSubmesh& region);

//! Reverses each edge-connected part of the region whose border runs along the kept faces' edges
//! the way they do (an orientation that disagrees with theirs; most such edges decide), so that
//! the remeshed region meets the kept faces consistently oriented. Returns the faces reversed;
//! `against` receives the border edges outvoted (kept faces on both sides of the vote: the input
//! is not consistently oriented there, or not orientable through the region).
int orientRegionToKept(RegionSubmesh& region, const KeptEdges& kept, int* against = nullptr);

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
//! bit for bit; new vertices and faces come after them, in patch order. A patch vertex whose
//! original is a copy's id (RegionSubmesh::originalVertex) is a new vertex, one per id.
StitchedMesh stitchRegions(const TriMesh& input, const std::vector<char>& selected, const std::vector<RegionPatch>& patches);

//! The vertex density μ of one region (RemeshParams::vertexDensity, per region vertex): the
//! target edge length `target` inside, graded from the border's edge lengths (RegionParams::
//! grading, along the region's edges); empty when the border's edges are all within
//! RegionParams::uniformWithin of the target (then uniform). `borderRatio` receives the worst
//! border edge length over target (or its inverse, if larger).
std::vector<double> regionDensity(const RegionSubmesh& region, double target, const RegionParams& params,
                                  double* borderRatio = nullptr);

//! What a mesh must not hold to be a manifold, oriented surface.
struct SurfaceFaults {
    int nonManifoldEdges = 0;     //!< edges of more than two faces
    int oppositeEdges = 0;        //!< edges whose two faces run them the same way
    int nonManifoldVertices = 0;  //!< vertices whose faces form several fans
    bool any() const { return nonManifoldEdges + oppositeEdges + nonManifoldVertices > 0; }
    std::string describe() const;  //!< e.g. "1 non-manifold edge and 2 non-manifold vertices"
};

//! The faults of a stitched mesh: `kept` the input's own, on no selected face left as it was:
//! an edge between input vertices that had the same fault in `input` (among kept faces, or where
//! a kept face runs the way the selected face it met did), a vertex of the input whose faces
//! formed several fans already; `elsewhere` every other one.
void stitchedFaults(const TriMesh& input, const std::vector<char>& selected, const StitchedMesh& stitched, SurfaceFaults& kept,
                    SurfaceFaults& elsewhere);

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
    //! Faces added to the selection: where it touched itself (closePinches) and around the
    //! non-manifold edges on its border (takeInNonManifoldEdges).
    int addedFaces = 0;
};

//! Remeshes the faces with selected[f] != 0 (one flag per face of `input`): params.vertexCount
//! applies to the selected area (split between the pieces by their area, the border's grading
//! adding or removing some), the rest of the mesh is kept. Everything selected: exactly
//! remesh(input, params). Throws InvalidInputError for a flag count that is not the face count,
//! an empty selection, a bad index, or parameters out of range (checkRemeshParams), and when the
//! result would not be manifold and oriented outside the kept faces (stitchedFaults: a piece
//! that could not be remeshed, left as it was, holds a fault of the input) instead of returning it.
RegionRemeshResult remeshRegion(const TriMesh& input, const std::vector<char>& selected, const RemeshParams& params,
                                const RegionParams& regionParams = {}, const Progress& progress = {});

}  // namespace fieldcvt
