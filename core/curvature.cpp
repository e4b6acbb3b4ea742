#include "curvature.h"

#include "field_hierarchy.h"  // rosy::anyTangent

#include <Eigen/Dense>
#include <cmath>

namespace fieldcvt {

PrincipalCurvature computePrincipalCurvature(const TriMesh& mesh, const std::vector<Vec3>& normals)
{
    const int n = mesh.vertexCount();
    // Normal equations of the per-vertex fit, unknowns (L, M, N) of S = [[L, M], [M, N]] in the
    // frame (u, v) of the tangent plane.
    std::vector<Eigen::Matrix3d> ata(n, Eigen::Matrix3d::Zero());
    std::vector<Eigen::Vector3d> atb(n, Eigen::Vector3d::Zero());
    std::vector<Vec3> us(n), vs(n);
    for (int i = 0; i < n; ++i) {
        us[i] = rosy::anyTangent(normals[i]);
        vs[i] = normals[i].cross(us[i]);
    }
    double edgeSum = 0;
    for (const Face& f : mesh.faces)
        for (int k = 0; k < 3; ++k) {
            const int i = f[k];
            edgeSum += (mesh.vertices[f[(k + 1) % 3]] - mesh.vertices[i]).norm();
            // Each corner sees its two edges; an interior edge is seen from two faces, so half.
            for (int s = 1; s <= 2; ++s) {
                const int j = f[(k + s) % 3];
                const Vec3 e = mesh.vertices[j] - mesh.vertices[i];
                const double len2 = e.squaredNorm();
                if (!(len2 > 0)) continue;
                const Vec3 dn = normals[j] - normals[i];
                const double x = e.dot(us[i]), y = e.dot(vs[i]), a = dn.dot(us[i]), b = dn.dot(vs[i]);
                // Weight 1/|e|²: both sides of dn ≈ S e scale with |e|, so every edge counts alike.
                const double w = 0.5 / len2;
                const Eigen::Vector3d r1(x, y, 0), r2(0, x, y);
                ata[i] += w * (r1 * r1.transpose() + r2 * r2.transpose());
                atb[i] += w * (r1 * a + r2 * b);
            }
        }
    const double meanEdge = mesh.faces.empty() ? 1.0 : edgeSum / (3.0 * mesh.faces.size());

    PrincipalCurvature pc;
    pc.kMax.assign(n, 0.0);
    pc.kMin.assign(n, 0.0);
    pc.dirMax.resize(n);
    pc.dirMin.resize(n);
    pc.reliable.assign(n, 0);
    for (int i = 0; i < n; ++i) {
        pc.dirMax[i] = us[i];
        pc.dirMin[i] = vs[i];
        const Eigen::Matrix3d& m = ata[i];
        const double trace = m.trace();
        // Edges spanning fewer than two tangent directions leave S undetermined.
        if (!(trace > 0) || !(m.determinant() > 1e-10 * trace * trace * trace)) continue;
        const Eigen::Vector3d s = m.ldlt().solve(atb[i]);
        const double L = s[0], M = s[1], N = s[2];
        const double half = 0.5 * (L - N), root = std::sqrt(half * half + M * M);
        const double l1 = 0.5 * (L + N) + root, l2 = 0.5 * (L + N) - root;
        const double phi = 0.5 * std::atan2(2 * M, L - N);  // eigenvector of l1
        const Vec3 t1 = std::cos(phi) * us[i] + std::sin(phi) * vs[i];
        const Vec3 t2 = normals[i].cross(t1);
        const bool firstIsMax = std::abs(l1) >= std::abs(l2);
        pc.kMax[i] = firstIsMax ? l1 : l2;
        pc.kMin[i] = firstIsMax ? l2 : l1;
        pc.dirMax[i] = firstIsMax ? t1 : t2;
        pc.dirMin[i] = firstIsMax ? t2 : t1;
        // Directions are meaningful only where the two magnitudes differ relative to each other
        // (not umbilic) and relative to the sampling (not flat: noise of the fit on a plane).
        const double gap = std::abs(pc.kMax[i]) - std::abs(pc.kMin[i]);
        pc.reliable[i] = gap > 0.05 * (std::abs(pc.kMax[i]) + std::abs(pc.kMin[i])) && gap * meanEdge > 1e-3;
    }
    return pc;
}

}  // namespace fieldcvt
