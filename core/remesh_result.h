#pragma once
// What remesh() returns: the output mesh and the report of the run (core/remesh.h).
#include "field_types.h"
#include "lattice_params.h"
#include "mesh.h"
#include "metrics_types.h"
#include "repair_params.h"
#include "valence_params.h"

#include <string>
#include <vector>

namespace fieldcvt {

//! Energies after one L-BFGS step (an evaluation that lowered E_tot) or one Lloyd step.
struct EnergyRecord {
    std::string phase;  //!< "lloyd", "cvt" or "fcvt"
    double cvt = 0;     //!< E_CVT at the working scale (mean cell area 1)
    double field = 0;   //!< E_field (FCVT phase only; 0 in the Lloyd and CVT phases, where it is not computed)
};

//! One timed stage of a run ("sampling", "cvt", "rdt", "metrics", ...), in seconds.
struct StageTime {
    std::string stage;
    double seconds = 0;
};

struct RemeshResult {
    TriMesh mesh;                       //!< the restricted Delaunay triangulation
    int evaluations = 0;                //!< energy + gradient evaluations
    int fcvtIterations = 0;             //!< the FCVT iteration budget used (RemeshParams::largeRunFcvtIterations)
    std::vector<StageTime> stageTimes;  //!< per-stage wall time, in pipeline order
    double totalSeconds = 0;
    QualityMetrics metrics;             //!< Table 2 figures of mesh (d_* against the input)
    TopologySummary inputTopology;      //!< genus / boundary loops / components of the input
    TopologySummary outputTopology;     //!< the same for the output
    std::vector<std::string> warnings;  //!< e.g. topology not recovered, solver restarts
    //! The first inputWarnings of `warnings` are the input check's and the repair's (the stage
    //! that ran first), for a log in stage order.
    int inputWarnings = 0;
    //! The OpenMP threads the run took (RemeshParams::threads, or for 0 the cores no other
    //! task held as it started: thread_budget.h).
    int threads = 0;
    //! Information: what changed nothing a user sees (unreferenced vertices removed, ...).
    std::vector<std::string> notes;
    std::vector<EnergyRecord> energyHistory;  //!< convergence (paper Fig. 8)
    //! The field interpolated at the output vertices (empty for a pure CVT without a field).
    std::vector<Vec3> outputNormals, outputDirections;
    std::vector<Singularity> singularities;  //!< of the input's field, positions in input units
    ValenceStats valence;                    //!< V6% before / after valence optimisation, operations done
    RepairReport repair;                     //!< what the repair stage did (RemeshParams::repair)
    //! The lattice start (RemeshParams::latticeStart), spacing in input units; passes 0 = random start.
    LatticeReport lattice;
    //! Faces of the surface the optimisation ran on: the input's (after repair) or its coarser
    //! copy's (RemeshParams::optimisationFacesPerSample).
    int optimisationFaces = 0;
    //! Vertices added for thin parts (RemeshParams::exactCount) and where: `added` > 0 when the
    //! vertex count was raised beyond the one asked for.
    struct ThinParts {
        int added = 0;        //!< samples beyond the vertex count asked for
        int faces = 0;        //!< faces of the optimisation surface thinner than the edge length allows
        double thinnest = 0;  //!< the smallest thickness measured, in input units (0: none thin)
        bool capped = false;  //!< the samples reached ThinPartParams::maxVertexFactor × the count asked for
        //! The kept pass has side-aware cells (a sample owns nothing of the far side of a wall).
        bool sideAwareCells = false;
    } thinParts;
    //! Shells (connected components of the surface) whose restricted Delaunay triangulation did not
    //! keep their topology even after the thin-part passes, remeshed by local operations on the
    //! surface instead (local_remesh.h), which keep it by construction. None with exactCount.
    struct LocalShells {
        int shells = 0;       //!< shells remeshed by local operations
        int faces = 0;        //!< faces of the optimisation surface in them
        int rdtVertices = 0;  //!< the RDT's vertices there, replaced
        int vertices = 0;     //!< the local remeshing's vertices there
        std::string reasons;  //!< what was wrong with the RDT's pieces there, in words
    } localShells;
};

//! The mesh remesh() computed the field and its singularities on, for a log or report next to
//! them: "the input (N faces)" or "the optimisation surface, a simplified copy of the input (N
//! faces)". `fcvt field` and the field filter compute on the input: the figures agree there.
std::string fieldMeshDescription(const RemeshResult& result);

}  // namespace fieldcvt
