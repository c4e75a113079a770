#include "symcontact/solvers/geometry_fixed_point.hpp"

#include <sstream>

#include "symcontact/core/error.hpp"
#include "symcontact/solvers/contact_forces.hpp"
#include "symcontact/solvers/equilibrium_solver.hpp"
#include "symcontact/solvers/geometry_diagnostics.hpp"

namespace symcontact {

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
  // Rows that changed since the previous iteration or solve (the edge of a zone moving in or out of the search
  // distance): its multipliers carried by family and node, 0 on the new rows, still start the active set.
  VectorXd carried;
  if (!same_rows && it > 1) carried = values_on_rows(rows_prev_family_, rows_prev_node_, mu_prev_, lin);
  if (!same_rows && it == 1 && workspace_->multipliers.size() > 0)
    carried = values_on_rows(workspace_->row_family, workspace_->row_node, workspace_->multipliers, lin);
  const SubproblemWarmStart warm{same_rows ? &mu_prev_ : nullptr, carried.size() > 0 ? &carried : nullptr};
  auto [s, dual] = subproblem_.solve(x_, it, warm, ipopt_, polish_.closes(), rep_);
  IpoptResult& res = s.result;
  bool closed = s.closed;  ///< the active set was closed exactly at this iteration
  if (dual && !s.closing_failure.empty()) polish_.closing_rejected(s.closing_failure, log_);
  rep_.ipopt_iterations += s.failed_iterations + res.iterations;
  rep_.ipopt_per_iteration.push_back(res.iterations);
  rep_.ipopt_status = res.status_text;
  rep_.geometry_iterations = it;
  if (!res.success) {
    u = problem.expand(res.x.size() == target.num_variables() ? from_target(res.x) : x_);
    throw SolveError("IPOPT failed (" + res.status_text + ") at geometry iteration " + std::to_string(it));
  }
  // The dual's point, and a primal one its method closed (the active-set start: exact on its set, stationary
  // to round-off), leave the polish nothing to do.
  if (dual || s.closed)
    polish_.closed_by_method();
  else
    closed = polish_.polish_primal(target, res, log_, rep_.times);
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
    m << "  geometry iteration " << it << ": " << lin.A.rows() << " constraints, optimizer " << res.iterations << " iterations ("
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
