// §4.4 look-ahead, deepened: the defects left after the greedy rounds are mostly isolated 5–7
// pairs (dislocations) and lone 5s / 7s. No single operation lowers R there, but an R-neutral
// flip moves a 5–7 pair by one edge; a few such moves bring it next to another defect, where a
// flip, collapse or split annihilates both. Depth-first, bounded by the look-ahead depth.
#include "valence/operations.h"

#include <omp.h>
#include <algorithm>
#include <memory>
#include <tuple>

namespace fieldcvt::valence {

namespace {

bool irregular(const ValenceMesh& mesh, int v)
{
    return mesh.vertexAlive(v) && mesh.data(v).manifold && mesh.data(v).valence != mesh.target(v);
}

//! Buffers shared by every level of one vertex's search (used within a level, never across).
struct Scratch {
    std::vector<int> around, involved;
    std::vector<Op> finals;
    Ring ring;
};

//! The best R-lowering operation among the irregular vertices of the flipped quad `quad` and
//! their neighbours (the operation that ends a chain must use what the move changed), or none.
bool bestFinal(const ValenceMesh& mesh, const std::vector<int>& quad, Scratch& scratch, Op& best)
{
    std::vector<int>& around = scratch.around;
    around = quad;
    for (int x : quad) {
        mesh.ring(x, scratch.ring);
        around.insert(around.end(), scratch.ring.verts.begin(), scratch.ring.verts.end());
    }
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    std::vector<Op>& finals = scratch.finals;
    finals.clear();
    for (int x : around)
        if (mesh.data(x).manifold && mesh.data(x).valence != mesh.target(x)) collectOperations(mesh, x, false, finals);
    const Op* found = nullptr;
    for (const Op& op : finals)
        if (!found || std::make_tuple(op.gain, op.key()) < std::make_tuple(found->gain, found->key())) found = &op;
    if (found) best = *found;
    return found != nullptr;
}

//! `chain` ended by `last`, its region the vertices that existed before the chain, sorted.
Candidate finished(const ValenceMesh& mesh, const Candidate& chain, const Op& last, int existing, std::vector<int>& involved)
{
    Candidate found = chain;
    found.ops[found.length++] = last;
    found.gain = chain.gain + last.gain;
    involvedVertices(mesh, last, involved);
    found.region.insert(found.region.end(), involved.begin(), involved.end());
    found.region.erase(std::remove_if(found.region.begin(), found.region.end(), [existing](int x) { return x >= existing; }),
                       found.region.end());
    std::sort(found.region.begin(), found.region.end());
    found.region.erase(std::unique(found.region.begin(), found.region.end()), found.region.end());
    return found;
}

//! One level of the chain search: each R-neutral flip at the irregular vertices of `from`,
//! applied tentatively, then either the best R-lowering operation around it ends the chain or,
//! if there is none and the depth allows, the search goes on from the flipped quad.
void extendChain(ValenceMesh& mesh, int depth, const std::vector<int>& from, Candidate& chain, Scratch& scratch,
                 std::vector<Candidate>& out)
{
    const int existing = mesh.vertexCount();  // the region holds only these
    std::vector<Op> moves;
    for (int x : from)
        if (irregular(mesh, x)) collectOperations(mesh, x, true, moves);
    std::sort(moves.begin(), moves.end(), [](const Op& p, const Op& q) { return p.key() < q.key(); });
    moves.erase(std::unique(moves.begin(), moves.end(), [](const Op& p, const Op& q) { return p.key() == q.key(); }),
                moves.end());
    std::vector<int> involved, smooth, changed;
    for (const Op& move : moves) {
        int gain, c, d, f1, f2;
        if (!evaluateFlip(mesh, move.a, move.b, gain, c, d, f1, f2)) continue;
        // Flipping back the edge the previous move created only returns to where we were.
        if (chain.length > 0) {
            const Op& last = chain.ops[chain.length - 1];
            if (last.type == OpType::Flip && std::minmax(c, d) == std::minmax(last.a, last.b)) continue;
        }
        involvedVertices(mesh, move, involved);
        const auto mark = mesh.begin();
        smooth.clear();
        changed.clear();
        if (applyTopology(mesh, move, smooth, changed)) {
            mesh.refreshValences(smooth);
            const size_t regionSize = chain.region.size();
            chain.ops[chain.length++] = move;
            chain.region.insert(chain.region.end(), involved.begin(), involved.end());
            Op last;
            if (bestFinal(mesh, smooth, scratch, last)) {
                out.push_back(finished(mesh, chain, last, existing, scratch.involved));
            } else if (chain.length + 1 < std::min(depth, kMaxChain)) {
                const std::vector<int> quad = smooth;
                extendChain(mesh, depth, quad, chain, scratch, out);
            }
            --chain.length;
            chain.region.resize(regionSize);
        }
        mesh.rollback(mark);
    }
}

}  // namespace

void collectAllChains(ValenceMesh& mesh, int lookAheadDepth, std::vector<Candidate>& out)
{
    std::vector<int> starts;
    for (int v = 0; v < mesh.vertexCount(); ++v)
        if (irregular(mesh, v)) starts.push_back(v);
    std::vector<std::vector<Candidate>> found(starts.size());
    // Copying the mesh costs about one search of a few dozen vertices: not for small lists.
    const bool parallel = omp_get_max_threads() > 1 && starts.size() >= 64;
#pragma omp parallel if (parallel)
    {
        std::unique_ptr<ValenceMesh> copy;
        if (omp_get_thread_num() > 0) copy = std::make_unique<ValenceMesh>(mesh);
        ValenceMesh& own = copy ? *copy : mesh;
#pragma omp barrier
        // (no thread changes the mesh before every copy is made)
#pragma omp for schedule(dynamic, 4)
        for (long long k = 0; k < static_cast<long long>(starts.size()); ++k) {
            Candidate chain;
            Scratch scratch;
            extendChain(own, lookAheadDepth, {starts[size_t(k)]}, chain, scratch, found[size_t(k)]);
        }
    }
    for (std::vector<Candidate>& list : found)
        for (Candidate& c : list) out.push_back(std::move(c));
}

}  // namespace fieldcvt::valence
