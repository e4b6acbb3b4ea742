#pragma once
// The restricted Voronoi diagram's inside (rvd.h is its interface), shared by its three parts:
// rvd.cpp (the surface renumbered, one evaluation, the cell pieces and RDT triangles),
// rvd_neighbours.cpp (each seed's neighbour list, each vertex's nearest seed) and rvd_clip.cpp
// (each input triangle clipped to the cells it meets, and integrated). Internal to the core.
#include "point_tree.h"
#include "rvd.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

namespace fieldcvt {
std::array<int, 3> canonicalTriangleOf(int a, int b, int c);
namespace rvd_detail {

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

// Fragment `fragment` (chunk-local) has an edge on the input edge shared with `face`. Eight
// bytes: at 400 000 seeds on 800 000 faces there are 5.7 million of them.
struct FragmentLink {
    int fragment;
    int face;
};

// Where a link's fragment meets the shared edge; recorded for side-aware cells only (their seam
// triangles, addSeamTriangles), one per link, in the same order.
struct LinkSpan {
    int edge;         // the edge of the fragment's face (from its corner `edge` to the next)
    double from, to;  // the fragment's part of that edge, as parameters along it (0 .. 1)
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
    std::vector<LinkSpan> linkSpans;  // empty unless the cells are side-aware
    std::vector<RawTriangle> triangles;
    long long clipped = 0;
    void clear()
    {
        pieces.clear();
        borderPieces.clear();
        edges.clear();
        fragments.clear();
        links.clear();
        linkSpans.clear();
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

}  // namespace rvd_detail

struct RestrictedVoronoiDiagram::Impl {
    using Polygon = rvd_detail::Polygon;
    using ChunkOutput = rvd_detail::ChunkOutput;
    using Scratch = rvd_detail::Scratch;

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
    const std::vector<Vec3>* seedNormals = nullptr;
    double minSideCos = -0.5;
    bool sideOk(uint32_t j, const Vec3& faceNormal) const
    {
        return !seedNormals || (*seedNormals)[j].dot(faceNormal) > minSideCos;
    }
    PointCloud cloud;  // the seeds, for their k-d tree (point_tree.h)
    // The k-d tree of the seeds, built on first use in an evaluation: with the candidate lists
    // most evaluations need it only for rare fallbacks (docs/tuning.md, "RVD: the seeds' k-d tree").
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
    // (docs/tuning.md, "RVD: the seeds' k-d tree").
    std::vector<uint32_t> movers;
    // Per seed: its candidate list (candidateIndex) is, in this evaluation, sorted by distance
    // and complete below this squared distance (every seed nearer is in it); 0 = not known.
    // Where the stored neighbours do not reach a security radius, the candidates beyond them
    // serve before the k-d tree (which is then not built in most evaluations).
    std::vector<double> certifiedRadius2;
    std::vector<double> moveSquared, moveOrder;  // per seed, work space

    // rvd.cpp
    Impl(const TriMesh& s, const std::vector<double>& faceDensity);
    //! Frees the chunks' fragments, links and triangles as it uses them.
    void buildPieces(RvdResult& result);
    void addSeamTriangles(const std::vector<int>& chunkStart, const std::vector<rvd_detail::Fragment>& fragments,
                          const std::function<int(int)>& pieceOf, RvdResult& result) const;

