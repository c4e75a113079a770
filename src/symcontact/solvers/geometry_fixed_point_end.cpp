// How the geometry fixed point (geometry_fixed_point.hpp) ends: converged (accept), on a subproblem that
// repeats the last one (accept_unchanged, with the deferred force balance of balance_at_end), or tightening its
// optimiser at a noise floor and failing past its iteration limit (after_stagnation).
#include <sstream>

#include "symcontact/core/error.hpp"
#include "symcontact/solvers/geometry_fixed_point.hpp"

namespace symcontact {

namespace {
/// How close to the tolerance a change that stops falling is taken for the subproblems' noise.
constexpr double kNearTolerance = 10.0;
}  // namespace

/// The subproblem at the iterate is the last one again (the header): the iterate, its solution, ends the loop
/// with a change of 0 when its gaps b moved by at most 1e-3 of the tolerance's share of the displacements
/// (what a new solve would move it by, besides the optimiser's own noise), with the force balance a
/// converged iterate gets. Not where the last iterate was accelerated: then it is not that solution.
bool GeometryFixedPoint::accept_unchanged(int it, const VectorXd& u_it) {
  if (!x_solves_last_) return false;
  const double b_tolerance = 1e-3 * stop_tolerance_ * u_it.lpNorm<Eigen::Infinity>();
  if (!subproblem_.unchanged(rep_.linearization, u_it, b_tolerance)) return false;
  IpoptResult res;
  res.x = x_;
  res.multipliers = mu_prev_;
  if (polish_.balance_deferred() && !inexact_) {
    balance_at_end(subproblem_.target(), subproblem_.condensed(), res);
    x_ = res.x;
  }
  rep_.ipopt_per_iteration.push_back(0);
  rep_.change_history.push_back(0.0);
  rep_.geometry_iterations = it;
  std::ostringstream m;
  m << "  geometry iteration " << it << ": " << rep_.linearization.A.rows()
    << " constraints, the subproblem of the last iteration again: its solution stands (change 0)";
  log_iteration(log_, clock_, m.str());
  accept(subproblem_.condensed(), res, 0.0);
  return true;
}

/// The force balance deferred to the iterate that ends the fixed point (polish_strategy.hpp), of res.x.
void GeometryFixedPoint::balance_at_end(ConstrainedProblem& target, const CondensedProblem* condensed,
                                        IpoptResult& res) {
  VectorXd xt = condensed ? condensed->restrict(res.x) : res.x;
  polish_.balance(target, xt, res.multipliers, log_, rep_.times);
  ScopedPhase t(rep_.times, "condensation");
  if (!condensed)
    res.x = xt;
  else
    res.x = lazy_ ? condensed->with_boundary(res.x, xt) : condensed->expand(xt);
}

/// The converged iterate: the bodies' residual on B for the contact forces (∇E = ĝ + S y there,
/// condensed_problem.hpp; O(|B|²) instead of an assembly over the whole mesh), the multipliers, and the
/// warm start of the next solve.
void GeometryFixedPoint::accept(const CondensedProblem* condensed, const IpoptResult& res, double change) {
  if (condensed) {
    const VectorXd y = condensed->restrict(res.x);
    residual_b_ = condensed->linear_term() +
                  condensed->condensation().schur_lower().selfadjointView<Eigen::Lower>() * y;
  }
  rep_.converged = !inexact_ && change < options_.geometry_tolerance;
  rep_.multipliers = res.multipliers;
  workspace_->multipliers = res.multipliers;
  workspace_->row_family = rep_.linearization.row_family;
  workspace_->row_node = rep_.linearization.row_node;
}

/// A fixed point with no new low in six iterations stands at the noise floor of its subproblems' answers
/// (the optimiser's tolerance, or the barrier offset where the closing polish does not apply), above the
/// geometry tolerance: IPOPT is tightened, at most kMaxTightenings times. Past the iteration limit the solve
/// fails, u holding the last iterate.
void GeometryFixedPoint::after_stagnation(int it, double change, VectorXd& u) {
  monitor_.record(change);
  // Linear elasticity: near the tolerance, a change that stops falling fast is the subproblems' noise: within
  // kNearTolerance × the tolerance, one above half of the previous change (both under the same optimiser
  // settings) tightens at once, instead of after the monitor's window of iterations at that floor. (With
  // finite-strain bodies a tighter IPOPT can fail where the looser one converges: the frictional ironing's
  // sub-steps; there the monitor alone decides.)
  const std::vector<double>& c = monitor_.changes();
  const bool at_noise = energy_.hessian_is_constant() && since_tightening_ >= 1 && c.size() >= 2 &&
                        change < kNearTolerance * stop_tolerance_ && change > 0.5 * c[c.size() - 2];
  ++since_tightening_;
  if ((monitor_.stagnated() || at_noise) && tightenings_ < kMaxTightenings) {
    ++tightenings_;
    since_tightening_ = 0;
    tighten_optimiser(ipopt_);
    std::ostringstream s;
    if (at_noise)
      s << "  the geometry fixed point stopped falling near its tolerance (" << c[c.size() - 2] << ", then " << change
        << "); optimiser tolerance ([ipopt] tol) tightened to " << ipopt_.tolerance;
    else
      s << "  the geometry fixed point stagnated (no new low below " << monitor_.best()
        << "); optimiser tolerance ([ipopt] tol) tightened to " << ipopt_.tolerance;
    log_.detail(s.str());
    monitor_.restart();
  }
  if (it < options_.max_geometry_iterations) return;
  u = subproblem_.reduced().expand(x_);
  std::ostringstream s;
  s << "the geometry fixed point did not converge in " << options_.max_geometry_iterations
    << " iterations (last relative change " << change << ", tolerance " << stop_tolerance_ << ")";
  if (tightenings_ > 0)
    s << "; tried: optimiser tolerance ([ipopt] tol) tightened " << tightenings_ << " time(s), to " << ipopt_.tolerance;
  s << "; try smaller load steps ([contact_solver] max_step_cuts = 4, or more [steps])";
  throw SolveError(s.str());
}

}  // namespace symcontact
