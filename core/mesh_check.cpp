#include "mesh_check.h"

#include "errors.h"
#include "mesh_edges.h"
#include "surface_gluing.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numeric>
#include <sstream>

namespace fieldcvt {

namespace {

//! True when the triangle's area is below rounding against its longest edge (a sine of about
//! 1e-12): corners on one line that doubles could not place exactly on it. Scaled first, so
//! neither 1e300 nor 1e-300 coordinates overflow or underflow.
bool cornersOnOneLine(const Vec3& a, const Vec3& b, const Vec3& c)
{
    Vec3 u = b - a, v = c - a;
    const double scale = std::max(u.cwiseAbs().maxCoeff(), v.cwiseAbs().maxCoeff());
    if (!(scale > 0) || !std::isfinite(scale)) return false;  // the exact checks decide those
    u /= scale;
    v /= scale;
    const double longest = std::max({u.squaredNorm(), v.squaredNorm(), (v - u).squaredNorm()});
    return u.cross(v).norm() <= 1e-12 * longest;
}

std::string point(const Vec3& p)
{
    std::ostringstream s;
    s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
    return s.str();
}

std::string vertexAt(const TriMesh& input, int v) { return std::to_string(v) + " " + point(input.vertices[v]); }

//! The faces on the representatives `rep`, without degenerate ones (repeated corner, zero area;
//! thin needles of non-zero area are fine for the RVD and kept); faceOrigin: clean face -> input
//! face, for messages.
std::vector<Face> nonDegenerateFaces(const TriMesh& input, const std::vector<int>& rep, std::vector<int>& faceOrigin,
                                     InputReport& report)
{
    std::vector<Face> faces;
    bool allOnLines = true;
    faces.reserve(input.faces.size());
    faceOrigin.reserve(input.faces.size());
    for (int f = 0; f < input.faceCount(); ++f) {
        const Face t{rep[input.faces[f][0]], rep[input.faces[f][1]], rep[input.faces[f][2]]};
        int exponent = 0;
        const Vec3 normal = scaledCross(input.vertices[t[0]], input.vertices[t[1]], input.vertices[t[2]], exponent);
        // Exact zero test (not squaredNorm() == 0, which underflows on tiny but valid faces), on
        // the scaled edges: a face of a 1e-170 model is not degenerate.
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0] || (normal.array() == 0.0).all()) {
            ++report.removedDegenerateFaces;
            continue;
        }
        allOnLines = allOnLines && cornersOnOneLine(input.vertices[t[0]], input.vertices[t[1]], input.vertices[t[2]]);
        faces.push_back(t);
        faceOrigin.push_back(f);
    }
    // Corners on one line up to rounding leave a tiny area that is not exactly zero: a surface
    // made only of such faces has nothing to remesh either.
    if (!faces.empty() && allOnLines)
        throw InvalidInputError("every face of the mesh is degenerate (its corners lie on one line, up to rounding)");
    return faces;
}

//! Removes faces with the corner set of an earlier face (exact duplicates).
void removeDuplicateFaces(std::vector<Face>& faces, std::vector<int>& faceOrigin, InputReport& report)
{
    std::vector<std::pair<std::array<int, 3>, int>> keys;
    keys.reserve(faces.size());
    for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
        std::array<int, 3> k = faces[f];
        std::sort(k.begin(), k.end());
        keys.push_back({k, f});
    }
    std::sort(keys.begin(), keys.end());
    std::vector<char> keep(faces.size(), 1);
    for (size_t r = 1; r < keys.size(); ++r)
        if (keys[r].first == keys[r - 1].first) {
            keep[keys[r].second] = 0;
            ++report.removedDuplicateFaces;
        }
    std::vector<Face> kept;
    std::vector<int> keptOrigin;
    kept.reserve(faces.size());
    keptOrigin.reserve(faces.size());
    for (size_t f = 0; f < faces.size(); ++f)
        if (keep[f]) kept.push_back(faces[f]), keptOrigin.push_back(faceOrigin[f]);
    faces.swap(kept);
    faceOrigin.swap(keptOrigin);
}

