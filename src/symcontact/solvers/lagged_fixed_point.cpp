#include "symcontact/solvers/lagged_fixed_point.hpp"

#include <algorithm>
#include <optional>
#include <sstream>
#include <utility>

#include "symcontact/core/error.hpp"
#include "symcontact/core/progress_clock.hpp"
#include "symcontact/solvers/fixed_point_monitor.hpp"

namespace symcontact {

namespace {

/// How far past the tolerance a fast-falling loop goes at most (the file comment).
constexpr double kPastTolerance = 1e-2;

/// Each stagnation remedy tightens the inner solves: IPOPT's tolerance × 1e-2 and the geometry tolerance × 0.1
/// (the noise of what the term reads from the answer falls with them).
void tighten(ContactSolveOptions& o) {
  tighten_optimiser(o.ipopt);
  o.geometry_tolerance *= 0.1;
}

/// Aitken's ω_k of the file comment, all parts as one vector (1 without a previous residual).
double aitken_relaxation(const std::vector<Eigen::VectorXd>& r, const std::vector<Eigen::VectorXd>& r_prev,
                         double omega) {
  double dot = 0.0, dd = 0.0;
  for (std::size_t p = 0; p < r.size(); ++p) {
    if (r[p].size() == 0 || p >= r_prev.size() || r_prev[p].size() != r[p].size()) continue;
    const Eigen::VectorXd dr = r[p] - r_prev[p];
    dot += r_prev[p].dot(dr);
    dd += dr.squaredNorm();
  }
  return dd > 0 ? std::clamp(-omega * dot / dd, 0.1, 1.0) : 1.0;
}

/// The loop of one load step (the file comment of the header). One object per solve_lagged call.
class LaggedFixedPoint {
 public:
  LaggedFixedPoint(LaggedTerm& term, const LaggedSolve& solve, const FrictionalOptions& options, bool inexact,
                   const Logger& log)
      : term_(term), solve_(solve), options_(options), log_(log), inexact_(inexact), inner_(options.contact) {}

  SolveReport run(VectorXd& u, const VectorXd& u_cold);

 private:
  void solve(double change);
  void first_solve(VectorXd& u, const VectorXd& u_cold);
  bool stops(int k, const std::vector<Eigen::VectorXd>& r);
  bool stagnation_ends(int iteration, double change);
  bool falls_fast(double change) const;
  void keep_fallback(const VectorXd& u);
  void accept_fallback(VectorXd& u, const SolveError& failed);
  void accept_at_noise_floor(double change, const std::string& how);
  std::string failure(const std::string& what, int iteration, double change) const;

