#include "energy.h"

#include "errors.h"
#include "interpolation.h"
#include "morton_order.h"

#include <cmath>
#include <complex>
#include <utility>

namespace fieldcvt {

Eigen::VectorXd flatten(const std::vector<Vec3>& points)
{
    Eigen::VectorXd x(3 * points.size());
    for (size_t i = 0; i < points.size(); ++i) x.segment<3>(3 * i) = points[i];
    return x;
}

std::vector<Vec3> unflatten(const Eigen::VectorXd& x)
{
    std::vector<Vec3> points(x.size() / 3);
    for (size_t i = 0; i < points.size(); ++i) points[i] = x.segment<3>(3 * i);
    return points;
}

double directionDistance(const Vec3& e, const Vec3& n, const Vec3& d, Vec3* gradient)
{
    // Spherical coordinates of e in {d, m = n × d, n} (§3.4): a = ρ cos φ, b = ρ sin φ with
    // ρ = r sin θ. Then D = 1 − ½ (ρ/r + Re(z⁶) / (ρ⁵ r)) with z = a + ib.
    const Vec3 m = n.cross(d);
    const double a = e.dot(d), b = e.dot(m);
    const double r2 = e.squaredNorm();
    const double rho2 = a * a + b * b;
    if (gradient) gradient->setZero();
    if (!(r2 > 0)) return 1.0;
    const double r = std::sqrt(r2);
    if (!(rho2 > 1e-24 * r2)) return 1.0;  // along the normal: sin θ = 0, D = 1, φ undefined
    const double rho = std::sqrt(rho2);
    const std::complex<double> z(a, b);
    const std::complex<double> z2 = z * z, z5 = z2 * z2 * z, z6 = z5 * z;
    const double rho5 = rho2 * rho2 * rho;
    const double g1 = rho / r;                 // sin θ
    const double g2 = z6.real() / (rho5 * r);  // cos 6φ · sin θ
    if (gradient) {
        // ∂ρ/∂e = t/ρ with t = a d + b m (tangent part); ∂r/∂e = e/r;
        // ∂Re(z⁶)/∂e = 6 (Re(z⁵) d − Im(z⁵) m).
        const Vec3 t = a * d + b * m;
        const Vec3 dg1 = t / (rho * r) - g1 * e / r2;
        const Vec3 dP = 6.0 * (z5.real() * d - z5.imag() * m);
        const Vec3 dg2 = dP / (rho5 * r) - 5.0 * g2 * t / rho2 - g2 * e / r2;
        *gradient = -0.5 * (dg1 + dg2);
    }
    return 1.0 - 0.5 * (g1 + g2);
}

double fieldEnergy(const std::vector<Vec3>& seeds, const std::vector<RvdEdge>& edges, const FieldFrames& frames,
                   Eigen::VectorXd* gradient)
{
    // The terms in parallel (two directionDistance per edge: most of the cost), then summed
    // sequentially in edge order: the same sums whatever the thread count.
    const long long count = static_cast<long long>(edges.size());
    std::vector<double> terms(edges.size(), 0.0);
    std::vector<Vec3> termGradients(gradient ? edges.size() : 0, Vec3::Zero());
#pragma omp parallel for schedule(static)
    for (long long k = 0; k < count; ++k) {
        const RvdEdge& edge = edges[size_t(k)];
        if (!(edge.length > 0)) continue;
        const Vec3 e = seeds[edge.j] - seeds[edge.i];
        // Both directions of the edge, each measured in the frame at its origin (appendix).
        Vec3 gi, gj;
        const double dij = directionDistance(e, frames.normals[edge.i], frames.directions[edge.i], gradient ? &gi : nullptr);
        const double dji = directionDistance(-e, frames.normals[edge.j], frames.directions[edge.j], gradient ? &gj : nullptr);
        terms[size_t(k)] = edge.length * (dij + dji);
        // e_ij = x_j − x_i: ∂D_ij/∂x_i = −∂D/∂e, ∂D_ij/∂x_j = +∂D/∂e; e_ji the other way.
        if (gradient) termGradients[size_t(k)] = edge.length * (gj - gi);
    }
    double energy = 0;  // skipped edges add exact zeros
    for (long long k = 0; k < count; ++k) {
        const RvdEdge& edge = edges[size_t(k)];
        energy += terms[size_t(k)];
        if (gradient) {
            gradient->segment<3>(3 * edge.i) += termGradients[size_t(k)];
            gradient->segment<3>(3 * edge.j) -= termGradients[size_t(k)];
        }
    }
    return energy;
}

EnergyFunction::EnergyFunction(const TriMesh& surface, std::vector<double> faceDensity)
    : surface_(surface), faceDensity_(std::move(faceDensity)), diagram_(surface, faceDensity_)
{
}

void EnergyFunction::setField(const DirectionField* field, const ClosestPointTree* tree, double lambda)
{
    const bool present = field && tree;
    field_ = present ? field : nullptr;
    tree_ = present ? tree : nullptr;
    lambda_ = present ? lambda : 0.0;
    if (present && !walk_) walk_ = std::make_unique<SurfaceWalk>(surface_);
}

ClosestPoint EnergyFunction::closestOnOwnSheet(const Vec3& point, const ClosestPointTree& tree, int faceHint) const
{
    // A short walk over the surface from the hint (the closest point unless another sheet comes
    // nearer: the sample's own sheet), the tree where the walk does not settle or there is no hint.
    bool settled = false;
    ClosestPoint cp;
    if (walk_ && faceHint >= 0) cp = walk_->closestFrom(point, faceHint, &settled, true);
    if (!settled) cp = tree.closest(point, faceHint);
    return cp;
}

void EnergyFunction::setSideAware(const ClosestPointTree* tree)
{
    sideTree_ = tree;
    sideFaces_.clear();
    if (tree && !walk_) walk_ = std::make_unique<SurfaceWalk>(surface_);
}

const std::vector<Vec3>* EnergyFunction::sideNormalsAt(const std::vector<Vec3>& seeds)
{
    if (!sideTree_) return nullptr;
    sideFaces_.resize(seeds.size(), -1);
    sideNormals_.resize(seeds.size());
#pragma omp parallel for schedule(static)
    for (long long k = 0; k < static_cast<long long>(seeds.size()); ++k) {
        const ClosestPoint cp = closestOnOwnSheet(seeds[k], *sideTree_, sideFaces_[k]);
        sideFaces_[k] = cp.face;
        const Vec3 n = faceNormal(surface_, cp.face);
        const double length = n.norm();
        sideNormals_[k] = length > 0 ? Vec3(n / length) : Vec3::Zero();
    }
    return &sideNormals_;
}

const RvdResult& EnergyFunction::diagram(const std::vector<Vec3>& seeds, const RvdOptions& options)
{
    RvdOptions sided = options;
    sided.seedNormals = sideNormalsAt(seeds);
    diagram_.compute(seeds, sided, rvd_);
    rvdOfSeeds_ = false;
    return rvd_;
}

const RvdResult& EnergyFunction::diagramAt(const std::vector<Vec3>& seeds)
{
    if (rvdOfSeeds_ && seeds == seeds_) return rvd_;
    return diagram(seeds, RvdOptions{});
}

FieldFrames EnergyFunction::framesAt(const std::vector<Vec3>& points) const
{
    std::vector<int> faces(points.size(), -1);
    return framesAt(points, faces);
}

FieldFrames EnergyFunction::framesAt(const std::vector<Vec3>& points, std::vector<int>& faces) const
{
    // Queries in Morton order: consecutive ones walk the same branches of the tree (cache).
    return framesAt(points, faces, mortonIndexOrder(points));
}

FieldFrames EnergyFunction::framesAt(const std::vector<Vec3>& points, std::vector<int>& faces,
                                     const std::vector<int>& order) const
{
    FieldFrames frames;
    frames.normals.resize(points.size());
    frames.directions.resize(points.size());
    if (!field_ || !tree_) return frames;
    if (order.size() != points.size()) throw InvalidInputError("framesAt: the query order does not match the points");
    faces.resize(points.size(), -1);
#pragma omp parallel for schedule(static)
    for (long long k = 0; k < static_cast<long long>(points.size()); ++k) {
        const int i = order[k];
        // From the hint, a short walk over the surface to the nearest point around it (a
        // sample moves little between evaluations: a few faces at most); the tree only where
        // the walk does not settle (no hint, or a sample that jumped). The walk's answer is the
        // closest point except where another sheet of the surface comes nearer, where the
        // sample's own sheet is the one its cell lies on. Faster than the tree alone, with the
        // same figures (docs/tuning.md, "Frames by a walk from the hint").
        const ClosestPoint cp = closestOnOwnSheet(points[i], *tree_, faces[i]);
        faces[i] = cp.face;
        const FieldSample s = interpolateField(surface_, *field_, cp.face, cp.barycentric);
        frames.normals[i] = s.normal;
        frames.directions[i] = s.direction;
    }
    return frames;
}

EnergyValue EnergyFunction::evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& gradient)
{
    seeds_.resize(x.size() / 3);
    for (size_t i = 0; i < seeds_.size(); ++i) seeds_[i] = x.segment<3>(3 * i);
    RvdOptions options;
    options.edges = field_ != nullptr;
    options.seedNormals = sideNormalsAt(seeds_);
    diagram_.compute(seeds_, options, rvd_);
    rvdOfSeeds_ = true;

    EnergyValue value;
    gradient.resize(x.size());
    for (size_t i = 0; i < seeds_.size(); ++i) {
        value.cvt += rvd_.energy[i];
        // ∂E_CVT/∂x_i = 2 m_i (x_i − c_i) = 2 (m_i x_i − ∫_cell x dσ)   (§4.3, [DFG99])
        gradient.segment<3>(3 * i) = 2.0 * (rvd_.mass[i] * seeds_[i] - rvd_.moment[i]);
    }
    if (field_) {
        // Frames and weights are frozen for this evaluation (appendix).
        if (frameOrder_.size() != seeds_.size()) frameOrder_ = mortonIndexOrder(seeds_);
        frames_ = framesAt(seeds_, frameFaces_, frameOrder_);
        if (lambda_ > 0) {
            fieldGradient_.setZero(x.size());
            value.field = fieldEnergy(seeds_, rvd_.edges, frames_, &fieldGradient_);
            gradient += lambda_ * fieldGradient_;
        } else {
            value.field = fieldEnergy(seeds_, rvd_.edges, frames_, nullptr);  // measured only
        }
    }
    for (size_t i = 0; i < frozen_.size() && i < seeds_.size(); ++i)
        if (frozen_[i]) gradient.segment<3>(3 * i).setZero();
    value.total = value.cvt + lambda_ * value.field;
    ++evaluations_;
    if (onEvaluation) onEvaluation(value);
    return value;
}

}  // namespace fieldcvt