//! Refuses a mesh with an edge of more than two faces: it cannot be remeshed as one surface.
void refuseNonManifoldEdges(const TriMesh& input, const EdgeTable& edges)
{
    int nonManifold = 0, first = -1;
    for (int e = 0; e < edges.edgeCount(); ++e)
        if (edges.isNonManifold(e) && nonManifold++ == 0) first = e;
    if (nonManifold > 0)
        throw SurfaceTopologyError(std::to_string(nonManifold) +
                                   " non-manifold edge(s) (more than two faces on one edge), the first between vertices " +
                                   vertexAt(input, edges.ends[first][0]) + " and " + vertexAt(input, edges.ends[first][1]));
}

//! The information and notes of what the preparation changed.
void describePreparation(InputReport& report)
{
    if (report.mergedDuplicateVertices > 0)
        report.information.push_back("merged " + std::to_string(report.mergedDuplicateVertices) +
                                     " duplicate vertices (same coordinates)");
    if (report.removedUnreferencedVertices > 0)
        report.information.push_back("removed " + std::to_string(report.removedUnreferencedVertices) + " unreferenced vertices");
    if (report.removedDegenerateFaces > 0)
        report.notes.push_back("removed " + std::to_string(report.removedDegenerateFaces) + " degenerate (zero-area) faces");
    if (report.removedDuplicateFaces > 0)
        report.notes.push_back("removed " + std::to_string(report.removedDuplicateFaces) + " duplicate faces");
    if (report.flippedFaces > 0)
        report.notes.push_back("flipped " + std::to_string(report.flippedFaces) +
                               " faces to orient each connected component consistently (with its first face)");
    if (report.splitNonManifoldVertices > 0)
        report.notes.push_back("split " + std::to_string(report.splitNonManifoldVertices) +
                               " non-manifold vertices (faces forming several fans) into one vertex per fan (" +
                               std::to_string(report.addedVertexCopies) + " vertices added)");
    if (report.components > 1) {
        const double total = std::accumulate(report.componentAreas.begin(), report.componentAreas.end(), 0.0);
        const double smallest = *std::min_element(report.componentAreas.begin(), report.componentAreas.end());
        std::ostringstream s;
        s << "the mesh has " << report.components << " connected components (kept; the smallest has " << std::setprecision(3)
          << (total > 0 ? 100.0 * smallest / total : 0.0) << " % of the area)";
        report.information.push_back(s.str());
    }
}

}  // namespace

