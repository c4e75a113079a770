#include "symcontact/solvers/frictional_contact.hpp"

#include <algorithm>
#include <sstream>

#include "symcontact/contact/surface_tractions.hpp"
#include "symcontact/core/error.hpp"
#include "symcontact/solvers/contact_solver.hpp"
#include "symcontact/solvers/fixed_point_monitor.hpp"

namespace symcontact {

namespace {
/// Nodal pressures (clamped at 0) on the friction-slave surface of pair p.
Eigen::VectorXd friction_side_pressure(const ContactSet& cs, int p, const DofMap& dofs, const VectorXd& u,
                                       const VectorXd& force) {
  // Along the interface normal, as the friction term and the contact results decompose.
  const ContactFamily& fam = cs.families()[cs.friction_family(p)];
  const ContactSurface& s = cs.surfaces[fam.slave];
  const Eigen::MatrixXd xs = current_positions(s, dofs, u);
  Eigen::MatrixXd normals;
  if (fam.master >= 0) {
    const ContactSurface& ms = cs.surfaces[fam.master];
    const MasterGeometry mg = prepare_master(ms, current_positions(ms, dofs, u));
    normals = interface_normals(s, xs, &mg, nullptr, cs.pairs[p].search_distance, cs.pairs[p].bisector_ray());
  } else {
    normals = interface_normals(s, xs, nullptr, &cs.obstacles[cs.pairs[p].obstacle], cs.pairs[p].search_distance);
  }
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

/// r_k = μ p_k − τ_k per Coulomb pair (empty for the others), p_k from the last solve's contact forces.
std::vector<Eigen::VectorXd> coulomb_residuals(const ContactSet& contacts, const DofMap& dofs, const VectorXd& u,
                                               const FrictionalReport& rep, const Logger& log) {
  const int np = static_cast<int>(contacts.pairs.size());
  std::vector<Eigen::VectorXd> r(np);
  for (int p = 0; p < np; ++p) {
    if (contacts.pairs[p].friction != FrictionLaw::kCoulomb) continue;
    r[p] = contacts.pairs[p].mu * friction_side_pressure(contacts, p, dofs, u, rep.last.contact_force) -
           rep.friction.nodal_tau[p];
    if (log.level() >= Verbosity::kDebug && r[p].size() > 0) {
      Index at = 0;
      r[p].cwiseAbs().maxCoeff(&at);
      const ContactSurface& s = contacts.surfaces[contacts.families()[contacts.friction_family(p)].slave];
      std::ostringstream m;
      m << "    pair " << contacts.pairs[p].name << ": largest threshold change at surface node " << at << " (X = "
        << s.X.col(at).transpose() << "): " << rep.friction.nodal_tau[p][at] << " -> "
        << rep.friction.nodal_tau[p][at] + r[p][at];
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
}  // namespace

FrictionalReport solve_frictional_contact(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts,
                                          const DofMap& dofs, VectorXd& u, const FrictionalOptions& options,
                                          const Logger& log, const FrictionState* previous) {
  FrictionalReport rep;
  const int np = static_cast<int>(contacts.pairs.size());
  rep.friction.u_start = u;
  rep.friction.nodal_tau.assign(np, Eigen::VectorXd());
  if (previous) rep.friction.previous_tau = previous->nodal_tau;
  // The predictor (FrictionalOptions::extrapolate): this step repeats the previous one's increment, scaled.
  const double s_extrapolate = options.extrapolate && previous && energy.hessian_is_constant()
                                   ? proportional_increment(fixed, u, previous->u_start)
                                   : 0.0;
  bool any_friction = false, any_coulomb = false, warm = false;
  for (int p = 0; p < np; ++p) {
    const ContactPair& pair = contacts.pairs[p];
    if (pair.friction == FrictionLaw::kNone) continue;
    any_friction = true;
    const ContactSurface& s = contacts.surfaces[contacts.families()[contacts.friction_family(p)].slave];
    // Tresca: the given threshold; Coulomb: the previous step's, or 0 for a frictionless first solve.
    rep.friction.nodal_tau[p] =
        Eigen::VectorXd::Constant(s.num_nodes(), pair.friction == FrictionLaw::kTresca ? pair.tau : 0.0);
    if (pair.friction == FrictionLaw::kCoulomb) {
      any_coulomb = true;
      if (previous && p < static_cast<int>(previous->nodal_tau.size()) &&
          previous->nodal_tau[p].size() == s.num_nodes() && previous->nodal_tau[p].maxCoeff() > 0.0) {
        rep.friction.nodal_tau[p] = previous->nodal_tau[p];
        warm = true;
        if (s_extrapolate > 0.0 && p < static_cast<int>(previous->previous_tau.size()) &&
            previous->previous_tau[p].size() == s.num_nodes())
          rep.friction.nodal_tau[p] =
              (previous->nodal_tau[p] + s_extrapolate * (previous->nodal_tau[p] - previous->previous_tau[p]))
                  .cwiseMax(0.0);
      }
    }
  }
  const VectorXd u_step_start = u;
  if (warm && s_extrapolate > 0.0) {
    u += s_extrapolate * (u - previous->u_start);
    std::ostringstream m;
    m << "  predictor: the previous step's increment extrapolated (scale " << s_extrapolate << ")";
    log.detail(m.str());
  }
  // Inexact inner solves (FrictionalOptions::inner_tolerance_factor): the geometry fixed point of a solve
  // stops at factor × the threshold change that set its τ (1 before any is known: the frictionless start,
  // or the previous step's thresholds); without a Coulomb pair the one solve is the answer, to full tolerance.
  bool inexact = any_coulomb && energy.hessian_is_constant() && options.inner_tolerance_factor > 0.0;
  ContactSolveOptions inner = options.contact;  ///< tightened when the fixed point stagnates (InnerAccuracy)
  bool same_loads = false;
  // Between two solves only the surfaces are read (pressures, slips, the next search): with a condensed
  // workspace each solve leaves the interior out of date (ContactSolveOptions::lazy_interior) and u is made
  // whole once, when this load step ends — also when it throws (the last iterate is kept for inspection).
  const std::shared_ptr<ContactWorkspace> workspace = options.contact.workspace;
  struct CompleteOnExit {
    const EnergyTerm& energy;
    const FixedDofs& fixed;
    VectorXd& u;
    ContactWorkspace* ws;
    void now() {
      if (ws) complete_interior(energy, fixed, u, *ws);
    }
    ~CompleteOnExit() {  // a throw in flight: complete what can be, never throw from here
      try {
        now();
      } catch (...) {
      }
    }
  } complete_on_exit{energy, fixed, u, workspace.get()};
  auto solve = [&](double threshold_change) {
    ContactSolveOptions o = inner;
    if (inexact) o.loose_geometry_tolerance = options.inner_tolerance_factor * threshold_change;
    o.same_loads = same_loads;
    o.lazy_interior = options.lazy_interior;  // solve_contact applies it where it condenses (workspace, linear elasticity)
    ContactSolveReport r = solve_contact(energy, fixed, contacts, dofs, u, o, log, any_friction ? &rep.friction : nullptr);
    same_loads = true;  // the later solves of this call: the same load step, whose load part is now known
    rep.geometry_iterations += r.geometry_iterations;
    rep.ipopt_iterations += r.ipopt_iterations;
    rep.times.merge(r.times);
    rep.last = std::move(r);
  };
  if (warm) {
    // A warm start the solve cannot take (IPOPT failing from a start the moved boundary made far
    // infeasible, with the friction already on) falls back to the frictionless start.
    try {
      solve(1.0);
    } catch (const SolveError& e) {
      log.detail(std::string("  warm-started Coulomb solve failed (") + e.what() + "); starting frictionless");
      u = u_step_start;
      warm = false;
      for (int p = 0; p < np; ++p)
        if (contacts.pairs[p].friction == FrictionLaw::kCoulomb) rep.friction.nodal_tau[p].setZero();
      solve(1.0);
    }
  } else {
    solve(1.0);
  }
  if (!any_coulomb) {
    complete_on_exit.now();
    return rep;
  }
  std::vector<Eigen::VectorXd> r_prev;  // r_{k−1}, per pair (empty before the first Tresca solve)
  double omega = 1.0;
  double scale = 1.0;  ///< of the next solve's loose geometry tolerance: the last ‖r_k‖∞ / ‖τ_k‖∞ (1 before)
  FixedPointMonitor monitor;
  int tightenings = 0;         ///< inner accuracy raised this many times (at most kMaxTightenings)
  bool confirming = false;     ///< the last solve confirmed, to full tolerance, a change met on an inexact one
  for (int k = 1;; ++k) {
    // r_k = μ p_k − τ_k for every Coulomb pair (τ_0 = 0: the frictionless solve).
    const std::vector<Eigen::VectorXd> r = coulomb_residuals(contacts, dofs, u, rep, log);
    if (k > 1 || warm) {
      const int iteration = k - (warm ? 0 : 1);
      const double change = relative_change(r, rep.friction.nodal_tau);
      scale = change;
      rep.coulomb_change.push_back(change);
      monitor.record(change);
      omega = aitken_relaxation(r, r_prev, omega);
      rep.coulomb_relaxation.push_back(omega);
      std::ostringstream s;
      s << "  Coulomb iteration " << iteration << ": threshold change " << change << ", relaxation " << omega;
      log.detail(s.str());
      if (change < options.coulomb_tolerance) {
        // The loop ends on a solve converged to the geometry tolerance (and force-balanced): after an
        // inexact one, one more solve at full tolerance (its τ moves by less than the tolerance).
        if (rep.last.converged) break;
        log.detail("  thresholds settled on an inexact solve; one more solve to the geometry tolerance");
        scale = 0.0;
      } else if (confirming && inexact) {
        // The exact solve moved the thresholds back above the tolerance: the inexact solves' error was larger
        // than their change showed. The rest of the step solves to full tolerance, so that this cannot repeat.
        inexact = false;
        log.detail("  the solve to full tolerance undid the inexact solves' convergence; inner solves exact from now on");
      }
      confirming = scale == 0.0;
      if (monitor.stagnated()) {
        if (tightenings < kMaxTightenings) {
          ++tightenings;
          inexact = false;
          tighten(inner);
          std::ostringstream m;
          m << "  the Coulomb fixed point stagnated (no new low below " << monitor.best()
            << "); inner solves tightened to IPOPT tol " << inner.ipopt.tolerance << ", geometry tolerance "
            << inner.geometry_tolerance;
          log.detail(m.str());
          monitor.restart();
        } else if (rep.last.converged && change <= options.stagnation_acceptance) {
          rep.accepted_at_noise_floor = change;
          std::ostringstream m;
          m << "Coulomb fixed point: the thresholds stopped changing at " << change << " of their size (tolerance "
            << options.coulomb_tolerance << "), the noise floor of the inner solves; accepted: the friction law holds to "
            << change << " (acceptance " << options.stagnation_acceptance << ")";
          log.warning(m.str());
          break;
        } else {
          throw SolveError(coulomb_failure("stagnated", iteration, change, options, tightenings, inner, monitor));
        }
      }
      if (iteration >= options.max_coulomb_iterations)
        throw SolveError(coulomb_failure("did not converge", iteration, change, options, tightenings, inner, monitor));
    }
    for (int p = 0; p < np; ++p)
      if (r[p].size() > 0)
        rep.friction.nodal_tau[p] = (rep.friction.nodal_tau[p] + (k > 1 || warm ? omega : 1.0) * r[p]).cwiseMax(0.0);
    r_prev = r;
    rep.coulomb_iterations = k;
    solve(scale);
  }
  complete_on_exit.now();
  return rep;
}

}  // namespace symcontact
