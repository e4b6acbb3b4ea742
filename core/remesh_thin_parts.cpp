// remesh()'s passes for thin parts (remesh_stages.h, remeshThinPartsAgain): more vertices where the
// surface is thinner than the edge length, until the output's topology is the input's.
#include "boundary.h"
#include "closest_point.h"
#include "errors.h"
#include "metrics.h"
#include "remesh_stages.h"
#include "thin_parts.h"
#include "valence.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace fieldcvt {

namespace {

//! A pass around tears looks for thin parts this many edge lengths from the torn border.
constexpr double kTearFocusEdges = 2;
//! Passes after the first: one around the first pass's tears, then two wherever the surface is
//! thin, each from the best density so far and asking more of the thin parts than the one before
//! (docs/tuning.md, "Thin-part passes").
constexpr int kExtraPasses = 3;
constexpr double kEdgeShrinkPerPass = 0.7;
//! A later pass is kept only with at most this many output vertices per vertex asked for.
constexpr double kMaxOutputVertexFactor = 2.0;
//! A pass over the vertex budget runs once more with its samples scaled to this share of the
//! budget (the vertex count varies by a percent or two with the samples' places).
constexpr double kBudgetRetryShare = 0.97;
//! The passes stop after this many in a row that were not kept (each costs an optimisation).
constexpr int kMaxPassesInVain = 2;
//! The triangle bars a later pass is held to: no smaller angle (degrees) than this where the
//! first pass had none,
constexpr double kThinPassSmallestAngle = 15;
//! Nor more triangles with an angle under 30 degrees (%) than the first pass had, or this many.
constexpr double kThinPassShareUnder30 = 0.5;

//! Side-aware passes run only on closed inputs whose first pass's RDT had at least this many
//! vertices per sample (cells in several pieces): elsewhere they never won and cost a second
//! round of passes (docs/tuning.md, "kSideAwareMinPiecesPerSample").
constexpr double kSideAwareMinPiecesPerSample = 1.1;

//! Where the RDT tore: the vertices of `mesh`'s border edges farther than an edge length from
//! the surface's own border `surfaceBorder` (a closed surface: every border vertex).
std::vector<Vec3> tornBorderPoints(const TriMesh& mesh, const std::vector<Segment>& surfaceBorder)
{
    std::vector<Vec3> torn;
    const double limit = kWorkingEdgeLength * kWorkingEdgeLength;
    for (const Segment& edge : boundarySegments(mesh))
        for (const Vec3& p : {edge.first, edge.second})
            if (surfaceBorder.empty() || (closestPointOnSegments(p, surfaceBorder) - p).squaredNorm() > limit) torn.push_back(p);
    return torn;
}

//! A part of the surface farther than this many edge lengths from the output is lost (every
//! point of a part is to stay within 2 edge lengths of the output).
constexpr double kLostEdges = 1.5;

//! What of the surface the output lost: the surface's vertices farther than kLostEdges edge
//! lengths from `mesh` (a peninsula of a ragged border or a plate narrower than the edge
//! length, which the RDT drops, or a crumb of it dropped as debris), and their area in cells
//! (one cell per unit of area at the working scale: about the vertices missing), rounded up.
struct LostSurface {
    std::vector<Vec3> points;
    int cells = 0;
};

LostSurface lostSurface(const TriMesh& mesh, const TriMesh& surface)
{
    LostSurface lost;
    if (mesh.faces.empty()) return lost;
    const ClosestPointTree tree(mesh);
    const double limit = kLostEdges * kWorkingEdgeLength;
    const int vertexCount = surface.vertexCount();
    std::vector<char> far(vertexCount, 0);
#pragma omp parallel for schedule(static)
    for (int v = 0; v < vertexCount; ++v) far[v] = tree.closest(surface.vertices[v]).squaredDistance > limit * limit;
    double area = 0;
    for (int f = 0; f < surface.faceCount(); ++f)
        for (int v : surface.faces[f])
            if (far[v]) area += faceArea(surface, f) / 3;
    for (int v = 0; v < vertexCount; ++v)
        if (far[v]) lost.points.push_back(surface.vertices[v]);
    lost.cells = static_cast<int>(std::ceil(area));
    if (lost.cells == 0 && !lost.points.empty()) lost.cells = 1;
    return lost;
}

//! How far a mesh's topology is from the input's: 0 when genus, boundary loops and components
//! all agree and it is manifold.
int topologyDistance(const TopologySummary& output, const TopologySummary& input)
{
    return std::abs(output.genus - input.genus) + std::abs(output.boundaryLoops - input.boundaryLoops) +
           std::abs(output.components - input.components) + (output.manifold() ? 0 : 1);
}

//! One pass's output with its input and what the passes measure of it, to keep the best pass.
struct PassOutcome {
    PassResult result;
    PassInput input;
    TopologySummary topology;
    LostSurface lost;          //!< the surface it lost
    int topologyDistance = 0;  //!< from the input's topology
    int distance = 0;          //!< topologyDistance plus the lost surface's cells
    bool shapeMeasured = false;
    double smallestAngle = 0;  //!< degrees, after the valence stage (when shapeMeasured)
    double shareUnder30 = 0;   //!< % of the triangles with an angle under 30 degrees, after it
    int thinFaces = 0;         //!< faces whose density the passes raised
    double thinnest = 0;       //!< the thinnest part they measured (working units)
    const TriMesh& mesh() const { return result.extracted.mesh; }
    bool made() const { return input.sampleCount > 0; }
};

//! The triangles' shape (Table 2) of a pass's mesh once the valence stage has run on it (on a
//! copy: the stage runs on the kept pass later, with the same result), which repairs many of the
//! RDT's slivers; the RDT's own when that stage is off.
QualityMetrics shapeAfterValence(const PassContext& context, const ExtractedMesh& extracted)
{
    if (!context.params.valenceOptimization) return computeQuality(extracted.mesh);
    TriMesh mesh = extracted.mesh;
    std::vector<VertexRole> roles = extracted.roles;
    optimizeValence(mesh, roles, valenceSurface(context), context.params.valence, extracted.vertexFaceHints);
    return computeQuality(mesh);
}

PassOutcome takeOutcome(const PassContext& context, PassResult&& result, const PassInput& input)
{
    PassOutcome out;
    out.topology = computeTopology(result.extracted.mesh);
    out.lost = lostSurface(result.extracted.mesh, context.surface.mesh());
    out.topologyDistance = topologyDistance(out.topology, context.surface.inputTopology);
    out.distance = out.topologyDistance + out.lost.cells;
    out.result = std::move(result);
    out.input = input;
    return out;
}

//! Measures the pass's shape once (it costs a valence stage): only passes nearer the input's
//! topology, and the first one to compare them with, need it.
void measureShape(const PassContext& context, PassOutcome& pass)
{
    if (pass.shapeMeasured) return;
    const QualityMetrics shape = shapeAfterValence(context, pass.result.extracted);
    pass.smallestAngle = shape.thetaMin;
    pass.shareUnder30 = shape.pctLt30;
    pass.shapeMeasured = true;
}

//! Whether more vertices on thin parts can bring `output` nearer `input`: it tore (more loops),
//! fell apart (more components) or lost handles (a lower genus). Fewer loops (a slit the output
//! closed) is not what density mends.
bool thinPartsMayMend(const TopologySummary& output, const TopologySummary& input)
{
    return output.boundaryLoops > input.boundaryLoops || output.components > input.components || output.genus < input.genus;
}

//! Raises `pass.rho` to at least μ² on the thin parts near `focus` (everywhere when it has no
//! points) and `pass.sampleCount` by the vertices that adds (∫ √ρ dA at one vertex per unit of
//! area), within `maxSamples`. False when nothing is thin there or the budget is spent.
bool raiseDensityOnThinParts(const PassContext& context, const ThinPartFocus& focus, const ThinPartParams& params, int maxSamples,
                             PassInput& pass, PassOutcome& report)
{
    const TriMesh& surface = context.surface.mesh();
    bool raised = false;
    context.pipeline.run("thickness", [&] {
        const ThinPartDensity thin = thinPartDensity(surface, *context.tree, kWorkingEdgeLength, params, focus);
        if (thin.mu.empty()) return;
        std::vector<double> rho = pass.rho.empty() ? std::vector<double>(size_t(surface.faceCount()), 1.0) : pass.rho;
        double before = 0, after = 0;
        for (int f = 0; f < surface.faceCount(); ++f) {
            const double a = faceArea(surface, f);
            before += a * std::sqrt(rho[f]);
            rho[f] = std::max(rho[f], thin.mu[f] * thin.mu[f]);
            after += a * std::sqrt(rho[f]);
        }
        // Within the budget: over it, every cell grows a little so that the count fits.
        const int count = before > 0 ? std::min(maxSamples, static_cast<int>(std::lround(pass.sampleCount * after / before))) : 0;
        if (count <= pass.sampleCount) return;
        pass.rho = std::move(rho);
        pass.sampleCount = count;
        report.thinFaces += thin.thinFaces;
        report.thinnest = report.thinFaces == thin.thinFaces ? thin.thinnest : std::min(report.thinnest, thin.thinnest);
        raised = true;
    });
    return raised;
}

//! The warning of a kept later pass: how many vertices were added, where and why.
std::string thinPartsWarning(const PassContext& context, const PassOutcome& first, const PassOutcome& kept)
{
    const TopologySummary& in = context.surface.inputTopology;
    char text[400];
    std::snprintf(text, sizeof text,
                  "%d vertices added where the surface is thinner than the edge length (%d faces, the thinnest %.3g "
                  "across): at %d vertices the output had genus %d, %d boundary loops, %d components against the "
                  "input's %d, %d, %d",
                  kept.input.sampleCount - first.input.sampleCount, kept.thinFaces, kept.thinnest / context.frame.scale,
                  first.input.sampleCount, first.topology.genus, first.topology.boundaryLoops, first.topology.components,
                  in.genus, in.boundaryLoops, in.components);
    std::string warning = text;
    if (kept.input.sideAwareCells)
        warning = "with cells kept to their own side of walls thinner than them (side-aware cells), " + warning;
    if (first.lost.cells > 0)
        warning += ", and had lost about " + std::to_string(first.lost.cells) +
                   " cells' area of it (parts narrower than the edge length)";
    return warning;
}

}  // namespace

