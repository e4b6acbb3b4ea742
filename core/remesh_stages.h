#pragma once
// The stages of remesh() (remesh.h), in the order it runs them. Internal to the core: remesh() is
// the public entry point. Each stage is a function of explicit inputs (the parameters read-only)
// that returns what it makes; remesh() (remesh.cpp) passes the products from stage to stage.
// docs/development.md maps them.
#include "closest_point.h"
#include "energy.h"
#include "errors.h"
#include "feature_lines.h"
#include "lattice.h"
#include "field.h"
#include "field_hierarchy.h"
#include "huge_pages.h"
#include "progress.h"
#include "remesh_params.h"
#include "remesh_result.h"
#include "simplify.h"
#include "valence.h"
#include "working_frame.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace fieldcvt {

using Clock = std::chrono::steady_clock;

//! At the working scale the mean cell has area 1: an equilateral triangle mesh with one vertex
//! per unit of area has edges sqrt(2 / sqrt(3)) long.
inline const double kWorkingEdgeLength = std::sqrt(2.0 / std::sqrt(3.0));

double secondsSince(Clock::time_point start);

//! The optimisation surface's face count for `sampleCount` samples: optimisationFacesPerSample a
//! sample, at most optimisationFacesCap in all but never fewer than 2 a sample (or the per-sample
//! count if lower); 0 when optimisationFacesPerSample is 0 (the input itself).
int optimisationFaceTarget(const RemeshParams& params, int sampleCount);

//! Where the optimisation is, for the progress line, the energy history and the time limit.
enum class Phase { Sampling, Field, Lloyd, Cvt, Features, Fcvt, Rdt, Valence };
//! "sampling", "field", "lloyd", "cvt", "features", "fcvt", "rdt", "valence".
const char* phaseName(Phase phase);

//! planOptimisation: what one optimisation pass does.
struct OptimisationPlan {
    bool useField = false;      //!< E_field is used (FCVT iterations with lambda > 0)
    bool latticeStart = false;  //!< start from the field-aligned lattice (lattice.h)
    int lloydSteps = 0;
    int fcvtIterations = 0;          //!< RemeshParams::fcvtIterations or, on a large run, largeRunFcvtIterations
    double expectedEvaluations = 0;  //!< for the progress percentage
};

//! What the orchestration alone holds: runs named stages in order, timing each and reporting
//! progress (which may cancel: CancelledError), and follows the optimisation's evaluations for
//! the energy history, the progress line and the time limit (TimeLimitReached).
class Pipeline {
public:
    Pipeline(const Progress& progress, const RemeshParams& params) : progress_(progress), params_(params) {}

    template <class Stage>
    void run(const std::string& name, Stage&& stage)
    {
        const auto begin = Clock::now();
        report(name, percent_);
        releaseFreeMemory();   // what the earlier stages freed, back to the system before this one allocates
        adviseNewHugePages();  // the memory the earlier stages added, before this one works on it
        try {
            stage();
        } catch (const TimeLimitReached&) {
            stageTimes.push_back({name, secondsSince(begin)});  // cut short, still timed
            throw;
        }
        stageTimes.push_back({name, secondsSince(begin)});
    }

    void report(const std::string& stage, double percent);

    //! The phase the next evaluations belong to; the CVT and FCVT phases start their best anew.
    void enterPhase(Phase phase);
    Phase phase() const { return phase_; }
    //! Called at every energy evaluation (`evaluations` of the current energy so far).
    void onEvaluation(const EnergyValue& value, int evaluations, const OptimisationPlan& plan);

    const Clock::time_point start = Clock::now();
    std::vector<StageTime> stageTimes;        //!< RemeshResult::stageTimes
    std::vector<EnergyRecord> energyHistory;  //!< one entry per accepted step, over every pass
    int evaluations = 0;                      //!< over every pass
    int reseedCalls = 0;                      //!< seeds the re-seeding of emptied cells, over every pass

private:
    const Progress& progress_;
    const RemeshParams& params_;
    double percent_ = 0;
    Phase phase_ = Phase::Sampling;
    double best_ = HUGE_VAL;             //!< lowest E_tot of the current phase
    Phase stepPhase_ = Phase::Sampling;  //!< the phase whose steps steps_ counts
    int steps_ = 0;
};

//! prepareSurface: the clean (repaired) input in the working frame (§5).
struct PreparedSurface {
    TriMesh surface;
    std::vector<int> cleanIndex;  //!< input vertex -> surface vertex (-1: removed)
    Normalisation frame;
    RepairReport repair;
    std::vector<std::string> warnings;  //!< the input check's, the repair's, the holes closed
    std::vector<std::string> notes;
};

