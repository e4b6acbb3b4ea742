// `fcvt metrics MESH [--ref INPUT] [--json]`: the paper's Table 2 figures of a mesh file.
#include "cli_common.h"
#include "commands.h"
#include "metrics_report.h"

#include "mesh_io.h"
#include "metrics.h"
#include "part_coverage.h"

#include <cmath>
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
        "                (fractions of INPUT's bounding-box diagonal; without it they are null),\n"
        "                and INPUT's parts (components with 0.5 %% of its area or more): parts,\n"
        "                part_gap (largest distance from a part to MESH, in MESH's mean edge\n"
        "                lengths), part_pieces (most components of MESH one part became),\n"
        "                small_parts and small_parts_area_pct (the components under 0.5 %%)\n"
        "  --json        print the metrics as one JSON object (the keys of 'fcvt remesh --report')\n"
        "  -h, --help    show this help\n");
}

void printTable(const std::string& path, const TriMesh& mesh, const nlohmann::ordered_json& metrics, const TopologySummary& t,
                const nlohmann::ordered_json& parts)
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
    for (const auto& [key, value] : parts.items()) {
        if (value.is_null())
            std::printf("%-14s inf\n", key.c_str());
        else
            std::printf("%-14s %.6g\n", key.c_str(), value.get<double>());
    }
}

}  // namespace

int runMetrics(const std::vector<std::string>& args)
{
    const Arguments a(args, {"ref"}, {"json", "help"});
    if (printedHelp(a, printUsage)) return 0;
    const std::string& path = fileArguments(a, 1, "metrics", "exactly one mesh file")[0];
    const TriMesh mesh = readMesh(path);
    TriMesh reference;
    if (auto ref = a.text("ref")) reference = readMesh(*ref);
    const frontend::MeshMeasurement measured = frontend::measureMesh(mesh, a.has("ref") ? &reference : nullptr);
    const nlohmann::ordered_json& metrics = measured.metrics;
    const nlohmann::ordered_json& parts = measured.parts;
    const PartCoverage& coverage = measured.coverage;
    if (a.flag("json")) {
        std::printf("%s\n", measured.json().dump(2).c_str());
    } else {
        printTable(path, mesh, metrics, computeTopology(mesh), parts);
        for (size_t p = 0; p < coverage.parts.size(); ++p)
            std::printf("  part %zu: %.3g %% of the area, gap %.3g edge lengths (at %.6g %.6g %.6g), %d pieces\n", p + 1,
                        100.0 * coverage.parts[p].areaFraction, coverage.parts[p].gap, coverage.parts[p].farthestPoint.x(),
                        coverage.parts[p].farthestPoint.y(), coverage.parts[p].farthestPoint.z(), coverage.parts[p].pieces);
    }
    return 0;
}

}  // namespace fieldcvt::cli
