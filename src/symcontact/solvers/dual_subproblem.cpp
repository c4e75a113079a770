#include "symcontact/solvers/dual_subproblem.hpp"

#include <algorithm>

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
    const bool rows_known = warm.multipliers && warm.multipliers->size() == rows;
    const bool is_warm = rows_known && equality_prev_.size() == dual->num_rigid_modes() && solves_ > 0;
    VectorXd l0, z0;
    DualStart start;
    if (is_warm) {
      l0 = dual->scaled_multipliers(*warm.multipliers);
      z0 = dual->scaled_gaps(p.start).cwiseMax(0.0);
      start = {&l0, &z0, &equality_prev_};
    }
    bool solved = false;
    if (p.close_active_set && closes_previous_set())  // (the closing finds β itself)
      solved = rows_known ? close_set(*dual, dual->scaled_multipliers(*warm.multipliers),
                                      VectorXd::Zero(dual->num_rigid_modes()), SetStart::kPrevious, res, s, log)
                          : close_set(*dual, dual->cold_start(), VectorXd::Zero(dual->num_rigid_modes()),
                                      SetStart::kCold, res, s, log);
    if (!solved) solved = solve_first(*dual, start, p.ipopt, res, s, log);
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
  if (p.close_active_set && !s.closed) {
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

bool DualIpopt::close_set(const DualCondensedProblem& dual, VectorXd lambda_hat, VectorXd equality, SetStart from,
                          IpoptResult& res, SubproblemSolution& s, const Logger& log) const {
  // A round costs a Cholesky of the |F| closed rows, an interior-point iteration one of all m rows: the rounds
  // may cost up to about six iterations' worth, (m/|F|)³ rounds per iteration, between 6 and 30 rounds. A set
  // a few rows off closes in one to five; a zone grown through a load step in five to eight.
  const std::vector<char> in_set = DualCondensedProblem::closing_start_set(lambda_hat);
  const double active = std::max<double>(1.0, static_cast<double>(std::count(in_set.begin(), in_set.end(), 1)));
  const double ratio = static_cast<double>(lambda_hat.size()) / active;
  const int rounds = static_cast<int>(std::clamp(6.0 * ratio * ratio * ratio, 6.0, 30.0));
  const bool cold = from == SetStart::kCold;
  if (cold && !std::count(in_set.begin(), in_set.end(), 1)) return false;  // nothing violated: no set to close
  const DualCondensedProblem::Closing cl = dual.close_contact_set(
      lambda_hat, equality, rounds, cold ? DualCondensedProblem::Rows::kIndependent : DualCondensedProblem::Rows::kAny);
  const std::string which = cold ? "violated rows' set" : "previous active set";
  if (!cl.applied) {
    log.debug("  the " + which + " did not close (" + cl.reason + "); the interior point");
    return false;
  }
  res.success = true;
  res.status_text = which + " closed in " + std::to_string(cl.rounds) + " rounds";
  res.iterations = 0;
  res.x = std::move(lambda_hat);
  res.multipliers = std::move(equality);
  s.closed = true;
  return true;
}

}  // namespace symcontact
