#pragma once
// The stages of remesh() (remesh.h), in the order it runs them, over one explicit state. Internal
// to the core: remesh() is the public entry point. Each stage reads what the earlier ones left in
// RemeshRun and adds its own part; the comments at each field say which stage sets it.
#include "closest_point.h"
#include "energy.h"
#include "errors.h"
#include "feature_lines.h"
#include "field.h"
#include "field_hierarchy.h"
#include "huge_pages.h"
#include "remesh.h"
#include "simplify.h"
#include "valence.h"
#include "working_frame.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace fieldcvt {

using Clock = std::chrono::steady_clock;

//! At the working scale the mean cell has area 1: an equilateral triangle mesh with one vertex
//! per unit of area has edges sqrt(2 / sqrt(3)) long.
inline const double kWorkingEdgeLength = std::sqrt(2.0 / std::sqrt(3.0));
//! The RDT's debris (rdt.h, dropDebris): pieces of at most this many faces, within this many edge
//! lengths of the rest of the output (issue 32 item 3 asks every point of a part within 2).
constexpr int kDebrisFaces = 8;
constexpr double kDebrisReachEdges = 2;

double secondsSince(Clock::time_point start);

//! Where the optimisation is, for the progress line, the energy history and the time limit.
enum class Phase { Sampling, Field, Lloyd, Cvt, Features, Fcvt, Rdt, Valence };
//! "sampling", "field", "lloyd", "cvt", "features", "fcvt", "rdt", "valence".
const char* phaseName(Phase phase);

//! Runs named stages in order, timing each (RemeshResult::stageTimes) and reporting progress
//! (which may cancel: CancelledError).
class Pipeline {
public:
    Pipeline(const Progress& progress, RemeshResult& result) : progress_(progress), result_(result) {}

    template <class Stage>
    void run(const std::string& name, Stage&& stage)
    {
        const auto start = Clock::now();
        report(name, percent_);
        releaseFreeMemory();   // what the earlier stages freed, back to the system before this one allocates
        adviseNewHugePages();  // the memory the earlier stages added, before this one works on it
        try {
            stage();
        } catch (const TimeLimitReached&) {
            result_.stageTimes.push_back({name, secondsSince(start)});  // cut short, still timed
            throw;
        }
        result_.stageTimes.push_back({name, secondsSince(start)});
    }

    void report(const std::string& stage, double percent);

private:
    const Progress& progress_;
    RemeshResult& result_;
    double percent_ = 0;
};

//! The state of one remesh() call, filled stage by stage.
struct RemeshRun {
    RemeshRun(const TriMesh& input, const RemeshParams& params, const Progress& progress, RemeshResult& result);

    const TriMesh& input;
    const RemeshParams& params;
    RemeshResult& result;
    Pipeline pipeline;
    const Clock::time_point start;
    //! The output's vertex budget: vertexCount, or the initial samples; chooseDensity raises it
    //! for thin parts (RemeshParams::exactCount).
    int sampleCount;

