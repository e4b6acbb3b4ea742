#include "rdt.h"

#include "errors.h"
#include "mesh_edges.h"
#include "triangle_shape.h"

#include <algorithm>
#include <string>
#include <tuple>
#include <utility>

namespace fieldcvt {

int splitNonManifoldVertices(TriMesh& mesh, std::vector<int>& seedOfVertex, std::vector<int>* alongside)
{
    // Union the face corners around each vertex across the edges they share; every class of
    // corners beyond the first at a vertex is one more fan, which gets its own vertex copy.
    const int cornerCount = 3 * mesh.faceCount();
    std::vector<int> parent(cornerCount);
    for (int c = 0; c < cornerCount; ++c) parent[c] = c;
    auto find = [&](int c) {
        while (parent[c] != c) c = parent[c] = parent[parent[c]];
        return c;
    };
    // Directed half-edge (a, b) of face f: its corner at a is 3f+k, at b is 3f+(k+1)%3. The
    // opposite half-edge (b, a) of the neighbouring face (the first one, for a non-manifold
    // edge) shares both endpoints.
    const EdgeTable edges = buildEdgeTable(mesh);
    for (int f = 0; f < mesh.faceCount(); ++f)
        for (int k = 0; k < 3; ++k) {
            const int h = edges.firstHalfEdgeFrom(mesh.faces, edges.edgeOf(f, k), mesh.faces[f][(k + 1) % 3]);
            if (h < 0) continue;
            const int g = h / 3, kb = h % 3;  // (b, a) in face g, corner of b is kb
            auto unite = [&](int x, int y) { parent[find(x)] = find(y); };
            unite(3 * f + k, 3 * g + (kb + 1) % 3);  // corners at a
            unite(3 * f + (k + 1) % 3, 3 * g + kb);  // corners at b
        }
    std::vector<int> firstClass(mesh.vertices.size(), -1);
    std::vector<std::pair<int, int>> copyOf;  // (class root, new vertex)
    int split = 0;
    for (int c = 0; c < cornerCount; ++c) {
        int& v = mesh.faces[c / 3][c % 3];
        const int root = find(c);
        if (firstClass[v] < 0 || firstClass[v] == root) {
            firstClass[v] = root;
            continue;
        }
        auto it = std::find_if(copyOf.begin(), copyOf.end(), [&](const auto& p) { return p.first == root; });
        if (it == copyOf.end()) {
            mesh.vertices.push_back(mesh.vertices[v]);
            seedOfVertex.push_back(seedOfVertex[v]);
            if (alongside) alongside->push_back((*alongside)[v]);
            copyOf.push_back({root, mesh.vertexCount() - 1});
            it = copyOf.end() - 1;
            ++split;
        }
        v = it->second;
    }
    return split;
}

namespace {

// A lens piece: a small piece of cell i lying across the border of two cells j and l only. The
// surface crosses the Voronoi edge of (i, j, l) twice close together (a fold of the input, a
// cell poking through a thin part), so the piece is bounded by the bisectors of (i, j) and
// (i, l) alone; its two RVD vertices give the triangles (p, j, l) and (p, l, j): the same
// triangle twice with opposite orientations (a pillow) at a vertex p of degree 2, which no
// manifold can hold. The RDT edge (j, l) then has these two faces besides its regular ones
// (j and l are also neighbours outside the lens), so the edge check below would remove all
// of them and leave a hole. Dropping the pillow instead (the lens area counts as j's and l's)
// keeps the regular faces of (j, l). Only done when (j, l) has other faces, so a surface that
// is nothing but a pillow (three samples) keeps it. `edges` is the edge table of `faces`.
// Returns the number of lenses removed.
int removeLensPieces(int n, const EdgeTable& edges, std::vector<std::array<int, 3>>& faces)
{
    std::vector<int> degree(n, 0);
    for (const auto& t : faces)
        for (int v : t) ++degree[v];
    // Faces at the candidates of degree 2, as (vertex, face index): the two of a vertex adjacent.
    std::vector<std::pair<int, int>> star;
    for (int f = 0; f < static_cast<int>(faces.size()); ++f)
        for (int v : faces[f])
            if (degree[v] == 2) star.push_back({v, f});
    std::sort(star.begin(), star.end());
    std::vector<char> removed(faces.size(), 0);
    int lenses = 0;
    for (size_t r = 0; r + 1 < star.size(); r += 2) {
        const int v = star[r].first, f = star[r].second, g = star[r + 1].second;
        if (removed[f] || removed[g]) continue;
        // f = (v, a, b) rotated to start at v; g must be (v, b, a).
        auto rotated = [&](int face) {
            std::array<int, 3> t = faces[face];
            while (t[0] != v) t = {t[1], t[2], t[0]};
            return t;
        };
        const std::array<int, 3> tf = rotated(f), tg = rotated(g);
        if (tf[1] != tg[2] || tf[2] != tg[1]) continue;
        if (edges.faceCount(edges.find(tf[1], tf[2])) <= 2) continue;  // nothing else on (a, b): keep the pillow
        removed[f] = removed[g] = 1;
        ++lenses;
    }
    if (lenses == 0) return 0;
    std::vector<std::array<int, 3>> kept;
    kept.reserve(faces.size());
    for (size_t f = 0; f < faces.size(); ++f)
        if (!removed[f]) kept.push_back(faces[f]);
    faces.swap(kept);
    return lenses;
}

// Builds the output from triangles over `n` vertex candidates (samples, or pieces of cells);
// `seedOf` gives the sample of a candidate, `position` its output position.
template <class SeedOf, class Position>
RdtResult buildRdt(int n, const std::vector<std::array<int, 3>>& triangles, SeedOf seedOf, Position position)
{
    RdtResult result;

    // An edge is kept manifold when it has at most two faces and they traverse it in opposite
    // directions.
    std::vector<std::array<int, 3>> faces;
    faces.reserve(triangles.size());
    for (const auto& t : triangles)
        if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) faces.push_back(t);
    EdgeTable edges = buildEdgeTable(faces, n);
    result.lensPieces = removeLensPieces(n, edges, faces);
    if (result.lensPieces > 0) edges = buildEdgeTable(faces, n);

