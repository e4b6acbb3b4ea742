#include "remesh_stages.h"

#include "boundary.h"
#include "density.h"
#include "errors.h"
#include "feature_strips.h"
#include "hole_filling.h"
#include "lattice.h"
#include "mesh_check.h"
#include "metrics.h"
#include "optimize.h"
#include "rdt.h"
#include "repair.h"
#include "sampling.h"
#include "side_by_side.h"
#include "triangle_shape.h"

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

//! Far from the origin the coordinates are coarse (doubles at 1e15 are 0.125 apart): the output,
//! computed in the working frame, may collapse when taken back. Says so in a warning (the
//! offset, the resolution, the edge length, what collapsed) and measures the quality figures
//! on the mesh as returned, so the summary and the report describe the file written.
void checkOutputPrecision(const TriMesh& mesh, bool inFloat, QualityMetrics& metrics, std::vector<std::string>& warnings)
{
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
    warnings.push_back(text);
    // The figures of the mesh as returned: measured about one of its vertices (a subtraction of
    // nearby values, exact), where the collapsed faces show as they are.
    TriMesh centred = mesh;
    const Vec3 centre = mesh.vertices[mesh.faces[0][0]];
    for (Vec3& p : centred.vertices) p -= centre;
    const QualityMetrics quality = computeQuality(centred);
    const double dRms = metrics.dRms, dH = metrics.dH, dBoundary = metrics.dBoundary;
    metrics = quality;
    metrics.dRms = dRms;
    metrics.dH = dH;
    metrics.dBoundary = dBoundary;
}

}  // namespace

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

int optimisationFaceTarget(const RemeshParams& params, int sampleCount)
{
    constexpr long long kMinFacesPerSample = 2;
    const long long full = static_cast<long long>(params.optimisationFacesPerSample) * sampleCount;
    const long long floor = std::min(full, kMinFacesPerSample * sampleCount);
    return static_cast<int>(std::max(floor, std::min(full, static_cast<long long>(params.optimisationFacesCap))));
}

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

void Pipeline::enterPhase(Phase phase)
{
    phase_ = phase;
    if (phase == Phase::Cvt || phase == Phase::Fcvt) best_ = HUGE_VAL;
}

void Pipeline::onEvaluation(const EnergyValue& value, int energyEvaluations, const OptimisationPlan& plan)
{
    ++evaluations;
    // One history entry per accepted step: L-BFGS's line search only moves on after an
    // evaluation that lowers E_tot, and every Lloyd step counts.
    const bool accepted = phase_ == Phase::Lloyd || value.total < best_;
    if (accepted) {
        best_ = std::min(best_, value.total);
        energyHistory.push_back({phaseName(phase_), value.cvt, value.field});
    }
    const double fraction = std::min(1.0, energyEvaluations / plan.expectedEvaluations);
    const int budget = phase_ == Phase::Lloyd  ? plan.lloydSteps
                       : phase_ == Phase::Cvt  ? params_.cvtIterations
                       : phase_ == Phase::Fcvt ? plan.fcvtIterations
                                               : 0;
    if (phase_ != stepPhase_) stepPhase_ = phase_, steps_ = 0;
    steps_ += accepted;
    const std::string name = phaseName(phase_);
    report(budget > 0 ? name + " " + std::to_string(std::min(steps_, budget)) + "/" + std::to_string(budget) : name,
           5 + 85 * fraction);
    if (params_.timeLimitSeconds > 0 && secondsSince(start) > params_.timeLimitSeconds) throw TimeLimitReached();
}

namespace {

//! Closes the holes under RemeshParams::closeHolesUnder edge lengths across; a warning counts them.
void closeHoles(PreparedSurface& prepared, const RemeshParams& params)
{
    const double under = params.closeHolesUnder;
    if (!(under > 0)) return;
    const HoleFillReport holes = closeSmallHoles(prepared.surface, under * kWorkingEdgeLength);
    if (holes.closed == 0) return;
    char text[240];
    // No option named: the CLI's is --keep-holes, the MeshLab filter has none.
    std::snprintf(text, sizeof text, "%d hole%s under %g edge lengths across closed (%.3g %% of the surface's area added)",
                  holes.closed, holes.closed == 1 ? "" : "s", under,
                  100.0 * holes.area / std::max(1e-300, surfaceArea(prepared.surface) - holes.area));
    prepared.warnings.push_back(text);
}

}  // namespace

PreparedSurface prepareSurface(const TriMesh& input, const RemeshParams& params, int sampleCount, Pipeline& pipeline)
{
    PreparedSurface prepared;
    pipeline.run("prepare", [&] {
        InputReport report;
        RepairParams repairParams = params.repairParams;
        repairParams.vertexBudget = sampleCount;
        prepared.surface =
            params.repair ? repairAndPrepare(input, repairParams, prepared.repair, report) : prepareInput(input, report);
        prepared.cleanIndex = report.cleanIndex;
        prepared.warnings = report.notes;
        prepared.notes = report.information;
        prepared.frame = workingFrame(prepared.surface, sampleCount);
        for (Vec3& p : prepared.surface.vertices) p = prepared.frame.toWork(p);
        closeHoles(prepared, params);
    });
    return prepared;
}

