#pragma once
// The objective minimised over the sample positions X: E_tot = E_CVT + λ·E_field (§3).
// E_CVT (eq. 1) with ∂E/∂x_i = 2 m_i (x_i − c_i) (§4.3); E_field (eq. 2–3) over the restricted
// Delaunay edges, weighted by the length of the dual RVD edge (§3.5), with the gradient of the
// paper's appendix (normal, direction and weights held fixed within an evaluation).
#include "closest_point.h"
#include "field.h"
#include "mesh.h"
#include "rvd.h"

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <vector>

namespace fieldcvt {

//! Seeds <-> the flat coordinate vector the optimiser works on (x0 y0 z0 x1 ...).
Eigen::VectorXd flatten(const std::vector<Vec3>& points);
std::vector<Vec3> unflatten(const Eigen::VectorXd& x);

//! The 6-RoSy direction distance of eq. 3 for edge vector e in the frame {d, n × d, n}:
//! D = 1 − ((1 + cos 6φ) / 2) · sin θ ∈ [0, 1], 0 on a field direction, 60°-periodic in φ.
//! cos 6φ comes from the tangent components as Re((a + ib)⁶) / ρ⁶ (no trigonometry). If
//! `gradient` is given it receives ∂D/∂e (zero where e is parallel to n, where φ is undefined).
double directionDistance(const Vec3& e, const Vec3& n, const Vec3& d, Vec3* gradient = nullptr);

struct EnergyValue {
    double cvt = 0;    //!< E_CVT
    double field = 0;  //!< E_field (0 while λ = 0)
    double total = 0;  //!< E_CVT + λ E_field
};

//! The field as the energy sees it: per-sample frames interpolated (§4.2) at the samples'
//! closest points on the surface.
struct FieldFrames {
    std::vector<Vec3> normals;
    std::vector<Vec3> directions;
};

//! E_field (eq. 2) for frozen frames and weights: Σ over RVD edges (i, j) of
//! w_ij·D(x_j − x_i, n_i, d_i) + w_ij·D(x_i − x_j, n_j, d_j); adds ∂E_field/∂x into `gradient`
//! (3n, not cleared) if given.
double fieldEnergy(const std::vector<Vec3>& seeds, const std::vector<RvdEdge>& edges, const FieldFrames& frames,
                   Eigen::VectorXd* gradient);

//! Evaluates the energy and its gradient on one surface; owns the RVD work space.
class EnergyFunction {
public:
    //! `faceDensity`: ρ per face of `surface` for eq. 1 (density.h), empty for ρ = 1.
    explicit EnergyFunction(const TriMesh& surface, std::vector<double> faceDensity = {});
    //! ρ per face (empty: uniform).
    const std::vector<double>& faceDensity() const { return faceDensity_; }

    //! Sets the field (null: none) and the weight λ of E_field. With a field and λ = 0, E_field
    //! is measured (EnergyValue::field) but does not enter E_tot. The field lives on `surface`
    //! (the one given to the constructor); `tree` answers closest-point queries on it. Both
    //! must outlive the energy.
    void setField(const DirectionField* field, const ClosestPointTree* tree, double lambda);
    double lambda() const { return lambda_; }

    //! Samples whose gradient is set to zero (e.g. samples held on the open border).
    void setFrozen(std::vector<char> frozen) { frozen_ = std::move(frozen); }
    const std::vector<char>& frozen() const { return frozen_; }

    //! E at `x` (flattened seeds); writes ∂E/∂x into `gradient` (resized).
    EnergyValue evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& gradient);

    //! Side-aware cells (RvdOptions::seedNormals) from now on, each sample's normal the face
    //! normal at its closest point on the surface (`tree`, the surface's); null: off.
    void setSideAware(const ClosestPointTree* tree);
    bool sideAware() const { return sideTree_ != nullptr; }

    //! Computes the RVD of `seeds` with the requested extras (no energy bookkeeping).
    const RvdResult& diagram(const std::vector<Vec3>& seeds, const RvdOptions& options);

