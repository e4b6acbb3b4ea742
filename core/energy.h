#pragma once
// The objective minimised over the sample positions X: E_tot = E_CVT + λ·E_field (§3).
// This file holds E_CVT (eq. 1) and its gradient ∂E/∂x_i = 2 m_i (x_i − c_i) (§4.3).
#include "mesh.h"
#include "rvd.h"

#include <Eigen/Core>
#include <functional>
#include <vector>

namespace fieldcvt {

//! Seeds <-> the flat coordinate vector the optimiser works on (x0 y0 z0 x1 ...).
Eigen::VectorXd flatten(const std::vector<Vec3>& points);
std::vector<Vec3> unflatten(const Eigen::VectorXd& x);

struct EnergyValue {
    double cvt = 0;    //!< E_CVT
    double field = 0;  //!< E_field (0 while λ = 0)
    double total = 0;  //!< E_CVT + λ E_field
};

//! Evaluates the energy and its gradient on one surface; owns the RVD work space.
class EnergyFunction {
public:
    explicit EnergyFunction(const TriMesh& surface);

    //! E at `x` (flattened seeds); writes ∂E/∂x into `gradient` (resized).
    EnergyValue evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& gradient);

    //! Computes the RVD of `seeds` with the requested extras (no energy bookkeeping).
    const RvdResult& diagram(const std::vector<Vec3>& seeds, const RvdOptions& options);

    //! The RVD of the last evaluate() / diagram() call.
    const RvdResult& lastDiagram() const { return rvd_; }
    int evaluations() const { return evaluations_; }
    //! Called after every evaluation (progress, cancellation: it may throw).
    std::function<void(const EnergyValue&)> onEvaluation;

private:
    RestrictedVoronoiDiagram diagram_;
    RvdResult rvd_;
    std::vector<Vec3> seeds_;
    int evaluations_ = 0;
};

}  // namespace fieldcvt
