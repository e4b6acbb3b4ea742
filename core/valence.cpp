#include "valence.h"

#include "mesh_edges.h"

#include "energy.h"
#include "errors.h"
#include "interpolation.h"
#include "metrics.h"

#include <Eigen/Geometry>
#include <omp.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace fieldcvt {

namespace {

constexpr double kPi = 3.14159265358979323846;
//! A face whose unit normal makes more than 32° with the surface normal (mean of its corners'
//! surface normals) counts as folded, unless it was already that bad before the operation. (60°
//! let operations bridge valleys and cut rounded rims: fertility 3000 d_H 1.01 % against 0.87 %
//! at 32°, same V6%.)
constexpr double kMinNormalDot = 0.85;
//! The final relaxation moves a vertex at most this many mean edge lengths from where it started
//! (the sag check below is what keeps it on ridges and tips; 0.25 held Q_avg back: fertility
//! 3000 0.963 against 0.966 at 0.5 and 1.0, same d_H; camelhead's lips keep d_H 0.82 %).
constexpr double kMaxDrift = 1.0;
//! The final relaxation moves a vertex by at most this fraction of the mean edge length per step.
constexpr double kMaxRelaxStep = 0.25;
//! Step of the final relaxation down the shape energy, in units of the vertex's mean incident
//! face area times the energy's gradient: about a Newton step of the energy's edge-length part
//! on a valence-6 fan (its Hessian there is ~ 6 * 4 / (4 sqrt3 A)). Measured, fertility 3000 /
//! fandisk 5000 Q_avg (Jacobi, no momentum, no field term): 0.2 -> 0.963 / 0.956, 0.3 -> 0.963 /
//! 0.956, 0.45 oscillates (0.897 / 0.887).
constexpr double kShapeStep = 0.25;
//! Heavy-ball momentum of the final relaxation: each step adds this fraction of the vertex's
//! last (accepted, tangential) move. The shape energy's smooth modes converge slowly under
//! plain Jacobi steps; with 0.8, 20 steps reach what 40 plain steps reach (fertility 3000 Q_avg
//! without the field term: 0.969 against 0.968 at 40 plain steps and 0.966 at 20).
constexpr double kRelaxMomentum = 0.8;

//! A face whose centroid lies farther than this fraction of the mean edge length from the input
//! surface, and farther than a multiple of its own sag before, cuts a corner of the input (a
//! crease, an ear tip): the relaxation refuses such a move (kRelaxSagGrowth times the face's sag
//! at its start), an operation too (kOperationSagGrowth times the largest sag around it before).
//! Measured, fertility 3000 / bunny 5000 d_H: 0.53 / 0.45 % before the stage, 1.23 / 1.28 %
//! without the checks, 0.90 / 0.89 % with them (1.0 and 1.0: 0.53 / 0.45 %, but V6% 93.3 and
//! Q_avg 0.949; relaxation 1.0 alone: 0.74 / 0.76 %, Q_avg 0.953 / 0.949).
constexpr double kMaxSag = 0.1;
constexpr double kOperationSagGrowth = 1.5;
constexpr double kRelaxSagGrowth = 1.25;
//! ... and in the relaxation, any face may sag up to this fraction of the largest sag of any face
//! at its start (when that is more than kMaxSag edges): that largest sag is about the distance
//! d_H measures, so faces well under it may grow towards it without moving d_H, and on models
//! whose details sag ~0.3–0.4 edge at the output's resolution (nefertiti, fertility's handles,
//! fandisk's rounded creases) the 1.25× rule had held ~2 % of the faces back at every step
//! (their corners reverted, their momentum lost). Measured with the fold limit below, seeds 1–4,
//! nine bench rows: Q_avg +0.002 to +0.007 on bunny, camelhead, fandisk, both fertilities and
//! nefertiti, mask +0.001 at most, torus and cylinder the same bytes (their largest sag is under
//! 0.2 edge); θ_min the same or higher; highest d_H per row within 3 % (fandisk seed 3: 1.08 ->
//! 1.21 %, Instant Meshes 1.30). 0.75: fandisk 0.964 Q_avg but fertility 7000 d_H 0.445 ->
//! 0.470 % (Instant Meshes 0.451); no limit at all: torus d_H 0.354 -> 0.40 %.
constexpr double kRelaxSagShareOfLargest = 0.5;
//! The relaxation's fold limit: a face whose normal turns more than ~45° from the surface normal
//! (and more than before). Looser than the operations' kMinNormalDot: the connectivity is fixed
//! and every move is small, and at fandisk's rounded creases the faces across the crease sit
//! near 32° from the corners' mean normal, so 0.85 froze ~90 faces per step there (fandisk 5000
//! Q_avg 0.951 -> 0.954 with 0.7, nefertiti d_H 0.99 -> 0.90 %, the other rows the same).
constexpr double kRelaxMinNormalDot = 0.7;
//! ... and an operation's allowed growth is at most this many mean edge lengths: where the mesh
//! already sags (an ear tip at this resolution sags ~0.3 edge) 1.5× let a run of operations
//! ratchet the tip off, each within its limit (bunny 5000, seed 1, 5 + 10 + 40 iterations: d_H
//! 0.47 % before the operations, 0.77 % after the first round, 0.85 % at the end; 0.59 % with
//! the cap). With the default 10 + 10 + 40 iterations and look-ahead 8, seeds 1–4, highest d_H %
//! without / with the cap: bunny 0.84 / 0.68, fertility 7000 0.56 / 0.49, fandisk 1.18 / 1.18
//! (seed 1: 1.07 / 0.94), the other six rows the same; V6 % at most 0.1 lower. With 5 + 10 +
//! 40, seed 1: 0.05 edge instead of 0.1 left fandisk V6 93.7 % (its rounded creases need the
//! growth); growth 1.0× or 1.2× instead of 1.5×: fandisk V6 91.1 / 92.7 %.
constexpr double kOperationSagStep = 0.1;

//! The angle repair after the relaxation (raiseSmallestAngles): rounds over the corners of the
//! faces still under ValenceParams::minAngleDegrees; per corner, a pattern search (8 tangent
//! directions, first step kAngleRepairStep mean edge lengths, halved down to 1/32 of it) for
//! the position on the surface with the largest smallest angle over its faces, within
//! kAngleRepairDrift edges of where it was, without folding (kMinNormalDot) or sagging
//! (kRelaxSagGrowth, kMaxSag) more than its faces did before it: the stricter limits of the
//! operations, as a repair moves one vertex after the others have settled.
constexpr int kAngleRepairRounds = 3;
constexpr double kAngleRepairStep = 0.1;
constexpr double kAngleRepairDrift = 0.3;
constexpr int kAngleRepairMaxSteps = 64;

//! The sag repair after the angle repair (lowerLargestSags): d_H is the largest distance between
//! the mesh and the input, and it sits at a handful of faces (torus 1000: 2 faces within 5 % of
//! the largest sag, 10 within 10 %). The Free corners of the faces whose sag is within
//! kSagRepairBand of the largest (at most kSagRepairFaces of them) move on the surface, by a
//! pattern search like the angle repair's, to bring the largest sag of their faces down to the
//! band's lower edge, without a fold, a sharper face or a worse shape (below);
//! kSagRepairRounds rounds, the largest sag measured again before each. (Sag: against the
//! optimisation surface, within SimplifyParams::maxError of the input.) Measured, seeds 1–4 on
//! the nine bench rows, highest d_H % per row before -> after: fertility 3000 0.88 -> 0.84,
//! fertility 7000 0.49 -> 0.46, fandisk 1.21 -> 1.06, bunny 0.68 -> 0.61, mask 0.42 -> 0.39,
//! torus 0.40 -> 0.36, cylinder 0.22 -> 0.21, camelhead and nefertiti the same (seed 1:
//! fertility 7000 0.445 -> 0.359, fertility 3000 0.72 -> 0.62); Q_avg within 0.0003 but torus
//! (-0.001 to -0.002). The pattern search: 12 steps, down to 1/8 of the first (32 steps down to
//! 1/16: the same figures within ±0.04 % d_H, the valence stage on torus 1000 +50 ms instead
//! of +30 ms on one thread).
constexpr int kSagRepairRounds = 4;
constexpr double kSagRepairBand = 0.05;
constexpr int kSagRepairFaces = 64;
constexpr int kSagRepairMaxSteps = 12;
//! ... and the mean of its faces' mean ratio (4√3 A / Σ l², 1 for an equilateral triangle) drops
//! by at most this much.
constexpr double kSagRepairShapeLoss = 0.003;
//! ... and no face's smallest angle goes under min(ValenceParams::minAngleDegrees + this, its
//! own before): on a coarse optimisation surface the projection onto the input that follows
//! moves the vertices a little and costs up to ~2° (camelhead 3000: 36.4° here, 34.7° in the
//! output with no margin; 35.5° with 3°, as without the repair).
constexpr double kSagRepairAngleMargin = 3.0;
//! ... and only where the largest sag is at least this many edge lengths (the bench rows: 0.02
//! (cylinder 1000) to 0.4).
constexpr double kSagRepairMinSag = 0.005;

//! Also the tie-break between candidates of equal gain: splits before collapses keeps the vertex
//! count near the target (fertility 3000: 2960 vertices with collapses first, 2993 this way).
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
    size_t operator()(const Candidate& k) const
    {
        std::uint64_t h = static_cast<std::uint64_t>(k.length);
        for (int i = 0; i < k.length; ++i) {
            const Op& op = k.ops[i];
            for (std::int64_t x : {static_cast<std::int64_t>(op.type), static_cast<std::int64_t>(op.a),
                                   static_cast<std::int64_t>(op.b), static_cast<std::int64_t>(op.c),
                                   static_cast<std::int64_t>(op.gain)})
                h = (h ^ static_cast<std::uint64_t>(x)) * 0x100000001B3ull + 0x9E3779B97F4A7C15ull;
        }
        return static_cast<size_t>(h);
    }
};

//! The ordered neighbours of a vertex, counter-clockwise: face i is (v, verts[i], verts[i+1])
//! (indices mod size for a closed fan). `ok` is false for a vertex whose faces do not form a
//! single fan (non-manifold): such vertices are never touched.
struct Ring {
    std::vector<int> verts;
    std::vector<int> faces;
    bool closed = true;
    bool ok = true;
};

bool isFeatureLike(VertexRole r) { return r == VertexRole::Feature || r == VertexRole::Corner; }
//! Vertices that neither the smoothing after an operation nor the final relaxation moves. Border
//! vertices stay where the 1D CVT along the border put them: slid along it, they left unpinned
//! turns of a jagged border uncovered (camelhead 3000: boundary distance 0.18 -> 0.24 % once the
//! border weight made operations there; kept in place 0.17 %, bunny 5000 0.47 -> 0.43 %).
bool isFixed(VertexRole r) { return r == VertexRole::Corner || r == VertexRole::Boundary; }

