#pragma once
// The types of the 6-RoSy direction field (field.h) that other modules share without the field's
// computation: the field itself, where it comes from, what computing it did, its singularities.
#include "mesh.h"

#include <vector>

namespace fieldcvt {

struct DirectionField {
    std::vector<Vec3> normals;     //!< per input vertex, unit
    std::vector<Vec3> directions;  //!< per input vertex, unit, orthogonal to the normal
};

enum class FieldSource {
    Extrinsic,     //!< extrinsically smooth field of Instant Meshes (Jakob et al. 2015)
    CurvatureMax,  //!< maximal principal-curvature direction
    CurvatureMin,  //!< minimal principal-curvature direction
    User,          //!< given per vertex by the caller (RemeshParams::userDirections)
};

//! What one computeField run did (for tests, benchmarks and reports).
struct FieldReport {
    std::vector<int> levelVertexCounts;  //!< vertices per hierarchy level, finest (the input) first
    //! Energy minimised (extrinsicEnergy, or its intrinsic counterpart: FieldSmoothness) of the
    //! field on the input mesh: [0] the random initial field, then after smoothing each level,
    //! coarsest first, prolongated to the input mesh.
    std::vector<double> levelEnergies;
    //! Per level, coarsest first: that level's weighted energy before smoothing, then after each
    //! Gauss–Seidel sweep (non-increasing).
    std::vector<std::vector<double>> sweepEnergies;
    int constrainedVertices = 0;  //!< input vertices whose direction was prescribed
    //! Curvature sources: vertices where curvature was (nearly) umbilic or flat and the direction
    //! comes from smoothing with the reliable ones fixed.
    int umbilicVertices = 0;
};

struct Singularity {
    int face = -1;  //!< face whose corners' representatives turn by a non-zero amount
    int index = 0;  //!< 6-RoSy index in sixths of a turn (sum over faces = 6·χ on a closed surface)
    Vec3 position;  //!< the face's centroid
};

}  // namespace fieldcvt
