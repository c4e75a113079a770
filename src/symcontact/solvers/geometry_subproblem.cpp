#include "symcontact/solvers/geometry_subproblem.hpp"

#include "symcontact/contact/surface_tractions.hpp"
#include "symcontact/solvers/equilibrium_solver.hpp"
#include "symcontact/solvers/condensation_cache.hpp"

namespace symcontact {

namespace {

/// Who may take the uncondensed problem (CondensationLimits::sparse_alternative): linear-elastic bodies only;
/// the primal interior point where it solves, else IPOPT as ContactSolveOptions::ipopt_problem says.
SparseAlternative sparse_alternative(const EnergyTerm& energy, const ContactSet& contacts,
                                     const ContactSolveOptions& options) {
  if (!energy.hessian_is_constant()) return SparseAlternative::kNone;
  if (dense_primal_first(contacts, options.subproblem_solver)) return SparseAlternative::kWholeSolve;
  switch (options.ipopt_problem) {
    case IpoptProblem::kCondensed: return SparseAlternative::kNone;
    case IpoptProblem::kUncondensed: return SparseAlternative::kOptimiserAlways;
    case IpoptProblem::kAutomatic: break;
  }
  return SparseAlternative::kOptimiser;
}

}  // namespace

GeometrySubproblem::GeometrySubproblem(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts,
                                       const DofMap& dofs, const ContactSolveOptions& options,
                                       ContactWorkspace& workspace, const Logger& log, const FrictionState* friction)
    : energy_(energy), fixed_(fixed), contacts_(contacts), dofs_(dofs), options_(options), workspace_(workspace),
      log_(log), friction_(friction), total_(energy), problem_(total_, fixed, dofs.num_dofs()),
      bulk_(energy, fixed, dofs.num_dofs()), condense_(options.static_condensation && energy.hessian_is_constant()),
      dual_(dual_method(options.subproblem_solver, options.warm_start)),
      primal_(primal_method(contacts, dofs.dim(), options.subproblem_solver, options.warm_start)),
      follows_(friction && friction->follower),
      sparse_alternative_(sparse_alternative(energy, contacts, options)),
      friction_hessian_(primal_interior_point_first(contacts, dofs.dim(), options.subproblem_solver)
                            ? FrictionHessian::kPrimalDual
                            : FrictionHessian::kExact) {
  // Linear elasticity: K_ff assembled once (bulk_ caches it) and the bodies' energy its quadratic form, the friction
  // terms at each call.
  if (energy.hessian_is_constant())
    problem_.split_energy(bulk_, {[this](const VectorXd& u) { return total_.extra_value(u); },
                                  [this](const VectorXd& u, VectorXd& g) { total_.add_extra_gradient(u, g); },
                                  [this](const VectorXd& u, MatrixSink& sink) { total_.add_extra_hessian(u, sink); }});
}

/// A zero threshold (the frictionless start of Coulomb, μ = 0) adds nothing to the energy: its term is left out
/// of it, so that the problem stays quadratic, and kept for the slips it reports — unless the thresholds follow
/// the iterates, which may make them positive.
ConstrainedProblem& GeometrySubproblem::build(const ContactLinearization& lin, const VectorXd& u_it,
                                              const VectorXd& x, PhaseTimes& times) {
  {
    ScopedPhase t(times, "assembly");
    last_.A = lin.A;
    last_.b = lin.b;
    last_.row_family = lin.row_family;
    last_.row_node = lin.row_node;
    problem_.set_constraints(lin.A, lin.b);
    total_.extra.assign(contacts_.pairs.size(), nullptr);
    friction_terms_.assign(contacts_.pairs.size(), nullptr);
    if (friction_) {
      friction_terms_ = symcontact::friction_terms(*friction_, contacts_, dofs_, u_it);
      for (std::size_t p = 0; p < friction_terms_.size(); ++p) {
        if (friction_terms_[p]) friction_terms_[p]->set_hessian_model(friction_hessian_);
        if (friction_terms_[p] && (follows_ || friction_->nodal_tau[p].maxCoeff() > 0.0))
          total_.extra[p] = friction_terms_[p];
      }
    }
  }
  condensed_.reset();
  if (!condense_) return problem_;
  ScopedPhase t(times, "condensation");
  condensed_ = condense_problem(bulk_, problem_, contacts_, dofs_, total_.extra, u_it, x, energy_, workspace_,
                                {options_.max_condensed_dofs, options_.same_loads, sparse_alternative_}, log_,
                                condensed_load_);
  if (condensed_) return *condensed_;
  return problem_;
}

namespace {

/// Two sparse matrices with the same pattern and the same values, bit for bit.
bool identical(const SparseMatrix& a, const SparseMatrix& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols() || a.nonZeros() != b.nonZeros()) return false;
  for (Index j = 0; j < a.outerSize(); ++j) {
    SparseMatrix::InnerIterator ia(a, j), ib(b, j);
    for (; ia && ib; ++ia, ++ib)
      if (ia.row() != ib.row() || ia.value() != ib.value()) return false;
    if (ia || ib) return false;
  }
  return true;
}

/// The same point in every field a FrictionTerm reads (friction_term.hpp): where it is and what it weighs.
bool same_friction_point(const ContactPoint& a, const ContactPoint& b) {
  return a.slave_facet == b.slave_facet && a.xi[0] == b.xi[0] && a.xi[1] == b.xi[1] &&
         a.master_facet == b.master_facet && a.eta[0] == b.eta[0] && a.eta[1] == b.eta[1] &&
         a.normal == b.normal && a.weight == b.weight && a.slave_node == b.slave_node;
}

}  // namespace