FeatureLines findFeatureLines(const PreparedSurface& prepared, const RemeshParams& params, std::vector<std::string>& warnings,
                              std::vector<std::string>& notes)
{
    // On the input: their vertices stay in the coarse surface.
    int ignored = 0;
    const std::vector<std::array<int, 2>> userEdges = featureEdgesOnSurface(params.featureEdges, prepared.cleanIndex);
    FeatureLines features = detectFeatures(prepared.surface, params.featureAngleDegrees, userEdges, &ignored, kCornerSpacing);
    if (ignored > 0)
        warnings.push_back(std::to_string(ignored) + " of the given feature edges are not edges of the mesh and were ignored");
    if (params.featureAngleDegrees > 0 && params.narrowFeatureStripShare > 0 && !features.edges.empty()) {
        // Detected lines on strips the edge length cannot resolve are left free; the user's own
        // feature edges are kept whatever their neighbours.
        NarrowStripParams strip;
        strip.widthShare = params.narrowFeatureStripShare;
        NarrowStrips narrow = findNarrowStrips(prepared.surface, features, kWorkingEdgeLength, strip);
        if (narrow.dropped > 0) {
            narrow.kept.insert(narrow.kept.end(), userEdges.begin(), userEdges.end());
            features = detectFeatures(prepared.surface, 0, narrow.kept, nullptr, kCornerSpacing);
            notes.push_back(std::to_string(narrow.dropped) + " sharp edges on strips narrower than " +
                            std::to_string(params.narrowFeatureStripShare).substr(0, 4) +
                            " edge lengths were not kept as feature lines (their strips are cut like a smooth surface)");
        }
    }
    return features;
}

OptimisationSurface chooseOptimisationSurface(const PreparedSurface& prepared, FeatureLines features, const RemeshParams& params,
                                              int sampleCount, Pipeline& pipeline)
{
    OptimisationSurface out;
    const TriMesh& surface = prepared.surface;
    out.input = &surface;
    out.features = std::move(features);
    const int coarseFaces = optimisationFaceTarget(params, sampleCount);
    out.simplified = coarseFaces > 0 && double(surface.faceCount()) > 1.5 * double(coarseFaces);
    if (out.simplified) {
        pipeline.run("simplify", [&] {
            SimplifyParams simplify;
            simplify.targetFaces = coarseFaces;
            // 5 % of the output's edge length (about 1.07 at the working scale): the coarse
            // surface is within that of the input, far inside the output's own sag.
            simplify.maxError = 0.05;
            simplify.blockFaces = params.simplifyBlockFaces;
            simplify.locked.assign(surface.vertices.size(), 0);
            for (const auto& [a, b] : out.features.edges) simplify.locked[a] = simplify.locked[b] = 1;
            // Both are serial: the input's closest-point tree (for projectOnInput) and its
            // topology (for the report) are computed on the other thread meanwhile; the tree not
            // for inputs whose tree would add to the optimisation's peak memory (about 110 bytes
            // a face), nor beside a simplification in blocks, which has every thread.
            constexpr int kMaxEarlyTreeFaces = 500000;
            const bool early =
                surface.faceCount() <= kMaxEarlyTreeFaces && simplifyBlockCount(surface.faceCount(), simplify) == 1;
            // The simplification on the main thread (whose heap keeps the CLI's padding).
            sideBySide(
                early, [&] { out.coarse = simplifyMesh(surface, simplify); },
                [&] {
                    if (early) out.inputTree = std::make_unique<ClosestPointTree>(surface);
                    out.inputTopology = computeTopology(surface);
                });
            // The same feature edges (both ends kept, so still edges), corners found again.
            std::vector<std::array<int, 2>> edges;
            for (const auto& [a, b] : out.features.edges)
                edges.push_back({out.coarse.coarseVertex[a], out.coarse.coarseVertex[b]});
            out.features = detectFeatures(out.coarse.mesh, 0, edges, nullptr, kCornerSpacing);
        });
    }
    if (!out.simplified) out.inputTopology = computeTopology(surface);
    out.optIndex = prepared.cleanIndex;
    if (out.simplified)
        for (int& v : out.optIndex) v = v >= 0 ? out.coarse.coarseVertex[v] : -1;
    out.border = boundarySegments(out.mesh());
    return out;
}

