#pragma once
// Principal curvature directions per vertex, for the curvature-aligned field sources (paper
// Fig. 7: cylinder and torus aligned to the maximal or minimal curvature direction).
#include "mesh.h"

#include <vector>

namespace fieldcvt {

struct PrincipalCurvature {
    std::vector<double> kMax;  //!< principal curvature of larger magnitude, per vertex
    std::vector<double> kMin;  //!< principal curvature of smaller magnitude
    std::vector<Vec3> dirMax;  //!< unit tangent direction of kMax (orthogonal to the normal)
    std::vector<Vec3> dirMin;  //!< unit tangent direction of kMin
    //! 1 where |kMax| and |kMin| differ clearly enough for the directions to mean something;
    //! 0 at (nearly) umbilic or flat vertices and where the fit is degenerate.
    std::vector<unsigned char> reliable;
};

//! Per vertex, a least-squares fit of the symmetric 2×2 shape operator S in the tangent plane
//! from the 1-ring, using the Weingarten relation n_j − n_i ≈ S·(p_j − p_i) on each incident
//! edge (the per-edge normal-variation idea of Rusinkiewicz 2004, "Estimating curvatures and
//! their derivatives on triangle meshes", solved per vertex instead of per face). `normals`
//! are unit vertex normals (vertexNormals).
PrincipalCurvature computePrincipalCurvature(const TriMesh& mesh, const std::vector<Vec3>& normals);

}  // namespace fieldcvt
