#include "lattice.h"

#include "boundary.h"
#include "field_hierarchy.h"
#include "point_tree.h"
#include "sampling.h"  // unitInterval

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

namespace fieldcvt {

namespace {

// The lattice point (integer coordinates a, b) of {origin + ρ(a·d + b·R60·d)} nearest to the
// point whose tangent coordinates relative to origin are (x, y) in the frame (d, n × d). The
// parallelogram cell with corners (⌊u⌋ + {0,1}, ⌊v⌋ + {0,1}) is two equilateral triangles, and
// a point of an equilateral triangle is nearest to one of its corners: four candidates suffice.
void nearestInFrame(double x, double y, double spacing, double& a, double& b)
{
    constexpr double s = rosy::kSin60;
    const double v = y / (s * spacing), u = x / spacing - 0.5 * v;
    const double fu = std::floor(u), fv = std::floor(v);
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
            const double du = fu + i - u, dv = fv + j - v;
            // |du·d + dv·R60 d|² in units of ρ²
            const double d2 = du * du + du * dv + dv * dv;
            if (d2 < best) best = d2, a = fu + i, b = fv + j;
        }
}

// nearestLatticePoint with the frame's second axis t = n × d given.
inline Vec3 nearestWithFrame(const Vec3& origin, const Vec3& d, const Vec3& t, double spacing, const Vec3& target)
{
    const Vec3 r = target - origin;
    double a = 0, b = 0;
    nearestInFrame(r.dot(d), r.dot(t), spacing, a, b);
    return origin + spacing * ((a + 0.5 * b) * d + (rosy::kSin60 * b) * t);
}

// What the sweeps of one level read and never change: each vertex's frame (d, n × d) and each
// directed edge's middle point (computed once, for every pass of latticeSamples).
struct LevelFrames {
    std::vector<Vec3> d, t;
    std::vector<Vec3> middle;  // per directed entry of the level's graph
};

LevelFrames levelFrames(const FieldGraph& g, const std::vector<Vec3>& d)
{
    LevelFrames f;
    const int n = g.vertexCount();
    f.d = d;
    f.t.resize(n);
    f.middle.resize(g.neighbours.size());
#pragma omp parallel for schedule(static) if (n > 32768)
    for (int i = 0; i < n; ++i) {
        f.t[i] = g.normals[i].cross(d[i]);
        for (int e = g.offsets[i]; e < g.offsets[i + 1]; ++e) {
            const int j = g.neighbours[e];
            f.middle[e] = middlePoint(g.positions[i], g.normals[i], g.positions[j], g.normals[j]);
        }
    }
    return f;
}

// One level's position field: Gauss–Seidel sweeps colour class by colour class (the field
// solver's scheme, field_hierarchy.cpp), so the result does not depend on the thread count.
void smoothPositions(const FieldGraph& g, const LevelFrames& f, std::vector<Vec3>& origin, double spacing, int iterations)
{
    const int n = g.vertexCount();
    const int colours = static_cast<int>(g.colourOffsets.size()) - 1;
    // Threads from 256 vertices per colour class on (the field solver waits for 1024, because
    // every class ends with a barrier): faster on the finest levels (docs/tuning.md, "Threads
    // per colour class").
    const bool parallel = colours > 0 && n / colours >= 256;
    // The running weighted mean of Jakob et al.'s update: each neighbour j moves i's lattice by
    // the offset between the two lattices' points nearest to the edge's middle point (where
    // both lattices are meant to agree), weighted like the orientation field's edges.
    auto edgeStep = [&](int i, int e, Vec3& current, double& weightSum) {
        const int j = g.neighbours[e];
        const Vec3 mine = nearestWithFrame(current, f.d[i], f.t[i], spacing, f.middle[e]);
        // j's point nearest to mine, not to the middle: near a tie the two lattices would
        // otherwise pick different points and see a whole lattice step.
        const Vec3 theirs = nearestWithFrame(origin[j], f.d[j], f.t[j], spacing, mine);
        const double w = g.weights[e];
        current += (w / (weightSum + w)) * (theirs - mine);
        weightSum += w;
        current -= g.normals[i].dot(current - g.positions[i]) * g.normals[i];  // back on i's tangent plane
    };
#pragma omp parallel if (parallel)
    for (int it = 0; it < iterations; ++it) {
        for (int c = 0; c < colours; ++c) {
            // Two vertices of the class at a time, their edges in lockstep: each update is a
            // chain of dependent steps, and two independent chains keep the core busier. Each
            // vertex's own steps (and so the result) are those of one at a time.
            const int first = g.colourOffsets[c], count = g.colourOffsets[c + 1] - first;
#pragma omp for schedule(static)
            for (int p = 0; p < (count + 1) / 2; ++p) {
                const int a = g.colourVertices[first + 2 * p];
                const int b = 2 * p + 1 < count ? g.colourVertices[first + 2 * p + 1] : -1;
                Vec3 currentA = origin[a], currentB = b >= 0 ? origin[b] : Vec3::Zero();
                double sumA = 0, sumB = 0;
                int ea = g.offsets[a], eb = b >= 0 ? g.offsets[b] : 0;
                const int endA = g.offsets[a + 1], endB = b >= 0 ? g.offsets[b + 1] : 0;
                while (ea < endA || eb < endB) {
                    if (ea < endA) edgeStep(a, ea++, currentA, sumA);
                    if (eb < endB) edgeStep(b, eb++, currentB, sumB);
                }
                origin[a] = nearestWithFrame(currentA, f.d[a], f.t[a], spacing, g.positions[a]);
                if (b >= 0) origin[b] = nearestWithFrame(currentB, f.d[b], f.t[b], spacing, g.positions[b]);
            }
        }
    }
}

}  // namespace

