#include "symcontact/solvers/primal_subproblem.hpp"

#include "symcontact/solvers/active_set_start.hpp"

namespace symcontact {

SubproblemSolution PrimalIpopt::solve(const Subproblem& p, const SubproblemWarmStart& warm, const Logger& log,
                                      PhaseTimes& times) {
  ScopedPhase t(times, "optimizer");
  SubproblemSolution s;
  IpoptResult& res = s.result;
  IpoptOptions opt = p.ipopt;
  opt.warm_start = warm.multipliers != nullptr;
  res = solve_with_ipopt(p.target, p.start, opt, warm.multipliers);
  if (res.status_text == "Restoration_Failed" && res.x.allFinite() && res.multipliers.allFinite()) {
    // IPOPT gives up when its line search fails at an iterate that is already feasible: there is no
    // feasibility to restore (coin-or/Ipopt issue 394). f was evaluated there, so it is a valid start: resumed
    // from it with its multipliers, the step keeps its path where round-off alone derailed IPOPT, instead of
    // a cold start that ends elsewhere within the Coulomb tolerance (the frictional ironing in m and in mm on
    // OpenBLAS's Zen kernels: one unit system restarted a step, and the reactions parted by 2.6e-4).
    log.detail("  IPOPT failed (" + res.status_text + "); resumed from its last iterate");
    IpoptOptions resumed = p.ipopt;
    resumed.warm_start = true;
    s.failed_iterations += res.iterations;
    res = solve_with_ipopt(p.target, res.x, resumed, &res.multipliers);
  }
  if (!res.success && p.geometry_iteration == 1 && warm.multipliers) {
    log.detail("  IPOPT failed from the previous solve's multipliers (" + res.status_text + "); cold start");
    s.failed_iterations += res.iterations;
    res = solve_with_ipopt(p.target, p.start, p.ipopt);
  }
  if (!res.success && p.restart) {
    log.detail("  IPOPT failed (" + res.status_text + "); retrying from the start of the load step");
    const IpoptResult retry = solve_with_ipopt(p.target, p.restart(), p.ipopt);
    s.failed_iterations += res.iterations;
    res = retry;
  }
  return s;
}

namespace {

/// Newton on the active set of (x, μ) (active_set_start.hpp), at the interior point's tolerance.
IpoptResult on_active_set(const Subproblem& p, const VectorXd& x, const VectorXd& multipliers, double tolerance,
                          const FollowIterate* follow) {
  ActiveSetStartOptions a;
  a.tolerance = tolerance;
  return solve_from_active_set(p.target, x, multipliers, a, follow);
}

}  // namespace

SubproblemSolution PrimalInteriorPoint::solve(const Subproblem& p, const SubproblemWarmStart& warm,
                                              const Logger& log, PhaseTimes& times) {
  int failed = 0;
  const bool takes = p.condensed || (p.quadratic_bodies && forms_ == PrimalForms::kCondensedAndUncondensed);
  if (takes && p.target.num_equalities() == 0 && !p.target.lower_bounds()) {
    ScopedPhase t(times, "optimizer");
    DensePrimalOptions o;
    // IPOPT's tolerance, also when the problem file sets it ([ipopt] tol).
    const auto tol = p.ipopt.numeric_options.find("tol");
    o.tolerance = tol != p.ipopt.numeric_options.end() ? tol->second : p.ipopt.tolerance;
    // A later geometry iteration starts from thresholds at the previous iteration's fixed point.
    if (p.follow && p.geometry_iteration > 1)
      o.follow_below = DensePrimalOptions::follow_below_near_fixed_point(o.tolerance);
    SubproblemSolution s;
    const FollowIterate* follow = p.follow ? &p.follow : nullptr;
    // Only where the polish would close the set (PolishStrategy::closes()): the active-set start closes it.
    // Without the previous rows' multipliers, on the uncondensed problem (a sparse Hessian) it starts from the
    // rows that p.start violates (the primal-dual active set method's own start, Hintermüller, Ito & Kunisch
    // 2003): each of its Newton steps costs a sparse factorisation at most, as each interior-point iteration
    // does, and it takes fewer of them on the 3D pads (docs/performance.md); the dense condensed problem keeps
    // the interior point.
    const Index rows = p.target.constraint_matrix().rows();
    const VectorXd* set_start = warm.multipliers ? warm.multipliers : warm.carried;
    const bool warm_rows = set_start && set_start->size() == rows;
    if (warm_ == WarmStart::kActiveSet && p.close_active_set && (warm_rows || !p.target.hessian_is_dense())) {
      s.result = on_active_set(p, p.start, warm_rows ? *set_start : VectorXd::Zero(rows), o.tolerance, follow);
      if (s.result.success) {
        s.result.status_text = "primal interior point: " + s.result.status_text;
        s.closed = true;
        return s;
      }
      log.detail("  active-set start: " + s.result.status_text + "; the interior point instead");
      failed = s.result.iterations;
    }
    s.result = solve_dense_primal(p.target, p.start, o, warm.multipliers, follow);
    s.result.status_text = "primal interior point: " + s.result.status_text;
    s.failed_iterations = failed;
    if (s.result.success && follow && p.close_active_set) close_with_followed_data(p, o.tolerance, *follow, s, log);
    if (s.result.success) return s;
    log.detail("  the dense " + s.result.status_text + "; IPOPT instead");
    failed += s.result.iterations;
  }
  SubproblemSolution s = PrimalIpopt::solve(p, warm, log, times);
  s.failed_iterations += failed;
  return s;
}

/// The interior point leaves every active row open by about its barrier, and the polish would close them
/// with the thresholds where the interior point's iterates left them: the closed answer's pressure, which the
/// Coulomb loop reads, differs from theirs by that offset, and each new solve would follow them back to the
/// interior point's (a cycle of the loop at a change of the offset's size, seen at the edge of a growing
/// zone). Closed here by Newton on the set with the data following, the thresholds are those of the answer.
void PrimalInteriorPoint::close_with_followed_data(const Subproblem& p, double tolerance, const FollowIterate& follow,
                                                   SubproblemSolution& s, const Logger& log) const {
  IpoptResult closed = on_active_set(p, s.result.x, s.result.multipliers, tolerance, &follow);
  if (!closed.success) {
    log.detail("  active-set closing: " + closed.status_text + "; the polish instead");
    return;
  }
  closed.iterations += s.result.iterations;
  // "converged (active set: N factorisations)" → "…; set closed (active set: N factorisations)"
  const std::string converged = "converged";
  std::string how = closed.status_text;
  if (how.compare(0, converged.size(), converged) == 0) how.erase(0, converged.size());
  closed.status_text = s.result.status_text + "; set closed" + how;
  s.result = std::move(closed);
  s.closed = true;
}

}  // namespace symcontact
