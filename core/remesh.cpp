#include "remesh.h"

#include "closest_point.h"
#include "energy.h"
#include "field.h"
#include "errors.h"
#include "mesh_check.h"
#include "optimize.h"
#include "rdt.h"
#include "sampling.h"
#include "boundary.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

namespace fieldcvt {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

void validate(const RemeshParams& p)
{
    if (p.vertexCount < 4) throw InvalidInputError("vertex count must be at least 4 (got " + std::to_string(p.vertexCount) + ")");
    if (p.vertexCount > 50000000) throw InvalidInputError("vertex count " + std::to_string(p.vertexCount) + " is too large (at most 50000000)");
    if (!std::isfinite(p.lambda) || p.lambda < 0) throw InvalidInputError("lambda must be a finite number >= 0");
    if (p.lloydIterations < 0 || p.cvtIterations < 0 || p.fcvtIterations < 0 || p.boundaryIterations < 0)
        throw InvalidInputError("iteration counts must be >= 0");
    if (p.threads < 0) throw InvalidInputError("thread count must be >= 0");
    if (!(p.timeLimitSeconds >= 0) || !std::isfinite(p.timeLimitSeconds)) throw InvalidInputError("time limit must be >= 0 seconds");
}

// The working frame (§5): centred, and scaled so that the mean restricted Voronoi cell has
// area 1. Every energy then has the same magnitude whatever the model's units and resolution.
struct Normalisation {
    Vec3 centre = Vec3::Zero();
    double scale = 1;
    Vec3 toWork(const Vec3& p) const { return (p - centre) * scale; }
    Vec3 fromWork(const Vec3& p) const { return p / scale + centre; }
};

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

    TriMesh surface;
    std::vector<int> cleanIndex;  // input vertex -> surface vertex
    Normalisation frame;
    pipeline.run("prepare", [&] {
        InputReport report;
        surface = prepareInput(input, report);
        cleanIndex = report.cleanIndex;
        result.warnings.insert(result.warnings.end(), report.notes.begin(), report.notes.end());
        result.inputTopology = computeTopology(surface);
        const double area = surfaceArea(surface);
        if (!(area > 0) || !std::isfinite(area)) throw InvalidInputError("the surface has no area");
        Vec3 lo = surface.vertices[0], hi = surface.vertices[0];
        for (const Vec3& p : surface.vertices) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
        frame.centre = 0.5 * (lo + hi);
        frame.scale = std::sqrt(params.vertexCount / area);
        for (Vec3& p : surface.vertices) p = frame.toWork(p);
    });

    // The field is needed when E_field is used (in the FCVT iterations only: measuring it during
    // the CVT iterations would cost a closest-point query per sample and evaluation).
    const bool useField = params.fcvtIterations > 0 && params.lambda > 0;
    const std::vector<Segment> border = boundarySegments(surface);
    const double expectedEvaluations = params.lloydIterations + 1.1 * (params.cvtIterations + params.fcvtIterations) +
                                       (border.empty() ? 0 : params.boundaryIterations) + 2;
    EnergyFunction energy(surface);
    ClosestPointTree tree(surface);
    DirectionField field;
    std::string stage = "sampling";
    double best = std::numeric_limits<double>::infinity();
    energy.onEvaluation = [&](const EnergyValue& value) {
        // One history entry per accepted step: L-BFGS's line search only moves on after an
        // evaluation that lowers E_tot, and every Lloyd step counts.
        if (stage == "lloyd" || value.total < best) {
            best = std::min(best, value.total);
            result.energyHistory.push_back({stage, value.cvt, value.field});
        }
        const double fraction = std::min(1.0, energy.evaluations() / expectedEvaluations);
        pipeline.report(stage, 5 + 85 * fraction);
        if (params.timeLimitSeconds > 0 && secondsSince(start) > params.timeLimitSeconds) throw TimeLimitReached();
    };

