// Keeping the input's atlas on the remeshed surface: charts by union-find over the
// edges that are no seam, closest points through ClosestPointTree, seam faces continued.
#include "texture_transfer.h"

#include "closest_point.h"
#include "thread_budget.h"
#include "disjoint_sets.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <tuple>

namespace fieldcvt {

std::string textureProblem(const TriMesh& mesh, const MeshTexture& texture)
{
    const std::size_t faces = mesh.faces.size();
    if (texture.uv.size() != 3 * faces)
        return std::to_string(texture.uv.size()) + " texture coordinates for " + std::to_string(faces) + " faces (3 each)";
    if (texture.faceMaterial.size() != faces)
        return std::to_string(texture.faceMaterial.size()) + " face materials for " + std::to_string(faces) + " faces";
    for (std::size_t c = 0; c < texture.uv.size(); ++c)
        if (!texture.uv[c].allFinite()) return "texture coordinate of face " + std::to_string(c / 3) + " is not finite";
    for (std::size_t f = 0; f < faces; ++f)
        if (texture.faceMaterial[f] < 0 || texture.faceMaterial[f] >= static_cast<int>(texture.materials.size()))
            return "material of face " + std::to_string(f) + " out of range";
    return {};
}

namespace {

//! The coordinates of `vertex` in face f (its first corner with that vertex).
const Vec2& cornerUv(const TriMesh& mesh, const MeshTexture& texture, int f, int vertex)
{
    const Face& face = mesh.faces[f];
    const int k = face[0] == vertex ? 0 : face[1] == vertex ? 1 : 2;
    return texture.uv[3 * static_cast<std::size_t>(f) + k];
}

//! A corner's own coordinates farther than this many times its face's size (in the home face's
//! map) from that map's are across a seam.
constexpr double kSeamJump = 1.0;

bool sameUv(const Vec2& a, const Vec2& b, double tolerance) { return (a - b).cwiseAbs().maxCoeff() <= tolerance; }

//! Coordinates of p by face f's affine map: barycentric coordinates in f's plane (outside
//! [0, 1] allowed); on a face without a plane, those of p's closest point on it.
Vec2 continuedUv(const TriMesh& mesh, const MeshTexture& texture, int f, const Vec3& p)
{
    const Face& face = mesh.faces[f];
    const Vec3& a = mesh.vertices[face[0]];
    const Vec3 e0 = mesh.vertices[face[1]] - a, e1 = mesh.vertices[face[2]] - a, d = p - a;
    const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1), d20 = d.dot(e0), d21 = d.dot(e1);
    const double denominator = d00 * d11 - d01 * d01;
    Vec3 w;
    if (denominator > 1e-12 * d00 * d11 && std::isfinite(denominator)) {
        w[1] = (d11 * d20 - d01 * d21) / denominator;
        w[2] = (d00 * d21 - d01 * d20) / denominator;
        w[0] = 1.0 - w[1] - w[2];
    } else {
        closestPointOnTriangle(p, a, mesh.vertices[face[1]], mesh.vertices[face[2]], &w);
    }
    const std::size_t c = 3 * static_cast<std::size_t>(f);
    return w[0] * texture.uv[c] + w[1] * texture.uv[c + 1] + w[2] * texture.uv[c + 2];
}

Vec2 interpolatedUv(const MeshTexture& texture, const ClosestPoint& cp)
{
    const std::size_t c = 3 * static_cast<std::size_t>(cp.face);
    return cp.barycentric[0] * texture.uv[c] + cp.barycentric[1] * texture.uv[c + 1] + cp.barycentric[2] * texture.uv[c + 2];
}

}  // namespace

