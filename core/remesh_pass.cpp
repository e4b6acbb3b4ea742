// One optimisation pass of remesh() (remesh_stages.h): the initial samples, §5's schedule on the
// energy, and the restricted Delaunay triangulation of the samples.
#include "remesh_stages.h"

#include "errors.h"
#include "optimize.h"
#include "rdt.h"
#include "sampling.h"
#include "side_by_side.h"

#include <algorithm>
#include <limits>
#include <sstream>

namespace fieldcvt {

namespace {

//! The RDT's debris (rdt.h, dropDebris): pieces of at most this many faces, within this many edge
//! lengths of the rest of the output (every point of a part stays within 2 of the output).
constexpr int kDebrisFaces = 8;
constexpr double kDebrisReachEdges = 2;

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

void lbfgs(EnergyFunction& energy, std::vector<Vec3>& seeds, int iterations, std::vector<std::string>& warnings)
{
    OptimizeStats stats = minimizeLbfgs(energy, seeds, LbfgsParams{iterations});
    warnings.insert(warnings.end(), stats.warnings.begin(), stats.warnings.end());
}

}  // namespace

InitialSamples placeSamples(const PassContext& context, const OptimisationPlan& plan, const PassInput& pass)
{
    const RemeshParams& p = context.params;
    const TriMesh& surface = context.surface.mesh();
    const ClosestPointTree& tree = *context.tree;
    InitialSamples out;
    context.pipeline.run("sampling", [&] {
        if (plan.latticeStart) {
            // The field-aligned lattice (lattice.h) on the optimisation surface, put on it.
            LatticeParams lattice;
            lattice.seed = p.seed;
            lattice.iterations = p.latticeIterations;
            lattice.maxPasses = p.latticePasses;
            std::vector<int> faces;  // each point's face: the hint of its closest-point query
            out.lattice = std::make_unique<LatticeReport>();
            out.seeds = latticeSamples(surface, context.field.field, pass.sampleCount, lattice, out.lattice.get(),
                                       &context.hierarchy, &faces);
            std::vector<Vec3>& seeds = out.seeds;
#pragma omp parallel for schedule(static)
            for (int i = 0; i < static_cast<int>(seeds.size()); ++i) seeds[i] = tree.closest(seeds[i], faces[i]).point;
            out.lattice->spacing /= context.frame.scale;  // reported in input units
            context.hierarchy = FieldHierarchyLevels{};
        } else if (p.initialSamples.empty()) {
            out.seeds = sampleSurface(surface, pass.sampleCount, p.seed, pass.rho);  // uniform when rho is empty
        }
        if (p.initialSamples.empty()) {
            // A small part kept on its own (RepairParams::farComponentEdges) may have drawn fewer
            // samples than make a triangle of it.
            topUpSmallComponents(
                surface, [&tree](const Vec3& x) { return tree.closest(x).face; },
                static_cast<int>(p.repairParams.minFarComponentFloor), p.seed, out.seeds);
        } else {
            out.seeds.clear();
            for (const Vec3& x : p.initialSamples) out.seeds.push_back(context.frame.toWork(x));
        }
    });
    return out;
}

OptimisedSamples optimiseSamples(const PassContext& context, const OptimisationPlan& plan, EnergyFunction& energy,
                                 std::vector<Vec3> seeds)
{
    const RemeshParams& p = context.params;
    Pipeline& pipeline = context.pipeline;
    const TriMesh& surface = context.surface.mesh();
    OptimisedSamples out;
    int reseeded = 0;
    // A seed whose cell emptied during L-BFGS (a neighbour passed over it) has no gradient and
    // would be lost in the RDT: it starts again elsewhere.
    const auto reseedEmpty = [&] {
        const int moved = reseedEmptyCells(energy, surface, seeds, p.seed + 7919u * ++pipeline.reseedCalls);
        reseeded += moved;
        return moved;
    };
    try {
        pipeline.run("lloyd", [&] {
            pipeline.enterPhase(Phase::Lloyd);
            lloydRelaxation(energy, surface, seeds, plan.lloydSteps, p.seed);
        });
        pipeline.run("cvt", [&] {
            pipeline.enterPhase(Phase::Cvt);
            lbfgs(energy, seeds, p.cvtIterations, out.warnings);
            if (p.cvtIterations > 0) reseedEmpty();
        });
        // Second stage of §5: samples on the border and on feature lines, held there from now on.
        pipeline.run("features", [&] {
            pipeline.enterPhase(Phase::Features);
            out.constraints = relaxConstrainedSamples(energy, seeds, surface, context.surface.border, context.surface.features,
                                                      p.boundaryIterations, plan.fcvtIterations > 0);
            std::vector<char> frozen(seeds.size(), 0);
            for (size_t i = 0; i < seeds.size(); ++i) frozen[i] = out.constraints[i] != SampleConstraint::Free;
            energy.setFrozen(std::move(frozen));
        });
        if (plan.fcvtIterations > 0) {
            pipeline.run("fcvt", [&] {
                pipeline.enterPhase(Phase::Fcvt);
                energy.setField(plan.useField ? &context.field.field : nullptr, context.tree.get(), p.lambda);
                lbfgs(energy, seeds, plan.fcvtIterations, out.warnings);
                if (reseedEmpty() > 0)
                    lbfgs(energy, seeds, std::min(10, plan.fcvtIterations), out.warnings);  // to find their place
            });
        }
    } catch (const TimeLimitReached&) {
        std::ostringstream message;
        message << "time limit of " << p.timeLimitSeconds << " s reached during " << phaseName(pipeline.phase())
                << ": the output is made from the best samples so far";
        out.warnings.push_back(message.str());
    }
    if (reseeded > 0)
        out.warnings.push_back(std::to_string(reseeded) +
                               " samples whose cells had emptied during the optimisation were re-seeded");
    out.seeds = std::move(seeds);
    return out;
}

ExtractedMesh extractMesh(const PassContext& context, EnergyFunction& energy, const OptimisedSamples& samples, int sampleCount)
{
    Pipeline& pipeline = context.pipeline;
    ExtractedMesh out;
    pipeline.run("rdt", [&] {
        pipeline.enterPhase(Phase::Rdt);
        pipeline.report(phaseName(Phase::Rdt), 90);
        RvdOptions options;
        options.triangles = true;
        const std::vector<Vec3>& seeds = samples.seeds;
        const RvdResult& rvd = energy.diagram(seeds, options);
        // On cell pieces (multi-nerve RDT); the samples' frame faces are hints for their closest points.
        const std::vector<int>&hints = energy.lastFrameFaces(), none;
        RdtResult rdt = extractRdt(seeds, rvd, *context.tree, hints.size() == seeds.size() ? hints : none);
        dropDebris(rdt, kDebrisFaces, kDebrisReachEdges * kWorkingEdgeLength);
        out.warnings = std::move(rdt.warnings);
        out.mesh = std::move(rdt.mesh);
        // Without exactCount, keepTopology remeshes the shells by local operations instead.
        if (out.mesh.faces.empty() && (context.params.exactCount || !context.params.initialSamples.empty()))
            throw SolverError(std::to_string(sampleCount) + " vertices are too few for this surface: they form no " +
                              "triangle on it (it is thinner than the edge length everywhere); use more vertices");
        for (int seed : rdt.seedOfVertex)
            out.roles.push_back(size_t(seed) < samples.constraints.size() ? roleOf(samples.constraints[size_t(seed)])
                                                                          : VertexRole::Free);
        out.vertexFaceHints = std::move(rdt.faceOfVertex);
    });
    return out;
}

PassResult optimiseAndExtract(const PassContext& context, const PassInput& pass)
{
    PassResult out;
    const OptimisationPlan plan = planOptimisation(context.surface, pass.rho, pass.sampleCount, context.params);
    out.fcvtIterations = plan.fcvtIterations;
    // The energy's diagram structures and the surface's closest-point tree are independent and
    // serial: built side by side (the tree once, by the first pass).
    const TriMesh& surface = context.surface.mesh();
    const bool treeBuilt = context.tree != nullptr;
    sideBySide(
        !treeBuilt, [&] { out.energy = std::make_unique<EnergyFunction>(surface, pass.rho); },
        [&] {
            if (!treeBuilt) context.tree = std::make_unique<ClosestPointTree>(surface);
        });
    EnergyFunction& energy = *out.energy;
    Pipeline& pipeline = context.pipeline;
    energy.onEvaluation = [&pipeline, &energy, plan](const EnergyValue& value) {
        pipeline.onEvaluation(value, energy.evaluations(), plan);
    };
    energy.setSideAware(pass.sideAwareCells ? context.tree.get() : nullptr);
    InitialSamples initial = placeSamples(context, plan, pass);
    out.lattice = std::move(initial.lattice);
    const OptimisedSamples samples = optimiseSamples(context, plan, energy, std::move(initial.seeds));
    out.extracted = extractMesh(context, energy, samples, pass.sampleCount);
    out.warnings = samples.warnings;
    out.warnings.insert(out.warnings.end(), out.extracted.warnings.begin(), out.extracted.warnings.end());
    return out;
}

}  // namespace fieldcvt