std::vector<double> chooseDensity(const OptimisationSurface& surface, const RemeshParams& params)
{
    // μ normalised to an area-weighted mean of 1 keeps the scale (mean cell area 1, sampleCount
    // samples) right on average; cells are then ~1/μ in area. ρ = μ² per face enters eq. 1.
    const bool curvature = params.density == DensitySource::Curvature && params.gradation > 0;
    if (!curvature && params.density != DensitySource::PerVertex) return {};
    const TriMesh& mesh = surface.mesh();
    std::vector<double> mu = curvature ? curvatureDensity(mesh, params.gradation, kWorkingEdgeLength)
                                       : densityOnSurface(params.vertexDensity, surface.optIndex, mesh.vertexCount());
    normaliseDensity(mesh, mu);
    return faceDensity(mesh, mu);
}

OptimisationPlan planOptimisation(const OptimisationSurface& surface, const std::vector<double>& rho, int sampleCount,
                                  const RemeshParams& p)
{
    OptimisationPlan plan;
    // The field is needed when E_field is used (in the FCVT iterations only: measuring it during
    // the CVT iterations would cost a closest-point query per sample and evaluation).
    plan.useField = usesField(p);
    const bool constrained = !surface.border.empty() || !surface.features.empty();
    // The start (RemeshParams::latticeStart). A constant density is the uniform one. Not with
    // feature lines: lattice points near a crease cut creases (docs/tuning.md).
    const bool uniform = std::all_of(rho.begin(), rho.end(), [&](double r) { return r == rho.front(); });
    plan.latticeStart =
        p.initialSamples.empty() && p.latticeStart && plan.useField && uniform && surface.features.segments.empty();
    plan.lloydSteps = plan.latticeStart ? p.latticeLloydIterations : p.lloydIterations;
    const bool largeRun = plan.latticeStart && sampleCount >= p.largeRunSamples;
    plan.fcvtIterations = largeRun && p.fcvtIterations > 0 ? p.largeRunFcvtIterations : p.fcvtIterations;
    plan.expectedEvaluations =
        plan.lloydSteps + 1.1 * (p.cvtIterations + plan.fcvtIterations) + (constrained ? p.boundaryIterations : 0) + 2;
    return plan;
}

FieldStage computeFieldStage(const TriMesh& input, const OptimisationSurface& surface, const Normalisation& frame,
                             const OptimisationPlan& plan, const RemeshParams& p, Pipeline& pipeline)
{
    FieldStage out;
    if (!plan.useField) return out;
    const TriMesh& mesh = surface.mesh();
    pipeline.run("field", [&] {
        pipeline.enterPhase(Phase::Field);
        pipeline.report(phaseName(Phase::Field), 2);
        if (p.fieldSource == FieldSource::User) {
            std::vector<Vec3> vectors(mesh.vertices.size(), Vec3::Zero());
            if (p.userDirections.size() != input.vertices.size())
                throw InvalidInputError("the user field has " + std::to_string(p.userDirections.size()) + " vectors for " +
                                        std::to_string(input.vertices.size()) + " vertices");
            for (size_t v = 0; v < input.vertices.size(); ++v)
                if (surface.optIndex[v] >= 0) vectors[surface.optIndex[v]] = p.userDirections[v];
            out.field = fieldFromVectors(mesh, vectors, p.seed);
        } else {
            FieldParams fieldParams;
            fieldParams.source = p.fieldSource;
            fieldParams.seed = p.seed;
            fieldParams.smoothingIterations = p.fieldSmoothingIterations;
            // The field follows the same creases the samples are snapped to (§5).
            if (p.featureAngleDegrees > 0) fieldParams.sharpAngle = p.featureAngleDegrees;
            out.field = computeField(mesh, fieldParams, nullptr, plan.latticeStart ? &out.hierarchy : nullptr);
        }
        if (p.computeSingularities) out.singularities = findSingularities(mesh, out.field);
        for (Singularity& s : out.singularities) s.position = frame.fromWork(s.position);
    });
    return out;
}

//! projectOnInput: a face whose smallest angle the projection would bring under this (and
//! under its own on the coarse copy) keeps its vertices where they are (issue 52 item 4's bar).
constexpr double kProjectionSliverDegrees = 15.0;

bool usesField(const RemeshParams& params) { return params.fcvtIterations > 0 && params.lambda > 0; }

ValenceSurface valenceSurface(const PassContext& context)
{
    const OptimisationSurface& surface = context.surface;
    return {surface.mesh(), *context.tree, surface.features.segments, usesField(context.params) ? &context.field.field : nullptr,
            surface.border};
}

ValencedMesh optimiseValence(ExtractedMesh extracted, const PassContext& context)
{
    ValencedMesh out;
    out.mesh = std::move(extracted.mesh);
    if (!context.params.valenceOptimization) return out;
    Pipeline& pipeline = context.pipeline;
    pipeline.run("valence", [&] {
        pipeline.enterPhase(Phase::Valence);
        pipeline.report(phaseName(Phase::Valence), 92);
        out.stats = optimizeValence(out.mesh, extracted.roles, valenceSurface(context), context.params.valence,
                                    extracted.vertexFaceHints);
    });
    return out;
}

