#include "field_hierarchy.h"

#include "sampling.h"  // unitInterval: platform-independent doubles from the generator

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace fieldcvt {

namespace rosy {

Vec3 anyTangent(const Vec3& n)
{
    // Cross with the coordinate axis least aligned with n: never degenerate.
    int axis = 0;
    if (std::abs(n.y()) < std::abs(n[axis])) axis = 1;
    if (std::abs(n.z()) < std::abs(n[axis])) axis = 2;
    return n.cross(Vec3::Unit(axis)).normalized();
}

}  // namespace rosy

namespace {

struct DirectedEdge {
    int from, to;
    double weight;
};

// CSR adjacency from directed entries (both directions must be present); duplicates merge and
// add their weights. Bucketing by `from` then sorting each short bucket keeps it O(E log deg).
void buildAdjacency(int vertexCount, const std::vector<DirectedEdge>& edges, FieldGraph& g)
{
    std::vector<int> count(vertexCount + 1, 0);
    for (const DirectedEdge& e : edges) ++count[e.from + 1];
    for (int v = 0; v < vertexCount; ++v) count[v + 1] += count[v];
    std::vector<std::pair<int, double>> bucket(edges.size());
    std::vector<int> fill(count.begin(), count.end() - 1);
    for (const DirectedEdge& e : edges) bucket[fill[e.from]++] = {e.to, e.weight};

    g.offsets.assign(vertexCount + 1, 0);
    g.neighbours.clear();
    g.weights.clear();
    g.neighbours.reserve(edges.size());
    g.weights.reserve(edges.size());
    for (int v = 0; v < vertexCount; ++v) {
        auto first = bucket.begin() + count[v], last = bucket.begin() + count[v + 1];
        std::sort(first, last, [](const auto& a, const auto& b) { return a.first < b.first; });
        for (auto it = first; it != last; ++it) {
            if (!g.neighbours.empty() && static_cast<int>(g.neighbours.size()) > g.offsets[v] && g.neighbours.back() == it->first)
                g.weights.back() += it->second;
            else {
                g.neighbours.push_back(it->first);
                g.weights.push_back(it->second);
            }
        }
        g.offsets[v + 1] = static_cast<int>(g.neighbours.size());
    }
}

// Greedy colouring in vertex order (deterministic); vertices grouped by colour.
void colourGraph(FieldGraph& g)
{
    const int n = g.vertexCount();
    std::vector<int> colour(n, -1);
    std::vector<int> stamp;  // stamp[c] == v: colour c is used by a neighbour of v
    int colours = 0;
    for (int v = 0; v < n; ++v) {
        for (int e = g.offsets[v]; e < g.offsets[v + 1]; ++e) {
            const int c = colour[g.neighbours[e]];
            if (c >= 0) stamp[c] = v;
        }
        int c = 0;
        while (c < colours && stamp[c] == v) ++c;
        if (c == colours) {
            ++colours;
            stamp.push_back(-1);
        }
        colour[v] = c;
    }
    g.colourOffsets.assign(colours + 1, 0);
    for (int v = 0; v < n; ++v) ++g.colourOffsets[colour[v] + 1];
    for (int c = 0; c < colours; ++c) g.colourOffsets[c + 1] += g.colourOffsets[c];
    g.colourVertices.resize(n);
    std::vector<int> fill(g.colourOffsets.begin(), g.colourOffsets.end() - 1);
    for (int v = 0; v < n; ++v) g.colourVertices[fill[colour[v]]++] = v;
}

// One coarsening step: greedy matching of the edges, best first. The score prefers pairs whose
// normals agree (clusters stay nearly flat, so projecting a coarse direction on the children's
// tangent planes loses little) and whose combined area is small (clusters stay balanced in
// size, so the levels resolve the surface uniformly). Returns false when it would not shrink
// the graph enough to be worth a level.
bool coarsen(const FieldGraph& fine, FieldGraph& coarse, std::vector<int>& parent)
{
    const int n = fine.vertexCount();
    struct Candidate {
        double score;
        int i, j;
    };
    std::vector<Candidate> candidates;
    candidates.reserve(fine.neighbours.size() / 2);
    for (int i = 0; i < n; ++i)
        for (int e = fine.offsets[i]; e < fine.offsets[i + 1]; ++e) {
            const int j = fine.neighbours[e];
            if (j <= i) continue;
            const double dp = std::max(fine.normals[i].dot(fine.normals[j]), 0.0) + 1e-3;
            const double area = fine.areas[i] + fine.areas[j];
            candidates.push_back({dp / (area > 0 ? area : 1.0), i, j});
        }
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& a, const Candidate& b) { return a.score > b.score; });

    std::vector<int> partner(n, -1);
    for (const Candidate& c : candidates)
        if (partner[c.i] < 0 && partner[c.j] < 0) partner[c.i] = c.j, partner[c.j] = c.i;

    // Coarse ids in order of the smallest child, which keeps neighbouring vertices close in
    // memory level after level.
    parent.assign(n, -1);
    int m = 0;
    for (int v = 0; v < n; ++v)
        if (parent[v] < 0) {
            parent[v] = m;
            if (partner[v] >= 0) parent[partner[v]] = m;
            ++m;
        }
    if (m > 0.9 * n) return false;

    coarse.positions.assign(m, Vec3::Zero());
    coarse.normals.assign(m, Vec3::Zero());
    coarse.areas.assign(m, 0.0);
    std::vector<int> firstChild(m, -1);
    for (int v = 0; v < n; ++v) {
        const int p = parent[v];
        if (firstChild[p] < 0) firstChild[p] = v;
        // Area-weighted position and normal; a zero-area vertex still counts a little.
        const double a = std::max(fine.areas[v], 1e-300);
        coarse.positions[p] += a * fine.positions[v];
        coarse.normals[p] += a * fine.normals[v];
        coarse.areas[p] += a;
    }
    for (int p = 0; p < m; ++p) {
        coarse.positions[p] /= coarse.areas[p];
        const double len = coarse.normals[p].norm();
        // Opposite normals cancel (a thin sheet): take the first child's.
        coarse.normals[p] = len > 1e-9 * coarse.areas[p] ? Vec3(coarse.normals[p] / len) : fine.normals[firstChild[p]];
    }

    std::vector<DirectedEdge> edges;
    edges.reserve(fine.neighbours.size());
    for (int v = 0; v < n; ++v)
        for (int e = fine.offsets[v]; e < fine.offsets[v + 1]; ++e) {
            const int a = parent[v], b = parent[fine.neighbours[e]];
            if (a != b) edges.push_back({a, b, fine.weights[e]});
        }
    buildAdjacency(m, edges, coarse);
    colourGraph(coarse);
    return true;
}