bool GeometrySubproblem::unchanged(const ContactLinearization& lin, const VectorXd& u_it, double b_tolerance) const {
  if (lin.row_family != last_.row_family || lin.row_node != last_.row_node || !identical(lin.A, last_.A) ||
      lin.b.size() != last_.b.size() || (lin.b.size() > 0 && (lin.b - last_.b).lpNorm<Eigen::Infinity>() > b_tolerance))
    return false;
  for (std::size_t p = 0; p < friction_terms_.size(); ++p) {
    if (!friction_terms_[p]) continue;
    const std::vector<ContactPoint> now = nodal_friction_points(contacts_, static_cast<int>(p), dofs_, u_it);
    const std::vector<ContactPoint>& then = friction_terms_[p]->points();
    if (now.size() != then.size()) return false;
    for (std::size_t q = 0; q < now.size(); ++q)
      if (!same_friction_point(now[q], then[q])) return false;
  }
  return true;
}

/// The bodies' force on the surfaces at the uncondensed iterate x with multipliers λ, as
/// CondensedProblem::surface_force gives it: Aᵀλ − ∇(friction terms) at the free DOFs, zero at the others
/// (full-DOF vector).
VectorXd GeometrySubproblem::surface_force(const VectorXd& x, const VectorXd& multipliers) {
  const VectorXd u = problem_.expand(x);
  VectorXd friction = VectorXd::Zero(u.size());
  total_.add_extra_gradient(u, friction);
  const VectorXd free_force = problem_.constraint_matrix().transpose() * multipliers;
  const std::vector<Index>& free_index = problem_.free_index();
  VectorXd f = VectorXd::Zero(u.size());
  for (std::size_t d = 0; d < free_index.size(); ++d)
    if (free_index[d] >= 0) f[static_cast<Index>(d)] = free_force[free_index[d]] - friction[static_cast<Index>(d)];
  return f;
}

void GeometrySubproblem::add_fixed_dof_force(const VectorXd& multipliers, VectorXd& force) const {
  const VectorXd multiplier_force = last_.A.transpose() * multipliers;
  const std::vector<Index>& free_index = problem_.free_index();
  for (std::size_t d = 0; d < free_index.size(); ++d)
    if (free_index[d] < 0) force[static_cast<Index>(d)] = multiplier_force[static_cast<Index>(d)];
}

