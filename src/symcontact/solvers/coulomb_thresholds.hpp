#pragma once
/// \file coulomb_thresholds.hpp
/// Coulomb friction as the lagged term of a load step's outer loop (lagged_fixed_point.hpp): the thresholds τ
/// of the regularised-Tresca friction term (friction_state.hpp) lag the normal pressure, τ = μ p (Raous 1999,
/// eq. 17; Algorithm 1 of the talk, METHOD.md).
///  - Data: τ at the nodes of the slave surface of each pair's friction family. Tresca pairs hold their given
///    τ and lag nothing; pairs without friction hold none.
///  - Start: τ_0 = 0 (cold: the first solve is frictionless), or from the second load step on the thresholds
///    the previous step converged to (warm), optionally extrapolated along the previous increment
///    (FrictionalOptions::extrapolate). Under large sliding a frictionless solve lets everything friction held
///    spring back (a dragged flexible die: 40 % of the solution's size), and dragging it back is a large step
///    for the geometry fixed point (2D ironing); the warm start also saves one contact solve per step.
///  - Residual: r_p = μ_p p_p − τ_p, p the nodal pressure (clamped at 0) recovered from the solve's contact
///    forces at the nodes its multipliers act on (surface_tractions.hpp), along the interface normal.
///  - Update: τ ← max(0, τ + ω r).
///  - Inside a solve (follow_iterates(), CoulombUpdate::kInsideOptimizer): the optimiser hands each iterate
///    to follow() (ThresholdFollower, friction_state.hpp), which sets τ ← max(0, μ p) from the force the bodies
///    exert on the surfaces there, until the relative change falls below the tolerance. It stops following
///    for the rest of a solve after kMaxFollows changes or when the change has made no new low in kStall
///    calls (a cycle); the outer loop then goes on from where it stopped.

#include <vector>

#include "symcontact/contact/contact_set.hpp"
#include "symcontact/core/log.hpp"
#include "symcontact/fem/dof_map.hpp"
#include "symcontact/solvers/friction_state.hpp"
#include "symcontact/solvers/lagged_fixed_point.hpp"

namespace symcontact {

class CoulombThresholds final : public LaggedTerm, public ThresholdFollower {
 public:
  /// The thresholds a step starting at u begins with: those of `previous` (the previous step's state, null for
  /// the first step) extrapolated by s_extrapolate ≥ 0 (0: not), or cold ones. The state's u_start is u; its
  /// previous_tau those of `previous`, or on the first step the cold ones (the unloaded start's).
  CoulombThresholds(const ContactSet& contacts, const DofMap& dofs, const VectorXd& u, const FrictionState* previous,
                    double s_extrapolate, const Logger& log);

  /// Whether any pair has friction (false: the solves take no friction term).
  bool any_friction() const { return any_friction_; }
  /// The thresholds of the next solve, with the slip reference u_start.
  const FrictionState& state() const { return state_; }

  std::string loop_name() const override { return "Coulomb"; }
  std::string data_name() const override { return "threshold"; }
  std::string advice() const override;
  bool lags() const override { return any_coulomb_; }
  bool warm() const override { return warm_; }
  void start_cold() override;
  const std::vector<Eigen::VectorXd>& data() const override { return state_.nodal_tau; }
  std::vector<Eigen::VectorXd> residual(const VectorXd& u, const SolveReport& solve) const override;
  void update(const std::vector<Eigen::VectorXd>& r, double omega) override;
  void set_data(const std::vector<Eigen::VectorXd>& data) override { state_.nodal_tau = data; }

  /// The thresholds follow the optimiser's iterates until they change by less than `tolerance` (relative):
  /// state().follower is this object.
  void follow_iterates(double tolerance);
  void start_solve() override;
  bool follow(const VectorXd& u, const VectorXd& force) override;

 private:
  /// r_p = μ_p p_p − τ_p, p read from the contact force `force` at u.
  std::vector<Eigen::VectorXd> law_residual(const VectorXd& u, const VectorXd& force) const;

  const ContactSet& contacts_;
  const DofMap& dofs_;
  const Logger& log_;
  FrictionState state_;
  bool any_friction_ = false, any_coulomb_ = false;
  bool warm_ = false;  ///< the thresholds come from the previous step, or followed an iterate
  double follow_tolerance_ = 0.0;
  struct FollowCount {
    int changes = 0, since_low = 0;
    double low = 0.0;
    bool stopped = false;
  } follow_;  ///< of the current solve
};

}  // namespace symcontact
