#include "feature_lines.h"

#include "errors.h"
#include "mesh_edges.h"
#include "point_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fieldcvt {

namespace {

// A feature line that turns by more than this at a vertex has a corner there.
constexpr double kCornerTurnDegrees = 25.0;

// Per vertex, how far (degrees) a polyline made of `edges` turns there: 0 going straight on,
// 180 where more than two of its edges meet, 0 off the polyline.
std::vector<double> turnAngles(const TriMesh& surface, const std::vector<std::array<int, 2>>& edges)
{
    std::vector<Vec3> firstDirection(surface.vertices.size(), Vec3::Zero());
    std::vector<int> count(surface.vertices.size(), 0);
    std::vector<double> turn(surface.vertices.size(), 0.0);
    for (const auto& [a, b] : edges) {
        for (const auto& [from, to] : {std::pair<int, int>{a, b}, std::pair<int, int>{b, a}}) {
            const Vec3 out = (surface.vertices[size_t(to)] - surface.vertices[size_t(from)]).normalized();
            Vec3& first = firstDirection[size_t(from)];
            if (++count[size_t(from)] == 1)
                first = out;
            else if (count[size_t(from)] > 2)
                turn[size_t(from)] = 180;
            else  // straight on is first = -out
                turn[size_t(from)] = std::acos(std::clamp(-first.dot(out), -1.0, 1.0)) * 180.0 / kPi;
        }
    }
    return turn;
}

}  // namespace

