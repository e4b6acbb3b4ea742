#include "remesh.h"

#include "closest_point.h"
#include "energy.h"
#include "field.h"
#include "field_hierarchy.h"
#include "density.h"
#include "errors.h"
#include "mesh_check.h"
#include "optimize.h"
#include "rdt.h"
#include "sampling.h"
#include "simplify.h"
#include "boundary.h"
#include "feature_lines.h"
#include "lattice.h"
#include "valence.h"
#include "working_frame.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <memory>
#include <sstream>

namespace fieldcvt {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

void validate(const RemeshParams& p)
{
    if (p.initialSamples.empty()) {
        if (p.vertexCount < kMinVertexCount || p.vertexCount > kMaxVertexCount)
            throw InvalidInputError("the vertex count must be " + vertexCountRange() + ", got " + std::to_string(p.vertexCount));
    } else {
        if (p.initialSamples.size() < 4)
            throw InvalidInputError("at least 4 initial samples are needed (got " + std::to_string(p.initialSamples.size()) + ")");
        for (const Vec3& x : p.initialSamples)
            if (!x.allFinite()) throw InvalidInputError("an initial sample has a NaN or infinite coordinate");
    }
    if (!std::isfinite(p.lambda) || p.lambda < 0) throw InvalidInputError("lambda must be a finite number >= 0");
    if (p.lloydIterations < 0 || p.latticeLloydIterations < 0 || p.cvtIterations < 0 || p.fcvtIterations < 0 || p.boundaryIterations < 0)
        throw InvalidInputError("iteration counts must be >= 0");
    if (p.threads < 0) throw InvalidInputError("thread count must be >= 0");
    if (p.optimisationFacesPerSample < 0) throw InvalidInputError("optimisation faces per sample must be >= 0");
    if (p.distanceSamples < 0) throw InvalidInputError("distance sample count must be >= 0");
    if (!(p.timeLimitSeconds >= 0) || !std::isfinite(p.timeLimitSeconds)) throw InvalidInputError("time limit must be >= 0 seconds");
    if (!(p.featureAngleDegrees >= 0 && p.featureAngleDegrees <= 180))
        throw InvalidInputError("feature angle must be between 0 and 180 degrees (0 = no sharp features)");
    if (!std::isfinite(p.gradation) || p.gradation < 0) throw InvalidInputError("gradation must be a finite number >= 0");
    if (p.valence.maxRounds < 0 || p.valence.localSmoothing < 0 || p.valence.relaxIterations < 0)
        throw InvalidInputError("valence optimisation step counts must be >= 0");
    if (p.valence.borderWeight < 1) throw InvalidInputError("valence optimisation border weight must be >= 1");
}

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

// Runs the stages in order, timing each and reporting overall progress.
class Pipeline {
public:
    Pipeline(const Progress& progress, RemeshResult& result) : progress_(progress), result_(result)
    {
    }

    template <class Stage>
    void run(const std::string& name, Stage&& stage)
    {
        const auto start = Clock::now();
        report(name, percent_);
        try {
            stage();
        } catch (const TimeLimitReached&) {
            result_.stageTimes.push_back({name, secondsSince(start)});  // cut short, still timed
            throw;
        }
        result_.stageTimes.push_back({name, secondsSince(start)});
    }

    void report(const std::string& stage, double percent)
    {
        percent_ = percent;
        if (progress_ && !progress_(stage, percent)) throw CancelledError();
    }

private:
    const Progress& progress_;
    RemeshResult& result_;
    double percent_ = 0;
};

}  // namespace

namespace {

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
    const double resolution = inFloat ? double(std::nextafter(float(offset), HUGE_VALF) - float(offset))
                                      : std::nextafter(offset, HUGE_VAL) - offset;
    // An edge of 256 grid steps still gives angles within about half a degree. Every face has
    // an edge of at least its share of the area's square root: most meshes stop here, unsorted.
    const double area = surfaceArea(mesh);
    if (!(resolution > 0) || std::sqrt(area / double(mesh.faceCount())) > 1024 * resolution) return;
    const double meanEdge = meanEdgeLength(mesh);
    if (!(meanEdge < 256 * resolution)) return;
    std::vector<Vec3> sorted = mesh.vertices;
    std::sort(sorted.begin(), sorted.end(), [](const Vec3& a, const Vec3& b) { return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3); });
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
    // The figures of the mesh as returned: measured about its own centre (a subtraction of
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

