#pragma once
// The one public entry point of the engine: input mesh + parameters -> remeshed mesh + report.
#include "mesh.h"
#include "metrics.h"
#include "progress.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace fieldcvt {

struct RemeshParams {
    int vertexCount = 5000;       //!< target number of output vertices (samples), >= 4
    double lambda = 0.0;          //!< weight of E_field (eq. 2); 0 = pure CVT
    //! Lloyd warm-up steps before L-BFGS (§5, uneven sampling). 30 rather than a few: the
    //! L-BFGS then settles in a better minimum (fertility 3000: V6 85.1 -> 86.0 % over 3 seeds).
    int lloydIterations = 30;
    int cvtIterations = 130;      //!< L-BFGS iterations on E_CVT (§5)
    int fcvtIterations = 0;       //!< L-BFGS iterations on E_CVT + lambda E_field (§5)
    //! Open surfaces: Lloyd steps after the optimisation that put the samples of border cells
    //! on the border (1D CVT along it), so the output's boundary follows the input's.
    int boundaryIterations = 10;
    std::uint64_t seed = 1;       //!< seed of the initial sampling; same seed, same output
    int threads = 0;              //!< OpenMP threads, 0 = runtime default
    bool computeDistances = true; //!< also compute d_RMS / d_H against the input in the report
};

//! One timed stage of a run ("sampling", "cvt", "rdt", "metrics", ...), in seconds.
struct StageTime {
    std::string stage;
    double seconds = 0;
};

struct RemeshResult {
    TriMesh mesh;                        //!< the restricted Delaunay triangulation
    int evaluations = 0;                 //!< energy + gradient evaluations
    std::vector<StageTime> stageTimes;   //!< per-stage wall time, in pipeline order
    double totalSeconds = 0;
    QualityMetrics metrics;              //!< Table 2 figures of mesh (d_* against the input)
    TopologySummary inputTopology;       //!< genus / boundary loops / components of the input
    TopologySummary outputTopology;      //!< the same for the output
    std::vector<std::string> warnings;   //!< e.g. topology not recovered, solver restarts
};

//! Remeshes `input` (validated first; throws InvalidInputError with a clear message).
RemeshResult remesh(const TriMesh& input, const RemeshParams& params, const Progress& progress = {});

}  // namespace fieldcvt
