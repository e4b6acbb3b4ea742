#include "feature_strips.h"

#include "boundary.h"
#include "disjoint_sets.h"
#include "point_tree.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace fieldcvt {

namespace {

//! The feature edges at each vertex, as sorted (vertex, edge) pairs: the lines as a graph.
class FeatureGraph {
public:
    explicit FeatureGraph(const std::vector<std::array<int, 2>>& edges)
    {
        for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
            incidence_.push_back({edges[e][0], e});
            incidence_.push_back({edges[e][1], e});
        }
        std::sort(incidence_.begin(), incidence_.end());
    }
    template <class Visit>
    void forEdgesAt(int vertex, Visit visit) const
    {
        auto it = std::lower_bound(incidence_.begin(), incidence_.end(), std::pair<int, int>{vertex, -1});
        for (; it != incidence_.end() && it->first == vertex; ++it) visit(it->second);
    }

private:
    std::vector<std::pair<int, int>> incidence_;
};

using Entry = std::pair<double, int>;  // (distance along the lines, vertex)

//! The bounded Dijkstra's queue and settled vertices, kept from call to call (no allocation per
//! pair of edges tested).
struct AlongLinesScratch {
    std::vector<Entry> heap, settled;  // few vertices: a sorted search is not needed
};

//! Whether point q of feature edge `to` is within `limit` of point p of feature edge `from`
//! along the lines (a bounded Dijkstra over the feature graph): then the two are one line
//! bending, not two lines beside each other.

bool reachableAlongLines(const TriMesh& surface, const std::vector<std::array<int, 2>>& edges, const FeatureGraph& graph,
                         int from, const Vec3& p, int to, const Vec3& q, double limit, AlongLinesScratch& scratch)
{
    std::vector<Entry>& heap = scratch.heap;  // a min-heap on the distance (std::greater)
    std::vector<Entry>& settled = scratch.settled;
    heap.clear();
    settled.clear();
    auto at = [&](int v) -> const Vec3& { return surface.vertices[size_t(v)]; };
    auto push = [&](double distance, int v) {
        heap.push_back({distance, v});
        std::push_heap(heap.begin(), heap.end(), std::greater<>());
    };
    for (int end : edges[from]) push((at(end) - p).norm(), end);
    while (!heap.empty()) {
        std::pop_heap(heap.begin(), heap.end(), std::greater<>());
        const double distance = heap.back().first;
        const int v = heap.back().second;
        heap.pop_back();
        if (distance > limit) break;
        if (std::any_of(settled.begin(), settled.end(), [v](const Entry& s) { return s.second == v; })) continue;
        settled.push_back({distance, v});
        if ((v == edges[to][0] || v == edges[to][1]) && distance + (q - at(v)).norm() <= limit) return true;
        graph.forEdgesAt(v, [&](int e) {
            const int next = edges[e][0] == v ? edges[e][1] : edges[e][0];
            push(distance + (at(next) - at(v)).norm(), next);
        });
    }
    return false;
}

//! Per feature edge, whether it lies within `reach` along the lines of a wedge's apex: a vertex
//! where a line turns back, its two feature edges leaving between wedgeDegrees and
//! acos(parallelCos) of each other (a branch is no apex: CAD exports' slivers make many). Near
//! the apex the two lines run closer than any width, but the apex is a corner the user wants,
//! and the 1D CVT along both lines meshes it well (fandisk's 22° wedge). Two edges that leave
//! closer than that are a polyline folding back on itself (a CAD export's slivers), no wedge.
std::vector<char> edgesNearWedges(const TriMesh& surface, const std::vector<std::array<int, 2>>& edges, const FeatureGraph& graph,
                                  const NarrowStripParams& params, double reach)
{
    auto at = [&](int v) -> const Vec3& { return surface.vertices[size_t(v)]; };
    std::vector<int> ends;  // every feature vertex once, sorted
    for (const auto& edge : edges) ends.insert(ends.end(), edge.begin(), edge.end());
    std::sort(ends.begin(), ends.end());
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    const double foldCos = std::cos(params.wedgeDegrees * kPi / 180);
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;  // from an apex
    std::vector<Vec3> leaving;
    for (int v : ends) {
        leaving.clear();
        graph.forEdgesAt(
            v, [&](int e) { leaving.push_back((at(edges[e][0] == v ? edges[e][1] : edges[e][0]) - at(v)).normalized()); });
        bool apex = false;
        for (size_t i = 0; i < leaving.size() && !apex; ++i)
            for (size_t j = i + 1; j < leaving.size() && !apex; ++j) {
                const double c = leaving[i].dot(leaving[j]);
                apex = c > params.parallelCos && c <= foldCos;
            }
        if (apex && leaving.size() == 2) queue.push({0.0, v});
    }
    std::vector<double> distance(ends.size(), std::numeric_limits<double>::infinity());
    auto slot = [&](int v) { return static_cast<size_t>(std::lower_bound(ends.begin(), ends.end(), v) - ends.begin()); };
    while (!queue.empty()) {
        const double d = queue.top().first;
        const int v = queue.top().second;
        queue.pop();
        double& best = distance[slot(v)];
        if (d >= best || d > reach) continue;
        best = d;
        graph.forEdgesAt(v, [&](int e) {
            const int next = edges[e][0] == v ? edges[e][1] : edges[e][0];
            queue.push({d + (at(next) - at(v)).norm(), next});
        });
    }
    std::vector<char> near(edges.size(), 0);
    for (size_t e = 0; e < edges.size(); ++e)
        near[e] = distance[slot(edges[e][0])] <= reach || distance[slot(edges[e][1])] <= reach;
    return near;
}

