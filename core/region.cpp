// Region extraction, its graded density and the stitching of the remeshed regions (region.h).
#include "region.h"

#include "disjoint_sets.h"
#include "errors.h"
#include "mesh_edges.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <queue>

namespace fieldcvt {

void checkRegionParams(const RegionParams& p)
{
    auto fail = [](const char* name, const char* range, double got) {
        char text[160];
        std::snprintf(text, sizeof text, "region %s must be %s, got %g", name, range, got);
        throw InvalidInputError(text);
    };
    if (!(p.grading > 0) || !std::isfinite(p.grading)) fail("grading", "a finite number > 0", p.grading);
    if (!(p.uniformWithin >= 1) || !std::isfinite(p.uniformWithin))
        fail("uniform factor", "a finite number >= 1", p.uniformWithin);
    if (!(p.warnRatio >= 1) || !std::isfinite(p.warnRatio)) fail("warning ratio", "a finite number >= 1", p.warnRatio);
}

std::vector<std::vector<int>> regionComponents(const TriMesh& mesh, const std::vector<char>& selected)
{
    const int n = mesh.faceCount();
    DisjointSets sets(n);
    std::map<std::pair<int, int>, int> firstFace;  // undirected edge -> a selected face with it
    for (int f = 0; f < n; ++f) {
        if (!selected[size_t(f)]) continue;
        const Face& t = mesh.faces[size_t(f)];
        for (int k = 0; k < 3; ++k) {
            const auto edge = std::minmax(t[k], t[(k + 1) % 3]);
            const auto [it, added] = firstFace.insert({edge, f});
            if (!added) sets.unite(f, it->second);
        }
    }
    std::map<int, std::vector<int>> pieces;  // by root: the smallest face of each piece
    for (int f = 0; f < n; ++f)
        if (selected[size_t(f)]) pieces[sets.find(f)].push_back(f);
    std::vector<std::vector<int>> out;
    for (auto& [root, faces] : pieces) out.push_back(std::move(faces));
    return out;
}

int closePinches(const TriMesh& mesh, std::vector<char>& selected)
{
    int added = 0;
    for (int round = 0; round < 100; ++round) {
        std::vector<int> pieceOf(mesh.faces.size(), -1);
        const std::vector<std::vector<int>> pieces = regionComponents(mesh, selected);
        for (size_t p = 0; p < pieces.size(); ++p)
            for (int f : pieces[p]) pieceOf[size_t(f)] = int(p);
        // Border edges of each piece at each vertex: more than two is a pinch.
        std::map<std::pair<int, int>, int> faceCount;
        for (int f = 0; f < mesh.faceCount(); ++f)
            if (selected[size_t(f)])
                for (int k = 0; k < 3; ++k)
                    ++faceCount[std::minmax(mesh.faces[size_t(f)][k], mesh.faces[size_t(f)][(k + 1) % 3])];
        std::map<std::pair<int, int>, int> borderEdges;  // (piece, vertex) -> count
        for (int f = 0; f < mesh.faceCount(); ++f)
            if (selected[size_t(f)])
                for (int k = 0; k < 3; ++k) {
                    const int a = mesh.faces[size_t(f)][k], b = mesh.faces[size_t(f)][(k + 1) % 3];
                    if (faceCount[std::minmax(a, b)] != 1) continue;
                    ++borderEdges[{pieceOf[size_t(f)], a}];
                    ++borderEdges[{pieceOf[size_t(f)], b}];
                }
        std::vector<char> pinch(mesh.vertices.size(), 0);
        bool any = false;
        for (const auto& [key, count] : borderEdges)
            if (count > 2) pinch[size_t(key.second)] = 1, any = true;
        if (!any) break;
        for (int f = 0; f < mesh.faceCount(); ++f) {
            const Face& t = mesh.faces[size_t(f)];
            if (!selected[size_t(f)] && (pinch[size_t(t[0])] || pinch[size_t(t[1])] || pinch[size_t(t[2])]))
                selected[size_t(f)] = 1, ++added;
        }
    }
    return added;
}

int takeInNonManifoldEdges(const TriMesh& mesh, std::vector<char>& selected)
{
    const EdgeTable edges = buildEdgeTable(mesh, RepeatedVertexFaces::Skip);
    int added = 0;
    for (int e = 0; e < edges.edgeCount(); ++e) {
        if (!edges.isNonManifold(e)) continue;
        bool any = false;
        for (int i = 0; i < edges.faceCount(e); ++i) any = any || selected[size_t(edges.face(e, i))];
        if (!any) continue;
        for (int i = 0; i < edges.faceCount(e); ++i) {
            char& s = selected[size_t(edges.face(e, i))];
            if (!s) s = 1, ++added;
        }
    }
    return added;
}

RegionSubmesh extractRegion(const TriMesh& mesh, const std::vector<int>& faces)
{
    RegionSubmesh region;
    std::map<int, int> local;
    for (int f : faces) {
        Face t = mesh.faces[size_t(f)];
        for (int& v : t) {
            const auto [it, added] = local.insert({v, region.mesh.vertexCount()});
            if (added) {
                region.mesh.vertices.push_back(mesh.vertices[size_t(v)]);
                region.originalVertex.push_back(v);
                region.sourceVertex.push_back(v);
            }
            v = it->second;
        }
        region.mesh.faces.push_back(t);
        region.originalFace.push_back(f);
    }
    region.border.assign(region.mesh.vertices.size(), 0);
    std::map<std::pair<int, int>, int> uses;
    for (const Face& t : region.mesh.faces)
        for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
    for (const auto& [edge, count] : uses)
        if (count == 1) region.border[size_t(edge.first)] = region.border[size_t(edge.second)] = 1;
    return region;
}

namespace {

//! Shortest paths over the region's edges from `start` (infinity: not a source), each edge
//! costing grading times its length: the value reached at every vertex.
std::vector<double> gradedDistance(const TriMesh& mesh, std::vector<double> value, double grading)
{
    std::vector<std::vector<int>> neighbours(mesh.vertices.size());
    for (const Face& t : mesh.faces)
        for (int k = 0; k < 3; ++k) {
            neighbours[size_t(t[k])].push_back(t[(k + 1) % 3]);
            neighbours[size_t(t[(k + 1) % 3])].push_back(t[k]);
        }
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    for (size_t v = 0; v < value.size(); ++v)
        if (std::isfinite(value[v])) queue.push({value[v], int(v)});
    while (!queue.empty()) {
        const auto [d, v] = queue.top();
        queue.pop();
        if (d > value[size_t(v)]) continue;
        for (int w : neighbours[size_t(v)]) {
            const double reached = d + grading * (mesh.vertices[size_t(w)] - mesh.vertices[size_t(v)]).norm();
            if (reached < value[size_t(w)]) value[size_t(w)] = reached, queue.push({reached, w});
        }
    }
    return value;
}

}  // namespace

std::vector<double> regionDensity(const RegionSubmesh& region, double target, const RegionParams& params, double* borderRatio)
{
    const TriMesh& mesh = region.mesh;
    const double inf = std::numeric_limits<double>::infinity();
    // Per border vertex, the mean length of its border edges.
    std::vector<double> sum(mesh.vertices.size(), 0.0), count(mesh.vertices.size(), 0.0);
    double ratio = 1;
    for (const std::vector<int>& loop : borderLoops(mesh))
        for (size_t i = 0; i < loop.size(); ++i) {
            const int a = loop[i], b = loop[(i + 1) % loop.size()];
            const double length = (mesh.vertices[size_t(a)] - mesh.vertices[size_t(b)]).norm();
            if (length > 0) ratio = std::max({ratio, length / target, target / length});
            sum[size_t(a)] += length, count[size_t(a)] += 1;
            sum[size_t(b)] += length, count[size_t(b)] += 1;
        }
    if (borderRatio) *borderRatio = ratio;
    if (ratio <= params.uniformWithin) return {};
    // Shorter border edges: the length grows by grading per unit of distance up to the target;
    // longer ones: it shrinks down to it (values negated for the same shortest-path search).
    std::vector<double> shorter(mesh.vertices.size(), inf), longer(mesh.vertices.size(), inf);
    for (size_t v = 0; v < mesh.vertices.size(); ++v)
        if (count[v] > 0 && sum[v] > 0) {
            const double length = sum[v] / count[v];
            shorter[v] = length;
            longer[v] = -length;
        }
    shorter = gradedDistance(mesh, std::move(shorter), params.grading);
    longer = gradedDistance(mesh, std::move(longer), params.grading);
    std::vector<double> mu(mesh.vertices.size());
    for (size_t v = 0; v < mu.size(); ++v) {
        const double length = std::min(shorter[v], std::max(target, -longer[v]));
        mu[v] = 1 / (length * length);
    }
    return mu;
}

StitchedMesh stitchRegions(const TriMesh& input, const std::vector<char>& selected, const std::vector<RegionPatch>& patches)
{
    // A vertex goes when a selected face uses it and neither a kept face nor a patch does.
    std::vector<char> keep(input.vertices.size(), 1);
    for (int f = 0; f < input.faceCount(); ++f)
        if (selected[size_t(f)])
            for (int v : input.faces[size_t(f)]) keep[size_t(v)] = 0;
    for (int f = 0; f < input.faceCount(); ++f)
        if (!selected[size_t(f)])
            for (int v : input.faces[size_t(f)]) keep[size_t(v)] = 1;
    const int n = input.vertexCount();
    for (const RegionPatch& patch : patches)
        for (int v : patch.original)
            if (v >= 0 && v < n) keep[size_t(v)] = 1;
    StitchedMesh out;
    std::vector<int> index(input.vertices.size(), -1);
    for (size_t v = 0; v < input.vertices.size(); ++v)
        if (keep[v]) {
            index[v] = out.mesh.vertexCount();
            out.mesh.vertices.push_back(input.vertices[v]);
            out.vertexOrigin.push_back(int(v));
        }
    for (int f = 0; f < input.faceCount(); ++f)
        if (!selected[size_t(f)]) {
            Face t = input.faces[size_t(f)];
            for (int& v : t) v = index[size_t(v)];
            out.mesh.faces.push_back(t);
            out.faceOrigin.push_back(f);
        }
    std::map<int, int> copies;  // a repair's copy id -> its output vertex
    for (const RegionPatch& patch : patches) {
        std::vector<int> local(patch.mesh.vertices.size());
        for (size_t v = 0; v < local.size(); ++v) {
            const int original = patch.original[v];
            if (original >= 0 && original < n) {
                local[v] = index[size_t(original)];
                continue;
            }
            if (original >= n) {
                const auto [it, added] = copies.insert({original, out.mesh.vertexCount()});
                local[v] = it->second;
                if (!added) continue;
            } else {
                local[v] = out.mesh.vertexCount();
            }
            out.mesh.vertices.push_back(patch.mesh.vertices[v]);
            out.vertexOrigin.push_back(-1);
        }
        for (Face t : patch.mesh.faces) {
            for (int& v : t) v = local[size_t(v)];
            out.mesh.faces.push_back(t);
            out.faceOrigin.push_back(-1);
        }
    }
    return out;
}

}  // namespace fieldcvt
