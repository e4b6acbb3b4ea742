#include "mesh_check.h"

#include "errors.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>

namespace fieldcvt {

namespace {

std::string point(const Vec3& p)
{
    std::ostringstream s;
    s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
    return s.str();
}

}  // namespace

TriMesh prepareInput(const TriMesh& input, InputReport& report)
{
    if (input.faces.empty())
        throw InvalidInputError(input.vertices.empty() ? "the mesh is empty"
                                                       : "the mesh has no faces (a point cloud cannot be remeshed)");
    const int n = input.vertexCount();
    for (int f = 0; f < input.faceCount(); ++f)
        for (int c : input.faces[f])
            if (c < 0 || c >= n)
                throw InvalidInputError("face " + std::to_string(f) + " refers to vertex " + std::to_string(c) +
                                        ", but the mesh has " + std::to_string(n) + " vertices");

    // Faces: drop degenerate ones and exact duplicates (same corner set).
    std::vector<Face> faces;
    faces.reserve(input.faces.size());
    std::vector<std::tuple<int, int, int>> seen;
    seen.reserve(input.faces.size());
    for (int f = 0; f < input.faceCount(); ++f) {
        const Face& t = input.faces[f];
        for (int c : t)
            if (!input.vertices[c].allFinite())
                throw InvalidInputError("vertex " + std::to_string(c) + " has a non-finite coordinate " + point(input.vertices[c]));
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0] || faceNormal(input, f).squaredNorm() == 0.0) {
            ++report.removedDegenerateFaces;
            continue;
        }
        faces.push_back(t);
    }
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
        kept.reserve(faces.size());
        for (size_t f = 0; f < faces.size(); ++f)
            if (keep[f]) kept.push_back(faces[f]);
        faces.swap(kept);
    }
    if (faces.empty()) throw InvalidInputError("every face of the mesh is degenerate (zero area)");

    // Non-manifold edges: more than two faces on one edge cannot be remeshed as one surface.
    {
        std::vector<std::pair<int, int>> edges;
        edges.reserve(faces.size() * 3);
        for (const Face& t : faces)
            for (int k = 0; k < 3; ++k) edges.push_back(std::minmax(t[k], t[(k + 1) % 3]));
        std::sort(edges.begin(), edges.end());
        int nonManifold = 0;
        std::pair<int, int> first{-1, -1};
        for (size_t r = 0; r < edges.size();) {
            size_t e = r;
            while (e < edges.size() && edges[e] == edges[r]) ++e;
            if (e - r > 2) {
                if (nonManifold == 0) first = edges[r];
                ++nonManifold;
            }
            r = e;
        }
        if (nonManifold > 0)
            throw InvalidInputError(std::to_string(nonManifold) + " non-manifold edge(s) (more than two faces on one edge), the first between vertices " +
                                    std::to_string(first.first) + " " + point(input.vertices[first.first]) + " and " +
                                    std::to_string(first.second) + " " + point(input.vertices[first.second]));
    }

    // Compact: keep referenced vertices only, in their original order.
    std::vector<int> newIndex(n, -1);
    for (const Face& t : faces)
        for (int c : t) newIndex[c] = 0;
    TriMesh clean;
    for (int v = 0; v < n; ++v)
        if (newIndex[v] == 0) {
            newIndex[v] = clean.vertexCount();
            clean.vertices.push_back(input.vertices[v]);
        }
    report.removedUnreferencedVertices = n - clean.vertexCount();
    report.cleanIndex = newIndex;  // -1 exactly for the removed vertices
    clean.faces.reserve(faces.size());
    for (const Face& t : faces) clean.faces.push_back({newIndex[t[0]], newIndex[t[1]], newIndex[t[2]]});

    if (report.removedUnreferencedVertices > 0)
        report.notes.push_back("removed " + std::to_string(report.removedUnreferencedVertices) + " unreferenced vertices");
    if (report.removedDegenerateFaces > 0)
        report.notes.push_back("removed " + std::to_string(report.removedDegenerateFaces) + " degenerate (zero-area) faces");
    if (report.removedDuplicateFaces > 0)
        report.notes.push_back("removed " + std::to_string(report.removedDuplicateFaces) + " duplicate faces");
    return clean;
}

}  // namespace fieldcvt
