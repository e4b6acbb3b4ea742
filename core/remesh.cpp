#include "remesh.h"

#include "errors.h"
#include "remesh_stages.h"
#include "thread_budget.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fieldcvt {

namespace {

//! The OpenMP thread count of a run, restored after it: the caller's process (MeshLab's) keeps
//! its own setting.
class ThreadCountScope {
public:
    explicit ThreadCountScope(int threads) : restore_(omp_get_max_threads()) { omp_set_num_threads(threads); }
    ~ThreadCountScope() { omp_set_num_threads(restore_); }
    ThreadCountScope(const ThreadCountScope&) = delete;
    ThreadCountScope& operator=(const ThreadCountScope&) = delete;

private:
    int restore_;
};

//! Above this share over the count asked for, and this many vertices, the output's vertex count
//! is reported as raised: the RDT's count varies by a percent or two (a few vertices at 100)
//! with the samples' places.
constexpr double kMoreVerticesShare = 0.03;
constexpr int kMoreVerticesFloor = 10;

//! Whenever the output has more vertices than asked for: how many more, and why.
std::string moreVerticesWarning(int vertices, int asked, const RemeshResult& result, const RemeshParams& params)
{
    if (!params.initialSamples.empty() || vertices - asked <= std::max<double>(kMoreVerticesFloor, asked * kMoreVerticesShare))
        return {};
    std::string why;
    if (result.thinParts.added > 0) why += std::to_string(result.thinParts.added) + " samples added on thin parts";
    if (result.localShells.shells > 0) {
        if (!why.empty()) why += "; ";
        why += std::to_string(result.localShells.shells) + " shells remeshed by local operations to keep their topology (" +
               std::to_string(result.localShells.vertices) + " vertices there instead of " +
               std::to_string(result.localShells.rdtVertices) + ")";
    }
    const int explained = asked + result.thinParts.added + result.localShells.vertices - result.localShells.rdtVertices;
    if (vertices > explained + asked * kMoreVerticesShare) {
        if (!why.empty()) why += "; ";
        why += "cells cut in several pieces by thin walls, each piece a vertex";
    }
    return std::to_string(vertices - asked) + " vertices added beyond the " + std::to_string(asked) + " asked for (" +
           std::to_string(vertices) + " in all) to keep the input's topology: " + why +
           " (--exact-count keeps the count and may lose the topology)";
}

}  // namespace

std::string vertexCountRange()
{
    return "between " + std::to_string(kMinVertexCount) + " and " + std::to_string(kMaxVertexCount);
}

VertexCountFromLength vertexCountForLength(double area, double length, const std::string& parameter)
{
    char text[200];
    if (!(length > 0) || !std::isfinite(length)) {
        std::snprintf(text, sizeof text, "%s must be > 0, got %g", parameter.c_str(), length);
        throw InvalidInputError(text);
    }
    const double wanted = 2.0 * area / (std::sqrt(3.0) * length * length);
    std::snprintf(text, sizeof text, "%s %g on a surface of area %g gives %.3g vertices", parameter.c_str(), length, area,
                  wanted);
    if (!std::isfinite(wanted) || wanted > kMaxVertexCount)
        throw InvalidInputError(text + std::string("; the vertex count must be ") + vertexCountRange() +
                                ": choose a longer edge");
    VertexCountFromLength out;
    out.vertexCount = static_cast<int>(std::lround(wanted));
    if (out.vertexCount < kMinVertexCount) {
        out.vertexCount = kMinVertexCount;
        out.warning = text + std::string(", fewer than the minimum: remeshed to ") + std::to_string(kMinVertexCount) +
                      " vertices (choose a shorter edge for more)";
    }
    return out;
}