std::vector<int> textureCharts(const TriMesh& mesh, const MeshTexture& texture, double uvTolerance, int* count)
{
    // Every edge once per face, keyed by its sorted ends: the faces of one run share the edge.
    std::vector<std::tuple<int, int, int>> edges;  // (lower end, upper end, face)
    edges.reserve(3 * mesh.faces.size());
    for (int f = 0; f < mesh.faceCount(); ++f)
        for (int k = 0; k < 3; ++k) {
            const int a = mesh.faces[f][k], b = mesh.faces[f][(k + 1) % 3];
            if (a != b) edges.emplace_back(std::min(a, b), std::max(a, b), f);
        }
    std::sort(edges.begin(), edges.end());
    DisjointSets sets(mesh.faceCount());
    for (std::size_t first = 0; first < edges.size();) {
        std::size_t end = first + 1;
        while (end < edges.size() && std::get<0>(edges[end]) == std::get<0>(edges[first]) &&
               std::get<1>(edges[end]) == std::get<1>(edges[first]))
            ++end;
        const int a = std::get<0>(edges[first]), b = std::get<1>(edges[first]);
        for (std::size_t i = first; i < end; ++i)
            for (std::size_t j = i + 1; j < end; ++j) {
                const int f = std::get<2>(edges[i]), g = std::get<2>(edges[j]);
                if (texture.faceMaterial[f] == texture.faceMaterial[g] &&
                    sameUv(cornerUv(mesh, texture, f, a), cornerUv(mesh, texture, g, a), uvTolerance) &&
                    sameUv(cornerUv(mesh, texture, f, b), cornerUv(mesh, texture, g, b), uvTolerance))
                    sets.unite(f, g);
            }
        first = end;
    }
    std::vector<int> chart(mesh.faces.size(), -1), number(mesh.faces.size(), -1);
    int charts = 0;
    for (int f = 0; f < mesh.faceCount(); ++f) {
        const int root = sets.find(f);
        if (number[root] < 0) number[root] = charts++;
        chart[f] = number[root];
    }
    if (count) *count = charts;
    return chart;
}

TextureTransferResult transferTexture(const TriMesh& input, const MeshTexture& inputTexture, const TriMesh& output,
                                      const TextureTransferParams& params, const ClosestPointTree* inputTree)
{
    TextureTransferResult result;
    const std::vector<int> chart = textureCharts(input, inputTexture, params.uvTolerance, &result.charts);
    std::unique_ptr<const ClosestPointTree> ownTree;
    if (!inputTree) ownTree = std::make_unique<const ClosestPointTree>(input);
    const ClosestPointTree& tree = inputTree ? *inputTree : *ownTree;
    const int threads = openMpThreads(params.threads);
    // Each query is independent and written to its own slot: the same result on any thread count.
    std::vector<ClosestPoint> atVertex(output.vertices.size());
    std::vector<int> centroidFace(output.faces.size());
#pragma omp parallel num_threads(threads) if (threads > 1)
    {
#pragma omp for schedule(static)
        for (long long v = 0; v < static_cast<long long>(atVertex.size()); ++v) atVertex[v] = tree.closest(output.vertices[v]);
#pragma omp for schedule(static)
        for (long long f = 0; f < static_cast<long long>(centroidFace.size()); ++f) {
            const Face& face = output.faces[f];
            const Vec3 centroid = (output.vertices[face[0]] + output.vertices[face[1]] + output.vertices[face[2]]) / 3.0;
            centroidFace[f] = tree.closest(centroid, atVertex[face[0]].face).face;
        }
    }
    MeshTexture& out = result.texture;
    out.materials = inputTexture.materials;
    out.libraries = inputTexture.libraries;
    out.uv.resize(3 * output.faces.size());
    out.faceMaterial.resize(output.faces.size());
    for (int f = 0; f < output.faceCount(); ++f) {
        const int home = centroidFace[f];
        out.faceMaterial[f] = inputTexture.faceMaterial[home];
        // The corners by the home face's map, and the face's size there: a corner whose own
        // coordinates jump farther than that from them lies across a seam, even one inside a
        // chart (a chart that meets itself, as a torus cut open along two circles).
        std::array<Vec2, 3> extended;
        for (int k = 0; k < 3; ++k) extended[k] = continuedUv(input, inputTexture, home, output.vertices[output.faces[f][k]]);
        const double size = std::max(
            {(extended[0] - extended[1]).norm(), (extended[1] - extended[2]).norm(), (extended[2] - extended[0]).norm()});
        bool continued = false;
        for (int k = 0; k < 3; ++k) {
            const ClosestPoint& cp = atVertex[output.faces[f][k]];
            Vec2& uv = out.uv[3 * static_cast<std::size_t>(f) + k];
            uv = extended[k];
            if (chart[cp.face] == chart[home]) {
                const Vec2 own = interpolatedUv(inputTexture, cp);
                if ((own - extended[k]).norm() <= kSeamJump * size) {
                    uv = own;
                    continue;
                }
            }
            continued = true;
        }
        result.continuedFaces += continued;
    }
    result.continuedShare = output.faces.empty() ? 0.0 : static_cast<double>(result.continuedFaces) / output.faceCount();
    return result;
}

}  // namespace fieldcvt