//! Gradient with respect to v of the shape energy of triangle (v, a, b) (counter-clockwise
//! seen from its normal): e = (|a - v|^2 + |b - v|^2 + |a - b|^2) / (4 sqrt3 |t|), the inverse
//! of the mean ratio [Liu & Joe 1994; Knupp 2001]: 1 for an equilateral triangle, growing
//! without bound as it degenerates, independent of its size. Zero (and area 0) for a
//! degenerate triangle, which has no direction to offer.
Vec3 shapeEnergyGradient(const Vec3& v, const Vec3& a, const Vec3& b, double& area)
{
    const Vec3 twiceAreaNormal = (a - v).cross(b - v);
    const double twiceArea = twiceAreaNormal.norm();
    area = 0.5 * twiceArea;
    if (!(twiceArea > 0)) return Vec3::Zero();
    const double c = 4 * std::sqrt(3.0);
    const double lengths = (a - v).squaredNorm() + (b - v).squaredNorm() + (a - b).squaredNorm();
    // d|t|/dv = (n x (b - a)) / 2: moving v away from the edge ab grows the triangle.
    const Vec3 areaGradient = 0.5 * (twiceAreaNormal / twiceArea).cross(b - a);
    return 2 * (2 * v - a - b) / (c * area) - lengths / (c * area * area) * areaGradient;
}

//! The smallest angle of triangle (p0, p1, p2) in radians (atan2 form, as computeQuality).
double smallestAngle(const Vec3& p0, const Vec3& p1, const Vec3& p2)
{
    const Vec3 p[3] = {p0, p1, p2};
    double smallest = kPi;
    for (int k = 0; k < 3; ++k) {
        const Vec3 u = p[(k + 1) % 3] - p[k], w = p[(k + 2) % 3] - p[k];
        smallest = std::min(smallest, std::atan2(u.cross(w).norm(), u.dot(w)));
    }
    return smallest;
}

//! Mean ratio of a triangle, 4√3 A / (l0² + l1² + l2²): 1 for an equilateral one, 0 when flat.
double meanRatio(const Vec3& p0, const Vec3& p1, const Vec3& p2)
{
    const double lengths = (p1 - p0).squaredNorm() + (p2 - p1).squaredNorm() + (p0 - p2).squaredNorm();
    return lengths > 0 ? 2 * std::sqrt(3.0) * (p1 - p0).cross(p2 - p0).norm() / lengths : 0.0;
}

// ---------------------------------------------------------------------------------------------

//! The state of one optimizeValence call: a mutable triangle soup with per-vertex incident face
//! lists (faces are only ever killed and appended, so an undo log can roll back a tentative
//! operation exactly), plus each vertex's closest point on the input and surface normal there.
class ValenceOptimizer {
public:
    ValenceOptimizer(TriMesh& mesh, std::vector<VertexRole>& roles, const ValenceSurface& surface,
                     const ValenceParams& params, const std::vector<int>& faceHints);
    ValenceStats run();

private:

    // --- mutable mesh with undo -------------------------------------------------------------
    enum class UndoKind : std::uint8_t { AddFace, KillFace, Move, AddVertex, KillVertex, Valence };
    struct UndoEntry {
        UndoKind kind;
        int index;
        Vec3 position;
        ClosestPoint closest;
        Vec3 normal;
    };

    int addFace(const Face& f);
    void killFace(int f);
    int addVertex(const Vec3& p, VertexRole role);
    void killVertex(int v);
    void setPosition(int v, const Vec3& p, const ClosestPoint& cp);
    void rollback(size_t mark);

    // --- queries ------------------------------------------------------------------------------
    void ring(int v, Ring& r) const;
    int target(int v) const { return onBorder_[v] ? 4 : 6; }
    int weight(int v) const { return onBorder_[v] ? params_.borderWeight : 1; }
    //! Term of R for vertex v at valence `valence` (ValenceParams::borderWeight on the border).
    int cost(int v, int valence) const
    {
        const int d = valence - target(v);
        return weight(v) * d * d;
    }
    int valenceDelta(int v, int delta) const { return cost(v, valence_[v] + delta) - cost(v, valence_[v]); }
    //! Faces containing both a and b.
    void edgeFaces(int a, int b, std::vector<int>& out) const;
    bool hasEdge(int a, int b) const;
    Vec3 surfaceNormal(const ClosestPoint& cp) const;
    Vec3 faceUnitNormal(int f) const;
    //! Largest distance from face f's centroid and edge midpoints to the input surface: large
    //! where the face cuts across a crease or a thin part of the input.
    double faceSag(int f) const;
    //! The points whose distance to the input makes face f's sag, and for each the face its
    //! query starts from (shared by faceSag and faceSagBound).
    void sagPoints(int f, Vec3 (&points)[4], int (&starts)[4]) const;
    //! At least faceSag(f), from walks over the input (SurfaceWalk) instead of tree queries;
    //! usually equal to it.
    double faceSagBound(int f) const;
    //! faceSag(f), remembered with f's corner positions: an operation's check measures the faces
    //! around it before, and most of them were measured by an earlier check and have not moved.
    double cachedFaceSag(int f);
    struct SagEntry;
    //! f's entry of sagCache_ when it holds faceSag(f) for f's corners now, else null.
    const SagEntry* rememberedSag(int f) const;
    //! cachedFaceSag(f) when remembered for f's corners, else faceSagBound(f): at least the sag.
    double knownFaceSag(int f) const;
    //! The largest sag an operation may leave on the faces around it, from `faces` before it.
    double operationSagLimit(const std::vector<int>& faces);
    //! The alive faces around `verts`, sorted, without repeats.
    void facesAround(const std::vector<int>& verts, std::vector<int>& faces) const;
    //! Smallest angle (radians) and smallest normal agreement over `faces`.
    void localShape(const std::vector<int>& faces, double& minAngle, double& minDot) const;
    //! Whether faceSag exceeds `limit` on one of `faces`: the bound first, the exact sag (cached)
    //! only where the bound does not decide. The same answer as comparing faceSag itself.
    bool sagExceeds(const std::vector<int>& faces, double limit);

    // --- operations ---------------------------------------------------------------------------
    bool evaluateFlip(int a, int b, int& gain, int& c, int& d, int& f1, int& f2) const;
    bool evaluateCollapse(int a, int b, int& gain, int& keep, int& remove) const;
    //! The single operations around irregular vertex v that lower R (ΔR < 0), or with
    //! `zeroGainFlips` the flips around v that leave R unchanged (look-ahead first steps).
    void collectOperations(int v, bool zeroGainFlips, std::vector<Op>& out);
    //! Look-ahead (when no single operation is left): chains that start with an R-neutral flip
    //! around v, see collectChains.
    void collectChains(int v, std::vector<Candidate>& out);
    //! collectChains for every irregular vertex, appended to `out` in vertex order. In parallel:
    //! the search applies operations tentatively and rolls them back, so each thread but the
    //! first searches on its own copy of the mesh; every vertex's search starts from the same
    //! state, so the list is the one a single thread makes.
    void collectAllChains(std::vector<Candidate>& out);
    //! One level of the chain search: each R-neutral flip at the irregular vertices of `from`,
    //! applied tentatively, then either the best R-lowering operation around it ends the chain or,
    //! if there is none and the depth allows, the search goes on from the flipped quad.
    void extendChain(const std::vector<int>& from, Candidate& chain, std::vector<Candidate>& out);
    //! Vertices that must be unlocked (and unchanged since the candidate was made) for `op`.
    void involvedVertices(const Op& op, std::vector<int>& out);
    //! A single-operation candidate with its region.
    Candidate single(const Op& op);
    //! Re-checks `op` (topology and ΔR) on the current mesh and applies its topology, with the
    //! first positions of the vertices it creates or merges; adds the vertices to smooth to
    //! `smooth` and the removed / created ones to `changed`. Logging must be on.
    bool applyTopology(const Op& op, std::vector<int>& smooth, std::vector<int>& changed);
    //! Applies `c` with local smoothing; keeps it only if the geometry stays valid. Fills the
    //! vertices it changed into `changed`.
    bool tryApply(const Candidate& c, std::vector<int>& changed);
    //! Applies the sorted candidates greedily where their region is unlocked; returns how many.
    int applyCandidates(const std::vector<Candidate>& candidates);
    void smoothLocally(const std::vector<int>& verts);
    //! Moves v towards `goal` as its role allows (tangentially, then on the surface / line).
    void moveVertex(int v, const Vec3& goal);
    Vec3 oneRingCentroid(int v) const;
    void updateValences(const std::vector<int>& verts);

    // --- final relaxation and output --------------------------------------------------------
    void relax();
    //! After the relaxation: the corners of the faces that still have an angle under
    //! ValenceParams::minAngleDegrees move (on the surface) to raise the smallest angle of their
    //! incident faces (see kAngleRepairRounds).
    void raiseSmallestAngles();
    //! One vertex of raiseSmallestAngles: a pattern search in its tangent plane; returns whether
    //! it moved.
    bool raiseAnglesAround(int v, double maxSag);
    //! The repairs' pattern search for a Free vertex v on the surface: 8 directions in its tangent
    //! plane, a first step of kAngleRepairStep edge lengths halved when none improves, down to
    //! `smallestStepShare` of it, at most `maxSteps` steps, within kAngleRepairDrift edges of
    //! where v was. At each trial position (v and its closest point set) `improves()` says
    //! whether it is the best so far (and keeps its score); the search stops early once `done()`.
    //! v ends at the best position; returns whether it moved.
    //! Whether the repairs may move v: a live Free vertex with a single fan of faces.
    bool repairMovable(int v) const
    {
        return vertexAlive_[v] && role_[v] == VertexRole::Free && !vertexFaces_[v].empty() && manifold_[v];
    }
    template <class Improves, class Done>
    bool searchOnSurface(int v, int maxSteps, double smallestStepShare, Improves&& improves, Done&& done);
    //! After the angle repair: the corners of the faces that sag most move to lower the largest
    //! sag of their faces (see kSagRepairRounds).
    void lowerLargestSags();
    //! One vertex of lowerLargestSags: a pattern search in its tangent plane; returns whether it moved.
    bool lowerSagAround(int v, double target);
    long long irregularity() const;
    double meanFieldDistance();
    void compact();

    TriMesh& mesh_;
    std::vector<VertexRole>& roles_;
    const ValenceSurface& surface_;
    const ValenceParams& params_;
    std::vector<Vec3> inputNormals_;  //!< area-weighted vertex normals of the input
    //! Distance bounds on the input (faceSagBound); shared by the copies collectAllChains makes.
    std::shared_ptr<const SurfaceWalk> walk_;
    struct SagEntry {
        std::array<Vec3, 3> corners;
        double sag = -1;  //!< < 0: not measured
    };
    std::vector<SagEntry> sagCache_;  //!< per face, see cachedFaceSag

    std::vector<Vec3> pos_;
    std::vector<ClosestPoint> closest_;  //!< per vertex: its closest point on the input
    std::vector<Vec3> normal_;           //!< per vertex: surface normal at its closest point
    std::vector<VertexRole> role_;
    std::vector<char> onBorder_, vertexAlive_, manifold_;
    std::vector<int> valence_;
    std::vector<Face> faces_;
    std::vector<char> faceAlive_;
    std::vector<std::vector<int>> vertexFaces_;  //!< alive incident faces, sorted
    std::vector<UndoEntry> undo_;
    bool logging_ = false;
    double edgeLength_ = 1;  //!< mean edge length of the mesh at the start

    std::vector<int> lockStamp_;
    std::vector<long long> changeStamp_;
    int round_ = 0;
    long long opCounter_ = 0;  //!< operations committed so far
    //! Candidates that failed the geometric checks, with opCounter_ at the time: retried only
    //! once one of their vertices changed.
    std::unordered_map<Candidate, long long, CandidateHash> failed_;
    ValenceStats stats_;
};

