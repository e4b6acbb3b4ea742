#include "field_drawing.h"

#include <vcg/complex/allocate.h>
#include <vcg/complex/algorithms/update/bounding.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <unordered_set>
#include <vector>

#include "errors.h"
#include "interpolation.h"

namespace fcvt_plugin {

namespace {

Point3m toPoint(const fieldcvt::Vec3& v) { return Point3m(Scalarm(v.x()), Scalarm(v.y()), Scalarm(v.z())); }

// Per vertex the mean length of its face edges (each edge seen once per face), 0 on no face.
std::vector<double> localEdgeLengths(const fieldcvt::TriMesh& mesh, double& meanEdge)
{
    std::vector<double> sum(mesh.vertices.size(), 0.0);
    std::vector<int> count(mesh.vertices.size(), 0);
    double total = 0;
    long long edges = 0;
    for (const fieldcvt::Face& f : mesh.faces)
        for (int k = 0; k < 3; ++k) {
            const int a = f[k], b = f[(k + 1) % 3];
            const double len = (mesh.vertices[size_t(a)] - mesh.vertices[size_t(b)]).norm();
            sum[size_t(a)] += len;
            sum[size_t(b)] += len;
            ++count[size_t(a)];
            ++count[size_t(b)];
            total += len;
            ++edges;
        }
    meanEdge = edges > 0 ? total / double(edges) : 0.0;
    for (size_t v = 0; v < sum.size(); ++v) sum[v] = count[v] > 0 ? sum[v] / count[v] : meanEdge;
    return sum;
}

// The first vertex (index order) of each occupied cell of the grid of cell `cell`.
std::vector<size_t> oneVertexPerCell(const fieldcvt::TriMesh& mesh, const fieldcvt::Vec3& origin, double cell)
{
    struct Hash {
        size_t operator()(const std::array<long long, 3>& k) const
        {
            return size_t(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL);
        }
    };
    std::unordered_set<std::array<long long, 3>, Hash> taken;
    std::vector<size_t> chosen;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        const fieldcvt::Vec3 q = (mesh.vertices[v] - origin) / cell;
        const std::array<long long, 3> key = {(long long)std::floor(q.x()), (long long)std::floor(q.y()),
                                              (long long)std::floor(q.z())};
        if (taken.insert(key).second) chosen.push_back(v);
    }
    return chosen;
}

}  // namespace

FieldDrawingStats drawField(const fieldcvt::TriMesh& mesh, const fieldcvt::DirectionField& field, CMeshO& out, int maxCrosses)
{
    const size_t n = mesh.vertices.size();
    if (field.normals.size() != n || field.directions.size() != n)
        throw fieldcvt::Error("field drawing: the field has " + std::to_string(field.directions.size()) + " directions for " +
                              std::to_string(n) + " vertices");
    FieldDrawingStats stats;
    const std::vector<double> local = localEdgeLengths(mesh, stats.meanEdgeLength);
    out.Clear();
    if (n == 0) return stats;

    maxCrosses = std::max(1, maxCrosses);
    std::vector<size_t> drawn;
    if (n <= size_t(maxCrosses)) {
        drawn.resize(n);
        for (size_t v = 0; v < n; ++v) drawn[v] = v;
    } else {
        fieldcvt::Vec3 lo = mesh.vertices[0];
        for (const fieldcvt::Vec3& p : mesh.vertices) lo = lo.cwiseMin(p);
        double area = 0;
        for (const fieldcvt::Face& f : mesh.faces)
            area += 0.5 * (mesh.vertices[size_t(f[1])] - mesh.vertices[size_t(f[0])])
                              .cross(mesh.vertices[size_t(f[2])] - mesh.vertices[size_t(f[0])])
                              .norm();
        double cell = std::sqrt(std::max(area, 1e-300) / double(maxCrosses));
        if (!(cell > 0) || !std::isfinite(cell)) cell = 1;
        for (int step = 0; step < 200; ++step, cell *= 1.1) {
            drawn = oneVertexPerCell(mesh, lo, cell);
            if (drawn.size() <= size_t(maxCrosses)) break;
        }
        stats.spacing = cell;
    }
    stats.drawnVertices = int(drawn.size());

    // All vertices first, then all faces: AddVertices may reallocate and faces hold pointers.
    vcg::tri::Allocator<CMeshO>::AddVertices(out, 12 * drawn.size());
    vcg::tri::Allocator<CMeshO>::AddFaces(out, 6 * drawn.size());
    double lengthSum = 0;
    for (size_t slot = 0; slot < drawn.size(); ++slot) {
        const size_t v = drawn[slot];
        const fieldcvt::Vec3& normal = field.normals[v];
        const double length = std::max(kSegmentPerEdge * local[v], kSegmentPerCell * stats.spacing);
        lengthSum += length;
        const fieldcvt::Vec3 centre = mesh.vertices[v] + kLift * length * normal;
        for (int s = 0; s < 3; ++s) {
            const fieldcvt::Vec3 dir = fieldcvt::rotateRepresentative(field.directions[v], normal, s);
            const fieldcvt::Vec3 side = 0.5 * kStripWidth * length * normal.cross(dir).normalized();
            const fieldcvt::Vec3 a = centre - 0.5 * length * dir, b = centre + 0.5 * length * dir;
            const fieldcvt::Vec3 corners[4] = {a - side, b - side, b + side, a + side};
            CVertexO* vert = &out.vert[12 * slot + 4 * size_t(s)];
            for (int k = 0; k < 4; ++k) {
                vert[k].P() = toPoint(corners[k]);
                vert[k].N() = toPoint(normal);
                vert[k].C() = kFieldColour;
            }
            CFaceO& f0 = out.face[6 * slot + 2 * size_t(s)];
            CFaceO& f1 = out.face[6 * slot + 2 * size_t(s) + 1];
            f0.V(0) = &vert[0];
            f0.V(1) = &vert[1];
            f0.V(2) = &vert[2];
            f1.V(0) = &vert[0];
            f1.V(1) = &vert[2];
            f1.V(2) = &vert[3];
        }
    }
    stats.meanSegmentLength = drawn.empty() ? 0.0 : lengthSum / double(drawn.size());
    out.C() = kFieldColour;
    vcg::tri::UpdateBounding<CMeshO>::Box(out);
    return stats;
}

}  // namespace fcvt_plugin
