#pragma once
/// \file geometry_fixed_point.hpp
/// The loop of Algorithm 2 (METHOD.md) for one solve_contact() call:
///
///   repeat  linearise the constraints at U_n (contact/contact_set.hpp);
///           build and solve the subproblem: U_{n+1}, μ (geometry_subproblem.hpp);
///           remove the interior point's barrier offset (polish_strategy.hpp);
///           accelerate while the map is smooth (anderson_acceleration.hpp);
///   until   ‖U_{n+1} − U_n‖∞ / ‖U_{n+1}‖∞ < tolerance,
///
/// with IPOPT tightened when the change stagnates above the tolerance (fixed_point_monitor.hpp), and the
/// contact forces recovered from the final multipliers and the bodies' residual (contact_forces.hpp). Where
/// the linearisation at U_{n+1} gives the subproblem of U_n again (GeometrySubproblem::unchanged(): a pair in
/// the reference geometry, a rigid plane), U_{n+1} solves it: the loop ends there without solving it again.
/// The loop is in geometry_fixed_point.cpp, how it ends (converged, unchanged, stagnated, failed) in
/// geometry_fixed_point_end.cpp.

#include <memory>
#include <vector>

#include "symcontact/core/progress_clock.hpp"
#include "symcontact/solvers/anderson_acceleration.hpp"
#include "symcontact/solvers/contact_solver.hpp"
#include "symcontact/solvers/fixed_point_monitor.hpp"
#include "symcontact/solvers/geometry_subproblem.hpp"
#include "symcontact/solvers/polish_strategy.hpp"

namespace symcontact {

class GeometryFixedPoint {
 public:
  GeometryFixedPoint(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts,
                     const DofMap& dofs, const ContactSolveOptions& options, const Logger& log,
                     const FrictionState* friction);
  /// solve_contact()'s contract (contact_solver.hpp): u the start on entry, the solution on exit.
  SolveReport solve(VectorXd& u);

 private:
  bool iterate(int it, VectorXd& u);
  bool rows_match_previous(int it);
  bool accept_unchanged(int it, const VectorXd& u_it);
  void balance_at_end(ConstrainedProblem& target, const CondensedProblem* condensed, IpoptResult& res);
  void accept(const CondensedProblem* condensed, const IpoptResult& res, double change);
  void after_stagnation(int it, double change, VectorXd& u);
  void accelerate(const VectorXd& x_in, const IpoptResult& res, bool closed, bool same_rows);

  const EnergyTerm& energy_;
  const FixedDofs& fixed_;
  const ContactSet& contacts_;
  const DofMap& dofs_;
  const ContactSolveOptions& options_;
  const Logger& log_;
  SolveReport rep_;
  const std::shared_ptr<ContactWorkspace> workspace_;
  const int factorisations_at_start_;
  GeometrySubproblem subproblem_;
  PolishStrategy polish_;
  std::unique_ptr<AndersonAcceleration> anderson_;
  /// An inexact solve (ContactSolveOptions::loose_geometry_tolerance) is never balanced at the end nor
  /// reported converged, even where its change falls below geometry_tolerance: its answer is an intermediate.
  const bool inexact_;
  const double stop_tolerance_;
  IpoptOptions ipopt_;  ///< the settings of this solve: tightened when the fixed point stagnates
  FixedPointMonitor monitor_;
  int tightenings_ = 0;
  int since_tightening_ = 0;  ///< changes recorded since the last tightening (or the start)
  VectorXd x_;                        ///< the iterate (free DOFs)
  VectorXd mu_prev_;                  ///< the previous rows' multipliers
  std::vector<int> rows_prev_family_;
  std::vector<Index> rows_prev_node_;
  std::vector<char> active_prev_;     ///< rows with μ > 0 after the previous closed polish
  VectorXd residual_b_;  ///< ∇E on the condensed set B at the solution, when the last iteration was condensed
  bool lazy_ = false;    ///< the iterate's interior is out of date (ContactSolveOptions::lazy_interior)
  bool x_solves_last_ = false;  ///< x_ is the last subproblem's solution as it came (no Anderson step)
  ProgressClock clock_;  ///< since the solve started
};

}  // namespace symcontact