void checkRemeshParams(const RemeshParams& p, const ParameterNames& names)
{
    auto fail = [](const std::string& name, const std::string& range, const std::string& got) {
        throw InvalidInputError(name + " must be " + range + ", got " + got);
    };
    auto number = [](double x) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", x);
        return std::string(text);
    };
    if (p.initialSamples.empty()) {
        if (p.vertexCount < kMinVertexCount || p.vertexCount > kMaxVertexCount)
            fail(names.vertexCount, vertexCountRange(), std::to_string(p.vertexCount));
    } else {
        if (p.initialSamples.size() < 4)
            throw InvalidInputError("at least 4 initial samples are needed (got " + std::to_string(p.initialSamples.size()) +
                                    ")");
        for (const Vec3& x : p.initialSamples)
            if (!x.allFinite()) throw InvalidInputError("an initial sample has a NaN or infinite coordinate");
    }
    if (!std::isfinite(p.lambda) || p.lambda < 0) fail(names.lambda, "a finite number >= 0", number(p.lambda));
    if (p.lloydIterations < 0) fail(names.lloydIterations, ">= 0", std::to_string(p.lloydIterations));
    if (p.latticeLloydIterations < 0) fail(names.lloydIterations, ">= 0", std::to_string(p.latticeLloydIterations));
    if (p.cvtIterations < 0) fail(names.cvtIterations, ">= 0", std::to_string(p.cvtIterations));
    if (p.fcvtIterations < 0) fail(names.fcvtIterations, ">= 0", std::to_string(p.fcvtIterations));
    if (p.largeRunFcvtIterations < 0) fail(names.fcvtIterations, ">= 0", std::to_string(p.largeRunFcvtIterations));
    if (p.largeRunSamples < 0) throw InvalidInputError("large-run sample count must be >= 0");
    if (p.threads < 0 || p.threads > kMaxThreads)
        fail(names.threads, "between 0 and " + std::to_string(kMaxThreads) + " (0 = all cores)", std::to_string(p.threads));
    if (!(p.timeLimitSeconds >= 0) || !std::isfinite(p.timeLimitSeconds))
        fail(names.timeLimit, "a finite number of seconds >= 0 (0 = none)", number(p.timeLimitSeconds));
    if (!(p.featureAngleDegrees >= 0 && p.featureAngleDegrees <= 180))
        fail(names.featureAngle, "0..180 degrees (0 = off)", number(p.featureAngleDegrees));
    if (!std::isfinite(p.gradation) || p.gradation < 0) fail(names.gradation, "a finite number >= 0", number(p.gradation));
    // Settings no front end offers: the core's words.
    if (p.boundaryIterations < 0) throw InvalidInputError("border iteration count must be >= 0");
    if (p.fieldSmoothingIterations < 0 || p.latticeIterations < 0)
        throw InvalidInputError("field and lattice smoothing iteration counts must be >= 0");
    if (p.latticePasses < 1) throw InvalidInputError("lattice pass count must be >= 1");
    if (p.optimisationFacesPerSample < 0) throw InvalidInputError("optimisation faces per sample must be >= 0");
    if (p.optimisationFacesCap < 0) throw InvalidInputError("optimisation face cap must be >= 0");
    if (p.simplifyBlockFaces < 0) throw InvalidInputError("simplification block size must be >= 0");
    if (p.distanceSamples < 0) throw InvalidInputError("distance sample count must be >= 0");
    if (!(p.narrowFeatureStripShare >= 0) || !std::isfinite(p.narrowFeatureStripShare))
        throw InvalidInputError("the narrow feature strip share must be a finite number >= 0");
    if (p.valence.maxRounds < 0 || p.valence.localSmoothing < 0 || p.valence.relaxIterations < 0 || p.valence.sagRepairRounds < 0)
        throw InvalidInputError("valence optimisation step counts must be >= 0");
    if (p.valence.borderWeight < 1) throw InvalidInputError("valence optimisation border weight must be >= 1");
}

std::string fieldMeshDescription(const RemeshResult& result)
{
    const int faces = result.optimisationFaces;
    if (faces < result.inputTopology.faces)
        return "the optimisation surface, a simplified copy of the input (" + std::to_string(faces) + " faces)";
    return "the input (" + std::to_string(faces) + " faces)";
}

