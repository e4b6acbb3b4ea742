// The helpers every format shares (io_detail.h).
#include "io_detail.h"

#include "errors.h"
#include "side_files.h"
#include "triangulate.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fieldcvt::io_detail {

void fail(const std::string& path, const std::string& what) { throw IOError(path + ": " + what); }

std::string readFileBytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, std::string("cannot open: ") + std::strerror(errno));
    // A regular file is read in one go into a string of its size (a growing string buffer
    // copied the 2.4 MB bunny.obj several times: a third of its 28 ms read); anything whose size
    // is not known up front (a pipe) through the stream buffer.
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size >= 0 && in) {
        std::string bytes(static_cast<size_t>(size), '\0');
        in.seekg(0, std::ios::beg);
        if (size > 0) in.read(bytes.data(), size);
        if (in.gcount() == size && !in.bad()) {
            // Nothing beyond the size seen (a file that grew meanwhile reads as it was then).
            return bytes;
        }
        in.clear();
        in.seekg(0, std::ios::beg);
    } else {
        in.clear();
    }
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) fail(path, "read error");
    return buffer.str();
}

void addPolygon(TriMesh& mesh, const std::vector<int>& polygon, MeshReadInfo& info)
{
    if (triangulatePolygon(mesh.vertices, polygon, mesh.faces) == PolygonShape::NotSimple) ++info.polygonsNotSimple;
    if (polygon.size() > 3) ++info.polygonsTriangulated;
}

void appendCornerTexture(const TriMesh& mesh, std::size_t firstFace, const std::vector<int>& polygon,
                         const std::vector<Vec2>& polygonUv, int material, MeshTexture& texture)
{
    for (std::size_t f = firstFace; f < mesh.faces.size(); ++f) {
        for (int v : mesh.faces[f]) {
            // A triangle of the polygon's triangulation: its corner's coordinates by position.
            const auto j = static_cast<std::size_t>(std::find(polygon.begin(), polygon.end(), v) - polygon.begin());
            texture.uv.push_back(j < polygonUv.size() ? polygonUv[j] : Vec2(NAN, NAN));
        }
        texture.faceMaterial.push_back(material);
    }
}

bool replacedOnWrite(const std::string& path)
{
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::symlink_status(path, ec);
    return !std::filesystem::exists(status) || std::filesystem::is_regular_file(status) || std::filesystem::is_symlink(status);
}

void writeFileBytes(const std::string& path, const std::string& bytes)
{
    // A new file renamed into place: a link at `path` is replaced, never written through, and a
    // reader never sees half a mesh. Devices (/dev/null) and FIFOs are written as they are.
    if (replacedOnWrite(path)) {
        writeFileReplacing(path, bytes);
        return;
    }
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) fail(path, std::string("cannot write: ") + std::strerror(errno));
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) fail(path, "write error (disk full?)");
}

}  // namespace fieldcvt::io_detail
