#include "symcontact/solvers/geometry_fixed_point.hpp"

#include <sstream>

#include "symcontact/core/error.hpp"
#include "symcontact/solvers/contact_forces.hpp"
#include "symcontact/solvers/equilibrium_solver.hpp"
#include "symcontact/solvers/geometry_diagnostics.hpp"

namespace symcontact {

namespace {
/// How close to the tolerance a change that stops falling is taken for the subproblems' noise.
constexpr double kNearTolerance = 10.0;
}  // namespace

GeometryFixedPoint::GeometryFixedPoint(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts,
                                       const DofMap& dofs, const ContactSolveOptions& options, const Logger& log,
                                       const FrictionState* friction)
    : energy_(energy), fixed_(fixed), contacts_(contacts), dofs_(dofs), options_(options), log_(log),
      workspace_(options.workspace ? options.workspace : std::make_shared<ContactWorkspace>()),
      factorisations_at_start_(workspace_->factorisations),
      subproblem_(energy, fixed, contacts, dofs, options, *workspace_, log, friction),
      polish_(options.polish, *workspace_,
              options.geometry_acceleration > 0 && energy.hessian_is_constant() ? options.geometry_acceleration : 0,
              energy.hessian_is_constant() ? BodiesEnergy::kQuadratic : BodiesEnergy::kNonQuadratic),
      inexact_(options.loose_geometry_tolerance > options.geometry_tolerance),
      stop_tolerance_(inexact_ ? options.loose_geometry_tolerance : options.geometry_tolerance),
      ipopt_(options.ipopt) {
  // Anderson acceleration: quadratic energies only, where the closing polish solves each subproblem exactly.
  if (options.geometry_acceleration > 0 && energy.hessian_is_constant())
    anderson_ = std::make_unique<AndersonAcceleration>(options.geometry_acceleration);
}

SolveReport GeometryFixedPoint::solve(VectorXd& u) {
  const ReducedProblem& problem = subproblem_.reduced();
  rep_.num_free = problem.num_free();
  {
    // New Dirichlet values: a finite-strain body follows them by its linearised response first, so that
    // the start point inverts no cell next to a moved boundary (a quadratic energy just takes them).
    ScopedPhase t(rep_.times, "predictor");
    if (predict_dirichlet_increment(energy_, fixed_, u) < 1.0)
      log_.detail("the Dirichlet predictor took a shortened step; the rest of the boundary motion is imposed at once");
    fixed_.impose(u);
  }
  x_ = problem.restrict(u);
  for (int it = 1; !iterate(it, u); ++it) {
  }
  u = problem.expand(x_);
  workspace_->interior_pending = lazy_;
  rep_.interior_deferred = lazy_;
  rep_.friction = subproblem_.friction_terms();
  rep_.condensation_factorisations = workspace_->factorisations - factorisations_at_start_;
  CondensedResidual condensed;
  if (residual_b_.size() > 0) condensed = {&residual_b_, &workspace_->condensation->boundary_position()};
  ContactForces f = recover_contact_forces(energy_, fixed_, contacts_, dofs_, u, rep_.linearization.A,
                                           rep_.multipliers, subproblem_.friction_terms(), condensed);
  rep_.contact_force = std::move(f.contact_force);
  rep_.multiplier_force = std::move(f.multiplier_force);
  rep_.force_defect = std::move(f.force_defect);
  return rep_;
}

/// Whether this iteration's rows are the previous solution's (same families, same nodes): then its
/// multipliers start the optimiser. The first geometry iteration starts from the previous solve of the run
/// (the previous Coulomb iteration or load step) when its rows are the same.
bool GeometryFixedPoint::rows_match_previous(int it) {
  const ContactLinearization& lin = rep_.linearization;
  const bool from_previous_solve = it == 1 && workspace_->multipliers.size() == lin.A.rows();
  if (from_previous_solve) {
    mu_prev_ = workspace_->multipliers;
    rows_prev_family_ = workspace_->row_family;
    rows_prev_node_ = workspace_->row_node;
  }
  return (it > 1 || from_previous_solve) && lin.row_family == rows_prev_family_ && lin.row_node == rows_prev_node_;
}

/// One geometry iteration; true when the fixed point has converged (the solution is then in x_).
bool GeometryFixedPoint::iterate(int it, VectorXd& u) {
  const ReducedProblem& problem = subproblem_.reduced();
  const VectorXd u_it = problem.expand(x_);  ///< the iterate with its fixed DOFs
  {
    // A pair in ContactGeometry::kReference gives the same rows and friction points at every iterate
    // (contact_geometry.hpp): with every pair so, the second iteration repeats the first subproblem and its
    // change is that subproblem's noise, below the tolerance, which ends the loop.
    ScopedPhase t(rep_.times, "search");
    rep_.linearization = contacts_.linearize(dofs_, u_it);
  }
  const ContactLinearization& lin = rep_.linearization;
  if (it == 1) warn_pairs_without_points(contacts_, lin, log_);
  if (it > 1 && accept_unchanged(it, u_it)) return true;
  ConstrainedProblem& target = subproblem_.build(lin, u_it, x_, rep_.times);
  const CondensedProblem* condensed = subproblem_.condensed();
  rep_.num_constraints = lin.A.rows();
  rep_.num_condensed = condensed ? condensed->num_variables() : 0;
  // ContactSolveOptions::lazy_interior: this iteration updates B only.
  lazy_ = options_.lazy_interior && options_.workspace && condensed &&
          surfaces_condensed(contacts_, dofs_, problem.free_index(), workspace_->condensation->boundary_position());
  if (lazy_) workspace_->interior_pending = true;  // from here on until an iteration expands (a failure completes u)
  auto from_target = [&](const VectorXd& xt) { return condensed ? condensed->expand(xt) : xt; };
  const bool same_rows = rows_match_previous(it);
  auto [s, dual] = subproblem_.solve(x_, it, same_rows ? &mu_prev_ : nullptr, ipopt_, polish_.closes(), rep_);
  IpoptResult& res = s.result;
  bool closed = s.closed;  ///< the active set was closed exactly at this iteration
  if (dual) {
    if (!s.closing_failure.empty()) polish_.closing_rejected(s.closing_failure, log_);
    polish_.dual_iteration();
  }
  rep_.ipopt_iterations += s.failed_iterations + res.iterations;
  rep_.ipopt_per_iteration.push_back(res.iterations);
  rep_.ipopt_status = res.status_text;
  rep_.geometry_iterations = it;
  if (!res.success) {
    u = problem.expand(res.x.size() == target.num_variables() ? from_target(res.x) : x_);
    throw SolveError("IPOPT failed (" + res.status_text + ") at geometry iteration " + std::to_string(it));
  }
  if (!dual) closed = polish_.polish_primal(target, res, log_, rep_.times);
  if (condensed) {
    ScopedPhase t(rep_.times, "condensation");
    res.x = lazy_ ? condensed->with_boundary(x_, res.x) : condensed->expand(res.x);
  }
  const double change =
      (res.x - x_).lpNorm<Eigen::Infinity>() / std::max(res.x.lpNorm<Eigen::Infinity>(), 1e-300);
  if (polish_.balance_deferred() && !inexact_ && change < options_.geometry_tolerance)
    balance_at_end(target, condensed, res);
  polish_.record_change(change, closed, rep_.change_history, log_);
  rep_.change_history.push_back(change);
  if (log_.level() >= Verbosity::kDebug)
    log_geometry_change(problem.expand(res.x) - u_it, dofs_, lin, rows_prev_family_, rows_prev_node_,
                        log_);
  const VectorXd x_in = x_;
  x_ = res.x;
  mu_prev_ = res.multipliers;
  rows_prev_family_ = lin.row_family;
  rows_prev_node_ = lin.row_node;
  {
    std::ostringstream m;
    m << "  geometry iteration " << it << ": " << lin.A.rows() << " constraints, IPOPT " << res.iterations << " iterations ("
      << res.status_text << "), change " << change;
    log_iteration(log_, clock_, m.str());
  }
  if (change < stop_tolerance_) {
    accept(condensed, res, change);
    return true;
  }
  after_stagnation(it, change, u);
  accelerate(x_in, res, closed, same_rows);
  x_solves_last_ = x_ == res.x;
  return false;
}

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
        << "); IPOPT tol tightened to " << ipopt_.tolerance;
    else
      s << "  the geometry fixed point stagnated (no new low below " << monitor_.best()
        << "); IPOPT tol tightened to " << ipopt_.tolerance;
    log_.detail(s.str());
    monitor_.restart();
  }
  if (it < options_.max_geometry_iterations) return;
  u = subproblem_.reduced().expand(x_);
  std::ostringstream s;
  s << "the geometry fixed point did not converge in " << options_.max_geometry_iterations
    << " iterations (last relative change " << change << ", tolerance " << stop_tolerance_ << ")";
  if (tightenings_ > 0) s << "; tried: IPOPT tol tightened " << tightenings_ << " time(s), to " << ipopt_.tolerance;
  s << "; try smaller load steps ([contact_solver] max_step_cuts = 4, or more [steps])";
  throw SolveError(s.str());
}

/// The next iterate: Anderson's (anderson_acceleration.hpp) while the map stays the same smooth one (same
/// rows, the set closed exactly on the same active set), else the plain step, restarting the history.
void GeometryFixedPoint::accelerate(const VectorXd& x_in, const IpoptResult& res, bool closed, bool same_rows) {
  if (!anderson_) return;
  std::vector<char> active(res.multipliers.size());
  for (Index r = 0; r < res.multipliers.size(); ++r) active[r] = res.multipliers[r] > 0.0;
  const bool smooth = closed && same_rows && active == active_prev_;
  if (!smooth) anderson_->reset();
  if (closed) {
    x_ = anderson_->next(x_in, res.x);
    if (anderson_->columns() > 0)
      log_.debug("  next geometry: Anderson step on " + std::to_string(anderson_->columns()) + " differences");
  }
  active_prev_ = closed ? active : std::vector<char>();
}

}  // namespace symcontact
