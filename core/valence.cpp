// The valence stage (§4.4), the round loop over its parts in core/valence/: the mesh being
// optimised (valence_mesh), the sag guard (sag_guard), the operations and their look-ahead
// chains (operations, chains, apply), the relaxation (relax) and the repairs (repairs).
#include "valence.h"

#include "errors.h"
#include "metrics.h"
#include "valence/operations.h"
#include "valence/relax.h"
#include "valence/repairs.h"
#include "valence/sag_guard.h"
#include "valence/valence_mesh.h"

#include <algorithm>
#include <string>
#include <vector>

namespace fieldcvt {

namespace {

using namespace valence;

void checkInput(const TriMesh& mesh, const std::vector<VertexRole>& roles, const ValenceSurface& surface,
                const ValenceParams& params)
{
    const int n = mesh.vertexCount();
    for (const Face& f : mesh.faces)
        for (int v : f)
            if (v < 0 || v >= n) throw InvalidInputError("optimizeValence: a face refers to a missing vertex");
    if (!roles.empty() && static_cast<int>(roles.size()) != n)
        throw InvalidInputError("optimizeValence: " + std::to_string(roles.size()) + " vertex roles for " + std::to_string(n) +
                                " vertices");
    if (surface.field && (surface.field->normals.size() != surface.input.vertices.size() ||
                          surface.field->directions.size() != surface.input.vertices.size()))
        throw InvalidInputError("optimizeValence: the field does not match the input surface");
    if (params.maxRounds < 0 || params.localSmoothing < 0 || params.relaxIterations < 0)
        throw InvalidInputError("optimizeValence: negative round or iteration count");
    for (int f = 0; f < mesh.faceCount(); ++f) {
        const Face& t = mesh.faces[f];
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
            throw InvalidInputError("optimizeValence: face " + std::to_string(f) + " repeats a vertex");
    }
}

//! One round's candidates: per irregular vertex the single operations that lower R, or (the
//! look-ahead pass) the chains; sorted by gain (ties by kind and index), without repeats.
void collectCandidates(ValenceMesh& mesh, bool lookAhead, int lookAheadDepth, std::vector<Candidate>& candidates)
{
    candidates.clear();
    if (lookAhead) {
        collectAllChains(mesh, lookAheadDepth, candidates);
    } else {
        std::vector<Op> operations;
        for (int v = 0; v < mesh.vertexCount(); ++v) {
            if (!mesh.vertexAlive(v) || !mesh.data(v).manifold || mesh.data(v).valence == mesh.target(v)) continue;
            operations.clear();
            collectOperations(mesh, v, false, operations);
            for (const Op& op : operations) candidates.push_back(single(mesh, op));
        }
    }
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
}

//! §4.4's rounds: the candidates applied greedily where nothing has changed yet; when no single
//! operation is left, the look-ahead chains (R-neutral flips, then an operation they enable).
void applyRounds(ValenceMesh& mesh, SagGuard& sag, const ValenceParams& params, ValenceStats& stats)
{
    OperationApplier applier(mesh, sag, params);
    std::vector<Candidate> candidates;
    for (int round = 1; round <= params.maxRounds; ++round) {
        int applied = 0;
        bool lookAhead = false;
        for (int pass = 0; pass < (params.lookAheadDepth >= 2 ? 2 : 1) && applied == 0; ++pass) {
            lookAhead = pass == 1;
            collectCandidates(mesh, lookAhead, params.lookAheadDepth, candidates);
            applied = applier.apply(candidates, round, stats);
        }
        stats.rounds = round;
        if (applied == 0) break;
        if (lookAhead && applied < params.minChainsPerRound) break;  // diminishing returns (minChainsPerRound)
    }
}

}  // namespace

ValenceStats optimizeValence(TriMesh& mesh, std::vector<VertexRole>& roles, const ValenceSurface& surface,
                             const ValenceParams& params, const std::vector<int>& faceHints)
{
    if (!faceHints.empty() && faceHints.size() != mesh.vertices.size())
        throw InvalidInputError("optimizeValence: " + std::to_string(faceHints.size()) + " face hints for " +
                                std::to_string(mesh.vertices.size()) + " vertices");
    ValenceStats stats;
    if (mesh.faces.empty()) {
        if (roles.empty()) roles.assign(mesh.vertices.size(), VertexRole::Free);
        return stats;
    }
    checkInput(mesh, roles, surface, params);
    ValenceMesh optimised(mesh, roles, surface, params.borderWeight, faceHints);
    SagGuard sag(optimised);
    stats.v6Before = v6Percent(mesh);
    stats.verticesBefore = mesh.vertexCount();
    stats.irregularityBefore = optimised.irregularity();
    stats.fieldDistanceBefore = optimised.meanFieldDistance();

    applyRounds(optimised, sag, params, stats);
    stats.irregularityAfter = optimised.irregularity();
    stats.fieldDistanceOperations = optimised.meanFieldDistance();
    relax(optimised, sag, params);
    raiseSmallestAngles(optimised, sag, params);
    lowerLargestSags(optimised, sag, params);
    stats.fieldDistanceAfter = optimised.meanFieldDistance();
    optimised.compact(mesh, roles);
    stats.v6After = v6Percent(mesh);
    stats.verticesAfter = mesh.vertexCount();
    return stats;
}

}  // namespace fieldcvt
