// `fcvt remesh IN OUT --vertices N ...`: read, remesh with the core, write, summarise, report.
#include "cli_common.h"
#include "commands.h"
#include "progress_printer.h"
#include "output_texture.h"

#include "errors.h"
#include "mesh_io.h"
#include "metrics.h"
#include "region.h"
#include "remesh.h"

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace fieldcvt::cli {

namespace {

void printUsage()
{
    const RemeshParams defaults;
    std::printf(
        "Usage: fcvt remesh IN OUT (--vertices N | --target-length L) [options]\n"
        "\n"
        "Remeshes the triangle mesh IN into OUT with about N vertices: CVT iterations, then FCVT\n"
        "iterations that also align the edges to a 6-RoSy direction field (E_CVT + lambda * E_field).\n"
        "Formats by extension: .ply (written binary, double coordinates), .obj, .off, .stl. A .ply\n"
        "OUT also gets the field at its vertices (nx ny nz, rosy_x rosy_y rosy_z) when one was used.\n"
        "\n"
        "Options:\n"
        "  --vertices N          target vertex count, %s\n"
        "  --target-length L     target edge length (IN's units), > 0, instead of --vertices: the\n"
        "                        vertex count is 2 * area / (sqrt(3) * L^2); exactly one is required\n"
        "  --preset P            fast, default or quality: a set of the schedule's options, which the\n"
        "                        other options override. fast: 5 FCVT iterations from the lattice,\n"
        "                        no CVT ones, shorter field, lattice and valence solves, 2 faces a\n"
        "                        vertex to optimise on (a third to half the default's time); quality:\n"
        "                        the paper's 30 + 65 + 65 schedule on the input itself (default\n"
        "                        default)\n"
        "  --field F             the field to align to: extrinsic (smooth, Instant Meshes),\n"
        "                        curvature-max, curvature-min, or user (IN's PLY vertex properties\n"
        "                        rosy_x rosy_y rosy_z) (default %s)\n"
        "  --lambda L            weight of the field-alignment term, >= 0; 0 = pure CVT (default %g)\n"
        "  --lloyd-iterations K  Lloyd steps from the start before L-BFGS, >= 0 (default %d from the\n"
        "                        lattice start, %d from a random one)\n"
        "  --cvt-iterations A    L-BFGS iterations on the CVT energy, >= 0 (default %d)\n"
        "  --fcvt-iterations B   then L-BFGS iterations on CVT + lambda * field energy, >= 0 (default %d,\n"
        "                        %d from %d vertices on when starting from the lattice: as good there);\n"
        "                        the paper's fixed schedule: --lloyd-iterations 30 --cvt-iterations 65\n"
        "                        --fcvt-iterations 65\n"
        "  --full-surface        optimise on the input itself, as the paper does, even when it has many\n"
        "                        more faces than the output (by default such an input is optimised on\n"
        "                        a coarser copy, %d faces per vertex up to %d faces and at least 2 per\n"
        "                        vertex, and the result put back on it)\n"
        "  --random-start        start from random samples instead of the lattice points of the\n"
        "                        field-aligned position field (the default start when the field is\n"
        "                        used with a uniform density; it has no 5-7 pairs away from the field's\n"
        "                        singularities)\n"
        "  --no-valence          skip the valence optimisation (flips, collapses, splits towards valence\n"
        "                        6, 4 on boundaries, then a relaxation; on by default)\n"
        "  --no-repair           only check the input, as before the repair stage: refuse non-manifold\n"
        "                        edges and non-orientable pieces, keep every component (by default\n"
        "                        they are repaired: exact and near duplicate vertices welded, duplicate\n"
        "                        and opposite faces removed, non-manifold edges and vertices split,\n"
        "                        non-orientable pieces cut, components too small for N dropped)\n"
        "  --keep-holes          keep every hole open (by default a hole under 2 edge lengths across\n"
        "                        is closed before remeshing, counted in a warning)\n"
        "  --exact-count         keep N even where the topology needs more vertices (by default the\n"
        "                        density is raised where the surface is thinner than the edge length,\n"
        "                        and a shell whose topology the triangulation still loses is remeshed\n"
        "                        by local operations on the input: every shell, hole and handle kept;\n"
        "                        a warning and the report's thin_parts and local_shells say how many\n"
        "                        vertices were added and why)\n"
        "  --feature-angle DEG   input edges with a dihedral angle >= DEG degrees are sharp features the\n"
        "                        output follows, 0..180 (default %g: off)\n"
        "  --adaptive D          sample density: none (uniform) or curvature (more vertices where the\n"
        "                        surface bends; same vertex count) (default none)\n"
        "  --gradation G         with --adaptive curvature: how strongly curvature raises the density,\n"
        "                        >= 0, 0 = uniform (default %g)\n"
        "  --seed S              seed of the sampling and the field, >= 0 (default %llu); same seed, same output\n"
        "  --threads T           OpenMP threads, >= 0 (default %d: one per core that no other task holds\n"
        "                        as the run starts); output does not depend on it\n"
        "  --time-limit SEC      stop optimising after SEC seconds and write the best result so far,\n"
        "                        with a warning (default 0: no limit)\n"
        "  --region PROPERTY     remesh only the faces of IN (a .ply) whose face property PROPERTY is\n"
        "                        non-zero; the other faces and vertices are kept bit for bit, the\n"
        "                        region's border vertices stay where they are and the new faces meet\n"
        "                        them edge to edge (also on IN's own boundary, which is kept too). N or\n"
        "                        L applies to the region's area, split between its separate pieces\n"
        "                        (faces meeting at a vertex only are separate pieces); all faces\n"
        "                        selected is the plain remesh. A selection that is not a manifold,\n"
        "                        oriented surface is repaired as the whole mesh would be (the other\n"
        "                        faces of a non-manifold edge on its border join it) and oriented as\n"
        "                        the faces kept around it; faults of the kept faces themselves stay,\n"
        "                        with a warning, and a result broken anywhere else is an error. A .ply\n"
        "                        OUT gets PROPERTY back: 1 on the new faces, IN's value on the kept\n"
        "                        ones. To mark faces in MeshLab: select them, then Filters > Quality\n"
        "                        Measure and Computations > Per Face Quality Function with \"func q0 =\"\n"
        "                        fsel (1 on selected faces, 0 elsewhere), File > Export Mesh As... .ply\n"
        "                        with the face's Quality ticked, and --region quality\n"
        "  --report FILE.json    write a JSON report: counts, metrics, topology, stage times, energy\n"
        "                        history, field singularities (looked for only then), valence\n"
        "                        optimisation, repair, warnings\n"
        "  --texture MODE        the output's texture, when IN has texture coordinates (OBJ vt, PLY\n"
        "                        texcoord) and OUT is .obj or .ply: keep (IN's atlas and images, each\n"
        "                        face in one chart; an OBJ OUT gets its own OUT.mtl, IN's never edited),\n"
        "                        bake (a new image OUT_texture.png, one triangle per face, sampled from\n"
        "                        IN's images),\n"
        "                        auto (default: bake when keeping would put over 10 %% of the faces\n"
        "                        across a seam of IN's atlas, i.e. its charts are small; keep when IN's\n"
        "                        images cannot be read)\n"
        "  --no-texture          drop the input's texture coordinates\n"
        "  --overwrite           let the files written beside OUT (OUT.mtl, OUT_texture.png) replace\n"
        "                        existing files of those names (by default such a file is kept and\n"
        "                        the new one numbered, OUT_texture_2.png, with a warning); IN and the\n"
        "                        files it names are never written over\n"
        "  --quiet               print nothing but errors (progress: a bar on a terminal, plain lines\n"
        "                        on stderr otherwise); without --report, d_RMS and d_H are then\n"
        "                        not computed (nothing would show them)\n"
        "  -h, --help            show this help\n",
        vertexCountRange().c_str(), fieldSourceName(defaults.fieldSource).c_str(), defaults.lambda,
        defaults.latticeLloydIterations, defaults.lloydIterations, defaults.cvtIterations, defaults.fcvtIterations,
        defaults.largeRunFcvtIterations, defaults.largeRunSamples, defaults.optimisationFacesPerSample,
        defaults.optimisationFacesCap, defaults.featureAngleDegrees, defaults.gradation,
        static_cast<unsigned long long>(defaults.seed), defaults.threads);
}

//! Writes OUT: a PLY gets the field at its vertices when one was used and, with --region (a
//! non-empty `regionProperty`), that property back: 1 on the new faces, the input's value on the
//! kept ones (not when everything was selected: then the output is the plain remesh's); a
//! non-null `texture` its per-corner coordinates (outputTexture).
void writeOutput(const std::string& outPath, const RegionRemeshResult& run, const std::string& regionProperty,
                 const VertexAttributes& inputAttributes, const MeshTexture* texture)
{
    const RemeshResult& result = run.result;
    VertexAttributes outputAttributes;
    const bool writeField = !result.outputDirections.empty() && isPlyPath(outPath) &&
                            result.outputDirections.size() == result.mesh.vertices.size() &&
                            result.outputNormals.size() == result.mesh.vertices.size();
    if (writeField) {
        outputAttributes.normals = result.outputNormals;
        outputAttributes.rosy = result.outputDirections;
    }
    const bool writeRegion = !regionProperty.empty() && !run.wholeMesh && isPlyPath(outPath);
    if (writeRegion) {
        outputAttributes.faceProperty = regionProperty;
        for (int origin : run.faceOrigin)
            outputAttributes.faceValues.push_back(origin < 0 ? 1.0 : inputAttributes.faceValues[size_t(origin)]);
    }
    writeMesh(outPath, result.mesh, writeField || writeRegion ? &outputAttributes : nullptr, texture);
}

//! The summary's second line with --region.
void printRegionLine(const RegionRemeshResult& run)
{
    const auto isNew = [](int origin) { return origin < 0; };
    std::printf(
        "region: %d piece%s (%d kept as %s), %ld new vertices, %ld new faces, %d border vertices kept; the "
        "figures above are the new faces' (away from the border: theta_min %.1f deg, Q_avg %.3f)\n",
        run.regions, run.regions == 1 ? "" : "s", run.keptRegions, run.keptRegions == 1 ? "it was" : "they were",
        long(std::count_if(run.vertexOrigin.begin(), run.vertexOrigin.end(), isNew)),
        long(std::count_if(run.faceOrigin.begin(), run.faceOrigin.end(), isNew)), run.borderVertices,
        run.interiorMetrics.thetaMin, run.interiorMetrics.qAvg);
}

//! The faces whose `property` value is non-zero; InvalidInputError when there are none.
std::vector<char> regionFromProperty(const std::string& path, const std::string& property, const VertexAttributes& attributes)
{
    std::vector<char> selected(attributes.faceValues.size(), 0);
    for (size_t f = 0; f < selected.size(); ++f)
        selected[f] = attributes.faceValues[f] != 0 && !std::isnan(attributes.faceValues[f]);
    if (std::none_of(selected.begin(), selected.end(), [](char c) { return c != 0; }))
        throw InvalidInputError(path + ": the region is empty: no face has a non-zero " + quoteInput(property) +
                                " (mark the faces to remesh first; see fcvt remesh --help)");
    return selected;
}

//! The run's information lines: the reader's, the core's, the texture's.
std::vector<std::string> runNotes(const std::string& inPath, const MeshReadInfo& readInfo, const RemeshResult& result,
                                  const WrittenTexture& texture)
{
    std::vector<std::string> notes;
    for (const std::string& note : readInfo.notes) notes.push_back(inPath + ": " + note);
    notes.insert(notes.end(), result.notes.begin(), result.notes.end());
    if (!texture.made.texture.empty()) notes.push_back(textureNote(texture));
    return notes;
}

}  // namespace

int runRemesh(const std::vector<std::string>& args)
{
    const Arguments a(args, remeshOptionNames().valued, remeshOptionNames().flags);
    if (printedHelp(a, printUsage)) return 0;
    const auto [inPath, outPath] = inputAndOutput(a, "remesh");
    frontend::RemeshOptions options = remeshOptions(a);
    RemeshParams& params = options.params;
    const double targetLength = options.targetLength;
    const bool quiet = options.quiet;
    if (params.fieldSource == FieldSource::User && !isPlyPath(inPath))
        throw UsageError("--field user takes the field from the input's PLY vertex properties rosy_x rosy_y rosy_z; " + inPath +
                         " is not a .ply file");
    const auto region = a.text("region");
    if (region && (region->empty() || !isPlyPath(inPath)))
        throw UsageError(
            "--region takes the region from a face property of a PLY input: it needs a property name and a "
            ".ply IN" +
            (isPlyPath(inPath) ? std::string() : " (" + inPath + " is not a .ply file)"));
    checkOutputPath(outPath, inPath);
    const TextureMethod textureMethod = textureMethodFromText(a.text("texture").value_or("auto"));
    if (const auto reportPath = a.text("report")) {
        checkDistinctOutputs(*reportPath, outPath, "output mesh");
        checkWritable(*reportPath, inPath);
    }

    const auto start = std::chrono::steady_clock::now();
    MeshReadInfo readInfo;
    VertexAttributes inputAttributes;
    if (region) inputAttributes.faceProperty = *region;
    MeshTexture inputTexture;
    const TriMesh input = readMesh(inPath, &readInfo, &inputAttributes, a.flag("no-texture") ? nullptr : &inputTexture);
    const std::vector<char> selected = region ? regionFromProperty(inPath, *region, inputAttributes) : std::vector<char>{};
    const std::string sizeWarning = applyTargetLength(options, sizedArea(input, selected));
    if (params.fieldSource == FieldSource::User) params.userDirections = userField(inPath, inputAttributes);
    const double readSeconds = secondsSince(start);

    RegionRemeshResult regionRun;
    RemeshResult& result = regionRun.result;
    {
        ProgressPrinter progress(quiet);
        try {
            if (region)
                regionRun = remeshRegion(input, selected, params, RegionParams{}, progress.callback());
            else
                result = remesh(input, params, progress.callback());
        } catch (const InvalidInputError& e) {
            throw InvalidInputError(inPath + ": " + e.what());  // say which file the problem is in
        } catch (const SolverError& e) {
            throw SolverError(inPath + ": " + e.what());
        }
    }

    const auto writeStart = std::chrono::steady_clock::now();
    const std::string regionProperty = region ? *region : std::string();
    std::vector<std::string> textureWarnings;
    // After a selection-only run the kept faces keep their own coordinates (faceOrigin).
    const std::vector<int> faceOrigin = region && !regionRun.wholeMesh ? regionRun.faceOrigin : std::vector<int>{};
    SideFileNames sideFiles(a.flag("overwrite"));
    sideFiles.reserve(outPath);
    if (const auto reportPath = a.text("report")) sideFiles.reserve(*reportPath);
    const WrittenTexture texture = writeOutputTexture(input, inputTexture, result.mesh, faceOrigin, result.threads, inPath,
                                                      outPath, textureMethod, sideFiles, textureWarnings);
    writeOutput(outPath, regionRun, regionProperty, inputAttributes,
                texture.made.texture.empty() ? nullptr : &texture.made.texture);
    const double writeSeconds = secondsSince(writeStart);

    // Warnings say that the output differs from what was asked (topology, parts, faces, vertex
    // count): they are printed even with --quiet. The reader's notes (polygons triangulated,
    // properties ignored) are information: printed without --quiet, and in the report.
    std::vector<std::string> warnings;
    for (const std::string& warning : readInfo.warnings) warnings.push_back(inPath + ": " + warning);
    if (!sizeWarning.empty()) warnings.push_back(sizeWarning);
    warnings.insert(warnings.end(), result.warnings.begin(), result.warnings.end());
    warnings.insert(warnings.end(), textureWarnings.begin(), textureWarnings.end());
    const std::vector<std::string> notes = runNotes(inPath, readInfo, result, texture);
    // The output's topology and mean edge length are only printed or reported.
    const bool described = !quiet || a.has("report");
    const TopologySummary outputTopology = described ? computeTopology(result.mesh) : TopologySummary{};
    const double meanEdge = described ? meanEdgeLength(result.mesh) : 0.0;
    const double totalSeconds = secondsSince(start);

    if (auto reportPath = a.text("report")) {
        nlohmann::ordered_json report = remeshReport(
            inPath, outPath, params, targetLength, result, {readSeconds, writeSeconds, totalSeconds, meanEdge, outputTopology},
            warnings, notes, region ? regionJson(*region, regionRun) : nlohmann::ordered_json(nullptr));
        report["texture"] = textureJson(inputTexture, a.flag("no-texture"), texture);
        writeJsonFile(*reportPath, report);
    }

    for (const std::string& w : warnings) std::fprintf(stderr, "fcvt: warning: %s\n", escapeControlCharacters(w).c_str());
    if (!quiet) {
        for (const std::string& n : notes) std::fprintf(stderr, "fcvt: note: %s\n", escapeControlCharacters(n).c_str());
        const QualityMetrics& m = result.metrics;
        std::printf(
            "%s: %d vertices, %d faces, genus %d, %d boundary loops%s; Q_avg %.3f, theta_min %.1f deg, "
            "V6 %.1f %%, d_H %.3g %% of the diagonal, mean edge %.4g; %d evaluations, %.2f s\n",
            outPath.c_str(), result.mesh.vertexCount(), result.mesh.faceCount(), outputTopology.genus,
            outputTopology.boundaryLoops, outputTopology.manifold() ? "" : " (NOT MANIFOLD)", m.qAvg, m.thetaMin, m.v6Pct,
            100 * m.dH, meanEdge, result.evaluations, totalSeconds);
        if (region && !regionRun.wholeMesh) printRegionLine(regionRun);
    }
    return 0;
}

}  // namespace fieldcvt::cli
