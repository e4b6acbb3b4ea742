#pragma once
// The valence stage's operations (§4.4): edge flips, edge collapses and vertex splits, their
// effect on R, the look-ahead chains (R-neutral flips ending in an operation that lowers R), and
// applying them to the mesh with local smoothing, kept only where the geometry stays valid.
#include "valence/sag_guard.h"
#include "valence/valence_mesh.h"

#include <array>
#include <cstdint>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace fieldcvt::valence {

//! Also the tie-break between candidates of equal gain: splits before collapses keeps the vertex
//! count near the target (see docs/tuning.md, "Operation order").
enum class OpType : std::uint8_t { Flip = 0, Split = 1, Collapse = 2, None = 3 };

//! One topological operation. Flip: edge (a, b), a < b. Collapse: edge (a, b), a < b. Split:
//! vertex a, its ring cut at neighbours b and c (a keeps the neighbours from b counter-clockwise
//! to c, the new vertex those from c to b).
struct Op {
    OpType type = OpType::None;
    int a = -1, b = -1, c = -1;
    int gain = 0;  //!< ΔR of this operation on the mesh it applies to
    auto key() const { return std::make_tuple(static_cast<int>(type), a, b, c, gain); }
};

//! The longest chain the look-ahead builds (R-neutral flips, then one operation lowering R).
constexpr int kMaxChain = 8;

//! A proposal for an irregular vertex: one operation, or (look-ahead) a chain of R-neutral
//! flips followed by an operation they make possible. `gain` is the total ΔR (< 0 is better).
struct Candidate {
    int gain = 0;
    int length = 0;
    std::array<Op, kMaxChain> ops;
    //! The vertices the chain reads and changes (before it is applied): unlocked, unchanged ones
    //! make it still valid. Not part of the key.
    std::vector<int> region;

    bool compound() const { return length > 1; }
    bool operator<(const Candidate& o) const
    {
        if (gain != o.gain) return gain < o.gain;
        if (length != o.length) return length < o.length;  // shorter chains first
        for (int k = 0; k < length; ++k)
            if (ops[k].key() != o.ops[k].key()) return ops[k].key() < o.ops[k].key();
        return false;
    }
    bool operator==(const Candidate& o) const { return !(*this < o) && !(o < *this); }
};

struct CandidateHash {
    size_t operator()(const Candidate& k) const;
};

// --- evaluation (operations.cpp) ------------------------------------------------------------
//! Whether edge (a, b) may be flipped, its faces (a, b, c) = f1 and (b, a, d) = f2, and ΔR.
bool evaluateFlip(const ValenceMesh& mesh, int a, int b, int& gain, int& c, int& d, int& f1, int& f2);
//! Whether edge (a, b) may be collapsed, which end it keeps, and ΔR.
bool evaluateCollapse(const ValenceMesh& mesh, int a, int b, int& gain, int& keep, int& remove);
//! The single operations around irregular vertex v that lower R (ΔR < 0), or with
//! `zeroGainFlips` the flips around v that leave R unchanged (look-ahead first steps).
void collectOperations(const ValenceMesh& mesh, int v, bool zeroGainFlips, std::vector<Op>& out);
//! Vertices that must be unlocked (and unchanged since the candidate was made) for `op`.
void involvedVertices(const ValenceMesh& mesh, const Op& op, std::vector<int>& out);
//! A single-operation candidate with its region.
Candidate single(const ValenceMesh& mesh, const Op& op);
//! Re-checks `op` (topology and ΔR) on the current mesh and applies its topology, with the
//! first positions of the vertices it creates or merges; adds the vertices to smooth to
//! `smooth` and the removed / created ones to `changed`. Needs an open log (the caller rolls a
//! failure back).
bool applyTopology(ValenceMesh& mesh, const Op& op, std::vector<int>& smooth, std::vector<int>& changed);

// --- look-ahead (chains.cpp) ----------------------------------------------------------------
//! The chains of every irregular vertex (at most min(lookAheadDepth, kMaxChain) operations),
//! appended to `out` in vertex order. In parallel: the search applies operations tentatively and
//! rolls them back, so each thread but the first searches on its own copy of the mesh; every
//! vertex's search starts from the same state, so the list is the one a single thread makes.
void collectAllChains(ValenceMesh& mesh, int lookAheadDepth, std::vector<Candidate>& out);

// --- applying (apply.cpp) -------------------------------------------------------------------
//! Applies sorted candidates greedily, each where its region is unlocked this round and has
//! changed since it last failed, with local smoothing; keeps one only if the geometry stays
//! valid (no fold, no sharper angle under the minimum, no more sag than the guard allows).
class OperationApplier {
public:
    OperationApplier(ValenceMesh& mesh, SagGuard& sag, const ValenceParams& params) : mesh_(mesh), sag_(sag), params_(params) {}
    //! Applies `candidates` (sorted) in round `round`; returns how many; counts the operations in `stats`.
    int apply(const std::vector<Candidate>& candidates, int round, ValenceStats& stats);

private:
    //! Applies `c` with local smoothing; keeps it only if the geometry stays valid. Fills the
    //! vertices it changed into `changed`.
    bool tryApply(const Candidate& c, std::vector<int>& changed);

    ValenceMesh& mesh_;
    SagGuard& sag_;
    const ValenceParams& params_;
    std::vector<int> lockStamp_;          //!< per vertex, the round it was last changed in
    std::vector<long long> changeStamp_;  //!< per vertex, opCounter_ when it or a neighbour last changed
    long long opCounter_ = 0;             //!< operations committed so far
    //! Candidates that failed the geometric checks, with opCounter_ at the time: retried only
    //! once one of their vertices changed.
    std::unordered_map<Candidate, long long, CandidateHash> failed_;
};

}  // namespace fieldcvt::valence
