#pragma once
// Initial samples for the CVT (§5): random points on the surface, area-uniform or following a
// density (adaptive remeshing, density.h).
#include "mesh.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace fieldcvt {

//! `count` points distributed uniformly by area over the surface, from a seeded generator
//! (std::mt19937_64 and our own uniform mapping, so the points are the same on every platform).
std::vector<Vec3> sampleSurfaceUniform(const TriMesh& surface, int count, std::uint64_t seed);

//! `count` points distributed ∝ area × μ_f with μ_f = sqrt(ρ_f), ρ_f the CVT density of face f
//! (density.h: the number of samples per unit area is ∝ μ, not ρ). Empty `faceDensity` gives
//! exactly sampleSurfaceUniform's points.
std::vector<Vec3> sampleSurface(const TriMesh& surface, int count, std::uint64_t seed, const std::vector<double>& faceDensity);

//! Adds samples to every connected component of `surface` (faces through shared vertices) that
//! holds fewer than `minimum` of `points`, at random points of it (area-uniform, from `seed`):
//! a small part kept on its own (repair.h) then becomes a piece of the output, not nothing.
//! `faceOf` gives the face a point lies on; it is called only when the surface has several
//! components. Returns how many points were added.
int topUpSmallComponents(const TriMesh& surface, const std::function<int(const Vec3&)>& faceOf, int minimum, std::uint64_t seed,
                         std::vector<Vec3>& points);

//! Maps a 64-bit random word to [0, 1) with 53 bits (platform-independent, unlike
//! std::uniform_real_distribution).
inline double unitInterval(std::uint64_t word) { return static_cast<double>(word >> 11) * 0x1.0p-53; }

}  // namespace fieldcvt
