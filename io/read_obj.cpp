// A tolerant Wavefront OBJ reader of our own: MeshLab 2020.09's vcglib importer aborts on files
// with `f a//n` corners, normals and CRLF line ends, which are common in the wild.
#include "errors.h"
#include "io_detail.h"
#include "text_scan.h"

#include <limits>

namespace fieldcvt::io_detail {

namespace {

//! The vertex of one face corner `a`, `a/t`, `a//n` or `a/t/n`: 1-based, or negative = relative
//! to the vertices read so far. Returns the 0-based index, or fails naming the line.
int cornerVertex(const TextScanner& scan, std::string_view corner, int vertexCount)
{
    const long long raw = scan.integer(corner.substr(0, corner.find('/')));
    const long long index = raw < 0 ? vertexCount + raw : raw - 1;
    if (raw == 0 || index < 0 || index >= vertexCount)
        scan.fail("face corner " + quoteInput(corner) + " refers to a vertex that does not exist (" +
                  std::to_string(vertexCount) + " vertices so far)");
    return static_cast<int>(index);
}

}  // namespace

TriMesh readObj(const std::string& path, const std::string& text, MeshReadInfo& info)
{
    TriMesh mesh;
    TextScanner scan(path, text, true);  // a line ending in a backslash goes on
    std::vector<int> polygon;
    while (scan.nextLine()) {
        const auto& t = scan.tokens();
        if (t[0] == "v") {
            if (t.size() < 4) scan.fail("vertex with fewer than 3 coordinates");
            mesh.vertices.emplace_back(scan.number(t[1]), scan.number(t[2]), scan.number(t[3]));
            if (mesh.vertices.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) scan.fail("too many vertices");
        } else if (t[0] == "f") {
            if (t.size() < 4) scan.fail("face with fewer than 3 corners");
            polygon.clear();
            for (std::size_t i = 1; i < t.size(); ++i) polygon.push_back(cornerVertex(scan, t[i], mesh.vertexCount()));
            addPolygon(mesh, polygon, info);
        }
        // vn, vt, g, o, s, usemtl, mtllib, l, p ... carry nothing the remesher uses.
    }
    return mesh;
}

}  // namespace fieldcvt::io_detail
