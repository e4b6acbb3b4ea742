#include "remesh_stages.h"

#include "boundary.h"
#include "density.h"
#include "errors.h"
#include "hole_filling.h"
#include "lattice.h"
#include "mesh_check.h"
#include "metrics.h"
#include "optimize.h"
#include "rdt.h"
#include "repair.h"
#include "sampling.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <sstream>

namespace fieldcvt {

namespace {

// Corners at least 2 apart at the working scale (about two edge lengths): closer fixed samples
// make slivers and pull border samples off the holes of jagged outlines.
constexpr double kCornerSpacing = 2.0;

// The user's feature edges, from input vertex indices to the cleaned surface's.
std::vector<std::array<int, 2>> featureEdgesOnSurface(const std::vector<std::array<int, 2>>& edges,
                                                      const std::vector<int>& cleanIndex)
{
    std::vector<std::array<int, 2>> mapped;
    for (const auto& [a, b] : edges) {
        if (a < 0 || b < 0 || size_t(a) >= cleanIndex.size() || size_t(b) >= cleanIndex.size())
            throw InvalidInputError("feature edge (" + std::to_string(a) + ", " + std::to_string(b) +
                                    ") names a vertex the input does not have");
        if (cleanIndex[size_t(a)] >= 0 && cleanIndex[size_t(b)] >= 0 && cleanIndex[size_t(a)] != cleanIndex[size_t(b)])
            mapped.push_back({cleanIndex[size_t(a)], cleanIndex[size_t(b)]});
    }
    return mapped;
}

VertexRole roleOf(SampleConstraint c)
{
    switch (c) {
    case SampleConstraint::Border: return VertexRole::Boundary;
    case SampleConstraint::Feature: return VertexRole::Feature;
    case SampleConstraint::Corner: return VertexRole::Corner;
    case SampleConstraint::Free: break;
    }
    return VertexRole::Free;
}

// `first` on the calling thread and `second` on another one at the same time (when `together`
// and there are threads; else one after the other), for two serial jobs that do not depend on
// each other. An exception of either is rethrown once both are done (first's if both throw).
template <class First, class Second>
void sideBySide(bool together, First&& first, Second&& second)
{
    std::exception_ptr failures[2];
#pragma omp parallel num_threads(2) if (together && omp_get_max_threads() > 1)
    {
        const int thread = omp_get_thread_num();
        const bool alone = omp_get_num_threads() == 1;
        try {
            if (thread == 0) first();
        } catch (...) {
            failures[0] = std::current_exception();
        }
        try {
            if (thread == 1 || (alone && !failures[0])) second();
        } catch (...) {
            failures[1] = std::current_exception();
        }
    }
    for (const std::exception_ptr& failure : failures)
        if (failure) std::rethrow_exception(failure);
}

// Called at every energy evaluation: the energy history, the progress line and the time limit.
void onEvaluation(RemeshRun& run, const EnergyValue& value)
{
    // One history entry per accepted step: L-BFGS's line search only moves on after an
    // evaluation that lowers E_tot, and every Lloyd step counts.
    const bool accepted = run.phase == Phase::Lloyd || value.total < run.best;
    if (accepted) {
        run.best = std::min(run.best, value.total);
        run.result.energyHistory.push_back({phaseName(run.phase), value.cvt, value.field});
    }
    const double fraction = std::min(1.0, run.energy->evaluations() / run.expectedEvaluations);
    const RemeshParams& p = run.params;
    const int budget = run.phase == Phase::Lloyd  ? run.lloydSteps
                       : run.phase == Phase::Cvt  ? p.cvtIterations
                       : run.phase == Phase::Fcvt ? run.fcvtIterations
                                                  : 0;
    if (run.phase != run.stepPhase) run.stepPhase = run.phase, run.steps = 0;
    run.steps += accepted;
    const std::string name = phaseName(run.phase);
    run.pipeline.report(
        budget > 0 ? name + " " + std::to_string(std::min(run.steps, budget)) + "/" + std::to_string(budget) : name,
        5 + 85 * fraction);
    if (p.timeLimitSeconds > 0 && secondsSince(run.start) > p.timeLimitSeconds) throw TimeLimitReached();
}

void lbfgs(RemeshRun& run, int iterations)
{
    OptimizeStats stats = minimizeLbfgs(*run.energy, run.seeds, LbfgsParams{iterations});
    run.result.warnings.insert(run.result.warnings.end(), stats.warnings.begin(), stats.warnings.end());
}

// A seed whose cell emptied during L-BFGS (a neighbour passed over it) has no gradient and would
// be lost in the RDT: it starts again elsewhere. Returns how many did.
int reseedEmpty(RemeshRun& run)
{
    const int moved = reseedEmptyCells(*run.energy, run.optSurface(), run.seeds, run.params.seed + 7919u * ++run.reseedCalls);
    run.reseededSamples += moved;
    return moved;
}

//! Far from the origin the coordinates are coarse (doubles at 1e15 are 0.125 apart): the output,
//! computed in the working frame, may collapse when taken back. Says so in a warning (the
//! offset, the resolution, the edge length, what collapsed) and measures the quality figures
//! on the mesh as returned, so the summary and the report describe the file written.
void checkOutputPrecision(RemeshResult& result, bool inFloat)
{
    TriMesh& mesh = result.mesh;
    if (mesh.faces.empty()) return;
    double offset = 0;
    for (const Vec3& p : mesh.vertices) offset = std::max(offset, p.cwiseAbs().maxCoeff());
    // The spacing of representable coordinates at the largest one.
    const double resolution =
        inFloat ? double(std::nextafter(float(offset), HUGE_VALF) - float(offset)) : std::nextafter(offset, HUGE_VAL) - offset;
    // An edge of 256 grid steps still gives angles within about half a degree. Every face has
    // an edge of at least its share of the area's square root: most meshes stop here, unsorted.
    const double area = surfaceArea(mesh);
    if (!(resolution > 0) || std::sqrt(area / double(mesh.faceCount())) > 1024 * resolution) return;
    const double meanEdge = meanEdgeLength(mesh);
    if (!(meanEdge < 256 * resolution)) return;
    std::vector<Vec3> sorted = mesh.vertices;
    std::sort(sorted.begin(), sorted.end(), [](const Vec3& a, const Vec3& b) {
        return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
    });
    int coincident = 0;
    for (size_t i = 1; i < sorted.size(); ++i) coincident += sorted[i] == sorted[i - 1];
    int zeroArea = 0;
    for (const Face& f : mesh.faces) {
        int exponent = 0;
        zeroArea += (scaledCross(mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]], exponent).array() == 0.0).all();
    }
    char text[400];
    std::snprintf(text, sizeof text,
                  "the coordinates are too coarse for this edge length: %s %.3g from the origin are %.3g apart, against a "
                  "mean edge of %.3g; the output has %d zero-area faces and %d coincident vertices (move the model "
                  "nearer the origin, or use a longer edge)",
                  inFloat ? "floats" : "doubles", offset, resolution, meanEdge, zeroArea, coincident);
    result.warnings.push_back(text);
    // The figures of the mesh as returned: measured about one of its vertices (a subtraction of
    // nearby values, exact), where the collapsed faces show as they are.
    TriMesh centred = mesh;
    const Vec3 centre = mesh.vertices[mesh.faces[0][0]];
    for (Vec3& p : centred.vertices) p -= centre;
    const QualityMetrics quality = computeQuality(centred);
    const double dRms = result.metrics.dRms, dH = result.metrics.dH, dBoundary = result.metrics.dBoundary;
    result.metrics = quality;
    result.metrics.dRms = dRms;
    result.metrics.dH = dH;
    result.metrics.dBoundary = dBoundary;
}

}  // namespace

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

