#include "rvd.h"

#include "closest_point.h"
#include "errors.h"
#include "point_tree.h"

#include <Eigen/Geometry>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <mutex>
#include <string>

namespace fieldcvt {

double RvdResult::totalEnergy() const
{
    double e = 0;
    for (double v : energy) e += v;
    return e;
}

std::vector<int> mortonIndexOrder(const std::vector<Vec3>& points)
{
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max()), hi = -lo;
    for (const Vec3& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const Vec3 extent = (hi - lo).cwiseMax(Vec3::Constant(1e-300));
    auto spread = [](uint64_t x) {  // 21 bits -> every third bit of 63
        x &= 0x1fffff;
        x = (x | x << 32) & 0x1f00000000ffffULL;
        x = (x | x << 16) & 0x1f0000ff0000ffULL;
        x = (x | x << 8) & 0x100f00f00f00f00fULL;
        x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
        x = (x | x << 2) & 0x1249249249249249ULL;
        return x;
    };
    std::vector<std::pair<uint64_t, int>> keys(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
        const Vec3 q = ((points[i] - lo).array() / extent.array() * 2097151.0).matrix();
        keys[i] = {spread(static_cast<uint64_t>(q.x())) | spread(static_cast<uint64_t>(q.y())) << 1 |
                       spread(static_cast<uint64_t>(q.z())) << 2,
                   static_cast<int>(i)};
    }
    std::sort(keys.begin(), keys.end());
    std::vector<int> order(points.size());
    for (size_t i = 0; i < keys.size(); ++i) order[i] = keys[i].second;
    return order;
}

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

// A convex polygon inside one input triangle. label[k] names what created the edge from
// vertex k to vertex k+1: a seed index j >= 0 for the bisector of (i, j), or -1 - e for the
// triangle's own edge e (from its corner e to corner e+1). A convex polygon gains at most one vertex per clipping plane.
constexpr int kMaxPolygonVertices = 96;
struct Polygon {
    int size = 0;
    Vec3 point[kMaxPolygonVertices];
    int label[kMaxPolygonVertices];
};

constexpr int kTrianglesPerChunk = 256;  // fixed, so results do not depend on the thread count
constexpr int kStoredNeighbours = 12;    // per seed: covers the security radius almost always (measured: 12 ~ 20, faster)
constexpr int kMaxMovers = 32;           // seeds checked against every candidate list (movers)
constexpr int kCandidates = 36;          // per seed in the candidate lists (twice the stored neighbours)

// Integrals over the part of one cell in consecutive triangles of a chunk.
struct CellPiece {
    int seed;
    double mass;
    Vec3 moment;
    double energy;
};

// Length and first moment of the input's border inside one cell, in one triangle.
struct BorderPiece {
    int seed;
    double length;
    Vec3 moment;
};

// The polygon of one cell in one input triangle, for the connected pieces of the cells
// (RvdOptions::triangles): its seed, its triangle and the closest point of the seed on it.
struct Fragment {
    int seed;
    int face;
    Vec3 point;
    double distance2;
};

// Fragment `fragment` (chunk-local) has an edge on the input edge shared with `face`.
struct FragmentLink {
    int fragment;
    int face;
};

// An RDT triangle found in input triangle `face`: corners are chunk-local fragment indices, or
// -1 - seed when no fragment of that seed is in `face` (degenerate: the RVD vertex is on its
// border).
struct RawTriangle {
    std::array<int, 3> corner;
    int face;
};

// Cache-line aligned: neighbouring chunks and threads' scratch spaces are written by
// different threads at once (vector ends, counters), and must not share lines.
struct alignas(64) ChunkOutput {
    std::vector<CellPiece> pieces;
    std::vector<BorderPiece> borderPieces;
    std::vector<RvdEdge> edges;
    std::vector<Fragment> fragments;
    std::vector<FragmentLink> links;
    std::vector<RawTriangle> triangles;
    long long clipped = 0;
    void clear()
    {
        pieces.clear();
        borderPieces.clear();
        edges.clear();
        fragments.clear();
        links.clear();
        triangles.clear();
        clipped = 0;
    }
};

// Per-thread work space, reused across evaluations (no allocation in steady state).
struct alignas(64) Scratch {
    std::vector<int> stack;
    std::vector<int> visited;
    std::vector<uint32_t> extraIndex;
    std::vector<double> extraDist;
    std::vector<uint32_t> atCovered;  // clipToCell: the seeds visited at the largest distance so far
};

std::array<int, 3> canonicalTriangle(int a, int b, int c)
{
    // Rotate so the smallest index comes first; the cyclic order (orientation) is kept.
    if (a < b && a < c) return {a, b, c};
    if (b < a && b < c) return {b, c, a};
    return {c, a, b};
}

}  // namespace

