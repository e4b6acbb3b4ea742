#pragma once
// MeshLab's built-in "Remeshing: Isotropic Explicit Remeshing" (vcg::tri::IsotropicRemeshing) run
// through a meshlabserver process, for `fcvt compare`'s "meshlab-isotropic" row.
#include "mesh.h"

#include <string>
#include <vector>

namespace fieldcvt::cli {

//! The meshlabserver to run: `explicitPath` if not empty, else $FCVT_MESHLABSERVER, else
//! `meshlabserver` on PATH; empty when none is found (or an explicit path is not executable).
std::string findMeshlabserver(const std::string& explicitPath);

struct IsotropicRun {
    TriMesh mesh;                    //!< the remeshed surface as MeshLab wrote it
    double targetLength = 0;         //!< TargetLen of the last run (IN's units)
    int iterations = 0;              //!< the filter's Iterations
    int runs = 0;                    //!< meshlabserver runs made to approach the vertex count
    double seconds = 0;              //!< wall time of the last run (MeshLab start-up and file I/O included)
    std::vector<std::string> notes;  //!< how the target length was matched
};

//! Remeshes `input` with the built-in filter (MeshLab's defaults, but `iterations` iterations and
//! no surface-distance check) at about `vertices` vertices: TargetLen starts at the edge of an
//! equilateral triangulation with that many vertices, sqrt(2 A / (sqrt(3) N)), and is rescaled by
//! sqrt(achieved / wanted) while the vertex count is off by more than 5 % (at most 3 runs).
//! Runs under `xvfb-run -a` when DISPLAY is unset (meshlabserver 2020.09 needs an OpenGL context).
//! Throws fieldcvt::Error with the end of MeshLab's log when a run fails.
IsotropicRun runMeshlabIsotropic(const std::string& server, const TriMesh& input, int vertices, int iterations);

}  // namespace fieldcvt::cli