Vec3 nearestLatticePoint(const Vec3& origin, const Vec3& d, const Vec3& n, double spacing, const Vec3& target)
{
    return nearestWithFrame(origin, d, n.cross(d), spacing, target);
}

Vec3 middlePoint(const Vec3& p0, const Vec3& n0, const Vec3& p1, const Vec3& n1)
{
    // m = mid + α n0 + β n1 with n0·m = n0·p0 and n1·m = n1·p1: a 2×2 system whose matrix
    // [1 c; c 1] (c = n0·n1) is singular for parallel planes, hence the small regulariser.
    const Vec3 mid = 0.5 * (p0 + p1);
    const double c = n0.dot(n1);
    const double r0 = n0.dot(p0 - mid), r1 = n1.dot(p1 - mid);
    const double det = 1 - c * c + 1e-4;
    const double alpha = (r0 - c * r1) / det, beta = (r1 - c * r0) / det;
    return mid + alpha * n0 + beta * n1;
}

double latticeSpacingFor(const TriMesh& surface, int count)
{
    const double area = surfaceArea(surface);
    double border = 0;
    for (const Segment& edge : boundarySegments(surface)) border += (edge.second - edge.first).norm();
    // count = area / (√3/2·ρ²) + border / (2ρ), a quadratic in x = 1/ρ.
    const double qa = area / rosy::kSin60, qb = 0.5 * border, qc = -static_cast<double>(count);
    const double x = (-qb + std::sqrt(qb * qb - 4 * qa * qc)) / (2 * qa);
    return 1 / x;
}

