// remesh()'s topology stage (remesh_stages.h, keepTopology): every shell of the surface whose
// restricted Delaunay triangulation did not come back with the shell's topology is remeshed by
// local operations on the surface instead (local_remesh.h), which keep it by construction.
#include "boundary.h"
#include "closest_point.h"
#include "errors.h"
#include "local_remesh.h"
#include "mesh_edges.h"
#include "metrics.h"
#include "remesh_limits.h"
#include "remesh_stages.h"
#include "thin_parts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace fieldcvt {

namespace {

//! A shell is in reach of the output when every vertex of it is within this many edge lengths of
//! the output (a part's points are to stay within 2 edge lengths; vertices are a sample of them).
constexpr double kReachEdges = 1.5;
//! An output piece belongs to the shell nearest most of its vertices; it merges shells when
//! more than this share of its vertices (and at least kMergedMinVertices) are nearest another.
constexpr double kMergedShare = 0.05;
constexpr int kMergedMinVertices = 3;
//! Shells under this share of the surface's area may be left out of the output (what the part
//! check, part_coverage.h, counts as small); larger ones are to come back.
constexpr double kSmallShellShare = 0.005;

//! The connected components (through edges) of a mesh and each one's topology and area.
struct Shells {
    std::vector<int> ofFace;  //!< per face, its shell
    int count = 0;
    std::vector<TopologySummary> topology;  //!< per shell
    std::vector<double> area;               //!< per shell
    //! Per shell, its border loops under RemeshParams::closeHolesUnder edge lengths across, which
    //! the hole filling left open (they pass a vertex twice, as the repair's cuts along
    //! non-manifold edges do): an output that closes them closes a small hole, as by design.
    std::vector<int> smallLoops;
};

//! Whether `loop` is under `maxAcross` across (the diameter of a round hole with the same bounding
//! box, as hole_filling.h measures it).
bool isSmallLoop(const TriMesh& mesh, const std::vector<int>& loop, double maxAcross)
{
    if (loop.empty()) return false;
    Vec3 lo = mesh.vertices[loop[0]], hi = lo;
    for (int v : loop) lo = lo.cwiseMin(mesh.vertices[v]), hi = hi.cwiseMax(mesh.vertices[v]);
    return (hi - lo).norm() / std::sqrt(2.0) < maxAcross;
}

Shells findShells(const TriMesh& mesh, double smallLoopAcross = 0)
{
    Shells shells;
    shells.ofFace = faceComponents(buildEdgeTable(mesh), mesh.faceCount(), shells.count);
    std::vector<std::vector<int>> faces(shells.count);
    for (int f = 0; f < mesh.faceCount(); ++f) faces[shells.ofFace[f]].push_back(f);
    shells.topology.resize(shells.count);
    shells.area.assign(shells.count, 0.0);
    shells.smallLoops.assign(shells.count, 0);
    std::vector<int> local(mesh.vertexCount(), -1);
    for (int s = 0; s < shells.count; ++s) {
        TriMesh piece;
        for (int f : faces[s]) {
            Face t = mesh.faces[f];
            for (int& v : t) {
                if (local[v] < 0) {
                    local[v] = piece.vertexCount();
                    piece.vertices.push_back(mesh.vertices[v]);
                }
                v = local[v];
            }
            piece.faces.push_back(t);
            shells.area[s] += faceArea(mesh, f);
        }
        for (int f : faces[s])
            for (int v : mesh.faces[f]) local[v] = -1;
        shells.topology[s] = computeTopology(piece);
        if (shells.topology[s].boundaryLoops > 0 && smallLoopAcross > 0)
            for (const std::vector<int>& loop : borderLoops(piece))
                shells.smallLoops[s] += isSmallLoop(piece, loop, smallLoopAcross);
    }
    return shells;
}

//! Why the RDT's pieces of a shell do not have its topology.
enum Problem : unsigned { kCut = 1, kMerged = 2, kGenus = 4, kLoops = 8, kOutOfReach = 16, kNotManifold = 32 };

//! The output's pieces, the shell each belongs to, and what is wrong per shell.
struct ShellCheck {
    Shells output;                   //!< the output's pieces
    std::vector<int> shellOfPiece;   //!< per piece, the surface shell nearest most of its vertices (-1: none)
    std::vector<unsigned> problems;  //!< per surface shell, Problem bits (0: its topology is kept)
};

//! Per shell of the surface, what is wrong with the output there.
ShellCheck checkShells(const ExtractedMesh& extracted, const TriMesh& surface, const Shells& input, double smallShellArea)
{
    const TriMesh& mesh = extracted.mesh;
    ShellCheck check;
    check.output = findShells(mesh);
    const Shells& output = check.output;
    check.shellOfPiece.assign(output.count, -1);
    std::vector<unsigned>& problems = check.problems;
    problems.assign(input.count, 0);
    // Each output piece's shell: the one nearest most of its vertices.
    std::vector<std::vector<int>> votes(output.count);
    std::vector<int> pieceOfVertex(mesh.vertexCount(), -1);
    for (int f = 0; f < mesh.faceCount(); ++f)
        for (int v : mesh.faces[f]) pieceOfVertex[v] = output.ofFace[f];
    for (int v = 0; v < mesh.vertexCount(); ++v) {
        const int hint = v < static_cast<int>(extracted.vertexFaceHints.size()) ? extracted.vertexFaceHints[v] : -1;
        if (pieceOfVertex[v] < 0 || hint < 0 || hint >= surface.faceCount()) continue;
        votes[pieceOfVertex[v]].push_back(input.ofFace[hint]);
    }
    std::vector<int> pieces(input.count, 0), pieceOfShell(input.count, -1);
    for (int c = 0; c < output.count; ++c) {
        std::vector<int>& shellVotes = votes[c];
        if (shellVotes.empty()) continue;
        std::sort(shellVotes.begin(), shellVotes.end());
        int best = shellVotes[0], bestCount = 0;
        for (size_t i = 0; i < shellVotes.size();) {
            size_t j = i;
            while (j < shellVotes.size() && shellVotes[j] == shellVotes[i]) ++j;
            if (static_cast<int>(j - i) > bestCount) bestCount = static_cast<int>(j - i), best = shellVotes[i];
            i = j;
        }
        const int others = static_cast<int>(shellVotes.size()) - bestCount;
        if (others >= kMergedMinVertices && others > kMergedShare * shellVotes.size())
            for (int s : shellVotes) problems[s] |= kMerged;
        ++pieces[best];
        pieceOfShell[best] = c;
        check.shellOfPiece[c] = best;
    }
    for (int s = 0; s < input.count; ++s) {
        if (pieces[s] == 0) {
            if (input.area[s] >= smallShellArea) problems[s] |= kCut;  // lost: a small shell may go
            continue;
        }
        if (pieces[s] > 1) problems[s] |= kCut;
        const TopologySummary& got = output.topology[pieceOfShell[s]];
        const TopologySummary& want = input.topology[s];
        if (!got.manifold()) problems[s] |= kNotManifold;
        if (got.genus != want.genus) problems[s] |= kGenus;
        if (got.boundaryLoops > want.boundaryLoops || got.boundaryLoops < want.boundaryLoops - input.smallLoops[s])
            problems[s] |= kLoops;
    }
    // Out of reach: a vertex of the surface far from the output (a shell with output pieces).
    if (!mesh.faces.empty()) {
        const ClosestPointTree tree(mesh);
        const double limit = kReachEdges * kWorkingEdgeLength;
        std::vector<int> shellOfVertex(surface.vertexCount(), -1);
        for (int f = 0; f < surface.faceCount(); ++f)
            for (int v : surface.faces[f]) shellOfVertex[v] = input.ofFace[f];
        std::vector<char> far(surface.vertexCount(), 0);
#pragma omp parallel for schedule(static)
        for (int v = 0; v < surface.vertexCount(); ++v)
            far[v] = shellOfVertex[v] >= 0 && pieces[shellOfVertex[v]] > 0 &&
                     tree.closest(surface.vertices[v]).squaredDistance > limit * limit;
        for (int v = 0; v < surface.vertexCount(); ++v)
            if (far[v]) problems[shellOfVertex[v]] |= kOutOfReach;
    }
    return check;
}

//! Per face of the surface, the edge length the local remeshing aims at: the pass's density
//! (vertices per unit of area: `pass.sampleCount` √ρ / ∫ √ρ dA, eq. 1's ρ) or the thin parts'
//! (thin_parts.h), whichever asks for more vertices.
std::vector<double> targetLengths(const PassContext& context, const PassInput& pass, const std::vector<char>& selected)
{
    const TriMesh& surface = context.surface.mesh();
    const int faces = surface.faceCount();
    std::vector<double> density(faces, 1.0);
    if (!pass.rho.empty()) {
        double integral = 0;
        for (int f = 0; f < faces; ++f) integral += faceArea(surface, f) * std::sqrt(pass.rho[f]);
        if (integral > 0)
            for (int f = 0; f < faces; ++f) density[f] = pass.sampleCount * std::sqrt(pass.rho[f]) / integral;
    }
    ThinPartFocus focus;  // the selected shells' vertices: their faces, and a margin
    for (int f = 0; f < faces; ++f)
        if (selected[f]) focus.points.push_back(surface.vertices[surface.faces[f][0]]);
    focus.radius = kWorkingEdgeLength;
    const ThinPartDensity thin = thinPartDensity(surface, *context.tree, kWorkingEdgeLength, context.params.thinParts, focus);
    std::vector<double> length(faces, kWorkingEdgeLength);
    for (int f = 0; f < faces; ++f) {
        const double mu = thin.mu.empty() ? 1.0 : thin.mu[f];
        length[f] = kWorkingEdgeLength / std::sqrt(std::max({density[f], mu, 1e-12}));
    }
    return length;
}

//! The local remeshing's shells are given up (the triangulation's pieces kept, with a warning)
//! when they would need more vertices than this times the samples, or this floor, or the count
//! limit: a face 1e30 long at the working scale would be split into as many.
constexpr double kLocalVertexFactor = 50;
constexpr double kLocalVertexFloor = 10000;

//! About how many vertices the local remeshing makes of the selected faces: their area over an
//! equilateral triangle's per vertex at their target length, or, on a sliver, its longest edge over
//! the length (the vertices along it).
double localVertexEstimate(const TriMesh& surface, const std::vector<char>& selected, const std::vector<double>& lengths)
{
    double estimate = 0;
    for (int f = 0; f < surface.faceCount(); ++f) {
        if (!selected[f]) continue;
        const Face& t = surface.faces[f];
        double longest = 0;
        for (int k = 0; k < 3; ++k)
            longest = std::max(longest, (surface.vertices[t[(k + 1) % 3]] - surface.vertices[t[k]]).norm());
        const double l = lengths[f];
        estimate += std::max(2 * faceArea(surface, f) / (std::sqrt(3.0) * l * l), longest / l);
        if (!std::isfinite(estimate)) return estimate;
    }
    return estimate;
}

std::string problemWords(unsigned problems)
{
    std::string words;
    auto add = [&](unsigned bit, const char* text) {
        if (!(problems & bit)) return;
        if (!words.empty()) words += ", ";
        words += text;
    };
    add(kCut, "cut or lost");
    add(kMerged, "merged with another");
    add(kGenus, "handles lost or made");
    add(kLoops, "holes opened or closed");
    add(kOutOfReach, "surface out of reach");
    add(kNotManifold, "not manifold");
    return words;
}

//! The output pieces of the shells kept, then the local remeshing of the others.
ExtractedMesh assemble(ExtractedMesh rdt, const ShellCheck& check, const std::vector<char>& remeshed,
                       const LocalRemeshResult& local, int& rdtVerticesReplaced)
{
    ExtractedMesh out;
    out.warnings = std::move(rdt.warnings);
    const TriMesh& mesh = rdt.mesh;
    auto kept = [&](int f) {
        const int shell = check.shellOfPiece[check.output.ofFace[f]];
        return shell >= 0 && !remeshed[shell];
    };
    std::vector<int> index(mesh.vertexCount(), -1);
    for (int f = 0; f < mesh.faceCount(); ++f)
        if (kept(f))
            for (int v : mesh.faces[f]) index[v] = 0;
    for (int v = 0; v < mesh.vertexCount(); ++v) {
        if (index[v] < 0) {
            ++rdtVerticesReplaced;
            continue;
        }
        index[v] = out.mesh.vertexCount();
        out.mesh.vertices.push_back(mesh.vertices[v]);
        out.roles.push_back(rdt.roles[v]);
        out.vertexFaceHints.push_back(rdt.vertexFaceHints[v]);
    }
    for (int f = 0; f < mesh.faceCount(); ++f) {
        if (!kept(f)) continue;
        Face t = mesh.faces[f];
        for (int& v : t) v = index[v];
        out.mesh.faces.push_back(t);
    }
    const int offset = out.mesh.vertexCount();
    out.mesh.vertices.insert(out.mesh.vertices.end(), local.mesh.vertices.begin(), local.mesh.vertices.end());
    out.roles.insert(out.roles.end(), local.roles.begin(), local.roles.end());
    out.vertexFaceHints.insert(out.vertexFaceHints.end(), local.vertexFaceHints.begin(), local.vertexFaceHints.end());
    for (Face t : local.mesh.faces) {
        for (int& v : t) v += offset;
        out.mesh.faces.push_back(t);
    }
    return out;
}

}  // namespace

