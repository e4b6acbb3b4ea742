#include "field_drawing.h"

#include <vcg/complex/allocate.h>
#include <vcg/complex/algorithms/update/bounding.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "errors.h"
#include "interpolation.h"

namespace fcvt_plugin {

namespace {

double meanFaceEdgeLength(const fieldcvt::TriMesh& mesh)
{
    double sum = 0;
    long long count = 0;
    for (const fieldcvt::Face& f : mesh.faces)
        for (int k = 0; k < 3; ++k) {
            sum += (mesh.vertices[size_t(f[k])] - mesh.vertices[size_t(f[(k + 1) % 3])]).norm();
            ++count;
        }
    return count > 0 ? sum / double(count) : 0.0;
}

Point3m toPoint(const fieldcvt::Vec3& v)
{
    return Point3m(Scalarm(v.x()), Scalarm(v.y()), Scalarm(v.z()));
}

}  // namespace

FieldDrawingStats drawField(const fieldcvt::TriMesh& mesh, const fieldcvt::DirectionField& field, CMeshO& out,
                            int maxPoints)
{
    const size_t n = mesh.vertices.size();
    if (field.normals.size() != n || field.directions.size() != n)
        throw fieldcvt::Error("field drawing: the field has " + std::to_string(field.directions.size()) +
                              " directions for " + std::to_string(n) + " vertices");
    FieldDrawingStats stats;
    maxPoints = std::max(1, maxPoints);
    stats.stride = n > size_t(maxPoints) ? int((n + size_t(maxPoints) - 1) / size_t(maxPoints)) : 1;
    stats.meanEdgeLength = meanFaceEdgeLength(mesh);
    stats.segmentLength = 0.5 * stats.meanEdgeLength * std::sqrt(double(stats.stride));
    const double half = 0.5 * stats.segmentLength;

    out.Clear();
    if (n == 0)
        return stats;
    const size_t drawn = (n + size_t(stats.stride) - 1) / size_t(stats.stride);
    stats.drawnVertices = int(drawn);

    // All vertices first, then all edges: AddVertices may reallocate and edges hold pointers.
    vcg::tri::Allocator<CMeshO>::AddVertices(out, 6 * drawn);
    vcg::tri::Allocator<CMeshO>::AddEdges(out, 3 * drawn);
    const vcg::Color4b colour(220, 40, 40, 255);
    size_t slot = 0;
    for (size_t v = 0; v < n; v += size_t(stats.stride), ++slot) {
        const fieldcvt::Vec3& p = mesh.vertices[v];
        const fieldcvt::Vec3& normal = field.normals[v];
        for (int s = 0; s < 3; ++s) {
            const fieldcvt::Vec3 dir = fieldcvt::rotateRepresentative(field.directions[v], normal, s);
            CVertexO& a = out.vert[6 * slot + 2 * size_t(s)];
            CVertexO& b = out.vert[6 * slot + 2 * size_t(s) + 1];
            a.P() = toPoint(p + half * dir);
            b.P() = toPoint(p - half * dir);
            a.N() = b.N() = toPoint(normal);
            a.C() = b.C() = colour;
            CEdgeO& e = out.edge[3 * slot + size_t(s)];
            e.V(0) = &a;
            e.V(1) = &b;
        }
    }
    out.C() = colour;
    vcg::tri::UpdateBounding<CMeshO>::Box(out);
    return stats;
}

}  // namespace fcvt_plugin
