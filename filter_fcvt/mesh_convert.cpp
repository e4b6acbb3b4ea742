#include "mesh_convert.h"

#include <vcg/complex/allocate.h>

#include <cctype>
#include <string>
#include <vector>

#include "errors.h"
#include "mesh_io.h"
#include "triangulate.h"

namespace fcvt_plugin {

fieldcvt::TriMesh toTriMesh(const CMeshO& in)
{
    fieldcvt::TriMesh out;
    out.vertices.reserve(static_cast<size_t>(in.vn));
    out.faces.reserve(static_cast<size_t>(in.fn));

    // Deleted vertices stay in cm.vert until a compaction, so indices must be remapped.
    std::vector<int> remap(in.vert.size(), -1);
    for (size_t i = 0; i < in.vert.size(); ++i) {
        const CVertexO& v = in.vert[i];
        if (v.IsD()) continue;
        remap[i] = out.vertexCount();
        const Point3m& p = v.cP();
        out.vertices.emplace_back(double(p[0]), double(p[1]), double(p[2]));
    }
    for (size_t f = 0; f < in.face.size(); ++f) {
        const CFaceO& face = in.face[f];
        if (face.IsD()) continue;
        fieldcvt::Face tri;
        for (int k = 0; k < 3; ++k) {
            const size_t vi = size_t(vcg::tri::Index(in, face.cV(k)));
            if (vi >= remap.size() || remap[vi] < 0)
                throw fieldcvt::InvalidInputError("face " + std::to_string(f) + " references a deleted or invalid vertex");
            tri[k] = remap[vi];
        }
        out.faces.push_back(tri);
    }
    return out;
}

fieldcvt::TriMesh toSurfaceMesh(const CMeshO& in, int& flipped)
{
    fieldcvt::TriMesh out = toTriMesh(in);
    flipped = fieldcvt::flipZeroAreaTriangles(out);
    return out;
}

FilePrecision fullPrecisionCoordinates(const std::string& path, fieldcvt::TriMesh& mesh, std::vector<fieldcvt::Face>* fileFaces)
{
    if (fileFaces != nullptr) fileFaces->clear();
    std::string ext = path.size() > 4 ? path.substr(path.size() - 4) : std::string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".ply" && ext != ".obj" && ext != ".off") return FilePrecision::NoFile;
    fieldcvt::TriMesh file;
    fieldcvt::MeshReadInfo info;
    try {
        file = fieldcvt::readMesh(path, &info);
    } catch (const std::exception&) {
        return FilePrecision::NoFile;  // gone, unreadable: the layer is what there is
    }
    if (file.vertices.size() != mesh.vertices.size()) return FilePrecision::NotTheFile;
    bool finer = false;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        const fieldcvt::Vec3& exact = file.vertices[v];
        if (exact.cast<Scalarm>().cast<double>() != mesh.vertices[v]) return FilePrecision::NotTheFile;
        finer = finer || exact != mesh.vertices[v];
    }
    if (fileFaces != nullptr && info.polygonsTriangulated > 0) *fileFaces = std::move(file.faces);
    if (!finer) return FilePrecision::Same;
    mesh.vertices = std::move(file.vertices);
    return FilePrecision::Restored;
}

void fromTriMesh(const fieldcvt::TriMesh& mesh, CMeshO& out)
{
    out.Clear();
    if (mesh.vertices.empty()) return;
    auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(out, mesh.vertices.size());
    for (const fieldcvt::Vec3& p : mesh.vertices) {
        vi->P() = Point3m(Scalarm(p.x()), Scalarm(p.y()), Scalarm(p.z()));
        ++vi;
    }
    auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(out, mesh.faces.size());
    for (const fieldcvt::Face& f : mesh.faces) {
        for (int k = 0; k < 3; ++k) {
            if (f[k] < 0 || f[k] >= mesh.vertexCount())
                throw fieldcvt::Error("output face references vertex " + std::to_string(f[k]) + " out of range");
            fi->V(k) = &out.vert[size_t(f[k])];
        }
        ++fi;
    }
}

}  // namespace fcvt_plugin
