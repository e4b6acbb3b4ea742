// A region that is not a manifold, oriented surface, repaired as remesh() repairs a whole mesh, and
// the check of what remeshRegion returns (region.h).
#include "disjoint_sets.h"
#include "errors.h"
#include "mesh_check.h"
#include "mesh_edges.h"
#include "region.h"

#include <algorithm>
#include <map>

namespace fieldcvt {

namespace {

std::uint64_t edgeKey(int a, int b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); }

//! Per vertex, the fans its faces form: corners joined across the edges they share (a
//! non-manifold edge joins all its faces). More than one: a non-manifold vertex.
std::vector<int> vertexFans(const TriMesh& mesh)
{
    const EdgeTable edges = buildEdgeTable(mesh, RepeatedVertexFaces::Skip);
    const int faceCount = mesh.faceCount();
    DisjointSets corners(3 * faceCount);
    const auto cornerAt = [&](int f, int v) {
        const Face& t = mesh.faces[size_t(f)];
        return 3 * f + (t[0] == v ? 0 : t[1] == v ? 1 : 2);
    };
    for (int e = 0; e < edges.edgeCount(); ++e)
        for (int i = 1; i < edges.faceCount(e); ++i)
            for (int end : edges.ends[size_t(e)]) corners.unite(cornerAt(edges.face(e, 0), end), cornerAt(edges.face(e, i), end));
    std::vector<int> fans(mesh.vertices.size(), 0);
    std::vector<char> counted(3 * size_t(faceCount), 0);
    for (int c = 0; c < 3 * faceCount; ++c) {
        if (edges.halfEdgeEdge[size_t(c)] < 0) continue;  // a face with a repeated corner
        const int root = corners.find(c);
        if (!counted[size_t(root)]) counted[size_t(root)] = 1, ++fans[size_t(mesh.faces[size_t(c / 3)][size_t(c % 3)])];
    }
    return fans;
}

std::string plural(int count, const char* one, const char* many)
{
    return std::to_string(count) + " " + (count == 1 ? one : many);
}

}  // namespace

bool KeptEdges::runs(int a, int b) const { return a >= 0 && b >= 0 && directed.count(edgeKey(a, b)) > 0; }

KeptEdges keptEdges(const TriMesh& mesh, const std::vector<char>& selected)
{
    // Only the edges between vertices of selected faces can meet a region: a band along the
    // seam, not a table of the whole mesh.
    std::vector<char> inRegion(mesh.vertices.size(), 0);
    for (size_t f = 0; f < mesh.faces.size(); ++f)
        if (selected[f])
            for (int v : mesh.faces[f]) inRegion[size_t(v)] = 1;
    KeptEdges kept;
    for (size_t f = 0; f < mesh.faces.size(); ++f)
        if (!selected[f])
            for (int k = 0; k < 3; ++k) {
                const int a = mesh.faces[f][k], b = mesh.faces[f][(k + 1) % 3];
                if (inRegion[size_t(a)] && inRegion[size_t(b)]) kept.directed.insert(edgeKey(a, b));
            }
    return kept;
}

bool regionIsClean(const RegionSubmesh& region)
{
    const TopologySummary topology = computeTopology(region.mesh);
    return topology.manifold() && topology.orientable;
}