TopologyKept keepTopology(ExtractedMesh extracted, const PassInput& pass, const PassContext& context)
{
    TopologyKept out;
    const RemeshParams& params = context.params;
    if (params.exactCount || !params.initialSamples.empty()) {
        out.extracted = std::move(extracted);
        return out;
    }
    const TriMesh& surface = context.surface.mesh();
    context.pipeline.run("topology", [&] {
        const Shells input = findShells(surface, params.closeHolesUnder * kWorkingEdgeLength);
        double total = 0;
        for (double a : input.area) total += a;
        const ShellCheck check = checkShells(extracted, surface, input, kSmallShellShare * total);
        const std::vector<unsigned>& problems = check.problems;
        std::vector<char> remeshed(input.count, 0);
        unsigned all = 0;
        for (int s = 0; s < input.count; ++s) {
            remeshed[s] = problems[s] != 0;
            out.report.shells += remeshed[s];
            all |= problems[s];
        }
        // Nothing of the output kept and nothing to remesh (every shell small, none made into a
        // piece by the samples): all of them, rather than an empty mesh.
        bool anyKept = false;
        for (int piece : check.shellOfPiece) anyKept = anyKept || (piece >= 0 && !remeshed[piece]);
        if (!anyKept && out.report.shells == 0) {
            std::fill(remeshed.begin(), remeshed.end(), 1);
            out.report.shells = input.count;
            all |= kCut;
        }
        if (out.report.shells == 0) {
            out.extracted = std::move(extracted);
            return;
        }
        std::vector<char> selected(surface.faceCount(), 0);
        for (int f = 0; f < surface.faceCount(); ++f) selected[f] = remeshed[input.ofFace[f]];
        std::vector<double> lengths = targetLengths(context, pass, selected);
        const double needed = localVertexEstimate(surface, selected, lengths);
        const double limit =
            std::min<double>(kMaxVertexCount, std::max(kLocalVertexFloor, kLocalVertexFactor * pass.sampleCount));
        if (needed > limit) {
            if (extracted.mesh.faces.empty())
                throw SolverError(std::to_string(pass.sampleCount) +
                                  " vertices are too few for this surface: they form no triangle on it, and remeshing it "
                                  "by local operations would take too many (faces far longer than the edge length?); use "
                                  "more vertices");
            char text[300];
            std::snprintf(text, sizeof text,
                          "topology not kept on %d shells (%s): remeshing them by local operations would need about "
                          "%.3g vertices, over the limit of %.3g for this count (faces far longer than the edge length?)",
                          out.report.shells, problemWords(all).c_str(), needed, limit);
            out.warning = text;
            out.report = {};
            out.extracted = std::move(extracted);
            return;
        }
        LocalRemeshInput local{
            surface,           *context.tree, selected, context.surface.features.edges, context.surface.features.corners,
            std::move(lengths)};
        LocalRemeshResult made = remeshLocally(local, LocalRemeshParams{});
        out.report.vertices = made.mesh.vertexCount();
        for (int f = 0; f < surface.faceCount(); ++f) out.report.faces += selected[f];
        out.extracted = assemble(std::move(extracted), check, remeshed, made, out.report.rdtVertices);
        out.report.reasons = problemWords(all);
        char text[300];
        std::snprintf(text, sizeof text,
                      "%d of %d shells remeshed by local operations on the input to keep their topology (the "
                      "restricted Delaunay triangulation's pieces there: %s): %d vertices there instead of %d",
                      out.report.shells, input.count, out.report.reasons.c_str(), out.report.vertices, out.report.rdtVertices);
        out.warning = text;
    });
    return out;
}

}  // namespace fieldcvt