    for (int pass = 0; pass < 8; ++pass) {
        // No face repeats a vertex, so a face lies on each of its edges once, and an edge with
        // two faces has a directed side twice exactly when its two half-edges run the same way.
        if (pass > 0) edges = buildEdgeTable(faces, n);
        std::vector<std::array<int, 3>> kept;
        kept.reserve(faces.size());
        for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
            bool bad = false;
            for (int k = 0; k < 3 && !bad; ++k) {
                const int e = edges.edgeOf(f, k);
                bad = edges.isNonManifold(e) || edges.firstTwoSameDirection(faces, e);
            }
            if (!bad) kept.push_back(faces[f]);
        }
        if (kept.size() == faces.size()) break;
        result.removedFaces += static_cast<int>(faces.size() - kept.size());
        faces.swap(kept);
    }

    // Compact the vertices (candidates used by a face), in candidate order, and place them.
    std::vector<int> vertexOf(n, -1);
    for (const auto& t : faces)
        for (int s : t) vertexOf[s] = 0;
    std::vector<int> candidateOfVertex;
    for (int s = 0; s < n; ++s) {
        if (vertexOf[s] < 0) continue;
        vertexOf[s] = static_cast<int>(candidateOfVertex.size());
        candidateOfVertex.push_back(s);
        result.seedOfVertex.push_back(seedOf(s));
    }
    result.mesh.vertices.resize(candidateOfVertex.size());
    result.faceOfVertex.resize(candidateOfVertex.size());
#pragma omp parallel for schedule(static)
    for (int v = 0; v < static_cast<int>(candidateOfVertex.size()); ++v)
        std::tie(result.mesh.vertices[v], result.faceOfVertex[v]) = position(candidateOfVertex[v]);
    result.mesh.faces.reserve(faces.size());
    for (const auto& t : faces) result.mesh.faces.push_back({vertexOf[t[0]], vertexOf[t[1]], vertexOf[t[2]]});
    result.splitVertices = splitNonManifoldVertices(result.mesh, result.seedOfVertex, &result.faceOfVertex);
    if (result.splitVertices > 0)
        result.warnings.push_back(
            std::to_string(result.splitVertices) +
            " output vertices joined separate fans of faces (a restricted cell in several pieces: thin parts or "
            "near-touching sheets) and were split, one vertex per fan");