// The compatible running sum of averageCompatible: adds v's representative closest to `sum`.
void addCompatible(const Vec3& n, Vec3& sum, const Vec3& v)
{
    const Vec3 t = rosy::projectTangent(v, n);
    const double len = t.norm();
    if (!(len > 1e-12)) return;
    if (sum.squaredNorm() == 0) {
        sum = t / len;
        return;
    }
    Vec3 r[3];
    rosy::representatives3(t / len, n, r);
    int best = 0;
    for (int k = 1; k < 3; ++k)
        if (std::abs(r[k].dot(sum)) > std::abs(r[best].dot(sum))) best = k;
    sum += r[best].dot(sum) < 0 ? Vec3(-r[best]) : r[best];
}

bool normalisedTangent(const Vec3& v, const Vec3& n, Vec3& out)
{
    const Vec3 t = rosy::projectTangent(v, n);
    const double len = t.norm();
    if (!(len > 1e-12)) return false;
    out = t / len;
    return true;
}

}  // namespace

int FieldConstraints::count() const
{
    return static_cast<int>(std::count(fixed.begin(), fixed.end(), static_cast<unsigned char>(1)));
}

bool averageCompatible(const Vec3& n, const Vec3* vectors, int count, Vec3& out)
{
    Vec3 sum = Vec3::Zero();
    for (int i = 0; i < count; ++i) addCompatible(n, sum, vectors[i]);
    return normalisedTangent(sum, n, out);
}