ValenceOptimizer::ValenceOptimizer(TriMesh& mesh, std::vector<VertexRole>& roles, const ValenceSurface& surface,
                                   const ValenceParams& params, const std::vector<int>& faceHints)
    : mesh_(mesh), roles_(roles), surface_(surface), params_(params),
      walk_(std::make_shared<const SurfaceWalk>(surface.input))
{
    const int n = mesh.vertexCount();
    for (const Face& f : mesh.faces)
        for (int v : f)
            if (v < 0 || v >= n) throw InvalidInputError("optimizeValence: a face refers to a missing vertex");
    if (!roles.empty() && static_cast<int>(roles.size()) != n)
        throw InvalidInputError("optimizeValence: " + std::to_string(roles.size()) + " vertex roles for " +
                                std::to_string(n) + " vertices");
    if (surface.field && (surface.field->normals.size() != surface.input.vertices.size() ||
                          surface.field->directions.size() != surface.input.vertices.size()))
        throw InvalidInputError("optimizeValence: the field does not match the input surface");
    if (params.maxRounds < 0 || params.localSmoothing < 0 || params.relaxIterations < 0)
        throw InvalidInputError("optimizeValence: negative round or iteration count");

    inputNormals_ = vertexNormals(surface.input);
    pos_ = mesh.vertices;
    role_ = roles.empty() ? std::vector<VertexRole>(n, VertexRole::Free) : roles;
    vertexAlive_.assign(n, 1);
    faces_ = mesh.faces;
    faceAlive_.assign(faces_.size(), 1);
    vertexFaces_.assign(n, {});
    for (int f = 0; f < static_cast<int>(faces_.size()); ++f) {
        const Face& t = faces_[f];
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
            throw InvalidInputError("optimizeValence: face " + std::to_string(f) + " repeats a vertex");
        }
        for (int v : t) vertexFaces_[v].push_back(f);
    }

    // Border vertices (on an edge with one face) aim at valence 4 (§4.4). They keep the places
    // the border's 1D CVT gave them, so a Free one is promoted to Boundary: the border is never
    // flipped, collapsed or split, hence a vertex's border status never changes.
    onBorder_.assign(n, 0);
    std::vector<int> shared;
    double lengthSum = 0;
    long long edgeCount = 0;
    for (int f = 0; f < static_cast<int>(faces_.size()); ++f)
        for (int k = 0; k < 3; ++k) {
            const int a = faces_[f][k], b = faces_[f][(k + 1) % 3];
            edgeFaces(a, b, shared);
            if (shared.size() == 1) onBorder_[a] = onBorder_[b] = 1;
            if (a < b || shared.size() == 1) lengthSum += (pos_[a] - pos_[b]).norm(), ++edgeCount;
        }
    if (edgeCount > 0 && lengthSum > 0) edgeLength_ = lengthSum / edgeCount;
    for (int v = 0; v < n; ++v)
        if (onBorder_[v] && role_[v] == VertexRole::Free) {
            // Measured: camelhead 3000 (seed 1) had one such vertex 1.1 % of the diagonal inside.
            if (!surface.border.empty()) pos_[v] = closestPointOnSegments(pos_[v], surface.border);
            role_[v] = VertexRole::Boundary;
        }

    closest_.resize(n);
    normal_.resize(n);
#pragma omp parallel for schedule(static)
    for (int v = 0; v < n; ++v) {
        closest_[v] = surface.tree.closest(pos_[v], faceHints.empty() ? -1 : faceHints[v]);  // the hint: speed only
        normal_[v] = surfaceNormal(closest_[v]);
    }
    manifold_.assign(n, 1);
    valence_.assign(n, 0);
    Ring r;
    for (int v = 0; v < n; ++v) {
        ring(v, r);
        manifold_[v] = r.ok && !vertexFaces_[v].empty();
        valence_[v] = static_cast<int>(r.verts.size());
    }
    lockStamp_.assign(n, 0);
    changeStamp_.assign(n, 0);
}

// --- mutable mesh --------------------------------------------------------------------------

int ValenceOptimizer::addFace(const Face& f)
{
    const int index = static_cast<int>(faces_.size());
    faces_.push_back(f);
    faceAlive_.push_back(1);
    for (int v : f) vertexFaces_[v].push_back(index);  // the largest index: stays sorted
    if (logging_) undo_.push_back({UndoKind::AddFace, index, {}, {}, {}});
    return index;
}

void ValenceOptimizer::killFace(int f)
{
    faceAlive_[f] = 0;
    for (int v : faces_[f]) {
        auto& list = vertexFaces_[v];
        list.erase(std::lower_bound(list.begin(), list.end(), f));
    }
    if (logging_) undo_.push_back({UndoKind::KillFace, f, {}, {}, {}});
}

int ValenceOptimizer::addVertex(const Vec3& p, VertexRole role)
{
    const int v = static_cast<int>(pos_.size());
    pos_.push_back(p);
    closest_.push_back(surface_.tree.closest(p));
    normal_.push_back(surfaceNormal(closest_.back()));
    role_.push_back(role);
    onBorder_.push_back(0);
    vertexAlive_.push_back(1);
    manifold_.push_back(1);
    valence_.push_back(0);
    vertexFaces_.emplace_back();
    lockStamp_.push_back(0);
    changeStamp_.push_back(0);
    if (logging_) undo_.push_back({UndoKind::AddVertex, v, {}, {}, {}});
    return v;
}

void ValenceOptimizer::killVertex(int v)
{
    vertexAlive_[v] = 0;
    if (logging_) undo_.push_back({UndoKind::KillVertex, v, {}, {}, {}});
}

void ValenceOptimizer::setPosition(int v, const Vec3& p, const ClosestPoint& cp)
{
    if (logging_) undo_.push_back({UndoKind::Move, v, pos_[v], closest_[v], normal_[v]});
    pos_[v] = p;
    closest_[v] = cp;
    normal_[v] = surfaceNormal(cp);
}

void ValenceOptimizer::rollback(size_t mark)
{
    while (undo_.size() > mark) {
        const UndoEntry e = undo_.back();
        undo_.pop_back();
        switch (e.kind) {
        case UndoKind::AddFace:
            for (int v : faces_[e.index]) vertexFaces_[v].pop_back();  // it was appended last
            faces_.pop_back();
            faceAlive_.pop_back();
            break;
        case UndoKind::KillFace:
            faceAlive_[e.index] = 1;
            for (int v : faces_[e.index]) {
                auto& list = vertexFaces_[v];
                list.insert(std::lower_bound(list.begin(), list.end(), e.index), e.index);
            }
            break;
        case UndoKind::Move:
            pos_[e.index] = e.position;
            closest_[e.index] = e.closest;
            normal_[e.index] = e.normal;
            break;
        case UndoKind::AddVertex:
            pos_.pop_back();
            closest_.pop_back();
            normal_.pop_back();
            role_.pop_back();
            onBorder_.pop_back();
            vertexAlive_.pop_back();
            manifold_.pop_back();
            valence_.pop_back();
            vertexFaces_.pop_back();
            lockStamp_.pop_back();
            changeStamp_.pop_back();
            break;
        case UndoKind::KillVertex:
            vertexAlive_[e.index] = 1;
            break;
        case UndoKind::Valence:  // old valence in position.x, manifold flag in position.y
            valence_[e.index] = static_cast<int>(e.position.x());
            manifold_[e.index] = static_cast<char>(e.position.y());
            break;
        }
    }
}

// --- queries -------------------------------------------------------------------------------

void ValenceOptimizer::ring(int v, Ring& r) const
{
    r.verts.clear();
    r.faces.clear();
    r.closed = true;
    r.ok = true;
    const auto& list = vertexFaces_[v];
    const int k = static_cast<int>(list.size());
    if (k == 0) return;
    // Face (v, next, prev) turns counter-clockwise from `next` to `prev`.
    auto nextOf = [&](int f) {
        const Face& t = faces_[f];
        const int i = t[0] == v ? 0 : t[1] == v ? 1 : 2;
        return std::make_pair(t[(i + 1) % 3], t[(i + 2) % 3]);
    };
    // The start: the `next` of a face that is no face's `prev` (border), else the smallest
    // neighbour (a canonical start, so the ring does not depend on the face order).
    int startFace = -1, openStarts = 0;
    for (int f : list) {
        const int nxt = nextOf(f).first;
        bool isPrev = false;
        for (int g : list) isPrev |= nextOf(g).second == nxt;
        if (!isPrev) {
            ++openStarts;
            startFace = f;
        }
    }
    if (openStarts > 1) {
        r.ok = false;
        return;
    }
    r.closed = openStarts == 0;
    if (r.closed) {
        startFace = list[0];
        for (int f : list)
            if (nextOf(f).first < nextOf(startFace).first) startFace = f;
    }
    int f = startFace;
    r.verts.push_back(nextOf(f).first);
    for (int step = 0; step < k; ++step) {
        r.faces.push_back(f);
        const int prv = nextOf(f).second;
        int following = -1, matches = 0;
        for (int g : list)
            if (nextOf(g).first == prv) following = g, ++matches;
        if (matches > 1) {
            r.ok = false;
            return;
        }
        if (following < 0) {  // the end of an open fan
            r.verts.push_back(prv);
            if (step != k - 1) r.ok = false;
            break;
        }
        if (step == k - 1) {
            if (following != startFace) r.ok = false;
            break;
        }
        if (following == startFace) {  // closed before visiting every face: several fans
            r.ok = false;
            return;
        }
        r.verts.push_back(prv);
        f = following;
    }
    if (static_cast<int>(r.faces.size()) != k) r.ok = false;
    // Repeated neighbours (two faces over the same edge on the same side) are not manifold.
    // Pairwise: a ring has a few neighbours, and ring() runs for every candidate operation (no
    // allocation).
    for (size_t a = 1; a < r.verts.size() && r.ok; ++a)
        r.ok = std::find(r.verts.begin(), r.verts.begin() + a, r.verts[a]) == r.verts.begin() + a;
}

void ValenceOptimizer::edgeFaces(int a, int b, std::vector<int>& out) const
{
    out.clear();
    for (int f : vertexFaces_[a]) {
        const Face& t = faces_[f];
        if (t[0] == b || t[1] == b || t[2] == b) out.push_back(f);
    }
}

bool ValenceOptimizer::hasEdge(int a, int b) const
{
    for (int f : vertexFaces_[a]) {
        const Face& t = faces_[f];
        if (t[0] == b || t[1] == b || t[2] == b) return true;
    }
    return false;
}

Vec3 ValenceOptimizer::surfaceNormal(const ClosestPoint& cp) const
{
    if (cp.face < 0) return Vec3::UnitZ();
    const Face& t = surface_.input.faces[cp.face];
    Vec3 n = cp.barycentric[0] * inputNormals_[t[0]] + cp.barycentric[1] * inputNormals_[t[1]] +
             cp.barycentric[2] * inputNormals_[t[2]];
    if (!(n.squaredNorm() > 1e-24)) n = faceNormal(surface_.input, cp.face);
    const double length = n.norm();
    return length > 0 ? Vec3(n / length) : Vec3(Vec3::UnitZ());
}

