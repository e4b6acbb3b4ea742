// STL: ASCII through vcglib's wrap/io_trimesh importer, with the checks vcglib 2020.09 lacks done
// before the call; binary (a fixed 50-byte record) read here directly.
#include "io_detail.h"
#include "vcg_mesh.h"

#include <wrap/io_trimesh/import_stl.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <new>

namespace fieldcvt::io_detail {

namespace {

//! Maps vcglib vertex slots to TriMesh indices, welding vertices at identical positions (STL
//! repeats them per triangle) and keeping first occurrences in order (deterministic).
std::vector<int> weldVertices(const VcgMesh& m, TriMesh& mesh)
{
    std::vector<int> index(m.vert.size(), -1);
    // Keyed by bit pattern: well ordered even for NaN (which the core reports); +0.0 folds -0.
    std::map<std::array<std::uint64_t, 3>, int> seen;
    auto bits = [](double x) {
        x += 0.0;
        std::uint64_t b;
        std::memcpy(&b, &x, sizeof b);
        return b;
    };
    for (std::size_t i = 0; i < m.vert.size(); ++i) {
        if (m.vert[i].IsD()) continue;
        const auto& p = m.vert[i].cP();
        const auto [it, inserted] = seen.emplace(std::array<std::uint64_t, 3>{bits(p[0]), bits(p[1]), bits(p[2])}, mesh.vertexCount());
        index[i] = it->second;
        if (inserted) mesh.vertices.emplace_back(p[0], p[1], p[2]);
    }
    return index;
}

//! Triangle soup (STL) welded into an indexed mesh; the welding is reported in `info`.
TriMesh toTriMesh(const VcgMesh& m, MeshReadInfo& info)
{
    TriMesh mesh;
    const std::vector<int> index = weldVertices(m, mesh);
    for (const VcgFace& f : m.face)
        if (!f.IsD())
            mesh.faces.push_back({index[vcg::tri::Index(m, f.cV(0))], index[vcg::tri::Index(m, f.cV(1))], index[vcg::tri::Index(m, f.cV(2))]});
    const std::size_t merged = m.vert.size() - mesh.vertices.size();
    if (merged > 0) info.notes.push_back("merged " + std::to_string(merged) + " duplicate STL vertices");
    return mesh;
}

bool hasNewline(const std::string& bytes) { return bytes.find('\n') != std::string::npos; }

//! Binary STL from its bytes (size already checked): vcglib's OpenBinary first runs
//! IsSTLColored, which builds a string from an unterminated 80-byte label (a stack over-read).
void readBinaryStl(const std::string& bytes, VcgMesh& m)
{
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    auto fi = vcg::tri::Allocator<VcgMesh>::AddFaces(m, count);
    auto vi = vcg::tri::Allocator<VcgMesh>::AddVertices(m, std::size_t(count) * 3);
    for (std::uint32_t t = 0; t < count; ++t, ++fi) {
        float corners[9];  // after the 12-byte facet normal, which is recomputed anyway
        std::memcpy(corners, bytes.data() + 84 + 50 * std::size_t(t) + 12, sizeof corners);
        for (int k = 0; k < 3; ++k, ++vi) {
            vi->P() = vcg::Point3d(corners[3 * k], corners[3 * k + 1], corners[3 * k + 2]);
            fi->V(k) = &*vi;
        }
    }
}

}  // namespace

TriMesh readStl(const std::string& path, const std::string& bytes, MeshReadInfo& info)
{
    // We decide binary vs ASCII ourselves: vcglib's IsSTLBinary inspects 4 bytes it never read
    // (uninitialised) and so may call a valid ASCII file malformed. A binary file must have
    // exactly the size its triangle count gives (else vcglib reads past the end), an ASCII one
    // must have a line end (else vcglib loops forever skipping line 1).
    constexpr std::size_t headerSize = 84, facetSize = 50;
    const bool binary = [&] {
        if (bytes.size() < headerSize) return false;
        std::uint32_t count = 0;
        std::memcpy(&count, bytes.data() + 80, 4);
        return bytes.size() == headerSize + facetSize * std::size_t(count);
    }();
    if (!binary) {
        const std::size_t probe = std::min<std::size_t>(bytes.size(), 1080);
        const bool ascii = std::all_of(bytes.begin(), bytes.begin() + probe, [](char c) { return static_cast<unsigned char>(c) < 128; });
        if (!ascii) fail(path, "invalid binary STL file (its size does not match its triangle count: truncated?)");
        if (bytes.compare(0, 5, "solid") != 0 || !hasNewline(bytes)) fail(path, "not an STL file (ASCII STL starts with 'solid')");
    }
    using Importer = vcg::tri::io::ImporterSTL<VcgMesh>;
    VcgMesh m;
    if (binary) {
        readBinaryStl(bytes, m);
    } else if (const int status = Importer::OpenAscii(m, path.c_str()); status != Importer::E_NOERROR) {
        fail(path, std::string("invalid STL file: ") + Importer::ErrorMsg(status));
    }
    return toTriMesh(m, info);
}

}  // namespace fieldcvt::io_detail