FieldHierarchyLevels buildFieldHierarchy(const TriMesh& mesh, const std::vector<Vec3>& normals)
{
    FieldHierarchyLevels h;
    h.levels.emplace_back();
    FieldGraph& g = h.levels.back();
    const int n = mesh.vertexCount();
    g.positions = mesh.vertices;
    g.normals = normals;
    g.areas.assign(n, 0.0);
    std::vector<DirectedEdge> edges;
    edges.reserve(6 * mesh.faces.size());
    for (int f = 0; f < mesh.faceCount(); ++f) {
        const Face& t = mesh.faces[f];
        const double a = faceArea(mesh, f) / 3;
        for (int k = 0; k < 3; ++k) {
            g.areas[t[k]] += a;
            // Both directions; the edge shared by two faces merges into weight 2, so halve.
            edges.push_back({t[k], t[(k + 1) % 3], 0.5});
            edges.push_back({t[(k + 1) % 3], t[k], 0.5});
        }
    }
    buildAdjacency(n, edges, g);
    // Unit weights on the input mesh: its energy is exactly extrinsicEnergy (eq. 3 unweighted),
    // whether the edge is interior (two faces) or on the border (one).
    std::fill(g.weights.begin(), g.weights.end(), 1.0);
    colourGraph(g);

    // Down to a handful of vertices: there a random start cannot get stuck with singularities
    // (a coarsest level of a few dozen vertices on a flat square kept a pair of them).
    constexpr int kCoarsest = 2;
    while (h.levels.back().vertexCount() > kCoarsest && h.levels.size() < 40) {
        FieldGraph coarse;
        std::vector<int> parent;
        if (!coarsen(h.levels.back(), coarse, parent)) break;
        h.levels.push_back(std::move(coarse));
        h.parents.push_back(std::move(parent));
    }
    return h;
}

double graphEnergy(const FieldGraph& g, const std::vector<Vec3>& d, bool intrinsic)
{
    double energy = 0;
    for (int i = 0; i < g.vertexCount(); ++i)
        for (int e = g.offsets[i]; e < g.offsets[i + 1]; ++e) {
            const int j = g.neighbours[e];
            if (j <= i) continue;
            energy += g.weights[e] * (intrinsic ? rosy::edgeEnergyIntrinsic(d[i], g.normals[i], d[j], g.normals[j])
                                                : rosy::edgeEnergy(d[i], g.normals[i], d[j], g.normals[j]));
        }
    return energy;
}

