// remesh()'s second pass for thin parts (remesh_stages.h, remeshThinPartsAgain): issue 32, item 2.
#include "metrics.h"
#include "remesh_stages.h"
#include "thin_parts.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace fieldcvt {

namespace {

//! Thin parts (thin_parts.h): their faces' ρ raised to at least μ², and sampleCount by the
//! vertices that μ adds over the surface (∫ μ dA at one vertex per unit of area). False when
//! nothing is thin enough to need more vertices.
bool raiseDensityOnThinParts(RemeshRun& run, const TopologySummary& firstOutput)
{
    const TriMesh& surface = run.optSurface();
    bool raised = false;
    run.pipeline.run("thickness", [&] {
        const ThinPartDensity thin = thinPartDensity(surface, *run.tree, kWorkingEdgeLength, run.params.thinParts);
        if (thin.mu.empty()) return;
        std::vector<double> rho = run.rho.empty() ? std::vector<double>(size_t(surface.faceCount()), 1.0) : run.rho;
        double before = 0, after = 0;
        for (int f = 0; f < surface.faceCount(); ++f) {
            const double a = faceArea(surface, f);
            before += a * std::sqrt(rho[f]);
            rho[f] = std::max(rho[f], thin.mu[f] * thin.mu[f]);
            after += a * std::sqrt(rho[f]);
        }
        const int added = before > 0 ? static_cast<int>(std::lround(run.sampleCount * (after - before) / before)) : 0;
        if (added < 1) return;
        run.rho = std::move(rho);
        RemeshResult::ThinParts& report = run.result.thinParts;
        report.added = added;
        report.faces = thin.thinFaces;
        report.thinnest = thin.thinnest / run.frame.scale;
        report.capped = thin.capped;
        const TopologySummary& in = run.result.inputTopology;
        char text[400];
        std::snprintf(text, sizeof text,
                      "%d vertices added where the surface is thinner than the edge length (%d faces, the thinnest "
                      "%.3g across)%s: at %d vertices the output had genus %d, %d boundary loops, %d components "
                      "against the input's %d, %d, %d",
                      added, thin.thinFaces, report.thinnest, thin.capped ? ", capped by the vertex count's limit" : "",
                      run.sampleCount, firstOutput.genus, firstOutput.boundaryLoops, firstOutput.components, in.genus,
                      in.boundaryLoops, in.components);
        run.sampleCount += added;
        run.result.warnings.push_back(text);
        raised = true;
    });
    return raised;
}

//! The smallest angle (degrees) a second pass for thin parts may bring where the first one had
//! none smaller (issue 32 item 1's bar).
constexpr double kThinPassSmallestAngle = 15;

//! How far a mesh's topology is from the input's: 0 when genus, boundary loops and components
//! all agree and it is manifold.
int topologyDistance(const TopologySummary& output, const TopologySummary& input)
{
    return std::abs(output.genus - input.genus) + std::abs(output.boundaryLoops - input.boundaryLoops) +
           std::abs(output.components - input.components) + (output.manifold() ? 0 : 1);
}

}  // namespace

void remeshThinPartsAgain(RemeshRun& run)
{
    const RemeshParams& p = run.params;
    RemeshResult& result = run.result;
    if (p.exactCount || !p.initialSamples.empty() || result.mesh.faces.empty()) return;
    const TopologySummary firstOutput = computeTopology(result.mesh);
    const int firstDistance = topologyDistance(firstOutput, result.inputTopology);
    if (firstDistance == 0) return;
    const double firstSmallestAngle = computeQuality(result.mesh).thetaMin;
    // The first pass, to go back to when the second one is no nearer the input's topology.
    TriMesh firstMesh = std::move(result.mesh);
    std::vector<VertexRole> firstRoles = std::move(run.roles);
    std::vector<int> firstHints = std::move(run.vertexFaceHints);
    const std::vector<std::string> firstWarnings = result.warnings;
    const size_t firstPassWarnings = run.optimisationWarnings;  // from the first optimisation on
    const int firstCount = run.sampleCount;
    const std::vector<double> firstRho = run.rho;
    auto restoreFirstPass = [&] {
        result.mesh = std::move(firstMesh);
        run.roles = std::move(firstRoles);
        run.vertexFaceHints = std::move(firstHints);
        result.warnings = firstWarnings;
        result.thinParts = {};
        run.sampleCount = firstCount;
        run.rho = firstRho;
    };
    if (!raiseDensityOnThinParts(run, firstOutput)) return restoreFirstPass();
    const size_t secondPassWarnings = result.warnings.size() - 1;  // the thin parts' warning on
    setUpEnergy(run);
    placeSamples(run);
    optimiseSamples(run);
    extractMesh(run);
    // Kept when nearer the input's topology without slivers the first pass did not have (issue
    // 32 item 1's bar: no angle under 15 degrees).
    if (topologyDistance(computeTopology(result.mesh), result.inputTopology) >= firstDistance ||
        computeQuality(result.mesh).thetaMin < std::min(firstSmallestAngle, kThinPassSmallestAngle))
        return restoreFirstPass();
    // The second pass kept: the first one's optimisation and RDT warnings were about its mesh.
    result.warnings.erase(result.warnings.begin() + static_cast<std::ptrdiff_t>(firstPassWarnings),
                          result.warnings.begin() + static_cast<std::ptrdiff_t>(secondPassWarnings));
}

}  // namespace fieldcvt
