#pragma once
// The `fcvt remesh --report` JSON of one run, shared by the CLI and the Python module's
// Result.report: the same keys from the same code (other tooling reads them: keep them stable).
#include "metrics.h"
#include "region.h"
#include "remesh.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace fieldcvt::frontend {

//! What the report takes besides the parameters and the core's result.
struct RunFigures {
    double readSeconds = 0, writeSeconds = 0, totalSeconds = 0;
    double meanEdge = 0;
    TopologySummary outputTopology;
};

//! The report's "params" object.
nlohmann::ordered_json paramsJson(const RemeshParams& params);

//! The --report JSON of one run (its "region" object: regionJson, or null without a region).
//! `inputFile` and `outputFile` are the files' names (the Python module's are null).
nlohmann::ordered_json remeshReport(const nlohmann::ordered_json& inputFile, const nlohmann::ordered_json& outputFile,
                                    const RemeshParams& params, double targetLength, const RemeshResult& result,
                                    const RunFigures& figures, const std::vector<std::string>& warnings,
                                    const std::vector<std::string>& notes, const nlohmann::ordered_json& region);

//! The report's "region" object (--region): the pieces, the border kept, the new part's figures.
nlohmann::ordered_json regionJson(const std::string& property, const RegionRemeshResult& run);

//! The first keys of the report's "texture" object, all of it when the output has no texture:
//! `input_has_texture` (null when `dropped`: --no-texture, not read then), `no_texture_option`, `kept`.
nlohmann::ordered_json textureSummaryJson(bool inputHasTexture, bool dropped, bool kept);

}  // namespace fieldcvt::frontend
