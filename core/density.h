#pragma once
// Adaptive sizing: a vertex density μ > 0 per surface vertex and the CVT
// density ρ of eq. 1 derived from it.
//
// Semantics. μ is a *vertex density*: the number of output vertices per unit area is ∝ μ, so
// the target edge length is ∝ 1/sqrt(μ). In a 2D CVT the cell diameter scales as ρ^(-1/4)
// (Gersho's conjecture), hence the CVT density is ρ = μ². ρ is piecewise constant per input
// triangle (the mean of its corners' μ²), which keeps the RVD integrals exact; the initial
// and Lloyd re-seeding samples are drawn ∝ area × sqrt(ρ_f) (≈ area × μ).
#include "mesh.h"

#include <vector>

namespace fieldcvt {

//! Per-vertex μ from curvature: μ = (1 + gradation · κ̂)² with κ̂ = sqrt(k1² + k2²) · h (the
//! curvature magnitude in units of the uniform target edge length `edgeLength`, so the result
//! does not depend on the model's scale), clamped to at most 25× its minimum (edge lengths vary
//! at most 5×) and smoothed by Laplacian steps over about one target edge length, so that the
//! sizing is graded. Not normalised. gradation = 0 gives all ones.
std::vector<double> curvatureDensity(const TriMesh& surface, double gradation, double edgeLength);

//! The user's μ (one per *input* vertex: finite and > 0, else InvalidInputError) on the
//! cleaned surface: `cleanIndex` maps input vertices to surface vertices (mesh_check.h); a
//! surface vertex merged from several input vertices gets their mean.
std::vector<double> densityOnSurface(const std::vector<double>& perInputVertex, const std::vector<int>& cleanIndex,
                                     int surfaceVertexCount);

//! Scales μ so that its area-weighted mean over the surface is 1 (∫μ dA = area): the number of
//! samples per unit area is then 1 on average, like the uniform normalisation of §5.
void normaliseDensity(const TriMesh& surface, std::vector<double>& mu);

//! ρ per face: the mean of its corners' μ². Empty `mu` gives an empty result (uniform ρ = 1).
std::vector<double> faceDensity(const TriMesh& surface, const std::vector<double>& mu);

}  // namespace fieldcvt
