// STL, read here (binary: a fixed 50-byte record; ASCII: a token parser) into a vcglib mesh that
// is then welded. vcglib 2020.09's ASCII importer drops the last facet when the file ends right
// after its "endfacet" (no newline, no "endsolid"), reads coordinates as float and loops forever
// on a file without a line end; its binary one over-reads the label.
#include "errors.h"
#include "formats.h"
#include "io_detail.h"
#include "text_scan.h"
#include "vcg_mesh.h"

#include <vcg/complex/allocate.h>

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
        const auto [it, inserted] =
            seen.emplace(std::array<std::uint64_t, 3>{bits(p[0]), bits(p[1]), bits(p[2])}, mesh.vertexCount());
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
            mesh.faces.push_back(
                {index[vcg::tri::Index(m, f.cV(0))], index[vcg::tri::Index(m, f.cV(1))], index[vcg::tri::Index(m, f.cV(2))]});
    const std::size_t merged = m.vert.size() - mesh.vertices.size();
    if (merged > 0) info.notes.push_back("merged " + std::to_string(merged) + " duplicate STL vertices");
    return mesh;
}

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

//! ASCII STL: "solid NAME", then per facet "facet normal i j k / outer loop / vertex x y z (3
//! times) / endloop / endfacet", then "endsolid NAME" (several solids may follow each other).
//! Every facet is read whole or the file is refused naming its line; a missing final
//! "endsolid" is noted, never a reason to drop a facet.
void readAsciiStl(const std::string& path, const std::string& text, VcgMesh& m, MeshReadInfo& info)
{
    TextScanner scan(path, text);
    std::size_t next = 0;  // the next token of the current line
    bool inSolid = false;
    auto token = [&](const char* expected) -> std::string_view {
        if (next == scan.tokens().size()) {
            if (!scan.nextLine())
                fail(path, std::string("unexpected end of file: expected '") + expected + "' in facet " +
                               std::to_string(m.face.size() + 1));
            next = 0;
        }
        return scan.tokens()[next++];
    };
    auto keyword = [&](const char* expected) {
        const std::string_view t = token(expected);
        if (t != expected) scan.fail("expected '" + std::string(expected) + "', found " + quoteInput(t));
    };
    for (;;) {
        if (next == scan.tokens().size()) {
            if (!scan.nextLine()) break;
            next = 0;
        }
        const std::string_view t = scan.tokens()[next++];
        if (t == "solid" || t == "endsolid") {  // the rest of the line is the solid's name
            inSolid = t == "solid";
            next = scan.tokens().size();
            continue;
        }
        if (t != "facet") scan.fail("expected 'facet' or 'endsolid', found " + quoteInput(t));
        if (!inSolid) scan.fail("'facet' outside a solid");
        keyword("normal");
        for (int k = 0; k < 3; ++k) token("the facet normal");  // recomputed anyway
        keyword("outer");
        keyword("loop");
        vcg::Point3d corner[3];
        for (int c = 0; c < 3; ++c) {
            keyword("vertex");
            for (int k = 0; k < 3; ++k) corner[c][k] = scan.number(token("a vertex coordinate"));
        }
        keyword("endloop");
        keyword("endfacet");
        auto fi = vcg::tri::Allocator<VcgMesh>::AddFaces(m, 1);
        auto vi = vcg::tri::Allocator<VcgMesh>::AddVertices(m, 3);
        for (int c = 0; c < 3; ++c, ++vi) {
            vi->P() = corner[c];
            fi->V(c) = &*vi;
        }
    }
    if (inSolid)
        info.warnings.push_back("ASCII STL ends without 'endsolid' (truncated?); its " + std::to_string(m.face.size()) +
                                " complete facets were read");
}

}  // namespace

TriMesh readStl(const std::string& path, const std::string& bytes, MeshReadInfo& info)
{
    // We decide binary vs ASCII ourselves: vcglib's IsSTLBinary inspects 4 bytes it never read
    // (uninitialised) and so may call a valid ASCII file malformed. A binary file must have
    // exactly the size its triangle count gives.
    constexpr std::size_t headerSize = 84, facetSize = 50;
    const bool binary = [&] {
        if (bytes.size() < headerSize) return false;
        std::uint32_t count = 0;
        std::memcpy(&count, bytes.data() + 80, 4);
        return bytes.size() == headerSize + facetSize * std::size_t(count);
    }();
    if (!binary) {
        const std::size_t start = byteOrderMarkLength(bytes), probe = std::min<std::size_t>(bytes.size(), 1080);
        const bool ascii = std::all_of(bytes.begin() + start, bytes.begin() + std::max(start, probe),
                                       [](char c) { return static_cast<unsigned char>(c) < 128; });
        if (!ascii) fail(path, "invalid binary STL file (its size does not match its triangle count: truncated?)");
        if (bytes.compare(start, 5, "solid") != 0) fail(path, "not an STL file (ASCII STL starts with 'solid')");
    }
    VcgMesh m;
    if (binary)
        readBinaryStl(bytes, m);
    else
        readAsciiStl(path, bytes, m, info);
    return toTriMesh(m, info);
}

}  // namespace fieldcvt::io_detail