    if (result.removedFaces > 0)
        result.warnings.push_back(
            "removed " + std::to_string(result.removedFaces) +
            " restricted Delaunay faces on non-manifold edges (sampling too coarse for the input's detail)");
    return result;
}

// A slit piece: a piece of a cell other than the one nearest to its seed, in a single restricted
// Delaunay triangle that it would make a sliver (smallest angle under kSlitAngle, the pieces at
// their points). The seed's cell reaches across a gap of the border narrower than a cell (a
// ragged border, a slit, a pinched hole) and cuts a sliver off the far side between the border
// and two cells j, l only; its vertex would sit on the border in line with j's and l's. Without
// it, (j, l) is the border there. Returns the triangles without those of slit pieces.
std::vector<std::array<int, 3>> withoutSlitPieces(const std::vector<Vec3>& seeds, const RvdResult& rvd, int& slitPieces)
{
    constexpr double kSlitAngle = 30 * kPi / 180;
    const int pieceCount = static_cast<int>(rvd.pieceSeed.size());
    std::vector<int> faceCount(pieceCount, 0), nearest(seeds.size(), -1);
    for (const auto& t : rvd.pieceTriangles)
        for (int p : t) ++faceCount[p];
    for (int p = 0; p < pieceCount; ++p) {
        const int s = rvd.pieceSeed[p];
        const double d = (rvd.piecePoint[p] - seeds[s]).squaredNorm();
        if (nearest[s] < 0 || d < (rvd.piecePoint[nearest[s]] - seeds[s]).squaredNorm()) nearest[s] = p;
    }
    std::vector<std::array<int, 3>> kept;
    kept.reserve(rvd.pieceTriangles.size());
    slitPieces = 0;
    for (const auto& t : rvd.pieceTriangles) {
        bool secondary = false;
        for (int p : t)
            if (faceCount[p] == 1 && nearest[rvd.pieceSeed[p]] != p) secondary = true;
        if (secondary && smallestAngle(rvd.piecePoint[t[0]], rvd.piecePoint[t[1]], rvd.piecePoint[t[2]]) < kSlitAngle)
            ++slitPieces;
        else
            kept.push_back(t);
    }
    return kept;
}

void warnAboutDroppedSeeds(RdtResult& result, int seedCount)
{
    std::vector<char> used(seedCount, 0);
    for (int s : result.seedOfVertex) used[s] = 1;
    result.droppedSeeds = seedCount - static_cast<int>(std::count(used.begin(), used.end(), 1));
    if (result.droppedSeeds > 0)
        result.warnings.push_back(std::to_string(result.droppedSeeds) + " samples are in no output triangle");
}

}  // namespace