RemeshResult remesh(const TriMesh& input, const RemeshParams& params, const Progress& progress)
{
    checkRemeshParams(params);
    const int threadCount = threadsForThisMachine(params.threads);
    const ThreadCountScope threads(threadCount);
    const HugePageHeap heap;  // and adviseNewHugePages() before each stage (Pipeline::run)
    Pipeline pipeline(progress, params);
    RemeshResult result;
    result.threads = threadCount;
    const int sampleCount = params.initialSamples.empty() ? params.vertexCount : static_cast<int>(params.initialSamples.size());

    PreparedSurface prepared = prepareSurface(input, params, sampleCount, pipeline);
    result.warnings = prepared.warnings;
    result.inputWarnings = static_cast<int>(result.warnings.size());
    result.notes = prepared.notes;
    result.repair = std::move(prepared.repair);
    FeatureLines features = findFeatureLines(prepared, params, result.warnings, result.notes);
    OptimisationSurface surface = chooseOptimisationSurface(prepared, std::move(features), params, sampleCount, pipeline);
    result.inputTopology = surface.inputTopology;
    result.optimisationFaces = surface.mesh().faceCount();
    const PassInput firstPass{chooseDensity(surface, params), sampleCount, false};
    const OptimisationPlan plan = planOptimisation(surface, firstPass.rho, sampleCount, params);
    FieldStage field = computeFieldStage(input, surface, prepared.frame, plan, params, pipeline);
    result.singularities = field.singularities;

    std::unique_ptr<const ClosestPointTree> tree;  // the optimisation surface's, built by the first pass
    const PassContext context{input, surface, prepared.frame, field, params, pipeline, tree, field.hierarchy};
    ThinPartsOutcome kept = remeshThinPartsAgain(optimiseAndExtract(context, firstPass), firstPass, context);
    PassResult& pass = kept.pass;
    pass.energy->releaseDiagram();  // the mesh is extracted: the diagram's memory is free for the next stages
    if (!kept.warning.empty()) result.warnings.push_back(kept.warning);
    result.warnings.insert(result.warnings.end(), pass.warnings.begin(), pass.warnings.end());
    result.thinParts = kept.report;
    result.fcvtIterations = pass.fcvtIterations;
    if (pass.lattice) result.lattice = *pass.lattice;

    TopologyKept topology = keepTopology(std::move(pass.extracted), kept.input, context);
    if (!topology.warning.empty()) result.warnings.push_back(topology.warning);
    result.localShells = std::move(topology.report);

    ValencedMesh valenced = optimiseValence(std::move(topology.extracted), context);
    result.valence = valenced.stats;
    TriMesh mesh = std::move(valenced.mesh);
    if (surface.simplified) {
        if (!surface.inputTree) surface.inputTree = std::make_unique<ClosestPointTree>(prepared.surface);
        mesh.vertices = projectOnInput(mesh, *surface.inputTree, pipeline);
    }
    if (plan.useField) {
        // The field at the output's vertices (written with a PLY output).
        FieldFrames frames = pass.energy->framesAt(mesh.vertices);
        result.outputNormals = std::move(frames.normals);
        result.outputDirections = std::move(frames.directions);
    }
    const std::string moreVertices = moreVerticesWarning(mesh.vertexCount(), sampleCount, result, params);
    if (!moreVertices.empty()) result.warnings.push_back(moreVertices);
    Measurement measured = measure(mesh, surface, *tree, params, pipeline);
    result.outputTopology = measured.outputTopology;
    result.warnings.insert(result.warnings.end(), measured.warnings.begin(), measured.warnings.end());
    OutputInInputFrame output = returnToInputFrame(std::move(mesh), prepared.frame, params, measured.metrics);
    result.mesh = std::move(output.mesh);
    result.metrics = output.metrics;
    result.warnings.insert(result.warnings.end(), output.warnings.begin(), output.warnings.end());

    pipeline.report("done", 100);
    result.evaluations = pipeline.evaluations;
    result.energyHistory = std::move(pipeline.energyHistory);
    result.stageTimes = std::move(pipeline.stageTimes);
    result.totalSeconds = secondsSince(pipeline.start);
    return result;
}

}  // namespace fieldcvt