void smoothLevel(const FieldGraph& g, std::vector<Vec3>& d, const std::vector<unsigned char>* fixed, int iterations,
                 std::vector<double>* energies, bool intrinsic)
{
    const int n = g.vertexCount();
    const int colours = static_cast<int>(g.colourOffsets.size()) - 1;
    // t_i = n_i × d_i completes the orthonormal frame (d_i, t_i) of each tangent plane. The
    // representatives are a_p = cos(p·60°) d + sin(p·60°) t, so all 3×3 dot products between
    // the representatives of i and j follow from the four dots between the two frames, and the
    // chosen representative of j is expressed directly in i's frame: no cross product and no
    // 3D rotation per neighbour.
    std::vector<Vec3> t(n);
    for (int i = 0; i < n; ++i) t[i] = g.normals[i].cross(d[i]);
    constexpr double s = rosy::kSin60;
    static constexpr double kC[3] = {1.0, 0.5, -0.5}, kS[3] = {0.0, s, s};

    // Threads only where a colour class holds a thousand vertices: every class ends with a
    // barrier, and on a busy machine a barrier can cost a scheduler time slice, so small
    // levels run faster on one thread (docs/tuning.md, "Threads per colour class"). One
    // parallel region for all sweeps of the level.
    const bool parallel = colours > 0 && n / colours >= 1024;
#pragma omp parallel if (parallel)
    for (int it = 0; it < iterations; ++it) {
        for (int c = 0; c < colours; ++c) {
            const int begin = g.colourOffsets[c], end = g.colourOffsets[c + 1];
            // Vertices of one colour have no edge between them: updating them in any order or
            // in parallel gives the same result as the sequential sweep.
#pragma omp for schedule(static)
            for (int k = begin; k < end; ++k) {
                const int i = g.colourVertices[k];
                if (fixed && (*fixed)[i]) continue;
                const Vec3 di = d[i], ti = t[i];
                double x = 0, y = 0;  // Σ_j w_ij R^{−p_j} b_j in the frame (d_i, t_i)
                for (int e = g.offsets[i]; e < g.offsets[i + 1]; ++e) {
                    const int j = g.neighbours[e];
                    Vec3 dj = d[j], tj = t[j];
                    if (intrinsic) {  // j's frame carried to i's plane (a rotation: still orthonormal)
                        dj = rosy::rotateIntoPlane(dj, g.normals[j], g.normals[i]);
                        tj = rosy::rotateIntoPlane(tj, g.normals[j], g.normals[i]);
                    }
                    const double m00 = di.dot(dj), m01 = di.dot(tj), m10 = ti.dot(dj), m11 = ti.dot(tj);
                    // a_p · c_q = cq·u_p + sq·v_p with (u_p, v_p) = cp·(m00, m01) + sp·(m10, m11).
                    double value[9];
                    for (int p = 0; p < 3; ++p) {
                        const double u = kC[p] * m00 + kS[p] * m10, v = kC[p] * m01 + kS[p] * m11;
                        value[3 * p] = u;
                        value[3 * p + 1] = 0.5 * u + s * v;
                        value[3 * p + 2] = -0.5 * u + s * v;
                    }
                    int bestIndex = 0;  // first maximum of |a_p · c_q|, p major (branch-free)
                    double best = std::abs(value[0]);
                    for (int k = 1; k < 9; ++k) {
                        const double a = std::abs(value[k]);
                        bestIndex = a > best ? k : bestIndex;
                        best = a > best ? a : best;
                    }
                    const int bp = bestIndex / 3, bq = bestIndex % 3;
                    const double bestValue = value[bestIndex];
                    // b = ±c_q in i's frame (its normal component drops: the projection P_i),
                    // then rotated by −p·60° about n_i: (R^p d_i)·b = d_i·(R^{−p} b).
                    const double sign = bestValue < 0 ? -1.0 : 1.0;
                    const double bx = sign * (kC[bq] * m00 + kS[bq] * m01), by = sign * (kC[bq] * m10 + kS[bq] * m11);
                    const double w = g.weights[e];
                    x += w * (kC[bp] * bx + kS[bp] * by);
                    y += w * (kC[bp] * by - kS[bp] * bx);
                }
                // The exact minimiser of i's local energy for this matching (see the header).
                const Vec3 sum = rosy::projectTangent(x * di + y * ti, g.normals[i]);
                const double len = sum.norm();
                if (len > 1e-300) {
                    d[i] = sum / len;
                    t[i] = g.normals[i].cross(d[i]);
                }
            }
        }
        if (energies) {
#pragma omp single
            energies->push_back(graphEnergy(g, d, intrinsic));  // implicit barrier after single
        }
    }
}