int dropDebris(RdtResult& rdt, int maxFaces, double reach)
{
    TriMesh& mesh = rdt.mesh;
    const int faceCount = mesh.faceCount();
    int pieceCount = 0;
    const std::vector<int> piece = faceComponents(buildEdgeTable(mesh), faceCount, pieceCount);
    std::vector<int> size(pieceCount, 0);
    for (int f = 0; f < faceCount; ++f) ++size[piece[f]];
    TriMesh rest;  // the faces of the larger pieces (vertices shared with `mesh`)
    rest.vertices = mesh.vertices;
    bool anySmall = false;
    for (int f = 0; f < faceCount; ++f) {
        if (size[piece[f]] > maxFaces)
            rest.faces.push_back(mesh.faces[f]);
        else
            anySmall = true;
    }
    if (!anySmall || rest.faces.empty()) return 0;
    const ClosestPointTree tree(rest);
    // Per small piece: whether some vertex is farther than `reach` from the rest.
    std::vector<char> far(pieceCount, 0);
    for (int f = 0; f < faceCount; ++f) {
        if (size[piece[f]] > maxFaces || far[piece[f]]) continue;
        for (int v : mesh.faces[f])
            if (tree.closest(mesh.vertices[v]).squaredDistance > reach * reach) far[piece[f]] = 1;
    }
    std::vector<char> drop(pieceCount, 0);
    int dropped = 0;
    for (int c = 0; c < pieceCount; ++c)
        if (size[c] <= maxFaces && !far[c]) drop[c] = 1, ++dropped;
    if (dropped == 0) return 0;
    rdt.debrisPieces += dropped;
    std::vector<Face> faces;
    for (int f = 0; f < faceCount; ++f)
        if (!drop[piece[f]]) faces.push_back(mesh.faces[f]);
    // Renumber the vertices the kept faces use, in their order.
    std::vector<int> index(mesh.vertices.size(), -1);
    std::vector<Vec3> vertices;
    std::vector<int> seedOfVertex, faceOfVertex;
    for (Face& t : faces)
        for (int& v : t) {
            if (index[v] < 0) {
                index[v] = static_cast<int>(vertices.size());
                vertices.push_back(mesh.vertices[v]);
                seedOfVertex.push_back(rdt.seedOfVertex[v]);
                if (!rdt.faceOfVertex.empty()) faceOfVertex.push_back(rdt.faceOfVertex[v]);
            }
            v = index[v];
        }
    mesh.vertices = std::move(vertices);
    mesh.faces = std::move(faces);
    rdt.seedOfVertex = std::move(seedOfVertex);
    rdt.faceOfVertex = std::move(faceOfVertex);
    rdt.warnings.push_back(std::to_string(dropped) + " pieces of at most " + std::to_string(maxFaces) +
                           " faces beside the rest of the mesh dropped (cells cut by parts narrower than the edge length)");
    return dropped;
}

RdtResult extractRdt(const std::vector<Vec3>& seeds, const std::vector<std::array<int, 3>>& triangles,
                     const ClosestPointTree& surface)
{
    RdtResult result = buildRdt(
        static_cast<int>(seeds.size()), triangles, [](int s) { return s; },
        [&](int s) {
            const ClosestPoint cp = surface.closest(seeds[s]);
            return std::make_pair(cp.point, cp.face);
        });
    warnAboutDroppedSeeds(result, static_cast<int>(seeds.size()));
    return result;
}

RdtResult extractRdt(const std::vector<Vec3>& seeds, const RvdResult& rvd, const ClosestPointTree& surface,
                     const std::vector<int>& seedFaceHints)
{
    const int n = static_cast<int>(seeds.size());
    if (!seedFaceHints.empty() && seedFaceHints.size() != seeds.size())
        throw InvalidInputError("extractRdt: " + std::to_string(seedFaceHints.size()) + " face hints for " +
                                std::to_string(seeds.size()) + " seeds");
    std::vector<int> pieces(n, 0);
    for (int s : rvd.pieceSeed) ++pieces[s];
    int slitPieces = 0;
    const std::vector<std::array<int, 3>> triangles = withoutSlitPieces(seeds, rvd, slitPieces);
    RdtResult result = buildRdt(
        static_cast<int>(rvd.pieceSeed.size()), triangles, [&](int p) { return rvd.pieceSeed[p]; },
        [&](int p) {
            // One piece: the closest point on the whole surface, as for a plain RDT; several:
            // the closest point on this piece (the surface's may be on another sheet).
            const int s = rvd.pieceSeed[p];
            if (pieces[s] != 1) return std::make_pair(rvd.piecePoint[p], -1);
            const ClosestPoint cp = surface.closest(seeds[s], seedFaceHints.empty() ? -1 : seedFaceHints[s]);
            return std::make_pair(cp.point, cp.face);
        });
    result.slitPieces = slitPieces;
    result.multiPieceSeeds = static_cast<int>(std::count_if(pieces.begin(), pieces.end(), [](int c) { return c > 1; }));
    warnAboutDroppedSeeds(result, n);
    return result;
}

}  // namespace fieldcvt
