#include "metrics_report.h"

#include "report.h"

#include <cmath>

namespace fieldcvt::frontend {

namespace {

nlohmann::ordered_json partsJson(const PartCoverage& c)
{
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    j["parts"] = static_cast<int>(c.parts.size());
    // An output without faces leaves the gap infinite, which JSON cannot hold: null.
    j["part_gap"] = std::isfinite(c.largestGap) ? nlohmann::ordered_json(c.largestGap) : nlohmann::ordered_json();
    j["part_pieces"] = c.mostPieces;
    j["small_parts"] = c.smallParts;
    j["small_parts_area_pct"] = 100.0 * c.smallAreaFraction;
    j["small_parts_gap"] = std::isfinite(c.smallPartsGap) ? nlohmann::ordered_json(c.smallPartsGap) : nlohmann::ordered_json();
    return j;
}

}  // namespace

nlohmann::ordered_json MeshMeasurement::json() const
{
    nlohmann::ordered_json j = metrics;
    j.update(parts);
    return j;
}

MeshMeasurement measureMesh(const TriMesh& mesh, const TriMesh* reference)
{
    MeshMeasurement m;
    m.quality = computeQuality(mesh);
    m.parts = nlohmann::ordered_json::object();
    if (reference != nullptr) {
        const DistanceMetrics d = computeDistance(mesh, *reference);
        m.quality.dRms = d.rms;
        m.quality.dH = d.hausdorff;
        m.quality.dBoundary = boundaryDistance(mesh, *reference);
        m.coverage = measurePartCoverage(mesh, *reference);
        m.parts = partsJson(m.coverage);
    }
    m.metrics = metricsJson(m.quality);
    return m;
}

}  // namespace fieldcvt::frontend
