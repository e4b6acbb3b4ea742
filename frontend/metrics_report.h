#pragma once
// `fcvt metrics MESH [--ref INPUT] --json`: the figures of a mesh, with the distances and the
// input's parts against a reference; shared by the CLI and the Python module's fcvt.metrics.
#include "mesh.h"
#include "metrics.h"
#include "part_coverage.h"

#include <nlohmann/json.hpp>

namespace fieldcvt::frontend {

struct MeshMeasurement {
    QualityMetrics quality;          //!< d_rms, d_h and d_boundary NaN without a reference
    PartCoverage coverage;           //!< the reference's parts (empty without one)
    nlohmann::ordered_json metrics;  //!< metricsJson(quality)
    nlohmann::ordered_json parts;    //!< parts, part_gap, part_pieces, small_parts, ... (empty without a reference)
    //! What `fcvt metrics --json` prints: the metrics, then the parts' keys.
    nlohmann::ordered_json json() const;
};

//! The Table 2 figures of `mesh`; with `reference`, also the distances to it (fractions of its
//! bounding-box diagonal) and how its parts come back in `mesh`.
MeshMeasurement measureMesh(const TriMesh& mesh, const TriMesh* reference);

}  // namespace fieldcvt::frontend
