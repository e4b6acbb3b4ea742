// libFuzzer target: fieldcvt::readMesh on arbitrary bytes. The first byte picks the extension
// (.ply, .obj, .off, .stl, upper/lower case), the rest is the file. Reading must either return
// a mesh whose indices are in range, or throw fieldcvt::Error (IOError); any other exception,
// crash, leak or sanitizer report is a finding.
#include "errors.h"
#include "mesh_io.h"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace {

std::string tempPath(const char* extension)
{
    static const std::string base = "/tmp/fcvt-fuzz-read-" + std::to_string(getpid());
    return base + extension;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size < 1) return 0;
    static const char* const extensions[] = {".ply", ".obj", ".off", ".stl", ".PLY", ".OBJ", ".OFF", ".STL"};
    const std::string path = tempPath(extensions[data[0] % 8]);
    {
        std::FILE* f = std::fopen(path.c_str(), "wb");
        if (!f) return 0;
        if (size > 1) std::fwrite(data + 1, 1, size - 1, f);
        std::fclose(f);
    }
    try {
        fieldcvt::MeshReadInfo info;
        fieldcvt::MeshTexture texture;  // the texture readers too, on every other input
        const bool textured = (data[0] / 8) % 2 == 1;
        const fieldcvt::TriMesh mesh = fieldcvt::readMesh(path, &info, nullptr, textured ? &texture : nullptr);
        for (const fieldcvt::Face& t : mesh.faces)
            for (int c : t)
                if (c < 0 || c >= mesh.vertexCount()) __builtin_trap();  // readMesh promised valid indices
        if (!texture.empty() && !fieldcvt::textureProblem(mesh, texture).empty()) __builtin_trap();  // and a fitting texture
    } catch (const fieldcvt::Error&) {
        // A clear refusal: the documented outcome for a bad file.
    }
    std::remove(path.c_str());
    return 0;
}