struct RestrictedVoronoiDiagram::Impl {
    // The surface renumbered: vertices in Morton order, faces in Morton order of their
    // centroids (corners in their input order). The passes over triangles and vertices then read
    // memory sequentially; random access to the input's arrays was the main cost on big meshes.
    std::vector<Vec3> position;              // per vertex
    std::vector<Face> faces;                 // per face, corners index `position`
    std::vector<Vec3> unitNormals;           // per face
    std::vector<unsigned char> borderEdges;  // per face: bit e set if edge e has no other face
    std::vector<int> borderFaceVertices;     // the corners of the faces with a border edge, ascending
    std::vector<int> neighbourFace;          // per face edge (3f + e): the face across it, -1 if none or several
    std::vector<double> density;             // per face: ρ (empty: ρ = 1)
    std::vector<ChunkOutput> chunks;
    std::vector<Scratch> scratch;

    // Per evaluation.
    const std::vector<Vec3>* seeds = nullptr;
    PointCloud cloud;  // the seeds, for their k-d tree (point_tree.h)
    // The k-d tree of the seeds, built on first use in an evaluation: with the candidate lists
    // most evaluations need it only for rare fallbacks (0.8 ms of ~15 for bunny 5000).
    mutable std::unique_ptr<PointTree> tree;
    mutable std::unique_ptr<std::once_flag> treeBuilt;
    const PointTree& seedTree() const
    {
        std::call_once(*treeBuilt,
                       [this] { tree = std::make_unique<PointTree>(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10)); });
        return *tree;
    }
    std::vector<uint32_t> neighbourIndex;  // n * kStoredNeighbours, nearest first, self excluded
    std::vector<double> neighbourDist2;
    std::vector<char> duplicate;     // seed coincides with a lower-index seed: empty cell, no bisector
    std::vector<char> listDistinct;  // the stored neighbours of the seed are distinct seeds (no fill-up)
    std::vector<int> vertexSeed;     // per input vertex: the seed whose cell contains it, -1 on a tie
    std::vector<int> edgeStart;      // work space of the edge merge
    std::vector<RvdEdge> edgeBuffer;
    int storedNeighbours = 0;

    // Candidate lists (Verlet lists of molecular dynamics): per seed its kCandidates nearest
    // seeds at the positions `candidatePosition` they were found at, and the distance of the
    // last one (the radius). Every seed nearer than that at the time is in the list; a seed
    // that is not was at least the radius away and is now at least (radius - own move - largest
    // move of any seed) away. While the 12th nearest candidate is nearer than that, the nearest
    // candidates are the nearest seeds: the neighbour lists come from a sort of a few distances
    // instead of a k-d tree search. L-BFGS steps move the seeds little, so the lists serve many
    // evaluations (listFromCandidates).
    std::vector<Vec3> candidatePosition;
    std::vector<uint32_t> candidateIndex;  // n * candidateCount, kept sorted by the last distances
    std::vector<double> candidateRadius;   // per seed: distance of its last candidate when found
    double candidateMargin = 0;            // median of (candidate radius - stored radius) at the build
    int candidateCount = 0;
    bool rebuildCandidates = true;
    // The seeds that moved more than a sixth of the candidate margin since the candidate lists
    // were found ("movers", at most kMaxMovers, the farthest): every list is checked against them
    // explicitly, so that the drift bound (`drift` of listFromCandidates) is the largest move of
    // the others. One L-BFGS step that sends a handful of seeds far used to invalidate every list
    // (bunny 5000: a rebuild every 3-4 evaluations, each ~10 ms on one thread, most triggered by
    // 1-6 seeds).
    std::vector<uint32_t> movers;
    // Per seed: its candidate list (candidateIndex) is, in this evaluation, sorted by distance
    // and complete below this squared distance (every seed nearer is in it); 0 = not known.
    // Where the stored neighbours do not reach a security radius, the candidates beyond them
    // serve before the k-d tree (which is then not built in most evaluations).
    std::vector<double> certifiedRadius2;
    std::vector<double> moveSquared, moveOrder;  // per seed, work space

    void buildPieces(RvdResult& result) const;

    Impl(const TriMesh& s, const std::vector<double>& faceDensity)
    {
        if (!faceDensity.empty()) {
            if (faceDensity.size() != s.faces.size())
                throw InvalidInputError("the density has " + std::to_string(faceDensity.size()) + " values for " +
                                        std::to_string(s.faces.size()) + " faces");
            for (double rho : faceDensity)
                if (!std::isfinite(rho) || !(rho > 0)) throw InvalidInputError("the density must be finite and > 0");
        }
        const std::vector<int> vertexOrder = mortonIndexOrder(s.vertices);
        std::vector<int> vertexRank(s.vertices.size());
        position.resize(s.vertices.size());
        for (size_t k = 0; k < vertexOrder.size(); ++k) {
            vertexRank[vertexOrder[k]] = static_cast<int>(k);
            position[k] = s.vertices[vertexOrder[k]];
        }
        std::vector<Vec3> centroids(s.faces.size());
        for (int f = 0; f < s.faceCount(); ++f)
            centroids[f] = (s.vertices[s.faces[f][0]] + s.vertices[s.faces[f][1]] + s.vertices[s.faces[f][2]]) / 3.0;
        const std::vector<int> faceOrder = mortonIndexOrder(centroids);
        faces.resize(s.faces.size());
        unitNormals.resize(s.faces.size());
        for (size_t k = 0; k < faceOrder.size(); ++k) {
            const Face& f = s.faces[faceOrder[k]];
            faces[k] = {vertexRank[f[0]], vertexRank[f[1]], vertexRank[f[2]]};
            const Vec3 n = faceNormal(s, faceOrder[k]);
            const double len = n.norm();
            unitNormals[k] = len > 0 ? Vec3(n / len) : Vec3::Zero();
        }
        if (!faceDensity.empty()) {  // follows the faces into Morton order
            density.resize(faces.size());
            for (size_t k = 0; k < faceOrder.size(); ++k) density[k] = faceDensity[faceOrder[k]];
        }
        chunks.resize((faces.size() + kTrianglesPerChunk - 1) / kTrianglesPerChunk);

        std::vector<std::pair<std::pair<int, int>, int>> edges;  // (sorted corners) -> face * 3 + e
        edges.reserve(faces.size() * 3);
        for (int f = 0; f < static_cast<int>(faces.size()); ++f)
            for (int e = 0; e < 3; ++e) edges.push_back({std::minmax(faces[f][e], faces[f][(e + 1) % 3]), 3 * f + e});
        std::sort(edges.begin(), edges.end());
        borderEdges.assign(faces.size(), 0);
        neighbourFace.assign(3 * faces.size(), -1);
        for (size_t r = 0; r < edges.size();) {
            size_t q = r;
            while (q < edges.size() && edges[q].first == edges[r].first) ++q;
            if (q - r == 1) borderEdges[edges[r].second / 3] |= static_cast<unsigned char>(1u << (edges[r].second % 3));
            if (q - r == 2) {
                neighbourFace[edges[r].second] = edges[r + 1].second / 3;
                neighbourFace[edges[r + 1].second] = edges[r].second / 3;
            }
            r = q;
        }
        for (int f = 0; f < static_cast<int>(faces.size()); ++f)
            if (borderEdges[f]) borderFaceVertices.insert(borderFaceVertices.end(), faces[f].begin(), faces[f].end());
        std::sort(borderFaceVertices.begin(), borderFaceVertices.end());
        borderFaceVertices.erase(std::unique(borderFaceVertices.begin(), borderFaceVertices.end()), borderFaceVertices.end());
    }

    // A bound on the distance² of x_i's k-th nearest seed: the largest distance² to k other
    // distinct seeds (a list of an earlier evaluation), with a rounding margin.
    double listBound(const Vec3& xi, const uint32_t* list, int count) const
    {
        double r2 = 0;
        for (int q = 0; q < count; ++q) r2 = std::max(r2, ((*seeds)[list[q]] - xi).squaredNorm());
        return r2 * (1 + 1e-9) + std::numeric_limits<double>::min();
    }

    // Seed i's neighbour list from its candidates, when they certify it (see candidateIndex):
    // sorts the candidates by (distance², index) into `sorted` and keeps that order in the list
    // (nearly sorted next time, so the insertion sort does little work). `drift` is the largest
    // move of any seed but the movers since the lists were found; `certified2` receives the squared
    // radius below which the candidate list is complete (certifiedRadius2). False: moved too
    // far, a mover missing from the list, or a coincident seed.
    bool listFromCandidates(int i, double drift, std::vector<std::pair<double, uint32_t>>& sorted, uint32_t* listIndex,
                            double* listDist2, double& certified2)
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

    // Returns how many lists came from the candidate lists.
    int buildNeighbourLists()
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
            // built on demand only (a failed list, rare: bunny 5000, 26 in 55 evaluations); the
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

    // Seed i's candidates beyond its stored neighbours, nearest first, as far as they are
    // certified complete (certifiedRadius2): visit(j, |x_j - x_i|²) for each until it returns
    // false (then false is returned).
    template <class Visit>
    bool visitCertifiedCandidates(int i, Visit&& visit) const
    {
        if (!(certifiedRadius2[i] > 0)) return true;
        const uint32_t* cand = candidateIndex.data() + static_cast<size_t>(i) * candidateCount;
        const Vec3& xi = (*seeds)[i];
        for (int q = storedNeighbours; q < candidateCount; ++q) {
            const double dq = ((*seeds)[cand[q]] - xi).squaredNorm();
            if (!(dq < certifiedRadius2[i])) break;
            if (!visit(cand[q], dq)) return false;
        }
        return true;
    }

    // The seed whose Voronoi cell contains point p, certified: a greedy walk over the neighbour
    // lists from `from`, then the security-radius test (no seed farther than 2|p - x_s| from
    // x_s can be nearer to p). Falls back to the kd-tree when the stored list and the certified
    // candidates beyond it (certifiedRadius2) do not reach that radius or
    // the walk stalls (a greedy walk on a curved surface can stop at a local minimum).
    // Returns -1 when p is equidistant from two seeds (then its triangles are clipped).
    int certifiedNearestSeed(int from, const Vec3& p) const
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

    // The k-d tree's answer to "the two seeds nearest to p" (the nearest, -1 when the second is
    // as near or the nearest is a duplicate: ties and coincident seeds go the clipping way, which
    // resolves them), by a scan of every seed: the vertices whose lists do not certify their
    // nearest seed are a few dozen per evaluation (bunny 5000: ~28), and a scan of 5000 seeds
    // (~8 µs) each costs less than building the tree for them (~1 ms). The squared distances
    // are summed as nanoflann's L2 metric sums them, so the answers are the tree's, bit for bit.
    int nearestSeedByScan(const Vec3& p) const
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

    // The nearest seed of every vertex, or (borderOnly) of the corners of the faces with a border
    // edge only (the others are then left as they were and not read).
    void computeVertexSeeds(bool borderOnly)
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

    // Clips `in` by the bisector half-space of seeds i and j that contains x_i, into `out` when
    // it changes. Returns 0 when `in` is unchanged (`out` untouched), 1 when clipped into `out`
    // (`radius2` is then the maximum squared distance of out's vertices to x_i: the same values
    // as maxSquaredDistance(out, xi), so the same maximum), 2 when nothing is left.
    static int clipByBisector(const Polygon& in, Polygon& out, const Vec3& xi, const Vec3& xj, int j, double& radius2)
    {
        const Vec3 d = xj - xi;
        const double half = 0.5 * d.squaredNorm();
        double side[kMaxPolygonVertices];
        bool anyOutside = false, anyInside = false;
        const int size = in.size;
        for (int k = 0; k < size; ++k) {
            side[k] = (in.point[k] - xi).dot(d) - half;  // > 0: nearer to x_j
            if (side[k] > 0)
                anyOutside = true;
            else
                anyInside = true;
        }
        if (!anyOutside) return 0;
        if (!anyInside) return 2;
        int count = 0;
        double r2 = 0;
        for (int k = 0; k < size; ++k) {
            const int next = k + 1 == size ? 0 : k + 1;
            const bool inside = side[k] <= 0, nextInside = side[next] <= 0;
            if (inside) {
                out.point[count] = in.point[k];
                out.label[count] = in.label[k];
                r2 = std::max(r2, (out.point[count] - xi).squaredNorm());
                ++count;
            }
            if (inside != nextInside) {
                if (count + 1 >= kMaxPolygonVertices) throw Error("restricted Voronoi cell has too many vertices");
                const double t = side[k] / (side[k] - side[next]);
                out.point[count] = in.point[k] + t * (in.point[next] - in.point[k]);
                // Leaving the half-space: the new edge runs along the bisector of (i, j).
                out.label[count] = inside ? j : in.label[k];
                r2 = std::max(r2, (out.point[count] - xi).squaredNorm());
                ++count;
            }
        }
        out.size = count;
        radius2 = r2;
        return 1;
    }

    static double maxSquaredDistance(const Polygon& poly, const Vec3& x)
    {
        double r2 = 0;
        for (int k = 0; k < poly.size; ++k) r2 = std::max(r2, (poly.point[k] - x).squaredNorm());
        return r2;
    }

    // Clips `poly` to the Voronoi cell of seed i. A neighbour farther than twice the polygon's
    // radius around x_i cannot cut it (security radius), so neighbours are visited nearest
    // first until that holds. The clipped polygons alternate between `poly` and `spare` (no
    // copy per clip); returns the one holding the result (size 0: empty).
    const Polygon& clipToCell(Polygon& poly, Polygon& spare, int i, Scratch& scratch, long long& clipped) const
    {
        const Vec3& xi = (*seeds)[i];
        if (duplicate[i]) {
            poly.size = 0;
            return poly;
        }
        Polygon* current = &poly;
        Polygon* other = &spare;
        double radius2 = maxSquaredDistance(poly, xi);
        auto visit = [&](uint32_t j, double d2) {
            if (d2 > 4.0 * radius2) return false;  // security radius reached: done
            // Coincident seeds: the lowest index keeps the cell, the others are ignored.
            if (duplicate[j]) return true;
            ++clipped;
            const int status = clipByBisector(*current, *other, xi, (*seeds)[j], static_cast<int>(j), radius2);
            if (status == 2) {
                current->size = 0;
                return false;
            }
            if (status == 1) std::swap(current, other);
            return true;
        };
        const uint32_t* idx = neighbourIndex.data() + static_cast<size_t>(i) * storedNeighbours;
        const double* d2 = neighbourDist2.data() + static_cast<size_t>(i) * storedNeighbours;
        for (int q = 0; q < storedNeighbours; ++q)
            if (!visit(idx[q], d2[q])) return *current;
        // Rare: the stored neighbours did not reach the security radius. The candidates beyond
        // them next (they continue the stored list, nearest first), as far as they are complete,
        // then the k-d tree; each seed is visited once (`covered`: the largest distance visited,
        // `atCovered`: the seeds visited at exactly that distance).
        double covered = -1.0;
        std::vector<uint32_t>& atCovered = scratch.atCovered;
        atCovered.clear();
        auto visitOnce = [&](uint32_t j, double dj) {
            if (dj < covered || (dj == covered && std::find(atCovered.begin(), atCovered.end(), j) != atCovered.end()))
                return true;  // visited already
            if (!visit(j, dj)) return false;
            if (dj > covered) covered = dj, atCovered.clear();
            atCovered.push_back(j);
            return true;
        };
        for (int q = 0; q < storedNeighbours; ++q) {  // the stored list, visited above (nearest first)
            if (d2[q] > covered) covered = d2[q], atCovered.clear();
            atCovered.push_back(idx[q]);
        }
        if (!visitCertifiedCandidates(i, visitOnce)) return *current;
        const size_t n = seeds->size();
        for (size_t k = 4 * static_cast<size_t>(storedNeighbours) + 1;; k *= 4) {
            k = std::min(k, n);
            scratch.extraIndex.resize(k);
            scratch.extraDist.resize(k);
            const size_t found = seedTree().knnSearch(xi.data(), k, scratch.extraIndex.data(), scratch.extraDist.data());
            for (size_t q = 0; q < found; ++q) {
                const uint32_t j = scratch.extraIndex[q];
                if (static_cast<int>(j) != i && !visitOnce(j, scratch.extraDist[q])) return *current;
            }
            if (k == n) return *current;
        }
    }

    // All cells meeting input triangle t: start from the seed nearest to its centroid and walk
    // across shared bisector edges (cells meeting a convex polygon form a connected set).
    void processTriangle(int t, const RvdOptions& options, ChunkOutput& out, Scratch& scratch) const
    {
        const Face& f = faces[t];
        const Vec3& nrm = unitNormals[t];
        if (nrm.isZero()) return;  // zero-area face: nothing to integrate
        const Vec3 a = position[f[0]], b = position[f[1]], c = position[f[2]];
        // Convex cell, convex triangle: when one seed's cell holds all three corners it holds
        // the whole triangle, and no clipping is needed. This is most triangles.
        const int s0 = vertexSeed[f[0]], s1 = vertexSeed[f[1]], s2 = vertexSeed[f[2]];
        if (s0 >= 0 && s0 == s1 && s1 == s2) {
            Polygon whole;
            whole.size = 3;
            whole.point[0] = a, whole.point[1] = b, whole.point[2] = c;
            whole.label[0] = -1, whole.label[1] = -2, whole.label[2] = -3;
            integrate(whole, s0, t, out);
            if (options.triangles) recordFragment(whole, s0, t, out);
            return;
        }
        // Otherwise start from a seed whose cell meets the triangle: the cells of its corners,
        // then (only on exact ties) the seeds nearest to the centroid.
        const Vec3 centroid = (a + b + c) / 3.0;
        constexpr int kStartCandidates = 8;
        uint32_t candidate[kStartCandidates];
        double candidateDist2[kStartCandidates];
        int candidates = 0;
        for (int sv : {s0, s1, s2})
            if (sv >= 0) candidate[candidates++] = static_cast<uint32_t>(sv);
        bool treeQueried = false;
        int nextCandidate = 0;
        bool anyPiece = false;
        const int firstFragment = static_cast<int>(out.fragments.size());
        const int firstTriangle = static_cast<int>(out.triangles.size());

        scratch.stack.clear();
        scratch.visited.clear();
        while (true) {
            if (scratch.stack.empty()) {
                if (anyPiece) break;
                if (nextCandidate >= candidates) {
                    if (treeQueried) break;
                    candidates =
                        static_cast<int>(seedTree().knnSearch(centroid.data(), kStartCandidates, candidate, candidateDist2));
                    nextCandidate = 0;
                    treeQueried = true;
                }
                const int start = static_cast<int>(candidate[nextCandidate++]);
                if (std::find(scratch.visited.begin(), scratch.visited.end(), start) != scratch.visited.end()) continue;
                scratch.stack.push_back(start);
                scratch.visited.push_back(start);
            }
            const int i = scratch.stack.back();
            scratch.stack.pop_back();
            Polygon start, spare;
            start.size = 3;
            start.point[0] = a, start.point[1] = b, start.point[2] = c;
            start.label[0] = -1, start.label[1] = -2, start.label[2] = -3;
            const Polygon& poly = clipToCell(start, spare, i, scratch, out.clipped);
            if (poly.size < 3) continue;
            anyPiece = true;

            integrate(poly, i, t, out);
            const int fragment = options.triangles ? recordFragment(poly, i, t, out) : -1;
            for (int k = 0; k < poly.size; ++k) {
                const int j = poly.label[k];
                if (j < 0) continue;
                if (std::find(scratch.visited.begin(), scratch.visited.end(), j) == scratch.visited.end()) {
                    scratch.visited.push_back(j);
                    scratch.stack.push_back(j);
                }
                if (options.edges && i < j) {
                    const double len = (poly.point[(k + 1) % poly.size] - poly.point[k]).norm();
                    out.edges.push_back({i, j, len});
                }
                // Vertex k+1 ends edge k (bisector i|j) and starts edge k+1 (bisector i|l):
                // it is equidistant from i, j, l, and j, l follow each other counter-clockwise
                // around i, so (i, j, l) is a restricted Delaunay triangle with the input's
                // orientation.
                const int l = poly.label[(k + 1) % poly.size];
                if (options.triangles && l >= 0 && l != j) out.triangles.push_back({{fragment, -1 - j, -1 - l}, t});
            }
        }
        // The other two corners of each RDT triangle: the fragments of their seeds in this
        // input triangle (the RVD vertex is inside it, so they exist but in degenerate cases).
        const int fragmentEnd = static_cast<int>(out.fragments.size());
        for (size_t r = firstTriangle; r < out.triangles.size(); ++r)
            for (int c = 1; c < 3; ++c) {
                const int seed = -1 - out.triangles[r].corner[c];
                for (int g = firstFragment; g < fragmentEnd; ++g)
                    if (out.fragments[g].seed == seed) {
                        out.triangles[r].corner[c] = g;
                        break;
                    }
            }
    }

    // Records the polygon of cell i in input triangle t as a fragment: the closest point of x_i
    // on it, and a link across each input edge it reaches (the polygon of cell i in the face on
    // the other side shares that edge's part inside the cell, so the two are connected).
    // Returns the fragment's chunk-local index.
    int recordFragment(const Polygon& poly, int i, int t, ChunkOutput& out) const
    {
        const Vec3& xi = (*seeds)[i];
        Fragment fragment{i, t, poly.point[0], (poly.point[0] - xi).squaredNorm()};
        for (int k = 1; k + 1 < poly.size; ++k) {
            const Vec3 q = closestPointOnTriangle(xi, poly.point[0], poly.point[k], poly.point[k + 1]);
            const double d2 = (q - xi).squaredNorm();
            if (d2 < fragment.distance2) fragment.point = q, fragment.distance2 = d2;
        }
        const int index = static_cast<int>(out.fragments.size());
        out.fragments.push_back(fragment);
        for (int k = 0; k < poly.size; ++k) {
            if (poly.label[k] >= 0) continue;
            const int across = neighbourFace[3 * t + (-1 - poly.label[k])];
            if (across >= 0) out.links.push_back({index, across});
        }
        return index;
    }

    // Accumulates mass, first moment and ∫||x - x_i||² over the polygon by a fan of triangles,
    // times the face's ρ (eq. 1); areas are signed along the input face normal. Also the length
    // and moment of the input's border inside it (geometric).
    void integrate(const Polygon& poly, int i, int face, ChunkOutput& out) const
    {
        const Vec3& nrm = unitNormals[face];
        const Vec3& xi = (*seeds)[i];
        const Vec3 q0 = poly.point[0] - xi;
        double mass = 0, energy = 0;
        Vec3 moment = Vec3::Zero();
        for (int k = 1; k + 1 < poly.size; ++k) {
            const Vec3 q1 = poly.point[k] - xi, q2 = poly.point[k + 1] - xi;
            const double area = 0.5 * nrm.dot((q1 - q0).cross(q2 - q0));
            mass += area;
            moment += area / 3.0 * (q0 + q1 + q2);
            energy +=
                area / 6.0 * (q0.squaredNorm() + q1.squaredNorm() + q2.squaredNorm() + q0.dot(q1) + q1.dot(q2) + q2.dot(q0));
        }
        moment += mass * xi;
        if (!density.empty()) {
            const double rho = density[face];
            mass *= rho;
            moment *= rho;
            energy *= rho;
        }
        // Consecutive triangles (Morton order) are mostly in the same cell: one piece for them.
        if (!out.pieces.empty() && out.pieces.back().seed == i) {
            CellPiece& last = out.pieces.back();
            last.mass += mass;
            last.moment += moment;
            last.energy += energy;
        } else {
            out.pieces.push_back({i, mass, moment, energy});
        }
        if (borderEdges[face]) {
            double borderLength = 0;
            Vec3 borderMoment = Vec3::Zero();
            for (int k = 0; k < poly.size; ++k) {
                const int label = poly.label[k];
                if (label >= 0 || !(borderEdges[face] & (1u << (-1 - label)))) continue;
                const Vec3& p0 = poly.point[k];
                const Vec3& p1 = poly.point[(k + 1) % poly.size];
                const double len = (p1 - p0).norm();
                borderLength += len;
                borderMoment += 0.5 * len * (p0 + p1);
            }
            if (borderLength > 0) out.borderPieces.push_back({i, borderLength, borderMoment});
        }
    }
};

