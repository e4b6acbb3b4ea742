// The restricted Voronoi diagram, part 2 of 3: each seed's neighbour list and each input vertex's
// nearest seed (rvd_impl.h).
#include "rvd_impl.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace fieldcvt {

using namespace rvd_detail;

namespace {

// nanoflann's k-nearest result set with a known upper bound on the k-th distance: subtrees
// beyond it are skipped from the start. The answer is the same as without the bound as long as
// the bound is not below the true k-th distance.
class BoundedKnnResult {
public:
    using DistanceType = double;  // nanoflann >= 1.5 reads these
    using IndexType = uint32_t;
    BoundedKnnResult(size_t capacity, uint32_t* indices, double* dists, double bound)
        : indices_(indices), dists_(dists), capacity_(capacity)
    {
        dists_[capacity_ - 1] = bound;
    }
    size_t size() const { return count_; }
    bool full() const { return count_ == capacity_; }
    double worstDist() const { return dists_[capacity_ - 1]; }
    bool addPoint(double dist, uint32_t index)
    {
        size_t i = count_;
        for (; i > 0 && dists_[i - 1] > dist; --i)
            if (i < capacity_) dists_[i] = dists_[i - 1], indices_[i] = indices_[i - 1];
        if (i < capacity_) dists_[i] = dist, indices_[i] = index;
        if (count_ < capacity_) ++count_;
        return true;
    }
    void sort() {}  // nanoflann >= 1.5 asks for a sorted result: it always is

private:
    uint32_t* indices_;
    double* dists_;
    size_t capacity_;
    size_t count_ = 0;
};

}  // namespace

inline double RestrictedVoronoiDiagram::Impl::listBound(const Vec3& xi, const uint32_t* list, int count) const
{
    double r2 = 0;
    for (int q = 0; q < count; ++q) r2 = std::max(r2, ((*seeds)[list[q]] - xi).squaredNorm());
    return r2 * (1 + 1e-9) + std::numeric_limits<double>::min();
}

inline bool RestrictedVoronoiDiagram::Impl::listFromCandidates(int i, double drift,
                                                               std::vector<std::pair<double, uint32_t>>& sorted,
                                                               uint32_t* listIndex, double* listDist2, double& certified2)
{
    const Vec3& xi = (*seeds)[i];
    uint32_t* cand = candidateIndex.data() + static_cast<size_t>(i) * candidateCount;
    for (int q = 0; q < candidateCount; ++q) {
        const std::pair<double, uint32_t> entry{((*seeds)[cand[q]] - xi).squaredNorm(), cand[q]};
        int r = q;
        for (; r > 0 && entry < sorted[r - 1]; --r) sorted[r] = sorted[r - 1];
        sorted[r] = entry;
    }
    for (int q = 0; q < candidateCount; ++q) cand[q] = sorted[q].second;
    // Complete up to the radius less both moves (`drift` bounds every seed's but the
    // movers'); a rounding margin keeps the test strict.
    const double complete = candidateRadius[i] - drift - (xi - candidatePosition[i]).norm();
    const double last = sorted[storedNeighbours - 1].first;
    if (!(complete > 0 && last < complete * complete * (1 - 1e-9) && sorted[0].first > 0)) return false;
    // A mover now among the nearest must be one of them already (else the list is incomplete:
    // the k-d tree decides; the rounding margin errs towards that check). Beyond the stored
    // ones the candidates are complete up to the radius and to the nearest mover (which may
    // be missing from them).
    double certified = complete * complete * (1 - 1e-9);
    for (uint32_t j : movers) {
        if (static_cast<int>(j) == i) continue;
        const double dj = ((*seeds)[j] - xi).squaredNorm();
        certified = std::min(certified, dj);
        if (dj > last * (1 + 1e-9)) continue;
        bool listed = false;
        for (int q = 0; q < storedNeighbours && !listed; ++q) listed = sorted[q].second == j;
        if (!listed) return false;
    }
    for (int q = 0; q < storedNeighbours; ++q) listIndex[q] = sorted[q].second, listDist2[q] = sorted[q].first;
    certified2 = certified;
    return true;
}

