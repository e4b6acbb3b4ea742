// OFF reader of our own. vcglib 2020.09's ImporterOFF dereferences face indices without a range
// check and reads the first token of an empty line at a truncated end (undefined behaviour, a
// crash at best), so it cannot be given untrusted files.
#include "errors.h"
#include "formats.h"
#include "io_detail.h"
#include "text_scan.h"

#include <algorithm>
#include <limits>

namespace fieldcvt::io_detail {

namespace {

//! Counts from `tokens[first..]`: vertices, faces (edges ignored); fails if absent or negative.
std::pair<long long, long long> readCounts(const TextScanner& scan, std::size_t first)
{
    const auto& t = scan.tokens();
    if (t.size() < first + 2) scan.fail("expected the vertex and face counts");
    const long long nv = scan.integer(t[first]), nf = scan.integer(t[first + 1]);
    if (nv < 0 || nf < 0 || nv > std::numeric_limits<int>::max() || nf > std::numeric_limits<int>::max())
        scan.fail("invalid vertex or face count");
    return {nv, nf};
}

}  // namespace

TriMesh readOff(const std::string& path, const std::string& text, MeshReadInfo& info)
{
    TextScanner scan(path, text);
    // Header keyword: [ST][C][N]OFF; 4OFF / nOFF (other dimensions) and binary OFF are refused.
    if (!scan.nextLine()) fail(path, "empty OFF file");
    const std::string keyword(scan.tokens()[0]);
    if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0)
        scan.fail("not an OFF file (the first word must be OFF, found " + quoteInput(keyword) + ")");
    if (keyword.find_first_of("4n") != std::string::npos) scan.fail(quoteInput(keyword) + " (not 3D) is not supported");
    if (scan.tokens().size() > 1 && scan.tokens()[1] == "BINARY") scan.fail("binary OFF is not supported");
    // Some writers put the counts on the keyword's line.
    const bool countsOnHeader = scan.tokens().size() > 1;
    if (!countsOnHeader && !scan.nextLine()) scan.fail("unexpected end of file: expected the vertex and face counts");
    const auto [nv, nf] = readCounts(scan, countsOnHeader ? 1 : 0);

    TriMesh mesh;
    // A lying header must not make us allocate gigabytes: reserve no more than the text can hold.
    mesh.vertices.reserve(static_cast<std::size_t>(std::min<long long>(nv, text.size() / 6)));
    for (long long i = 0; i < nv; ++i) {
        if (!scan.nextLine())
            fail(path, "unexpected end of file: " + std::to_string(i) + " of " + std::to_string(nv) + " vertices read");
        const auto& t = scan.tokens();
        if (t.size() < 3) scan.fail("vertex with fewer than 3 coordinates");
        // Anything after x y z (normal, colour, texture coordinates) is not used.
        mesh.vertices.emplace_back(scan.number(t[0]), scan.number(t[1]), scan.number(t[2]));
    }
    mesh.faces.reserve(static_cast<std::size_t>(std::min<long long>(nf, text.size() / 8)));
    for (long long f = 0; f < nf; ++f) {
        if (!scan.nextLine())
            fail(path, "unexpected end of file: " + std::to_string(f) + " of " + std::to_string(nf) + " faces read");
        const auto& t = scan.tokens();
        const long long corners = scan.integer(t[0]);
        if (corners < 3) scan.fail("face with " + std::to_string(corners) + " corners");
        if (static_cast<long long>(t.size()) < corners + 1) scan.fail("face with fewer indices than its corner count");
        std::vector<int> polygon;
        for (long long c = 1; c <= corners; ++c) {
            const long long index = scan.integer(t[c]);
            if (index < 0 || index >= nv)
                scan.fail("vertex index " + std::to_string(index) + " out of range (" + std::to_string(nv) + " vertices)");
            polygon.push_back(static_cast<int>(index));
        }
        addPolygon(mesh, polygon, info);  // anything after the indices is a face colour
    }
    return mesh;
}

}  // namespace fieldcvt::io_detail