RestrictedVoronoiDiagram::RestrictedVoronoiDiagram(const TriMesh& surface, std::vector<double> faceDensity)
    : impl_(std::make_unique<Impl>(surface, faceDensity))
{
}
RestrictedVoronoiDiagram::~RestrictedVoronoiDiagram() = default;

void RestrictedVoronoiDiagram::compute(const std::vector<Vec3>& seeds, const RvdOptions& options, RvdResult& result)
{
    if (seeds.empty()) throw InvalidInputError("restricted Voronoi diagram needs at least one seed");
    Impl& m = *impl_;
    m.seeds = &seeds;
    const int fromCandidates = m.buildNeighbourLists();
    m.computeVertexSeeds(options.borderFacesOnly);

    const int faceCount = static_cast<int>(m.faces.size());
    const int chunkCount = static_cast<int>(m.chunks.size());
    m.scratch.resize(std::max(1, omp_get_max_threads()));
#pragma omp parallel
    {
        Scratch& scratch = m.scratch[omp_get_thread_num()];
#pragma omp for schedule(dynamic, 1)
        for (int c = 0; c < chunkCount; ++c) {
            ChunkOutput& out = m.chunks[c];
            out.clear();
            const int end = std::min(faceCount, (c + 1) * kTrianglesPerChunk);
            for (int k = c * kTrianglesPerChunk; k < end; ++k)
                if (!options.borderFacesOnly || m.borderEdges[k]) m.processTriangle(k, options, out, scratch);
        }
    }

    // Reduction in chunk order: identical sums whatever the thread count.
    const size_t n = seeds.size();
    result.mass.assign(n, 0.0);
    result.moment.assign(n, Vec3::Zero());
    result.energy.assign(n, 0.0);
    result.boundaryLength.assign(options.boundary ? n : 0, 0.0);
    result.boundaryMoment.assign(options.boundary ? n : 0, Vec3::Zero());
    result.edges.clear();
    result.triangles.clear();
    result.clippedPolygons = 0;
    result.listsFromCandidates = fromCandidates;
    for (const ChunkOutput& out : m.chunks) {
        for (const CellPiece& p : out.pieces) {
            result.mass[p.seed] += p.mass;
            result.moment[p.seed] += p.moment;
            result.energy[p.seed] += p.energy;
        }
        if (options.boundary)
            for (const BorderPiece& p : out.borderPieces) {
                result.boundaryLength[p.seed] += p.length;
                result.boundaryMoment[p.seed] += p.moment;
            }
        result.clippedPolygons += out.clipped;
    }
    if (options.edges) {
        // Sum the pieces of each shared edge (an RVD edge crosses several input triangles):
        // bucket the pieces by their first seed (counting sort straight from the chunks, chunk
        // order kept), then merge each seed's few pieces by second seed, then gather the merged
        // buckets in parallel. Linear time and deterministic.
        std::vector<int>& start = m.edgeStart;
        start.assign(n + 1, 0);
        for (const ChunkOutput& out : m.chunks)
            for (const RvdEdge& e : out.edges) ++start[e.i + 1];
        for (size_t i = 0; i < n; ++i) start[i + 1] += start[i];
        std::vector<RvdEdge>& bucketed = m.edgeBuffer;
        bucketed.resize(static_cast<size_t>(start[n]));
        std::vector<int> fill(start.begin(), start.end() - 1);
        for (const ChunkOutput& out : m.chunks)
            for (const RvdEdge& e : out.edges) bucketed[fill[e.i]++] = e;
        std::vector<int> kept(n + 1, 0);
#pragma omp parallel for schedule(static)
        for (long long i = 0; i < static_cast<long long>(n); ++i) {
            RvdEdge* first = bucketed.data() + start[i];
            RvdEdge* last = bucketed.data() + start[i + 1];
            // Pieces with the same second seed summed in chunk order (into the first of them),
            // then the few merged edges sorted by second seed (insertion sort: a seed has a
            // dozen pieces or so, half a dozen edges).
            RvdEdge* w = first;
            for (RvdEdge* r = first; r != last; ++r) {
                RvdEdge* same = first;
                while (same != w && same->j != r->j) ++same;
                if (same != w)
                    same->length += r->length;
                else
                    *w++ = *r;
            }
            for (RvdEdge* r = first; r != w; ++r) {  // (not first + 1: `first` is null when no seed has an edge)
                const RvdEdge moving = *r;
                RvdEdge* to = r;
                for (; to != first && (to - 1)->j > moving.j; --to) *to = *(to - 1);
                *to = moving;
            }
            kept[i + 1] = static_cast<int>(w - first);
        }
        for (size_t i = 0; i < n; ++i) kept[i + 1] += kept[i];  // now where each seed's edges go
        result.edges.resize(static_cast<size_t>(kept[n]));
#pragma omp parallel for schedule(static)
        for (long long i = 0; i < static_cast<long long>(n); ++i)
            std::copy(bucketed.begin() + start[i], bucketed.begin() + start[i] + (kept[i + 1] - kept[i]),
                      result.edges.begin() + kept[i]);
    }
    result.pieceSeed.clear();
    result.piecePoint.clear();
    result.pieceTriangles.clear();
    if (options.triangles) m.buildPieces(result);
}