const char* phaseName(Phase phase)
{
    switch (phase) {
    case Phase::Sampling: return "sampling";
    case Phase::Field: return "field";
    case Phase::Lloyd: return "lloyd";
    case Phase::Cvt: return "cvt";
    case Phase::Features: return "features";
    case Phase::Fcvt: return "fcvt";
    case Phase::Rdt: return "rdt";
    case Phase::Valence: return "valence";
    }
    return "?";
}

void Pipeline::report(const std::string& stage, double percent)
{
    percent_ = percent;
    if (progress_ && !progress_(stage, percent)) throw CancelledError();
}

RemeshRun::RemeshRun(const TriMesh& input_, const RemeshParams& params_, const Progress& progress, RemeshResult& result_)
    : input(input_),
      params(params_),
      result(result_),
      pipeline(progress, result_),
      start(Clock::now()),
      sampleCount(params_.initialSamples.empty() ? params_.vertexCount : static_cast<int>(params_.initialSamples.size()))
{
}

namespace {

void closeHoles(RemeshRun& run)
{
    const double under = run.params.closeHolesUnder;
    if (!(under > 0)) return;
    const HoleFillReport holes = closeSmallHoles(run.surface, under * kWorkingEdgeLength);
    if (holes.closed == 0) return;
    char text[240];
    // No option named: the CLI's is --keep-holes, the MeshLab filter has none.
    std::snprintf(text, sizeof text, "%d hole%s under %g edge lengths across closed (%.3g %% of the surface's area added)",
                  holes.closed, holes.closed == 1 ? "" : "s", under,
                  100.0 * holes.area / std::max(1e-300, surfaceArea(run.surface) - holes.area));
    run.result.warnings.push_back(text);
    ++run.result.inputWarnings;
}

}  // namespace