FeatureLines detectFeatures(const TriMesh& surface, double angleDegrees, const std::vector<std::array<int, 2>>& userEdges,
                            int* ignoredUserEdges, double cornerSpacing)
{
    FeatureLines lines;
    if (ignoredUserEdges) *ignoredUserEdges = 0;
    const EdgeTable table = buildEdgeTable(surface);
    std::vector<char> onBorder(surface.vertices.size(), 0);
    std::vector<std::array<int, 2>> borderEdges;
    const double cosLimit = std::cos(std::min(angleDegrees, 180.0) * kPi / 180.0);
    for (int e = 0; e < table.edgeCount(); ++e) {
        const auto [a, b] = table.ends[e];
        if (table.isBorder(e)) {
            onBorder[size_t(a)] = onBorder[size_t(b)] = 1;
            borderEdges.push_back({a, b});
        } else if (table.faceCount(e) == 2 && angleDegrees > 0) {
            // The dihedral angle here is the angle between the two face normals: 0 on a flat
            // stretch, 90° on a cube's edge.
            const Vec3 n1 = faceNormal(surface, table.face(e, 0)).normalized();
            const Vec3 n2 = faceNormal(surface, table.face(e, 1)).normalized();
            if (n1.dot(n2) <= cosLimit) lines.edges.push_back({a, b});
        }
    }
    for (const auto& edge : userEdges) {
        const int e = table.find(edge[0], edge[1]);
        if (e >= 0)
            lines.edges.push_back(table.ends[e]);
        else if (ignoredUserEdges)
            ++*ignoredUserEdges;
    }
    std::sort(lines.edges.begin(), lines.edges.end());
    lines.edges.erase(std::unique(lines.edges.begin(), lines.edges.end()), lines.edges.end());

    std::vector<int> degree(surface.vertices.size(), 0);
    for (const auto& [a, b] : lines.edges) {
        ++degree[size_t(a)], ++degree[size_t(b)];
        lines.segments.push_back({surface.vertices[size_t(a)], surface.vertices[size_t(b)]});
    }
    // A line ends (1), branches (>= 3), runs into the open border or turns sharply: those
    // points must be output vertices, so a sample sits on each: a sample free to slide past a
    // sharp turn would cut it. The open border's own sharp turns are corners too.
    // Corners closer than `cornerSpacing` to a more important one are dropped: two fixed
    // samples closer than a cell make a sliver. Line ends and branches come first, then the
    // sharper turns. (The cases behind these rules: docs/tuning.md, "Feature corners".)
    const std::vector<double> lineTurns = turnAngles(surface, lines.edges);
    const std::vector<double> borderTurns = turnAngles(surface, borderEdges);
    std::vector<std::pair<double, int>> candidates;  // (importance, vertex)
    for (int v = 0; v < surface.vertexCount(); ++v) {
        const int d = degree[size_t(v)];
        const double turn = std::max(lineTurns[size_t(v)], borderTurns[size_t(v)]);
        if (d == 1 || d >= 3 || (d > 0 && onBorder[size_t(v)]))
            candidates.push_back({1000.0, v});
        else if (turn > kCornerTurnDegrees)
            candidates.push_back({turn, v});
    }
    std::stable_sort(candidates.begin(), candidates.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    const double spacing2 = cornerSpacing * cornerSpacing;
    for (const auto& candidate : candidates) {
        const int v = candidate.second;
        bool isolated = true;
        for (int kept : lines.corners)
            if ((surface.vertices[size_t(kept)] - surface.vertices[size_t(v)]).squaredNorm() < spacing2) {
                isolated = false;
                break;
            }
        if (isolated) lines.corners.push_back(v);
    }
    std::sort(lines.corners.begin(), lines.corners.end());
    return lines;
}

std::vector<CurvePiece> restrictCurvesToCells(const std::vector<Vec3>& seeds, const FeatureLines& lines, double spacing)
{
    std::vector<CurvePiece> pieces;
    if (seeds.empty() || lines.segments.empty()) return pieces;
    if (!(spacing > 0)) throw InvalidInputError("curve sampling spacing must be > 0");
    PointCloud cloud{&seeds};
    PointTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    tree.buildIndex();

    // Per (seed, segment): the length and moment of the segment's part nearest to the seed.
    struct Part {
        int seed, segment;
        double length;
        Vec3 moment;
        bool atStart, atEnd;  // holds the segment's first / last sample point
    };
    std::vector<Part> parts;
    for (size_t s = 0; s < lines.segments.size(); ++s) {
        const Vec3& a = lines.segments[s].first;
        const Vec3& b = lines.segments[s].second;
        const double length = (b - a).norm();
        if (!(length > 0)) continue;
        // Midpoint rule on n equal pieces: each piece's length goes to the seed nearest its
        // midpoint (the seeds' 1D restricted Voronoi cells, up to one piece at each cell end).
        const int n = std::max(1, static_cast<int>(std::ceil(length / spacing)));
        const double step = length / n;
        const size_t first = parts.size();
        for (int k = 0; k < n; ++k) {
            const Vec3 p = a + (k + 0.5) / n * (b - a);
            uint32_t nearest = 0;
            double d2 = 0;
            if (tree.knnSearch(p.data(), 1, &nearest, &d2) == 0) continue;  // no seeds
            Part* part = nullptr;
            for (size_t q = first; q < parts.size(); ++q)
                if (parts[q].seed == int(nearest)) part = &parts[q];
            if (!part) {
                parts.push_back({int(nearest), int(s), 0.0, Vec3::Zero(), false, false});
                part = &parts.back();
            }
            part->atStart |= k == 0;
            part->atEnd |= k == n - 1;
            part->length += step;
            part->moment += step * p;
        }
    }
    std::sort(parts.begin(), parts.end(),
              [](const Part& x, const Part& y) { return x.seed != y.seed ? x.seed < y.seed : x.segment < y.segment; });

    // The parts of one seed form one piece where they meet: both reach the end vertex their
    // segments share. (Sharing the vertex is not enough: near a corner the corner's sample owns
    // the vertex and two lines leaving it are separate pieces of the next cells.)
    std::vector<int> parent;
    auto find = [&](int x) {
        while (parent[size_t(x)] != x) x = parent[size_t(x)] = parent[size_t(parent[size_t(x)])];
        return x;
    };
    for (size_t r = 0; r < parts.size();) {
        size_t e = r;
        while (e < parts.size() && parts[e].seed == parts[r].seed) ++e;
        const int count = int(e - r);
        parent.resize(size_t(count));
        for (int i = 0; i < count; ++i) parent[size_t(i)] = i;
        for (int i = 0; i < count; ++i)
            for (int j = i + 1; j < count; ++j) {
                const Part& pi = parts[r + size_t(i)];
                const Part& pj = parts[r + size_t(j)];
                const auto& ei = lines.edges[size_t(pi.segment)];
                const auto& ej = lines.edges[size_t(pj.segment)];
                const bool meet = (pi.atStart && pj.atStart && ei[0] == ej[0]) || (pi.atStart && pj.atEnd && ei[0] == ej[1]) ||
                                  (pi.atEnd && pj.atStart && ei[1] == ej[0]) || (pi.atEnd && pj.atEnd && ei[1] == ej[1]);
                if (meet) parent[size_t(find(i))] = find(j);
            }
        const size_t firstPiece = pieces.size();
        std::vector<int> pieceOfRoot(size_t(count), -1);
        for (int i = 0; i < count; ++i) {
            const int root = find(i);
            if (pieceOfRoot[size_t(root)] < 0) {
                pieceOfRoot[size_t(root)] = int(pieces.size() - firstPiece);
                pieces.push_back(CurvePiece{parts[r].seed, 0.0, Vec3::Zero(), {}});
            }
            CurvePiece& piece = pieces[firstPiece + size_t(pieceOfRoot[size_t(root)])];
            piece.length += parts[r + size_t(i)].length;
            piece.moment += parts[r + size_t(i)].moment;
            piece.segments.push_back(parts[r + size_t(i)].segment);
        }
        std::stable_sort(pieces.begin() + long(firstPiece), pieces.end(),
                         [](const CurvePiece& x, const CurvePiece& y) { return x.length > y.length; });
        r = e;
    }
    return pieces;
}

namespace {

// The piece's centroid, put back on the piece's own segments.
Vec3 projectOnPiece(const CurvePiece& piece, const std::vector<Segment>& segments)
{
    const Vec3 centroid = piece.moment / piece.length;
    Vec3 best = centroid;
    double bestDist2 = std::numeric_limits<double>::infinity();
    for (int s : piece.segments) {
        double d2 = 0;
        const Vec3 q = closestPointOnSegment(centroid, segments[size_t(s)], &d2);
        if (d2 < bestDist2) bestDist2 = d2, best = q;
    }
    return best;
}

}  // namespace

std::vector<SampleConstraint> relaxConstrainedSamples(EnergyFunction& energy, std::vector<Vec3>& seeds, const TriMesh& surface,
                                                      const std::vector<Segment>& border, const FeatureLines& features,
                                                      int iterations, bool iterationsFollow)
{
    std::vector<SampleConstraint> role(seeds.size(), SampleConstraint::Free);
    if (border.empty() && features.empty()) return role;
    // At the working scale the mean cell has area 1 (edge length ~1.07): 16 points per unit
    // length put each 1D cell's ends within 1/32 of their exact place.
    const double spacing = 1.0 / 16;
    // A second piece of line in one cell (two lines closer than a cell) gets a sample of its
    // own when it is at least this long; shorter ones are within a third of an edge anyway.
    const double ownSampleLength = 0.3;
    RvdOptions options;
    options.boundary = !border.empty();
    // Without feature lines the free samples stay where the CVT iterations left them (the FCVT
    // iterations move them next), and only the faces along the border are clipped, which is
    // all the border's 1D cells need: 10 RVDs of the border faces instead of the whole surface,
    // faster for the same figures (docs/tuning.md, "Border stage: free samples"). With feature
    // lines they still move to their centroids, filling in behind the samples pulled onto the lines.
    // When nothing follows (no FCVT iterations: a pure CVT run), the free samples move here as
    // before, or the ones next to the border would keep the gaps the border samples left.
    const bool moveFree = !features.segments.empty() || !iterationsFollow;
    options.borderFacesOnly = !moveFree;
    constexpr size_t kCandidates = 16;
    for (int it = 0; it < iterations; ++it) {
        const RvdResult& rvd = energy.diagram(seeds, options);
        const std::vector<CurvePiece> pieces = restrictCurvesToCells(seeds, features, spacing);
        std::vector<int> firstPiece(seeds.size(), -1);
        for (size_t p = pieces.size(); p-- > 0;) firstPiece[size_t(pieces[p].seed)] = int(p);
        std::vector<Vec3> next(seeds.size());
#pragma omp parallel for schedule(static)
        for (long long i = 0; i < static_cast<long long>(seeds.size()); ++i) {
            role[size_t(i)] = SampleConstraint::Free;
            next[size_t(i)] = seeds[size_t(i)];
            if (options.boundary && rvd.boundaryLength[size_t(i)] > 0) {
                role[size_t(i)] = SampleConstraint::Border;
                next[size_t(i)] = closestPointOnSegments(rvd.boundaryMoment[size_t(i)] / rvd.boundaryLength[size_t(i)], border);
            } else if (firstPiece[size_t(i)] >= 0) {
                role[size_t(i)] = SampleConstraint::Feature;
                next[size_t(i)] = projectOnPiece(pieces[size_t(firstPiece[size_t(i)])], features.segments);
            } else if (moveFree && rvd.mass[size_t(i)] > 0) {
                next[size_t(i)] = rvd.moment[size_t(i)] / rvd.mass[size_t(i)];
            }
        }
        if (features.empty()) {
            seeds.swap(next);
            continue;
        }
        const std::vector<Vec3> positions = next;  // the tree reads these; `next` changes below
        PointCloud cloud{&positions};
        PointTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
        tree.buildIndex();
        uint32_t index[kCandidates];
        double d2[kCandidates];
        std::vector<char> taken(seeds.size(), 0);
        // Further pieces of line in a cell: the nearest free sample moves onto each (in seed
        // order, so the result is deterministic).
        for (size_t p = 0; p < pieces.size(); ++p) {
            if (int(p) == firstPiece[size_t(pieces[p].seed)] || pieces[p].length < ownSampleLength) continue;
            const Vec3 target = projectOnPiece(pieces[p], features.segments);
            const size_t found = tree.knnSearch(target.data(), std::min(kCandidates, seeds.size()), index, d2);
            for (size_t k = 0; k < found; ++k)
                if (role[index[k]] == SampleConstraint::Free && !taken[index[k]]) {
                    taken[index[k]] = 1;
                    next[index[k]] = target;
                    role[index[k]] = SampleConstraint::Feature;
                    break;
                }
        }
        // Corners: the nearest sample not already holding a corner sits on it (in corner order).
        std::fill(taken.begin(), taken.end(), 0);
        std::vector<Vec3> corner(seeds.size());
        for (int c : features.corners) {
            const Vec3& p = surface.vertices[size_t(c)];
            const size_t found = tree.knnSearch(p.data(), std::min(kCandidates, seeds.size()), index, d2);
            for (size_t k = 0; k < found; ++k)
                if (!taken[index[k]]) {
                    taken[index[k]] = 1;
                    corner[index[k]] = p;
                    break;
                }
        }
        for (size_t i = 0; i < seeds.size(); ++i)
            if (taken[i]) next[i] = corner[i], role[i] = SampleConstraint::Corner;
        seeds.swap(next);
    }
    return role;
}

double featureDeviation(const FeatureLines& features, const TriMesh& mesh, double angleDegrees, double spacing)
{
    if (features.segments.empty()) return 0;
    // The output edges that count: sharp ones (or all).
    std::vector<Segment> edges;
    const EdgeTable table = buildEdgeTable(mesh);
    const double cosLimit = angleDegrees > 0 ? std::cos(std::min(angleDegrees, 180.0) * kPi / 180.0) : 2.0;
    for (int e = 0; e < table.edgeCount(); ++e) {
        bool keep = angleDegrees <= 0 || table.faceCount(e) != 2;  // border / non-manifold edges count as sharp
        if (!keep) {
            const Vec3 n1 = faceNormal(mesh, table.face(e, 0)).normalized();
            const Vec3 n2 = faceNormal(mesh, table.face(e, 1)).normalized();
            keep = n1.dot(n2) <= cosLimit;
        }
        if (keep) edges.push_back({mesh.vertices[size_t(table.ends[e][0])], mesh.vertices[size_t(table.ends[e][1])]});
    }
    if (edges.empty()) return std::numeric_limits<double>::infinity();
    // Brute force over edge midpoints through a kd-tree, then exact distance to the few nearest.
    std::vector<Vec3> mids(edges.size());
    double longest = 0;
    for (size_t i = 0; i < edges.size(); ++i) {
        mids[i] = 0.5 * (edges[i].first + edges[i].second);
        longest = std::max(longest, (edges[i].second - edges[i].first).norm());
    }
    PointCloud cloud{&mids};
    PointTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    tree.buildIndex();
    double worst = 0;
    std::vector<uint32_t> index;
    std::vector<double> d2;
    for (const Segment& s : features.segments) {
        const double length = (s.second - s.first).norm();
        const int n = std::max(1, static_cast<int>(std::ceil(length / spacing)));
        for (int k = 0; k <= n; ++k) {
            const Vec3 p = s.first + double(k) / n * (s.second - s.first);
            // Any edge within reach has its midpoint within (best distance + half the longest
            // edge): the nearest midpoints, more of them until the farthest one is beyond that
            // (one long edge makes the reach long; all edges was the old fallback).
            double best = std::numeric_limits<double>::infinity();
            for (size_t want = 8;; want *= 4) {
                want = std::min(want, mids.size());
                index.resize(want);
                d2.resize(want);
                const size_t found = tree.knnSearch(p.data(), want, index.data(), d2.data());
                for (size_t j = 0; j < found; ++j) {
                    double dist2 = 0;
                    closestPointOnSegment(p, edges[index[j]], &dist2);
                    best = std::min(best, dist2);
                }
                if (found < want || want == mids.size() || std::sqrt(d2[found - 1]) >= std::sqrt(best) + 0.5 * longest) break;
            }
            worst = std::max(worst, std::sqrt(best));
        }
    }
    return worst;
}

}  // namespace fieldcvt
