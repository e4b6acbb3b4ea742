// Binary little-endian PLY written by hand: vcglib's exporter cannot add the custom per-vertex
// properties (rosy_x rosy_y rosy_z) without a vcg attribute plumbing of its own.
#include "formats.h"
#include "io_detail.h"

#include <cstdint>
#include <cstring>

namespace fieldcvt::io_detail {

namespace {

//! Appends the little-endian bytes of a trivially copyable value, whatever the host's order.
template <typename T>
void put(std::string& out, T value)
{
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    const std::uint16_t probe = 1;
    const bool littleEndianHost = *reinterpret_cast<const unsigned char*>(&probe) == 1;
    for (std::size_t i = 0; i < sizeof(T); ++i) out.push_back(static_cast<char>(bytes[littleEndianHost ? i : sizeof(T) - 1 - i]));
}

void putFloats(std::string& out, const Vec3& v)
{
    for (int k = 0; k < 3; ++k) put(out, static_cast<float>(v[k]));
}

}  // namespace

void writePly(const std::string& path, const TriMesh& mesh, const VertexAttributes& attributes, const MeshTexture& texture)
{
    const bool normals = !attributes.normals.empty(), rosy = !attributes.rosy.empty(), textured = !texture.empty();
    const bool texnumber = textured && texture.materials.size() > 1;
    std::string out = "ply\nformat binary_little_endian 1.0\ncomment written by fcvt\n";
    // MeshLab's texture list (texnumber indexes it), written when some image is known.
    bool images = false;
    for (const TextureMaterial& m : texture.materials) images |= !m.image.empty();
    if (textured && images)
        for (const TextureMaterial& m : texture.materials) out += "comment TextureFile " + m.image + "\n";
    out += "element vertex " + std::to_string(mesh.vertexCount()) + "\n";
    // Coordinates in double: the core computes in double and a round trip must not move them.
    out += "property double x\nproperty double y\nproperty double z\n";
    if (normals) out += "property float nx\nproperty float ny\nproperty float nz\n";
    if (rosy) out += "property float rosy_x\nproperty float rosy_y\nproperty float rosy_z\n";
    out += "element face " + std::to_string(mesh.faceCount()) + "\n";
    out += "property list uchar int vertex_indices\n";
    const bool faceValues = !attributes.faceValues.empty();
    if (faceValues) out += "property float " + (attributes.faceProperty.empty() ? "quality" : attributes.faceProperty) + "\n";
    if (textured) out += "property list uchar float texcoord\n";
    if (texnumber) out += "property int texnumber\n";
    out += "end_header\n";
    for (int v = 0; v < mesh.vertexCount(); ++v) {
        for (int k = 0; k < 3; ++k) put(out, mesh.vertices[v][k]);
        if (normals) putFloats(out, attributes.normals[v]);
        if (rosy) putFloats(out, attributes.rosy[v]);
    }
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        put(out, std::uint8_t{3});
        for (int k = 0; k < 3; ++k) put(out, std::int32_t{mesh.faces[f][k]});
        if (faceValues) put(out, static_cast<float>(attributes.faceValues[f]));
        if (textured) {
            put(out, std::uint8_t{6});
            for (int k = 0; k < 3; ++k)
                for (int c = 0; c < 2; ++c) put(out, static_cast<float>(texture.uv[3 * f + k][c]));
        }
        if (texnumber) put(out, std::int32_t{texture.faceMaterial[f]});
    }
    writeFileBytes(path, out);
}

}  // namespace fieldcvt::io_detail
