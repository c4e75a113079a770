#include "symcontact/solvers/primal_subproblem.hpp"

namespace symcontact {

SubproblemSolution PrimalIpopt::solve(const Subproblem& p, const SubproblemWarmStart& warm, const Logger& log,
                                      PhaseTimes& times) {
  ScopedPhase t(times, "optimizer");
  SubproblemSolution s;
  IpoptResult& res = s.result;
  IpoptOptions opt = p.ipopt;
  opt.warm_start = warm.multipliers != nullptr;
  res = solve_with_ipopt(p.target, p.start, opt, warm.multipliers);
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

}  // namespace symcontact
