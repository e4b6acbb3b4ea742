// Format dispatch by extension and the checks every format shares.
#include "mesh_io.h"

#include "errors.h"
#include "formats.h"
#include "io_detail.h"
#include "mesh_format.h"
#include "side_files.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace fieldcvt {

namespace {

enum class Format { Ply, Obj, Off, Stl };

Format formatOf(const std::string& path)
{
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".ply") return Format::Ply;
    if (ext == ".obj") return Format::Obj;
    if (ext == ".off") return Format::Off;
    if (ext == ".stl") return Format::Stl;
    io_detail::fail(path, "unknown mesh file extension " + quoteInput(ext) + " (use .ply, .obj, .off or .stl)");
}

std::string describeFileType(std::filesystem::file_type type)
{
    using std::filesystem::file_type;
    switch (type) {
    case file_type::fifo: return "a FIFO (named pipe)";
    case file_type::socket: return "a socket";
    case file_type::character: return "a character device";
    case file_type::block: return "a block device";
    default: return "a special file";
    }
}

//! Missing, directory, unreadable and empty files get their own message before any parser runs.
void checkReadable(const std::string& path)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) io_detail::fail(path, "no such file");
    if (fs::is_directory(status)) io_detail::fail(path, "is a directory, not a mesh file");
    // Opening a FIFO blocks until something writes to it, and a device or socket never ends:
    // only a regular file (also through links) is a mesh file.
    if (!fs::is_regular_file(status))
        io_detail::fail(path, "is " + describeFileType(status.type()) + ", not a regular mesh file");
    if (!std::ifstream(path, std::ios::binary)) io_detail::fail(path, std::string("cannot open: ") + std::strerror(errno));
    if (fs::file_size(path, ec) == 0) io_detail::fail(path, "file is empty");
}

//! Every reader's result must be usable as is by the core: indices in range, some faces.
void checkResult(const std::string& path, const TriMesh& mesh)
{
    if (mesh.faces.empty())
        io_detail::fail(path, "no faces (" + std::to_string(mesh.vertexCount()) + " vertices): not a surface mesh");
    for (const Face& f : mesh.faces)
        for (int v : f)
            if (v < 0 || v >= mesh.vertexCount())
                io_detail::fail(path, "face vertex index " + std::to_string(v) + " out of range");
}

}  // namespace

void checkMeshExtension(const std::string& path) { formatOf(path); }

TriMesh readMesh(const std::string& path, MeshReadInfo* info, VertexAttributes* attributes, MeshTexture* texture)
{
    const Format format = formatOf(path);
    checkReadable(path);
    MeshReadInfo local;
    MeshReadInfo& out = info ? *info : local;
    VertexAttributes localAttributes;
    VertexAttributes& attrs = attributes ? *attributes : localAttributes;
    const std::string faceProperty = attrs.faceProperty;  // the one request the caller makes
    attrs = VertexAttributes{};
    attrs.faceProperty = faceProperty;
    if (!faceProperty.empty() && format != Format::Ply)
        io_detail::fail(path, "face property " + quoteInput(faceProperty) + " can only be read from a PLY file");
    if (texture) *texture = MeshTexture{};
    TriMesh mesh;
    switch (format) {
    case Format::Ply: mesh = io_detail::readPly(path, io_detail::readFileBytes(path), out, attrs, texture); break;
    case Format::Obj: mesh = io_detail::readObj(path, io_detail::readFileBytes(path), out, texture); break;
    case Format::Off: mesh = io_detail::readOff(path, io_detail::readFileBytes(path), out); break;
    case Format::Stl: mesh = io_detail::readStl(path, io_detail::readFileBytes(path), out); break;
    }
    checkResult(path, mesh);
    if (!faceProperty.empty() && attrs.faceValues.size() != mesh.faces.size())
        io_detail::fail(path, "face property " + quoteInput(faceProperty) + " not given for every face");
    if (texture && !texture->empty()) {
        if (const std::string problem = textureProblem(mesh, *texture); !problem.empty()) {
            out.warnings.push_back("texture coordinates dropped: " + problem);
            *texture = MeshTexture{};
        }
    }
    for (auto* a : {&attrs.normals, &attrs.rosy})
        if (!a->empty() && a->size() != mesh.vertices.size()) {
            a->clear();  // e.g. several vertex elements, not all with the properties
            out.notes.push_back("per-vertex properties not given for every vertex: ignored");
        }
    if (out.polygonsTriangulated > 0)
        out.notes.push_back("triangulated " + std::to_string(out.polygonsTriangulated) + " polygons");
    if (out.polygonsNotSimple > 0)
        out.warnings.push_back(
            std::to_string(out.polygonsNotSimple) + " polygons are not simple (their edges cross or touch, " +
            "or their corners are on one line): triangulated as well as possible, their triangles may overlap");
    return mesh;
}

void writeMesh(const std::string& path, const TriMesh& mesh, const VertexAttributes* attributes, const MeshTexture* texture)
{
    const MeshTexture noTexture;
    const MeshTexture& tex = texture ? *texture : noTexture;
    if (!tex.empty())
        if (const std::string problem = textureProblem(mesh, tex); !problem.empty()) io_detail::fail(path, problem);
    const Format format = formatOf(path);
    const VertexAttributes none;
    const VertexAttributes& attrs = attributes ? *attributes : none;
    for (const auto* a : {&attrs.normals, &attrs.rosy})
        if (!a->empty() && a->size() != mesh.vertices.size())
            io_detail::fail(path, "vertex attribute count " + std::to_string(a->size()) + " does not match the " +
                                      std::to_string(mesh.vertexCount()) + " vertices");
    if (!attrs.faceValues.empty() && attrs.faceValues.size() != mesh.faces.size())
        io_detail::fail(path, "face value count " + std::to_string(attrs.faceValues.size()) + " does not match the " +
                                  std::to_string(mesh.faceCount()) + " faces");
    switch (format) {
    case Format::Ply: io_detail::writePly(path, mesh, attrs, tex); break;
    case Format::Obj: io_detail::writeObj(path, mesh, attrs, tex); break;
    case Format::Off:
    case Format::Stl: {
        // vcglib's exporters take a file name: they write a temporary one, renamed into place.
        const auto write = [&](const std::string& file) {
            format == Format::Off ? io_detail::writeOff(file, mesh) : io_detail::writeStl(file, mesh);
        };
        if (io_detail::replacedOnWrite(path))
            writeFileReplacing(path, write);
        else
            write(path);
        break;
    }
    }
}

}  // namespace fieldcvt