    // rvd_neighbours.cpp (the inline ones are used there only: inline as when they were defined in
    // the class, so that the compiler inlines them into their loops; measured +5.7 %
    // instructions without)
    // A bound on the distance² of x_i's k-th nearest seed: the largest distance² to k other
    // distinct seeds (a list of an earlier evaluation), with a rounding margin.
    inline double listBound(const Vec3& xi, const uint32_t* list, int count) const;
    // Seed i's neighbour list from its candidates, when they certify it (see candidateIndex):
    // sorts the candidates by (distance², index) into `sorted` and keeps that order in the list
    // (nearly sorted next time, so the insertion sort does little work). `drift` is the largest
    // move of any seed but the movers since the lists were found; `certified2` receives the squared
    // radius below which the candidate list is complete (certifiedRadius2). False: moved too
    // far, a mover missing from the list, or a coincident seed.
    inline bool listFromCandidates(int i, double drift, std::vector<std::pair<double, uint32_t>>& sorted, uint32_t* listIndex,
                                   double* listDist2, double& certified2);
    // Returns how many lists came from the candidate lists.
    int buildNeighbourLists();
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
    inline int certifiedNearestSeed(int from, const Vec3& p) const;
    // The k-d tree's answer to "the two seeds nearest to p" (the nearest, -1 when the second is
    // as near or the nearest is a duplicate: ties and coincident seeds go the clipping way, which
    // resolves them), by a scan of every seed: the vertices whose lists do not certify their
    // nearest seed are a few dozen per evaluation, and a scan each costs less than building the
    // tree for them (docs/tuning.md, "RVD: the seeds' k-d tree"). The squared distances
    // are summed as nanoflann's L2 metric sums them, so the answers are the tree's, bit for bit.
    inline int nearestSeedByScan(const Vec3& p) const;
    // The nearest seed of every vertex, or (borderOnly) of the corners of the faces with a border
    // edge only (the others are then left as they were and not read).
    void computeVertexSeeds(bool borderOnly);

    // rvd_clip.cpp (the inline ones likewise)
    // Clips `in` by the bisector half-space of seeds i and j that contains x_i, into `out` when
    // it changes. Returns 0 when `in` is unchanged (`out` untouched), 1 when clipped into `out`
    // (`radius2` is then the maximum squared distance of out's vertices to x_i: the same values
    // as maxSquaredDistance(out, xi), so the same maximum), 2 when nothing is left.
    static inline int clipByBisector(const Polygon& in, Polygon& out, const Vec3& xi, const Vec3& xj, int j, double& radius2);
    static inline double maxSquaredDistance(const Polygon& poly, const Vec3& x);
    // Clips `poly` to the Voronoi cell of seed i. A neighbour farther than twice the polygon's
    // radius around x_i cannot cut it (security radius), so neighbours are visited nearest
    // first until that holds. The clipped polygons alternate between `poly` and `spare` (no
    // copy per clip); returns the one holding the result (size 0: empty).
    inline const Polygon& clipToCell(Polygon& poly, Polygon& spare, int i, Scratch& scratch, long long& clipped,
                                     const Vec3* faceNormal) const;
    // All cells meeting input triangle t: start from the seed nearest to its centroid and walk
    // across shared bisector edges (cells meeting a convex polygon form a connected set).
    void processTriangle(int t, const RvdOptions& options, ChunkOutput& out, Scratch& scratch) const;
    // Side-aware cells (seedNormals): the corners' seeds s0..s2 that may own the face with unit
    // normal `normal`, or (none of them) the nearest seed to the centroid that may, in s0.
    // False when no seed near the face may own it: then every seed may (s0..s2 unchanged).
    bool sideAwareStart(const Vec3& normal, const Vec3& centroid, int& s0, int& s1, int& s2) const;
    // Records the polygon of cell i in input triangle t as a fragment: the closest point of x_i
    // on it, and a link across each input edge it reaches (the polygon of cell i in the face on
    // the other side shares that edge's part inside the cell, so the two are connected).
    // Returns the fragment's chunk-local index.
    inline int recordFragment(const Polygon& poly, int i, int t, ChunkOutput& out) const;
    // Accumulates mass, first moment and ∫||x - x_i||² over the polygon by a fan of triangles,
    // times the face's ρ (eq. 1); areas are signed along the input face normal. Also the length
    // and moment of the input's border inside it (geometric).
    inline void integrate(const Polygon& poly, int i, int face, ChunkOutput& out) const;
};

}  // namespace fieldcvt