//! chooseOptimisationSurface: the surface the optimisation runs on, the input or its coarser copy.
struct OptimisationSurface {
    const TriMesh* input = nullptr;  //!< the prepared surface
    bool simplified = false;
    SimplifyResult coarse;
    FeatureLines features;                              //!< on the optimisation surface
    std::unique_ptr<const ClosestPointTree> inputTree;  //!< the prepared surface's, when built early
    std::vector<int> optIndex;                          //!< input vertex -> optimisation surface vertex (-1: none)
    TopologySummary inputTopology;
    std::vector<Segment> border;  //!< the optimisation surface's own border edges
    const TriMesh& mesh() const { return simplified ? coarse.mesh : *input; }
};

//! computeFieldStage: the 6-RoSy field on the optimisation surface.
struct FieldStage {
    DirectionField field;
    FieldHierarchyLevels hierarchy;          //!< for the lattice start (the first pass from it consumes it)
    std::vector<Singularity> singularities;  //!< in input units
};

//! What one optimisation pass runs with besides the run's fixed inputs (PassContext): the
//! thin-part passes change these.
struct PassInput {
    std::vector<double> rho;  //!< CVT density per face of the optimisation surface (eq. 1), empty = uniform
    int sampleCount = 0;
    bool sideAwareCells = false;  //!< RvdOptions::seedNormals: a sample owns nothing of a wall's far side
};

//! The fixed inputs of every optimisation pass.
struct PassContext {
    const TriMesh& input;
    const OptimisationSurface& surface;
    const Normalisation& frame;
    const FieldStage& field;
    const RemeshParams& params;
    Pipeline& pipeline;
    //! The optimisation surface's closest-point tree: built beside the first pass's energy.
    std::unique_ptr<const ClosestPointTree>& tree;
    FieldHierarchyLevels& hierarchy;  //!< FieldStage::hierarchy, consumed by the first lattice start
};

//! placeSamples: the initial samples.
struct InitialSamples {
    std::vector<Vec3> seeds;
    std::unique_ptr<LatticeReport> lattice;  //!< when they are the lattice's (spacing in input units)
};

//! optimiseSamples: the optimised samples and where they ended up.
struct OptimisedSamples {
    std::vector<Vec3> seeds;
    std::vector<SampleConstraint> constraints;  //!< per sample: free, or held on the border or a feature
    std::vector<std::string> warnings;          //!< the solver's, the time limit's, the re-seeded samples
};

//! extractMesh: the restricted Delaunay triangulation of the samples.
struct ExtractedMesh {
    TriMesh mesh;
    std::vector<VertexRole> roles;      //!< per output vertex
    std::vector<int> vertexFaceHints;   //!< per output vertex, the face of its closest point
    std::vector<std::string> warnings;  //!< samples in no triangle, debris dropped, ...
};

//! optimiseAndExtract: one pass from its density and sample count to a mesh.
struct PassResult {
    ExtractedMesh extracted;
    std::vector<std::string> warnings;  //!< the optimisation's, then the extraction's
    int fcvtIterations = 0;             //!< the FCVT budget this pass used
    std::unique_ptr<LatticeReport> lattice;
    std::unique_ptr<EnergyFunction> energy;  //!< the pass's energy (its field frames serve the output)
};

//! The input checked (and repaired, RemeshParams::repair), centred and scaled (working_frame.h),
//! its small holes closed (hole_filling.h).
PreparedSurface prepareSurface(const TriMesh& input, const RemeshParams& params, int sampleCount, Pipeline& pipeline);
//! Sharp edges by dihedral angle and the user's feature edges (feature_lines.h), with a warning
//! in `warnings` for user edges that are no edges of the mesh. Sharp edges on strips narrower than
//! params.narrowFeatureStripShare edge lengths are left out (feature_strips.h), said in `notes`.
FeatureLines findFeatureLines(const PreparedSurface& prepared, const RemeshParams& params, std::vector<std::string>& warnings,
                              std::vector<std::string>& notes);
//! The surface the optimisation runs on: a coarser copy (simplify.h) when the input has many
//! more faces than RemeshParams::optimisationFacesPerSample per sample; also the input's topology.
OptimisationSurface chooseOptimisationSurface(const PreparedSurface& prepared, FeatureLines features, const RemeshParams& params,
                                              int sampleCount, Pipeline& pipeline);
//! Adaptive density (density.h): μ per vertex, normalised to an area-weighted mean of 1, ρ = μ²
//! per face of the optimisation surface; empty: uniform.
std::vector<double> chooseDensity(const OptimisationSurface& surface, const RemeshParams& params);
//! What a pass with density `rho` and `sampleCount` samples does: its start and schedule.
OptimisationPlan planOptimisation(const OptimisationSurface& surface, const std::vector<double>& rho, int sampleCount,
                                  const RemeshParams& params);