    // prepareSurface: the clean (repaired) input in the working frame (§5).
    TriMesh surface;
    std::vector<int> cleanIndex;  //!< input vertex -> surface vertex (-1: removed)
    Normalisation frame;
    // findFeatureLines, then chooseOptimisationSurface (on the coarse copy when there is one).
    FeatureLines features;
    // chooseOptimisationSurface: the input, or its coarser copy (simplify.h).
    bool simplified = false;
    SimplifyResult coarse;
    std::unique_ptr<const ClosestPointTree> inputTree;  //!< the surface's, for projectOnInput
    std::vector<int> optIndex;                          //!< input vertex -> optimisation surface vertex (-1: none)
    const TriMesh& optSurface() const { return simplified ? coarse.mesh : surface; }
    // chooseDensity: the CVT density per face of the optimisation surface (eq. 1), empty = uniform.
    std::vector<double> rho;
    // setUpEnergy: the plan of the optimisation and its energy.
    bool useField = false;        //!< E_field is used (FCVT iterations with lambda > 0)
    std::vector<Segment> border;  //!< the optimisation surface's own border edges
    bool latticeStart = false;    //!< start from the field-aligned lattice (lattice.h)
    int lloydSteps = 0;
    int fcvtIterations = 0;          //!< RemeshParams::fcvtIterations or, on a large run, largeRunFcvtIterations
    double expectedEvaluations = 0;  //!< for the progress percentage
    std::unique_ptr<EnergyFunction> energy;
    std::unique_ptr<const ClosestPointTree> tree;  //!< the optimisation surface's
    //! Side-aware cells (RvdOptions::seedNormals): a pass of remeshThinPartsAgain.
    bool sideAwareCells = false;
    // computeFieldStage.
    DirectionField field;
    FieldHierarchyLevels fieldHierarchy;  //!< the field's, for the lattice start (freed after it)
    // placeSamples, optimiseSamples.
    Phase phase = Phase::Sampling;
    double best = std::numeric_limits<double>::infinity();  //!< lowest E_tot of the current phase
    Phase stepPhase = Phase::Sampling;                      //!< the phase whose steps `steps` counts
    int steps = 0;
    std::vector<Vec3> seeds;
    std::vector<SampleConstraint> sampleRoles;
    int reseedCalls = 0, reseededSamples = 0;
    size_t optimisationWarnings = 0;  //!< RemeshResult::warnings' size as optimiseSamples started
    // extractMesh, for optimiseValence.
    std::vector<VertexRole> roles;     //!< per output vertex
    std::vector<int> vertexFaceHints;  //!< per output vertex, the face of its closest point (a query hint)
};

//! The input checked (and repaired, RemeshParams::repair), centred and scaled (working_frame.h).
void prepareSurface(RemeshRun& run);
//! Sharp edges by dihedral angle and the user's feature edges (feature_lines.h).
void findFeatureLines(RemeshRun& run);
//! The surface the optimisation runs on: a coarser copy when the input has many more faces
//! than RemeshParams::optimisationFacesPerSample per sample; also the input's topology.
void chooseOptimisationSurface(RemeshRun& run);
//! Adaptive density (density.h): μ per vertex, normalised to an area-weighted mean of 1; ρ = μ².
void chooseDensity(RemeshRun& run);
//! What the optimisation will do, its energy (E_CVT + λ E_field) and the closest-point tree.
void setUpEnergy(RemeshRun& run);
//! The 6-RoSy field (§4.1) on the optimisation surface, when E_field is used.
void computeFieldStage(RemeshRun& run);
//! The initial samples: the field-aligned lattice, random ones, or the caller's.
void placeSamples(RemeshRun& run);
//! §5's schedule: Lloyd steps, L-BFGS on E_CVT, the border and feature samples held, L-BFGS on
//! E_CVT + λ E_field; a time limit keeps the best samples so far.
void optimiseSamples(RemeshRun& run);
//! The restricted Delaunay triangulation of the samples: the output mesh.
void extractMesh(RemeshRun& run);
//! Issue 32, item 2: when the RDT's topology (genus, boundary loops, components) differs from
//! the input's, the density is raised where the surface is thinner than the edge length
//! (thin_parts.h), sampleCount with it, and the samples are placed, optimised and triangulated
//! again; the second mesh is kept when its topology is nearer the input's, with a warning and
//! RemeshResult::thinParts. Not with RemeshParams::exactCount or initial samples.
void remeshThinPartsAgain(RemeshRun& run);
//! §4.4: flips, collapses, splits towards valence 6, then a relaxation.
void optimiseValence(RemeshRun& run);
//! From the coarse copy back onto the input surface.
void projectOnInput(RemeshRun& run);
//! The field's normal and direction at the output's vertices (written with a PLY output).
void attachOutputField(RemeshRun& run);
//! Table 2's figures, d_RMS / d_H against the input, the topology check.
void measure(RemeshRun& run);
//! The output in the input's coordinates (float ones when RemeshParams::outputInFloat), and the
//! check that they can hold its edge length.
void returnToInputFrame(RemeshRun& run);

}  // namespace fieldcvt