    //! The masses, moments and energies of the RVD of `seeds`: the last evaluation's when it was
    //! of exactly these seeds (the optimiser's last step is usually the point it returns), else
    //! computed like diagram(seeds, RvdOptions{}).
    const RvdResult& diagramAt(const std::vector<Vec3>& seeds);

    //! The field frames at `points` (their closest points on the surface).
    FieldFrames framesAt(const std::vector<Vec3>& points) const;
    //! The same; `faces` holds a hint per point (the face of a nearby answer, or -1) and
    //! receives the face of each answer. With a hint the answer is the nearest point of the
    //! surface around it (SurfaceWalk: the closest point unless another sheet comes nearer),
    //! the closest point where that walk does not settle or there is no hint.
    FieldFrames framesAt(const std::vector<Vec3>& points, std::vector<int>& faces) const;
    //! The same, the points queried in the order `queryOrder` (a permutation of their indices;
    //! only the speed depends on it: nearby queries one after the other share the tree's cache).
    FieldFrames framesAt(const std::vector<Vec3>& points, std::vector<int>& faces, const std::vector<int>& queryOrder) const;

    //! Per sample, the face of its frame's point at the last evaluation with the field (empty
    //! before one): a hint for closest-point queries near the samples.
    const std::vector<int>& lastFrameFaces() const { return frameFaces_; }
    //! The RVD of the last evaluate() / diagram() call.
    const RvdResult& lastDiagram() const { return rvd_; }
    //! Frees the last diagram (lastDiagram() is empty afterwards) and the diagram's work space:
    //! once the mesh is extracted neither is needed, and the extraction's cell pieces and their
    //! links were the largest memory of a run (docs/tuning.md, "Memory of the diagram"). A later
    //! evaluation allocates them again.
    void releaseDiagram()
    {
        rvd_ = RvdResult{};
        diagram_.releaseWorkspace();
    }
    int evaluations() const { return evaluations_; }
    //! Called after every evaluation (progress, cancellation: it may throw).
    std::function<void(const EnergyValue&)> onEvaluation;

private:
    const TriMesh& surface_;
    std::vector<double> faceDensity_;
    RestrictedVoronoiDiagram diagram_;
    RvdResult rvd_;
    std::vector<Vec3> seeds_;
    bool rvdOfSeeds_ = false;  //!< rvd_ is the diagram of seeds_ (set by evaluate, cleared by diagram)
    const DirectionField* field_ = nullptr;
    const ClosestPointTree* tree_ = nullptr;
    double lambda_ = 0;
    std::vector<char> frozen_;
    FieldFrames frames_;
    //! Per sample, the face of its closest point at the previous evaluation: samples move
    //! little between evaluations, so it bounds the next closest-point search (same answer).
    std::vector<int> frameFaces_;
    //! The samples' Morton order at the first evaluation with the field, the frames' query order
    //! in every later one (sorting them again cost ~0.3 ms of one thread per evaluation at 5000
    //! samples; they move little, so the order stays nearly as coherent).
    std::vector<int> frameOrder_;
    //! Side-aware cells: the tree (null: off), per sample its closest point's face (a hint for
    //! the next evaluation) and that face's unit normal.
    const ClosestPointTree* sideTree_ = nullptr;
    std::vector<int> sideFaces_;
    std::vector<Vec3> sideNormals_;
    const std::vector<Vec3>* sideNormalsAt(const std::vector<Vec3>& seeds);
    //! The closest point of `point` on its own sheet of the surface, from the face `faceHint`
    //! of a nearby earlier answer (-1: none); `tree` is the surface's.
    ClosestPoint closestOnOwnSheet(const Vec3& point, const ClosestPointTree& tree, int faceHint) const;
    std::unique_ptr<SurfaceWalk> walk_;  //!< on surface_, with a field: the frames' projections
    Eigen::VectorXd fieldGradient_;
    int evaluations_ = 0;
};

}  // namespace fieldcvt
