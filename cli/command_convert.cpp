// `fcvt convert IN OUT`: a mesh file in another format (PLY, OBJ, OFF, STL, by extension), after
// the input checks `fcvt remesh` makes; e.g. an OBJ that MeshLab 2020.09's importer aborts on,
// turned into a PLY it opens. A non-manifold or non-orientable surface is written as read with a
// warning (a converter converts what it can read, as MeshLab does); --strict refuses it.
#include "cli_common.h"
#include "commands.h"
#include "texture_files.h"

#include "errors.h"
#include "mesh_check.h"
#include "mesh_io.h"
#include "repair.h"

#include <cstdio>
#include <string>
#include <vector>

namespace fieldcvt::cli {

namespace {

void printUsage()
{
    std::printf(
        "Usage: fcvt convert IN OUT [--quiet] [--strict] [--overwrite]\n"
        "\n"
        "Writes the triangle mesh IN to OUT, each in the format of its extension (.ply written\n"
        "binary, .obj, .off, .stl). IN is read and checked as 'fcvt remesh' reads and checks it: an\n"
        "empty file, a point cloud, a bad index or a non-finite coordinate is an error; polygons are\n"
        "triangulated. What remesh would repair (duplicate or unreferenced vertices, degenerate or\n"
        "duplicate faces, orientation, non-manifold vertices) is printed as a warning and written as\n"
        "it is: OUT holds IN's vertices and faces, in IN's order. So is a surface with non-manifold\n"
        "edges or a non-orientable part, with one warning line (remesh repairs both; --strict refuses\n"
        "them, as remesh --no-repair does). A PLY IN's normals (nx ny nz) and field (rosy_x rosy_y\n"
        "rosy_z) go to a PLY OUT; IN's texture coordinates (OBJ vt, PLY texcoord) go to an OBJ or PLY\n"
        "OUT with the materials' image names (an OBJ OUT gets its own OUT.mtl, with IN's materials).\n"
        "\n"
        "Options:\n"
        "  --quiet       print nothing but errors and the warnings on OUT itself (the reader's, the\n"
        "                texture's, a non-manifold or non-orientable surface)\n"
        "  --strict      refuse a non-manifold edge or a non-orientable surface (exit 1)\n"
        "  --overwrite   let OUT.mtl replace an existing file of that name (by default the new one\n"
        "                is numbered, OUT_2.mtl, with a warning); IN's own files are never written\n"
        "  -h, --help    show this help\n");
}

//! The one warning on a surface the strict check refuses (SurfaceTopologyError): what remesh's
//! repair would split or cut, counted as it counts them without welding (the strict check's
//! view: exact duplicates merged only); the check's own message if the repair finds nothing.
std::string surfaceSummary(const std::string& inPath, const TriMesh& input, const std::string& refusal)
{
    RepairParams params;
    params.weldTolerance = 0;
    RepairReport repair;
    repairMesh(input, params, repair);
    const auto counted = [](int n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); };
    std::string found;
    if (repair.nonManifoldEdges > 0) found = counted(repair.nonManifoldEdges, "non-manifold edge", "non-manifold edges");
    if (repair.nonOrientableComponents > 0)
        found += (found.empty() ? "" : " and ") +
                 counted(repair.nonOrientableComponents, "non-orientable component", "non-orientable components");
    if (found.empty()) found = refusal;
    const bool one = repair.nonManifoldEdges + repair.nonOrientableComponents <= 1;
    return inPath + ": " + found + ", written as read (remesh repairs " + (one ? "it" : "them") + "; --strict refuses)";
}

}  // namespace

int runConvert(const std::vector<std::string>& args)
{
    const Arguments a(args, {}, {"quiet", "help", "strict", "overwrite"});
    if (printedHelp(a, printUsage)) return 0;
    const auto [inPath, outPath] = inputAndOutput(a, "convert");
    const bool quiet = a.flag("quiet");
    checkOutputPath(outPath, inPath);

    MeshReadInfo readInfo;
    VertexAttributes attributes;
    MeshTexture texture;
    const TriMesh input = readMesh(inPath, &readInfo, &attributes, &texture);
    InputReport check;
    std::string surfaceWarning;
    try {
        prepareInput(input, check);
    } catch (const SurfaceTopologyError& e) {
        if (a.flag("strict")) throw InvalidInputError(inPath + ": " + e.what());
        surfaceWarning = surfaceSummary(inPath, input, e.what());
    } catch (const InvalidInputError& e) {
        throw InvalidInputError(inPath + ": " + e.what());  // say which file the problem is in
    }
    const bool keepAttributes = isPlyPath(outPath) && (attributes.normals.size() == input.vertices.size() ||
                                                       attributes.rosy.size() == input.vertices.size());
    if (attributes.normals.size() != input.vertices.size()) attributes.normals.clear();
    if (attributes.rosy.size() != input.vertices.size()) attributes.rosy.clear();
    const bool keepTexture =
        !texture.empty() && (isPlyPath(outPath) || isObjPath(outPath)) && textureProblem(input, texture).empty();
    std::vector<std::string> textureWarnings;
    if (keepTexture) {
        SideFileNames names(a.flag("overwrite"));
        names.reserve(outPath);
        const std::vector<MaterialLibrary> libraries = lookUpMaterialImages(texture, inPath, textureWarnings);
        protectInputFiles(texture, libraries, inPath, names);
        placeTextureFiles(texture, libraries, inPath, outPath, names, textureWarnings);
    }
    writeMesh(outPath, input, keepAttributes ? &attributes : nullptr, keepTexture ? &texture : nullptr);

    // What makes the mesh differ from the file is said even with --quiet, and so is a surface
    // that is no manifold: what the check refused before, written now.
    if (!surfaceWarning.empty()) std::fprintf(stderr, "fcvt: warning: %s\n", escapeControlCharacters(surfaceWarning).c_str());
    for (const std::string& warning : readInfo.warnings)
        std::fprintf(stderr, "fcvt: warning: %s: %s\n", inPath.c_str(), warning.c_str());
    for (const std::string& warning : textureWarnings) std::fprintf(stderr, "fcvt: warning: %s\n", warning.c_str());
    if (!quiet) {
        for (const std::string& note : readInfo.notes)
            std::fprintf(stderr, "fcvt: warning: %s: %s\n", inPath.c_str(), note.c_str());
        std::vector<std::string> checkLines = check.information;
        checkLines.insert(checkLines.end(), check.notes.begin(), check.notes.end());
        for (const std::string& note : checkLines)
            std::fprintf(stderr, "fcvt: warning: %s: not repaired, convert writes the mesh as read (remesh would have: %s)\n",
                         inPath.c_str(), note.c_str());
        std::printf("%s: %d vertices, %d faces (from %s)\n", outPath.c_str(), input.vertexCount(), input.faceCount(),
                    inPath.c_str());
    }
    return 0;
}

}  // namespace fieldcvt::cli