void ValenceOptimizer::sagPoints(int f, Vec3 (&points)[4], int (&starts)[4]) const
{
    // The centroid and the edge midpoints: an edge across a crease sags most at its middle.
    // The queries start from a corner's closest face (same answers, fewer tree nodes visited).
    const Face& t = faces_[f];
    points[0] = (pos_[t[0]] + pos_[t[1]] + pos_[t[2]]) / 3.0;
    points[1] = 0.5 * (pos_[t[0]] + pos_[t[1]]);
    points[2] = 0.5 * (pos_[t[1]] + pos_[t[2]]);
    points[3] = 0.5 * (pos_[t[2]] + pos_[t[0]]);
    starts[0] = starts[1] = closest_[t[0]].face;
    starts[2] = closest_[t[1]].face;
    starts[3] = closest_[t[2]].face;
}

double ValenceOptimizer::faceSag(int f) const
{
    Vec3 points[4];
    int starts[4];
    sagPoints(f, points, starts);
    double sag = 0;
    for (int k = 0; k < 4; ++k) sag = std::max(sag, (surface_.tree.closest(points[k], starts[k]).point - points[k]).norm());
    return sag;
}

double ValenceOptimizer::faceSagBound(int f) const
{
    Vec3 points[4];
    int starts[4];
    sagPoints(f, points, starts);
    double sag = 0;
    for (int k = 0; k < 4; ++k) sag = std::max(sag, walk_->distanceBound(points[k], starts[k]));
    return sag;
}

const ValenceOptimizer::SagEntry* ValenceOptimizer::rememberedSag(int f) const
{
    if (f >= static_cast<int>(sagCache_.size())) return nullptr;
    const SagEntry& entry = sagCache_[f];
    const Face& t = faces_[f];
    return entry.sag >= 0 && entry.corners == std::array<Vec3, 3>{pos_[t[0]], pos_[t[1]], pos_[t[2]]} ? &entry : nullptr;
}

double ValenceOptimizer::cachedFaceSag(int f)
{
    if (const SagEntry* entry = rememberedSag(f)) return entry->sag;
    if (sagCache_.size() < faces_.size()) sagCache_.resize(faces_.size());
    const Face& t = faces_[f];
    sagCache_[f] = {{pos_[t[0]], pos_[t[1]], pos_[t[2]]}, faceSag(f)};
    return sagCache_[f].sag;
}

bool ValenceOptimizer::sagExceeds(const std::vector<int>& faces, double limit)
{
    for (int f : faces)
        if (faceSagBound(f) > limit && cachedFaceSag(f) > limit) return true;
    return false;
}

Vec3 ValenceOptimizer::faceUnitNormal(int f) const
{
    const Face& t = faces_[f];
    const Vec3 n = (pos_[t[1]] - pos_[t[0]]).cross(pos_[t[2]] - pos_[t[0]]);
    const double length = n.norm();
    return length > 0 ? Vec3(n / length) : Vec3(Vec3::Zero());
}

void ValenceOptimizer::facesAround(const std::vector<int>& verts, std::vector<int>& faces) const
{
    faces.clear();
    for (int v : verts)
        if (vertexAlive_[v]) faces.insert(faces.end(), vertexFaces_[v].begin(), vertexFaces_[v].end());
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
}

void ValenceOptimizer::localShape(const std::vector<int>& faces, double& minAngle, double& minDot) const
{
    minAngle = kPi;
    minDot = 1;
    for (int f : faces) {
        const Face& t = faces_[f];
        minAngle = std::min(minAngle, smallestAngle(pos_[t[0]], pos_[t[1]], pos_[t[2]]));
        const Vec3 reference = normal_[t[0]] + normal_[t[1]] + normal_[t[2]];
        const double length = reference.norm();
        minDot = std::min(minDot, length > 0 ? faceUnitNormal(f).dot(reference) / length : -1.0);
    }
}

// --- candidate operations -----------------------------------------------------------------

bool ValenceOptimizer::evaluateFlip(int a, int b, int& gain, int& c, int& d, int& f1, int& f2) const
{
    if (!manifold_[a] || !manifold_[b]) return false;
    // Feature chains stay: an edge between two feature-line vertices is a feature edge.
    if (isFeatureLike(role_[a]) && isFeatureLike(role_[b])) return false;
    f1 = f2 = -1;
    int count = 0;
    for (int f : vertexFaces_[a]) {
        const Face& t = faces_[f];
        for (int k = 0; k < 3; ++k) {
            if (t[k] != a) continue;
            if (t[(k + 1) % 3] == b) f1 = f, c = t[(k + 2) % 3], ++count;       // (a, b, c)
            else if (t[(k + 2) % 3] == b) f2 = f, d = t[(k + 1) % 3], ++count;  // (b, a, d)
        }
    }
    // Border edges (one face) are never flipped.
    if (count != 2 || f1 < 0 || f2 < 0 || c == d) return false;
    if (!manifold_[c] || !manifold_[d]) return false;
    if (hasEdge(c, d)) return false;  // the new edge exists already: the flip would duplicate it
    if (valence_[a] - 1 < 3 || valence_[b] - 1 < 3) return false;
    gain = valenceDelta(a, -1) + valenceDelta(b, -1) + valenceDelta(c, +1) + valenceDelta(d, +1);
    return true;
}

bool ValenceOptimizer::evaluateCollapse(int a, int b, int& gain, int& keep, int& remove) const
{
    if (!manifold_[a] || !manifold_[b]) return false;
    // At least one Free end; the merged vertex keeps the constrained one's position and role.
    const bool freeA = role_[a] == VertexRole::Free, freeB = role_[b] == VertexRole::Free;
    if (!freeA && !freeB) return false;
    keep = !freeA ? a : !freeB ? b : std::min(a, b);
    remove = keep == a ? b : a;
    int count = 0, c = -1, d = -1;
    for (int f : vertexFaces_[a]) {
        const Face& t = faces_[f];
        for (int k = 0; k < 3; ++k) {
            if (t[k] != a) continue;
            if (t[(k + 1) % 3] == b) c = t[(k + 2) % 3], ++count;
            else if (t[(k + 2) % 3] == b) d = t[(k + 1) % 3], ++count;
        }
    }
    if (count != 2 || c < 0 || d < 0 || c == d) return false;
    if (!manifold_[c] || !manifold_[d]) return false;
    // Link condition: the common neighbours of a and b are exactly the two opposite vertices,
    // otherwise the collapse would pinch the surface (non-manifold edge or vertex).
    std::vector<int> neighbours;
    for (int f : vertexFaces_[a])
        for (int x : faces_[f])
            if (x != a && x != b) neighbours.push_back(x);
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
    int common = 0;
    for (int x : neighbours) common += hasEdge(x, b);
    if (common != 2) return false;
    const int merged = valence_[a] + valence_[b] - 4;
    if (merged < 3 || valence_[c] - 1 < 3 || valence_[d] - 1 < 3) return false;
    gain = cost(keep, merged) - cost(a, valence_[a]) - cost(b, valence_[b]) + valenceDelta(c, -1) + valenceDelta(d, -1);
    return true;
}

void ValenceOptimizer::collectOperations(int v, bool zeroGainFlips, std::vector<Op>& out)
{
    Ring r;
    ring(v, r);
    if (!r.ok) return;
    int gain, c, d, f1, f2, keep, remove;
    auto wanted = [&](int g) { return zeroGainFlips ? g == 0 : g < 0; };
    for (int w : r.verts) {
        // Flips of the edges at v (lower its valence).
        if (evaluateFlip(v, w, gain, c, d, f1, f2) && wanted(gain))
            out.push_back({OpType::Flip, std::min(v, w), std::max(v, w), -1, gain});
        // Collapses of the edges at v.
        if (!zeroGainFlips && evaluateCollapse(v, w, gain, keep, remove) && gain < 0)
            out.push_back({OpType::Collapse, std::min(v, w), std::max(v, w), -1, gain});
    }
    // Flips of the edges opposite v in its faces (raise its valence).
    for (size_t i = 0; i + 1 < r.verts.size() + (r.closed ? 1 : 0); ++i) {
        const int x = r.verts[i], y = r.verts[(i + 1) % r.verts.size()];
        if (evaluateFlip(x, y, gain, c, d, f1, f2) && wanted(gain))
            out.push_back({OpType::Flip, std::min(x, y), std::max(x, y), -1, gain});
    }
    if (zeroGainFlips) return;
    // Splits of v (interior Free vertices): v keeps ring[i..j], the new vertex ring[j..i].
    if (role_[v] == VertexRole::Free && r.closed && !onBorder_[v]) {
        const int n = static_cast<int>(r.verts.size());
        for (int i = 0; i < n; ++i)
            for (int s = 2; s <= n - 2; ++s) {
                const int j = (i + s) % n;
                const int a = r.verts[i], b = r.verts[j];
                const int keptValence = s + 2, newValence = n - s + 2;
                const int before = n - 6;
                gain = (keptValence - 6) * (keptValence - 6) + (newValence - 6) * (newValence - 6) - before * before +
                       valenceDelta(a, +1) + valenceDelta(b, +1);
                if (gain < 0) out.push_back({OpType::Split, v, a, b, gain});
            }
    }
}

void ValenceOptimizer::collectChains(int v, std::vector<Candidate>& out)
{
    // §4.4 look-ahead, deepened: the defects left after the greedy rounds are mostly isolated 5–7
    // pairs (dislocations) and lone 5s / 7s. No single operation lowers R there, but an R-neutral
    // flip moves a 5–7 pair by one edge; a few such moves bring it next to another defect, where
    // a flip, collapse or split annihilates both. Depth-first, bounded by lookAheadDepth.
    Candidate chain;
    extendChain({v}, chain, out);
}

void ValenceOptimizer::collectAllChains(std::vector<Candidate>& out)
{
    std::vector<int> irregular;
    for (int v = 0; v < static_cast<int>(pos_.size()); ++v)
        if (vertexAlive_[v] && manifold_[v] && valence_[v] != target(v)) irregular.push_back(v);
    std::vector<std::vector<Candidate>> found(irregular.size());
    // Copying the state costs about one search of a few dozen vertices: not for small lists.
    const bool parallel = omp_get_max_threads() > 1 && irregular.size() >= 64;
#pragma omp parallel if (parallel)
    {
        std::unique_ptr<ValenceOptimizer> copy;
        if (omp_get_thread_num() > 0) copy = std::make_unique<ValenceOptimizer>(*this);
        ValenceOptimizer& self = copy ? *copy : *this;
#pragma omp barrier
        // (no thread changes the mesh before every copy is made)
#pragma omp for schedule(dynamic, 4)
        for (long long k = 0; k < static_cast<long long>(irregular.size()); ++k)
            self.collectChains(irregular[size_t(k)], found[size_t(k)]);
    }
    for (std::vector<Candidate>& list : found)
        for (Candidate& c : list) out.push_back(std::move(c));
}