RepairReport repairRegion(RegionSubmesh& region, const KeptEdges& kept, int vertexBudget, int& nextCopyId)
{
    const int n = region.mesh.vertexCount();
    const auto meetsKept = [&](int a, int b) {
        return kept.touches(region.originalVertex[size_t(a)], region.originalVertex[size_t(b)]);
    };
    // A component the repair would drop as too small but which meets the kept faces would leave
    // a hole there: then nothing is dropped.
    std::vector<char> onSeam(size_t(n), 0);
    for (const Face& t : region.mesh.faces)
        for (int k = 0; k < 3; ++k)
            if (meetsKept(t[k], t[(k + 1) % 3])) onSeam[size_t(t[k])] = onSeam[size_t(t[(k + 1) % 3])] = 1;
    RepairParams params;
    params.mergeVertices = false;
    params.vertexBudget = vertexBudget;
    RepairReport repair;
    TriMesh repaired;
    try {
        repaired = repairMesh(region.mesh, params, repair);
    } catch (const InvalidInputError&) {
        repair.skipped = true;  // every component too small: nothing is dropped
    }
    const auto dropsSeam = [&] {
        for (int v = 0; v < n; ++v)
            if (onSeam[size_t(v)] && repair.vertexMap[size_t(v)] < 0) return true;
        return false;
    };
    if (params.vertexBudget > 0 && (repair.skipped || dropsSeam())) {
        params.vertexBudget = 0;
        repaired = repairMesh(region.mesh, params, repair);
    }
    InputReport prepared;
    if (repair.skipped) {
        prepareInput(region.mesh, prepared);  // throws the strict check's message
        throw InvalidInputError("the region could not be repaired");
    }
    const TriMesh clean = prepareInput(repaired, prepared, true);
    // Clean vertex -> the region vertex it is or copies, and the one the repair kept as it.
    const int m = clean.vertexCount();
    std::vector<int> source(size_t(m), -1), holder(size_t(n), -1), repairHolder(size_t(n), -1);
    for (size_t r = 0; r < repair.vertexSource.size(); ++r) {
        const int c = prepared.cleanIndex[r];
        if (c >= 0) source[size_t(c)] = repair.vertexSource[r];
    }
    for (int v = 0; v < n; ++v)
        if (repair.vertexMap[size_t(v)] >= 0) repairHolder[size_t(v)] = prepared.cleanIndex[size_t(repair.vertexMap[size_t(v)])];
    if (std::find(source.begin(), source.end(), -1) != source.end())
        throw InvalidInputError("the region's repair left a vertex it cannot trace back");
    // The copy on a border edge that meets the kept faces stays the whole mesh's vertex: the
    // seam is shared by index. Elsewhere the repair's choice stands.
    const EdgeTable edges = buildEdgeTable(clean);
    for (int e = 0; e < edges.edgeCount(); ++e) {
        const int a = edges.ends[size_t(e)][0], b = edges.ends[size_t(e)][1];
        if (!edges.isBorder(e) || !meetsKept(source[size_t(a)], source[size_t(b)])) continue;
        for (int c : {a, b})
            if (holder[size_t(source[size_t(c)])] < 0) holder[size_t(source[size_t(c)])] = c;
    }
    for (int v = 0; v < n; ++v)
        if (holder[size_t(v)] < 0) holder[size_t(v)] = repairHolder[size_t(v)];
    RegionSubmesh out;
    out.mesh = clean;
    out.repaired = true;
    out.border.assign(size_t(m), 0);
    for (int c = 0; c < m; ++c) {
        const int v = source[size_t(c)];
        out.originalVertex.push_back(holder[size_t(v)] == c ? region.originalVertex[size_t(v)] : nextCopyId++);
        out.sourceVertex.push_back(region.sourceVertex[size_t(v)]);
    }
    for (int e = 0; e < edges.edgeCount(); ++e)
        if (edges.isBorder(e)) out.border[size_t(edges.ends[size_t(e)][0])] = out.border[size_t(edges.ends[size_t(e)][1])] = 1;
    region = std::move(out);
    repair.notes.insert(repair.notes.end(), prepared.notes.begin(), prepared.notes.end());  // the flips
    return repair;
}

std::vector<RegionSubmesh> regionParts(const RegionSubmesh& region)
{
    const EdgeTable edges = buildEdgeTable(region.mesh, RepeatedVertexFaces::Skip);
    int count = 0;
    const std::vector<int> component = faceComponents(edges, region.mesh.faceCount(), count);
    std::vector<RegionSubmesh> parts{size_t(count)};
    std::map<std::pair<int, int>, int> index;  // (part, region vertex) -> part vertex
    for (size_t f = 0; f < region.mesh.faces.size(); ++f) {
        RegionSubmesh& part = parts[size_t(component[f])];
        Face t = region.mesh.faces[f];
        for (int& v : t) {
            const auto [it, added] = index.insert({{component[f], v}, part.mesh.vertexCount()});
            if (added) {
                part.mesh.vertices.push_back(region.mesh.vertices[size_t(v)]);
                part.originalVertex.push_back(region.originalVertex[size_t(v)]);
                part.sourceVertex.push_back(region.sourceVertex[size_t(v)]);
                part.border.push_back(region.border[size_t(v)]);
            }
            v = it->second;
        }
        part.mesh.faces.push_back(t);
        if (!region.originalFace.empty()) part.originalFace.push_back(region.originalFace[f]);
        part.repaired = region.repaired;
    }
    return parts;
}

