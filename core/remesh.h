#pragma once
// The one public entry point of the engine: input mesh + parameters -> remeshed mesh + report.
#include "mesh.h"
#include "field.h"
#include "lattice.h"
#include "metrics.h"
#include "progress.h"
#include "repair.h"
#include "thin_parts.h"
#include "valence.h"

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace fieldcvt {

//! Where the sample density ρ of eq. 1 comes from (adaptive remeshing). The density given or
//! computed is a *vertex density* μ > 0 per input vertex: output vertices per unit area ∝ μ, so
//! the target edge length is ∝ 1/sqrt(μ). A 2D CVT's cells have diameter ∝ ρ^(-1/4) (Gersho),
//! so eq. 1 uses ρ = μ², piecewise constant per input triangle (mean of its corners' μ²). μ is
//! normalised to an area-weighted mean of 1: the vertex count is kept, and cells are ~1/μ times
//! the uniform cell (density.h).
enum class DensitySource { Uniform, Curvature, PerVertex };

//! The vertex counts remesh() takes, one limit for the CLI's --vertices and --target-length and
//! the MeshLab filter's vertexCount and targetLength: 100 000 output vertices took 1.3 GB, so
//! the maximum needs about 65 GB.
constexpr int kMinVertexCount = 4;
constexpr int kMaxVertexCount = 5000000;
//! RemeshParams::threads at most (0 = all cores).
constexpr int kMaxThreads = 4096;
//! "between 4 and 5000000", the one wording of that limit in every message.
std::string vertexCountRange();

//! A target edge length turned into a vertex count, for the front ends' size-by-length option.
struct VertexCountFromLength {
    int vertexCount = kMinVertexCount;
    std::string warning;  //!< non-empty when the length asked for fewer than kMinVertexCount vertices
};
//! An equilateral triangulation with edge `length` has about 2 faces per vertex, each of area
//! sqrt(3) length^2 / 4: 2 area / (sqrt(3) length^2) vertices. Throws InvalidInputError naming
//! `parameter` (as its front end calls it) when the length is not > 0 or gives more than
//! kMaxVertexCount; fewer than kMinVertexCount give that minimum and a warning that says so.
VertexCountFromLength vertexCountForLength(double area, double length, const std::string& parameter);

struct RemeshParams {
    int vertexCount = 5000;  //!< target number of output vertices (samples), kMinVertexCount..kMaxVertexCount
    //! Weight of E_field (eq. 2) on the normalised surface (mean cell area 1, §5); 0 = pure CVT.
    //! Default chosen by measurement (README: λ sweep).
    double lambda = 0.002;
    //! The schedule: Lloyd warm-up steps (§5, uneven sampling), then L-BFGS iterations on E_CVT,
    //! then on E_CVT + λ E_field. The paper's fixed schedule is 65 + 65 (130 for a pure CVT),
    //! which we ran after 30 Lloyd steps; it stays available (CLI `--lloyd-iterations 30
    //! --cvt-iterations 65 --fcvt-iterations 65`). The default is shorter, 10 + 10 + 40 (63
    //! evaluations instead of 163, ~0.6× the time): the valence optimisation (§4.4), not the last
    //! L-BFGS iterations, decides V6%, and with its look-ahead at 8 the short schedule keeps the
    //! quality bars. Measured over seeds 1–4 on the nine rows of bench/side_by_side.py (README:
    //! the schedule): the lowest V6% per row at or above the paper schedule's on 8 of the 9 rows
    //! (camelhead 94.1 against 94.5), d_H within the seeds' spread, Q_avg 0.002–0.005 lower.
    //! Lloyd 5 instead of 10: nefertiti 10000 seed 3 kept a 26.7° triangle; fewer FCVT
    //! iterations (25, 30): fandisk 5000 V6 93.5–93.7 %.
    int lloydIterations = 10;
    //! Lloyd steps when the start is the lattice (latticeStart): it is already even, and 0, 3
    //! and 10 steps gave the same figures within the seeds' spread on the nine rows (README: the
    //! lattice start), 0 the shortest run.
    int latticeLloydIterations = 0;
    int cvtIterations = 10;   //!< L-BFGS iterations on E_CVT (see lloydIterations)
    int fcvtIterations = 40;  //!< then L-BFGS iterations on E_CVT + λ E_field (see lloydIterations)
    //! FCVT iterations instead of fcvtIterations from largeRunSamples samples on, when the start
    //! is the lattice (latticeStart). There each cell spans a nearly flat patch and the lattice
    //! starts close to the optimum: E_field levels off within 5 iterations, and 20 instead of 40
    //! gave the same figures in 0.5 of the FCVT stage (nefertiti x2 at 50 000 / 100 000, bunny x2
    //! at 60 000 / 150 000, camelhead x2 at 60 000: Q_avg within -0.0009..0, V6 within ±0.05,
    //! d_H within the seeds' spread; docs/measurements.md). Below it the shared rows need 40
    //! (25 or 30 lost V6 on fandisk 5000). The CLI's --fcvt-iterations sets both.
    int largeRunFcvtIterations = 20;
    int largeRunSamples = 50000;
    //! Open surfaces and sharp features (the second stage of §5): Lloyd steps after the CVT
    //! iterations that put the samples of cells meeting the input's border or a feature line on
    //! it (a 1D CVT along the curve) and one sample on each feature corner, so the output's
    //! boundary and creases follow the input's. Those samples stay fixed during the FCVT
    //! iterations.
    int boundaryIterations = 10;
    FieldSource fieldSource = FieldSource::Extrinsic;  //!< the 6-RoSy field E_field aligns to
    //! FieldSource::User: one vector per input vertex (projected on the tangent plane).
    std::vector<Vec3> userDirections;
    //! Starting samples (input units) instead of the random area-uniform ones, e.g. a previous
    //! result or a deliberately uneven start; when given, their number replaces vertexCount. The
    //! Lloyd warm-up makes any start work (§5, "Uneven initial sampling", Fig. 9).
    std::vector<Vec3> initialSamples;
    //! Start from the lattice points of the field-aligned position field (lattice.h) instead of
    //! random samples, when E_field is used with a uniform density, without feature lines
    //! (there the start cut fandisk's creases) and no initialSamples are given. Random starts
    //! leave 5–7 pairs that neither the CVT nor the valence optimisation removes (the cylinder
    //! at 1000 vertices kept 11 such pairs on a field without a singularity); the lattice has
    //! none away from the field's singularities. Measured over seeds 1–4 on the nine rows of
    //! bench/side_by_side.py (README: the lattice start): mean Q_avg +0.004 to +0.010, the
    //! lowest V6% up on every row, the cylinder's interior all valence 6. The seed sets the
    //! lattice's phase (LatticeParams::seed) and the field's random initial directions.
    bool latticeStart = true;
    std::uint64_t seed = 1;  //!< seed of the initial sampling and of the field
    int threads = 0;         //!< OpenMP threads, 0 = one per core that no other task holds (thread_budget.h)
    //! Wall-clock budget of the optimisation (Lloyd, CVT, FCVT) in seconds, 0 = none. When it
    //! runs out, the output is made from the best samples so far and a warning says so.
    double timeLimitSeconds = 0;
    bool computeDistances = true;  //!< also compute d_RMS / d_H against the input in the report
    //! The caller stores the output's coordinates as float (MeshLab's single-precision CMeshO):
    //! the output is rounded to float here, and its precision check (below) is of that mesh.
    //! Either way, when the coordinates' resolution far from the origin cannot hold the edge
    //! length (faces of zero area, coincident vertices), a warning says so and the quality
    //! figures are those of the mesh returned.
    bool outputInFloat = false;
    //! Also find the field's singularities (RemeshResult::singularities, for the report and the
    //! log; bunny 5000: 0.01 s, nefertiti 10000: 0.02 s).
    bool computeSingularities = true;
    //! Random samples per mesh for the report's d_RMS / d_H (plus every vertex and face centroid
    //! of both meshes); 0 = dense: 20 per face of both meshes, 20 000..200 000 (`fcvt metrics
    //! --ref` takes 200 000). 50 000 rather than dense: the metrics stage did 4× the closest-point
    //! queries of the FCVT iterations (fertility 3000: 425 000 against 198 000) for d_H figures
    //! that differ by at most 3 % (seed 1: torus 1000, fandisk 5000, bunny 5000 the same to
    //! 0.001 %, fertility 3000 0.842 against 0.867 %).
    int distanceSamples = 50000;
    //! Optimise on a coarser copy of the input (simplify.h) with about this many faces per
    //! sample when the input has more than 1.5 times that; 0 = always on the input itself, as
    //! the paper does. The output's vertices are put back on the input surface and d_RMS / d_H
    //! are measured against the input. Every RVD evaluation clips all triangles of the surface
    //! it runs on, so this is what makes a dense scan cost about what a coarse model costs.
    //! 4 by measurement (README: optimisation surface).
    int optimisationFacesPerSample = 4;
    //! ... but at most this many faces in all, and never fewer than 2 a sample
    //! (optimisationFaceTarget): nefertiti subdivided twice to 100 000 and 400 000 vertices
    //! with 2 faces a sample instead of 4 gave the same Q_avg, V6 and d_H in 0.80 and 0.70 of the
    //! time and 0.73 of the memory at 400 000; on the shared rows (at most 40 000 faces) 2 or 3
    //! a sample lost θ_min and V6 (docs/measurements.md), so below the cap they keep 4.
    int optimisationFacesCap = 200000;
    //! §4.4: after the RDT, flips / collapses / splits that lower Σ(d(v) − o(v))², then a
    //! relaxation on the fixed connectivity (valence.h).
    bool valenceOptimization = true;
    ValenceParams valence;
    //! Sharp features: input edges whose dihedral angle (between face normals) is at least this
    //! many degrees are feature lines; 0 = off.
    double featureAngleDegrees = 0;
    //! Feature edges chosen by the user (pairs of input vertex indices, e.g. MeshLab's selection),
    //! in addition to the dihedral ones.
    std::vector<std::array<int, 2>> featureEdges;
    //! Sample density ρ (eq. 1): uniform, from curvature, or one value per input vertex.
    DensitySource density = DensitySource::Uniform;
    //! DensitySource::Curvature: how strongly curvature raises the density (0 = uniform):
    //! μ = (1 + gradation · κ̂)², κ̂ = sqrt(k1² + k2²) times the uniform edge length, clamped to
    //! 25× its minimum and smoothed (density.h). Finite, >= 0.
    double gradation = 1.0;
    //! DensitySource::PerVertex: μ, one finite value > 0 per input vertex (e.g. MeshLab's vertex
    //! quality); InvalidInputError otherwise.
    std::vector<double> vertexDensity;
    //! Repair the input first (repair.h: welds, duplicate faces, non-manifold edges and
    //! vertices, non-orientable pieces, components too small for the vertex count); false = the
    //! strict check only, which refuses what it cannot take. vertexBudget is set by remesh().
    bool repair = true;
    RepairParams repairParams;
    //! Holes whose border spans less than this many target edge lengths (the bounding box of the
    //! border's vertices) are closed before remeshing (hole_filling.h), counted in a warning;
    //! 0 keeps every hole (CLI --keep-holes). 2: the output's cells cannot follow a border that
    //! small (issue 32: "holes smaller than about two edge lengths across are closed").
    double closeHolesUnder = 2.0;
    //! Keep the vertex count as asked even where the surface is thinner than the edge length
    //! (CLI --exact-count). false: the vertex density is raised there, locally, so that the RDT
    //! keeps the shells closed with their genus (thin_parts.h; RemeshResult::thinParts).
    bool exactCount = false;
    ThinPartParams thinParts;
};

//! How a front end names the parameters in its messages: the CLI by its options
//! ("--vertices"), the MeshLab filter by label and script name ("'Target vertices'
//! (vertexCount)"). The defaults are the core's own words.
struct ParameterNames {
    std::string vertexCount = "the vertex count";
    std::string lambda = "lambda";
    std::string lloydIterations = "the Lloyd iteration count";
    std::string cvtIterations = "the CVT iteration count";
    std::string fcvtIterations = "the FCVT iteration count";
    std::string threads = "the thread count";
    std::string timeLimit = "the time limit";
    std::string featureAngle = "the feature angle";
    std::string gradation = "the gradation";
};

//! The one check of RemeshParams' ranges (remesh() runs it too): throws InvalidInputError with
//! one line naming the parameter as `names` says, its range and the value given.
void checkRemeshParams(const RemeshParams& params, const ParameterNames& names = {});

//! Energies after one L-BFGS step (an evaluation that lowered E_tot) or one Lloyd step.
struct EnergyRecord {
    std::string phase;  //!< "lloyd", "cvt" or "fcvt"
    double cvt = 0;     //!< E_CVT at the working scale (mean cell area 1)
    double field = 0;   //!< E_field (FCVT phase only; 0 in the Lloyd and CVT phases, where it is not computed)
};

//! One timed stage of a run ("sampling", "cvt", "rdt", "metrics", ...), in seconds.
struct StageTime {
    std::string stage;
    double seconds = 0;
};

struct RemeshResult {
    TriMesh mesh;                       //!< the restricted Delaunay triangulation
    int evaluations = 0;                //!< energy + gradient evaluations
    int fcvtIterations = 0;             //!< the FCVT iteration budget used (RemeshParams::largeRunFcvtIterations)
    std::vector<StageTime> stageTimes;  //!< per-stage wall time, in pipeline order
    double totalSeconds = 0;
    QualityMetrics metrics;             //!< Table 2 figures of mesh (d_* against the input)
    TopologySummary inputTopology;      //!< genus / boundary loops / components of the input
    TopologySummary outputTopology;     //!< the same for the output
    std::vector<std::string> warnings;  //!< e.g. topology not recovered, solver restarts
    //! The first inputWarnings of `warnings` are the input check's and the repair's (the stage
    //! that ran first), for a log in stage order.
    int inputWarnings = 0;
    //! The OpenMP threads the run took (RemeshParams::threads, or for 0 the cores no other
    //! task held as it started: thread_budget.h).
    int threads = 0;
    //! Information: what changed nothing a user sees (unreferenced vertices removed, ...).
    std::vector<std::string> notes;
    std::vector<EnergyRecord> energyHistory;  //!< convergence (paper Fig. 8)
    //! The field interpolated at the output vertices (empty for a pure CVT without a field).
    std::vector<Vec3> outputNormals, outputDirections;
    std::vector<Singularity> singularities;  //!< of the input's field, positions in input units
    ValenceStats valence;                    //!< V6% before / after valence optimisation, operations done
    RepairReport repair;                     //!< what the repair stage did (RemeshParams::repair)
    //! The lattice start (RemeshParams::latticeStart), spacing in input units; passes 0 = random start.
    LatticeReport lattice;
    //! Faces of the surface the optimisation ran on: the input's (after repair) or its coarser
    //! copy's (RemeshParams::optimisationFacesPerSample).
    int optimisationFaces = 0;
    //! Vertices added for thin parts (RemeshParams::exactCount) and where: `added` > 0 when the
    //! vertex count was raised beyond the one asked for.
    struct ThinParts {
        int added = 0;        //!< samples beyond the vertex count asked for
        int faces = 0;        //!< faces of the optimisation surface thinner than the edge length allows
        double thinnest = 0;  //!< the smallest thickness measured, in input units (0: none thin)
        bool capped = false;  //!< the samples reached ThinPartParams::maxVertexFactor × the count asked for
        //! The kept pass has side-aware cells (a sample owns nothing of the far side of a wall).
        bool sideAwareCells = false;
    } thinParts;
};

//! The mesh remesh() computed the field and its singularities on, for a log or report next to
//! them: "the input (N faces)" or "the optimisation surface, a simplified copy of the input (N
//! faces)". `fcvt field` and the field filter compute on the input: the figures agree there.
std::string fieldMeshDescription(const RemeshResult& result);

//! The paper's fixed schedule (§5: 65 L-BFGS iterations on E_CVT, then 65 with E_field) after
//! the 30 Lloyd steps FCVT ran before the short default (RemeshParams::lloydIterations).
inline void usePaperSchedule(RemeshParams& params)
{
    params.lloydIterations = 30;
    params.latticeLloydIterations = 30;
    params.cvtIterations = 65;
    params.fcvtIterations = 65;
}

//! The optimisation surface's face count for `sampleCount` samples: optimisationFacesPerSample
//! a sample, at most optimisationFacesCap in all but never fewer than 2 a sample (or the
//! per-sample count if lower); 0 when optimisationFacesPerSample is 0 (the input itself).
int optimisationFaceTarget(const RemeshParams& params, int sampleCount);

//! Remeshes `input` (validated first; throws InvalidInputError with a clear message).
RemeshResult remesh(const TriMesh& input, const RemeshParams& params, const Progress& progress = {});

}  // namespace fieldcvt
