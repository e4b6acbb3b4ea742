#pragma once
// A field-aligned start for the CVT: the position field of Instant Meshes (Jakob, Tarini, Panozzo,
// Sorkine-Hornung 2015, §4.2, "position field") on the hierarchy the 6-RoSy field is solved on,
// and the lattice points it defines as the initial samples. Each vertex i carries the origin o_i
// of a triangular lattice {o_i + ρ(a·d_i + b·R60·d_i) : a, b integers} in its tangent plane,
// d_i its field direction (the six directions give the same lattice); smoothing makes
// neighbouring lattices agree, so their points form one field-aligned lattice over the surface,
// broken only at the field's singularities. Random samples instead start the CVT with
// dislocations (5–7 pairs) that neither the CVT nor the valence optimisation can remove once
// the samples have settled.
#include "field.h"
#include "lattice_params.h"
#include "mesh.h"

#include <cstdint>
#include <vector>

namespace fieldcvt {

struct FieldHierarchyLevels;

//! The lattice point of {origin + spacing·(a·d + b·R60·d)} (d, R60·d ⟂ n, |d| = 1) nearest to
//! `target` projected on that lattice's plane.
Vec3 nearestLatticePoint(const Vec3& origin, const Vec3& d, const Vec3& n, double spacing, const Vec3& target);

//! The point nearest to the midpoint of p0 and p1 that lies on both tangent planes (p0, n0) and
//! (p1, n1) (regularised where the planes are nearly parallel): where two neighbours' lattices
//! are compared.
Vec3 middlePoint(const Vec3& p0, const Vec3& n0, const Vec3& p1, const Vec3& n1);

//! Per vertex of `surface`: the lattice origin after the multi-resolution smoothing (the lattice
//! point nearest to the vertex). Deterministic and independent of the thread count.
std::vector<Vec3> solvePositionField(const TriMesh& surface, const DirectionField& field, double spacing, int iterations,
                                     std::uint64_t seed = 1);

//! The spacing ρ at which the lattice over `surface` has about `count` points: one per
//! √3/2·ρ² of area, plus half a row along the border (the rows at a border lie on it, so a
//! strip h high holds h/(√3/2·ρ) + 1 rows, not h/(√3/2·ρ)).
double latticeSpacingFor(const TriMesh& surface, int count);

//! About `count` lattice points over `surface` (the position field solved at
//! latticeSpacingFor(surface, count), and again at corrected spacings while the count is off by
//! more than params.countTolerance): each face's points, taken from its corners' lattices,
//! with those that coincide (closer than half the spacing) merged into one. The points lie on
//! the corners' tangent planes, not yet on the surface.
//! `hierarchy`: buildFieldHierarchy(surface, field.normals) if the caller has it (computeField
//! hands it out), else null and it is built here. `sampleFaces` (if given) receives, per point,
//! a face it was taken from (a hint for its closest point on the surface).
std::vector<Vec3> latticeSamples(const TriMesh& surface, const DirectionField& field, int count, const LatticeParams& params,
                                 LatticeReport* report = nullptr, const FieldHierarchyLevels* hierarchy = nullptr,
                                 std::vector<int>* sampleFaces = nullptr);

}  // namespace fieldcvt
