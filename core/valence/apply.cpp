#include "valence/operations.h"

#include <algorithm>

namespace fieldcvt::valence {

bool OperationApplier::tryApply(const Candidate& cand, std::vector<int>& changed)
{
    changed.clear();
    const std::vector<int>& region = cand.region;  // faces around it are compared before and after
    std::vector<int> faces;
    mesh_.facesAround(region, faces);
    double angleBefore, dotBefore;
    mesh_.localShape(faces, angleBefore, dotBefore);
    const double sagLimit = sag_.operationLimit(faces);

    const auto mark = mesh_.begin();
    std::vector<int> smooth;
    bool ok = true;
    for (int k = 0; k < cand.length && ok; ++k) {
        ok = applyTopology(mesh_, cand.ops[k], smooth, changed);
        if (ok) mesh_.refreshValences(smooth);
    }
    if (ok) {
        std::sort(smooth.begin(), smooth.end());
        smooth.erase(std::unique(smooth.begin(), smooth.end()), smooth.end());
        mesh_.smoothLocally(smooth, params_.localSmoothing);
        std::vector<int> after = region;
        after.insert(after.end(), smooth.begin(), smooth.end());
        mesh_.facesAround(after, faces);
        double angleAfter, dotAfter;
        mesh_.localShape(faces, angleAfter, dotAfter);
        const double minAngle = params_.minAngleDegrees * kPi / 180.0;
        const bool folded = dotAfter < std::min(kMinNormalDot, dotBefore);
        const bool sharper = angleAfter < minAngle && angleAfter < angleBefore - 1e-9;
        // A flip or collapse across a crease cuts it (d_H): refused like a fold (measured last,
        // the costliest test).
        ok = !folded && !sharper && angleAfter > 0 && !sag_.exceedsAny(faces, sagLimit);
    }
    if (!ok) {
        mesh_.rollback(mark);
        changed.clear();
        return false;
    }
    mesh_.commit(mark);
    changed.insert(changed.end(), smooth.begin(), smooth.end());
    return true;
}

int OperationApplier::apply(const std::vector<Candidate>& candidates, int round, ValenceStats& stats)
{
    std::vector<int> changed;
    Ring r;
    int applied = 0;
    lockStamp_.resize(mesh_.vertexCount(), 0);
    changeStamp_.resize(mesh_.vertexCount(), 0);
    for (const Candidate& cand : candidates) {
        if (cand.gain >= 0) continue;
        bool locked = false;
        long long lastChange = 0;
        for (int v : cand.region) {
            locked |= lockStamp_[v] == round;
            lastChange = std::max(lastChange, changeStamp_[v]);
        }
        if (locked) continue;
        const auto failure = failed_.find(cand);
        if (failure != failed_.end() && failure->second >= lastChange) continue;  // nothing new since
        if (!tryApply(cand, changed)) {
            failed_[cand] = opCounter_;
            continue;
        }
        ++applied;
        ++opCounter_;  // changes are stamped after the count, failures before it
        for (int k = 0; k < cand.length; ++k) {
            const Op& op = cand.ops[k];
            if (op.type == OpType::Flip)
                ++stats.flips;
            else if (op.type == OpType::Collapse)
                ++stats.collapses;
            else if (op.type == OpType::Split)
                ++stats.splits;
        }
        // Lock the changed vertices for this round (their rings are no longer the ones the
        // candidates were computed on) and mark their neighbourhood as changed.
        lockStamp_.resize(mesh_.vertexCount(), 0);  // (a split's new vertex)
        changeStamp_.resize(mesh_.vertexCount(), 0);
        for (int v : changed) {
            lockStamp_[v] = round;
            changeStamp_[v] = opCounter_;
            if (!mesh_.vertexAlive(v)) continue;
            mesh_.ring(v, r);
            for (int w : r.verts) changeStamp_[w] = opCounter_;
        }
    }
    return applied;
}

}  // namespace fieldcvt::valence
