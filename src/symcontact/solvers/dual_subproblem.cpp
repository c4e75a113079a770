#include "symcontact/solvers/dual_subproblem.hpp"

#include "symcontact/solvers/condensed_problem.hpp"
#include "symcontact/solvers/dual_condensed_problem.hpp"

namespace symcontact {

DualIpopt::DualIpopt() = default;
DualIpopt::~DualIpopt() = default;

bool DualIpopt::solve_first(const DualCondensedProblem&, const DualStart&, const IpoptOptions&, IpoptResult&,
                            SubproblemSolution&, const Logger&) {
  return false;
}

SubproblemSolution DualIpopt::solve(const Subproblem& p, const SubproblemWarmStart& warm, const Logger& log,
                                    PhaseTimes& times) {
  SubproblemSolution s;
  IpoptResult& res = s.result;
  const CondensedProblem& c = *p.condensed;
  std::unique_ptr<DualCondensedProblem> dual;
  {
    ScopedPhase t(times, "optimizer");  // forming W and d included
    dual = std::make_unique<DualCondensedProblem>(*p.schur, c.constraint_matrix(), c.constraint_offset(),
                                                  c.linear_term());
    const Index rows = c.constraint_matrix().rows();
    const bool is_warm = warm.multipliers && warm.multipliers->size() == rows &&
                         equality_prev_.size() == dual->num_rigid_modes() && solves_ > 0;
    VectorXd l0, z0;
    DualStart start;
    if (is_warm) {
      l0 = dual->scaled_multipliers(*warm.multipliers);
      z0 = dual->scaled_gaps(p.start).cwiseMax(0.0);
      start = {&l0, &z0, &equality_prev_};
    }
    const bool solved = solve_first(*dual, start, p.ipopt, res, s, log);
    if (!solved && is_warm) {
      IpoptOptions opt = p.ipopt;
      opt.warm_start = true;
      res = solve_with_ipopt(*dual, l0, opt, &equality_prev_, &z0);
      if (!res.success) {
        log.detail("  IPOPT failed on the dual from the previous iteration (" + res.status_text + "); cold start");
        s.failed_iterations += res.iterations;
      }
    }
    if (!solved && (!is_warm || !res.success))
      res = solve_with_ipopt(*dual, VectorXd::Zero(dual->num_variables()), p.ipopt);
  }
  ++solves_;
  if (!res.success) return s;
  VectorXd lambda_hat = res.x, eq = res.multipliers;
  if (p.close_active_set) {
    ScopedPhase t(times, "polish");
    const DualCondensedProblem::Closing cl = dual->close_contact_set(lambda_hat, eq);
    s.closed = cl.applied;
    if (!cl.applied) s.closing_failure = cl.reason;
    log.debug("  polish (dual): " + std::to_string(cl.rounds) + " rounds on " + std::to_string(cl.active) +
              " active constraints");
  }
  equality_prev_ = eq;
  res.x = dual->primal(lambda_hat, eq);
  res.multipliers = dual->multipliers(lambda_hat);
  res.constraint_values = c.constraint_matrix() * res.x + c.constraint_offset();
  return s;
}

bool DualInteriorPoint::solve_first(const DualCondensedProblem& dual, const DualStart& start,
                                    const IpoptOptions& ipopt, IpoptResult& res, SubproblemSolution& s,
                                    const Logger& log) {
  DenseQpOptions qp;
  // IPOPT's tolerance, also when the problem file sets it ([ipopt] tol).
  const auto tol = ipopt.numeric_options.find("tol");
  qp.tolerance = tol != ipopt.numeric_options.end() ? tol->second : ipopt.tolerance;
  qp.complementarity_tolerance = 1e-6 * qp.tolerance;
  DenseQpResult r = dual.solve_interior_point(qp, start.lambda_hat, start.gaps, start.equality);
  if (!r.success && start.lambda_hat) {
    log.detail("  the interior point failed on the dual from the previous iteration (" + r.status + "); cold start");
    s.failed_iterations += r.iterations;
    r = dual.solve_interior_point(qp);
  }
  if (!r.success) {
    log.detail("  the interior point failed on the dual (" + r.status + "); IPOPT instead");
    s.failed_iterations += r.iterations;
    return false;
  }
  res.success = true;
  res.status_text = "interior point: " + r.status;
  res.iterations = r.iterations;
  res.x = std::move(r.x);
  res.multipliers = std::move(r.beta);
  res.bound_multipliers = std::move(r.z);
  return true;
}

}  // namespace symcontact
