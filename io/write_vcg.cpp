// OFF and STL through vcglib's wrap/io_trimesh exporters (both deterministic: fixed STL header,
// printf with a fixed precision for OFF).
#include "formats.h"
#include "io_detail.h"
#include "vcg_mesh.h"

#include <wrap/io_trimesh/export_off.h>
#include <wrap/io_trimesh/export_stl.h>

namespace fieldcvt::io_detail {

namespace {

//! vcglib meshes cannot be copied: fills `m`.
void toVcgMesh(const TriMesh& mesh, VcgMesh& m)
{
    auto vi = vcg::tri::Allocator<VcgMesh>::AddVertices(m, mesh.vertices.size());
    for (const Vec3& p : mesh.vertices) (vi++)->P() = vcg::Point3d(p.x(), p.y(), p.z());
    auto fi = vcg::tri::Allocator<VcgMesh>::AddFaces(m, mesh.faces.size());
    for (const Face& f : mesh.faces) {
        for (int k = 0; k < 3; ++k) fi->V(k) = &m.vert[f[k]];
        ++fi;
    }
}

}  // namespace

void writeOff(const std::string& path, const TriMesh& mesh)
{
    VcgMesh m;
    toVcgMesh(mesh, m);
    using Exporter = vcg::tri::io::ExporterOFF<VcgMesh>;
    if (const int status = Exporter::Save(m, path.c_str(), 0))
        fail(path, std::string("cannot write: ") + Exporter::ErrorMsg(status));
}

void writeStl(const std::string& path, const TriMesh& mesh)
{
    VcgMesh m;
    toVcgMesh(mesh, m);
    using Exporter = vcg::tri::io::ExporterSTL<VcgMesh>;
    if (const int status = Exporter::Save(m, path.c_str(), true))
        fail(path, std::string("cannot write: ") + Exporter::ErrorMsg(status));
}

}  // namespace fieldcvt::io_detail
