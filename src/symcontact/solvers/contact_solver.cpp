#include "symcontact/solvers/contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "symcontact/core/error.hpp"
#include "symcontact/core/progress_clock.hpp"
#include "symcontact/solvers/anderson_acceleration.hpp"
#include "symcontact/solvers/condensed_problem.hpp"
#include "symcontact/solvers/contact_forces.hpp"
#include "symcontact/solvers/dual_subproblem.hpp"
#include "symcontact/solvers/equilibrium_solver.hpp"
#include "symcontact/solvers/fixed_point_monitor.hpp"
#include "symcontact/solvers/polish_strategy.hpp"
#include "symcontact/solvers/primal_subproblem.hpp"
#include "symcontact/solvers/reduced_problem.hpp"
#include "symcontact/solvers/static_condensation.hpp"

namespace symcontact {

namespace {
/// The bodies' energy plus the friction terms of the current geometry iterate.
class CompositeEnergy : public EnergyTerm {
 public:
  explicit CompositeEnergy(const EnergyTerm& base) : base_(base) {}
  std::vector<std::shared_ptr<const FrictionTerm>> extra;
  std::string name() const override { return "energy+friction"; }
  double value(const VectorXd& u) const override {
    double v = base_.value(u);
    for (const auto& t : extra)
      if (t) v += t->value(u);
    return v;
  }
  void add_gradient(const VectorXd& u, VectorXd& g) const override {
    base_.add_gradient(u, g);
    for (const auto& t : extra)
      if (t) t->add_gradient(u, g);
  }
  void add_hessian(const VectorXd& u, MatrixSink& sink) const override {
    base_.add_hessian(u, sink);
    for (const auto& t : extra)
      if (t) t->add_hessian(u, sink);
  }
  bool hessian_is_constant() const override {
    for (const auto& t : extra)
      if (t) return false;
    return base_.hessian_is_constant();
  }

 private:
  const EnergyTerm& base_;
};
}  // namespace

void tighten_optimiser(IpoptOptions& o) {
  o.tolerance *= 1e-2;
  if (auto it = o.numeric_options.find("tol"); it != o.numeric_options.end()) it->second *= 1e-2;
}

namespace {

/// A pair that sees nothing at all is usually a mistake (a meshed obstacle whose facets face away, a search
/// distance too small): say so rather than let the bodies pass through each other.
void warn_pairs_without_points(const ContactSet& contacts, const ContactLinearization& lin, const Logger& log) {
  for (int p = 0; p < static_cast<int>(contacts.pairs.size()); ++p) {
    std::size_t n = 0;
    for (int f = 0; f < static_cast<int>(contacts.families().size()); ++f)
      if (contacts.families()[f].pair == p) n += lin.points[f].size();
    if (n == 0)
      log.warning("contact '" + contacts.pairs[p].name +
                  "': no point of its surfaces faces the opposite side within the search distance " +
                  std::to_string(contacts.pairs[p].search_distance) +
                  " (a meshed obstacle's facets must be oriented with their normal towards the body)");
  }
}

/// Debug log of one geometry iteration: where the displacement changed most, and which constraint rows
/// (family, slave surface node) came and went since the previous linearisation — what a fixed point that
/// wanders or cycles is doing.
void log_geometry_change(const VectorXd& du, const DofMap& dofs, const ContactLinearization& lin,
                         const std::vector<int>& prev_family, const std::vector<Index>& prev_node, const Logger& log) {
  std::ostringstream s;
  Index d = 0;
  const double m = du.size() ? du.cwiseAbs().maxCoeff(&d) : 0.0;
  int body = 0;
  while (body + 1 < dofs.num_bodies() && d >= dofs.offset(body + 1)) ++body;
  s << "    largest change " << m << " at body " << body << " node " << (d - dofs.offset(body)) / dofs.dim()
    << " component " << (d - dofs.offset(body)) % dofs.dim();
  if (!prev_family.empty()) {
    std::set<std::pair<int, Index>> before, now;
    for (std::size_t r = 0; r < prev_family.size(); ++r) before.insert({prev_family[r], prev_node[r]});
    for (std::size_t r = 0; r < lin.row_family.size(); ++r) now.insert({lin.row_family[r], lin.row_node[r]});
    s << "; rows added:";
    for (const auto& fr : now)
      if (!before.count(fr)) s << " " << fr.first << ":" << fr.second;
    s << "; removed:";
    for (const auto& fr : before)
      if (!now.count(fr)) s << " " << fr.first << ":" << fr.second;
  }
  log.debug(s.str());
}

/// Algorithm 2's loop for one solve: linearise at the iterate, assemble the friction terms, condense, solve
/// the subproblem (subproblem.hpp), polish (polish_strategy.hpp), accelerate, until the relative change of
/// the iterate is below the tolerance. One object per solve_contact call.
class GeometryFixedPoint {
 public:
  GeometryFixedPoint(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts,
                     const DofMap& dofs, const ContactSolveOptions& options, const Logger& log,
                     const FrictionState* friction);
  SolveReport solve(VectorXd& u);

