#include "interpolation.h"

#include "errors.h"
#include "field_hierarchy.h"  // rosy:: kernels

#include <algorithm>
#include <cmath>

namespace fieldcvt {

Vec3 rotateRepresentative(const Vec3& d, const Vec3& n, int k)
{
    // Rodrigues' formula with exact cos/sin of the multiples of 60° (no trigonometric calls,
    // so k = 0 returns d bit for bit and k = 3 is −d up to the normal component of d).
    static constexpr double kCos[6] = {1.0, 0.5, -0.5, -1.0, -0.5, 0.5};
    static constexpr double kSin[6] = {0.0, rosy::kSin60, rosy::kSin60, 0.0, -rosy::kSin60, -rosy::kSin60};
    const int m = ((k % 6) + 6) % 6;
    if (m == 0) return d;
    return kCos[m] * d + kSin[m] * n.cross(d) + (1.0 - kCos[m]) * n.dot(d) * n;
}

FieldSample interpolateField(const TriMesh& mesh, const DirectionField& field, int face, const Vec3& barycentric)
{
    if (face < 0 || face >= mesh.faceCount()) throw InvalidInputError("interpolateField: face index out of range");
    const Face& t = mesh.faces[face];
    const double w[3] = {barycentric[0], barycentric[1], barycentric[2]};

    // §4.2: n = normalised Σ w_v n_v (the barycentric coordinates are the harmonic weights of
    // the linear triangle); a degenerate sum falls back to the face normal.
    FieldSample out;
    Vec3 n = w[0] * field.normals[t[0]] + w[1] * field.normals[t[1]] + w[2] * field.normals[t[2]];
    double len = n.norm();
    if (!(len > 1e-12)) {
        n = faceNormal(mesh, face);
        len = n.norm();
        if (!(len > 0)) n = field.normals[t[0]], len = 1;
    }
    n /= len;
    out.normal = n;

    // Weighted representatives: r[v][k] = w_v R^k d_v for k = 0..5, as ±(three of them), so that
    // the six rotations of each vertex are exact negations of one another and combinations that
    // differ by a global 180° turn give bit-identical norms.
    Vec3 r[3][3];
    for (int v = 0; v < 3; ++v) {
        Vec3 reps[3];
        rosy::representatives3(field.directions[t[v]], field.normals[t[v]], reps);
        for (int k = 0; k < 3; ++k) r[v][k] = w[v] * reps[k];
    }
    // Maximise ||(I − nnᵀ) d_w||² = ||d_w||² − (n·d_w)² over the representatives of B and C
    // (6 × 6) for each of A's three lines: d_A's sign does not matter (d_w → −d_w), but its
    // rotation by 60° does when the three normals differ, so A's rotations are searched too —
    // which is what makes the result independent of the representative stored at A, not only
    // at B and C. 108 combinations, no allocation.
    // A pair (ka, kb) whose six sums cannot beat the best so far is skipped: |P(ab + c)| <=
    // |P ab| + |P c| (P = I − nnᵀ), plus a margin far above the rounding of either side, so
    // the skipped sums are never the first maximum and the answer is that of all 108.
    double projectedC = 0, lengthC = 0;
    for (int kc = 0; kc < 3; ++kc) {
        const double nc = n.dot(r[2][kc]), c2 = r[2][kc].squaredNorm();
        projectedC = std::max(projectedC, std::sqrt(std::max(0.0, c2 - nc * nc)));
        lengthC = std::max(lengthC, std::sqrt(c2));
    }
    double best = -1;
    Vec3 bestSum = Vec3::Zero();
    for (int ka = 0; ka < 3; ++ka)
        for (int kb = 0; kb < 6; ++kb) {
            const Vec3 ab = r[0][ka] + (kb < 3 ? r[1][kb] : Vec3(-r[1][kb - 3]));
            if (best >= 0) {
                const double nab = n.dot(ab), ab2 = ab.squaredNorm();
                const double reach = std::sqrt(std::max(0.0, ab2 - nab * nab)) + projectedC;
                const double scale = std::sqrt(ab2) + lengthC;
                if (reach * reach + 1e-9 * scale * scale < best) continue;
            }
            for (int kc = 0; kc < 6; ++kc) {
                const Vec3 sum = ab + (kc < 3 ? r[2][kc] : Vec3(-r[2][kc - 3]));
                const double nd = n.dot(sum);
                const double value = sum.squaredNorm() - nd * nd;
                if (value > best) best = value, bestSum = sum;
            }
        }
    Vec3 d = rosy::projectTangent(bestSum, n);
    len = d.norm();
    if (len > 1e-300)
        out.direction = d / len;
    else {  // all weights zero or perfectly cancelling: any vertex's direction, projected
        d = rosy::projectTangent(field.directions[t[0]], n);
        len = d.norm();
        out.direction = len > 1e-300 ? Vec3(d / len) : rosy::anyTangent(n);
    }
    return out;
}

}  // namespace fieldcvt
