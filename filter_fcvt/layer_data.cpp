#include "layer_data.h"

#include <vcg/complex/allocate.h>

#include <QFileInfo>

#include <algorithm>
#include <cmath>
#include <map>

#include "closest_point.h"
#include "errors.h"
#include "log_text.h"
#include "valence_colour.h"

namespace fcvt_plugin {

fieldcvt::Vec3 toVec3(const Point3m& p) { return fieldcvt::Vec3(double(p[0]), double(p[1]), double(p[2])); }

Point3m toPoint3m(const fieldcvt::Vec3& v) { return Point3m(Scalarm(v.x()), Scalarm(v.y()), Scalarm(v.z())); }

// A handle to the per-vertex Point3m attribute `name`, created if missing; an attribute of that
// name but another type is replaced (vcg asserts on adding a name that exists).
CMeshO::PerVertexAttributeHandle<Point3m> pointAttribute(CMeshO& cm, const char* name)
{
    auto h = vcg::tri::Allocator<CMeshO>::FindPerVertexAttribute<Point3m>(cm, name);
    if (vcg::tri::Allocator<CMeshO>::IsValidHandle<Point3m>(cm, h)) return h;
    vcg::tri::Allocator<CMeshO>::DeletePerVertexAttribute(cm, name);
    return vcg::tri::Allocator<CMeshO>::AddPerVertexAttribute<Point3m>(cm, name);
}

// The name of the remeshing's new layer: the input's label without its extension and with no
// dot, then "_FCVT" ("bunny.off" -> "bunny_FCVT"). MeshLab's layer list shows a label up to its
// last dot (QFileInfo::completeBaseName), so "bunny.off FCVT" read "bunny", like its input; a
// rerun gets "bunny_FCVT(1)" from MeshLab's own disambiguation.
QString outputLayerName(const QString& inputLabel)
{
    QString base = QFileInfo(inputLabel).completeBaseName();
    if (base.isEmpty()) base = inputLabel;
    base.replace(QChar('.'), QChar('_'));
    return base + "_FCVT";
}

// Writes the valence colours to the live vertices of `cm` (vertex i of `mesh` = i-th live vertex)
// and returns the counts as a log line.
QString applyValenceColours(const fieldcvt::TriMesh& mesh, MeshModel& layer)
{
    const fcvt_plugin::ValenceColouring c = fcvt_plugin::colourByValence(mesh);
    layer.updateDataMask(MeshModel::MM_VERTCOLOR);
    size_t i = 0;
    for (CVertexO& v : layer.cm.vert)
        if (!v.IsD() && i < c.colours.size()) v.C() = c.colours[i++];
    if (i != c.colours.size()) throw fieldcvt::Error("valence colours: vertex count mismatch");
    return fcvt_plugin::valenceColourText(c);
}

// Feature lines from a face selection: the edges between a selected and an unselected face
// (vertex indices of `mesh`, whose face i is the i-th live face, `selected[i]` its flag).
std::vector<std::array<int, 2>> selectionBorder(const fieldcvt::TriMesh& mesh, const std::vector<char>& selected)
{
    std::map<std::pair<int, int>, std::pair<int, int>> edges;  // edge -> (faces, selected faces)
    for (size_t f = 0; f < mesh.faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const int a = mesh.faces[f][k], b = mesh.faces[f][(k + 1) % 3];
            auto& count = edges[{std::min(a, b), std::max(a, b)}];
            ++count.first;
            count.second += selected[f] ? 1 : 0;
        }
    std::vector<std::array<int, 2>> border;
    for (const auto& [edge, count] : edges)
        if (count.second > 0 && count.second < count.first) border.push_back({edge.first, edge.second});
    return border;
}

// Per-vertex colour / quality / normal of the input carried to the output: for each output
// vertex the closest point on the input (`in`, whose vertex i is `inVerts[i]`) and barycentric
// interpolation of its face's three corners. Normals are renormalised (a degenerate result keeps
// the output's own normal).
void transferVertexData(const fieldcvt::TriMesh& in, const std::vector<const CVertexO*>& inVerts, const KeptData& keep,
                        CMeshO& out)
{
    if (!keep.any() || in.faces.empty()) return;
    const fieldcvt::ClosestPointTree tree(in);
    for (CVertexO& v : out.vert) {
        if (v.IsD()) continue;
        const fieldcvt::ClosestPoint cp = tree.closest(toVec3(v.cP()));
        if (cp.face < 0) continue;
        const fieldcvt::Face& f = in.faces[size_t(cp.face)];
        const CVertexO* c[3] = {inVerts[size_t(f[0])], inVerts[size_t(f[1])], inVerts[size_t(f[2])]};
        const double w[3] = {cp.barycentric.x(), cp.barycentric.y(), cp.barycentric.z()};
        if (keep.colour) {
            for (int ch = 0; ch < 4; ++ch) {
                double x = 0;
                for (int k = 0; k < 3; ++k) x += w[k] * double(c[k]->cC()[ch]);
                v.C()[ch] = static_cast<unsigned char>(std::clamp(std::lround(x), 0L, 255L));
            }
        }
        if (keep.quality) {
            double q = 0;
            for (int k = 0; k < 3; ++k) q += w[k] * double(c[k]->cQ());
            v.Q() = static_cast<float>(q);
        }
        if (keep.normals) {
            fieldcvt::Vec3 n(0, 0, 0);
            for (int k = 0; k < 3; ++k) n += w[k] * toVec3(c[k]->cN());
            const double len = n.norm();
            if (std::isfinite(len) && len > 1e-12) v.N() = toPoint3m(n / len);
        }
    }
}

std::vector<char> faceSelection(const CMeshO& cm)
{
    std::vector<char> selected;
    for (const CFaceO& f : cm.face)
        if (!f.IsD()) selected.push_back(f.IsS() ? 1 : 0);
    return selected;
}

void keepRegionData(const MeshModel& input, const std::vector<int>& vertexOrigin, const std::vector<int>& faceOrigin,
                    const KeptData& keep, MeshModel& output)
{
    std::vector<const CVertexO*> inVerts;
    for (const CVertexO& v : input.cm.vert)
        if (!v.IsD()) inVerts.push_back(&v);
    std::vector<const CFaceO*> inFaces;
    for (const CFaceO& f : input.cm.face)
        if (!f.IsD()) inFaces.push_back(&f);
    if (vertexOrigin.size() != output.cm.vert.size() || faceOrigin.size() != output.cm.face.size())
        throw fieldcvt::Error("the region's output does not match the new layer");
    for (size_t i = 0; i < vertexOrigin.size(); ++i) {
        if (vertexOrigin[i] < 0) continue;
        const CVertexO& from = *inVerts[size_t(vertexOrigin[i])];
        CVertexO& to = output.cm.vert[i];
        if (keep.colour) to.C() = from.cC();
        if (keep.quality) to.Q() = from.cQ();
        if (keep.normals) to.N() = from.cN();
    }
    const bool faceColour = input.hasDataMask(MeshModel::MM_FACECOLOR);
    const bool faceQuality = input.hasDataMask(MeshModel::MM_FACEQUALITY);
    if (faceColour) output.updateDataMask(MeshModel::MM_FACECOLOR);
    if (faceQuality) output.updateDataMask(MeshModel::MM_FACEQUALITY);
    for (size_t i = 0; i < faceOrigin.size(); ++i) {
        CFaceO& to = output.cm.face[i];
        if (faceOrigin[i] < 0) {
            to.SetS();
            continue;
        }
        to.ClearS();
        const CFaceO& from = *inFaces[size_t(faceOrigin[i])];
        if (faceColour) to.C() = from.cC();
        if (faceQuality) to.Q() = from.cQ();
    }
}

}  // namespace fcvt_plugin