int RestrictedVoronoiDiagram::Impl::buildNeighbourLists()
{
    const int n = static_cast<int>(seeds->size());
    cloud.points = seeds;
    tree.reset();
    treeBuilt = std::make_unique<std::once_flag>();
    const int stored0 = std::min(kStoredNeighbours, n - 1);
    // The previous evaluation's lists (seeds move little between evaluations) bound the
    // k-th neighbour distance: the seed and its previous neighbours are k seeds.
    const bool previous = stored0 == storedNeighbours && listDistinct.size() == static_cast<size_t>(n) &&
                          neighbourIndex.size() == static_cast<size_t>(n) * stored0;
    storedNeighbours = stored0;
    neighbourIndex.resize(static_cast<size_t>(n) * storedNeighbours);
    neighbourDist2.resize(neighbourIndex.size());
    if (!previous) listDistinct.assign(n, 0);
    duplicate.assign(n, 0);

    // How far the seeds moved since the candidate lists were found.
    const int candidates0 = std::min(kCandidates, n - 1);
    bool useCandidates =
        !rebuildCandidates && candidates0 == candidateCount && candidatePosition.size() == size_t(n) && storedNeighbours > 0;
    double drift = 0;
    movers.clear();
    if (useCandidates) {
        moveSquared.resize(n);
#pragma omp parallel for schedule(static)
        for (int i = 0; i < n; ++i) moveSquared[i] = ((*seeds)[i] - candidatePosition[i]).squaredNorm();
        // The movers: the seeds that moved more than a sixth of the margin (a drift that
        // leaves most lists valid), at most kMaxMovers of them, the farthest; drift: the
        // largest move of the others. Usually there are none and no list pays for them.
        const double moverMove2 = candidateMargin * candidateMargin / 36;
        double drift2 = 0;
        int over = 0;
        for (int i = 0; i < n; ++i) {
            if (moveSquared[i] > moverMove2)
                ++over;
            else
                drift2 = std::max(drift2, moveSquared[i]);
        }
        if (over > kMaxMovers) {  // the (kMaxMovers + 1)-th largest move bounds the others
            moveOrder = moveSquared;
            std::nth_element(moveOrder.begin(), moveOrder.begin() + kMaxMovers, moveOrder.end(), std::greater<double>());
            drift2 = moveOrder[kMaxMovers];
        }
        for (int i = 0; over > 0 && i < n; ++i)
            if (moveSquared[i] > drift2 && moveSquared[i] > moverMove2) movers.push_back(static_cast<uint32_t>(i));
        drift = std::sqrt(drift2);
        // Most lists would fail their test: find new ones now.
        useCandidates = 3 * drift < candidateMargin;
    }
    const bool buildCandidates = !useCandidates && candidates0 > storedNeighbours;
    // The previous candidate lists (distinct seeds) bound the new ones' radius, as above.
    const bool previousCandidates =
        buildCandidates && candidates0 == candidateCount && candidateIndex.size() == static_cast<size_t>(n) * candidateCount;
    if (buildCandidates) {
        candidateCount = candidates0;
        candidatePosition = *seeds;
        candidateIndex.resize(static_cast<size_t>(n) * candidateCount);
        candidateRadius.resize(n);
        drift = 0;
    }
    long long failed = 0;
    certifiedRadius2.assign(n, 0.0);
    std::vector<double> margins(buildCandidates ? n : 0, 0.0);
    const int k = (buildCandidates ? candidateCount : storedNeighbours) + 1;
#pragma omp parallel reduction(+ : failed)
    {
        // Without the candidate lists every seed asks the k-d tree: one thread builds it while
        // the others start (built on first demand, they would wait for it). With them it is
        // built on demand only (a failed list, rare: docs/tuning.md, "RVD: the seeds' k-d tree"); the
        // vertices' fallbacks scan the seeds instead (nearestSeedByScan).
        if (!useCandidates) {
#pragma omp single nowait
            seedTree();
        }
        std::vector<uint32_t> idx(k);
        std::vector<double> d2(k);
        std::vector<std::pair<double, uint32_t>> sorted(candidateCount);
#pragma omp for schedule(dynamic, 256)
        for (int i = 0; i < n; ++i) {
            const Vec3& xi = (*seeds)[i];
            uint32_t* listIndex = neighbourIndex.data() + static_cast<size_t>(i) * storedNeighbours;
            double* listDist2 = neighbourDist2.data() + static_cast<size_t>(i) * storedNeighbours;
            if (useCandidates) {
                if (listFromCandidates(i, drift, sorted, listIndex, listDist2, certifiedRadius2[i])) {
                    listDistinct[i] = 1;
                    continue;
                }
                ++failed;  // the k-d tree as before
            }
            double bound = std::numeric_limits<double>::max();
            if (listDistinct[i] && !buildCandidates)
                bound = listBound(xi, listIndex, storedNeighbours);
            else if (previousCandidates)
                bound = listBound(xi, candidateIndex.data() + static_cast<size_t>(i) * candidateCount, candidateCount);
            const int want = buildCandidates ? k : storedNeighbours + 1;
            BoundedKnnResult knn(want, idx.data(), d2.data(), bound);
            seedTree().findNeighbors(knn, xi.data(), KnnSearchParams());
            size_t found = knn.size();
            if (found < static_cast<size_t>(std::min(want, n))) {  // cannot happen with a true bound; be safe
                found = seedTree().knnSearch(xi.data(), want, idx.data(), d2.data());
            }
            if (buildCandidates) {
                // The candidates: the seeds found, self excluded (a coincident seed stays in;
                // its zero distance sends this seed to the k-d tree in later evaluations).
                uint32_t* cand = candidateIndex.data() + static_cast<size_t>(i) * candidateCount;
                int c = 0;
                for (size_t q = 0; q < found && c < candidateCount; ++q)
                    if (static_cast<int>(idx[q]) != i) cand[c++] = idx[q];
                for (; c < candidateCount; ++c) cand[c] = idx[found - 1];
                candidateRadius[i] = found == static_cast<size_t>(k) ? std::sqrt(d2[found - 1]) : 0.0;
                // The k nearest (self included) were found: every seed nearer than the last
                // is among them.
                if (found == static_cast<size_t>(k)) certifiedRadius2[i] = d2[found - 1];
            }
            listDistinct[i] = found >= static_cast<size_t>(storedNeighbours + 1);
            int stored = 0;
            for (size_t q = 0; q < found && stored < storedNeighbours; ++q) {
                if (static_cast<int>(idx[q]) == i) continue;
                if (d2[q] == 0.0 && static_cast<int>(idx[q]) < i) duplicate[i] = 1;
                listIndex[stored] = idx[q];
                listDist2[stored] = d2[q];
                ++stored;
            }
            // The seed itself was not among the k nearest (many coincident seeds): fill up.
            if (stored < storedNeighbours) listDistinct[i] = 0;
            const size_t lastFound = std::min(found, static_cast<size_t>(storedNeighbours + 1)) - 1;
            for (; stored < storedNeighbours; ++stored) {
                listIndex[stored] = idx[lastFound];
                listDist2[stored] = d2[lastFound];
            }
            if (buildCandidates) margins[i] = candidateRadius[i] - std::sqrt(listDist2[storedNeighbours - 1]);
        }
    }
    if (buildCandidates) {
        std::nth_element(margins.begin(), margins.begin() + n / 2, margins.end());
        candidateMargin = margins[n / 2];
    }
    // Many lists failed their test: find new candidates at the next evaluation.
    rebuildCandidates = !buildCandidates && (!useCandidates || 64 * failed > n);
    return useCandidates ? n - static_cast<int>(failed) : 0;
}

