#pragma once
// RemeshParams, what remesh() (remesh.h) takes: each field's meaning, unit, range and default.
// Lengths and positions are in the input's units; "§", "eq." and "Fig." are the FCVT paper's.
// The measurements behind the defaults: docs/tuning.md, "RemeshParams::<field>".
#include "field_types.h"
#include "mesh.h"
#include "remesh_limits.h"
#include "repair_params.h"
#include "thin_part_params.h"
#include "valence_params.h"

#include <array>
#include <cstdint>
#include <vector>

namespace fieldcvt {

//! Where the sample density ρ of eq. 1 comes from. Each source gives a vertex density μ > 0 per input
//! vertex: output vertices per unit area ∝ μ, edge length ∝ 1/sqrt(μ). A 2D CVT's cells have diameter
//! ∝ ρ^(-1/4) (Gersho), so eq. 1 uses ρ = μ² per input triangle (mean of its corners' μ²); μ is
//! normalised to an area-weighted mean of 1, keeping the vertex count (density.h).
enum class DensitySource { Uniform, Curvature, PerVertex };

struct RemeshParams {
    //! Output vertices (samples), kMinVertexCount..kMaxVertexCount; initialSamples replace it.
    int vertexCount = 5000;
    //! Weight of E_field (eq. 2) against E_CVT on the surface scaled to mean cell area 1 (§5); finite,
    //! >= 0; 0 = a pure CVT.
    double lambda = 0.002;
    //! The schedule, every count >= 0: Lloyd steps after a random start (§5), then cvtIterations L-BFGS
    //! iterations on E_CVT, then fcvtIterations on E_CVT + λ E_field. Shorter than the paper's 30 + 65 +
    //! 65 (usePaperSchedule()): the valence stage, not the last iterations, decides V6%.
    int lloydIterations = 10;
    int latticeLloydIterations = 0;  //!< Lloyd steps after the lattice start (latticeStart): it is even already
    int cvtIterations = 10;
    int fcvtIterations = 40;
    //! From largeRunSamples samples on, after the lattice start: largeRunFcvtIterations instead of
    //! fcvtIterations, as E_field levels off sooner there. The CLI's --fcvt-iterations sets both.
    int largeRunFcvtIterations = 20;
    int largeRunSamples = 50000;
    //! Lloyd steps (>= 0) that put the samples of cells meeting the border or a feature line on it (a
    //! 1D CVT along the curve) and one on each feature corner (§5); they stay fixed in the FCVT steps.
    int boundaryIterations = 10;
    //! Gauss–Seidel sweeps of the extrinsic field per hierarchy level (FieldParams::smoothingIterations), >= 0.
    int fieldSmoothingIterations = 20;
    //! Gauss–Seidel sweeps of the lattice start's position field per hierarchy level
    //! (LatticeParams::iterations), >= 0.
    int latticeIterations = 4;
    //! Lattices solved at most (LatticeParams::maxPasses, >= 1), each with a spacing corrected
    //! towards vertexCount while the last is over 0.5 % off it; the closest is kept.
    int latticePasses = 3;
    FieldSource fieldSource = FieldSource::Extrinsic;  //!< the 6-RoSy field E_field aligns to
    std::vector<Vec3> userDirections;                  //!< FieldSource::User: a vector per input vertex (made tangent)
    //! Starting samples instead of random area-uniform ones: at least 4, finite; their number replaces
    //! vertexCount. The Lloyd steps make any start work (§5, Fig. 9).
    std::vector<Vec3> initialSamples;
    //! Start from the lattice points of the field-aligned position field (lattice.h) when E_field is used
    //! with a uniform density, no feature lines and no initialSamples: it has no 5–7 pairs away from the
    //! field's singularities, where a random start leaves some.
    bool latticeStart = true;
    std::uint64_t seed = 1;  //!< of the initial sampling, the lattice's phase and the field
    int threads = 0;         //!< OpenMP threads, 0..kMaxThreads; 0 = one per core no other task holds (thread_budget.h)
    //! Wall-clock budget of the Lloyd, CVT and FCVT steps in seconds, finite, >= 0 (0 = none); when it
    //! runs out, the output is made from the best samples so far, with a warning.
    double timeLimitSeconds = 0;
    bool computeDistances = true;  //!< also compute d_RMS / d_H against the input for the report
    //! Round the output to float (MeshLab's CMeshO) before its precision check; either way a warning says
    //! when the coordinates far from the origin cannot hold the edge length.
    bool outputInFloat = false;
    bool computeSingularities = true;  //!< also find the field's singularities (RemeshResult); cheap
    //! Random samples per mesh (>= 0) for d_RMS / d_H, besides every vertex and face centroid of both
    //! meshes; 0 = dense (20 a face, 20 000..200 000), whose d_H differs by at most 3 % for more queries.
    int distanceSamples = 50000;
    //! Optimise on a coarser copy of the input (simplify.h) of about this many faces a sample (>= 0) when
    //! the input has 1.5 times that; 0 = on the input, as the paper does. Every RVD evaluation clips
    //! every face: this makes a dense scan cost what a coarse model costs.
    int optimisationFacesPerSample = 4;
    int optimisationFacesCap = 200000;  //!< ... but at most this many faces (>= 0), never under 2 a sample
    //! Inputs of at least twice this many faces are simplified in blocks of about this many faces, in
    //! parallel (SimplifyParams::blockFaces; the blocks depend on the input only), >= 0; 0 = one pass.
    int simplifyBlockFaces = 250000;
    //! §4.4: after the RDT, flips / collapses / splits that lower Σ(d(v) − o(v))², then a relaxation on
    //! the fixed connectivity (valence.h).
    bool valenceOptimization = true;
    ValenceParams valence;
    //! Input edges whose dihedral angle is at least this many degrees are feature lines; 0..180, 0 = off.
    double featureAngleDegrees = 0;
    //! Feature edges chosen by the user (input vertex index pairs, e.g. MeshLab's selection), besides.
    std::vector<std::array<int, 2>> featureEdges;
    //! Sharp edges (by featureAngleDegrees) with another sharp edge or the open border beside them
    //! closer than this many edge lengths are not kept as feature lines: no triangle can span such
    //! a strip and keep both sides without a sliver (feature_strips.h). 0 keeps them all; >= 0. At
    //! 0.75 the real-world meshes and fandisk with --feature-angle 45 meet issue 52's triangle bars
    //! on 11 of 17 runs, against 2 with every line kept (docs/measurements.md, "Narrow feature
    //! strips"). Pieces of line left shorter than an edge length go too.
    double narrowFeatureStripShare = 0.75;
    DensitySource density = DensitySource::Uniform;  //!< the sample density ρ (eq. 1)
    //! DensitySource::Curvature: how strongly curvature raises μ; finite, >= 0 (0 = uniform). μ = (1 +
    //! gradation · κ̂)², κ̂ = sqrt(k1² + k2²) × the uniform edge length, clamped and smoothed (density.h).
    double gradation = 1.0;
    //! DensitySource::PerVertex: μ, one finite value > 0 per input vertex (e.g. MeshLab's quality).
    std::vector<double> vertexDensity;
    //! Repair the input first (repair.h: welds, duplicate faces, non-manifold edges and vertices,
    //! non-orientable pieces, components too small); false = the strict check only, which refuses what
    //! it cannot take. remesh() sets repairParams.vertexBudget.
    bool repair = true;
    RepairParams repairParams;
    //! Close holes whose border spans less than this many target edge lengths before remeshing
    //! (hole_filling.h), with a warning; <= 0 keeps every hole (CLI --keep-holes). Cells cannot follow
    //! a smaller border.
    double closeHolesUnder = 2.0;
    //! Keep the vertex count even where the surface is thinner than the edge length (CLI --exact-count);
    //! false raises the density there, so that the shells stay closed with their genus (thin_parts.h,
    //! RemeshResult::thinParts).
    bool exactCount = false;
    ThinPartParams thinParts;
};

//! Throws InvalidInputError, one line naming the parameter as `names` says, its range and the value
//! given, when a field of `params` is out of its range; remesh() runs it too.
void checkRemeshParams(const RemeshParams& params, const ParameterNames& names = {});

//! The paper's fixed schedule (§5: 65 L-BFGS iterations on E_CVT, then 65 with E_field) after 30
//! Lloyd steps.
inline void usePaperSchedule(RemeshParams& params)
{
    params.lloydIterations = 30;
    params.latticeLloydIterations = 30;
    params.cvtIterations = 65;
    params.fcvtIterations = 65;
}

}  // namespace fieldcvt
