#pragma once
// The JSON vocabulary of the CLI, shared by `fcvt remesh --report` and `fcvt metrics --json`
// (other tooling reads these key names: keep them stable).
#include "field.h"
#include "metrics.h"
#include "remesh.h"

#include <nlohmann/json.hpp>

#include <string>

namespace fieldcvt::frontend {

//! Exactly q_min q_avg theta_min theta_min_avg theta_max pct_lt30 pct_gt90 v6_pct d_rms d_h;
//! NaN (e.g. distances without a reference) becomes null.
nlohmann::ordered_json metricsJson(const QualityMetrics& metrics);
//! genus, boundary_loops, components, manifold, orientable (+ non-manifold counts).
nlohmann::ordered_json topologyJson(const TopologySummary& topology);

//! [{"phase", "e_cvt", "e_field"}, ...] in run order (phases "lloyd", "cvt", "fcvt").
nlohmann::ordered_json energyHistoryJson(const std::vector<EnergyRecord>& history);

//! "source", "singularities" (count), "index_sum" (sixths of a turn) and
//! "singularity_positions" ([[x, y, z], ...], the first `maxPositions`).
nlohmann::ordered_json fieldJson(FieldSource source, const std::vector<Singularity>& singularities,
                                 std::size_t maxPositions = 1000);

//! "enabled", "v6_before", "v6_after" (% of interior vertices of valence 6 around the valence
//! optimisation), "flips", "collapses", "splits", "rounds", "irregularity_before", "irregularity_after".
nlohmann::ordered_json valenceJson(bool enabled, const ValenceStats& stats);

//! "enabled" and, when enabled, one count per repair step (repair.h: "merged_duplicate_vertices",
//! "welded_vertices", "weld_distance", "t_junctions", "removed_duplicate_faces",
//! "removed_opposite_faces", "removed_flap_faces", "non_manifold_edges", "non_orientable_components", "seam_edges",
//! "split_vertices", "dropped_components", "dropped_area_fraction", ...).
nlohmann::ordered_json repairJson(bool enabled, const RepairReport& repair);

//! Writes `json` (indented, trailing newline) to `path`; throws IOError on failure.
void writeJsonFile(const std::string& path, const nlohmann::ordered_json& json);

}  // namespace fieldcvt::frontend
