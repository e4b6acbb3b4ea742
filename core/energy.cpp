#include "energy.h"

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

EnergyFunction::EnergyFunction(const TriMesh& surface) : diagram_(surface) {}

const RvdResult& EnergyFunction::diagram(const std::vector<Vec3>& seeds, const RvdOptions& options)
{
    diagram_.compute(seeds, options, rvd_);
    return rvd_;
}

EnergyValue EnergyFunction::evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& gradient)
{
    seeds_.resize(x.size() / 3);
    for (size_t i = 0; i < seeds_.size(); ++i) seeds_[i] = x.segment<3>(3 * i);
    diagram_.compute(seeds_, RvdOptions{}, rvd_);

    EnergyValue value;
    gradient.resize(x.size());
    for (size_t i = 0; i < seeds_.size(); ++i) {
        value.cvt += rvd_.energy[i];
        // ∂E_CVT/∂x_i = 2 m_i (x_i − c_i) = 2 (m_i x_i − ∫_cell x dσ)   (§4.3, [DFG99])
        gradient.segment<3>(3 * i) = 2.0 * (rvd_.mass[i] * seeds_[i] - rvd_.moment[i]);
    }
    value.total = value.cvt;
    ++evaluations_;
    if (onEvaluation) onEvaluation(value);
    return value;
}

}  // namespace fieldcvt
