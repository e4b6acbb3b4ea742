// remeshRegion (region.h): each piece of the selection remeshed, pinned to its border, stitched.
#include "region.h"

#include "closest_point.h"
#include "errors.h"
#include "valence.h"
#include "working_frame.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>

namespace fieldcvt {

namespace {

std::string format(const char* pattern, double a, double b = 0, double c = 0, double d = 0)
{
    char text[400];
    std::snprintf(text, sizeof text, pattern, a, b, c, d);
    return text;
}

//! The valence optimisation (§4.4) of a pinned patch on its region, the border vertices fixed
//! (VertexRole::Corner): it also raises the small angles the pinning left. At the working scale
//! of remesh(); the border vertices get their exact input coordinates back. False (patch
//! unchanged) if a border vertex cannot be found again.
bool optimiseSeam(const RegionSubmesh& region, RegionPatch& patch, const ValenceParams& params)
{
    const Normalisation frame = workingFrame(region.mesh, std::max(1, patch.mesh.vertexCount()));
    const TriMesh surface = inFrame(region.mesh, frame);
    const ClosestPointTree tree(surface);
    TriMesh work = inFrame(patch.mesh, frame);
    std::vector<VertexRole> roles(work.vertices.size(), VertexRole::Free);
    std::map<std::array<double, 3>, size_t> pinned;  // working position -> patch vertex
    for (size_t v = 0; v < roles.size(); ++v)
        if (patch.original[v] >= 0) {
            roles[v] = VertexRole::Corner;
            pinned[{work.vertices[v].x(), work.vertices[v].y(), work.vertices[v].z()}] = v;
        }
    const ValenceSurface on{surface, tree, {}, nullptr, {}};
    optimizeValence(work, roles, on, params);
    RegionPatch out;
    out.mesh.faces = work.faces;
    for (size_t v = 0; v < work.vertices.size(); ++v) {
        if (roles[v] != VertexRole::Corner) {
            out.mesh.vertices.push_back(frame.fromWork(work.vertices[v]));
            out.original.push_back(-1);
            continue;
        }
        const auto it = pinned.find({work.vertices[v].x(), work.vertices[v].y(), work.vertices[v].z()});
        if (it == pinned.end()) return false;
        out.mesh.vertices.push_back(patch.mesh.vertices[it->second]);
        out.original.push_back(patch.original[it->second]);
    }
    patch = std::move(out);
    return true;
}

//! The parameters of one piece's remesh(): its vertex count, its graded density, the caller's
//! per-vertex data taken to the piece's vertices.
RemeshParams pieceParams(const RemeshParams& params, const RegionSubmesh& region, std::vector<double> mu, double count)
{
    RemeshParams p = params;
    p.vertexCount = std::clamp(int(std::lround(count)), kMinVertexCount, kMaxVertexCount);
    p.closeHolesUnder = 0;  // the piece's border is the seam with the kept faces: it stays open
    p.exactCount = true;    // the pieces split the vertex count between them by area
    if (region.repaired) {
        // Repaired already: a merge of its split copies would make it non-manifold again, and a
        // part dropped now would not be on the border the patch is pinned to.
        p.repairParams.mergeVertices = false;
        p.repairParams.minComponentSamples = 0;
    }
    if (params.density == DensitySource::Uniform && !mu.empty()) {
        p.density = DensitySource::PerVertex;
        p.vertexDensity = std::move(mu);
    } else if (params.density == DensitySource::PerVertex) {
        p.vertexDensity.clear();
        for (int v : region.sourceVertex)
            p.vertexDensity.push_back(size_t(v) < params.vertexDensity.size() ? params.vertexDensity[size_t(v)] : 0.0);
    }
    if (params.fieldSource == FieldSource::User) {
        p.userDirections.clear();
        for (int v : region.sourceVertex)
            p.userDirections.push_back(size_t(v) < params.userDirections.size() ? params.userDirections[size_t(v)]
                                                                                : Vec3::Zero());
    }
    std::map<int, int> local;
    for (size_t v = 0; v < region.originalVertex.size(); ++v) local[region.originalVertex[v]] = int(v);
    p.featureEdges.clear();
    for (const auto& [a, b] : params.featureEdges)
        if (local.count(a) && local.count(b)) p.featureEdges.push_back({local[a], local[b]});
    return p;
}

struct PieceOutcome {
    bool remeshed = false;
    RegionPatch patch;
    std::string reason;         //!< why not remeshed
    bool moreVertices = false;  //!< more vertices may help
};

//! One piece: remesh(), pin its border, optimise the seam, check it. `result` collects the run's
//! warnings, notes, times and evaluations.
PieceOutcome remeshPiece(const RegionSubmesh& region, const RemeshParams& params, const RegionParams& regionParams, double target,
                         const Progress& progress, RemeshResult& result, double& worstRatio, std::vector<std::string>& warnings)
{
    PieceOutcome outcome;
    double ratio = 1;
    std::vector<double> mu = regionDensity(region, target, regionParams, &ratio);
    worstRatio = std::max(worstRatio, ratio);
    if (ratio > regionParams.warnRatio)
        warnings.push_back(
            format("its border edges are up to %.2f times longer or shorter than the target length %.4g; "
                   "beyond %.0f times the triangles along the border may have angles under 20 degrees",
                   ratio, target, regionParams.warnRatio));
    // Vertices of an equilateral mesh with edge 1 / sqrt(mu): 2 / sqrt(3) per unit of mu-weighted area.
    const double area = surfaceArea(region.mesh);
    double count = 2 / std::sqrt(3.0) * area / (target * target);
    if (!mu.empty()) {
        double graded = 0;
        for (int f = 0; f < region.mesh.faceCount(); ++f) {
            const Face& t = region.mesh.faces[size_t(f)];
            graded += faceArea(region.mesh, f) * (mu[size_t(t[0])] + mu[size_t(t[1])] + mu[size_t(t[2])]) / 3;
        }
        graded *= 2 / std::sqrt(3.0);
        // A region too small for the grading to reach the target: the count asked for, uniform.
        if (graded >= kMinVertexCount)
            count = graded;
        else
            mu.clear();
    }
    if (count < kMinVertexCount) {
        outcome.reason = format("it holds %.2g vertices at the target edge length %.4g, fewer than 4", count, target);
        return outcome;
    }
    if (count > kMaxVertexCount) throw InvalidInputError(format("a region needs %.3g vertices: too many", count));
    const RemeshParams p = pieceParams(params, region, std::move(mu), count);
    RemeshResult run;
    try {
        run = remesh(region.mesh, p, progress);
    } catch (const SolverError& e) {
        outcome.reason = e.what();
        return outcome;
    } catch (const InvalidInputError& e) {
        outcome.reason = e.what();
        return outcome;
    }
    for (const StageTime& t : run.stageTimes) {
        auto it = std::find_if(result.stageTimes.begin(), result.stageTimes.end(),
                               [&](const StageTime& s) { return s.stage == t.stage; });
        if (it == result.stageTimes.end())
            result.stageTimes.push_back(t);
        else
            it->seconds += t.seconds;
    }
    result.evaluations += run.evaluations;
    result.threads = run.threads;
    result.energyHistory.insert(result.energyHistory.end(), run.energyHistory.begin(), run.energyHistory.end());
    for (const std::string& w : run.warnings)
        if (w.find("topology not recovered") == std::string::npos) warnings.push_back(w);  // the seam check decides
    result.notes.insert(result.notes.end(), run.notes.begin(), run.notes.end());
    outcome.patch.mesh = std::move(run.mesh);
    if (borderLoops(region.mesh).empty()) {  // a whole closed piece: nothing to pin
        outcome.patch.original.assign(outcome.patch.mesh.vertices.size(), -1);
        outcome.remeshed = true;
        return outcome;
    }
    std::string failure;
    if (!pinBorder(region, outcome.patch.mesh, outcome.patch.original, failure)) {
        outcome.reason = failure;
        outcome.moreVertices = true;
        return outcome;
    }
    if (regionParams.seamOptimisation && params.valenceOptimization) {
        RegionPatch optimised = outcome.patch;
        if (optimiseSeam(region, optimised, params.valence) && patchMatchesBorder(region, optimised))
            outcome.patch = std::move(optimised);
    }
    flipForAngles(outcome.patch);
    if (params.outputInFloat)  // the new vertices only: the border keeps the input's coordinates
        for (size_t v = 0; v < outcome.patch.mesh.vertices.size(); ++v)
            if (outcome.patch.original[v] < 0)
                outcome.patch.mesh.vertices[v] = outcome.patch.mesh.vertices[v].cast<float>().cast<double>();
    if (!patchMatchesBorder(region, outcome.patch)) {
        outcome.reason = "the remeshed faces do not meet the region's border edge to edge";
        return outcome;
    }
    outcome.remeshed = true;
    return outcome;
}

//! The faces of `mesh` that `take` accepts, with only the vertices they use.
template <class Take>
TriMesh facesWhere(const TriMesh& mesh, Take take)
{
    TriMesh part;
    std::vector<int> index(mesh.vertices.size(), -1);
    for (size_t f = 0; f < mesh.faces.size(); ++f) {
        if (!take(f)) continue;
        Face t = mesh.faces[f];
        for (int& v : t) {
            if (index[size_t(v)] < 0) index[size_t(v)] = part.vertexCount(), part.vertices.push_back(mesh.vertices[size_t(v)]);
            v = index[size_t(v)];
        }
        part.faces.push_back(t);
    }
    return part;
}

void appendMesh(TriMesh& to, const TriMesh& from)
{
    const int offset = to.vertexCount();
    to.vertices.insert(to.vertices.end(), from.vertices.begin(), from.vertices.end());
    for (Face t : from.faces) {
        for (int& v : t) v += offset;
        to.faces.push_back(t);
    }
}

//! Table 2's figures of the new faces (`interior`: only those without a border vertex).
QualityMetrics newFaceMetrics(const StitchedMesh& stitched, bool interior)
{
    const TriMesh part = facesWhere(stitched.mesh, [&](size_t f) {
        const Face& t = stitched.mesh.faces[f];
        return stitched.faceOrigin[f] < 0 &&
               !(interior && std::any_of(t.begin(), t.end(), [&](int v) { return stitched.vertexOrigin[size_t(v)] >= 0; }));
    });
    return part.faces.empty() ? QualityMetrics{} : computeQuality(part);
}

void checkSelection(const TriMesh& input, const std::vector<char>& selected, const RemeshParams& params)
{
    checkRemeshParams(params);
    if (selected.size() != input.faces.size())
        throw InvalidInputError("the region has " + std::to_string(selected.size()) + " face flags for " +
                                std::to_string(input.faces.size()) + " faces");
    for (const Face& f : input.faces)
        for (int v : f)
            if (v < 0 || v >= input.vertexCount()) throw InvalidInputError("a face has a vertex index out of range");
    if (std::none_of(selected.begin(), selected.end(), [](char s) { return s != 0; }))
        throw InvalidInputError("the region is empty: no face is selected");
    if (!params.initialSamples.empty()) throw InvalidInputError("initial samples cannot be combined with a region");
}

//! The selection closed where it touches itself at a vertex (closePinches) and around the
//! non-manifold edges on its border (takeInNonManifoldEdges), until neither adds a face: each
//! can make work for the other. Returns the faces added; a note says why.
int closeSelection(const TriMesh& input, std::vector<char>& closed, std::vector<std::string>& notes)
{
    int pinches = 0, nonManifold = 0;
    for (int added = 1; added > 0;) {
        pinches += closePinches(input, closed);
        added = takeInNonManifoldEdges(input, closed);
        nonManifold += added;
    }
    if (pinches > 0)
        notes.push_back("the selection touched itself at a vertex: " + std::to_string(pinches) +
                        " faces around such vertices were added to it");
    if (nonManifold > 0)
        notes.push_back("the selection's border ran along non-manifold edges (more than two faces): their other " +
                        std::to_string(nonManifold) + " faces were added to it, and the edges repaired inside the region");
    return pinches + nonManifold;
}

//! A region made ready to remesh: repaired as remesh() repairs a whole mesh if it is not a
//! manifold, oriented surface (repairRegion), then oriented as the kept faces around it (`conflict`:
//! why that cannot agree with them all). False, with `reason`, when the repair fails.
bool prepareRegion(RegionSubmesh& region, const KeptEdges& kept, double target, int& nextCopyId,
                   std::vector<std::string>& warnings, std::string& reason, std::string& conflict)
{
    if (!regionIsClean(region)) {
        // The budget of the whole-mesh repair: the piece's vertices at the target edge length.
        const double count = 2 / std::sqrt(3.0) * surfaceArea(region.mesh) / (target * target);
        try {
            const RepairReport repair = repairRegion(region, kept, int(std::min(count, double(kMaxVertexCount))), nextCopyId);
            warnings.insert(warnings.end(), repair.notes.begin(), repair.notes.end());
        } catch (const InvalidInputError& e) {
            reason = std::string("its repair failed: ") + e.what();
            return false;
        }
    }
    int against = 0;
    if (const int reversed = orientRegionToKept(region, kept, &against))
        warnings.push_back("reversed " + std::to_string(reversed) + " of its faces to agree with the faces kept around it");
    if (against > 0) {
        conflict = "the faces kept around it run " + std::to_string(against) +
                   " of its border edges the other way than the rest: the input is not consistently oriented there "
                   "(or not orientable through the region)";
        warnings.push_back(conflict);
    }
    return true;
}

//! The last word on a region remesh: manifold and oriented, except for the input's own faults at
//! the faces kept outside the selection (a warning); anything else throws InvalidInputError naming
//! the faults and their likely `causes` (pieces left as they were, orientation conflicts).
void checkStitched(const TriMesh& input, const std::vector<char>& selected, const StitchedMesh& stitched,
                   const std::vector<std::string>& causes, std::vector<std::string>& warnings)
{
    SurfaceFaults kept, elsewhere;
    stitchedFaults(input, selected, stitched, kept, elsewhere);
    if (elsewhere.any()) {
        std::string message = "the remeshed region would leave " + elsewhere.describe() + " in the output";
        for (size_t i = 0; i < causes.size(); ++i) message += (i == 0 ? " (" : "; ") + causes[i];
        throw InvalidInputError(message + (causes.empty() ? "" : ")"));
    }
    if (kept.any())
        warnings.push_back("the output keeps the input's own " + kept.describe() +
                           " at the faces kept outside the region (select those faces to have them repaired)");
}

}  // namespace

RegionRemeshResult remeshRegion(const TriMesh& input, const std::vector<char>& selected, const RemeshParams& params,
                                const RegionParams& regionParams, const Progress& progress)
{
    const auto start = std::chrono::steady_clock::now();
    checkRegionParams(regionParams);
    checkSelection(input, selected, params);
    RegionRemeshResult out;
    RemeshResult& result = out.result;
    if (std::all_of(selected.begin(), selected.end(), [](char s) { return s != 0; })) {
        out.result = remesh(input, params, progress);  // the full remesh, byte for byte
        out.wholeMesh = true;
        out.regions = 1;
        out.vertexOrigin.assign(out.result.mesh.vertices.size(), -1);
        out.faceOrigin.assign(out.result.mesh.faces.size(), -1);
        out.interiorMetrics = out.result.metrics;
        return out;
    }
    std::vector<char> closed = selected;
    out.addedFaces = closeSelection(input, closed, result.notes);
    const KeptEdges kept = keptEdges(input, closed);
    const std::vector<std::vector<int>> pieces = regionComponents(input, closed);
    out.regions = int(pieces.size());
    double area = 0;
    for (int f = 0; f < input.faceCount(); ++f)
        if (closed[size_t(f)]) area += faceArea(input, f);
    out.targetLength = std::sqrt(2 * area / (std::sqrt(3.0) * params.vertexCount));
    std::vector<char> remeshed = closed;  // the faces replaced: pieces kept as they are drop out
    std::vector<RegionPatch> patches;
    std::vector<std::string> causes;  // of faults a refusal names: pieces kept as they are, orientation conflicts
    std::vector<char> repairedFaces(input.faces.size(), 0);
    TriMesh repairedSurfaces;  // what the distances of repaired pieces are measured against
    int nextCopyId = input.vertexCount();
    for (size_t i = 0; i < pieces.size(); ++i) {
        const std::string name = pieces.size() > 1 ? "region " + std::to_string(i + 1) + " of " + std::to_string(pieces.size()) +
                                                         " (" + std::to_string(pieces[i].size()) + " faces): "
                                                   : "region (" + std::to_string(pieces[i].size()) + " faces): ";
        const Progress pieceProgress = [&](const std::string& stage, double percent) {
            return !progress || progress(stage, (double(i) + percent / 100) / double(pieces.size()) * 100);
        };
        std::vector<std::string> warnings;
        PieceOutcome piece;
        RegionSubmesh region = extractRegion(input, pieces[i]);
        std::string conflict;
        if (prepareRegion(region, kept, out.targetLength, nextCopyId, warnings, piece.reason, conflict)) {
            if (!region.repaired) {
                piece = remeshPiece(region, params, regionParams, out.targetLength, pieceProgress, result, out.worstBorderRatio,
                                    warnings);
            } else {
                // Part by part: one that cannot be remeshed (a strip the repair cut off, too small
                // for the target) stays as repaired, a manifold, oriented surface still.
                const std::vector<RegionSubmesh> parts = regionParts(region);
                for (size_t k = 0; k < parts.size(); ++k) {
                    PieceOutcome part = remeshPiece(parts[k], params, regionParams, out.targetLength, pieceProgress, result,
                                                    out.worstBorderRatio, warnings);
                    if (!part.remeshed) {
                        warnings.push_back("its part " + std::to_string(k + 1) + " of " + std::to_string(parts.size()) + " (" +
                                           std::to_string(parts[k].mesh.faceCount()) + " faces): " + part.reason +
                                           ": kept as repaired");
                        part.patch = {parts[k].mesh, parts[k].originalVertex};
                    }
                    patches.push_back(std::move(part.patch));
                }
                piece.remeshed = true;
                for (int f : pieces[i]) repairedFaces[size_t(f)] = 1;
                appendMesh(repairedSurfaces, region.mesh);
            }
        }
        if (!piece.remeshed) {
            warnings.push_back(piece.reason + ": kept as it is" + (piece.moreVertices ? " (try more vertices)" : ""));
            causes.push_back(name + piece.reason + (piece.moreVertices ? " (try more vertices)" : ""));
        }
        if (!conflict.empty()) causes.push_back(name + conflict);
        for (size_t w = 0; w < warnings.size(); ++w)  // once: the parts of a repaired piece may repeat one
            if (std::find(warnings.begin(), warnings.begin() + long(w), warnings[w]) == warnings.begin() + long(w))
                result.warnings.push_back(name + warnings[w]);
        if (!piece.remeshed) {
            ++out.keptRegions;
            for (int f : pieces[i]) remeshed[size_t(f)] = 0;
            continue;
        }
        for (char b : region.border) out.borderVertices += b;
        if (!region.repaired) patches.push_back(std::move(piece.patch));
    }
    StitchedMesh stitched = stitchRegions(input, remeshed, patches);
    checkStitched(input, closed, stitched, causes, result.warnings);
    result.metrics = newFaceMetrics(stitched, false);
    out.interiorMetrics = newFaceMetrics(stitched, true);
    if (params.computeDistances && !patches.empty()) {
        // Against the selected input faces that were replaced, as repaired where they were (the
        // whole-mesh remesh measures against its repaired input too: a dropped fin is no error).
        const TriMesh newFaces = facesWhere(stitched.mesh, [&](size_t f) { return stitched.faceOrigin[f] < 0; });
        TriMesh oldFaces = facesWhere(input, [&](size_t f) { return remeshed[f] != 0 && !repairedFaces[f]; });
        appendMesh(oldFaces, repairedSurfaces);
        const DistanceMetrics d = computeDistance(newFaces, oldFaces, std::max(1000, params.distanceSamples));
        result.metrics.dRms = d.rms;
        result.metrics.dH = d.hausdorff;
    }
    result.inputTopology = computeTopology(input);
    result.outputTopology = computeTopology(stitched.mesh);
    result.mesh = std::move(stitched.mesh);
    out.vertexOrigin = std::move(stitched.vertexOrigin);
    out.faceOrigin = std::move(stitched.faceOrigin);
    result.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace fieldcvt
