#include "symcontact/solvers/frictional_contact.hpp"

#include <algorithm>
#include <sstream>

#include "symcontact/contact/surface_tractions.hpp"
#include "symcontact/core/error.hpp"
#include "symcontact/core/progress_clock.hpp"
#include "symcontact/solvers/contact_solver.hpp"
#include "symcontact/solvers/fixed_point_monitor.hpp"

namespace symcontact {

namespace {
/// Nodal pressures (clamped at 0) on the friction-slave surface of pair p.
Eigen::VectorXd friction_side_pressure(const ContactSet& cs, int p, const DofMap& dofs, const VectorXd& u,
                                       const VectorXd& force) {
  // Along the interface normal, as the friction term and the contact results decompose (the normal of X
  // for a pair in ContactGeometry::kReference).
  const int f = cs.friction_family(p);
  const ContactSurface& s = cs.surfaces[cs.families()[f].slave];
  const VectorXd u_geometry = cs.geometry_displacement(p, u);
  const Eigen::MatrixXd xs = current_positions(s, dofs, u_geometry);
  const OppositeSide other = cs.opposite_side(f, dofs, u_geometry);
  const Eigen::MatrixXd normals =
      interface_normals(s, xs, other.master(), other.obstacle, cs.pairs[p].search_distance, cs.pairs[p].bisector_ray());
  return surface_tractions(s, dofs, u, force, &normals).pressure.cwiseMax(0.0);
}

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

/// Each remedy of a stagnated Coulomb fixed point tightens its inner solves: IPOPT's tolerance × 1e-2 and the
/// geometry tolerance × 0.1 (the noise of the pressures p(τ) that the fixed point reads falls with them).
void tighten(ContactSolveOptions& o) {
  tighten_optimiser(o.ipopt);
  o.geometry_tolerance *= 0.1;
}

/// The contact force F_c at the nodes where the multipliers act (Aᵀμ ≠ 0 on some DOF of the node: every
/// node's `dim` DOFs are consecutive), zero at the others. F_c is ∇E(u) on the free DOFs of the surfaces
/// (contact_forces.hpp); where no multiplier acts it is the solve's equilibrium error alone, and a pressure
/// read from it would be noise: with no contact anywhere (a surface not yet within its search distance, or
/// every gap open) the thresholds would be that noise, and their relative change O(1) at every iteration.
VectorXd active_contact_force(const ContactState& state, int dim) {
  VectorXd f = VectorXd::Zero(state.contact_force.size());
  for (Index d = 0; d + dim <= f.size(); d += dim)
    if (state.multiplier_force.segment(d, dim).cwiseAbs().maxCoeff() > 0.0)
      f.segment(d, dim) = state.contact_force.segment(d, dim);
  return f;
}

/// r_k = μ p_k − τ_k per Coulomb pair (empty for the others), p_k from the last solve's contact forces at the
/// nodes its multipliers act on.
std::vector<Eigen::VectorXd> coulomb_residuals(const ContactSet& contacts, const DofMap& dofs, const VectorXd& u,
                                               const SolveReport& rep, const Logger& log) {
  const int np = static_cast<int>(contacts.pairs.size());
  const VectorXd force = active_contact_force(rep, dofs.dim());
  std::vector<Eigen::VectorXd> r(np);
  for (int p = 0; p < np; ++p) {
    if (contacts.pairs[p].friction != FrictionLaw::kCoulomb) continue;
    r[p] = contacts.pairs[p].mu * friction_side_pressure(contacts, p, dofs, u, force) -
           rep.friction_state.nodal_tau[p];
    if (log.level() >= Verbosity::kDebug && r[p].size() > 0) {
      Index at = 0;
      r[p].cwiseAbs().maxCoeff(&at);
      const ContactSurface& s = contacts.surfaces[contacts.families()[contacts.friction_family(p)].slave];
      std::ostringstream m;
      m << "    pair " << contacts.pairs[p].name << ": largest threshold change at surface node " << at << " (X = "
        << s.X.col(at).transpose() << "): " << rep.friction_state.nodal_tau[p][at] << " -> "
        << rep.friction_state.nodal_tau[p][at] + r[p][at];
      log.debug(m.str());
    }
  }
  return r;
}

/// max_p ‖r_p‖∞ / max_p ‖τ_p‖∞ over the Coulomb pairs (1 when τ = 0 and r is not).
double relative_change(const std::vector<Eigen::VectorXd>& r, const std::vector<Eigen::VectorXd>& tau) {
  double num = 0.0, den = 0.0;
  for (std::size_t p = 0; p < r.size(); ++p) {
    if (r[p].size() == 0) continue;
    num = std::max(num, r[p].lpNorm<Eigen::Infinity>());
    den = std::max(den, tau[p].lpNorm<Eigen::Infinity>());
  }
  return den > 0 ? num / den : (num > 0 ? 1.0 : 0.0);
}

/// Aitken: ω_k = −ω_{k−1} r_{k−1}·(r_k − r_{k−1}) / ‖r_k − r_{k−1}‖², clipped to [0.1, 1] (all Coulomb pairs as
/// one vector; 1 without a previous residual).
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

/// The message of a Coulomb fixed point that ends without converging: which loop, what was tried, the
/// residuals, and what the user can change.
std::string coulomb_failure(const std::string& what, int iteration, double change, const FrictionalOptions& options,
                            int tightenings, const ContactSolveOptions& inner, const FixedPointMonitor& monitor) {
  std::ostringstream e;
  e << "the Coulomb fixed point " << what << " after " << iteration << " iterations (last relative change of the "
    << "threshold " << change << ", smallest since the last remedy " << monitor.best() << ", tolerance "
    << options.coulomb_tolerance << ")";
  if (tightenings > 0)
    e << "; tried: inner solves tightened " << tightenings << " time(s), to IPOPT tol " << inner.ipopt.tolerance
      << " and geometry tolerance " << inner.geometry_tolerance;
  e << "; try smaller load steps ([contact_solver] max_step_cuts = 4, or more [steps]), or a larger friction "
       "regularisation alpha";
  return e.str();
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

/// The Coulomb fixed point of one load step (the file comment of frictional_contact.hpp), around the
/// regularised-Tresca solves of solve_contact. One object per solve_frictional_contact call.
class CoulombFixedPoint {
 public:
  CoulombFixedPoint(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts, const DofMap& dofs,
                    VectorXd& u, const FrictionalOptions& options, const Logger& log, const FrictionState* previous)
      : energy_(energy), fixed_(fixed), contacts_(contacts), dofs_(dofs), u_(u), options_(options), log_(log),
        previous_(previous), inner_(options.contact) {}

  SolveReport run();

 private:
  void start_thresholds(double s_extrapolate);
  void solve(double threshold_change);
  void first_solve();
  bool stops(int k, const std::vector<Eigen::VectorXd>& r);

  const EnergyTerm& energy_;
  const FixedDofs& fixed_;
  const ContactSet& contacts_;
  const DofMap& dofs_;
  VectorXd& u_;
  const FrictionalOptions& options_;
  const Logger& log_;
  const FrictionState* previous_;
  SolveReport rep_;
  bool any_friction_ = false, any_coulomb_ = false;
  bool warm_ = false;        ///< the step starts from the previous step's thresholds
  VectorXd u_step_start_;
  bool inexact_ = false;     ///< inexact inner solves (FrictionalOptions::inner_tolerance_factor)
  ContactSolveOptions inner_;  ///< tightened when the fixed point stagnates
  bool same_loads_ = false;
  std::vector<Eigen::VectorXd> r_prev_;  ///< r_{k−1}, per pair (empty before the first Tresca solve)
  double omega_ = 1.0;
  double scale_ = 1.0;       ///< of the next solve's loose geometry tolerance: the last ‖r_k‖∞ / ‖τ_k‖∞ (1 before)
  FixedPointMonitor monitor_;
  int tightenings_ = 0;      ///< inner accuracy raised this many times (at most kMaxTightenings)
  bool confirming_ = false;  ///< the last solve confirmed, to full tolerance, a change met on an inexact one
  ProgressClock clock_;      ///< since the step started
};

/// The thresholds the step starts from. Tresca: the given τ; Coulomb: the previous step's (extrapolated by
/// s_extrapolate > 0: FrictionalOptions::extrapolate), or 0 for a frictionless first solve.
void CoulombFixedPoint::start_thresholds(double s_extrapolate) {
  const int np = static_cast<int>(contacts_.pairs.size());
  rep_.friction_state.nodal_tau.assign(np, Eigen::VectorXd());
  for (int p = 0; p < np; ++p) {
    const ContactPair& pair = contacts_.pairs[p];
    if (pair.friction == FrictionLaw::kNone) continue;
    any_friction_ = true;
    const ContactSurface& s = contacts_.surfaces[contacts_.families()[contacts_.friction_family(p)].slave];
    rep_.friction_state.nodal_tau[p] =
        Eigen::VectorXd::Constant(s.num_nodes(), pair.friction == FrictionLaw::kTresca ? pair.tau : 0.0);
    if (pair.friction != FrictionLaw::kCoulomb) continue;
    any_coulomb_ = true;
    const FrictionState* prev = previous_;
    if (prev && p < static_cast<int>(prev->nodal_tau.size()) && prev->nodal_tau[p].size() == s.num_nodes() &&
        prev->nodal_tau[p].maxCoeff() > 0.0) {
      rep_.friction_state.nodal_tau[p] = prev->nodal_tau[p];
      warm_ = true;
      if (s_extrapolate > 0.0 && p < static_cast<int>(prev->previous_tau.size()) &&
          prev->previous_tau[p].size() == s.num_nodes())
        rep_.friction_state.nodal_tau[p] =
            (prev->nodal_tau[p] + s_extrapolate * (prev->nodal_tau[p] - prev->previous_tau[p])).cwiseMax(0.0);
    }
  }
}

/// One regularised-Tresca solve with the current thresholds; inexact (its geometry fixed point stopped at
/// inner_tolerance_factor × threshold_change) while inexact_ holds.
void CoulombFixedPoint::solve(double threshold_change) {
  ContactSolveOptions o = inner_;
  if (inexact_) o.loose_geometry_tolerance = options_.inner_tolerance_factor * threshold_change;
  o.same_loads = same_loads_;
  SolveReport r =
      solve_contact(energy_, fixed_, contacts_, dofs_, u_, o, log_, any_friction_ ? &rep_.friction_state : nullptr);
  same_loads_ = true;  // the later solves of this call: the same load step, whose load part is now known
  add_geometry_solve(rep_, std::move(r));
}

/// The first solve. A warm start the solve cannot take (IPOPT failing from a start the moved boundary made
/// far infeasible, with the friction already on) falls back to the frictionless start.
void CoulombFixedPoint::first_solve() {
  if (!warm_) {
    solve(1.0);
    return;
  }
  try {
    solve(1.0);
  } catch (const SolveError& e) {
    log_.detail(std::string("  warm-started Coulomb solve failed (") + e.what() + "); starting frictionless");
    u_ = u_step_start_;
    warm_ = false;
    for (std::size_t p = 0; p < contacts_.pairs.size(); ++p)
      if (contacts_.pairs[p].friction == FrictionLaw::kCoulomb) rep_.friction_state.nodal_tau[p].setZero();
    solve(1.0);
  }
}

/// Whether the loop ends after the solve of iteration k, whose residuals are r: converged on a solve to the
/// geometry tolerance, or stagnated and accepted at the noise floor. Tightens the inner solves of a stagnated
/// fixed point; throws SolveError when it cannot converge.
bool CoulombFixedPoint::stops(int k, const std::vector<Eigen::VectorXd>& r) {
  const int iteration = k - (warm_ ? 0 : 1);
  const double change = relative_change(r, rep_.friction_state.nodal_tau);
  scale_ = change;
  rep_.coulomb_change.push_back(change);
  monitor_.record(change);
  omega_ = aitken_relaxation(r, r_prev_, omega_);
  rep_.coulomb_relaxation.push_back(omega_);
  std::ostringstream s;
  s << "  Coulomb iteration " << iteration << ": threshold change " << change << ", relaxation " << omega_;
  log_iteration(log_, clock_, s.str());
  if (change < options_.coulomb_tolerance) {
    // The loop ends on a solve converged to the geometry tolerance (and force-balanced): after an inexact
    // one, one more solve at full tolerance (its τ moves by less than the tolerance).
    if (rep_.converged) return true;
    log_.detail("  thresholds settled on an inexact solve; one more solve to the geometry tolerance");
    scale_ = 0.0;
  } else if (confirming_ && inexact_) {
    // The exact solve moved the thresholds back above the tolerance: the inexact solves' error was larger
    // than their change showed. The rest of the step solves to full tolerance, so that this cannot repeat.
    inexact_ = false;
    log_.detail("  the solve to full tolerance undid the inexact solves' convergence; inner solves exact from now on");
  }
  confirming_ = scale_ == 0.0;
  if (monitor_.stagnated()) {
    if (tightenings_ < kMaxTightenings) {
      ++tightenings_;
      inexact_ = false;
      tighten(inner_);
      std::ostringstream m;
      m << "  the Coulomb fixed point stagnated (no new low below " << monitor_.best()
        << "); inner solves tightened to IPOPT tol " << inner_.ipopt.tolerance << ", geometry tolerance "
        << inner_.geometry_tolerance;
      log_.detail(m.str());
      monitor_.restart();
    } else if (rep_.converged && change <= options_.stagnation_acceptance) {
      rep_.accepted_at_noise_floor = change;
      std::ostringstream m;
      m << "Coulomb fixed point: the thresholds stopped changing at " << change << " of their size (tolerance "
        << options_.coulomb_tolerance << "), the noise floor of the inner solves; accepted: the friction law holds to "
        << change << " (acceptance " << options_.stagnation_acceptance << ")";
      log_.warning(m.str());
      return true;
    } else {
      throw SolveError(coulomb_failure("stagnated", iteration, change, options_, tightenings_, inner_, monitor_));
    }
  }
  if (iteration >= options_.max_coulomb_iterations)
    throw SolveError(coulomb_failure("did not converge", iteration, change, options_, tightenings_, inner_, monitor_));
  return false;
}

SolveReport CoulombFixedPoint::run() {
  rep_.friction_state.u_start = u_;
  if (previous_) rep_.friction_state.previous_tau = previous_->nodal_tau;
  // The predictor (FrictionalOptions::extrapolate): this step repeats the previous one's increment, scaled.
  const double s_extrapolate = options_.extrapolate && previous_ && energy_.hessian_is_constant()
                                   ? proportional_increment(fixed_, u_, previous_->u_start)
                                   : 0.0;
  start_thresholds(s_extrapolate);
  u_step_start_ = u_;
  if (warm_ && s_extrapolate > 0.0) {
    u_ += s_extrapolate * (u_ - previous_->u_start);
    std::ostringstream m;
    m << "  predictor: the previous step's increment extrapolated (scale " << s_extrapolate << ")";
    log_.detail(m.str());
  }
  // Inexact inner solves (FrictionalOptions::inner_tolerance_factor): the geometry fixed point of a solve
  // stops at factor × the threshold change that set its τ (1 before any is known: the frictionless start,
  // or the previous step's thresholds); without a Coulomb pair the one solve is the answer, to full tolerance.
  inexact_ = any_coulomb_ && energy_.hessian_is_constant() && options_.inner_tolerance_factor > 0.0;
  // Between two solves only the surfaces are read (pressures, slips, the next search): with a condensed
  // workspace each solve leaves the interior out of date (ContactSolveOptions::lazy_interior) and u is made
  // whole once, when this load step ends — also when it throws (the last iterate is kept for inspection).
  CompleteOnExit complete_on_exit{energy_, fixed_, u_, options_.contact.workspace.get()};
  first_solve();
  if (!any_coulomb_) {
    complete_on_exit.now();
    return rep_;
  }
  for (int k = 1;; ++k) {
    // r_k = μ p_k − τ_k for every Coulomb pair (τ_0 = 0: the frictionless solve).
    const std::vector<Eigen::VectorXd> r = coulomb_residuals(contacts_, dofs_, u_, rep_, log_);
    if ((k > 1 || warm_) && stops(k, r)) break;
    for (std::size_t p = 0; p < r.size(); ++p)
      if (r[p].size() > 0)
        rep_.friction_state.nodal_tau[p] = (rep_.friction_state.nodal_tau[p] + (k > 1 || warm_ ? omega_ : 1.0) * r[p]).cwiseMax(0.0);
    r_prev_ = r;
    rep_.coulomb_iterations = k;
    solve(scale_);
  }
  complete_on_exit.now();
  return rep_;
}

}  // namespace

SolveReport solve_frictional_contact(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts,
                                          const DofMap& dofs, VectorXd& u, const FrictionalOptions& options,
                                          const Logger& log, const FrictionState* previous) {
  return CoulombFixedPoint(energy, fixed, contacts, dofs, u, options, log, previous).run();
}

}  // namespace symcontact
