#include "symcontact/solvers/polish_strategy.hpp"

#include "symcontact/optim/ipopt_solver.hpp"
#include "symcontact/solvers/active_set_polish.hpp"
#include "symcontact/solvers/condensation_cache.hpp"

namespace symcontact {

PolishStrategy::PolishStrategy(bool enabled, ContactWorkspace& workspace, int acceleration_memory, BodiesEnergy bodies)
    : enabled_(enabled), workspace_(workspace), acceleration_memory_(acceleration_memory), bodies_(bodies) {}

void PolishStrategy::closing_rejected(const std::string& reason, const Logger& log) {
  closing_works_ = false;
  log.detail("  active-set polish (closing, dual) not applied: " + reason + "; the optimiser's point is kept");
}

bool PolishStrategy::polish_primal(ConstrainedProblem& target, IpoptResult& res, const Logger& log,
                                   PhaseTimes& times) {
  const bool nonquadratic = !target.hessian_is_constant();
  if (enabled_ && closing_works_ && nonquadratic && workspace_.closing_polish_rejected) {
    closing_works_ = false;
    log.detail("  active-set polish (closing) rejected in the previous solve; balancing forces only");
  }
  balance_at_end_ = enabled_ && nonquadratic && !closing_works_;
  if (!enabled_ || balance_at_end_) return false;
  ScopedPhase t(times, "polish");
  PolishResult pr;
  if (closing_works_) {
    pr = polish_active_set(target, res.x, res.multipliers, PolishMode::kClose);
    if (nonquadratic) workspace_.closing_polish_rejected = !pr.applied;
    if (!pr.applied) {
      closing_works_ = false;
      log.detail("  active-set polish (closing) not applied: " + pr.reason + "; balancing forces only");
    }
  }
  if (!pr.applied) {
    pr = polish_active_set(target, res.x, res.multipliers, PolishMode::kBalanceForces);
    if (!pr.applied) log.detail("  force-balance polish not applied: " + pr.reason);
  }
  log.debug("  polish: " + std::to_string(pr.iterations) + " iterations on " + std::to_string(pr.active) +
            " active constraints");
  // Closed with friction terms on linear-elastic bodies: the closing's method of multipliers leaves a
  // stationarity error (up to 1e-7 of the forces where friction sticks); the iterate that ends the fixed point
  // is balanced once more (the file comment of the header).
  if (pr.applied && closing_works_ && nonquadratic && bodies_ == BodiesEnergy::kQuadratic) balance_at_end_ = true;
  return pr.applied && closing_works_;
}

void PolishStrategy::balance(ConstrainedProblem& target, VectorXd& xt, VectorXd& mu, const Logger& log,
                             PhaseTimes& times) const {
  ScopedPhase t(times, "polish");
  const PolishResult pr = polish_active_set(target, xt, mu, PolishMode::kBalanceForces);
  if (!pr.applied) log.detail("  force-balance polish not applied: " + pr.reason);
  log.debug("  polish (at the end): " + std::to_string(pr.iterations) + " iterations on " +
            std::to_string(pr.active) + " active constraints");
}

void PolishStrategy::record_change(double change, bool closed, const std::vector<double>& history,
                                   const Logger& log) {
  if (!closed) return;
  if (change < best_closed_change_) {
    best_closed_change_ = change;
    closed_since_best_ = 0;
  } else {
    ++closed_since_best_;
  }
  const std::size_t n = history.size();
  const bool stalls = acceleration_memory_ > 0
                          ? closed_since_best_ > acceleration_memory_ + 2
                          : n >= 2 && change > history[n - 1] && history[n - 1] > history[n - 2];
  if (stalls) {
    closing_works_ = false;
    log.detail("  the change stalled or grew with the active set closed; balancing forces only from now on");
  }
}

}  // namespace symcontact
