#include "report.h"

#include "errors.h"

#include <cmath>
#include <fstream>

namespace fieldcvt::cli {

namespace {

nlohmann::ordered_json numberOrNull(double x) { return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json(nullptr); }

}  // namespace

nlohmann::ordered_json metricsJson(const QualityMetrics& m)
{
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    j["q_min"] = numberOrNull(m.qMin);
    j["q_avg"] = numberOrNull(m.qAvg);
    j["theta_min"] = numberOrNull(m.thetaMin);
    j["theta_min_avg"] = numberOrNull(m.thetaMinAvg);
    j["theta_max"] = numberOrNull(m.thetaMax);
    j["pct_lt30"] = numberOrNull(m.pctLt30);
    j["pct_gt90"] = numberOrNull(m.pctGt90);
    j["v6_pct"] = numberOrNull(m.v6Pct);
    j["d_rms"] = numberOrNull(m.dRms);
    j["d_h"] = numberOrNull(m.dH);
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

void writeJsonFile(const std::string& path, const nlohmann::ordered_json& json)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << json.dump(2) << '\n';
    out.close();
    if (!out) throw IOError(path + ": cannot write the report");
}

}  // namespace fieldcvt::cli
