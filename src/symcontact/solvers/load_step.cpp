#include "symcontact/solvers/load_step.hpp"

#include <cmath>
#include <sstream>

#include "symcontact/core/error.hpp"

namespace symcontact {

std::vector<double> solve_in_substeps(
    int max_cuts, const std::function<void(double from, double to)>& attempt,
    const std::function<void(double from, double to, const std::string& error, int cuts)>& on_cut) {
  std::vector<double> ends;
  double done = 0.0;  // fraction of the step reached
  int cuts = 0;
  while (done < 1.0) {
    // The last sub-step ends at exactly 1, so that the step's own loads are met without round-off.
    const double next = done + std::ldexp(1.0, -cuts);
    const double target = next >= 1.0 - 1e-12 ? 1.0 : next;
    try {
      attempt(done, target);
    } catch (const SolveError& e) {
      if (cuts >= max_cuts) {
        if (max_cuts == 0) throw;
        std::ostringstream s;
        s << e.what() << " (sub-step from " << done << " to " << target << " of the load step, after " << cuts
          << " halving" << (cuts == 1 ? "" : "s") << " of the increment, the most allowed: max_step_cuts)";
        throw SolveError(s.str());
      }
      ++cuts;
      if (on_cut) on_cut(done, target, e.what(), cuts);
      continue;
    }
    ends.push_back(target);
    done = target;
  }
  return ends;
}

SolveReport solve_load_step(const LoadStepProblem& problem, VectorXd& u, FrictionState& friction,
                            const LoadStepOptions& options, const Logger& log) {
  const int step = problem.step;
  const int max_cuts = options.max_step_cuts;
  SolveReport rep;
  auto attempt = [&](double, double to) {
    const VectorXd u0 = u;
    const FrictionState friction0 = friction;
    const FixedDofs fixed = problem.move_to(to);
    SolveReport fr;
    try {
      fr = solve_frictional_contact(problem.energy, fixed, problem.contacts, problem.dofs, u, options.friction, log,
                                    friction.nodal_tau.empty() ? nullptr : &friction);
    } catch (const SolveError&) {
      if (rep.cuts < max_cuts) {  // to be retried: back to the start of the increment
        u = u0;
        friction = friction0;
      }
      throw;
    }
    friction = fr.friction_state;
    add_substep(rep, std::move(fr));
    if (to < 1.0 || rep.cuts > 0) {
      std::ostringstream s;
      s << "  load step " << step + 1 << ": sub-step to " << to << " converged";
      log.detail(s.str());
    }
  };
  auto on_cut = [&](double from, double to, const std::string& error, int cuts) {
    rep.cuts = cuts;
    std::ostringstream s;
    s << "  load step " << step + 1 << ": the increment from " << from << " to " << to << " failed (" << error
      << "); halving it (cut " << cuts << " of at most " << max_cuts << ")";
    log.detail(s.str());
  };
  rep.substeps = solve_in_substeps(max_cuts, attempt, on_cut);
  return rep;
}

}  // namespace symcontact