void prepareSurface(RemeshRun& run)
{
    run.pipeline.run("prepare", [&] {
        InputReport report;
        RepairParams repairParams = run.params.repairParams;
        repairParams.vertexBudget = run.sampleCount;
        run.surface = run.params.repair ? repairAndPrepare(run.input, repairParams, run.result.repair, report)
                                        : prepareInput(run.input, report);
        run.cleanIndex = report.cleanIndex;
        run.result.warnings.insert(run.result.warnings.end(), report.notes.begin(), report.notes.end());
        run.result.inputWarnings = static_cast<int>(run.result.warnings.size());
        run.result.notes = report.information;
        run.frame = workingFrame(run.surface, run.sampleCount);
        for (Vec3& p : run.surface.vertices) p = run.frame.toWork(p);
        closeHoles(run);
    });
}

void findFeatureLines(RemeshRun& run)
{
    // On the input: their vertices stay in the coarse surface.
    int ignored = 0;
    const std::vector<std::array<int, 2>> userEdges = featureEdgesOnSurface(run.params.featureEdges, run.cleanIndex);
    run.features = detectFeatures(run.surface, run.params.featureAngleDegrees, userEdges, &ignored, kCornerSpacing);
    if (ignored > 0)
        run.result.warnings.push_back(std::to_string(ignored) +
                                      " of the given feature edges are not edges of the mesh and were ignored");
}

