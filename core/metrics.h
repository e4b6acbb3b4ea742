#pragma once
// Remeshing quality figures of the paper's Table 2 (§5) and topology summaries.
#include "closest_point.h"
#include "metrics_types.h"
#include "mesh.h"

#include <limits>

namespace fieldcvt {

TopologySummary computeTopology(const TriMesh& mesh);

//! Q_min ... V6% of `mesh` (distances left NaN).
QualityMetrics computeQuality(const TriMesh& mesh);

//! Mean length over the distinct (undirected) edges of the faces; 0 without faces. Lengths by
//! stableNorm: no overflow at coordinates of 1e300.
double meanEdgeLength(const TriMesh& mesh);

//! computeQuality(mesh).v6Pct without the rest (no angles).
double v6Percent(const TriMesh& mesh);

struct DistanceMetrics {
    double rms = 0;        //!< root mean square of the symmetric distance samples, / diagonal
    double hausdorff = 0;  //!< symmetric Hausdorff distance, / diagonal
};

//! Symmetric distances between `mesh` and `reference` from exact point-to-triangle distances on
//! dense area-uniform samples of both surfaces (plus their vertices). Deterministic.
//! `referenceTree`, when given, is a closest-point tree of `reference` (the caller's, e.g. the
//! remeshing's tree of its input): the same figures without building another.
DistanceMetrics computeDistance(const TriMesh& mesh, const TriMesh& reference, int samplesPerMesh = 200000,
                                const ClosestPointTree* referenceTree = nullptr);

//! Symmetric Hausdorff distance between the open-boundary curves of `mesh` and `reference`
//! (each sampled every 1e-4 of the reference's diagonal, exact distance to the other's
//! boundary edges), as a fraction of that diagonal. NaN when either has no boundary.
double boundaryDistance(const TriMesh& mesh, const TriMesh& reference);

}  // namespace fieldcvt