std::function<bool(const VectorXd&, const VectorXd&)> GeometrySubproblem::follow_hook(CondensedProblem* condensed) {
  return [this, condensed](const VectorXd& y, const VectorXd& multipliers) {
    // The force the residual of the Coulomb loop reads (CoulombThresholds::residual): the follower's τ and the
    // loop's must be the same function of the answer, or the loop stalls at their difference (at a node whose
    // interface normal has a component along a fixed DOF: the multipliers' force there).
    VectorXd force = condensed ? condensed->surface_force(y, multipliers) : surface_force(y, multipliers);
    add_fixed_dof_force(multipliers, force);
    const bool changed = friction_->follower->follow(
        condensed ? condensed->surface_displacement(y) : problem_.expand(y), force);
    if (!changed) return false;
    for (std::size_t p = 0; p < friction_terms_.size(); ++p) {
      if (!friction_terms_[p] || contacts_.pairs[p].friction != FrictionLaw::kCoulomb) continue;
      const ContactSurface& slave = contacts_.surfaces[contacts_.families()[contacts_.friction_family(p)].slave];
      const std::vector<ContactPoint>& points = friction_terms_[p]->points();
      friction_terms_[p]->set_thresholds(interpolate_at_points(slave, points, friction_->nodal_tau[p]));
    }
    return true;
  };
}

ConstrainedProblem& GeometrySubproblem::target() {
  if (condensed_) return *condensed_;
  return problem_;
}

GeometrySubproblem::Outcome GeometrySubproblem::solve(const VectorXd& x, int geometry_iteration,
                                                      const SubproblemWarmStart& warm, const IpoptOptions& ipopt,
                                                      bool close_active_set, SolveReport& rep) {
  const CondensedProblem* condensed = condensed_.get();
  ConstrainedProblem& target = this->target();
  const SemidefiniteFactor* schur = nullptr;
  if (condensed && dual_ && condensed->hessian_is_constant() && target.constraint_matrix().rows() > 0) {
    ScopedPhase t(rep.times, "condensation");  // the Schur complement's factor: once per condensation
    schur = dual_schur_factor(workspace_, log_);
  }
  const VectorXd start = condensed ? condensed->restrict(x) : x;
  Subproblem p{target,    condensed, schur, start, geometry_iteration, ipopt, close_active_set,
               energy_.hessian_is_constant(), {}, {}};
  if (schur) {
    SubproblemSolution s = dual_->solve(p, warm, log_, rep.times);
    ++rep.dual_solves;
    if (s.result.success) return {std::move(s), true};
    log_.detail("  IPOPT failed on the dual (" + s.result.status_text + "); the primal is solved instead");
    rep.ipopt_iterations += s.failed_iterations + s.result.iterations;
  }
  if (follows_) {
    friction_->follower->start_solve();
    p.follow = follow_hook(condensed_.get());
  }
  if (friction_)
    p.restart = [this, condensed] {
      const VectorXd xr = step_start();
      return condensed ? condensed->restrict(xr) : xr;
    };
  const bool optimiser = sparse_alternative_ == SparseAlternative::kOptimiser ||
                         sparse_alternative_ == SparseAlternative::kOptimiserAlways;
  if (condensed && optimiser && workspace_.optimise_uncondensed) {
    ++rep.uncondensed_solves;
    return {solve_uncondensed(p, *condensed, x, warm, rep.times), false};
  }
  return {primal_->solve(p, warm, log_, rep.times), false};
}

VectorXd GeometrySubproblem::step_start() const {
  VectorXd u_retry = friction_->u_start;  // the start of the step, moved as at the first solve
  predict_dirichlet_increment(energy_, fixed_, u_retry);
  return problem_.restrict(u_retry);
}

SubproblemSolution GeometrySubproblem::solve_uncondensed(const Subproblem& p, const CondensedProblem& condensed,
                                                         const VectorXd& x, const SubproblemWarmStart& warm,
                                                         PhaseTimes& times) {
  // x's interior completed for B's entries (lazy_interior leaves it out of date): the optimum over the
  // interior, IPOPT's best start.
  VectorXd start;
  {
    ScopedPhase t(times, "condensation");
    start = condensed.expand(condensed.restrict(x));
  }
  Subproblem whole{problem_, nullptr, nullptr, start, p.geometry_iteration, p.ipopt, p.close_active_set,
                   p.quadratic_bodies, {}, {}};
  if (p.restart) whole.restart = [this] { return step_start(); };
  if (p.follow) whole.follow = follow_hook(nullptr);
  SubproblemSolution s = primal_->solve(whole, warm, log_, times);
  IpoptResult& r = s.result;
  if (r.x.size() == problem_.num_variables()) r.x = condensed.restrict(r.x);
  if (r.bound_multipliers.size() == problem_.num_variables())
    r.bound_multipliers = condensed.restrict(r.bound_multipliers);
  return s;
}

}  // namespace symcontact