void chooseOptimisationSurface(RemeshRun& run)
{
    const RemeshParams& p = run.params;
    const int coarseFaces = optimisationFaceTarget(p, run.sampleCount);
    run.simplified = coarseFaces > 0 && double(run.surface.faceCount()) > 1.5 * double(coarseFaces);
    if (run.simplified) {
        run.pipeline.run("simplify", [&] {
            SimplifyParams simplify;
            simplify.targetFaces = coarseFaces;
            // 5 % of the output's edge length (about 1.07 at the working scale): the coarse
            // surface is within that of the input, far inside the output's own sag.
            simplify.maxError = 0.05;
            simplify.locked.assign(run.surface.vertices.size(), 0);
            for (const auto& [a, b] : run.features.edges) simplify.locked[a] = simplify.locked[b] = 1;
            // Both are serial: the input's closest-point tree (for projectOnInput) and its
            // topology (for the report) are computed on the other thread meanwhile. The tree not
            // for inputs over kMaxEarlyTreeFaces faces, whose tree would add to the optimisation's
            // peak memory (about 110 bytes a face).
            constexpr int kMaxEarlyTreeFaces = 500000;
            // Nor beside a simplification in blocks, which has every thread.
            const bool early =
                run.surface.faceCount() <= kMaxEarlyTreeFaces && simplifyBlockCount(run.surface.faceCount(), simplify) == 1;
            // The simplification on the main thread (whose heap keeps the CLI's padding).
            sideBySide(
                early, [&] { run.coarse = simplifyMesh(run.surface, simplify); },
                [&] {
                    if (early) run.inputTree = std::make_unique<ClosestPointTree>(run.surface);
                    run.result.inputTopology = computeTopology(run.surface);  // for the report: meanwhile too
                });
            // The same feature edges (both ends kept, so still edges), corners found again.
            std::vector<std::array<int, 2>> edges;
            for (const auto& [a, b] : run.features.edges)
                edges.push_back({run.coarse.coarseVertex[a], run.coarse.coarseVertex[b]});
            run.features = detectFeatures(run.coarse.mesh, 0, edges, nullptr, kCornerSpacing);
        });
    }
    if (!run.simplified) run.result.inputTopology = computeTopology(run.surface);
    run.result.optimisationFaces = run.optSurface().faceCount();
    run.optIndex = run.cleanIndex;
    if (run.simplified)
        for (int& v : run.optIndex) v = v >= 0 ? run.coarse.coarseVertex[v] : -1;
}

void chooseDensity(RemeshRun& run)
{
    // μ normalised to an area-weighted mean of 1 keeps the scale (mean cell area 1, sampleCount
    // samples) right on average; cells are then ~1/μ in area. ρ = μ² per face enters eq. 1.
    const RemeshParams& p = run.params;
    const bool curvature = p.density == DensitySource::Curvature && p.gradation > 0;
    if (!curvature && p.density != DensitySource::PerVertex) return;
    const TriMesh& surface = run.optSurface();
    std::vector<double> mu = curvature ? curvatureDensity(surface, p.gradation, kWorkingEdgeLength)
                                       : densityOnSurface(p.vertexDensity, run.optIndex, surface.vertexCount());
    normaliseDensity(surface, mu);
    run.rho = faceDensity(surface, mu);
}

void setUpEnergy(RemeshRun& run)
{
    const RemeshParams& p = run.params;
    const TriMesh& surface = run.optSurface();
    // The field is needed when E_field is used (in the FCVT iterations only: measuring it during
    // the CVT iterations would cost a closest-point query per sample and evaluation).
    run.useField = p.fcvtIterations > 0 && p.lambda > 0;
    run.border = boundarySegments(surface);
    const bool constrained = !run.border.empty() || !run.features.empty();
    // The start (RemeshParams::latticeStart). A constant density is the uniform one. Not with
    // feature lines yet: lattice points near a crease left fandisk's creases cut.
    const std::vector<double>& rho = run.rho;
    const bool uniform = std::all_of(rho.begin(), rho.end(), [&](double r) { return r == rho.front(); });
    run.latticeStart = p.initialSamples.empty() && p.latticeStart && run.useField && uniform && run.features.segments.empty();
    run.lloydSteps = run.latticeStart ? p.latticeLloydIterations : p.lloydIterations;
    const bool largeRun = run.latticeStart && run.sampleCount >= p.largeRunSamples;
    run.fcvtIterations = largeRun && p.fcvtIterations > 0 ? p.largeRunFcvtIterations : p.fcvtIterations;
    run.result.fcvtIterations = run.fcvtIterations;
    run.expectedEvaluations =
        run.lloydSteps + 1.1 * (p.cvtIterations + run.fcvtIterations) + (constrained ? p.boundaryIterations : 0) + 2;
    // The energy's diagram structures and the surface's closest-point tree are independent and
    // serial: built side by side.
    const bool treeBuilt = run.tree != nullptr;  // by the first pass (remeshThinPartsAgain runs this again)
    sideBySide(
        !treeBuilt, [&] { run.energy = std::make_unique<EnergyFunction>(surface, rho); },
        [&] {
            if (!treeBuilt) run.tree = std::make_unique<ClosestPointTree>(surface);
        });
    run.energy->onEvaluation = [&run](const EnergyValue& value) { onEvaluation(run, value); };
    run.energy->setSideAware(run.sideAwareCells ? run.tree.get() : nullptr);
}

