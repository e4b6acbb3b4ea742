#include "report.h"

#include "errors.h"

#include <cmath>
#include <fstream>
#include <utility>

namespace fieldcvt::frontend {

namespace {

nlohmann::ordered_json numberOrNull(double x)
{
    return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json(nullptr);
}

}  // namespace

nlohmann::ordered_json metricsJson(const QualityMetrics& m)
{
    const std::pair<const char*, double> figures[] = {
        {"q_min", m.qMin},         {"q_avg", m.qAvg},       {"theta_min", m.thetaMin},   {"theta_min_avg", m.thetaMinAvg},
        {"theta_max", m.thetaMax}, {"pct_lt30", m.pctLt30}, {"pct_gt90", m.pctGt90},     {"v6_pct", m.v6Pct},
        {"d_rms", m.dRms},         {"d_h", m.dH},           {"d_boundary", m.dBoundary}, {"boundary_v4_pct", m.boundaryV4Pct}};
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    for (const auto& [name, value] : figures) j[name] = numberOrNull(value);
    return j;
}

nlohmann::ordered_json topologyJson(const TopologySummary& t)
{
    return {{"genus", t.genus},
            {"boundary_loops", t.boundaryLoops},
            {"components", t.components},
            {"manifold", t.manifold()},
            {"orientable", t.orientable},
            {"non_manifold_edges", t.nonManifoldEdges},
            {"non_manifold_vertices", t.nonManifoldVertices}};
}

nlohmann::ordered_json energyHistoryJson(const std::vector<EnergyRecord>& history)
{
    nlohmann::ordered_json j = nlohmann::ordered_json::array();
    for (const EnergyRecord& r : history)
        j.push_back({{"phase", r.phase}, {"e_cvt", numberOrNull(r.cvt)}, {"e_field", numberOrNull(r.field)}});
    return j;
}

nlohmann::ordered_json fieldJson(FieldSource source, const std::vector<Singularity>& singularities, std::size_t maxPositions)
{
    long long indexSum = 0;
    nlohmann::ordered_json positions = nlohmann::ordered_json::array();
    for (const Singularity& s : singularities) {
        indexSum += s.index;
        if (positions.size() < maxPositions) positions.push_back({s.position.x(), s.position.y(), s.position.z()});
    }
    return {{"source", fieldSourceName(source)},
            {"singularities", singularities.size()},
            {"index_sum", indexSum},
            {"singularity_positions", positions}};
}

nlohmann::ordered_json valenceJson(bool enabled, const ValenceStats& v)
{
    return {{"enabled", enabled},
            {"v6_before", numberOrNull(v.v6Before)},
            {"v6_after", numberOrNull(v.v6After)},
            {"flips", v.flips},
            {"collapses", v.collapses},
            {"splits", v.splits},
            {"rounds", v.rounds},
            {"irregularity_before", v.irregularityBefore},
            {"irregularity_after", v.irregularityAfter}};
}

nlohmann::ordered_json repairJson(bool enabled, const RepairReport& r)
{
    if (!enabled) return {{"enabled", false}};
    return {{"enabled", true},
            {"removed_unreferenced_vertices", r.removedUnreferencedVertices},
            {"merged_duplicate_vertices", r.mergedDuplicateVertices},
            {"welded_vertices", r.weldedVertices},
            {"weld_distance", r.weldDistance},
            {"t_junctions", r.tJunctions},
            {"removed_degenerate_faces", r.removedDegenerateFaces},
            {"removed_duplicate_faces", r.removedDuplicateFaces},
            {"removed_opposite_faces", r.removedOppositeFaces},
            {"removed_flap_faces", r.removedFlapFaces},
            {"non_manifold_edges", r.nonManifoldEdges},
            {"non_orientable_components", r.nonOrientableComponents},
            {"seam_edges", r.seamEdges},
            {"split_vertices", r.splitVertices},
            {"added_vertex_copies", r.addedVertexCopies},
            {"dropped_components", r.droppedComponents},
            {"dropped_area", r.droppedArea},
            {"dropped_area_fraction", r.droppedAreaFraction},
            {"kept_small_components", r.keptSmallComponents},
            {"kept_far_components", r.keptFarComponents}};
}

void writeJsonFile(const std::string& path, const nlohmann::ordered_json& json)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << json.dump(2) << '\n';
    out.close();
    if (!out) throw IOError(path + ": cannot write the report");
}

}  // namespace fieldcvt::frontend