//! The 6-RoSy field (§4.1) on the optimisation surface, when `plan` uses E_field.
FieldStage computeFieldStage(const TriMesh& input, const OptimisationSurface& surface, const Normalisation& frame,
                             const OptimisationPlan& plan, const RemeshParams& params, Pipeline& pipeline);
//! The initial samples: the field-aligned lattice, random ones (density `pass.rho`), or the caller's.
InitialSamples placeSamples(const PassContext& context, const OptimisationPlan& plan, const PassInput& pass);
//! §5's schedule on `energy`: Lloyd steps, L-BFGS on E_CVT, the border and feature samples held,
//! L-BFGS on E_CVT + λ E_field; a time limit keeps the best samples so far.
OptimisedSamples optimiseSamples(const PassContext& context, const OptimisationPlan& plan, EnergyFunction& energy,
                                 std::vector<Vec3> seeds);
//! The restricted Delaunay triangulation of the samples (rdt.h): the output mesh.
ExtractedMesh extractMesh(const PassContext& context, EnergyFunction& energy, const OptimisedSamples& samples, int sampleCount);
//! One pass: its plan, its energy (E_CVT + λ E_field), placeSamples, optimiseSamples, extractMesh.
PassResult optimiseAndExtract(const PassContext& context, const PassInput& pass);

//! remeshThinPartsAgain: the pass kept, and what the thin-part passes did.
struct ThinPartsOutcome {
    PassResult pass;
    PassInput input;  //!< the kept pass's density and sample count
    RemeshResult::ThinParts report;
    std::string warning;  //!< set when a later pass was kept: how many vertices it added, and why
};
//! Thin parts: when the first pass's topology (genus, boundary loops, components) differs
//! from the input's, the density is raised where the surface is thinner than the edge length
//! (thin_parts.h) and the samples are placed, optimised and triangulated again; the pass nearest
//! the input's topology is kept. Not with RemeshParams::exactCount or initial samples.
ThinPartsOutcome remeshThinPartsAgain(PassResult first, const PassInput& firstInput, const PassContext& context);

//! keepTopology: the mesh with the shells whose topology the RDT lost remeshed locally.
struct TopologyKept {
    ExtractedMesh extracted;
    RemeshResult::LocalShells report;
    std::string warning;  //!< set when shells were remeshed locally: how many, why, the vertices there
};
//! Topology first: each connected component (shell) of the optimisation surface whose output
//! pieces are not one piece with the shell's genus and boundary loops, within reach of all of
//! it and merged with no other, is remeshed by local operations on the surface (local_remesh.h)
//! at the pass's density (`pass`) or the thin parts' if finer. Not with
//! RemeshParams::exactCount or initial samples.
TopologyKept keepTopology(ExtractedMesh extracted, const PassInput& pass, const PassContext& context);

//! Whether the run uses E_field (FCVT iterations with lambda > 0), and so computes the field.
bool usesField(const RemeshParams& params);
//! What the valence stage runs on: the optimisation surface, its tree, features, field, border.
ValenceSurface valenceSurface(const PassContext& context);

//! §4.4 (valence.h): flips, collapses, splits towards valence 6, then a relaxation.
struct ValencedMesh {
    TriMesh mesh;
    ValenceStats stats;
};
ValencedMesh optimiseValence(ExtractedMesh extracted, const PassContext& context);
//! From the coarse copy back onto the input surface (`inputTree`: the prepared surface's): each
//! vertex of `mesh` to its closest input point, but for the vertices of faces the move would
//! turn into slivers (kProjectionSliverDegrees), which stay on the coarse copy.
std::vector<Vec3> projectOnInput(const TriMesh& mesh, const ClosestPointTree& inputTree, Pipeline& pipeline);

//! measure: Table 2's figures, d_RMS / d_H against the input, the topology check.
struct Measurement {
    QualityMetrics metrics;
    TopologySummary outputTopology;
    std::vector<std::string> warnings;
};
Measurement measure(const TriMesh& mesh, const OptimisationSurface& surface, const ClosestPointTree& tree,
                    const RemeshParams& params, Pipeline& pipeline);

//! returnToInputFrame: the output in the input's coordinates (float ones when
//! RemeshParams::outputInFloat), checked that they can hold its edge length.
struct OutputInInputFrame {
    TriMesh mesh;
    QualityMetrics metrics;  //!< the shape figures of the mesh returned where its coordinates collapsed
    std::vector<std::string> warnings;
};
OutputInInputFrame returnToInputFrame(TriMesh mesh, const Normalisation& frame, const RemeshParams& params,
                                      const QualityMetrics& metrics);

}  // namespace fieldcvt
