// `fcvt metrics MESH [--ref INPUT] [--json]`: the paper's Table 2 figures of a mesh file.
#include "arguments.h"
#include "cli_common.h"
#include "commands.h"
#include "report.h"

#include "mesh_io.h"
#include "metrics.h"

#include <cstdio>
#include <string>

namespace fieldcvt::cli {

namespace {

void printUsage()
{
    std::printf(
        "Usage: fcvt metrics MESH [--ref INPUT] [--json]\n"
        "\n"
        "Prints the quality metrics (Q_min, Q_avg, angles, valence) and the topology of MESH.\n"
        "\n"
        "Options:\n"
        "  --ref INPUT   also measure d_rms and d_h, the RMS and Hausdorff distances to INPUT\n"
        "                (fractions of INPUT's bounding-box diagonal); without it they are null\n"
        "  --json        print the metrics as one JSON object (the keys of 'fcvt remesh --report')\n"
        "  -h, --help    show this help\n");
}

void printTable(const std::string& path, const TriMesh& mesh, const nlohmann::ordered_json& metrics, const TopologySummary& t)
{
    std::printf("%-14s %s\n%-14s %d\n%-14s %d\n", "mesh", path.c_str(), "vertices", mesh.vertexCount(), "faces",
                mesh.faceCount());
    for (const auto& [key, value] : metrics.items()) {
        if (value.is_null())
            std::printf("%-14s n/a\n", key.c_str());
        else
            std::printf("%-14s %.6g\n", key.c_str(), value.get<double>());
    }
    std::printf("%-14s %d\n%-14s %d\n%-14s %d\n%-14s %s\n%-14s %s\n", "genus", t.genus, "boundary_loops", t.boundaryLoops,
                "components", t.components, "manifold", t.manifold() ? "yes" : "no", "orientable", t.orientable ? "yes" : "no");
}

}  // namespace

int runMetrics(const std::vector<std::string>& args)
{
    const Arguments a(args, {"ref"}, {"json", "help"});
    if (a.flag("help")) {
        printUsage();
        return 0;
    }
    const std::string& path = fileArguments(a, 1, "metrics", "exactly one mesh file")[0];
    const TriMesh mesh = readMesh(path);
    QualityMetrics quality = computeQuality(mesh);
    if (auto ref = a.text("ref")) {
        const TriMesh reference = readMesh(*ref);
        const DistanceMetrics d = computeDistance(mesh, reference);
        quality.dRms = d.rms;
        quality.dH = d.hausdorff;
        quality.dBoundary = boundaryDistance(mesh, reference);
    }
    const nlohmann::ordered_json metrics = metricsJson(quality);
    if (a.flag("json"))
        std::printf("%s\n", metrics.dump(2).c_str());
    else
        printTable(path, mesh, metrics, computeTopology(mesh));
    return 0;
}

}  // namespace fieldcvt::cli
