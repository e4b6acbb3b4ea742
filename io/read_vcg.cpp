// PLY and STL through vcglib's wrap/io_trimesh importers, with the checks vcglib 2020.09 lacks
// done before the call (STL) and memory exhaustion from a lying header turned into an IOError.
#include "io_detail.h"
#include "vcg_mesh.h"

#include <wrap/io_trimesh/import_ply.h>
#include <wrap/io_trimesh/import_stl.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>
#include <new>

namespace fieldcvt::io_detail {

namespace {

//! Copies vcglib's mesh; `merge` welds vertices at identical positions (STL repeats them per
//! triangle), keeping the first occurrence's order so the result is deterministic.
TriMesh toTriMesh(const VcgMesh& m, bool merge, int* merged = nullptr)
{
    TriMesh mesh;
    std::vector<int> index(m.vert.size(), -1);
    // Keyed by bit pattern: well ordered even for NaN (which the core reports); +0.0 adds fold -0.
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
        if (merge) {
            const auto [it, inserted] = seen.emplace(std::array<std::uint64_t, 3>{bits(p[0]), bits(p[1]), bits(p[2])}, mesh.vertexCount());
            index[i] = it->second;
            if (!inserted) continue;
        } else {
            index[i] = mesh.vertexCount();
        }
        mesh.vertices.emplace_back(p[0], p[1], p[2]);
    }
    for (const VcgFace& f : m.face) {
        if (f.IsD()) continue;
        Face face;
        for (int k = 0; k < 3; ++k) face[k] = index[vcg::tri::Index(m, f.cV(k))];
        mesh.faces.push_back(face);
    }
    if (merged) *merged = static_cast<int>(m.vert.size()) - mesh.vertexCount();
    return mesh;
}

//! vcglib marks the first triangle of each fan-triangulated polygon with only faux edge 2.
int countTriangulatedPolygons(const VcgMesh& m)
{
    int polygons = 0;
    for (const VcgFace& f : m.face)
        if (!f.IsD() && f.IsF(2) && !f.IsF(0)) ++polygons;
    return polygons;
}

bool hasNewline(const std::string& bytes) { return bytes.find('\n') != std::string::npos; }

}  // namespace

TriMesh readPly(const std::string& path, MeshReadInfo& info)
{
    checkPlySize(path, std::filesystem::file_size(path));
    using Importer = vcg::tri::io::ImporterPLY<VcgMesh>;
    VcgMesh m;
    int mask = 0;
    int status = 0;
    try {
        status = Importer::Open(m, path.c_str(), mask);
    } catch (const std::bad_alloc&) {
        fail(path, "PLY header announces more elements than memory can hold (corrupt file?)");
    }
    if (status != 0 && Importer::ErrorCritical(status)) fail(path, std::string("invalid PLY file: ") + Importer::ErrorMsg(status));
    info.polygonsTriangulated += countTriangulatedPolygons(m);
    return toTriMesh(m, false);
}

TriMesh readStl(const std::string& path, const std::string& bytes, MeshReadInfo& info)
{
    // vcglib decides binary vs ASCII from the size; check that decision leads somewhere safe:
    // a binary file must have exactly the size its triangle count gives (else vcglib reads past
    // the end), an ASCII one must have a line end (else vcglib loops forever skipping line 1).
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
    int mask = 0;
    int status = 0;
    try {
        status = Importer::Open(m, path.c_str(), mask);
    } catch (const std::bad_alloc&) {
        fail(path, "not enough memory to read this STL file");
    }
    if (status != Importer::E_NOERROR) fail(path, std::string("invalid STL file: ") + Importer::ErrorMsg(status));
    int merged = 0;
    TriMesh mesh = toTriMesh(m, true, &merged);
    if (merged > 0) info.notes.push_back("merged " + std::to_string(merged) + " duplicate STL vertices");
    return mesh;
}

}  // namespace fieldcvt::io_detail