 private:
  bool iterate(int it, VectorXd& u);
  void assemble(const VectorXd& u_it);
  std::unique_ptr<CondensedProblem> condense(const VectorXd& u_it);
  bool rows_match_previous(int it);
  SubproblemSolution solve_subproblem(int it, ConstrainedProblem& target, const CondensedProblem* condensed,
                                      bool same_rows, bool& dual);
  void accept(const CondensedProblem* condensed, const IpoptResult& res, double change);
  void after_stagnation(int it, double change, VectorXd& u);
  void accelerate(const VectorXd& x_in, const IpoptResult& res, bool closed, bool same_rows);

  const EnergyTerm& energy_;
  const FixedDofs& fixed_;
  const ContactSet& contacts_;
  const DofMap& dofs_;
  const ContactSolveOptions& options_;
  const Logger& log_;
  const FrictionState* friction_;
  SolveReport rep_;
  CompositeEnergy total_;
  ReducedProblem problem_;  ///< the bodies' energy with the friction terms
  ReducedProblem bulk_;     ///< the bodies' energy alone (static condensation)
  const bool condense_;
  const std::shared_ptr<ContactWorkspace> workspace_;
  const int factorisations_at_start_;
  std::shared_ptr<const CondensedLoad> condensed_load_;  ///< of this solve's Dirichlet values and loads
  std::unique_ptr<DualIpopt> dual_;  ///< null: the dual is not used
  std::unique_ptr<PrimalIpopt> primal_;
  PolishStrategy polish_;
  std::unique_ptr<AndersonAcceleration> anderson_;
  /// An inexact solve (ContactSolveOptions::loose_geometry_tolerance) is never balanced at the end nor
  /// reported converged, even where its change falls below geometry_tolerance: its answer is an intermediate.
  const bool inexact_;
  const double stop_tolerance_;
  IpoptOptions ipopt_;  ///< the settings of this solve: tightened when the fixed point stagnates
  FixedPointMonitor monitor_;
  int tightenings_ = 0;
  VectorXd x_;                        ///< the iterate (free DOFs)
  VectorXd mu_prev_;                  ///< the previous rows' multipliers
  std::vector<int> rows_prev_family_;
  std::vector<Index> rows_prev_node_;
  std::vector<char> active_prev_;     ///< rows with μ > 0 after the previous closed polish
  VectorXd residual_b_;  ///< ∇E on the condensed set B at the solution, when the last iteration was condensed
  std::vector<std::shared_ptr<const FrictionTerm>> friction_terms_;  ///< per pair, for the reported slips
  bool lazy_ = false;  ///< the iterate's interior is out of date (ContactSolveOptions::lazy_interior)
  ProgressClock clock_;  ///< since the solve started
};

GeometryFixedPoint::GeometryFixedPoint(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts,
                                       const DofMap& dofs, const ContactSolveOptions& options, const Logger& log,
                                       const FrictionState* friction)
    : energy_(energy), fixed_(fixed), contacts_(contacts), dofs_(dofs), options_(options), log_(log),
      friction_(friction), total_(energy), problem_(total_, fixed, dofs.num_dofs()),
      bulk_(energy, fixed, dofs.num_dofs()), condense_(options.static_condensation && energy.hessian_is_constant()),
      workspace_(options.workspace ? options.workspace : std::make_shared<ContactWorkspace>()),
      factorisations_at_start_(workspace_->factorisations), dual_(dual_method(contacts, options.subproblem_solver)),
      primal_(primal_method(contacts, options.subproblem_solver)),
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
  rep_.num_free = problem_.num_free();
  {
    // New Dirichlet values: a finite-strain body follows them by its linearised response first, so that
    // the start point inverts no cell next to a moved boundary (a quadratic energy just takes them).
    ScopedPhase t(rep_.times, "predictor");
    if (predict_dirichlet_increment(energy_, fixed_, u) < 1.0)
      log_.detail("the Dirichlet predictor took a shortened step; the rest of the boundary motion is imposed at once");
    fixed_.impose(u);
  }
  x_ = problem_.restrict(u);
  for (int it = 1; !iterate(it, u); ++it) {
  }
  u = problem_.expand(x_);
  workspace_->interior_pending = lazy_;
  rep_.interior_deferred = lazy_;
  rep_.friction = friction_terms_;
  rep_.condensation_factorisations = workspace_->factorisations - factorisations_at_start_;
  CondensedResidual condensed;
  if (residual_b_.size() > 0) condensed = {&residual_b_, &workspace_->condensation->boundary_position()};
  ContactForces f = recover_contact_forces(energy_, fixed_, contacts_, dofs_, u, rep_.linearization.A,
                                           rep_.multipliers, friction_terms_, condensed);
  rep_.contact_force = std::move(f.contact_force);
  rep_.multiplier_force = std::move(f.multiplier_force);
  rep_.force_defect = std::move(f.force_defect);
  return rep_;
}

/// The constraints of the current linearisation and the friction terms of the current iterate. A zero
/// threshold (the frictionless start of Coulomb, μ = 0) adds nothing to the energy: its term is left out of
/// it, so that the problem stays quadratic, and kept for the slips it reports.
void GeometryFixedPoint::assemble(const VectorXd& u_it) {
  ScopedPhase t(rep_.times, "assembly");
  const ContactLinearization& lin = rep_.linearization;
  problem_.set_constraints(lin.A, lin.b);
  total_.extra.assign(contacts_.pairs.size(), nullptr);
  friction_terms_.assign(contacts_.pairs.size(), nullptr);
  if (!friction_) return;
  friction_terms_ = friction_terms(*friction_, contacts_, dofs_, u_it);
  for (std::size_t p = 0; p < friction_terms_.size(); ++p)
    if (friction_terms_[p] && friction_->nodal_tau[p].maxCoeff() > 0.0) total_.extra[p] = friction_terms_[p];
}

std::unique_ptr<CondensedProblem> GeometryFixedPoint::condense(const VectorXd& u_it) {
  if (!condense_) return nullptr;
  ScopedPhase t(rep_.times, "condensation");
  return condense_problem(bulk_, problem_, contacts_, dofs_, total_.extra, u_it, x_, energy_,
                          *workspace_, {options_.max_condensed_dofs, options_.same_loads}, log_, condensed_load_);
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

/// The subproblem by the dual where it applies (a condensed quadratic problem with constraints and a clean
/// Schur complement), else — or when the dual fails — by the primal, the reference formulation.
SubproblemSolution GeometryFixedPoint::solve_subproblem(int it, ConstrainedProblem& target,
                                                        const CondensedProblem* condensed, bool same_rows,
                                                        bool& dual) {
  const SemidefiniteFactor* schur = nullptr;
  if (condensed && dual_ && condensed->hessian_is_constant() && rep_.linearization.A.rows() > 0) {
    ScopedPhase t(rep_.times, "condensation");  // the Schur complement's factor: once per condensation
    schur = dual_schur_factor(*workspace_, log_);
  }
  const VectorXd start = condensed ? condensed->restrict(x_) : x_;
  const SubproblemWarmStart warm{same_rows ? &mu_prev_ : nullptr};
  Subproblem p{target, condensed, schur, start, it, ipopt_, polish_.closes(), {}};
  dual = false;
  if (schur) {
    SubproblemSolution s = dual_->solve(p, warm, log_, rep_.times);
    ++rep_.dual_solves;
    if (s.result.success) {
      dual = true;
      return s;
    }
    log_.detail("  IPOPT failed on the dual (" + s.result.status_text + "); the primal is solved instead");
    rep_.ipopt_iterations += s.failed_iterations + s.result.iterations;
  }
  if (friction_)
    p.restart = [this, condensed] {
      VectorXd u_retry = friction_->u_start;  // the start of the step, moved as at the first solve
      predict_dirichlet_increment(energy_, fixed_, u_retry);
      const VectorXd xr = problem_.restrict(u_retry);
      return condensed ? condensed->restrict(xr) : xr;
    };
  return primal_->solve(p, warm, log_, rep_.times);
}

/// One geometry iteration; true when the fixed point has converged (the solution is then in x_).
bool GeometryFixedPoint::iterate(int it, VectorXd& u) {
  const VectorXd u_it = problem_.expand(x_);  ///< the iterate with its fixed DOFs
  {
    // A pair in ContactGeometry::kReference gives the same rows and friction points at every iterate
    // (contact_geometry.hpp): with every pair so, the second iteration repeats the first subproblem and its
    // change is that subproblem's noise, below the tolerance, which ends the loop.
    ScopedPhase t(rep_.times, "search");
    rep_.linearization = contacts_.linearize(dofs_, u_it);
  }
  const ContactLinearization& lin = rep_.linearization;
  if (it == 1) warn_pairs_without_points(contacts_, lin, log_);
  assemble(u_it);
  rep_.num_constraints = lin.A.rows();
  std::unique_ptr<CondensedProblem> condensed = condense(u_it);
  rep_.num_condensed = condensed ? condensed->num_variables() : 0;
  // ContactSolveOptions::lazy_interior: this iteration updates B only.
  lazy_ = options_.lazy_interior && options_.workspace && condensed &&
          surfaces_condensed(contacts_, dofs_, problem_.free_index(), workspace_->condensation->boundary_position());
  if (lazy_) workspace_->interior_pending = true;  // from here on until an iteration expands (a failure completes u)
  ConstrainedProblem& target = condensed ? static_cast<ConstrainedProblem&>(*condensed) : problem_;
  auto from_target = [&](const VectorXd& xt) { return condensed ? condensed->expand(xt) : xt; };
  const bool same_rows = rows_match_previous(it);
  bool dual = false;
  SubproblemSolution s = solve_subproblem(it, target, condensed.get(), same_rows, dual);
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
    u = problem_.expand(res.x.size() == target.num_variables() ? from_target(res.x) : x_);
    throw SolveError("IPOPT failed (" + res.status_text + ") at geometry iteration " + std::to_string(it));
  }
  if (!dual) closed = polish_.polish_primal(target, res, log_, rep_.times);
  if (condensed) {
    ScopedPhase t(rep_.times, "condensation");
    res.x = lazy_ ? condensed->with_boundary(x_, res.x) : condensed->expand(res.x);
  }
  const double change =
      (res.x - x_).lpNorm<Eigen::Infinity>() / std::max(res.x.lpNorm<Eigen::Infinity>(), 1e-300);
  if (polish_.balance_deferred() && !inexact_ && change < options_.geometry_tolerance) {
    VectorXd xt = condensed ? condensed->restrict(res.x) : res.x;
    polish_.balance(target, xt, res.multipliers, log_, rep_.times);
    ScopedPhase t(rep_.times, "condensation");
    res.x = lazy_ ? condensed->with_boundary(res.x, xt) : from_target(xt);
  }
  polish_.record_change(change, closed, rep_.change_history, log_);
  rep_.change_history.push_back(change);
  if (log_.level() >= Verbosity::kDebug)
    log_geometry_change(problem_.expand(res.x) - u_it, dofs_, lin, rows_prev_family_, rows_prev_node_,
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
    accept(condensed.get(), res, change);
    return true;
  }
  after_stagnation(it, change, u);
  accelerate(x_in, res, closed, same_rows);
  return false;
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
  if (monitor_.stagnated() && tightenings_ < kMaxTightenings) {
    ++tightenings_;
    tighten_optimiser(ipopt_);
    std::ostringstream s;
    s << "  the geometry fixed point stagnated (no new low below " << monitor_.best() << "); IPOPT tol tightened to "
      << ipopt_.tolerance;
    log_.detail(s.str());
    monitor_.restart();
  }
  if (it < options_.max_geometry_iterations) return;
  u = problem_.expand(x_);
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

}  // namespace

SolveReport solve_contact(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts,
                                 const DofMap& dofs, VectorXd& u, const ContactSolveOptions& options,
                                 const Logger& log, const FrictionState* friction) {
  // A solve that is not lazy starts from a whole u; one that fails leaves a whole last iterate.
  auto complete = [&] {
    if (options.workspace) complete_interior(energy, fixed, u, *options.workspace);
  };
  if (!options.lazy_interior) complete();
  // IPOPT and the polish back away from states the energy cannot be evaluated at; one left over (the
  // start point of a step) is a failed solve, not an internal error.
  try {
    try {
      return GeometryFixedPoint(energy, fixed, contacts, dofs, options, log, friction).solve(u);
    } catch (const EvaluationError& e) {
      throw SolveError(std::string("the contact solve reached a state the energy cannot be evaluated at: ") +
                       e.what() + " — use smaller load steps");
    }
  } catch (const SolveError&) {
    complete();
    throw;
  }
}

}  // namespace symcontact