inline int RestrictedVoronoiDiagram::Impl::certifiedNearestSeed(int from, const Vec3& p) const
{
    const int n = static_cast<int>(seeds->size());
    int current = (from >= 0 && from < n && !duplicate[from]) ? from : 0;  // seed 0 is never a duplicate
    double best = ((*seeds)[current] - p).squaredNorm();
    for (int steps = 0; steps < 64; ++steps) {
        const uint32_t* idx = neighbourIndex.data() + static_cast<size_t>(current) * storedNeighbours;
        const double* d2 = neighbourDist2.data() + static_cast<size_t>(current) * storedNeighbours;
        int next = current;
        bool tie = false, certified = false;
        // Seed j, a neighbour of `current` at squared distance dj (nearest first): false when
        // the scan ends, at the security radius (certified) or at a seed nearer to p (the
        // first improvement: move on from there).
        auto scan = [&](uint32_t j, double dj) {
            if (dj > 4.0 * best) {
                certified = true;
                return false;
            }
            if (duplicate[j]) return true;
            const double dp = ((*seeds)[j] - p).squaredNorm();
            if (dp < best) {
                best = dp, next = static_cast<int>(j);
                return false;
            }
            if (dp == best) tie = true;
            return true;
        };
        bool more = true;
        for (int q = 0; q < storedNeighbours && more; ++q) more = scan(idx[q], d2[q]);
        // The stored neighbours did not reach the security radius: the certified candidates.
        if (more) visitCertifiedCandidates(current, scan);
        if (next != current) {
            current = next;
            continue;
        }
        if (certified || storedNeighbours == n - 1) return tie ? -1 : current;
        break;  // the lists did not reach the security radius: ask the tree
    }
    return nearestSeedByScan(p);
}

inline int RestrictedVoronoiDiagram::Impl::nearestSeedByScan(const Vec3& p) const
{
    const std::vector<Vec3>& s = *seeds;
    double best = std::numeric_limits<double>::infinity(), second = best;
    int nearest = -1;
    for (int j = 0; j < static_cast<int>(s.size()); ++j) {
        double d2 = 0;
        for (int k = 0; k < 3; ++k) {
            const double diff = p[k] - s[j][k];
            d2 += diff * diff;
        }
        if (d2 < best)
            second = best, best = d2, nearest = j;
        else if (d2 < second)
            second = d2;
    }
    if (nearest < 0 || second == best || duplicate[nearest]) return -1;
    return nearest;
}

void RestrictedVoronoiDiagram::Impl::computeVertexSeeds(bool borderOnly)
{
    vertexSeed.resize(position.size());
    const int n = borderOnly ? static_cast<int>(borderFaceVertices.size()) : static_cast<int>(position.size());
    constexpr int kVerticesPerChunk = 1024;
    const int chunkCount = (n + kVerticesPerChunk - 1) / kVerticesPerChunk;
#pragma omp parallel for schedule(dynamic, 1)
    for (int c = 0; c < chunkCount; ++c) {
        // Consecutive vertices (Morton order) are close: each walk starts at the previous answer.
        int previous = -1;
        const int end = std::min(n, (c + 1) * kVerticesPerChunk);
        for (int k = c * kVerticesPerChunk; k < end; ++k) {
            const int v = borderOnly ? borderFaceVertices[k] : k;
            const int s = certifiedNearestSeed(previous, position[v]);
            vertexSeed[v] = s;
            if (s >= 0) previous = s;
        }
    }
}

}  // namespace fieldcvt