void computeFieldStage(RemeshRun& run)
{
    if (!run.useField) return;
    const RemeshParams& p = run.params;
    const TriMesh& surface = run.optSurface();
    run.pipeline.run("field", [&] {
        run.phase = Phase::Field;
        run.pipeline.report(phaseName(run.phase), 2);
        if (p.fieldSource == FieldSource::User) {
            std::vector<Vec3> vectors(surface.vertices.size(), Vec3::Zero());
            if (p.userDirections.size() != run.input.vertices.size())
                throw InvalidInputError("the user field has " + std::to_string(p.userDirections.size()) + " vectors for " +
                                        std::to_string(run.input.vertices.size()) + " vertices");
            for (size_t v = 0; v < run.input.vertices.size(); ++v)
                if (run.optIndex[v] >= 0) vectors[run.optIndex[v]] = p.userDirections[v];
            run.field = fieldFromVectors(surface, vectors, p.seed);
        } else {
            FieldParams fieldParams;
            fieldParams.source = p.fieldSource;
            fieldParams.seed = p.seed;
            // The field follows the same creases the samples are snapped to (§5).
            if (p.featureAngleDegrees > 0) fieldParams.sharpAngle = p.featureAngleDegrees;
            run.field = computeField(surface, fieldParams, nullptr, run.latticeStart ? &run.fieldHierarchy : nullptr);
        }
        if (p.computeSingularities) run.result.singularities = findSingularities(surface, run.field);
        for (Singularity& s : run.result.singularities) s.position = run.frame.fromWork(s.position);
    });
}

void placeSamples(RemeshRun& run)
{
    const RemeshParams& p = run.params;
    run.pipeline.run("sampling", [&] {
        if (run.latticeStart) {
            // The field-aligned lattice (lattice.h) on the optimisation surface, put on it.
            LatticeParams lattice;
            lattice.seed = p.seed;
            std::vector<int> faces;  // each point's face: the hint of its closest-point query
            run.seeds = latticeSamples(run.optSurface(), run.field, p.vertexCount, lattice, &run.result.lattice,
                                       &run.fieldHierarchy, &faces);
            std::vector<Vec3>& seeds = run.seeds;
            const ClosestPointTree& tree = *run.tree;
#pragma omp parallel for schedule(static)
            for (int i = 0; i < static_cast<int>(seeds.size()); ++i) seeds[i] = tree.closest(seeds[i], faces[i]).point;
            run.result.lattice.spacing /= run.frame.scale;  // reported in input units
            run.fieldHierarchy = FieldHierarchyLevels{};
        } else if (p.initialSamples.empty()) {
            run.seeds = sampleSurface(run.optSurface(), run.sampleCount, p.seed, run.rho);  // uniform when rho is empty
        }
        if (p.initialSamples.empty()) {
            // A small part kept on its own (RepairParams::farComponentEdges) may have drawn fewer
            // samples than make a triangle of it.
            const ClosestPointTree& tree = *run.tree;
            topUpSmallComponents(
                run.optSurface(), [&tree](const Vec3& x) { return tree.closest(x).face; },
                static_cast<int>(p.repairParams.minFarComponentFloor), p.seed, run.seeds);
        } else {
            run.seeds.clear();
            for (const Vec3& x : p.initialSamples) run.seeds.push_back(run.frame.toWork(x));
        }
    });
}