void ValenceOptimizer::extendChain(const std::vector<int>& from, Candidate& chain, std::vector<Candidate>& out)
{
    const int existing = static_cast<int>(pos_.size());  // the region holds only these
    std::vector<Op> moves, finals;
    for (int x : from)
        if (vertexAlive_[x] && manifold_[x] && valence_[x] != target(x)) collectOperations(x, true, moves);
    std::sort(moves.begin(), moves.end(), [](const Op& p, const Op& q) { return p.key() < q.key(); });
    moves.erase(std::unique(moves.begin(), moves.end(), [](const Op& p, const Op& q) { return p.key() == q.key(); }),
                moves.end());
    std::vector<int> involved, smooth, changed, around, finalInvolved;
    Ring r;
    for (const Op& move : moves) {
        int gain, c, d, f1, f2;
        if (!evaluateFlip(move.a, move.b, gain, c, d, f1, f2)) continue;
        // Flipping back the edge the previous move created only returns to where we were.
        if (chain.length > 0) {
            const Op& last = chain.ops[chain.length - 1];
            if (last.type == OpType::Flip && std::minmax(c, d) == std::minmax(last.a, last.b)) continue;
        }
        involvedVertices(move, involved);
        const size_t mark = undo_.size();
        const bool wasLogging = logging_;
        logging_ = true;
        smooth.clear();
        changed.clear();
        if (applyTopology(move, smooth, changed)) {
            updateValences(smooth);
            const size_t regionSize = chain.region.size();
            chain.ops[chain.length++] = move;
            chain.region.insert(chain.region.end(), involved.begin(), involved.end());
            // The operation that ends the chain must use what the move changed: operations of
            // the irregular vertices among the flipped quad and its neighbours.
            around = smooth;
            for (int x : smooth) {
                ring(x, r);
                around.insert(around.end(), r.verts.begin(), r.verts.end());
            }
            std::sort(around.begin(), around.end());
            around.erase(std::unique(around.begin(), around.end()), around.end());
            finals.clear();
            for (int x : around)
                if (manifold_[x] && valence_[x] != target(x)) collectOperations(x, false, finals);
            const Op* best = nullptr;
            for (const Op& op : finals)
                if (!best || std::make_tuple(op.gain, op.key()) < std::make_tuple(best->gain, best->key())) best = &op;
            if (best) {
                Candidate found = chain;
                found.ops[found.length++] = *best;
                found.gain = chain.gain + best->gain;
                involvedVertices(*best, finalInvolved);
                found.region.insert(found.region.end(), finalInvolved.begin(), finalInvolved.end());
                found.region.erase(std::remove_if(found.region.begin(), found.region.end(),
                                                  [existing](int x) { return x >= existing; }),
                                   found.region.end());
                std::sort(found.region.begin(), found.region.end());
                found.region.erase(std::unique(found.region.begin(), found.region.end()), found.region.end());
                out.push_back(std::move(found));
            } else if (chain.length + 1 < std::min(params_.lookAheadDepth, kMaxChain)) {
                const std::vector<int> quad = smooth;
                extendChain(quad, chain, out);
            }
            --chain.length;
            chain.region.resize(regionSize);
        }
        rollback(mark);
        logging_ = wasLogging;
    }
}

Candidate ValenceOptimizer::single(const Op& op)
{
    Candidate c;
    c.gain = op.gain;
    c.length = 1;
    c.ops[0] = op;
    involvedVertices(op, c.region);
    return c;
}

