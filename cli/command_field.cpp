// `fcvt field IN OUT.ply [--field F] [--seed S]`: the 6-RoSy field of a mesh, written as PLY
// vertex properties, with its singularities (index sum = 6 chi on a closed surface).
#include "cli_common.h"
#include "commands.h"

#include "errors.h"
#include "field.h"
#include "field_of_input.h"
#include "mesh_check.h"
#include "mesh_io.h"
#include "metrics.h"

#include <chrono>
#include <cstdio>
#include <string>

namespace fieldcvt::cli {

namespace {

void printUsage()
{
    const FieldParams defaults;
    std::printf(
        "Usage: fcvt field IN OUT.ply [--field F] [--seed S] [--quiet]\n"
        "\n"
        "Computes the 6-RoSy direction field of the triangle mesh IN (checked and repaired as\n"
        "'fcvt remesh' does, each repair printed as a warning) and writes that mesh to OUT.ply\n"
        "with the per-vertex properties nx ny nz (unit normal) and rosy_x rosy_y rosy_z\n"
        "(unit representative direction; the six field directions are it turned by k * 60 deg).\n"
        "Prints the singularity count, the sum of their indices (in sixths of a turn) and the\n"
        "Euler characteristic chi = V - E + F: on a closed surface the index sum is 6 * chi.\n"
        "\n"
        "Options:\n"
        "  --field F     extrinsic (smooth, Instant Meshes), curvature-max, curvature-min, or user\n"
        "                (IN's PLY properties rosy_x rosy_y rosy_z, projected) (default %s)\n"
        "  --seed S      seed of the random initial directions, >= 0 (default %llu)\n"
        "  --quiet       print nothing but errors\n"
        "  -h, --help    show this help\n",
        fieldSourceName(defaults.source).c_str(), static_cast<unsigned long long>(defaults.seed));
}

}  // namespace

int runField(const std::vector<std::string>& args)
{
    const Arguments a(args, fieldOptionNames().valued, fieldOptionNames().flags);
    if (printedHelp(a, printUsage)) return 0;
    const auto [inPath, outPath] = inputAndOutput(a, "field");
    const FieldParams params = fieldParams(a);
    const bool quiet = a.flag("quiet");
    if (!isPlyPath(outPath))
        throw UsageError("field writes a .ply file (the only format with the field's vertex properties), got '" + outPath + "'");
    if (params.source == FieldSource::User && !isPlyPath(inPath))
        throw UsageError("--field user takes the field from the input's PLY vertex properties rosy_x rosy_y rosy_z; " + inPath +
                         " is not a .ply file");
    checkOutputPath(outPath, inPath);

    const auto start = std::chrono::steady_clock::now();
    MeshReadInfo readInfo;
    VertexAttributes inputAttributes;
    const TriMesh input = readMesh(inPath, &readInfo, &inputAttributes);
    std::vector<std::string> warnings;
    for (const std::string& warning : readInfo.warnings) warnings.push_back(inPath + ": " + warning);
    for (const std::string& note : readInfo.notes) warnings.push_back(inPath + ": " + note);

    InputField computed;
    try {
        const std::vector<Vec3>* vectors = params.source == FieldSource::User ? &userField(inPath, inputAttributes) : nullptr;
        computed = fieldOfInput(input, params, vectors);
    } catch (const InvalidInputError& e) {
        throw InvalidInputError(inPath + ": " + e.what());  // say which file the problem is in
    }
    const InputReport& cleaning = computed.report;
    const TriMesh& mesh = computed.clean;
    const DirectionField& field = computed.field;
    for (const std::string& note : cleaning.information) warnings.push_back(inPath + ": " + note);
    for (const std::string& note : cleaning.notes) warnings.push_back(inPath + ": " + note);

    const std::vector<Singularity>& singularities = computed.singularities;
    VertexAttributes attributes;
    attributes.normals = field.normals;
    attributes.rosy = field.directions;
    writeMesh(outPath, mesh, &attributes);

    if (!quiet) {
        for (const std::string& w : warnings) std::fprintf(stderr, "fcvt: warning: %s\n", w.c_str());
        long long indexSum = 0;
        int positive = 0, negative = 0;
        for (const Singularity& s : singularities) {
            indexSum += s.index;
            (s.index > 0 ? positive : negative) += 1;
        }
        const TopologySummary t = computeTopology(mesh);
        const long long chi = static_cast<long long>(t.vertices) - t.edges + t.faces;
        std::printf("%s: %d vertices, %d faces, field %s (seed %llu), %.2f s\n", outPath.c_str(), mesh.vertexCount(),
                    mesh.faceCount(), fieldSourceName(params.source).c_str(), static_cast<unsigned long long>(params.seed),
                    secondsSince(start));
        std::printf("singularities: %zu\n", singularities.size());
        std::printf("positive: %d, negative: %d\n", positive, negative);
        std::printf("index sum: %lld\n", indexSum);
        std::printf("euler characteristic: %lld\n", chi);
        std::printf("6 chi: %lld (genus %d, %d boundary loops; the index sum equals 6 chi on a closed surface)\n", 6 * chi,
                    t.genus, t.boundaryLoops);
    }
    return 0;
}

}  // namespace fieldcvt::cli