  LaggedTerm& term_;
  const LaggedSolve& solve_;
  const FrictionalOptions& options_;
  const Logger& log_;
  SolveReport rep_;
  bool inexact_;               ///< inexact inner solves (FrictionalOptions::inner_tolerance_factor)
  ContactSolveOptions inner_;  ///< tightened when the fixed point stagnates
  bool same_loads_ = false;
  std::vector<Eigen::VectorXd> r_prev_;  ///< r_{k−1} (empty before the first)
  double omega_ = 1.0;
  double scale_ = 1.0;       ///< c of the data the next solve takes (1 before any is known)
  FixedPointMonitor monitor_;
  int tightenings_ = 0;      ///< inner accuracy raised this many times (at most kMaxTightenings)
  bool confirming_ = false;  ///< the last solve confirmed, to full tolerance, a change met on an inexact one
  ContactSolveOptions last_inner_;  ///< inner_ of the last solve
  /// After a tightening: the iterate the next solve starts from (u, its data before the update, the options
  /// that solved it), accepted at the noise floor when a tightened solve fails (the file comment).
  struct Fallback {
    VectorXd u;
    std::vector<Eigen::VectorXd> data;
    ContactSolveOptions inner;
  };
  std::optional<Fallback> fallback_;
  ProgressClock clock_;      ///< since the step started
};

/// One solve with the term's current data; inexact (its geometry fixed point stopped at
/// inner_tolerance_factor × change) while inexact_ holds.
void LaggedFixedPoint::solve(double change) {
  last_inner_ = inner_;
  ContactSolveOptions o = inner_;
  if (inexact_) o.loose_geometry_tolerance = options_.inner_tolerance_factor * change;
  o.same_loads = same_loads_;
  SolveReport r = solve_(o);
  same_loads_ = true;  // the later solves of the loop: the same load step, whose load part is now known
  add_geometry_solve(rep_, std::move(r));
}

/// The first solve. A warm start the solve cannot take (IPOPT failing from a start that the moved boundary
/// made far infeasible, with the friction already on) falls back to the cold start.
void LaggedFixedPoint::first_solve(VectorXd& u, const VectorXd& u_cold) {
  if (!term_.warm()) {
    solve(1.0);
    return;
  }
  try {
    solve(1.0);
  } catch (const SolveError& e) {
    log_.detail("  warm-started " + term_.loop_name() + " solve failed (" + e.what() + "); starting cold");
    u = u_cold;
    term_.start_cold();
    solve(1.0);
  }
}

/// The message of a loop that ends without converging: which loop, what was tried, the changes, and what the
/// user can change.
std::string LaggedFixedPoint::failure(const std::string& what, int iteration, double change) const {
  std::ostringstream e;
  e << "the " << term_.loop_name() << " fixed point " << what << " after " << iteration
    << " iterations (last relative change of the " << term_.data_name() << " " << change
    << ", smallest since the last remedy " << monitor_.best() << ", tolerance " << options_.coulomb_tolerance
    << ")";
  if (tightenings_ > 0)
    e << "; tried: inner solves tightened " << tightenings_ << " time(s), to optimiser tolerance ([ipopt] tol) "
      << inner_.ipopt.tolerance << " and geometry tolerance " << inner_.geometry_tolerance;
  e << "; " << term_.advice();
  return e.str();
}

/// After a stagnation: tightens the inner solves (false: the loop goes on), accepts the iterate at the noise
/// floor (true), or throws.
bool LaggedFixedPoint::stagnation_ends(int iteration, double change) {
  if (tightenings_ < kMaxTightenings) {
    ++tightenings_;
    inexact_ = false;
    tighten(inner_);
    std::ostringstream m;
    m << "  the " << term_.loop_name() << " fixed point stagnated (no new low below " << monitor_.best()
      << "); inner solves tightened to optimiser tolerance ([ipopt] tol) " << inner_.ipopt.tolerance
      << ", geometry tolerance " << inner_.geometry_tolerance;
    log_.detail(m.str());
    monitor_.restart();
    return false;
  }
  if (rep_.converged && change <= options_.stagnation_acceptance) {
    accept_at_noise_floor(change, "");
    return true;
  }
  throw SolveError(failure("stagnated", iteration, change));
}

/// Ends the loop at the iterate whose change is `change`, with the warning of the file comment; `how`: what
/// showed the noise floor beyond the stagnation (empty, or a clause starting with " and").
void LaggedFixedPoint::accept_at_noise_floor(double change, const std::string& how) {
  rep_.accepted_at_noise_floor = change;
  std::ostringstream m;
  m << term_.loop_name() << " fixed point: the " << term_.data_name() << "s stopped changing at " << change
    << " of their size (tolerance " << options_.coulomb_tolerance << ")" << how
    << ", the noise floor of the inner solves; accepted: the law holds to " << change << " (acceptance "
    << options_.stagnation_acceptance << ")";
  log_.warning(m.str());
}

/// Whether a change below the tolerance is worth one more iteration (the file comment: past the tolerance):
/// it fell at least tenfold from the previous one and is still above kPastTolerance × the tolerance.
bool LaggedFixedPoint::falls_fast(double change) const {
  const std::vector<double>& c = rep_.coulomb_change;
  return options_.converge_past_tolerance && c.size() >= 2 && change <= 0.1 * c[c.size() - 2] &&
         change > kPastTolerance * options_.coulomb_tolerance;
}

/// Whether the loop ends after the solve of iteration k, whose residuals are r: converged on a solve to the
/// geometry tolerance, or stagnated and accepted at the noise floor. Throws SolveError when it cannot converge.
bool LaggedFixedPoint::stops(int k, const std::vector<Eigen::VectorXd>& r) {
  const int iteration = k - (term_.warm() ? 0 : 1);
  const double change = relative_change(r, term_.data());
  scale_ = change;
  rep_.coulomb_change.push_back(change);
  monitor_.record(change);
  omega_ = aitken_relaxation(r, r_prev_, omega_);
  rep_.coulomb_relaxation.push_back(omega_);
  std::ostringstream s;
  s << "  " << term_.loop_name() << " iteration " << iteration << ": " << term_.data_name() << " change " << change
    << ", relaxation " << omega_;
  log_iteration(log_, clock_, s.str());
  if (change < options_.coulomb_tolerance) {
    if (rep_.converged) {
      if (!falls_fast(change) || iteration >= options_.max_coulomb_iterations) return true;
      log_.detail("  below the tolerance and falling tenfold per iteration: one more iteration");
      confirming_ = false;
      return false;
    }
    log_.detail("  the " + term_.data_name() +
                "s settled on an inexact solve; one more solve to the geometry tolerance");
    scale_ = 0.0;
  } else if (confirming_ && inexact_) {
    // The exact solve moved the data back above the tolerance: the inexact solves' error was larger than
    // their change showed. The rest of the step solves to full tolerance, so that this cannot repeat.
    inexact_ = false;
    log_.detail("  the solve to full tolerance undid the inexact solves' convergence; inner solves exact from now on");
  }
  confirming_ = scale_ == 0.0;
  if (monitor_.stagnated() && stagnation_ends(iteration, change)) return true;
  if (iteration >= options_.max_coulomb_iterations) throw SolveError(failure("did not converge", iteration, change));
  return false;
}

SolveReport LaggedFixedPoint::run(VectorXd& u, const VectorXd& u_cold) {
  first_solve(u, u_cold);
  if (!term_.lags()) return std::move(rep_);
  for (int k = 1;; ++k) {
    const std::vector<Eigen::VectorXd> r = term_.residual(u, rep_);
    const bool judged = k > 1 || term_.warm();  // a cold start's first residual is not judged
    if (judged && stops(k, r)) break;
    keep_fallback(u);
    term_.update(r, judged ? omega_ : 1.0);
    r_prev_ = r;
    rep_.coulomb_iterations = k;
    try {
      solve(scale_);
    } catch (const SolveError& e) {
      if (!fallback_) throw;
      accept_fallback(u, e);
      break;
    }
  }
  return std::move(rep_);
}

/// Once the inner solves are tightened: the iterate u of a converged solve, the data it was solved with and
/// their options, before the update (none where the last solve did not converge).
void LaggedFixedPoint::keep_fallback(const VectorXd& u) {
  if (tightenings_ == 0) return;
  if (!rep_.converged) {
    fallback_.reset();
    return;
  }
  fallback_ = Fallback{u, term_.data(), last_inner_};
}

/// A tightened solve failed: back to the fallback iterate, solved again under its own options, accepted at the
/// noise floor where that solve converges with a change within the acceptance; otherwise `failed` stands.
void LaggedFixedPoint::accept_fallback(VectorXd& u, const SolveError& failed) {
  log_.detail(std::string("  a tightened solve failed (") + failed.what() + "); back to the iterate it started from");
  u = fallback_->u;
  term_.set_data(fallback_->data);
  inner_ = fallback_->inner;
  inexact_ = false;
  try {
    solve(scale_);
  } catch (const SolveError&) {
    throw failed;
  }
  const double change = relative_change(term_.residual(u, rep_), term_.data());
  rep_.coulomb_change.push_back(change);
  if (!rep_.converged || change > options_.stagnation_acceptance) throw failed;
  accept_at_noise_floor(change, std::string(" and a solve tightened past that failed (") + failed.what() + ")");
}

}  // namespace

double relative_change(const std::vector<Eigen::VectorXd>& r, const std::vector<Eigen::VectorXd>& d) {
  double num = 0.0, den = 0.0;
  for (std::size_t p = 0; p < r.size(); ++p) {
    if (r[p].size() == 0) continue;
    num = std::max(num, r[p].lpNorm<Eigen::Infinity>());
    den = std::max(den, d[p].lpNorm<Eigen::Infinity>());
  }
  return den > 0 ? num / den : (num > 0 ? 1.0 : 0.0);
}

SolveReport solve_lagged(LaggedTerm& term, const LaggedSolve& solve, VectorXd& u, const VectorXd& u_cold,
                         const FrictionalOptions& options, bool inexact, const Logger& log) {
  return LaggedFixedPoint(term, solve, options, inexact, log).run(u, u_cold);
}

}  // namespace symcontact