namespace {

// Frames on every level of the hierarchy: level 0's directions are the field's, each coarser
// vertex's the compatible average (6-RoSy mean) of its children's.
std::vector<LevelFrames> framesOnLevels(const FieldHierarchyLevels& h, const DirectionField& field)
{
    const int levels = static_cast<int>(h.levels.size());
    std::vector<std::vector<Vec3>> dirs(levels);
    dirs[0] = field.directions;
    for (int l = 1; l < levels; ++l) {
        const FieldGraph& coarse = h.levels[l];
        const std::vector<int>& parent = h.parents[l - 1];
        const int m = coarse.vertexCount();
        std::vector<int> first(m + 1, 0);
        for (int p : parent) ++first[p + 1];
        for (int p = 0; p < m; ++p) first[p + 1] += first[p];
        std::vector<Vec3> children(parent.size());
        std::vector<int> fill(first.begin(), first.end() - 1);
        for (size_t v = 0; v < parent.size(); ++v) children[fill[parent[v]]++] = dirs[l - 1][v];
        dirs[l].resize(m);
        for (int p = 0; p < m; ++p)
            if (!averageCompatible(coarse.normals[p], children.data() + first[p], first[p + 1] - first[p], dirs[l][p]))
                dirs[l][p] = rosy::anyTangent(coarse.normals[p]);
    }
    std::vector<LevelFrames> frames;
    for (int l = 0; l < levels; ++l) frames.push_back(levelFrames(h.levels[l], dirs[l]));
    return frames;
}

// Coarse to fine: at the coarsest level every origin starts at its vertex; each level is
// smoothed and hands its lattices to its children (the parent's origin on the child's plane,
// moved to the lattice point nearest the child).
std::vector<Vec3> solveOnHierarchy(const FieldHierarchyLevels& h, const std::vector<LevelFrames>& frames, double spacing,
                                   int iterations, std::uint64_t seed)
{
    const int levels = static_cast<int>(h.levels.size());
    // The seed shifts the coarsest lattices by a random fraction of a cell (a seeded,
    // platform-independent draw, like sampling.h): another seed, another phase of the lattice.
    const FieldGraph& coarsest = h.levels[levels - 1];
    std::vector<Vec3> origin = coarsest.positions;
    std::mt19937_64 rng(seed);
    for (int v = 0; v < coarsest.vertexCount(); ++v) {
        const double a = unitInterval(rng()), b = unitInterval(rng());
        const LevelFrames& f = frames[levels - 1];
        origin[v] += spacing * ((a + 0.5 * b) * f.d[v] + (rosy::kSin60 * b) * f.t[v]);
    }
    for (int l = levels - 1; l >= 0; --l) {
        smoothPositions(h.levels[l], frames[l], origin, spacing, iterations);
        if (l == 0) break;
        const FieldGraph& fine = h.levels[l - 1];
        const std::vector<int>& parent = h.parents[l - 1];
        std::vector<Vec3> finer(fine.vertexCount());
#pragma omp parallel for schedule(static) if (fine.vertexCount() > 32768)
        for (int v = 0; v < fine.vertexCount(); ++v) {
            const Vec3& x = fine.positions[v];
            const Vec3& n = fine.normals[v];
            Vec3 o = origin[parent[v]];
            o -= n.dot(o - x) * n;
            finer[v] = nearestWithFrame(o, frames[l - 1].d[v], frames[l - 1].t[v], spacing, x);
        }
        origin.swap(finer);
    }
    return origin;
}

// The lattice points of one face, from each of its corners' lattices (frames: level 0's): the
// integer points of the corner's lattice coordinates that fall in the face projected on the
// corner's tangent plane, each handed to `emit`. Where the three lattices agree the face gives
// each point three times (merged by latticePoints); where they do not, the union still covers
// the face.
template <class Emit>
void facePoints(const TriMesh& surface, int f, const LevelFrames& frames, const std::vector<Vec3>& origin, double rho,
                Emit&& emit)
{
    constexpr double s = rosy::kSin60;
    const Face& t = surface.faces[f];
    for (int corner = 0; corner < 3; ++corner) {
        const int v = t[corner];
        const Vec3& o = origin[v];
        const Vec3& d = frames.d[v];
        const Vec3& tangent = frames.t[v];
        // The face's corners in lattice coordinates (u, v) of this corner's lattice.
        double u[3], w[3];
        for (int k = 0; k < 3; ++k) {
            const Vec3 r = surface.vertices[t[k]] - o;
            w[k] = r.dot(tangent) / (s * rho);
            u[k] = r.dot(d) / rho - 0.5 * w[k];
        }
        const double area = (u[1] - u[0]) * (w[2] - w[0]) - (u[2] - u[0]) * (w[1] - w[0]);
        if (!(std::abs(area) > 1e-12)) continue;  // the face is edge-on to this plane
        const double tolerance = 1e-9 * std::abs(area);
        const int u0 = static_cast<int>(std::ceil(std::min({u[0], u[1], u[2]}) - 1e-9));
        const int u1 = static_cast<int>(std::floor(std::max({u[0], u[1], u[2]}) + 1e-9));
        const int w0 = static_cast<int>(std::ceil(std::min({w[0], w[1], w[2]}) - 1e-9));
        const int w1 = static_cast<int>(std::floor(std::max({w[0], w[1], w[2]}) + 1e-9));
        for (int a = u0; a <= u1; ++a)
            for (int b = w0; b <= w1; ++b) {
                bool inside = true;
                for (int k = 0; k < 3 && inside; ++k) {  // same side of each edge as the face
                    const int k1 = (k + 1) % 3;
                    const double side = (u[k1] - u[k]) * (b - w[k]) - (a - u[k]) * (w[k1] - w[k]);
                    inside = area > 0 ? side >= -tolerance : side <= tolerance;
                }
                if (inside) emit(o + rho * ((a + 0.5 * b) * d + (s * b) * tangent));
            }
    }
}

// The lattice points over the surface, given each vertex's lattice origin.
std::vector<Vec3> latticePoints(const TriMesh& surface, const LevelFrames& frames, const std::vector<Vec3>& origin, double rho,
                                int* candidateCount, std::vector<int>& sampleFaces)
{
    // Every face's points in face order (thread-count independent): counted first, then written
    // at their face's offset, so no per-face container is allocated.
    const int faces = surface.faceCount();
    std::vector<int> first(faces + 1, 0);
#pragma omp parallel for schedule(static)
    for (int f = 0; f < faces; ++f) facePoints(surface, f, frames, origin, rho, [&](const Vec3&) { ++first[f + 1]; });
    for (int f = 0; f < faces; ++f) first[f + 1] += first[f];
    std::vector<Vec3> candidates(first[faces]);
#pragma omp parallel for schedule(static)
    for (int f = 0; f < faces; ++f) {
        int next = first[f];
        facePoints(surface, f, frames, origin, rho, [&](const Vec3& p) { candidates[next++] = p; });
    }
    if (candidateCount) *candidateCount = static_cast<int>(candidates.size());

    // Points of neighbouring faces that are the same lattice point (closer than ρ/2; distinct
    // points of one lattice are ρ apart) become one sample at their mean, in candidate order.
    PointCloud cloud{&candidates};
    PointTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    tree.buildIndex();
    std::vector<int> cluster(candidates.size(), -1);
    std::vector<Vec3> samples;
    std::vector<double> members;
    std::vector<std::pair<double, uint32_t>> near;
    const double radius2 = 0.25 * rho * rho;
    for (size_t i = 0; i < candidates.size(); ++i) {
        if (cluster[i] >= 0) continue;
        const int id = static_cast<int>(samples.size());
        samples.push_back(Vec3::Zero());
        members.push_back(0);
        // The face that gave this candidate (faces' candidates are in face order).
        sampleFaces.push_back(
            static_cast<int>(std::upper_bound(first.begin(), first.end(), static_cast<int>(i)) - first.begin()) - 1);
        // The candidates within the radius, nearest first, equal distances in the order the
        // search meets them: the order of a k-nearest search (which ranks them so), at the cost
        // of a radius search (~3 found instead of 16 asked for).
        near.clear();
        WithinRadius within(radius2, near);
        tree.findNeighbors(within, candidates[i].data(), KnnSearchParams());
        std::stable_sort(near.begin(), near.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        for (const auto& [distance2, k] : near)
            if (cluster[k] < 0) {
                cluster[k] = id;
                samples[id] += candidates[k];
                members[id] += 1;
            }
    }
    for (size_t s = 0; s < samples.size(); ++s) samples[s] /= members[s];
    return samples;
}

}  // namespace

std::vector<Vec3> solvePositionField(const TriMesh& surface, const DirectionField& field, double spacing, int iterations,
                                     std::uint64_t seed)
{
    const FieldHierarchyLevels h = buildFieldHierarchy(surface, field.normals);
    return solveOnHierarchy(h, framesOnLevels(h, field), spacing, iterations, seed);
}

std::vector<Vec3> latticeSamples(const TriMesh& surface, const DirectionField& field, int count, const LatticeParams& params,
                                 LatticeReport* report, const FieldHierarchyLevels* hierarchy, std::vector<int>* sampleFaces)
{
    FieldHierarchyLevels built;
    const bool reuse = hierarchy && !hierarchy->levels.empty() && hierarchy->levels[0].vertexCount() == surface.vertexCount();
    if (!reuse) built = buildFieldHierarchy(surface, field.normals);
    const FieldHierarchyLevels& h = reuse ? *hierarchy : built;
    const std::vector<LevelFrames> frames = framesOnLevels(h, field);
    LatticeReport local;
    LatticeReport& r = report ? *report : local;
    r = LatticeReport{};
    r.levels = static_cast<int>(h.levels.size());
    // The count goes as 1/ρ² (the border's half row as 1/ρ): each correction lands closer,
    // but the count moves in steps (whole rows), so the closest of a few passes is kept.
    std::vector<Vec3> samples;
    std::vector<int> faces, keptFaces;
    double spacing = latticeSpacingFor(surface, count);
    for (r.passes = 1; r.passes <= params.maxPasses; ++r.passes) {
        int candidates = 0;
        faces.clear();
        std::vector<Vec3> points =
            latticePoints(surface, frames[0], solveOnHierarchy(h, frames, spacing, params.iterations, params.seed), spacing,
                          &candidates, faces);
        const double ratio = double(points.size()) / count;
        if (samples.empty() || std::abs(double(points.size()) - count) < std::abs(double(samples.size()) - count)) {
            samples.swap(points);
            keptFaces.swap(faces);
            r.spacing = spacing;
            r.candidates = candidates;
        }
        if (std::abs(ratio - 1) <= params.countTolerance || r.passes == params.maxPasses) break;
        spacing *= std::sqrt(ratio);
    }
    r.samples = static_cast<int>(samples.size());
    if (sampleFaces) *sampleFaces = std::move(keptFaces);
    return samples;
}

}  // namespace fieldcvt