namespace {

//! The passes after the first, and the best of them so far.
class ThinPartPasses {
public:
    ThinPartPasses(const PassContext& context, PassOutcome&& first) : context_(context), first_(std::move(first))
    {
        // Samples within maxVertexFactor × N, and output vertices within kMaxOutputVertexFactor
        // × N: on thin walls a plain cell falls into a piece on each side and each piece makes a
        // vertex, so the samples may grow only as far as the vertices per sample of the pass they
        // start from allow, and a pass over it is not kept.
        maxVertices_ = static_cast<int>(std::floor(kMaxOutputVertexFactor * first_.input.sampleCount));
        maxSampleFactorCount_ = static_cast<int>(std::floor(context.params.thinParts.maxVertexFactor * first_.input.sampleCount));
    }

    //! Passes with more vertices on thin parts, from the first pass's density: with plain cells,
    //! then with side-aware ones (a sample owns nothing of the far side of a plate or wall
    //! thinner than its cell, which plain cells tear or glue); the better of the two is kept.
    void runAll()
    {
        densityPasses(false);
        // Only on closed shells (solids: walls) where plain cells fell into pieces (each piece
        // an RDT vertex): cells reaching across walls thinner than them, what side-aware cells
        // change.
        const double piecesPerSample = double(first_.mesh().vertexCount()) / std::max(1, first_.input.sampleCount);
        if (base(false).distance == 0 || context_.surface.inputTopology.boundaryLoops > 0 ||
            piecesPerSample < kSideAwareMinPiecesPerSample)
            return;
        sameDensityPass(true);
        densityPasses(true);
        PassOutcome& side = best_[1];
        if (side.made() && (!best_[0].made() || better(side, best_[0]))) best_[0] = std::move(side);
    }

