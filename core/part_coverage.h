#pragma once
// Whether a remeshed surface keeps the input's parts: every connected
// component of the input that holds a visible share of its area must come back whole, neither
// lost (some of it far from the output) nor cut into pieces (its area nearest to several output
// components). A measurement, for `fcvt metrics --ref`, the tests and the benchmarks; the
// remeshing itself does not use it.
#include "mesh.h"

#include <vector>

namespace fieldcvt {

struct PartCoverageParams {
    //! A part is an input component with at least this share of the input's area; smaller
    //! components may be dropped by the remeshing (counted apart).
    double minAreaFraction = 0.005;
};

struct PartFigures {
    double areaFraction = 0;  //!< the part's share of the input's area
    //! Largest distance from a point of the part to the output surface, in output edge lengths
    //! (the output's mean edge length).
    double gap = 0;
    Vec3 farthestPoint = Vec3::Zero();  //!< the point of the part where the gap is
    //! Output components that belong to the part: those whose vertices are nearest to it for
    //! the most part.
    int pieces = 0;
};

struct PartCoverage {
    std::vector<PartFigures> parts;  //!< the input components over minAreaFraction, largest first
    int smallParts = 0;              //!< components under minAreaFraction
    double smallAreaFraction = 0;    //!< their share of the input's area
    double smallPartsGap = 0;        //!< the largest gap of a small component (0 if none)
    double largestGap = 0;           //!< max over parts of PartFigures::gap
    int mostPieces = 0;              //!< max over parts of PartFigures::pieces
};

//! Samples every input face at about half the output's mean edge length (the centroids of a
//! regular subdivision, plus the vertices) and finds each sample's closest output point exactly;
//! gives each output component to the input component nearest to most of its vertices.
//! Components through shared edges (non-manifold ones included). Deterministic; OpenMP over
//! samples. An output without faces leaves every gap infinite and no pieces.
PartCoverage measurePartCoverage(const TriMesh& output, const TriMesh& input, const PartCoverageParams& params = {});

}  // namespace fieldcvt
