#include "symcontact/solvers/frictional_contact.hpp"

#include <sstream>

#include "symcontact/solvers/contact_solver.hpp"
#include "symcontact/solvers/coulomb_thresholds.hpp"
#include "symcontact/solvers/lagged_fixed_point.hpp"
#include "symcontact/solvers/subproblem_solver.hpp"

namespace symcontact {

namespace {

/// Thresholds that follow the optimiser stop moving below this fraction of the loop's tolerance, so that the
/// loop's own test, on the answer, finds them settled.
constexpr double kFollowTolerance = 0.1;

/// s such that this step's Dirichlet increment (fixed values − u) is s times the previous step's
/// (u − u_previous_start) on every fixed DOF, to 1e-8 of the largest; 0 when they are not proportional
/// (a new direction of loading: pressing, then pushing) or either is zero.
double proportional_increment(const FixedDofs& fixed, const VectorXd& u, const VectorXd& u_previous_start) {
  if (u_previous_start.size() != u.size() || fixed.dofs.empty()) return 0.0;
  const Index n = static_cast<Index>(fixed.dofs.size());
  Eigen::VectorXd now(n), before(n);
  for (Index k = 0; k < n; ++k) {
    const Index d = fixed.dofs[k];
    now[k] = fixed.values[k] - u[d];
    before[k] = u[d] - u_previous_start[d];
  }
  const double bb = before.squaredNorm();
  if (!(bb > 0.0) || !(now.squaredNorm() > 0.0)) return 0.0;
  const double s = now.dot(before) / bb;
  if (!(s > 0.0) || (now - s * before).lpNorm<Eigen::Infinity>() > 1e-8 * now.lpNorm<Eigen::Infinity>()) return 0.0;
  return s;
}

/// Makes u whole (complete_interior) when the load step ends, also when it throws: a throw in flight
/// completes what can be, and nothing is thrown from the destructor.
struct CompleteOnExit {
  const EnergyTerm& energy;
  const FixedDofs& fixed;
  VectorXd& u;
  ContactWorkspace* ws;
  void now() {
    if (ws) complete_interior(energy, fixed, u, *ws);
  }
  ~CompleteOnExit() {
    try {
      now();
    } catch (...) {
    }
  }
};

/// Whether the thresholds follow the optimiser (CoulombUpdate::kInsideOptimizer): where the primal interior
/// point solves the subproblems of linear-elastic bodies (primal_interior_point_first(): condensed or not; the
/// condensed ones of 2D pairs), the only optimiser that calls Subproblem::follow.
bool follows_optimizer(const EnergyTerm& energy, const ContactSet& contacts, int dim, const FrictionalOptions& o) {
  return o.coulomb_update == CoulombUpdate::kInsideOptimizer && energy.hessian_is_constant() &&
         primal_interior_point_first(contacts, dim, o.contact.subproblem_solver);
}

}  // namespace

SolveReport solve_frictional_contact(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts,
                                     const DofMap& dofs, VectorXd& u, const FrictionalOptions& options,
                                     const Logger& log, const FrictionState* previous) {
  // The predictor (FrictionalOptions::extrapolate): this step repeats the previous one's increment, scaled.
  const double s_extrapolate = options.extrapolate && previous && energy.hessian_is_constant()
                                   ? proportional_increment(fixed, u, previous->u_start)
                                   : 0.0;
  CoulombThresholds coulomb(contacts, dofs, u, previous, s_extrapolate, log);
  const bool follows = follows_optimizer(energy, contacts, dofs.dim(), options);
  if (follows) coulomb.follow_iterates(kFollowTolerance * options.coulomb_tolerance);
  const VectorXd u_start = u;
  // Without Coulomb pairs there are no thresholds to start cold: u alone is extrapolated.
  if ((coulomb.warm() || !coulomb.lags()) && s_extrapolate > 0.0) {
    u += s_extrapolate * (u - previous->u_start);
    std::ostringstream m;
    m << "  predictor: the previous step's increment extrapolated (scale " << s_extrapolate << ")";
    log.detail(m.str());
  }
  // Inexact inner solves (FrictionalOptions::inner_tolerance_factor) with quadratic energies only; without a
  // Coulomb pair the one solve is the answer, to full tolerance. Not where the thresholds follow the
  // optimiser: its first solve already ends near the fixed point.
  const bool inexact =
      coulomb.lags() && energy.hessian_is_constant() && options.inner_tolerance_factor > 0.0 && !follows;
  // Between two solves only the surfaces are read (pressures, slips, the next search): with a condensed
  // workspace each solve leaves the interior out of date (ContactSolveOptions::lazy_interior) and u is made
  // whole once, when this load step ends — also when it throws (the last iterate is kept for inspection).
  CompleteOnExit complete_on_exit{energy, fixed, u, options.contact.workspace.get()};
  const LaggedSolve solve = [&](const ContactSolveOptions& o) {
    return solve_contact(energy, fixed, contacts, dofs, u, o, log, coulomb.any_friction() ? &coulomb.state() : nullptr);
  };
  // Past the tolerance with finite-strain bodies only (FrictionalOptions::converge_past_tolerance).
  FrictionalOptions loop = options;
  loop.converge_past_tolerance = options.converge_past_tolerance && !energy.hessian_is_constant();
  SolveReport rep = solve_lagged(coulomb, solve, u, u_start, loop, inexact, log);
  complete_on_exit.now();
  rep.friction_state = coulomb.state();
  rep.friction_state.follower = nullptr;  // the follower ends with this step
  return rep;
}

}  // namespace symcontact
