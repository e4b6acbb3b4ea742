#pragma once
// The multi-resolution solver behind the extrinsic 6-RoSy field (paper §4.1, after Jakob,
// Tarini, Panozzo, Sorkine-Hornung 2015, "Instant field-aligned meshes", §4–5): a hierarchy of
// vertex graphs built by greedy pairwise clustering, and coarse-to-fine Gauss–Seidel smoothing
// with the extrinsic compatibility of their eq. 3. Internal to field.cpp and curvature users;
// the public API is field.h.
#include "field_types.h"
#include "mesh.h"

#include <cstdint>
#include <vector>

namespace fieldcvt {

namespace rosy {

constexpr double kSin60 = 0.86602540378443864676;  // sin(60°) = √3/2

//! v projected on the plane orthogonal to the unit normal n.
inline Vec3 projectTangent(const Vec3& v, const Vec3& n) { return v - n.dot(v) * n; }

//! The three representatives d, R60·d, R120·d of a tangent direction d ⟂ n (the other three
//! are their negatives, since R180 = −I on the tangent plane). Rodrigues' formula with
//! n·d = 0.
inline void representatives3(const Vec3& d, const Vec3& n, Vec3 out[3])
{
    const Vec3 c = n.cross(d);
    out[0] = d;
    out[1] = 0.5 * d + kSin60 * c;
    out[2] = -0.5 * d + kSin60 * c;
}

//! The extrinsic compatibility of Jakob et al. 2015 (eq. 3, `compat_orientation_extrinsic_6`
//! idea): among the 6×6 pairs of representatives of (d_i, n_i) and (d_j, n_j), the pair closest
//! in 3D. Because the 6 representatives are ±(3 of them), it suffices to take the 3×3 pair
//! with the largest |dot| and flip the sign of j's. Returns k_i ∈ {0,1,2} (i's representative
//! R^{k_i}·d_i) and, in b, j's representative (unit).
inline int matchExtrinsic(const Vec3& di, const Vec3& ni, const Vec3& dj, const Vec3& nj, Vec3& b)
{
    Vec3 a[3], c[3];
    representatives3(di, ni, a);
    representatives3(dj, nj, c);
    int bi = 0, bj = 0;
    double best = -1;
    for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) {
            const double dp = std::abs(a[p].dot(c[q]));
            if (dp > best) best = dp, bi = p, bj = q;
        }
    b = a[bi].dot(c[bj]) < 0 ? Vec3(-c[bj]) : c[bj];
    return bi;
}

//! Squared 3D distance between the closest pair of representatives (one edge of eq. 3).
inline double edgeEnergy(const Vec3& di, const Vec3& ni, const Vec3& dj, const Vec3& nj)
{
    Vec3 b;
    const int k = matchExtrinsic(di, ni, dj, nj, b);
    Vec3 a[3];
    representatives3(di, ni, a);
    return (a[k] - b).squaredNorm();
}

//! v (tangent at the unit normal `from`) carried to the tangent plane of the unit normal `to` by
//! the smallest rotation taking `from` to `to` (Rodrigues' formula about from × to): the
//! discrete Levi-Civita transport along an edge that the intrinsic compatibility of Jakob et
//! al. 2015 (`rotate_vector_into_plane`) uses. Identity when the normals are (nearly) opposite,
//! where that rotation is not defined.
inline Vec3 rotateIntoPlane(const Vec3& v, const Vec3& from, const Vec3& to)
{
    const double c = from.dot(to);
    if (!(c > -1 + 1e-9)) return v;
    const Vec3 axis = from.cross(to);  // |axis| = sin θ, so (1 − cos θ)/sin² θ = 1/(1 + cos θ)
    return c * v + axis.cross(v) + (axis.dot(v) / (1 + c)) * axis;
}

//! Squared distance between the closest pair of representatives after carrying (d_j, n_j) to
//! i's tangent plane (rotateIntoPlane): the intrinsic counterpart of edgeEnergy. It vanishes
//! for a field that is parallel for that transport, e.g. any constant-angle field on a
//! cylinder, where the extrinsic energy is zero only along the axis.
inline double edgeEnergyIntrinsic(const Vec3& di, const Vec3& ni, const Vec3& dj, const Vec3& nj)
{
    return edgeEnergy(di, ni, rotateIntoPlane(dj, nj, ni), ni);
}

//! A unit vector orthogonal to the unit vector n (deterministic).
Vec3 anyTangent(const Vec3& n);

}  // namespace rosy

