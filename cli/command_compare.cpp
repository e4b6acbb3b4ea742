// `fcvt compare IN --vertices N`: CVT and FCVT on the same input with the same seed, and MeshLab's
// built-in isotropic remeshing when a meshlabserver is found, one row per method in the layout of
// the paper's Table 2.
#include "cli_common.h"
#include "commands.h"
#include "progress_printer.h"

#include "meshlab_isotropic.h"

#include "errors.h"
#include "mesh_check.h"
#include "mesh_io.h"
#include "remesh.h"

#include <algorithm>
#include <chrono>
#include <cctype>
#include <climits>
#include <optional>
#include <cmath>
#include <cstdio>
#include <string>

namespace fieldcvt::cli {

namespace {

//! The pure CVT of the comparison (paper §5: 130 L-BFGS iterations, no field term), after the 30
//! Lloyd steps it always had (RemeshParams::lloydIterations is 10 for the short FCVT schedule).
RemeshParams cvtParams(RemeshParams p)
{
    p.lloydIterations = 30;
    p.lambda = 0;
    p.cvtIterations = 130;
    p.fcvtIterations = 0;
    p.valenceOptimization = false;
    return p;
}

//! Iterations of MeshLab's isotropic remeshing (its GUI default is 3; 10 is what issue 7 compares
//! against).
constexpr int kMeshlabIterations = 10;

void printUsage()
{
    const RemeshParams fcvt;
    const RemeshParams cvt = cvtParams(fcvt);
    std::printf(
        "Usage: fcvt compare IN --vertices N [--seed S] [--lambda L] [--field F] [--threads T] [--no-valence]\n"
        "                    [--no-meshlab] [--meshlabserver PATH] [--meshlab-iterations K] [--save PREFIX]\n"
        "                    [--json] [--quiet]\n"
        "\n"
        "Remeshes IN with each method and prints one row per method in the layout of the paper's\n"
        "Table 2:\n"
        "  CVT                lambda = %g, %d CVT iterations, %d FCVT iterations, no valence optimisation\n"
        "  FCVT               lambda = %g (or --lambda), %d CVT iterations, then %d FCVT iterations,\n"
        "                     valence optimisation (the defaults of 'fcvt remesh')\n"
        "  meshlab-isotropic  MeshLab's 'Remeshing: Isotropic Explicit Remeshing' (MeshLab's defaults,\n"
        "                     K iterations) through meshlabserver, TargetLen matched to N vertices\n"
        "                     (rescaled and rerun while the count is off by > 5 %%, at most 3 runs);\n"
        "                     only when a meshlabserver is found (--meshlabserver, $FCVT_MESHLABSERVER\n"
        "                     or PATH); run under xvfb-run -a when DISPLAY is unset\n"
        "CVT and FCVT use the same seed.\n"
        "Columns: |X| vertices, |t| triangles, Q_min, Q_avg, theta_min, mean theta_min, theta_max\n"
        "(degrees), %%<30 and %%>90 (%% of triangles with an angle below 30 / above 90 degrees), V6%%\n"
        "(interior vertices of valence 6), d_RMS (x 1e-3) and d_H (x 1e-2) (fractions of IN's\n"
        "bounding-box diagonal), seconds (the remeshing, without measuring the metrics; for\n"
        "meshlab-isotropic the whole last meshlabserver run, start-up and file I/O included).\n"
        "\n"
        "Options:\n"
        "  --vertices N   target vertex count, %s (required)\n"
        "  --seed S       seed of the sampling and the field, >= 0 (default %llu)\n"
        "  --lambda L     the FCVT row's weight of the field term, >= 0 (default %g)\n"
        "  --field F      the FCVT row's field: extrinsic, curvature-max, curvature-min or user\n"
        "                 (default %s)\n"
        "  --threads T    OpenMP threads, >= 0 (default %d: all cores)\n"
        "  --no-valence   the FCVT row without valence optimisation (the paper's FCVT of Table 2)\n"
        "  --no-meshlab   no meshlab-isotropic row, even when meshlabserver is available\n"
        "  --meshlabserver PATH  the meshlabserver to run (an error if it is not executable)\n"
        "  --meshlab-iterations K  iterations of the built-in remeshing, 1..1000 (default %d)\n"
        "  --save PREFIX  also write each row's mesh to PREFIX-cvt.ply, PREFIX-fcvt.ply,\n"
        "                 PREFIX-meshlab-isotropic.ply\n"
        "  --json         print the rows as a JSON array (metrics keys of 'fcvt metrics --json';\n"
        "                 d_rms and d_h unscaled)\n"
        "  --quiet        no progress output\n"
        "  -h, --help     show this help\n",
        cvt.lambda, cvt.cvtIterations, cvt.fcvtIterations, fcvt.lambda, fcvt.cvtIterations, fcvt.fcvtIterations,
        vertexCountRange().c_str(), static_cast<unsigned long long>(fcvt.seed), fcvt.lambda,
        fieldSourceName(fcvt.fieldSource).c_str(), fcvt.threads, kMeshlabIterations);
}

struct Row {
    std::string method;
    RemeshParams params;
    RemeshResult result;
    double seconds = 0;
    bool meshlab = false;  //!< the meshlab-isotropic row (params unused)
    IsotropicRun isotropic;
};

//! The run's time without the metrics stage (distances on dense samples are not remeshing).
double remeshSeconds(const RemeshResult& r)
{
    double seconds = r.totalSeconds;
    for (const StageTime& s : r.stageTimes)
        if (s.stage == "metrics") seconds -= s.seconds;
    return seconds;
}

void printTable(const std::vector<Row>& rows)
{
    std::printf("%-17s %7s %7s %6s %6s %6s %6s %6s %6s %6s %6s %11s %9s %8s\n", "method", "|X|", "|t|", "Q_min", "Q_avg",
                "th_min", "th_avg", "th_max", "%<30", "%>90", "V6%", "d_RMS(1e-3)", "d_H(1e-2)", "seconds");
    for (const Row& row : rows) {
        const QualityMetrics& m = row.result.metrics;
        std::printf("%-17s %7d %7d %6.3f %6.3f %6.2f %6.2f %6.2f %6.2f %6.2f %6.2f %11.3f %9.3f %8.2f\n", row.method.c_str(),
                    row.result.mesh.vertexCount(), row.result.mesh.faceCount(), m.qMin, m.qAvg, m.thetaMin, m.thetaMinAvg,
                    m.thetaMax, m.pctLt30, m.pctGt90, m.v6Pct, m.dRms * 1e3, m.dH * 1e2, row.seconds);
    }
}

nlohmann::ordered_json rowsJson(const std::vector<Row>& rows)
{
    nlohmann::ordered_json j = nlohmann::ordered_json::array();
    for (const Row& row : rows) {
        nlohmann::ordered_json r = {
            {"method", row.method}, {"vertices", row.result.mesh.vertexCount()}, {"faces", row.result.mesh.faceCount()}};
        const nlohmann::ordered_json metrics = metricsJson(row.result.metrics);
        for (auto it = metrics.cbegin(); it != metrics.cend(); ++it) r[it.key()] = *it;
        r["seconds"] = row.seconds;
        if (row.meshlab) {
            r["target_length"] = row.isotropic.targetLength;
            r["iterations"] = row.isotropic.iterations;
            r["runs"] = row.isotropic.runs;
            r["warnings"] = row.result.warnings;
            j.push_back(r);
            continue;
        }
        r["evaluations"] = row.result.evaluations;
        r["field"] = fieldSourceName(row.params.fieldSource);
        r["lambda"] = row.params.lambda;
        r["cvt_iterations"] = row.params.cvtIterations;
        r["fcvt_iterations"] = row.params.fcvtIterations;
        r["seed"] = row.params.seed;
        r["valence_optimization"] = row.params.valenceOptimization;
        r["v6_before_valence"] = row.result.valence.v6Before;
        r["warnings"] = row.result.warnings;
        j.push_back(r);
    }
    return j;
}

//! The meshlab-isotropic row, or nothing (with a note saying why) when MeshLab's run fails.
std::optional<Row> meshlabRow(const std::string& server, const TriMesh& input, int vertices, int iterations,
                              const Progress& progress, std::vector<std::string>& notes)
{
    if (progress) progress("meshlab-isotropic", 0);
    Row row;
    row.method = "meshlab-isotropic";
    row.meshlab = true;
    try {
        row.isotropic = runMeshlabIsotropic(server, input, vertices, iterations);
        row.result.mesh = row.isotropic.mesh;
        row.result.metrics = computeQuality(row.result.mesh);
        // d_RMS / d_H against the checked input, as remesh() measures the other rows.
        InputReport report;
        const TriMesh reference = prepareInput(input, report);
        const int samples = std::clamp(20 * (row.result.mesh.faceCount() + reference.faceCount()), 20000, 200000);
        const DistanceMetrics d = computeDistance(row.result.mesh, reference, samples);
        row.result.metrics.dRms = d.rms;
        row.result.metrics.dH = d.hausdorff;
        row.result.metrics.dBoundary = boundaryDistance(row.result.mesh, reference);
        row.seconds = row.isotropic.seconds;
        row.result.warnings = row.isotropic.notes;
    } catch (const Error& e) {
        // The CVT and FCVT rows stand on their own: say why the MeshLab row is missing.
        notes.push_back(std::string("no meshlab-isotropic row: ") + e.what());
        return std::nullopt;
    }
    if (progress) progress("meshlab-isotropic", 100);
    return row;
}

}  // namespace

int runCompare(const std::vector<std::string>& args)
{
    const Arguments a(args, {"vertices", "seed", "lambda", "field", "threads", "meshlabserver", "meshlab-iterations", "save"},
                      {"json", "quiet", "help", "no-meshlab", "no-valence"});
    if (printedHelp(a, printUsage)) return 0;
    const std::string& inPath = fileArguments(a, 1, "compare", "exactly one input file")[0];
    if (!a.has("vertices")) throw UsageError("compare needs --vertices N (the target vertex count)");
    RemeshParams fcvt;
    fcvt.vertexCount = a.saturatedInt("vertices", fcvt.vertexCount);
    fcvt.seed = a.unsignedInteger("seed", fcvt.seed);
    fcvt.lambda = a.number("lambda", fcvt.lambda);
    fcvt.fieldSource = fieldOption(a, fcvt.fieldSource, true);
    fcvt.threads = a.saturatedInt("threads", fcvt.threads);
    fcvt.valenceOptimization = !a.flag("no-valence");
    checkOptions(fcvt);
    if (fcvt.fieldSource == FieldSource::User && !isPlyPath(inPath))
        throw UsageError("--field user takes the field from the input's PLY vertex properties rosy_x rosy_y rosy_z; " + inPath +
                         " is not a .ply file");
    const bool quiet = a.flag("quiet");
    const int meshlabIterations = static_cast<int>(a.integer("meshlab-iterations", kMeshlabIterations, 1, 1000));
    if (a.flag("no-meshlab") && (a.has("meshlabserver") || a.has("meshlab-iterations")))
        throw UsageError("--no-meshlab excludes --meshlabserver and --meshlab-iterations");
    std::string server;
    if (!a.flag("no-meshlab")) {
        server = findMeshlabserver(a.text("meshlabserver").value_or(""));
        if (server.empty() && a.has("meshlabserver"))
            throw UsageError("--meshlabserver " + *a.text("meshlabserver") + ": not an executable file");
    }

    const std::optional<std::string> savePrefix = a.text("save");
    const auto savePath = [&](const std::string& method) {
        std::string lower = method;
        for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return *savePrefix + "-" + lower + ".ply";
    };
    if (savePrefix)
        for (const char* method : {"cvt", "fcvt", "meshlab-isotropic"}) checkOutputPath(savePath(method), inPath);

    MeshReadInfo readInfo;
    VertexAttributes attributes;
    const TriMesh input = readMesh(inPath, &readInfo, &attributes);
    if (fcvt.fieldSource == FieldSource::User) fcvt.userDirections = userField(inPath, attributes);

    std::vector<std::string> notes;
    std::vector<Row> rows(2);
    rows[0].method = "CVT";
    rows[0].params = cvtParams(fcvt);
    rows[1].method = "FCVT";
    rows[1].params = fcvt;
    {
        ProgressPrinter printer(quiet);
        const Progress inner = printer.callback();
        for (Row& row : rows) {
            Progress progress;
            if (inner)
                progress = [&](const std::string& stage, double percent) { return inner(row.method + " " + stage, percent); };
            try {
                row.result = remesh(input, row.params, progress);
            } catch (const InvalidInputError& e) {
                throw InvalidInputError(inPath + ": " + e.what());
            }
            row.seconds = remeshSeconds(row.result);
        }
        if (!server.empty()) {
            std::optional<Row> row = meshlabRow(server, input, fcvt.vertexCount, meshlabIterations, inner, notes);
            if (row) rows.push_back(std::move(*row));
        }
    }
    if (server.empty() && !a.flag("no-meshlab"))
        notes.push_back("no meshlab-isotropic row: meshlabserver not found (--meshlabserver PATH or $FCVT_MESHLABSERVER)");

    if (!quiet) {
        for (const std::string& warning : readInfo.warnings)
            std::fprintf(stderr, "fcvt: warning: %s: %s\n", inPath.c_str(), warning.c_str());
        for (const std::string& note : readInfo.notes)
            std::fprintf(stderr, "fcvt: warning: %s: %s\n", inPath.c_str(), note.c_str());
        for (const Row& row : rows)
            for (const std::string& w : row.result.warnings)
                std::fprintf(stderr, "fcvt: %s: %s: %s\n", row.meshlab ? "note" : "warning", row.method.c_str(), w.c_str());
        for (const std::string& n : notes) std::fprintf(stderr, "fcvt: warning: %s\n", n.c_str());
    }
    if (savePrefix)
        for (const Row& row : rows) writeMesh(savePath(row.method), row.result.mesh);
    if (a.flag("json"))
        std::printf("%s\n", rowsJson(rows).dump(2).c_str());
    else
        printTable(rows);
    return 0;
}

}  // namespace fieldcvt::cli