    if (useField) {
        pipeline.run("field", [&] {
            stage = "field";
            pipeline.report(stage, 2);
            if (params.fieldSource == FieldSource::User) {
                std::vector<Vec3> vectors(surface.vertices.size(), Vec3::Zero());
                if (params.userDirections.size() != input.vertices.size())
                    throw InvalidInputError("the user field has " + std::to_string(params.userDirections.size()) +
                                            " vectors for " + std::to_string(input.vertices.size()) + " vertices");
                for (size_t v = 0; v < input.vertices.size(); ++v)
                    if (cleanIndex[v] >= 0) vectors[cleanIndex[v]] = params.userDirections[v];
                field = fieldFromVectors(surface, vectors, params.seed);
            } else {
                FieldParams fieldParams;
                fieldParams.source = params.fieldSource;
                fieldParams.seed = params.seed;
                field = computeField(surface, fieldParams);
            }
            result.singularities = findSingularities(surface, field);
            for (Singularity& s : result.singularities) s.position = frame.fromWork(s.position);
        });
    }

    std::vector<Vec3> seeds;
    pipeline.run("sampling", [&] { seeds = sampleSurfaceUniform(surface, params.vertexCount, params.seed); });
    auto lbfgs = [&](int iterations) {
        OptimizeStats stats = minimizeLbfgs(energy, seeds, LbfgsParams{iterations});
        result.warnings.insert(result.warnings.end(), stats.warnings.begin(), stats.warnings.end());
    };
    try {
        pipeline.run("lloyd", [&] {
            stage = "lloyd";
            lloydRelaxation(energy, surface, seeds, params.lloydIterations, params.seed);
        });
        pipeline.run("cvt", [&] {
            stage = "cvt";
            best = std::numeric_limits<double>::infinity();
            lbfgs(params.cvtIterations);
        });
        pipeline.run("boundary", [&] {
            stage = "boundary";
            energy.setFrozen(relaxBoundarySamples(energy, seeds, border, params.boundaryIterations));
        });
        if (params.fcvtIterations > 0) {
            pipeline.run("fcvt", [&] {
                stage = "fcvt";
                best = std::numeric_limits<double>::infinity();
                energy.setField(useField ? &field : nullptr, &tree, params.lambda);
                lbfgs(params.fcvtIterations);
            });
        }
    } catch (const TimeLimitReached&) {
        std::ostringstream message;
        message << "time limit of " << params.timeLimitSeconds << " s reached during " << stage
                << ": the output is made from the best samples so far";
        result.warnings.push_back(message.str());
    }

    pipeline.run("rdt", [&] {
        stage = "rdt";
        pipeline.report(stage, 90);
        RvdOptions options;
        options.triangles = true;
        const RvdResult& rvd = energy.diagram(seeds, options);
        RdtResult rdt = extractRdt(seeds, rvd.triangles, tree);
        result.warnings.insert(result.warnings.end(), rdt.warnings.begin(), rdt.warnings.end());
        result.mesh = std::move(rdt.mesh);
        if (result.mesh.faces.empty())
            throw SolverError("no restricted Delaunay triangle survives with " + std::to_string(params.vertexCount) +
                              " samples on this surface: use more vertices");
        if (useField) {
            const FieldFrames frames = energy.framesAt(result.mesh.vertices);
            result.outputNormals = frames.normals;
            result.outputDirections = frames.directions;
        }
        for (Vec3& p : result.mesh.vertices) p = frame.fromWork(p);
    });
    result.evaluations = energy.evaluations();

    pipeline.run("metrics", [&] {
        pipeline.report("metrics", 95);
        result.metrics = computeQuality(result.mesh);
        if (params.computeDistances && !result.mesh.faces.empty()) {
            TriMesh reference = surface;
            for (Vec3& p : reference.vertices) p = frame.fromWork(p);
            // Dense enough for a Hausdorff figure at the meshes' resolution, capped for big ones.
            const int samples = std::clamp(20 * (result.mesh.faceCount() + reference.faceCount()), 20000, 200000);
            const DistanceMetrics d = computeDistance(result.mesh, reference, samples);
            result.metrics.dRms = d.rms;
            result.metrics.dH = d.hausdorff;
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
    pipeline.report("done", 100);
    result.totalSeconds = secondsSince(start);
    return result;
}

}  // namespace fieldcvt