int orientRegionToKept(RegionSubmesh& region, const KeptEdges& kept, int* against)
{
    const EdgeTable edges = buildEdgeTable(region.mesh, RepeatedVertexFaces::Skip);
    int count = 0;
    const std::vector<int> component = faceComponents(edges, region.mesh.faceCount(), count);
    std::vector<int> agree(size_t(count), 0), disagree(size_t(count), 0);  // kept edges run the other way, the same way
    for (int e = 0; e < edges.edgeCount(); ++e) {
        if (!edges.isBorder(e)) continue;
        const int h = edges.halfEdge(e, 0);
        const Face& t = region.mesh.faces[size_t(h / 3)];
        const int a = region.originalVertex[size_t(t[h % 3])], b = region.originalVertex[size_t(t[(h % 3 + 1) % 3])];
        if (kept.runs(b, a)) ++agree[size_t(component[size_t(h / 3)])];
        if (kept.runs(a, b)) ++disagree[size_t(component[size_t(h / 3)])];
    }
    if (against) {
        *against = 0;
        for (int c = 0; c < count; ++c) *against += std::min(agree[size_t(c)], disagree[size_t(c)]);
    }
    int reversed = 0;
    for (size_t f = 0; f < region.mesh.faces.size(); ++f)
        if (disagree[size_t(component[f])] > agree[size_t(component[f])])
            std::swap(region.mesh.faces[f][1], region.mesh.faces[f][2]), ++reversed;
    return reversed;
}

std::string SurfaceFaults::describe() const
{
    std::vector<std::string> parts;
    if (nonManifoldEdges > 0) parts.push_back(plural(nonManifoldEdges, "non-manifold edge", "non-manifold edges"));
    if (oppositeEdges > 0)
        parts.push_back(
            plural(oppositeEdges, "edge between faces of opposite orientation", "edges between faces of opposite orientation"));
    if (nonManifoldVertices > 0) parts.push_back(plural(nonManifoldVertices, "non-manifold vertex", "non-manifold vertices"));
    std::string text;
    for (size_t i = 0; i < parts.size(); ++i) text += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
    return text;
}

void stitchedFaults(const TriMesh& input, const std::vector<char>& selected, const StitchedMesh& stitched, SurfaceFaults& kept,
                    SurfaceFaults& elsewhere)
{
    kept = elsewhere = SurfaceFaults{};
    const TriMesh& mesh = stitched.mesh;
    const EdgeTable edges = buildEdgeTable(mesh, RepeatedVertexFaces::Skip);
    const auto leftSelected = [&](int f) {  // a selected face left as it was (its piece not remeshed)
        const int origin = stitched.faceOrigin[size_t(f)];
        return origin >= 0 && selected[size_t(origin)];
    };
    EdgeTable inputEdges;
    const auto fault = [](const EdgeTable& table, const std::vector<Face>& faces, int e) {
        return table.faceCount(e) > 2 ? 2 : table.faceCount(e) == 2 && table.firstTwoSameDirection(faces, e) ? 1 : 0;
    };
    std::vector<char> nearLeft(mesh.vertices.size(), 0);
    for (int f = 0; f < mesh.faceCount(); ++f)
        if (leftSelected(f))
            for (int v : mesh.faces[size_t(f)]) nearLeft[size_t(v)] = 1;
    for (int e = 0; e < edges.edgeCount(); ++e) {
        const int kind = fault(edges, mesh.faces, e);
        if (kind == 0) continue;
        const int a = stitched.vertexOrigin[size_t(edges.ends[size_t(e)][0])];
        const int b = stitched.vertexOrigin[size_t(edges.ends[size_t(e)][1])];
        bool own = a >= 0 && b >= 0;
        for (int i = 0; i < edges.faceCount(e) && own; ++i) own = !leftSelected(edges.face(e, i));
        if (own) {
            if (inputEdges.ends.empty()) inputEdges = buildEdgeTable(input, RepeatedVertexFaces::Skip);
            const int was = inputEdges.find(a, b);
            own = was >= 0 && fault(inputEdges, input.faces, was) == kind;
        }
        SurfaceFaults& to = own ? kept : elsewhere;
        ++(kind == 2 ? to.nonManifoldEdges : to.oppositeEdges);
    }
    const std::vector<int> fans = vertexFans(mesh);
    std::vector<int> inputFans;
    for (size_t v = 0; v < fans.size(); ++v) {
        if (fans[v] <= 1) continue;
        if (inputFans.empty()) inputFans = vertexFans(input);
        const int origin = stitched.vertexOrigin[v];
        ++(origin >= 0 && inputFans[size_t(origin)] > 1 && !nearLeft[v] ? kept : elsewhere).nonManifoldVertices;
    }
}

}  // namespace fieldcvt