//! One level of the hierarchy: a weighted vertex graph with a position, a unit normal and an
//! area per vertex (CSR adjacency, both directions stored).
struct FieldGraph {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;
    std::vector<double> areas;
    std::vector<int> offsets;  //!< size V + 1
    std::vector<int> neighbours;
    std::vector<double> weights;  //!< per directed entry (number of finest edges it stands for)
    //! Vertices grouped by a greedy colouring (no two neighbours share a colour), so one
    //! colour class can be updated in parallel with the result of a sequential sweep.
    std::vector<int> colourOffsets;
    std::vector<int> colourVertices;

    int vertexCount() const { return static_cast<int>(positions.size()); }
};

struct FieldHierarchyLevels {
    std::vector<FieldGraph> levels;         //!< [0] = the input mesh's vertices
    std::vector<std::vector<int>> parents;  //!< parents[l][v]: v's vertex in level l + 1
};

//! Per vertex of the input mesh: whether its direction is prescribed, and the direction
//! (tangent, unit). Empty vectors = no constraint.
struct FieldConstraints {
    std::vector<unsigned char> fixed;
    std::vector<Vec3> directions;
    int count() const;
};

//! Level 0 from the mesh's edges (unit weights), then levels of about half the vertices by
//! greedy matching of the edges (Jakob et al. 2015, §5 "hierarchy"), until a few dozen remain.
FieldHierarchyLevels buildFieldHierarchy(const TriMesh& mesh, const std::vector<Vec3>& normals);

//! Σ_edges w_ij ||d_i' − d_j'||² over the graph (each undirected edge once); with `intrinsic`,
//! d_j is first carried to i's tangent plane (rosy::edgeEnergyIntrinsic).
double graphEnergy(const FieldGraph& graph, const std::vector<Vec3>& directions, bool intrinsic = false);

//! `iterations` Gauss–Seidel sweeps over `graph` (colour class by colour class). Each free
//! vertex's direction becomes the exact minimiser of its local energy for the current matching:
//! normalise(P_i Σ_j w_ij R_i^{-k_j} b_j), where (R_i^{k_j} d_i, b_j) is the closest pair with
//! neighbour j. Keeping the matching fixed, this cannot raise the energy; re-matching can only
//! lower it further, so the energy is non-increasing sweep after sweep. Appends the energy
//! after each sweep to `energies` when given. With `intrinsic`, each neighbour's frame is first
//! carried to i's tangent plane (rosy::rotateIntoPlane) and the energy is the intrinsic one.
void smoothLevel(const FieldGraph& graph, std::vector<Vec3>& directions, const std::vector<unsigned char>* fixed, int iterations,
                 std::vector<double>* energies = nullptr, bool intrinsic = false);

//! The whole multi-resolution solve: random tangent directions at level 0 from
//! std::mt19937_64(seed), restricted up the hierarchy, then from the coarsest level down:
//! smooth, prolongate (project the parent's direction on the child's tangent plane).
//! Constrained vertices (and coarse vertices containing one) keep their direction. `intrinsic`
//! selects the energy of every level (smoothLevel); the report's energies are that energy.
//! `hierarchy` (if given) receives the hierarchy the field was solved on (buildFieldHierarchy of
//! mesh and normals), for the lattice start to reuse.
std::vector<Vec3> solveField(const TriMesh& mesh, const std::vector<Vec3>& normals, const FieldConstraints& constraints,
                             std::uint64_t seed, int iterations, FieldReport* report, bool intrinsic = false,
                             FieldHierarchyLevels* hierarchy = nullptr);

//! The 6-RoSy-compatible average of tangent directions at a vertex of normal n: each next one
//! is added as its representative closest to the running sum. Returns false when it vanishes.
bool averageCompatible(const Vec3& n, const Vec3* vectors, int count, Vec3& out);

}  // namespace fieldcvt