std::vector<Vec3> solveField(const TriMesh& mesh, const std::vector<Vec3>& normals, const FieldConstraints& constraints,
                             std::uint64_t seed, int iterations, FieldReport* report, bool intrinsic,
                             FieldHierarchyLevels* hierarchy)
{
    FieldHierarchyLevels h = buildFieldHierarchy(mesh, normals);
    const int levels = static_cast<int>(h.levels.size());
    const int n = mesh.vertexCount();

    // Constraints on every level: a coarse vertex is fixed when one of its children is, to the
    // compatible average of its fixed children's directions (Jakob et al. 2015 propagate
    // constraints up their hierarchy likewise), projected on its own tangent plane.
    std::vector<std::vector<unsigned char>> fixed(levels);
    std::vector<std::vector<Vec3>> dirs(levels);
    fixed[0] = constraints.fixed.empty() ? std::vector<unsigned char>(n, 0) : constraints.fixed;
    dirs[0].resize(n);

    // Random initial directions (uniform in the cube, projected: a seeded, platform-independent
    // mapping of the generator's bits, like sampling.h).
    std::mt19937_64 rng(seed);
    for (int v = 0; v < n; ++v) {
        Vec3 t;
        do {
            const Vec3 x(2 * unitInterval(rng()) - 1, 2 * unitInterval(rng()) - 1, 2 * unitInterval(rng()) - 1);
            t = rosy::projectTangent(x, normals[v]);
        } while (!(t.norm() > 1e-3));
        dirs[0][v] = t.normalized();
        if (fixed[0][v]) dirs[0][v] = constraints.directions[v];
    }
    for (int l = 1; l < levels; ++l) {
        const FieldGraph& coarse = h.levels[l];
        const std::vector<int>& parent = h.parents[l - 1];
        const int m = coarse.vertexCount();
        fixed[l].assign(m, 0);
        dirs[l].assign(m, Vec3::Zero());
        std::vector<Vec3> sum(m, Vec3::Zero());
        std::vector<unsigned char> initialised(m, 0);
        for (int v = 0; v < h.levels[l - 1].vertexCount(); ++v) {
            const int p = parent[v];
            if (!initialised[p]) {  // restriction of the random field: the first child's
                initialised[p] = 1;
                if (!normalisedTangent(dirs[l - 1][v], coarse.normals[p], dirs[l][p]))
                    dirs[l][p] = rosy::anyTangent(coarse.normals[p]);
            }
            if (fixed[l - 1][v]) addCompatible(coarse.normals[p], sum[p], dirs[l - 1][v]);
        }
        for (int p = 0; p < m; ++p)
            if (sum[p].squaredNorm() > 0 && normalisedTangent(sum[p], coarse.normals[p], dirs[l][p])) fixed[l][p] = 1;
    }

    std::vector<Vec3> scratch;  // the trace's prolongation to the input mesh
    auto energyOnInput = [&](int level) {
        scratch = dirs[level];
        for (int l = level; l > 0; --l) {
            std::vector<Vec3> finer = dirs[l - 1];
            for (int v = 0; v < h.levels[l - 1].vertexCount(); ++v)
                if (!fixed[l - 1][v]) normalisedTangent(scratch[h.parents[l - 1][v]], h.levels[l - 1].normals[v], finer[v]);
            scratch.swap(finer);
        }
        return graphEnergy(h.levels[0], scratch, intrinsic);
    };
    if (report) {
        report->levelVertexCounts.clear();
        for (const FieldGraph& g : h.levels) report->levelVertexCounts.push_back(g.vertexCount());
        report->levelEnergies.assign(1, graphEnergy(h.levels[0], dirs[0], intrinsic));
        report->sweepEnergies.clear();
    }

    for (int l = levels - 1; l >= 0; --l) {
        std::vector<double>* trace = nullptr;
        if (report) {
            report->sweepEnergies.emplace_back(1, graphEnergy(h.levels[l], dirs[l], intrinsic));
            trace = &report->sweepEnergies.back();
        }
        smoothLevel(h.levels[l], dirs[l], &fixed[l], iterations, trace, intrinsic);
        if (report) report->levelEnergies.push_back(energyOnInput(l));
        if (l == 0) break;
        // Prolongation: each child takes its parent's direction, re-projected on its own
        // tangent plane (Jakob et al. 2015, §5); fixed children keep theirs.
        const FieldGraph& fine = h.levels[l - 1];
        const std::vector<int>& parent = h.parents[l - 1];
#pragma omp parallel for schedule(static) if (fine.vertexCount() > 32768)
        for (int v = 0; v < fine.vertexCount(); ++v)
            if (!fixed[l - 1][v]) normalisedTangent(dirs[l][parent[v]], fine.normals[v], dirs[l - 1][v]);
    }
    if (hierarchy) *hierarchy = std::move(h);
    return dirs[0];
}

}  // namespace fieldcvt