void RestrictedVoronoiDiagram::Impl::buildPieces(RvdResult& result) const
{
    // Global fragment numbering: chunk order, then order within the chunk.
    std::vector<int> chunkStart(chunks.size() + 1, 0);
    for (size_t c = 0; c < chunks.size(); ++c) chunkStart[c + 1] = chunkStart[c] + static_cast<int>(chunks[c].fragments.size());
    const int fragmentCount = chunkStart.back();
    std::vector<Fragment> fragments;
    fragments.reserve(fragmentCount);
    for (const ChunkOutput& out : chunks) fragments.insert(fragments.end(), out.fragments.begin(), out.fragments.end());
    // The fragments of one input triangle are consecutive.
    std::vector<int> faceFirst(faces.size(), -1), faceEnd(faces.size(), -1);
    for (int g = 0; g < fragmentCount; ++g) {
        const int f = fragments[g].face;
        if (faceFirst[f] < 0) faceFirst[f] = g;
        faceEnd[f] = g + 1;
    }

    // Union-find of the fragments of one cell across shared input edges.
    std::vector<int> parent(fragmentCount);
    for (int g = 0; g < fragmentCount; ++g) parent[g] = g;
    auto find = [&](int g) {
        while (parent[g] != g) g = parent[g] = parent[parent[g]];
        return g;
    };
    for (size_t c = 0; c < chunks.size(); ++c)
        for (const FragmentLink& link : chunks[c].links) {
            const int g = chunkStart[c] + link.fragment;
            for (int h = faceFirst[link.face]; h >= 0 && h < faceEnd[link.face]; ++h)
                if (fragments[h].seed == fragments[g].seed) {
                    const int a = find(g), b = find(h);
                    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the root is the first fragment
                    break;
                }
        }

    // Pieces sorted by seed, then by first fragment; each at its fragment nearest to the seed.
    const int seedCount = static_cast<int>(seeds->size());
    std::vector<int> pieceOfRoot(fragmentCount, -1);
    std::vector<int> firstOfSeed(seedCount + 1, 0);
    for (int g = 0; g < fragmentCount; ++g)
        if (find(g) == g) ++firstOfSeed[fragments[g].seed + 1];
    for (int s = 0; s < seedCount; ++s) firstOfSeed[s + 1] += firstOfSeed[s];
    const int pieceCount = firstOfSeed.back();
    result.pieceSeed.resize(pieceCount);
    result.piecePoint.resize(pieceCount);
    std::vector<int> fill(firstOfSeed.begin(), firstOfSeed.end() - 1);
    std::vector<double> nearest(pieceCount);
    for (int g = 0; g < fragmentCount; ++g) {
        const int root = find(g);
        if (root == g) {
            const int p = fill[fragments[g].seed]++;
            pieceOfRoot[g] = p;
            result.pieceSeed[p] = fragments[g].seed;
            result.piecePoint[p] = fragments[g].point;
            nearest[p] = fragments[g].distance2;
        } else {
            const int p = pieceOfRoot[root];  // the root comes first, so it is numbered
            if (fragments[g].distance2 < nearest[p])
                result.piecePoint[p] = fragments[g].point, nearest[p] = fragments[g].distance2;
        }
    }

    // RDT triangles on pieces. A corner without a fragment in the triangle of its RVD vertex
    // (the vertex is on the triangle's border) takes its seed's piece in a neighbouring triangle,
    // else the seed's first piece.
    auto pieceNear = [&](int seed, int face) {
        for (int e = 0; e < 3; ++e) {
            const int across = neighbourFace[3 * face + e];
            for (int h = across >= 0 ? faceFirst[across] : -1; h >= 0 && h < faceEnd[across]; ++h)
                if (fragments[h].seed == seed) return pieceOfRoot[find(h)];
        }
        return firstOfSeed[seed];
    };
    for (size_t c = 0; c < chunks.size(); ++c)
        for (const RawTriangle& raw : chunks[c].triangles) {
            std::array<int, 3> t;
            for (int k = 0; k < 3; ++k)
                t[k] = raw.corner[k] >= 0 ? pieceOfRoot[find(chunkStart[c] + raw.corner[k])]
                                          : pieceNear(-1 - raw.corner[k], raw.face);
            result.pieceTriangles.push_back(canonicalTriangle(t[0], t[1], t[2]));
        }
    std::sort(result.pieceTriangles.begin(), result.pieceTriangles.end());
    result.pieceTriangles.erase(std::unique(result.pieceTriangles.begin(), result.pieceTriangles.end()),
                                result.pieceTriangles.end());
    for (const std::array<int, 3>& t : result.pieceTriangles)
        result.triangles.push_back(canonicalTriangle(result.pieceSeed[t[0]], result.pieceSeed[t[1]], result.pieceSeed[t[2]]));
    std::sort(result.triangles.begin(), result.triangles.end());
    result.triangles.erase(std::unique(result.triangles.begin(), result.triangles.end()), result.triangles.end());
}

}  // namespace fieldcvt