    //! The best pass (or the first), with its warning and report.
    ThinPartsOutcome finish()
    {
        ThinPartsOutcome out;
        PassOutcome& best = best_[0];
        if (!best.made()) {
            out.pass = std::move(first_.result);
            out.input = first_.input;
            return out;
        }
        out.report.added = best.input.sampleCount - first_.input.sampleCount;
        out.report.faces = best.thinFaces;
        out.report.thinnest = best.thinnest / context_.frame.scale;
        out.report.capped = best.input.sampleCount >= maxSampleFactorCount_ || best.mesh().vertexCount() >= 0.97 * maxVertices_;
        out.report.sideAwareCells = best.input.sideAwareCells;
        out.warning = thinPartsWarning(context_, first_, best);
        out.pass = std::move(best.result);
        out.input = best.input;
        return out;
    }

private:
    //! The best pass so far with plain (false) or side-aware (true) cells, or the first.
    const PassOutcome& base(bool sideAware) const
    {
        const PassOutcome& best = best_[sideAware ? 1 : 0];
        return best.made() ? best : first_;
    }

    //! Whether `outcome` replaces `base`: nearer the input's topology, within the vertex budget
    //! (the RDT's count: the valence stage's splits and collapses change it by a percent or
    //! so), without slivers the first pass did not have. A side-aware pass must not trade
    //! topology for lost surface (docs/tuning.md).
    bool better(PassOutcome& outcome, const PassOutcome& base)
    {
        if (!(outcome.distance < base.distance && outcome.mesh().vertexCount() <= maxVertices_)) return false;
        if (outcome.input.sideAwareCells && outcome.topologyDistance > base.topologyDistance) return false;
        measureShape(context_, first_);
        measureShape(context_, outcome);
        return outcome.smallestAngle >= std::min(first_.smallestAngle, kThinPassSmallestAngle) &&
               outcome.shareUnder30 <= std::max(first_.shareUnder30, kThinPassShareUnder30);
    }

