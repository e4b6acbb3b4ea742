// Wavefront OBJ writer: shortest round-trip decimal numbers (std::to_chars), locale-independent
// and byte-deterministic.
#include "formats.h"
#include "io_detail.h"

#include <charconv>

namespace fieldcvt::io_detail {

namespace {

template <typename Vector>
void putNumbers(std::string& out, const char* key, const Vector& v)
{
    out += key;
    for (int k = 0; k < static_cast<int>(v.size()); ++k) {
        char buffer[32];
        const auto result = std::to_chars(buffer, buffer + sizeof buffer, v[k]);
        out += ' ';
        out.append(buffer, result.ptr);
    }
    out += '\n';
}

}  // namespace

void writeObj(const std::string& path, const TriMesh& mesh, const VertexAttributes& attributes, const MeshTexture& texture)
{
    const bool normals = !attributes.normals.empty(), textured = !texture.empty();
    std::string out = "# written by fcvt\n";
    for (const std::string& library : texture.libraries) out += "mtllib " + library + "\n";
    for (const Vec3& p : mesh.vertices) putNumbers(out, "v", p);
    if (normals)
        for (const Vec3& n : attributes.normals) putNumbers(out, "vn", n);
    for (const Vec2& uv : texture.uv) putNumbers(out, "vt", uv);  // one per corner, in face order
    int material = -1;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        if (textured && texture.faceMaterial[f] != material) {
            material = texture.faceMaterial[f];
            if (!texture.materials[material].name.empty()) out += "usemtl " + texture.materials[material].name + "\n";
        }
        out += 'f';
        for (int k = 0; k < 3; ++k) {
            const std::string index = std::to_string(mesh.faces[f][k] + 1);
            out += ' ' + index;
            if (textured) out += '/' + std::to_string(3 * f + k + 1);
            if (normals) out += (textured ? "/" : "//") + index;  // vertex normals share the vertex numbering
        }
        out += '\n';
    }
    writeFileBytes(path, out);
}

}  // namespace fieldcvt::io_detail
