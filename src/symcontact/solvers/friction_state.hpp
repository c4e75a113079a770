#pragma once
/// \file friction_state.hpp
/// The friction thresholds of one regularised-Tresca solve and the friction terms they give at a geometry
/// iterate (METHOD.md, eq. 16: j_{α,τ}(u) = Σ_k A_k τ_k sqrt(|s_k(u)|² + α²), s_k the slip increment of node
/// k of the pair's friction family since the start of the load step).

#include <memory>
#include <vector>

#include "symcontact/contact/contact_set.hpp"
#include "symcontact/contact/friction_term.hpp"

namespace symcontact {

/// Thresholds that follow a solve's own iterates between the optimiser's iterations (Coulomb's τ = μ p with
/// p read from the iterate: FrictionalOptions::coulomb_update), instead of staying fixed for the solve.
class ThresholdFollower {
 public:
  virtual ~ThresholdFollower() = default;
  /// A solve of the optimiser starts (its budget of changes restarts).
  virtual void start_solve() = 0;
  /// Sets FrictionState::nodal_tau from the displacement u of the surfaces and the bodies' force on them,
  /// ∇E(u) at their free DOFs (full-DOF vectors, the force zero elsewhere). Returns whether they changed: not
  /// when the change is below the follower's tolerance, nor once it has stopped following in this solve.
  virtual bool follow(const VectorXd& u, const VectorXd& force) = 0;
};

/// Friction thresholds for one solve (regularised Tresca, Algorithm 2 with j_{α,τ} added).
struct FrictionState {
  /// Per pair: τ at the nodes of the slave surface of the pair's friction family (empty: no friction).
  std::vector<Eigen::VectorXd> nodal_tau;
  VectorXd u_start;  ///< displacement at the start of the load step (slip increments are measured from it)
  /// The thresholds the previous load step converged to (on the first step the unloaded start's: its cold
  /// thresholds): with nodal_tau, the last two steps' τ for the predictor of the next step
  /// (FrictionalOptions::extrapolate).
  std::vector<Eigen::VectorXd> previous_tau;
  /// Sets nodal_tau from the solve's iterates (null: the thresholds are fixed during a solve).
  ThresholdFollower* follower = nullptr;
};

/// The nodal friction points of pair p's friction family at the displacement u (at X for a pair in
/// ContactGeometry::kReference: contact_geometry.hpp).
std::vector<ContactPoint> nodal_friction_points(const ContactSet& contacts, int p, const DofMap& dofs,
                                                const VectorXd& u_iterate);

/// The friction term of every pair at the displacement u (null for a pair without thresholds), integrated
/// node by node: node k of the slave surface carries its own weight A_k, slip and threshold τ_k, so that
/// σ_T = −τ_k s_k / sqrt(|s_k|² + α²) holds at every node with the same lumped A_k the pressure is recovered
/// with, and the nodal law |σ_T| ≤ μ σ_n with it (on Tri6 surfaces, in the test basis of the pressure, s_k
/// the slip's coefficient there: friction_term.hpp). (A quadrature of the interpolated τ and s would mix
/// neighbouring nodes' thresholds and break the law where the pressure varies, at the ends of a dragged
/// block for instance.) A self-contact surface holds both sides of its interface and every node of it
/// carries a friction point: j_τ counts the interface once, so each side carries half the weight. With a
/// follower the terms keep the Hessian blocks of zero thresholds (FrictionTerm::keep_zero_blocks).
std::vector<std::shared_ptr<FrictionTerm>> friction_terms(const FrictionState& state, const ContactSet& contacts,
                                                                const DofMap& dofs, const VectorXd& u);

}  // namespace symcontact