std::vector<Vec3> projectOnInput(const TriMesh& mesh, const ClosestPointTree& inputTree, Pipeline& pipeline)
{
    // The coarse surface is within SimplifyParams::maxError of the input. Border and feature
    // vertices lie on input edges, which both surfaces have.
    std::vector<Vec3> projected(mesh.vertices.size());
    pipeline.run("project", [&] {
        const int n = mesh.vertexCount();
#pragma omp parallel for schedule(static)
        for (int v = 0; v < n; ++v) projected[v] = inputTree.closest(mesh.vertices[v]).point;
        // Where the input differs from the coarse copy by more than the mesh resolves (a scan's
        // ragged border, a wall thinner than an edge: a local shell's vertices, issue 52),
        // neighbours can land on one input point and make a sliver or a zero-area face. Such a
        // face keeps its vertices on the coarse copy, until no projected face is a new sliver.
        const double sliver = kProjectionSliverDegrees * kPi / 180.0;
        std::vector<double> before(mesh.faces.size());
#pragma omp parallel for schedule(static)
        for (int f = 0; f < mesh.faceCount(); ++f) {
            const Face& t = mesh.faces[f];
            before[f] = smallestAngle(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
        }
        for (bool again = true; again;) {
            again = false;
            for (int f = 0; f < mesh.faceCount(); ++f) {
                const Face& t = mesh.faces[f];
                const double after = smallestAngle(projected[t[0]], projected[t[1]], projected[t[2]]);
                if (after >= std::min(sliver, before[f]) - 1e-12) continue;
                for (int v : t)
                    if (projected[v] != mesh.vertices[v]) projected[v] = mesh.vertices[v], again = true;
            }
        }
    });
    return projected;
}

Measurement measure(const TriMesh& mesh, const OptimisationSurface& surface, const ClosestPointTree& tree,
                    const RemeshParams& params, Pipeline& pipeline)
{
    // In the working frame (the figures are angles and fractions of the diagonal, the same in
    // every frame), where a model at 1e300 does not overflow them.
    Measurement out;
    pipeline.run("metrics", [&] {
        pipeline.report("metrics", 95);
        out.metrics = computeQuality(mesh);
        if (params.computeDistances && !mesh.faces.empty()) {
            const TriMesh& reference = *surface.input;
            // A fixed budget (RemeshParams::distanceSamples), or dense enough for a Hausdorff
            // figure at the meshes' resolution, capped for big ones.
            const int samples = params.distanceSamples > 0
                                    ? params.distanceSamples
                                    : std::clamp(20 * (mesh.faceCount() + reference.faceCount()), 20000, 200000);
            // The input's tree is there already (projectOnInput's; unsimplified, the
            // optimisation's, on the same surface): not built again.
            const ClosestPointTree* referenceTree = surface.inputTree     ? surface.inputTree.get()
                                                    : !surface.simplified ? &tree
                                                                          : nullptr;
            const DistanceMetrics d = computeDistance(mesh, reference, samples, referenceTree);
            out.metrics.dRms = d.rms;
            out.metrics.dH = d.hausdorff;
            if (!surface.border.empty()) out.metrics.dBoundary = boundaryDistance(mesh, reference);
        }
        out.outputTopology = computeTopology(mesh);
        const TopologySummary& in = surface.inputTopology;
        const TopologySummary& o = out.outputTopology;
        if (!o.manifold()) out.warnings.push_back("the output is not manifold");
        if (o.genus != in.genus || o.boundaryLoops != in.boundaryLoops || o.components != in.components)
            out.warnings.push_back("topology not recovered at this vertex count: input genus " + std::to_string(in.genus) + ", " +
                                   std::to_string(in.boundaryLoops) + " boundary loops, " + std::to_string(in.components) +
                                   " components; output genus " + std::to_string(o.genus) + ", " +
                                   std::to_string(o.boundaryLoops) + " boundary loops, " + std::to_string(o.components) +
                                   " components (use more vertices)");
    });
    return out;
}

OutputInInputFrame returnToInputFrame(TriMesh mesh, const Normalisation& frame, const RemeshParams& params,
                                      const QualityMetrics& metrics)
{
    OutputInInputFrame out;
    out.mesh = std::move(mesh);
    out.metrics = metrics;
    for (Vec3& p : out.mesh.vertices) p = frame.fromWork(p);
    if (params.outputInFloat)
        for (Vec3& p : out.mesh.vertices) p = p.cast<float>().cast<double>();
    checkOutputPrecision(out.mesh, params.outputInFloat, out.metrics, out.warnings);
    return out;
}

}  // namespace fieldcvt
