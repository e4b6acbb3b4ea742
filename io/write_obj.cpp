// Wavefront OBJ writer: shortest round-trip decimal numbers (std::to_chars), locale-independent
// and byte-deterministic.
#include "io_detail.h"

#include <charconv>

namespace fieldcvt::io_detail {

namespace {

void putNumbers(std::string& out, const char* key, const Vec3& v)
{
    out += key;
    for (int k = 0; k < 3; ++k) {
        char buffer[32];
        const auto result = std::to_chars(buffer, buffer + sizeof buffer, v[k]);
        out += ' ';
        out.append(buffer, result.ptr);
    }
    out += '\n';
}

}  // namespace

void writeObj(const std::string& path, const TriMesh& mesh, const VertexAttributes& attributes)
{
    const bool normals = !attributes.normals.empty();
    std::string out = "# written by fcvt\n";
    for (const Vec3& p : mesh.vertices) putNumbers(out, "v", p);
    if (normals)
        for (const Vec3& n : attributes.normals) putNumbers(out, "vn", n);
    for (const Face& f : mesh.faces) {
        out += 'f';
        for (int k = 0; k < 3; ++k) {
            const std::string index = std::to_string(f[k] + 1);
            out += ' ' + index;
            if (normals) out += "//" + index;  // vertex normals share the vertex numbering
        }
        out += '\n';
    }
    writeFileBytes(path, out);
}

}  // namespace fieldcvt::io_detail