//! Leaves out the connected pieces of out.kept shorter than `shortest` in all: a slot's rounded
//! ends once its sides went, a scan's noise. Both ends of such a piece would be corners (fixed
//! samples) closer than an edge.
void dropFragments(const TriMesh& surface, double shortest, NarrowStrips& out)
{
    if (!(shortest > 0) || out.kept.empty()) return;
    DisjointSets pieces(surface.vertexCount());
    for (const auto& [a, b] : out.kept) pieces.unite(a, b);
    std::vector<double> length(surface.vertices.size(), 0.0);  // per piece, at its root
    for (const auto& [a, b] : out.kept)
        length[size_t(pieces.find(a))] += (surface.vertices[size_t(a)] - surface.vertices[size_t(b)]).norm();
    std::vector<std::array<int, 2>> kept;
    for (const auto& edge : out.kept) {
        if (length[size_t(pieces.find(edge[0]))] < shortest)
            ++out.dropped;
        else
            kept.push_back(edge);
    }
    out.kept = std::move(kept);
}

}  // namespace

NarrowStrips findNarrowStrips(const TriMesh& surface, const FeatureLines& lines, double edgeLength,
                              const NarrowStripParams& params)
{
    NarrowStrips out;
    const double width = params.widthShare * edgeLength;
    if (lines.edges.empty() || !(width > 0)) {
        out.kept = lines.edges;
        return out;
    }
    // The feature edges first, then the open border's: a line beside the border makes a strip
    // too (samples sit on both), but only feature edges can be left out.
    const int featureCount = static_cast<int>(lines.edges.size());
    std::vector<std::array<int, 2>> edges = lines.edges;
    for (const auto& [a, b] : borderHalfEdges(surface.faces)) edges.push_back({a, b});
    auto segmentOf = [&](int e) { return Segment{surface.vertices[size_t(edges[e][0])], surface.vertices[size_t(edges[e][1])]}; };

    // Points along every edge, an eighth of the width apart at most.
    std::vector<Vec3> samples;
    std::vector<int> ofSample, firstSample(edges.size() + 1, 0);
    for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
        const Segment s = segmentOf(e);
        const int pieces = std::max(1, static_cast<int>(std::min(1e5, std::ceil((s.second - s.first).norm() / (0.125 * width)))));
        for (int i = 0; i < pieces; ++i) {
            samples.push_back(s.first + (i + 0.5) / pieces * (s.second - s.first));
            ofSample.push_back(e);
        }
        firstSample[e + 1] = static_cast<int>(samples.size());
    }
    PointCloud cloud{&samples};
    PointTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    tree.buildIndex();
    const FeatureGraph graph(edges);

    // An edge is narrow where one of its points has another line beside it within the width:
    // parallel, straight across, not reached along the lines by a short way round.
    AlongLinesScratch scratch;
    auto narrowAt = [&](int own, const Vec3& p, std::vector<std::pair<double, uint32_t>>& found, std::vector<int>& seen) {
        found.clear();
        WithinRadius within(width * width, found);
        tree.findNeighbors(within, p.data(), KnnSearchParams());
        seen.clear();
        for (const auto& hit : found) seen.push_back(ofSample[hit.second]);
        std::sort(seen.begin(), seen.end());
        seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
        const Segment mine = segmentOf(own);
        const Vec3 direction = (mine.second - mine.first).normalized();
        for (int other : seen) {
            if (other == own) continue;
            const Segment theirs = segmentOf(other);
            const Vec3 otherDirection = (theirs.second - theirs.first).normalized();
            if (std::abs(otherDirection.dot(direction)) < params.parallelCos) continue;
            const Vec3 q = closestPointOnSegment(p, theirs);
            const double distance = (q - p).norm();
            if (!(distance > 0) || distance >= width) continue;
            if (std::abs((q - p).dot(direction)) > params.acrossCos * distance) continue;
            if (reachableAlongLines(surface, edges, graph, own, p, other, q, params.alongShare * distance, scratch)) continue;
            return true;
        }
        return false;
    };
    const std::vector<char> nearWedge =
        edgesNearWedges(surface, lines.edges, FeatureGraph(lines.edges), params, params.wedgeReach * width);
    std::vector<std::pair<double, uint32_t>> found;
    std::vector<int> seen;
    for (int e = 0; e < featureCount; ++e) {
        bool narrow = false;
        if (nearWedge[size_t(e)]) {
            out.kept.push_back(edges[e]);
            continue;
        }
        for (int s = firstSample[e]; s < firstSample[e + 1] && !narrow; ++s)
            narrow = narrowAt(e, samples[size_t(s)], found, seen);
        if (narrow)
            ++out.dropped;
        else
            out.kept.push_back(edges[e]);
    }
    dropFragments(surface, params.fragmentShare * edgeLength, out);
    return out;
}

}  // namespace fieldcvt
