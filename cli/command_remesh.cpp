// `fcvt remesh IN OUT --vertices N ...`: read, remesh with the core, write, summarise, report.
#include "arguments.h"
#include "commands.h"
#include "progress_printer.h"
#include "report.h"

#include "errors.h"
#include "mesh_format.h"
#include "mesh_io.h"
#include "remesh.h"

#include <chrono>
#include <climits>
#include <cstdio>
#include <filesystem>
#include <string>

namespace fieldcvt::cli {

namespace {

void printUsage()
{
    const RemeshParams defaults;
    std::printf(
        "Usage: fcvt remesh IN OUT --vertices N [options]\n"
        "\n"
        "Remeshes the triangle mesh IN into OUT with about N vertices. Formats by extension:\n"
        ".ply (written binary, double coordinates), .obj, .off, .stl.\n"
        "\n"
        "Options:\n"
        "  --vertices N          target vertex count, >= 4 (required)\n"
        "  --lambda L            weight of the field-alignment term, >= 0 (default %g: pure CVT)\n"
        "  --cvt-iterations A    L-BFGS iterations on the CVT energy, >= 0 (default %d)\n"
        "  --fcvt-iterations B   L-BFGS iterations on CVT + lambda * field energy, >= 0 (default %d)\n"
        "  --seed S              seed of the initial sampling, >= 0 (default %llu); same seed, same output\n"
        "  --threads T           OpenMP threads, >= 0 (default %d: all cores); output does not depend on it\n"
        "  --report FILE.json    write a JSON report: counts, metrics, topology, stage times, warnings\n"
        "  --quiet               print nothing but errors\n"
        "  -h, --help            show this help\n",
        defaults.lambda, defaults.cvtIterations, defaults.fcvtIterations,
        static_cast<unsigned long long>(defaults.seed), defaults.threads);
}

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

//! What would make the final write fail, found before the long part rather than after it.
void checkOutputPath(const std::string& path)
{
    checkMeshExtension(path);
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent))
        throw IOError(path + ": cannot write: directory " + parent.string() + " does not exist");
}

RemeshParams paramsFrom(const Arguments& a)
{
    if (!a.has("vertices")) throw UsageError("remesh needs --vertices N (the target vertex count)");
    RemeshParams p;
    p.vertexCount = static_cast<int>(a.integer("vertices", p.vertexCount, 4, INT_MAX));
    p.lambda = a.number("lambda", p.lambda, 0.0);
    p.cvtIterations = static_cast<int>(a.integer("cvt-iterations", p.cvtIterations, 0, INT_MAX));
    p.fcvtIterations = static_cast<int>(a.integer("fcvt-iterations", p.fcvtIterations, 0, INT_MAX));
    p.seed = a.unsignedInteger("seed", p.seed);
    p.threads = static_cast<int>(a.integer("threads", p.threads, 0, 4096));
    return p;
}

nlohmann::ordered_json paramsJson(const RemeshParams& p)
{
    return {{"vertices", p.vertexCount},           {"lambda", p.lambda},
            {"lloyd_iterations", p.lloydIterations}, {"cvt_iterations", p.cvtIterations},
            {"fcvt_iterations", p.fcvtIterations},   {"seed", p.seed},
            {"threads", p.threads}};
}

}  // namespace

int runRemesh(const std::vector<std::string>& args)
{
    const Arguments a(args, {"vertices", "lambda", "cvt-iterations", "fcvt-iterations", "seed", "threads", "report"},
                      {"quiet", "help"});
    if (a.flag("help")) {
        printUsage();
        return 0;
    }
    if (a.positional().size() != 2)
        throw UsageError("remesh needs an input and an output file, got " + std::to_string(a.positional().size()) +
                         " file arguments (try 'fcvt remesh --help')");
    const std::string& inPath = a.positional()[0];
    const std::string& outPath = a.positional()[1];
    const RemeshParams params = paramsFrom(a);
    const bool quiet = a.flag("quiet");
    checkOutputPath(outPath);

    const auto start = std::chrono::steady_clock::now();
    MeshReadInfo readInfo;
    const TriMesh input = readMesh(inPath, &readInfo);
    const double readSeconds = secondsSince(start);

    RemeshResult result;
    {
        ProgressPrinter progress(quiet);
        try {
            result = remesh(input, params, progress.callback());
        } catch (const InvalidInputError& e) {
            throw InvalidInputError(inPath + ": " + e.what());  // say which file the problem is in
        }
    }

    const auto writeStart = std::chrono::steady_clock::now();
    writeMesh(outPath, result.mesh);
    const double writeSeconds = secondsSince(writeStart);

    std::vector<std::string> warnings;
    for (const std::string& note : readInfo.notes) warnings.push_back(inPath + ": " + note);
    warnings.insert(warnings.end(), result.warnings.begin(), result.warnings.end());
    const TopologySummary outputTopology = computeTopology(result.mesh);
    const double totalSeconds = secondsSince(start);

    if (auto reportPath = a.text("report")) {
        nlohmann::ordered_json times = nlohmann::ordered_json::object();
        times["read"] = readSeconds;
        for (const StageTime& stage : result.stageTimes) times[stage.stage] = stage.seconds;
        times["write"] = writeSeconds;
        times["total"] = totalSeconds;
        const nlohmann::ordered_json report = {{"input_file", inPath},
                                       {"output_file", outPath},
                                       {"vertices", result.mesh.vertexCount()},
                                       {"faces", result.mesh.faceCount()},
                                       {"evaluations", result.evaluations},
                                       {"time_s", times},
                                       {"metrics", metricsJson(result.metrics)},
                                       {"input", topologyJson(result.inputTopology)},
                                       {"output", topologyJson(outputTopology)},
                                       {"params", paramsJson(params)},
                                       {"warnings", warnings}};
        writeJsonFile(*reportPath, report);
    }

    if (!quiet) {
        for (const std::string& w : warnings) std::fprintf(stderr, "fcvt: warning: %s\n", w.c_str());
        const QualityMetrics& m = result.metrics;
        std::printf("%s: %d vertices, %d faces, genus %d, %d boundary loops%s; Q_avg %.3f, theta_min %.1f deg, "
                    "V6 %.1f %%, d_H %.3g %% of the diagonal; %d evaluations, %.2f s\n",
                    outPath.c_str(), result.mesh.vertexCount(), result.mesh.faceCount(), outputTopology.genus,
                    outputTopology.boundaryLoops, outputTopology.manifold() ? "" : " (NOT MANIFOLD)", m.qAvg,
                    m.thetaMin, m.v6Pct, 100 * m.dH, result.evaluations, totalSeconds);
    }
    return 0;
}

}  // namespace fieldcvt::cli
