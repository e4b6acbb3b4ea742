#include "remesh_report.h"

#include "report.h"

#include <algorithm>

namespace fieldcvt::frontend {

namespace {

//! The vertices asked for, the output's, and what the vertices beyond the count asked for are:
//! samples added on thin parts, the shells remeshed by local operations (their vertices less the
//! triangulation's there), the rest (cells cut in pieces by thin walls, the valence stage).
nlohmann::ordered_json vertexCountJson(const RemeshParams& params, const RemeshResult& result)
{
    const int asked = params.initialSamples.empty() ? params.vertexCount : static_cast<int>(params.initialSamples.size());
    const int output = result.mesh.vertexCount();
    const int localShells = result.localShells.vertices - result.localShells.rdtVertices;
    return {{"asked", asked},
            {"output", output},
            {"added_vertices", std::max(0, output - asked)},
            {"thin_part_samples", result.thinParts.added},
            {"local_shells", localShells},
            {"other", output - asked - result.thinParts.added - localShells}};
}

}  // namespace

nlohmann::ordered_json paramsJson(const RemeshParams& p)
{
    return {{"vertices", p.vertexCount},
            {"field", fieldSourceName(p.fieldSource)},
            {"lambda", p.lambda},
            {"lloyd_iterations", p.lloydIterations},
            {"lattice_lloyd_iterations", p.latticeLloydIterations},
            {"cvt_iterations", p.cvtIterations},
            {"fcvt_iterations", p.fcvtIterations},
            {"large_run_fcvt_iterations", p.largeRunFcvtIterations},
            {"large_run_samples", p.largeRunSamples},
            {"seed", p.seed},
            {"threads", p.threads},
            {"time_limit_s", p.timeLimitSeconds},
            {"valence_optimization", p.valenceOptimization},
            {"lattice_start", p.latticeStart},
            {"feature_angle", p.featureAngleDegrees},
            {"adaptive", p.density == DensitySource::Curvature ? "curvature" : "none"},
            {"gradation", p.gradation},
            {"repair", p.repair},
            {"optimisation_faces_per_sample", p.optimisationFacesPerSample},
            {"boundary_iterations", p.boundaryIterations},
            {"field_smoothing_iterations", p.fieldSmoothingIterations},
            {"lattice_iterations", p.latticeIterations},
            {"lattice_passes", p.latticePasses},
            {"valence_rounds", p.valence.maxRounds},
            {"valence_look_ahead", p.valence.lookAheadDepth},
            {"valence_relax_iterations", p.valence.relaxIterations},
            {"valence_local_smoothing", p.valence.localSmoothing},
            {"valence_sag_repair_rounds", p.valence.sagRepairRounds},
            {"simplify_block_faces", p.simplifyBlockFaces}};
}

//! The --report JSON of one run.
nlohmann::ordered_json remeshReport(const nlohmann::ordered_json& inputFile, const nlohmann::ordered_json& outputFile,
                                    const RemeshParams& params, double targetLength, const RemeshResult& result,
                                    const RunFigures& figures, const std::vector<std::string>& warnings,
                                    const std::vector<std::string>& notes, const nlohmann::ordered_json& region)
{
    nlohmann::ordered_json times = nlohmann::ordered_json::object();
    times["read"] = figures.readSeconds;
    // A stage run twice (remeshThinPartsAgain) counts both times.
    for (const StageTime& stage : result.stageTimes) times[stage.stage] = times.value(stage.stage, 0.0) + stage.seconds;
    times["write"] = figures.writeSeconds;
    times["total"] = figures.totalSeconds;
    nlohmann::ordered_json paramsOut = paramsJson(params);
    if (targetLength > 0) paramsOut["target_length"] = targetLength;
    nlohmann::ordered_json field = fieldJson(params.fieldSource, result.singularities);
    // The core computes a field only when it is used (lambda > 0 and FCVT iterations).
    field["computed"] = !result.outputDirections.empty() || !result.singularities.empty();
    if (field["computed"]) field["mesh"] = fieldMeshDescription(result);
    return {{"input_file", inputFile},
            {"output_file", outputFile},
            {"vertices", result.mesh.vertexCount()},
            {"faces", result.mesh.faceCount()},
            {"mean_edge_length", figures.meanEdge},
            {"evaluations", result.evaluations},
            {"fcvt_iterations", result.fcvtIterations},
            {"threads_used", result.threads},
            {"optimisation_faces", result.optimisationFaces},
            {"thin_parts",
             {{"added_vertices", result.thinParts.added},
              {"faces", result.thinParts.faces},
              {"thinnest", result.thinParts.thinnest},
              {"capped", result.thinParts.capped},
              {"side_aware_cells", result.thinParts.sideAwareCells}}},
            {"vertex_count", vertexCountJson(params, result)},
            {"local_shells",
             {{"shells", result.localShells.shells},
              {"faces", result.localShells.faces},
              {"rdt_vertices", result.localShells.rdtVertices},
              {"vertices", result.localShells.vertices},
              {"reasons", result.localShells.reasons}}},
            {"time_s", times},
            {"metrics", metricsJson(result.metrics)},
            {"input", topologyJson(result.inputTopology)},
            {"output", topologyJson(figures.outputTopology)},
            {"repair", repairJson(params.repair, result.repair)},
            {"params", paramsOut},
            {"field", field},
            {"valence", valenceJson(params.valenceOptimization, result.valence)},
            {"start", result.lattice.passes > 0 ? nlohmann::ordered_json{{"kind", "lattice"},
                                                                         {"spacing", result.lattice.spacing},
                                                                         {"passes", result.lattice.passes},
                                                                         {"samples", result.lattice.samples}}
                                                : nlohmann::ordered_json{{"kind", "random"}}},
            {"energy_history", energyHistoryJson(result.energyHistory)},
            {"region", region},
            {"warnings", warnings},
            {"notes", notes}};
}

//! The --report's "region" object (--region): the pieces, the border kept, the new part's figures.
nlohmann::ordered_json regionJson(const std::string& property, const RegionRemeshResult& run)
{
    const auto isNew = [](int origin) { return origin < 0; };
    return {{"property", property},
            {"whole_mesh", run.wholeMesh},
            {"pieces", run.regions},
            {"kept_pieces", run.keptRegions},
            {"added_faces", run.addedFaces},
            {"border_vertices", run.borderVertices},
            {"target_length", run.targetLength},
            {"worst_border_ratio", run.worstBorderRatio},
            {"new_vertices", std::count_if(run.vertexOrigin.begin(), run.vertexOrigin.end(), isNew)},
            {"new_faces", std::count_if(run.faceOrigin.begin(), run.faceOrigin.end(), isNew)},
            {"metrics", metricsJson(run.result.metrics)},
            {"interior_metrics", metricsJson(run.interiorMetrics)}};
}

nlohmann::ordered_json textureSummaryJson(bool inputHasTexture, bool dropped, bool kept)
{
    return {{"input_has_texture", dropped ? nlohmann::ordered_json() : nlohmann::ordered_json(inputHasTexture)},
            {"no_texture_option", dropped},
            {"kept", kept}};
}

}  // namespace fieldcvt::frontend