void ValenceOptimizer::involvedVertices(const Op& op, std::vector<int>& out)
{
    out.clear();
    Ring r;
    auto addRing = [&](int v) {
        out.push_back(v);
        ring(v, r);
        out.insert(out.end(), r.verts.begin(), r.verts.end());
    };
    if (op.type == OpType::Flip) {
        out = {op.a, op.b};
        int gain, c, d, f1, f2;
        if (evaluateFlip(op.a, op.b, gain, c, d, f1, f2)) out.push_back(c), out.push_back(d);
    } else if (op.type == OpType::Collapse) {
        addRing(op.a);
        addRing(op.b);
    } else if (op.type == OpType::Split) {
        addRing(op.a);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

Vec3 ValenceOptimizer::oneRingCentroid(int v) const
{
    // Area-weighted mean of the one-ring triangles' centroids: the centroid of the union of the
    // triangles, a cheap stand-in for v's Voronoi cell centroid (CVT-like smoothing).
    Vec3 sum = Vec3::Zero();
    double area = 0;
    for (int f : vertexFaces_[v]) {
        const Face& t = faces_[f];
        const Vec3 &p0 = pos_[t[0]], &p1 = pos_[t[1]], &p2 = pos_[t[2]];
        const double a = 0.5 * (p1 - p0).cross(p2 - p0).norm();
        sum += a * (p0 + p1 + p2) / 3.0;
        area += a;
    }
    return area > 0 ? Vec3(sum / area) : pos_[v];
}

void ValenceOptimizer::moveVertex(int v, const Vec3& goal)
{
    const VertexRole role = role_[v];
    if (isFixed(role)) return;
    Vec3 u = goal - pos_[v];
    u -= u.dot(normal_[v]) * normal_[v];  // tangential
    const Vec3 q = pos_[v] + u;
    if (role == VertexRole::Free) {
        const ClosestPoint cp = surface_.tree.closest(q, closest_[v].face);
        setPosition(v, cp.point, cp);
        return;
    }
    if (surface_.features.empty()) return;  // a Feature vertex with nothing to slide along: stays
    const Vec3 p = closestPointOnSegments(q, surface_.features);
    setPosition(v, p, surface_.tree.closest(p, closest_[v].face));
}

void ValenceOptimizer::smoothLocally(const std::vector<int>& verts)
{
    // §4.4: "a local tangential smoothing step to repair the distortion induced by the
    // operation". Gauss–Seidel in index order (deterministic).
    for (int step = 0; step < params_.localSmoothing; ++step)
        for (int v : verts)
            if (vertexAlive_[v] && !vertexFaces_[v].empty()) moveVertex(v, oneRingCentroid(v));
}

void ValenceOptimizer::updateValences(const std::vector<int>& verts)
{
    Ring r;
    for (int v : verts) {
        if (!vertexAlive_[v]) continue;
        if (logging_) undo_.push_back({UndoKind::Valence, v, Vec3(valence_[v], manifold_[v], 0), {}, {}});
        ring(v, r);
        manifold_[v] = r.ok && !vertexFaces_[v].empty();
        valence_[v] = static_cast<int>(r.verts.size());
    }
}

bool ValenceOptimizer::applyTopology(const Op& op, std::vector<int>& smooth, std::vector<int>& changed)
{
    // Re-check the operation on the current mesh: its vertices are unlocked, so nothing has
    // changed around them, but a stale candidate must never be applied.
    int gain = 0;
    Ring r;
    if (op.type == OpType::Flip) {
        int c, d, f1, f2;
        if (!evaluateFlip(op.a, op.b, gain, c, d, f1, f2) || gain != op.gain) return false;
        // (a, b, c) and (b, a, d) become (d, b, c) and (c, a, d): the same orientation.
        killFace(f1);
        killFace(f2);
        addFace({d, op.b, c});
        addFace({c, op.a, d});
        smooth.insert(smooth.end(), {op.a, op.b, c, d});
        return true;
    }
    if (op.type == OpType::Collapse) {
        int keep, remove;
        if (!evaluateCollapse(op.a, op.b, gain, keep, remove) || gain != op.gain) return false;
        const std::vector<int> facesOfRemoved = vertexFaces_[remove];
        const Vec3 midpoint = 0.5 * (pos_[keep] + pos_[remove]);
        const bool bothFree = role_[keep] == VertexRole::Free && role_[remove] == VertexRole::Free;
        for (int f : facesOfRemoved) {
            Face t = faces_[f];
            const bool hasKeep = t[0] == keep || t[1] == keep || t[2] == keep;
            killFace(f);
            if (hasKeep) continue;  // the two faces of the collapsed edge disappear
            for (int& x : t)
                if (x == remove) x = keep;
            addFace(t);
        }
        killVertex(remove);
        // The merged vertex keeps a constrained end's position, else starts at the midpoint.
        if (bothFree) {
            const ClosestPoint cp = surface_.tree.closest(midpoint, closest_[keep].face);
            setPosition(keep, cp.point, cp);
        }
        ring(keep, r);
        smooth.insert(smooth.end(), r.verts.begin(), r.verts.end());
        smooth.push_back(keep);
        changed.push_back(remove);
        return true;
    }
    if (op.type != OpType::Split) return false;
    const int v = op.a;
    ring(v, r);
    if (!r.ok || !r.closed || role_[v] != VertexRole::Free || onBorder_[v]) return false;
    const std::vector<int> splitRing = r.verts;
    const int n = static_cast<int>(splitRing.size());
    int splitI = -1, splitJ = -1;
    for (int i = 0; i < n; ++i) {
        if (splitRing[i] == op.b) splitI = i;
        if (splitRing[i] == op.c) splitJ = i;
    }
    if (splitI < 0 || splitJ < 0) return false;
    const int s = (splitJ - splitI + n) % n;
    if (s < 2 || s > n - 2) return false;
    const int keptValence = s + 2, newValence = n - s + 2, before = n - 6;
    gain = (keptValence - 6) * (keptValence - 6) + (newValence - 6) * (newValence - 6) - before * before +
           valenceDelta(op.b, +1) + valenceDelta(op.c, +1);
    if (gain != op.gain) return false;

    const Vec3 p = pos_[v];
    Vec3 keptCentre = Vec3::Zero(), newCentre = Vec3::Zero();
    int keptCount = 0, newCount = 0;
    for (int k = splitI;; k = (k + 1) % n) {
        keptCentre += pos_[splitRing[k]], ++keptCount;
        if (k == splitJ) break;
    }
    for (int k = splitJ;; k = (k + 1) % n) {
        newCentre += pos_[splitRing[k]], ++newCount;
        if (k == splitI) break;
    }
    keptCentre /= keptCount;
    newCentre /= newCount;
    // Each half starts a third of the way towards the neighbours it keeps; the local smoothing
    // then evens the two fans out.
    const Vec3 newPosition = p + (newCentre - p) / 3.0;
    const int w = addVertex(newPosition, VertexRole::Free);
    setPosition(w, closest_[w].point, closest_[w]);
    // Ring faces (v, ring[k], ring[k+1]) for k = j .. i-1 go to w.
    for (int k = splitJ; k != splitI; k = (k + 1) % n) {
        const int x = splitRing[k], y = splitRing[(k + 1) % n];
        int face = -1;
        for (int f : vertexFaces_[v]) {
            const Face& t = faces_[f];
            for (int q = 0; q < 3; ++q)
                if (t[q] == v && t[(q + 1) % 3] == x && t[(q + 2) % 3] == y) face = f;
        }
        if (face < 0) return false;  // cannot happen on a manifold ring; the caller rolls back
        Face t = faces_[face];
        killFace(face);
        for (int& q : t)
            if (q == v) q = w;
        addFace(t);
    }
    addFace({v, splitRing[splitJ], w});
    addFace({w, splitRing[splitI], v});
    const ClosestPoint cp = surface_.tree.closest(p + (keptCentre - p) / 3.0, closest_[v].face);
    setPosition(v, cp.point, cp);
    smooth.insert(smooth.end(), splitRing.begin(), splitRing.end());
    smooth.push_back(v);
    smooth.push_back(w);
    changed.push_back(w);
    return true;
}

double ValenceOptimizer::operationSagLimit(const std::vector<int>& faces)
{
    // The limit grows with the largest sag before, max(min(growth × sag, sag + step), floor).
    // It is monotone in the sag, so a face whose upper bound (its cached exact sag, else a walk's
    // bound) cannot lift it above the floor needs no exact measure: the same limit, bit for bit,
    // with tree queries only where a face may set it.
    const double floor = kMaxSag * edgeLength_;
    auto grown = [&](double sag) { return std::min(kOperationSagGrowth * sag, sag + kOperationSagStep * edgeLength_); };
    double limit = floor;
    for (int f : faces) {
        const double bound = knownFaceSag(f);
        if (grown(bound) <= floor) continue;  // (a NaN bound is measured)
        limit = std::max(limit, grown(cachedFaceSag(f)));
    }
    return limit;
}

double ValenceOptimizer::knownFaceSag(int f) const
{
    const SagEntry* entry = rememberedSag(f);
    return entry ? entry->sag : faceSagBound(f);
}

bool ValenceOptimizer::tryApply(const Candidate& cand, std::vector<int>& changed)
{
    changed.clear();
    const std::vector<int>& region = cand.region;  // faces around it are compared before and after
    std::vector<int> faces;
    facesAround(region, faces);
    double angleBefore, dotBefore;
    localShape(faces, angleBefore, dotBefore);

    const double sagLimit = operationSagLimit(faces);

    const size_t mark = undo_.size();
    logging_ = true;
    std::vector<int> smooth;
    bool ok = true;
    for (int k = 0; k < cand.length && ok; ++k) {
        ok = applyTopology(cand.ops[k], smooth, changed);
        if (ok) updateValences(smooth);
    }
    if (ok) {
        std::sort(smooth.begin(), smooth.end());
        smooth.erase(std::unique(smooth.begin(), smooth.end()), smooth.end());
        smoothLocally(smooth);
        std::vector<int> after = region;
        after.insert(after.end(), smooth.begin(), smooth.end());
        facesAround(after, faces);
        double angleAfter, dotAfter;
        localShape(faces, angleAfter, dotAfter);
        const double minAngle = params_.minAngleDegrees * kPi / 180.0;
        const bool folded = dotAfter < std::min(kMinNormalDot, dotBefore);
        const bool sharper = angleAfter < minAngle && angleAfter < angleBefore - 1e-9;
        // A flip or collapse across a crease cuts it (d_H): refused like a fold (measured last,
        // the costliest test).
        ok = !folded && !sharper && angleAfter > 0 && !sagExceeds(faces, sagLimit);
    }
    if (!ok) {
        rollback(mark);
        logging_ = false;
        changed.clear();
        return false;
    }
    undo_.clear();
    logging_ = false;
    changed.insert(changed.end(), smooth.begin(), smooth.end());
    return true;
}

// --- final relaxation ------------------------------------------------------------------------

void ValenceOptimizer::relax()
{
    // Stand-in for the paper's "several FCVT iterations after valence optimization" (§4.4): the
    // connectivity is fixed (the regularity gained stays), every vertex moves down the shape
    // energy of its faces (inverse mean ratio) and, with a field, down the field-alignment
    // energy of its edges (eq. 2–3, weighted like E_field), with heavy-ball momentum, then back
    // onto the surface / its line.
    const int n = static_cast<int>(pos_.size());
    std::vector<int> neighbourFirst(n + 1, 0), neighbours;
    {
        Ring r;
        for (int v = 0; v < n; ++v) {
            if (vertexAlive_[v]) {
                ring(v, r);
                neighbours.insert(neighbours.end(), r.verts.begin(), r.verts.end());
            }
            neighbourFirst[v + 1] = static_cast<int>(neighbours.size());
        }
    }
    double area = 0;
    int alive = 0;
    for (int f = 0; f < static_cast<int>(faces_.size()); ++f)
        if (faceAlive_[f]) area += 0.5 * (pos_[faces_[f][1]] - pos_[faces_[f][0]]).cross(pos_[faces_[f][2]] - pos_[faces_[f][0]]).norm();
    for (int v = 0; v < n; ++v) alive += vertexAlive_[v];
    // Working scale of remesh(): mean cell area 1. E_field's gradient converted to mesh units.
    const double workScale = area > 0 ? std::sqrt(alive / area) : 1.0;
    const double fieldFactor = params_.fieldWeight / (2.0 * std::sqrt(3.0) * workScale);
    const double maxStep = kMaxRelaxStep * edgeLength_;
    const double minAngle = params_.minAngleDegrees * kPi / 180.0;
    const double maxSag = kMaxSag * edgeLength_;

    std::vector<Vec3> frameN(n, Vec3::UnitZ()), frameD(n, Vec3::UnitX());
    std::vector<Vec3> oldPos;
    std::vector<ClosestPoint> oldClosest;
    std::vector<Vec3> oldNormal;
    std::vector<double> faceAngleBefore(faces_.size()), faceDotBefore(faces_.size()), faceSagStart(faces_.size());
    // The connectivity is fixed: each face's sag limit comes from its own sag at the start,
    // max(kRelaxSagGrowth × sag, sagFloor), with sagFloor from the largest start sag. The sag
    // points (centroids, and edge midpoints once for their two faces) get a walk's upper bound
    // first; the exact distance (tree) only where it can decide something: the points that may
    // hold the largest sag, and those whose bound could lift their face's limit above the floor.
    // Elsewhere the limit is the floor either way: the same limits, bit for bit, from ~a fifth
    // of the tree queries.
    std::vector<Face> liveFaces;
    std::vector<int> liveFace(faces_.size(), -1);
    for (int f = 0; f < static_cast<int>(faces_.size()); ++f)
        if (faceAlive_[f]) liveFace[f] = static_cast<int>(liveFaces.size()), liveFaces.push_back(faces_[f]);
    const EdgeTable liveEdges = buildEdgeTable(liveFaces, n);
    // Sag points: the live edges' midpoints (as faceSag computes them for the edge's first face;
    // the sum commutes, so its other face gets the same point), then the live faces' centroids.
    const int edgePoints = liveEdges.edgeCount(), pointCount = edgePoints + static_cast<int>(liveFaces.size());
    auto sagPoint = [&](int q, Vec3& x, int& start) {
        if (q < edgePoints) {
            const int h = liveEdges.halfEdge(q, 0);
            const Face& t = liveFaces[h / 3];
            const int k = h % 3;
            x = 0.5 * (pos_[t[k]] + pos_[t[(k + 1) % 3]]);
            start = closest_[t[k]].face;
        } else {
            const Face& t = liveFaces[q - edgePoints];
            x = (pos_[t[0]] + pos_[t[1]] + pos_[t[2]]) / 3.0;
            start = closest_[t[0]].face;
        }
    };
    std::vector<double> startSag(pointCount);  // a bound, exact where `exact`
    std::vector<char> exact(pointCount, 0);
    auto measureExactly = [&](int q) {
        Vec3 x;
        int start;
        sagPoint(q, x, start);
        startSag[q] = (surface_.tree.closest(x, start).point - x).norm();
        exact[q] = 1;
    };
    auto measureExactlyWhere = [&](auto&& needed) {
#pragma omp parallel for schedule(static)
        for (int q = 0; q < pointCount; ++q)
            if (!exact[q] && needed(q)) measureExactly(q);
    };
#pragma omp parallel for schedule(static)
    for (int q = 0; q < pointCount; ++q) {
        Vec3 x;
        int start;
        sagPoint(q, x, start);
        startSag[q] = walk_->distanceBound(x, start);
    }
    // The largest sag: exact at the point of the largest bound, then wherever a bound exceeds it.
    double largestStartSag = 0;
    if (pointCount > 0) {
        const int top = static_cast<int>(std::max_element(startSag.begin(), startSag.end()) - startSag.begin());
        measureExactly(top);
        const double reached = startSag[top];
        measureExactlyWhere([&](int q) { return startSag[q] > reached; });
        for (int q = 0; q < pointCount; ++q)
            if (exact[q]) largestStartSag = std::max(largestStartSag, startSag[q]);
    }
    const double sagFloor = std::max(maxSag, kRelaxSagShareOfLargest * largestStartSag);
    measureExactlyWhere([&](int q) { return kRelaxSagGrowth * startSag[q] > sagFloor; });
    // Per face, an upper bound of each sag point's distance to the surface (sagPoints' order:
    // the centroid, then the midpoints of edges 01, 12, 20) while its corners are sagCorners.
    std::vector<std::array<double, 4>> pointSag(faces_.size());
    for (int f = 0; f < static_cast<int>(faces_.size()); ++f) {
        const int g = liveFace[f];
        if (g < 0) continue;
        pointSag[f] = {startSag[edgePoints + g], startSag[liveEdges.edgeOf(g, 0)], startSag[liveEdges.edgeOf(g, 1)],
                       startSag[liveEdges.edgeOf(g, 2)]};
        // Exact where it lifts the limit above the floor, a bound under the floor elsewhere.
        faceSagStart[f] = *std::max_element(pointSag[f].begin(), pointSag[f].end());
    }
    // The check only asks whether a face's sag exceeds its limit. The distance to the surface is
    // 1-Lipschitz: a sag point moves by at most the mean of its corners' moves (an edge midpoint
    // of its two, the centroid of all three), so its last bound plus that move bounds its
    // distance now. Only the points whose bound reaches the limit (less a rounding margin) are
    // measured again: first by a walk (an upper bound, a fraction of a tree query's cost), then,
    // where the walk's bound still exceeds the limit, exactly by the tree. The answer is the one
    // the four exact distances would give (bunny 5000: 80 000 point walks and 3 600 tree queries,
    // against 112 000 and 14 000 when a face's four points were measured together).
    std::vector<std::array<Vec3, 3>> sagCorners(faces_.size());
    // Per face and sag point, where its walk ended last time: the next walk starts there (the
    // bound may differ with the start, the answers do not: the tree decides above it).
    std::vector<std::array<int, 4>> sagWalkStarts(faces_.size(), {-1, -1, -1, -1});
    for (int f = 0; f < static_cast<int>(faces_.size()); ++f)
        if (faceAlive_[f]) sagCorners[f] = {pos_[faces_[f][0]], pos_[faces_[f][1]], pos_[faces_[f][2]]};
    auto sagExceeds = [&](int f, double limit) {
        const Face& t = faces_[f];
        double m[3];
        for (int k = 0; k < 3; ++k) m[k] = (pos_[t[k]] - sagCorners[f][k]).norm();
        const double moved[4] = {(m[0] + m[1] + m[2]) / 3, 0.5 * (m[0] + m[1]), 0.5 * (m[1] + m[2]), 0.5 * (m[2] + m[0])};
        std::array<double, 4>& bound = pointSag[f];
        const double safe = limit * (1 - 1e-9);
        bool within = true;
        for (int k = 0; k < 4; ++k) within = within && bound[k] + moved[k] <= safe;
        if (within) return false;
        sagCorners[f] = {pos_[t[0]], pos_[t[1]], pos_[t[2]]};
        Vec3 points[4];
        int starts[4];
        sagPoints(f, points, starts);
        bool exceeds = false;
        for (int k = 0; k < 4; ++k) {
            if (bound[k] + moved[k] <= safe) {
                bound[k] += moved[k];  // still a bound at the corners now
                continue;
            }
            int& walkStart = sagWalkStarts[f][k];
            if (walkStart < 0) walkStart = starts[k];
            bound[k] = walk_->distanceBound(points[k], walkStart, &walkStart);
            if (bound[k] <= limit || exceeds) continue;  // one point over the limit answers
            bound[k] = (surface_.tree.closest(points[k], starts[k]).point - points[k]).norm();
            exceeds = bound[k] > limit;
        }
        return exceeds;
    };
    auto faceMeasures = [&](int f, double& angle, double& dot) {
        const Face& t = faces_[f];
        angle = smallestAngle(pos_[t[0]], pos_[t[1]], pos_[t[2]]);
        const Vec3 reference = normal_[t[0]] + normal_[t[1]] + normal_[t[2]];
        const double length = reference.norm();
        dot = length > 0 ? faceUnitNormal(f).dot(reference) / length : -1.0;
    };

    const std::vector<Vec3> startPos = pos_;
    std::vector<Vec3> lastMove(n, Vec3::Zero());  // momentum; zero after a revert
    const double maxDrift = kMaxDrift * edgeLength_;
    // Where each vertex's frame was interpolated (face -1: not yet): a vertex whose closest point
    // has not changed since (it stopped, or was put back) keeps its frame.
    std::vector<int> frameFace(n, -1);
    std::vector<Vec3> frameBarycentric(n);
    // The safety net's measures of every face after an iteration are the next iteration's
    // "before" (the net measures every face once, and again each face of a vertex it puts back).
    std::vector<double> faceAngleAfter(faces_.size()), faceDotAfter(faces_.size());
    for (int iteration = 0; iteration < params_.relaxIterations; ++iteration) {
        if (surface_.field && params_.fieldWeight > 0) {
#pragma omp parallel for schedule(static)
            for (int v = 0; v < n; ++v) {
                const ClosestPoint& c = closest_[v];
                if (!vertexAlive_[v] || c.face < 0 || (c.face == frameFace[v] && c.barycentric == frameBarycentric[v])) continue;
                const FieldSample s = interpolateField(surface_.input, *surface_.field, c.face, c.barycentric);
                frameN[v] = s.normal;
                frameD[v] = s.direction;
                frameFace[v] = c.face;
                frameBarycentric[v] = c.barycentric;
            }
        }
        const int faceCount = static_cast<int>(faces_.size());
        if (iteration == 0) {
#pragma omp parallel for schedule(static)
            for (int f = 0; f < faceCount; ++f)
                if (faceAlive_[f]) faceMeasures(f, faceAngleBefore[f], faceDotBefore[f]);
        } else {
            faceAngleBefore.swap(faceAngleAfter);
            faceDotBefore.swap(faceDotAfter);
        }
        oldPos = pos_;
        oldClosest = closest_;
        oldNormal = normal_;
        // Jacobi update: every vertex computed from the previous positions, so the result does
        // not depend on the thread count.
        std::vector<Vec3> newPos(pos_);
        std::vector<ClosestPoint> newClosest(closest_);
#pragma omp parallel for schedule(static)
        for (int v = 0; v < n; ++v) {
            if (!vertexAlive_[v] || isFixed(role_[v]) || vertexFaces_[v].empty()) continue;
            const int count = neighbourFirst[v + 1] - neighbourFirst[v];
            if (count == 0) continue;  // not a single fan: left alone
            // Down the shape energy of the incident faces (what Q_avg and the angles measure),
            // not to the mean of the neighbours: measured, Q_avg (torus 1000, fertility 3000,
            // bunny 5000, fandisk 5000, nefertiti 10000) 0.958 / 0.956 / 0.956 / 0.951 / 0.958
            // with the mean of the neighbours, 0.965 / 0.965 / 0.963 / 0.958 / 0.965 this way.
            // (The one-ring centroid and ODT's circumcentres were worse than the mean; maximising
            // Q itself oscillates, its longest edge switches.)
            Vec3 shapeGradient = Vec3::Zero();
            double areaSum = 0;
            for (int f : vertexFaces_[v]) {
                const Face& t = faces_[f];
                const int k = t[0] == v ? 0 : t[1] == v ? 1 : 2;
                double faceArea;
                shapeGradient += shapeEnergyGradient(pos_[v], pos_[t[(k + 1) % 3]], pos_[t[(k + 2) % 3]], faceArea);
                areaSum += faceArea;
            }
            Vec3 u = -kShapeStep * (areaSum / vertexFaces_[v].size()) * shapeGradient;
            if (surface_.field && params_.fieldWeight > 0) {
                Vec3 gradient = Vec3::Zero(), g;
                for (int k = neighbourFirst[v]; k < neighbourFirst[v + 1]; ++k) {
                    const int w = neighbours[k];
                    const Vec3 e = pos_[w] - pos_[v];
                    const double length = e.norm();
                    directionDistance(e, frameN[v], frameD[v], &g);
                    gradient -= length * g;
                    directionDistance(-e, frameN[w], frameD[w], &g);
                    gradient += length * g;
                }
                u -= fieldFactor * gradient;
            }
            u += kRelaxMomentum * lastMove[v];
            u -= u.dot(normal_[v]) * normal_[v];
            const double length = u.norm();
            if (length > maxStep) u *= maxStep / length;
            const Vec3 q = pos_[v] + u;
            if (role_[v] == VertexRole::Free) {
                // A short walk over the input from the vertex's face (a step moves it by at
                // most a quarter edge): the nearest point of the surface around it, which is
                // the closest point but where another sheet of the surface comes nearer;
                // the tree where the walk does not settle within its steps.
                bool settled = false;
                ClosestPoint cp = walk_->closestFrom(q, closest_[v].face, &settled);
                if (!settled) cp = surface_.tree.closest(q, closest_[v].face);
                // The relaxation only evens the mesh out: a vertex drifting far from where it
                // started can slide off ridges and tips that it covered (camelhead's lips, with
                // the earlier mean-of-neighbours step: d_H 0.74 -> 1.57 %), so it stops at
                // kMaxDrift edge lengths.
                if ((cp.point - startPos[v]).norm() > maxDrift) continue;
                newClosest[v] = cp;
                newPos[v] = cp.point;
            } else {
                if (surface_.features.empty()) continue;
                newPos[v] = closestPointOnSegments(q, surface_.features);
                newClosest[v] = surface_.tree.closest(newPos[v], closest_[v].face);
            }
        }
        for (int v = 0; v < n; ++v) lastMove[v] = newPos[v] - pos_[v];
        pos_.swap(newPos);
        closest_.swap(newClosest);
#pragma omp parallel for schedule(static)
        for (int v = 0; v < n; ++v)
            if (vertexAlive_[v]) normal_[v] = surfaceNormal(closest_[v]);
        // Safety net: a face that folds, gets a smaller angle than allowed (and than before) or
        // leaves the surface (sag) puts its corners back; then the faces of those corners are
        // checked again, until no face is worse (the old state is valid).
        std::vector<int> check;
        for (int f = 0; f < faceCount; ++f)
            if (faceAlive_[f]) check.push_back(f);
        std::vector<char> wrong(faceCount);
        for (;;) {
#pragma omp parallel for schedule(static)
            for (int k = 0; k < static_cast<int>(check.size()); ++k) {
                const int f = check[k];
                double& angle = faceAngleAfter[f];
                double& dot = faceDotAfter[f];
                faceMeasures(f, angle, dot);
                const bool folded = dot < std::min(kRelaxMinNormalDot, faceDotBefore[f]);
                const bool sharper = angle < minAngle && angle < faceAngleBefore[f] - 1e-9;
                const bool offSurface = sagExceeds(f, std::max(kRelaxSagGrowth * faceSagStart[f], sagFloor));
                wrong[f] = folded || sharper || offSurface;
            }
            std::vector<int> revert;
            for (int f : check)
                if (wrong[f]) revert.insert(revert.end(), faces_[f].begin(), faces_[f].end());
            if (revert.empty()) break;
            std::sort(revert.begin(), revert.end());
            revert.erase(std::unique(revert.begin(), revert.end()), revert.end());
            check.clear();
            for (int v : revert) {
                pos_[v] = oldPos[v];
                closest_[v] = oldClosest[v];
                lastMove[v] = Vec3::Zero();
                normal_[v] = oldNormal[v];
                check.insert(check.end(), vertexFaces_[v].begin(), vertexFaces_[v].end());
            }
            std::sort(check.begin(), check.end());
            check.erase(std::unique(check.begin(), check.end()), check.end());
        }
    }
}

void ValenceOptimizer::raiseSmallestAngles()
{
    const double minAngle = params_.minAngleDegrees * kPi / 180.0;
    const double maxSag = kMaxSag * edgeLength_;
    std::vector<int> verts;
    for (int round = 0; round < kAngleRepairRounds; ++round) {
        verts.clear();
        for (int f = 0; f < static_cast<int>(faces_.size()); ++f) {
            if (!faceAlive_[f]) continue;
            const Face& t = faces_[f];
            if (smallestAngle(pos_[t[0]], pos_[t[1]], pos_[t[2]]) < minAngle) verts.insert(verts.end(), t.begin(), t.end());
        }
        if (verts.empty()) return;
        std::sort(verts.begin(), verts.end());
        verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
        bool moved = false;
        for (int v : verts) moved = raiseAnglesAround(v, maxSag) || moved;  // Gauss–Seidel, index order
        if (!moved) return;
    }
}

template <class Improves, class Done>
bool ValenceOptimizer::searchOnSurface(int v, int maxSteps, double smallestStepShare, Improves&& improves, Done&& done)
{
    // Tangent directions at v: 8 around its normal.
    const Vec3 n = normal_[v];
    const Vec3 t1 = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
    const Vec3 t2 = n.cross(t1);
    const Vec3 start = pos_[v];
    Vec3 bestPos = start;
    ClosestPoint bestClosest = closest_[v];
    double step = kAngleRepairStep * edgeLength_;
    for (int iteration = 0; iteration < maxSteps && !done() && step > kAngleRepairStep * edgeLength_ * smallestStepShare;
         ++iteration) {
        const Vec3 centre = bestPos;
        const ClosestPoint centreClosest = bestClosest;
        bool improved = false;
        for (int k = 0; k < 8; ++k) {
            const double phi = k * kPi / 4;
            const Vec3 q = centre + step * (std::cos(phi) * t1 + std::sin(phi) * t2);
            const ClosestPoint cp = surface_.tree.closest(q, centreClosest.face);
            if ((cp.point - start).norm() > kAngleRepairDrift * edgeLength_) continue;
            setPosition(v, cp.point, cp);
            if (improves()) {
                bestPos = cp.point, bestClosest = cp;
                improved = true;
            }
        }
        setPosition(v, bestPos, bestClosest);
        if (!improved) step *= 0.5;
    }
    return bestPos != start;
}

bool ValenceOptimizer::raiseAnglesAround(int v, double maxSag)
{
    if (!repairMovable(v)) return false;
    const std::vector<int>& faces = vertexFaces_[v];
    double angleBefore, dotBefore;
    localShape(faces, angleBefore, dotBefore);
    double sagBefore = 0;
    for (int f : faces) sagBefore = std::max(sagBefore, cachedFaceSag(f));
    const double sagLimit = std::max(kRelaxSagGrowth * sagBefore, maxSag);
    const double minDot = std::min(kMinNormalDot, dotBefore);
    // At most kAngleRepairMaxSteps pattern steps: each accepted one raises the angle, but by
    // as little as it likes.
    double best = angleBefore;
    auto improves = [&] {
        double angle, dot;
        localShape(faces, angle, dot);
        if (!(angle > best + 1e-9 && dot >= minDot && !sagExceeds(faces, sagLimit))) return false;
        best = angle;
        return true;
    };
    return searchOnSurface(v, kAngleRepairMaxSteps, 1.0 / 32, improves, [] { return false; });
}

void ValenceOptimizer::lowerLargestSags()
{
    const int faceCount = static_cast<int>(faces_.size());
    std::vector<double> bound(faceCount, -1.0);
    std::vector<int> order, faces, verts;
    std::vector<std::pair<double, int>> measured;
    std::vector<int> movedVertices;  // by the last round
    for (int round = 0; round < kSagRepairRounds; ++round) {
        // The walks' bounds (at least the sag, equal to it where the walk settles: most faces)
        // rank the faces; the exact sag is measured down the ranking only until the bounds
        // fall under the band of the largest sag found, so only a few faces need tree queries.
        // After the first round only the faces of the vertices it moved are walked again (a
        // face whose corners and their closest points are as they were has the same bound).
        if (round == 0) {
#pragma omp parallel for schedule(static)
            for (int f = 0; f < faceCount; ++f) bound[f] = faceAlive_[f] ? faceSagBound(f) : -1.0;
        } else {
            for (int v : movedVertices)
                for (int f : vertexFaces_[v]) bound[f] = faceAlive_[f] ? faceSagBound(f) : -1.0;
        }
        order.clear();
        for (int f = 0; f < faceCount; ++f)
            if (faceAlive_[f]) order.push_back(f);
        std::sort(order.begin(), order.end(), [&](int a, int b) { return bound[a] != bound[b] ? bound[a] > bound[b] : a < b; });
        double largest = 0;
        measured.clear();
        for (int f : order) {
            if (bound[f] < (1 - kSagRepairBand) * largest) break;
            const double sag = cachedFaceSag(f);
            largest = std::max(largest, sag);
            measured.emplace_back(sag, f);
        }
        // A flat mesh's sags are rounding noise: nothing to gain, and its shape to lose.
        if (!(largest > kSagRepairMinSag * edgeLength_)) return;
        // The largest first, ties by index.
        std::sort(measured.begin(), measured.end(), [](const auto& a, const auto& b) { return a.first != b.first ? a.first > b.first : a.second < b.second; });
        faces.clear();
        for (const auto& [sag, f] : measured)
            if (sag >= (1 - kSagRepairBand) * largest && faces.size() < static_cast<size_t>(kSagRepairFaces)) faces.push_back(f);
        verts.clear();
        for (int f : faces) verts.insert(verts.end(), faces_[f].begin(), faces_[f].end());
        std::sort(verts.begin(), verts.end());
        verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
        bool moved = false;
        movedVertices.clear();
        for (int v : verts) {  // Gauss–Seidel
            const Vec3 position = pos_[v];
            const int face = closest_[v].face;
            moved = lowerSagAround(v, (1 - kSagRepairBand) * largest) || moved;
            if (pos_[v] != position || closest_[v].face != face) movedVertices.push_back(v);
        }
        if (!moved) return;
    }
}

bool ValenceOptimizer::lowerSagAround(int v, double target)
{
    if (!repairMovable(v)) return false;
    const std::vector<int>& faces = vertexFaces_[v];
    double angleBefore, dotBefore;
    localShape(faces, angleBefore, dotBefore);
    const double minDot = std::min(kMinNormalDot, dotBefore);
    // Per face: no smallest angle under min(35° + margin, its own before). (A vertex of more
    // than 32 faces is left alone: no such fan is worth moving.)
    const double angleBound = (params_.minAngleDegrees + kSagRepairAngleMargin) * kPi / 180.0;
    double faceAngleBefore[32];
    const int faceCount = static_cast<int>(faces.size());
    if (faceCount > 32) return false;
    for (int i = 0; i < faceCount; ++i) {
        const Face& t = faces_[faces[i]];
        faceAngleBefore[i] = std::min(angleBound, smallestAngle(pos_[t[0]], pos_[t[1]], pos_[t[2]]));
    }
    auto sharper = [&] {
        for (int i = 0; i < faceCount; ++i) {
            const Face& t = faces_[faces[i]];
            if (smallestAngle(pos_[t[0]], pos_[t[1]], pos_[t[2]]) < faceAngleBefore[i]) return true;
        }
        return false;
    };
    // Down to the band's lower edge, no further: the faces' shape pays for every move.
    auto largestSag = [&] {
        double largest = target;
        for (int f : faces) largest = std::max(largest, cachedFaceSag(f));
        return largest;
    };
    auto meanShape = [&] {
        double sum = 0;
        for (int f : faces) {
            const Face& t = faces_[f];
            sum += meanRatio(pos_[t[0]], pos_[t[1]], pos_[t[2]]);
        }
        return sum / faces.size();
    };
    const double minShape = meanShape() - kSagRepairShapeLoss;
    double best = largestSag();
    int order[32];
    std::copy(faces.begin(), faces.end(), order);
    auto improves = [&] {
        double angle, dot;
        localShape(faces, angle, dot);  // (the angles per face: sharper())
        if (dot < minDot || sharper() || meanShape() < minShape) return false;
        // largestSag() < limit, face by face: the first face at or over the limit answers (most
        // trial positions are refused, and each face's sag costs four closest-point queries);
        // the face that refused the last one is asked first.
        const double limit = best * (1 - 1e-6);
        if (!(target < limit)) return false;
        double sagHere = target;
        for (int i = 0; i < faceCount; ++i) {
            const double sag = cachedFaceSag(order[i]);
            if (sag >= limit) {
                std::swap(order[0], order[i]);
                return false;
            }
            sagHere = std::max(sagHere, sag);
        }
        best = sagHere;
        return true;
    };
    return searchOnSurface(v, kSagRepairMaxSteps, 1.0 / 8, improves, [&] { return !(best > target); });
}

long long ValenceOptimizer::irregularity() const
{
    long long sum = 0;
    for (int v = 0; v < static_cast<int>(pos_.size()); ++v) {
        if (!vertexAlive_[v] || vertexFaces_[v].empty()) continue;
        sum += cost(v, valence_[v]);
    }
    return sum;
}

double ValenceOptimizer::meanFieldDistance()
{
    if (!surface_.field) return 0;
    double sum = 0;
    long long count = 0;
    Ring r;
    for (int v = 0; v < static_cast<int>(pos_.size()); ++v) {
        if (!vertexAlive_[v] || closest_[v].face < 0) continue;
        const FieldSample s = interpolateField(surface_.input, *surface_.field, closest_[v].face, closest_[v].barycentric);
        ring(v, r);
        for (int w : r.verts) sum += directionDistance(pos_[w] - pos_[v], s.normal, s.direction), ++count;
    }
    return count > 0 ? sum / count : 0;
}

void ValenceOptimizer::compact()
{
    const int n = static_cast<int>(pos_.size());
    std::vector<int> index(n, -1);
    TriMesh out;
    std::vector<VertexRole> roles;
    for (int v = 0; v < n; ++v)
        if (vertexAlive_[v]) {
            index[v] = out.vertexCount();
            out.vertices.push_back(pos_[v]);
            roles.push_back(role_[v]);
        }
    for (int f = 0; f < static_cast<int>(faces_.size()); ++f)
        if (faceAlive_[f]) out.faces.push_back({index[faces_[f][0]], index[faces_[f][1]], index[faces_[f][2]]});
    mesh_ = std::move(out);
    roles_ = std::move(roles);
}

int ValenceOptimizer::applyCandidates(const std::vector<Candidate>& candidates)
{
    std::vector<int> changed;
    Ring r;
    int applied = 0;
    for (const Candidate& cand : candidates) {
        if (cand.gain >= 0) continue;
        bool locked = false;
        long long lastChange = 0;
        for (int v : cand.region) {
            locked |= lockStamp_[v] == round_;
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
            if (op.type == OpType::Flip) ++stats_.flips;
            else if (op.type == OpType::Collapse) ++stats_.collapses;
            else if (op.type == OpType::Split) ++stats_.splits;
        }
        // Lock the changed vertices for this round (their rings are no longer the ones the
        // candidates were computed on) and mark their neighbourhood as changed.
        for (int v : changed) {
            lockStamp_[v] = round_;
            changeStamp_[v] = opCounter_;
            if (!vertexAlive_[v]) continue;
            ring(v, r);
            for (int w : r.verts) changeStamp_[w] = opCounter_;
        }
    }
    return applied;
}

ValenceStats ValenceOptimizer::run()
{
    stats_.v6Before = v6Percent(mesh_);
    stats_.verticesBefore = mesh_.vertexCount();
    stats_.irregularityBefore = irregularity();
    stats_.fieldDistanceBefore = meanFieldDistance();

    std::vector<Candidate> candidates;
    std::vector<Op> operations;
    for (round_ = 1; round_ <= params_.maxRounds; ++round_) {
        // §4.4: per irregular vertex, the operations that lower R; all of them sorted by gain
        // (ties by kind and index), then applied greedily where nothing has changed yet. When
        // none is left, the look-ahead chains (R-neutral flips, then an operation they enable).
        int applied = 0;
        bool lookAhead = false;
        for (int pass = 0; pass < (params_.lookAheadDepth >= 2 ? 2 : 1) && applied == 0; ++pass) {
            lookAhead = pass == 1;
            const int n = static_cast<int>(pos_.size());
            candidates.clear();
            if (pass == 1) collectAllChains(candidates);
            for (int v = 0; v < n && pass == 0; ++v) {
                if (!vertexAlive_[v] || !manifold_[v] || valence_[v] == target(v)) continue;
                operations.clear();
                collectOperations(v, false, operations);
                for (const Op& op : operations) candidates.push_back(single(op));
            }
            std::sort(candidates.begin(), candidates.end());
            candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
            applied = applyCandidates(candidates);
        }
        stats_.rounds = round_;
        if (applied == 0) break;
        if (lookAhead && applied < params_.minChainsPerRound) break;  // diminishing returns (minChainsPerRound)
    }
    stats_.irregularityAfter = irregularity();
    stats_.fieldDistanceOperations = meanFieldDistance();
    relax();
    raiseSmallestAngles();
    lowerLargestSags();
    stats_.fieldDistanceAfter = meanFieldDistance();
    compact();
    stats_.v6After = v6Percent(mesh_);
    stats_.verticesAfter = mesh_.vertexCount();
    return stats_;
}

}  // namespace

ValenceStats optimizeValence(TriMesh& mesh, std::vector<VertexRole>& roles, const ValenceSurface& surface,
                             const ValenceParams& params, const std::vector<int>& faceHints)
{
    if (!faceHints.empty() && faceHints.size() != mesh.vertices.size())
        throw InvalidInputError("optimizeValence: " + std::to_string(faceHints.size()) + " face hints for " +
                                std::to_string(mesh.vertices.size()) + " vertices");
    if (mesh.faces.empty()) {
        ValenceStats stats;
        if (roles.empty()) roles.assign(mesh.vertices.size(), VertexRole::Free);
        return stats;
    }
    ValenceOptimizer optimizer(mesh, roles, surface, params, faceHints);
    return optimizer.run();
}

}  // namespace fieldcvt