TriMesh prepareInput(const TriMesh& input, InputReport& report, bool repaired)
{
    report = InputReport{};
    if (input.faces.empty())
        throw InvalidInputError(input.vertices.empty() ? "the mesh is empty"
                                                       : "the mesh has no faces (a point cloud cannot be remeshed)");
    const int n = input.vertexCount();
    for (int f = 0; f < input.faceCount(); ++f)
        for (int c : input.faces[f])
            if (c < 0 || c >= n)
                throw InvalidInputError("face " + std::to_string(f) + " refers to vertex " + std::to_string(c) +
                                        ", but the mesh has " + std::to_string(n) + " vertices");
    std::vector<char> referenced(n, 0);
    for (const Face& t : input.faces)
        for (int c : t) {
            if (!input.vertices[c].allFinite())
                throw InvalidInputError("vertex " + std::to_string(c) + " has a non-finite coordinate " +
                                        point(input.vertices[c]));
            referenced[c] = 1;
        }

    // 1. Exactly duplicate vertices (same coordinates) merged into the first of them, before
    // anything else: the faces on either side of a seam then share their edge.
    std::vector<int> rep(n);
    std::iota(rep.begin(), rep.end(), 0);
    if (!repaired) rep = exactDuplicateRepresentatives(input.vertices, referenced, report.mergedDuplicateVertices);

    // 2. Degenerate faces, then exact duplicates (not searched for in a repaired mesh: the repair
    // removed every face whose corner set an earlier face has, and its vertex splits give the
    // faces of one fan the same copy).
    std::vector<int> faceOrigin;
    std::vector<Face> faces = nonDegenerateFaces(input, rep, faceOrigin, report);
    if (!repaired) removeDuplicateFaces(faces, faceOrigin, report);
    if (faces.empty()) throw InvalidInputError("every face of the mesh is degenerate (zero area)");
    const int faceCount = static_cast<int>(faces.size());

    // 3. Non-manifold edges.
    const EdgeTable edges = buildEdgeTable(faces, n);
    refuseNonManifoldEdges(input, edges);

    // 4. Orientation: per connected component, a breadth-first walk from its first face flips
    // every face that disagrees with the face it was reached from. A face reached again with
    // the opposite requirement closes an orientation-reversing loop: a Möbius-like surface.
    const std::vector<int> partner = glueTwoSidedEdges(edges, faceCount);
    const Orientation orientation = orientByWalk(faces, partner, [&](int h) {
        const int g = partner[h] / 3, a = faces[h / 3][h % 3], b = faces[h / 3][(h % 3 + 1) % 3];
        throw SurfaceTopologyError(
            "a connected component is not orientable (like a Moebius strip, no consistent orientation "
            "exists): input faces " +
            std::to_string(faceOrigin[h / 3]) + " and " + std::to_string(faceOrigin[g]) +
            " disagree across the edge between vertices " + vertexAt(input, std::min(a, b)) + " and " +
            vertexAt(input, std::max(a, b)));
    });
    report.components = orientation.components;
    report.componentAreas.assign(report.components, 0.0);
    for (int f = 0; f < faceCount; ++f) {
        const Face& t = faces[f];
        report.componentAreas[orientation.component[f]] +=
            triangleArea(input.vertices[t[0]], input.vertices[t[1]], input.vertices[t[2]]);
    }

    // 5. Non-manifold vertices: corners of the faces around a vertex are joined across the
    // (manifold) edges they share; each resulting fan beyond the one of the vertex's first face
    // gets its own copy of the vertex. Then the flips of step 4.
    std::vector<int> cornerVertex, copySource;  // working vertex n + i is a copy of input vertex copySource[i]
    splitIntoFans(faces, partner, n, orientation.flip, cornerVertex, copySource);
    {
        std::vector<char> split(n, 0);
        for (int v : copySource) split[v] = 1;
        report.splitNonManifoldVertices = static_cast<int>(std::count(split.begin(), split.end(), 1));
        report.addedVertexCopies = static_cast<int>(copySource.size());
    }
    for (int f = 0; f < faceCount; ++f) {
        faces[f] = {cornerVertex[3 * f], cornerVertex[3 * f + 1], cornerVertex[3 * f + 2]};
        if (orientation.flip[f]) {
            std::swap(faces[f][1], faces[f][2]);
            ++report.flippedFaces;
        }
    }

    // 6. Compact: referenced vertices in their original order, then the split copies.
    const int working = n + static_cast<int>(copySource.size());
    std::vector<int> newIndex(working, -1);
    for (const Face& t : faces)
        for (int c : t) newIndex[c] = 0;
    TriMesh clean;
    clean.vertices.reserve(working);
    for (int v = 0; v < working; ++v)
        if (newIndex[v] == 0) {
            newIndex[v] = clean.vertexCount();
            clean.vertices.push_back(input.vertices[v < n ? v : copySource[v - n]]);
        }
    report.cleanIndex.assign(n, -1);
    for (int v = 0; v < n; ++v) {
        report.cleanIndex[v] = newIndex[rep[v]];
        if (rep[v] == v && newIndex[v] < 0) ++report.removedUnreferencedVertices;
    }
    clean.faces.reserve(faces.size());
    for (const Face& t : faces) clean.faces.push_back({newIndex[t[0]], newIndex[t[1]], newIndex[t[2]]});

    describePreparation(report);
    return clean;
}

}  // namespace fieldcvt