std::string vertexCountRange() { return "between " + std::to_string(kMinVertexCount) + " and " + std::to_string(kMaxVertexCount); }

VertexCountFromLength vertexCountForLength(double area, double length, const std::string& parameter)
{
    char text[200];
    if (!(length > 0) || !std::isfinite(length)) {
        std::snprintf(text, sizeof text, "%s must be > 0, got %g", parameter.c_str(), length);
        throw InvalidInputError(text);
    }
    const double wanted = 2.0 * area / (std::sqrt(3.0) * length * length);
    std::snprintf(text, sizeof text, "%s %g on a surface of area %g gives %.3g vertices", parameter.c_str(), length, area, wanted);
    if (!std::isfinite(wanted) || wanted > kMaxVertexCount)
        throw InvalidInputError(text + std::string("; the vertex count must be ") + vertexCountRange() + ": choose a longer edge");
    VertexCountFromLength out;
    out.vertexCount = static_cast<int>(std::lround(wanted));
    if (out.vertexCount < kMinVertexCount) {
        out.vertexCount = kMinVertexCount;
        out.warning = text + std::string(", fewer than the minimum: remeshed to ") + std::to_string(kMinVertexCount) +
                      " vertices (choose a shorter edge for more)";
    }
    return out;
}

RemeshResult remesh(const TriMesh& input, const RemeshParams& params, const Progress& progress)
{
    validate(params);
    const auto start = Clock::now();
    const int previousThreads = omp_get_max_threads();
    struct ThreadGuard {
        int restore;
        ~ThreadGuard() { omp_set_num_threads(restore); }
    } guard{previousThreads};
    if (params.threads > 0) omp_set_num_threads(params.threads);

    RemeshResult result;
    Pipeline pipeline(progress, result);
    const int sampleCount = params.initialSamples.empty() ? params.vertexCount : static_cast<int>(params.initialSamples.size());

    TriMesh surface;
    std::vector<int> cleanIndex;  // input vertex -> surface vertex
    Normalisation frame;
    pipeline.run("prepare", [&] {
        InputReport report;
        RepairParams repairParams = params.repairParams;
        repairParams.vertexBudget = sampleCount;
        surface = params.repair ? repairAndPrepare(input, repairParams, result.repair, report) : prepareInput(input, report);
        cleanIndex = report.cleanIndex;
        result.warnings.insert(result.warnings.end(), report.notes.begin(), report.notes.end());
        frame = workingFrame(surface, sampleCount);
        for (Vec3& p : surface.vertices) p = frame.toWork(p);
    });

    // Feature lines (if asked for) on the input: their vertices stay in the coarse surface.
    int ignored = 0;
    const std::vector<std::array<int, 2>> userFeatureEdges = featureEdgesOnSurface(params.featureEdges, cleanIndex);
    // Corners at least 2 apart at the working scale (about two edge lengths): closer fixed
    // samples make slivers and pull border samples off the holes of jagged outlines (bunny 5000:
    // spacing 0.6 gave θ_min 24° and a border 0.9 % away, 2 gives 29.6° and 0.43 %).
    constexpr double kCornerSpacing = 2.0;
    FeatureLines features = detectFeatures(surface, params.featureAngleDegrees, userFeatureEdges, &ignored, kCornerSpacing);
    if (ignored > 0)
        result.warnings.push_back(std::to_string(ignored) + " of the given feature edges are not edges of the mesh and were ignored");

    // The surface the optimisation runs on: the input, or its coarser copy (simplify.h), whose
    // vertices are input vertices (`toCoarse` maps them; -1 = removed).
    SimplifyResult coarse;
    std::unique_ptr<const ClosestPointTree> inputTree;  // the input's, for "project"
    const bool simplified = params.optimisationFacesPerSample > 0 &&
                            double(surface.faceCount()) > 1.5 * params.optimisationFacesPerSample * double(sampleCount);
    if (simplified) {
        pipeline.run("simplify", [&] {
            SimplifyParams simplify;
            simplify.targetFaces = params.optimisationFacesPerSample * sampleCount;
            // 5 % of the output's edge length (about 1.07 at the working scale): the coarse
            // surface is within that of the input, far inside the output's own sag.
            simplify.maxError = 0.05;
            simplify.locked.assign(surface.vertices.size(), 0);
            for (const auto& [a, b] : features.edges) simplify.locked[a] = simplify.locked[b] = 1;
            // Both are serial: the input's closest-point tree (for "project") and its topology
            // (for the report) are computed on the other thread meanwhile (bunny 5000: 0.045 and
            // 0.012 s). The tree not for inputs over kMaxEarlyTreeFaces faces, whose tree would
            // add to the optimisation's peak memory (about 110 bytes a face).
            constexpr int kMaxEarlyTreeFaces = 500000;
            const bool early = surface.faceCount() <= kMaxEarlyTreeFaces;
            // The simplification on the main thread (whose heap keeps the CLI's padding).
            sideBySide(
                early, [&] { coarse = simplifyMesh(surface, simplify); },
                [&] {
                    if (early) inputTree = std::make_unique<ClosestPointTree>(surface);
                    result.inputTopology = computeTopology(surface);  // for the report: meanwhile too
                });
            // The same feature edges (both ends kept, so still edges), corners found again.
            std::vector<std::array<int, 2>> edges;
            for (const auto& [a, b] : features.edges) edges.push_back({coarse.coarseVertex[a], coarse.coarseVertex[b]});
            features = detectFeatures(coarse.mesh, 0, edges, nullptr, kCornerSpacing);
        });
    }
    if (!simplified) result.inputTopology = computeTopology(surface);
    const TriMesh& optSurface = simplified ? coarse.mesh : surface;
    result.optimisationFaces = optSurface.faceCount();
    // Input vertex -> vertex of the optimisation surface (-1: none).
    std::vector<int> optIndex = cleanIndex;
    if (simplified)
        for (int& v : optIndex) v = v >= 0 ? coarse.coarseVertex[v] : -1;

    std::vector<double> rho;  // CVT density per face of the optimisation surface (eq. 1), empty = uniform
    // Adaptive density (density.h): μ per vertex, normalised to an area-weighted mean of 1, so
    // the scale above (mean cell area 1, sampleCount samples) stays right on average; cells are
    // then ~1/μ in area. ρ = μ² per face enters eq. 1.
    const bool curvature = params.density == DensitySource::Curvature && params.gradation > 0;
    if (curvature || params.density == DensitySource::PerVertex) {
        // Uniform target edge length at the working scale: unit-area cells of a regular
        // triangulation, sqrt(2 / sqrt(3)).
        const double edgeLength = std::sqrt(2 / std::sqrt(3.0));
        std::vector<double> mu = curvature ? curvatureDensity(optSurface, params.gradation, edgeLength)
                                           : densityOnSurface(params.vertexDensity, optIndex, optSurface.vertexCount());
        normaliseDensity(optSurface, mu);
        rho = faceDensity(optSurface, mu);
    }

    // The field is needed when E_field is used (in the FCVT iterations only: measuring it during
    // the CVT iterations would cost a closest-point query per sample and evaluation).
    const bool useField = params.fcvtIterations > 0 && params.lambda > 0;
    const std::vector<Segment> border = boundarySegments(optSurface);  // the input's own border edges
    const bool constrained = !border.empty() || !features.empty();
    // The start (RemeshParams::latticeStart). A constant density (e.g. a per-vertex density of 1
    // everywhere) is the uniform one. Not with feature lines yet: lattice points near a crease
    // left fandisk's creases cut (1.7 % of the diagonal off, Features.FandiskKeepsItsCreasesAndCorners).
    const bool uniform = std::all_of(rho.begin(), rho.end(), [&](double r) { return r == rho.front(); });
    const bool latticeStart =
        params.initialSamples.empty() && params.latticeStart && useField && uniform && features.segments.empty();
    const int lloydSteps = latticeStart ? params.latticeLloydIterations : params.lloydIterations;
    const double expectedEvaluations = lloydSteps + 1.1 * (params.cvtIterations + params.fcvtIterations) +
                                       (constrained ? params.boundaryIterations : 0) + 2;
    // The energy's diagram structures and the surface's closest-point tree are independent and
    // serial: built side by side (bunny 5000: ~6 and ~5 ms).
    std::unique_ptr<EnergyFunction> energyBuilt;
    std::unique_ptr<const ClosestPointTree> treeBuilt;
    sideBySide(
        true, [&] { energyBuilt = std::make_unique<EnergyFunction>(optSurface, rho); },
        [&] { treeBuilt = std::make_unique<ClosestPointTree>(optSurface); });
    EnergyFunction& energy = *energyBuilt;
    const ClosestPointTree& tree = *treeBuilt;
    DirectionField field;
    FieldHierarchyLevels fieldHierarchy;  // the field's, for the lattice start (freed after it)
    std::string stage = "sampling";
    double best = std::numeric_limits<double>::infinity();
    std::string stepStage;  // the stage whose steps `steps` counts (shown as "cvt 12/65")
    int steps = 0;
    energy.onEvaluation = [&](const EnergyValue& value) {
        // One history entry per accepted step: L-BFGS's line search only moves on after an
        // evaluation that lowers E_tot, and every Lloyd step counts.
        const bool accepted = stage == "lloyd" || value.total < best;
        if (accepted) {
            best = std::min(best, value.total);
            result.energyHistory.push_back({stage, value.cvt, value.field});
        }
        const double fraction = std::min(1.0, energy.evaluations() / expectedEvaluations);
        const int budget = stage == "lloyd" ? lloydSteps
                         : stage == "cvt"   ? params.cvtIterations
                         : stage == "fcvt"  ? params.fcvtIterations : 0;
        if (stage != stepStage) stepStage = stage, steps = 0;
        steps += accepted;
        pipeline.report(budget > 0 ? stage + " " + std::to_string(std::min(steps, budget)) + "/" + std::to_string(budget) : stage,
                        5 + 85 * fraction);
        if (params.timeLimitSeconds > 0 && secondsSince(start) > params.timeLimitSeconds) throw TimeLimitReached();
    };

    if (useField) {
        pipeline.run("field", [&] {
            stage = "field";
            pipeline.report(stage, 2);
            if (params.fieldSource == FieldSource::User) {
                std::vector<Vec3> vectors(optSurface.vertices.size(), Vec3::Zero());
                if (params.userDirections.size() != input.vertices.size())
                    throw InvalidInputError("the user field has " + std::to_string(params.userDirections.size()) +
                                            " vectors for " + std::to_string(input.vertices.size()) + " vertices");
                for (size_t v = 0; v < input.vertices.size(); ++v)
                    if (optIndex[v] >= 0) vectors[optIndex[v]] = params.userDirections[v];
                field = fieldFromVectors(optSurface, vectors, params.seed);
            } else {
                FieldParams fieldParams;
                fieldParams.source = params.fieldSource;
                fieldParams.seed = params.seed;
                // The field follows the same creases the samples are snapped to (§5).
                if (params.featureAngleDegrees > 0) fieldParams.sharpAngle = params.featureAngleDegrees;
                field = computeField(optSurface, fieldParams, nullptr, latticeStart ? &fieldHierarchy : nullptr);
            }
            if (params.computeSingularities) result.singularities = findSingularities(optSurface, field);
            for (Singularity& s : result.singularities) s.position = frame.fromWork(s.position);
        });
    }

    std::vector<Vec3> seeds;
    std::vector<SampleConstraint> sampleRoles;
    pipeline.run("sampling", [&] {
        if (latticeStart) {
            // The field-aligned lattice (lattice.h) on the optimisation surface, put on it.
            LatticeParams lattice;
            lattice.seed = params.seed;
            std::vector<int> faces;  // each point's face: the hint of its closest-point query
            seeds = latticeSamples(optSurface, field, params.vertexCount, lattice, &result.lattice, &fieldHierarchy, &faces);
#pragma omp parallel for schedule(static)
            for (int i = 0; i < static_cast<int>(seeds.size()); ++i) seeds[i] = tree.closest(seeds[i], faces[i]).point;
            result.lattice.spacing /= frame.scale;  // reported in input units
            fieldHierarchy = FieldHierarchyLevels{};
        } else if (params.initialSamples.empty()) {
            seeds = sampleSurface(optSurface, params.vertexCount, params.seed, rho);  // uniform when rho is empty
        } else {
            seeds.clear();
            for (const Vec3& x : params.initialSamples) seeds.push_back(frame.toWork(x));
        }
    });
    auto lbfgs = [&](int iterations) {
        OptimizeStats stats = minimizeLbfgs(energy, seeds, LbfgsParams{iterations});
        result.warnings.insert(result.warnings.end(), stats.warnings.begin(), stats.warnings.end());
    };
    // A seed whose cell emptied during L-BFGS (a neighbour passed over it) has no gradient and
    // would be lost in the RDT (nef2 at 100 000 vertices: 7): it starts again elsewhere.
    int reseedCalls = 0, reseededSamples = 0;
    auto reseedEmpty = [&] {
        const int moved = reseedEmptyCells(energy, optSurface, seeds, params.seed + 7919u * ++reseedCalls);
        reseededSamples += moved;
        return moved;
    };
    try {
        pipeline.run("lloyd", [&] {
            stage = "lloyd";
            lloydRelaxation(energy, optSurface, seeds, lloydSteps, params.seed);
        });
        pipeline.run("cvt", [&] {
            stage = "cvt";
            best = std::numeric_limits<double>::infinity();
            lbfgs(params.cvtIterations);
            if (params.cvtIterations > 0) reseedEmpty();
        });
        // Second stage of §5: samples on the border and on feature lines, held there from now on.
        pipeline.run("features", [&] {
            stage = "features";
            sampleRoles = relaxConstrainedSamples(energy, seeds, optSurface, border, features, params.boundaryIterations,
                                                  params.fcvtIterations > 0);
            std::vector<char> frozen(seeds.size(), 0);
            for (size_t i = 0; i < seeds.size(); ++i) frozen[i] = sampleRoles[i] != SampleConstraint::Free;
            energy.setFrozen(std::move(frozen));
        });
        if (params.fcvtIterations > 0) {
            pipeline.run("fcvt", [&] {
                stage = "fcvt";
                best = std::numeric_limits<double>::infinity();
                energy.setField(useField ? &field : nullptr, &tree, params.lambda);
                lbfgs(params.fcvtIterations);
                if (reseedEmpty() > 0) lbfgs(std::min(10, params.fcvtIterations));  // to find their place
            });
        }
    } catch (const TimeLimitReached&) {
        std::ostringstream message;
        message << "time limit of " << params.timeLimitSeconds << " s reached during " << stage
                << ": the output is made from the best samples so far";
        result.warnings.push_back(message.str());
    }
    if (reseededSamples > 0)
        result.warnings.push_back(std::to_string(reseededSamples) +
                                  " samples whose cells had emptied during the optimisation were re-seeded");

    std::vector<VertexRole> roles;  // per output vertex, for the valence optimisation
    std::vector<int> vertexFaceHints;  // per output vertex, the face of its closest point (a query hint)
    pipeline.run("rdt", [&] {
        stage = "rdt";
        pipeline.report(stage, 90);
        RvdOptions options;
        options.triangles = true;
        const RvdResult& rvd = energy.diagram(seeds, options);
        // On cell pieces (multi-nerve RDT); the samples' frame faces are hints for their closest points.
        const std::vector<int>& hints = energy.lastFrameFaces(), none;
        RdtResult rdt = extractRdt(seeds, rvd, tree, hints.size() == seeds.size() ? hints : none);
        result.warnings.insert(result.warnings.end(), rdt.warnings.begin(), rdt.warnings.end());
        result.mesh = std::move(rdt.mesh);
        if (result.mesh.faces.empty())
            throw SolverError(std::to_string(sampleCount) + " vertices are too few for this surface: they form no " +
                              "triangle on it (it is thinner than the edge length everywhere); use more vertices");
        for (int seed : rdt.seedOfVertex)
            roles.push_back(size_t(seed) < sampleRoles.size() ? roleOf(sampleRoles[size_t(seed)]) : VertexRole::Free);
        vertexFaceHints = std::move(rdt.faceOfVertex);
    });
    if (params.valenceOptimization) {
        pipeline.run("valence", [&] {
            stage = "valence";
            pipeline.report(stage, 92);
            const ValenceSurface on{optSurface, tree, features.segments, useField ? &field : nullptr, border};
            result.valence = optimizeValence(result.mesh, roles, on, params.valence, vertexFaceHints);
        });
    }
    if (simplified) {
        // Back on the input surface: the coarse one is within SimplifyParams::maxError of it. Border
        // and feature vertices lie on input edges, which both surfaces have.
        pipeline.run("project", [&] {
            if (!inputTree) inputTree = std::make_unique<ClosestPointTree>(surface);
            std::vector<Vec3>& vertices = result.mesh.vertices;
#pragma omp parallel for schedule(static)
            for (int v = 0; v < static_cast<int>(vertices.size()); ++v) vertices[v] = inputTree->closest(vertices[v]).point;
        });
    }
    if (useField) {
        const FieldFrames frames = energy.framesAt(result.mesh.vertices);
        result.outputNormals = frames.normals;
        result.outputDirections = frames.directions;
    }
    result.evaluations = energy.evaluations();

    // Measured in the working frame (the figures are angles and fractions of the diagonal, the
    // same in every frame), where a model at 1e300 does not overflow them.
    pipeline.run("metrics", [&] {
        pipeline.report("metrics", 95);
        result.metrics = computeQuality(result.mesh);
        if (params.computeDistances && !result.mesh.faces.empty()) {
            const TriMesh& reference = surface;
            // A fixed budget (RemeshParams::distanceSamples), or dense enough for a Hausdorff
            // figure at the meshes' resolution, capped for big ones.
            const int samples = params.distanceSamples > 0 ? params.distanceSamples
                                : std::clamp(20 * (result.mesh.faceCount() + reference.faceCount()), 20000, 200000);
            const DistanceMetrics d = computeDistance(result.mesh, reference, samples);
            result.metrics.dRms = d.rms;
            result.metrics.dH = d.hausdorff;
            if (!border.empty()) result.metrics.dBoundary = boundaryDistance(result.mesh, reference);
        }
        result.outputTopology = computeTopology(result.mesh);
        const TopologySummary& in = result.inputTopology;
        const TopologySummary& out = result.outputTopology;
        if (!out.manifold()) result.warnings.push_back("the output is not manifold");
        if (out.genus != in.genus || out.boundaryLoops != in.boundaryLoops || out.components != in.components)
            result.warnings.push_back("topology not recovered at this vertex count: input genus " + std::to_string(in.genus) +
                                      ", " + std::to_string(in.boundaryLoops) + " boundary loops, " + std::to_string(in.components) +
                                      " components; output genus " + std::to_string(out.genus) + ", " +
                                      std::to_string(out.boundaryLoops) + " boundary loops, " + std::to_string(out.components) +
                                      " components (use more vertices)");
    });
    for (Vec3& p : result.mesh.vertices) p = frame.fromWork(p);
    if (params.outputInFloat)
        for (Vec3& p : result.mesh.vertices) p = p.cast<float>().cast<double>();
    checkOutputPrecision(result, params.outputInFloat);
    pipeline.report("done", 100);
    result.totalSeconds = secondsSince(start);
    return result;
}

}  // namespace fieldcvt