void optimiseSamples(RemeshRun& run)
{
    run.optimisationWarnings = run.result.warnings.size();
    run.reseededSamples = 0;  // counted per pass (remeshThinPartsAgain runs a second one)
    const RemeshParams& p = run.params;
    EnergyFunction& energy = *run.energy;
    try {
        run.pipeline.run("lloyd", [&] {
            run.phase = Phase::Lloyd;
            lloydRelaxation(energy, run.optSurface(), run.seeds, run.lloydSteps, p.seed);
        });
        run.pipeline.run("cvt", [&] {
            run.phase = Phase::Cvt;
            run.best = std::numeric_limits<double>::infinity();
            lbfgs(run, p.cvtIterations);
            if (p.cvtIterations > 0) reseedEmpty(run);
        });
        // Second stage of §5: samples on the border and on feature lines, held there from now on.
        run.pipeline.run("features", [&] {
            run.phase = Phase::Features;
            run.sampleRoles = relaxConstrainedSamples(energy, run.seeds, run.optSurface(), run.border, run.features,
                                                      p.boundaryIterations, run.fcvtIterations > 0);
            std::vector<char> frozen(run.seeds.size(), 0);
            for (size_t i = 0; i < run.seeds.size(); ++i) frozen[i] = run.sampleRoles[i] != SampleConstraint::Free;
            energy.setFrozen(std::move(frozen));
        });
        if (run.fcvtIterations > 0) {
            run.pipeline.run("fcvt", [&] {
                run.phase = Phase::Fcvt;
                run.best = std::numeric_limits<double>::infinity();
                energy.setField(run.useField ? &run.field : nullptr, run.tree.get(), p.lambda);
                lbfgs(run, run.fcvtIterations);
                if (reseedEmpty(run) > 0) lbfgs(run, std::min(10, run.fcvtIterations));  // to find their place
            });
        }
    } catch (const TimeLimitReached&) {
        std::ostringstream message;
        message << "time limit of " << p.timeLimitSeconds << " s reached during " << phaseName(run.phase)
                << ": the output is made from the best samples so far";
        run.result.warnings.push_back(message.str());
    }
    if (run.reseededSamples > 0)
        run.result.warnings.push_back(std::to_string(run.reseededSamples) +
                                      " samples whose cells had emptied during the optimisation were re-seeded");
}

void extractMesh(RemeshRun& run)
{
    run.pipeline.run("rdt", [&] {
        run.phase = Phase::Rdt;
        run.pipeline.report(phaseName(run.phase), 90);
        RvdOptions options;
        options.triangles = true;
        const RvdResult& rvd = run.energy->diagram(run.seeds, options);
        // On cell pieces (multi-nerve RDT); the samples' frame faces are hints for their closest points.
        const std::vector<int>&hints = run.energy->lastFrameFaces(), none;
        RdtResult rdt = extractRdt(run.seeds, rvd, *run.tree, hints.size() == run.seeds.size() ? hints : none);
        dropDebris(rdt, kDebrisFaces, kDebrisReachEdges * kWorkingEdgeLength);
        run.result.warnings.insert(run.result.warnings.end(), rdt.warnings.begin(), rdt.warnings.end());
        run.result.mesh = std::move(rdt.mesh);
        if (run.result.mesh.faces.empty())
            throw SolverError(std::to_string(run.sampleCount) + " vertices are too few for this surface: they form no " +
                              "triangle on it (it is thinner than the edge length everywhere); use more vertices");
        run.roles.clear();
        for (int seed : rdt.seedOfVertex)
            run.roles.push_back(size_t(seed) < run.sampleRoles.size() ? roleOf(run.sampleRoles[size_t(seed)]) : VertexRole::Free);
        run.vertexFaceHints = std::move(rdt.faceOfVertex);
    });
}