    PassOutcome optimiseAndExtract(const PassInput& input)
    {
        return takeOutcome(context_, fieldcvt::optimiseAndExtract(context_, input), input);
    }

    //! The best density so far again, with side-aware cells: a sample then owns nothing of the
    //! far side of a plate or wall thinner than its cell, which plain cells tear or glue.
    void sameDensityPass(bool sideAware)
    {
        const PassOutcome& base = this->base(sideAware);
        PassInput input = base.input;
        input.sideAwareCells = sideAware;
        PassOutcome outcome = optimiseAndExtract(input);
        outcome.thinFaces = base.thinFaces;
        outcome.thinnest = base.thinnest;
        if (better(outcome, base)) best_[sideAware ? 1 : 0] = std::move(outcome);
    }

    //! Up to kExtraPasses passes, each from the best density so far: one around the first
    //! pass's tears and lost surface, then everywhere, each asking more of the thin parts.
    void densityPasses(bool sideAware)
    {
        ThinPartParams params = context_.params.thinParts;
        int passesInVain = 0;
        for (int pass = 0; pass < kExtraPasses && passesInVain < kMaxPassesInVain; ++pass) {
            const PassOutcome& base = this->base(sideAware);
            if (base.distance == 0) break;
            ThinPartFocus focus;
            if (pass == 0) {
                focus.points = tornBorderPoints(base.mesh(), context_.surface.border);
                focus.points.insert(focus.points.end(), base.lost.points.begin(), base.lost.points.end());
                focus.radius = kTearFocusEdges * kWorkingEdgeLength;
                if (focus.points.empty()) continue;  // nothing tore or was lost (a genus lost): the next passes
            }
            PassInput input = base.input;
            input.sideAwareCells = sideAware;
            PassOutcome measured;
            measured.thinFaces = base.thinFaces;
            measured.thinnest = base.thinnest;
            const double verticesPerSample =
                std::max(1.0, double(base.mesh().vertexCount()) / std::max(1, base.input.sampleCount));
            const int maxSamples =
                std::min(maxSampleFactorCount_, static_cast<int>(std::floor(maxVertices_ / verticesPerSample)));
            const bool raised = raiseDensityOnThinParts(context_, focus, params, maxSamples, input, measured);
            params.edgePerThickness /= kEdgeShrinkPerPass;
            params.edgePerStripWidth /= kEdgeShrinkPerPass;
            if (!raised) continue;
            PassOutcome outcome = optimiseAndExtract(input);
            if (outcome.distance < base.distance && outcome.mesh().vertexCount() > maxVertices_) {
                // Nearer, but over the budget (the vertices per sample grew with the density):
                // the same density once more with proportionally fewer samples.
                input.sampleCount = static_cast<int>(
                    std::floor(input.sampleCount * kBudgetRetryShare * maxVertices_ / outcome.mesh().vertexCount()));
                outcome = optimiseAndExtract(input);
            }
            outcome.thinFaces = measured.thinFaces;
            outcome.thinnest = measured.thinnest;
            if (better(outcome, base)) {
                best_[sideAware ? 1 : 0] = std::move(outcome);
                passesInVain = 0;
            } else {
                ++passesInVain;
            }
        }
    }

