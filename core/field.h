#pragma once
// The 6-RoSy direction field that FCVT aligns edges to (paper §3.2–3.3, §4.1): per input vertex
// a unit normal n and a unit representative direction d ⟂ n; the six field directions are d
// rotated by k·60° about n.
#include "field_types.h"
#include "mesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace fieldcvt {

//! "extrinsic", "curvature-max", "curvature-min", "user" <-> FieldSource (throws
//! InvalidInputError on an unknown name).
FieldSource fieldSourceFromName(const std::string& name);
std::string fieldSourceName(FieldSource source);

//! Which smoothness the extrinsic source's solver minimises (Jakob et al. 2015 offer both).
enum class FieldSmoothness {
    //! Intrinsic where the border constrains the field (alignToBorder on a mesh with a border)
    //! and is long for the surface (at least 2·sqrt(area): an open tube, a disk), extrinsic
    //! otherwise (closed meshes, a scan with small holes).
    Auto,
    //! Σ ||d_i' − d_j'||² in 3D (eq. 3): penalises the tangent planes' turning too, so on a
    //! cylinder it is zero only for a field along the axis, and a rim constraint (30° off that,
    //! mod 60°) makes the field twist between the rims and the middle.
    Extrinsic,
    //! The same after carrying d_j to i's tangent plane by the smallest rotation (discrete
    //! Levi-Civita transport): zero for any parallel field, so on a developable surface the
    //! border's alignment propagates without cost.
    Intrinsic,
};

struct FieldParams {
    FieldSource source = FieldSource::Extrinsic;
    std::uint64_t seed = 1;        //!< seed of the random initial directions (extrinsic)
    int smoothingIterations = 20;  //!< Gauss–Seidel sweeps per hierarchy level (extrinsic)
    //! Edges whose dihedral angle exceeds this (degrees) constrain the field to their tangent,
    //! like boundary edges; <= 0 disables crease constraints.
    double sharpAngle = 60.0;
    //! Border edges constrain the field to their tangent (extrinsic source). Turn off where the
    //! borders disagree with each other, e.g. a square (edges 90° apart). (An open cylinder's
    //! rims are fine with the Auto smoothness: the field follows the rings everywhere; off, it
    //! follows the axis, which no 6-RoSy representative of a rim tangent matches.)
    bool alignToBorder = true;
    FieldSmoothness smoothness = FieldSmoothness::Auto;  //!< extrinsic source only
};

//! Computes the field at every vertex of `mesh` (which must be a clean triangle mesh: see
//! mesh_check.h). Deterministic for a given seed and independent of the thread count.
DirectionField computeField(const TriMesh& mesh, const FieldParams& params);

struct FieldHierarchyLevels;

//! As above, and fills `report` (the energy traces cost extra time; pass nullptr to skip).
//! `hierarchy` (if given, extrinsic source) receives the hierarchy the field was smoothed on,
//! left empty when nothing was smoothed (every direction prescribed).
DirectionField computeField(const TriMesh& mesh, const FieldParams& params, FieldReport* report,
                            FieldHierarchyLevels* hierarchy = nullptr);

//! Builds a field from user vectors per vertex: each is projected on the tangent plane of the
//! vertex normal and normalised. Throws InvalidInputError on a size mismatch or a non-finite
//! vector; a vector (nearly) parallel to the normal (tangent part below 1e-3 of its length, or
//! zero) is replaced by the smooth extrinsic field's direction there: the multi-resolution
//! smoothing of computeField with the usable user directions held fixed.
DirectionField fieldFromVectors(const TriMesh& mesh, const std::vector<Vec3>& vectors, std::uint64_t seed = 1);

//! Area-weighted vertex normals (unit); isolated vertices get (0, 0, 1).
std::vector<Vec3> vertexNormals(const TriMesh& mesh);

//! The extrinsic energy Σ_edges ||d_i' − d_j'||² over the best-matching representatives
//! (Jakob et al. 2015, eq. 3); smoothing lowers it.
double extrinsicEnergy(const TriMesh& mesh, const DirectionField& field);

//! Per-face 6-RoSy index: the sum of the rotations (in multiples of 60°) of the matched
//! representatives around the face; faces with a non-zero index are singular.
//! Precisely (field.cpp): with a discrete Levi-Civita connection on the vertex tangent planes
//! (chart angles of the edges = corner angles scaled by 2π/Θ_v, Knöppel et al. 2013), the turn
//! δ'_ij ∈ (−π/6, π/6] from d_i transported to j to the nearest representative of d_j, and the
//! face's share of the angle defects K_f = Σ_corners (2π/Θ_v − 1)·α (0 at border vertices):
//! index_f = (Σ_{ij ∈ ∂f} δ'_ij + K_f) / (π/3). Exactly 6·χ in total on a closed surface.
std::vector<Singularity> findSingularities(const TriMesh& mesh, const DirectionField& field);

}  // namespace fieldcvt