void optimiseValence(RemeshRun& run)
{
    if (!run.params.valenceOptimization) return;
    run.pipeline.run("valence", [&] {
        run.phase = Phase::Valence;
        run.pipeline.report(phaseName(run.phase), 92);
        const ValenceSurface on{run.optSurface(), *run.tree, run.features.segments, run.useField ? &run.field : nullptr,
                                run.border};
        run.result.valence = optimizeValence(run.result.mesh, run.roles, on, run.params.valence, run.vertexFaceHints);
    });
}

void projectOnInput(RemeshRun& run)
{
    if (!run.simplified) return;
    // The coarse surface is within SimplifyParams::maxError of the input. Border and feature
    // vertices lie on input edges, which both surfaces have.
    run.pipeline.run("project", [&] {
        if (!run.inputTree) run.inputTree = std::make_unique<ClosestPointTree>(run.surface);
        const ClosestPointTree& inputTree = *run.inputTree;
        std::vector<Vec3>& vertices = run.result.mesh.vertices;
#pragma omp parallel for schedule(static)
        for (int v = 0; v < static_cast<int>(vertices.size()); ++v) vertices[v] = inputTree.closest(vertices[v]).point;
    });
}

void attachOutputField(RemeshRun& run)
{
    if (run.useField) {
        const FieldFrames frames = run.energy->framesAt(run.result.mesh.vertices);
        run.result.outputNormals = frames.normals;
        run.result.outputDirections = frames.directions;
    }
    run.result.evaluations = run.energy->evaluations();
}

void measure(RemeshRun& run)
{
    // In the working frame (the figures are angles and fractions of the diagonal, the same in
    // every frame), where a model at 1e300 does not overflow them.
    RemeshResult& result = run.result;
    run.pipeline.run("metrics", [&] {
        run.pipeline.report("metrics", 95);
        result.metrics = computeQuality(result.mesh);
        if (run.params.computeDistances && !result.mesh.faces.empty()) {
            const TriMesh& reference = run.surface;
            // A fixed budget (RemeshParams::distanceSamples), or dense enough for a Hausdorff
            // figure at the meshes' resolution, capped for big ones.
            const int samples = run.params.distanceSamples > 0
                                    ? run.params.distanceSamples
                                    : std::clamp(20 * (result.mesh.faceCount() + reference.faceCount()), 20000, 200000);
            // The input's tree is there already (projectOnInput's; unsimplified, the
            // optimisation's, on the same surface): 20-30 ms of a bunny's 0.14 s not spent again.
            const ClosestPointTree* referenceTree = run.inputTree     ? run.inputTree.get()
                                                    : !run.simplified ? run.tree.get()
                                                                      : nullptr;
            const DistanceMetrics d = computeDistance(result.mesh, reference, samples, referenceTree);
            result.metrics.dRms = d.rms;
            result.metrics.dH = d.hausdorff;
            if (!run.border.empty()) result.metrics.dBoundary = boundaryDistance(result.mesh, reference);
        }
        result.outputTopology = computeTopology(result.mesh);
        const TopologySummary& in = result.inputTopology;
        const TopologySummary& out = result.outputTopology;
        if (!out.manifold()) result.warnings.push_back("the output is not manifold");
        if (out.genus != in.genus || out.boundaryLoops != in.boundaryLoops || out.components != in.components)
            result.warnings.push_back("topology not recovered at this vertex count: input genus " + std::to_string(in.genus) +
                                      ", " + std::to_string(in.boundaryLoops) + " boundary loops, " +
                                      std::to_string(in.components) + " components; output genus " + std::to_string(out.genus) +
                                      ", " + std::to_string(out.boundaryLoops) + " boundary loops, " +
                                      std::to_string(out.components) + " components (use more vertices)");
    });
}

void returnToInputFrame(RemeshRun& run)
{
    for (Vec3& p : run.result.mesh.vertices) p = run.frame.fromWork(p);
    if (run.params.outputInFloat)
        for (Vec3& p : run.result.mesh.vertices) p = p.cast<float>().cast<double>();
    checkOutputPrecision(run.result, run.params.outputInFloat);
}

}  // namespace fieldcvt