    const PassContext& context_;
    PassOutcome first_;
    PassOutcome best_[2];  // the best later pass with plain and side-aware cells (none made yet: !made())
    int maxVertices_ = 0, maxSampleFactorCount_ = 0;
};

//! RemeshParams::exactCount: a pass whose RDT has more vertices than this share over or under the
//! count asked (cells cut in pieces by walls thinner than them, each piece a vertex; samples in no
//! triangle on parts thinner than the cells) runs again with proportionally fewer or more samples,
//! at most kExactCountPasses more times (larger cells are cut into more pieces: aimed at again).
constexpr double kExactCountShare = 0.03;
constexpr int kExactCountPasses = 3;

ThinPartsOutcome keepCountAskedFor(PassResult first, const PassInput& firstInput, const PassContext& context)
{
    ThinPartsOutcome out;
    out.pass = std::move(first);
    out.input = firstInput;
    const int asked = firstInput.sampleCount;
    for (int pass = 0; pass < kExactCountPasses; ++pass) {
        const int got = out.pass.extracted.mesh.vertexCount();
        if (std::abs(got - asked) <= asked * kExactCountShare) break;
        PassInput input = out.input;
        input.sampleCount = std::max(4, static_cast<int>(std::floor(double(input.sampleCount) * asked / got)));
        PassResult again;
        try {
            again = optimiseAndExtract(context, input);
        } catch (const SolverError&) {
            break;  // so few samples make no triangle on the thin parts: the pass before stands
        }
        if (again.extracted.mesh.faces.empty() || std::abs(again.extracted.mesh.vertexCount() - asked) >= std::abs(got - asked))
            break;
        out.pass = std::move(again);
        out.input = input;
    }
    return out;
}

//! A first pass whose topology is the input's but whose cells thin walls cut into pieces (each
//! piece a vertex: a plate thinner than the cells comes back with nearly a vertex per sample on
//! each side) has more vertices than its topology needs: the passes of keepCountAskedFor, each
//! kept only if its topology is still the input's and nothing is lost.
ThinPartsOutcome fewerPiecesOfCells(PassOutcome first, const PassContext& context)
{
    ThinPartsOutcome out;
    out.input = first.input;
    const int asked = first.input.sampleCount;
    int got = first.mesh().vertexCount();
    out.pass = std::move(first.result);
    for (int pass = 0; pass < kExactCountPasses && std::abs(got - asked) > asked * kExactCountShare; ++pass) {
        PassInput input = out.input;
        input.sampleCount = std::max(4, static_cast<int>(std::floor(double(input.sampleCount) * asked / got)));
        PassOutcome again;
        try {
            again = takeOutcome(context, optimiseAndExtract(context, input), input);
        } catch (const SolverError&) {
            break;
        }
        const int count = again.mesh().vertexCount();
        if (again.mesh().faces.empty() || thinPartsMayMend(again.topology, context.surface.inputTopology) ||
            !again.lost.points.empty() || std::abs(count - asked) >= std::abs(got - asked))
            break;
        out.pass = std::move(again.result);
        out.input = input;
        got = count;
    }
    return out;
}

}  // namespace

ThinPartsOutcome remeshThinPartsAgain(PassResult first, const PassInput& firstInput, const PassContext& context)
{
    const RemeshParams& p = context.params;
    if (p.exactCount && p.initialSamples.empty() && !first.extracted.mesh.faces.empty())
        return keepCountAskedFor(std::move(first), firstInput, context);
    if (p.exactCount || !p.initialSamples.empty() || first.extracted.mesh.faces.empty()) {
        ThinPartsOutcome out;
        out.pass = std::move(first);
        out.input = firstInput;
        return out;
    }
    PassOutcome measured = takeOutcome(context, std::move(first), firstInput);  // topology and lost surface, once
    if (!thinPartsMayMend(measured.topology, context.surface.inputTopology) && measured.lost.points.empty())
        return fewerPiecesOfCells(std::move(measured), context);
    ThinPartPasses passes(context, std::move(measured));
    passes.runAll();
    return passes.finish();
}

}  // namespace fieldcvt
