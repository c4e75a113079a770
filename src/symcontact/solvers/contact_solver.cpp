#include "symcontact/solvers/contact_solver.hpp"

#include "symcontact/solvers/equilibrium_solver.hpp"

#include <sstream>

#include "symcontact/core/error.hpp"
#include "symcontact/contact/surface_tractions.hpp"
#include "symcontact/solvers/active_set_polish.hpp"
#include "symcontact/solvers/equilibrium_solver.hpp"
#include "symcontact/solvers/reduced_problem.hpp"

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

namespace {
ContactSolveReport solve_contact_impl(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts,
                                      const DofMap& dofs, VectorXd& u, const ContactSolveOptions& options,
                                      const Logger& log, const FrictionState* friction) {
  ContactSolveReport rep;
  CompositeEnergy total(energy);
  ReducedProblem problem(total, fixed, dofs.num_dofs());
  rep.num_free = problem.num_free();
  {
    // New Dirichlet values: a finite-strain body follows them by its linearised response first, so that
    // the start point inverts no cell next to a moved boundary (a quadratic energy just takes them).
    ScopedPhase t(rep.times, "predictor");
    if (predict_dirichlet_increment(energy, fixed, u) < 1.0)
      log.detail("the Dirichlet predictor took a shortened step; the rest of the boundary motion is imposed at once");
    fixed.impose(u);
  }
  VectorXd x = problem.restrict(u);
  VectorXd mu_prev;
  std::vector<int> rows_prev_family;
  std::vector<Index> rows_prev_node;
  bool closing_polish_works = true;
  std::vector<std::shared_ptr<const FrictionTerm>> friction_terms;  ///< per pair, for the reported slips
  for (int it = 1;; ++it) {
    {
      ScopedPhase t(rep.times, "search");
      rep.linearization = contacts.linearize(dofs, problem.expand(x));
    }
    const ContactLinearization& lin = rep.linearization;
    if (it == 1) {
      // A pair that sees nothing at all is usually a mistake (a meshed obstacle whose facets face away,
      // a search distance too small): say so rather than let the bodies pass through each other.
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
    {
      ScopedPhase t(rep.times, "assembly");
      problem.set_constraints(lin.A, lin.b);
      total.extra.assign(contacts.pairs.size(), nullptr);
      friction_terms.assign(contacts.pairs.size(), nullptr);
      if (friction)
        for (int p = 0; p < static_cast<int>(contacts.pairs.size()); ++p) {
          if (p >= static_cast<int>(friction->nodal_tau.size()) || friction->nodal_tau[p].size() == 0) continue;
          const int f = contacts.friction_family(p);
          const ContactFamily& fam = contacts.families()[f];
          const ContactSurface& slave = contacts.surfaces[fam.slave];
          // Friction is integrated node by node (weight A_k, the node's own slip and threshold), so that
          // at every node σ_T = −τ_k s_k / sqrt(|s_k|² + α²) with the same lumped A_k the pressure is
          // recovered with: the nodal friction law then holds exactly, |σ_T| ≤ μ σ_n included. A
          // quadrature of the interpolated τ and s instead mixes neighbouring nodes' thresholds, which
          // breaks the law where the pressure varies (measured: 0.6 μ at the ends of a dragged block).
          const VectorXd up = problem.expand(x);
          std::vector<ContactPoint> nodal;
          if (fam.master >= 0) {
            const ContactSurface& ms = contacts.surfaces[fam.master];
            const MasterGeometry mg = prepare_master(ms, current_positions(ms, dofs, up));
            nodal = nodal_contact_points(slave, current_positions(slave, dofs, up), &mg, nullptr,
                                         contacts.pairs[p].search_distance);
          } else {
            nodal = nodal_contact_points(slave, current_positions(slave, dofs, up), nullptr,
                                         &contacts.obstacles[contacts.pairs[p].obstacle], contacts.pairs[p].search_distance);
          }
          const std::vector<double> tau = interpolate_at_points(slave, nodal, friction->nodal_tau[p]);
          friction_terms[p] = std::make_shared<FrictionTerm>(
              "friction(" + contacts.pairs[p].name + ")", slave, fam.master >= 0 ? &contacts.surfaces[fam.master] : nullptr,
              std::move(nodal), tau, contacts.pairs[p].alpha, dofs, friction->u_start);
          // A zero threshold (the frictionless start of Coulomb, μ = 0) adds nothing to the energy: left out
          // so that the problem stays quadratic; the term is kept for the slips it reports.
          if (friction->nodal_tau[p].maxCoeff() > 0.0) total.extra[p] = friction_terms[p];
        }
    }
    rep.num_constraints = lin.A.rows();
    // Warm start when the rows are the same (same families, same nodes).
    IpoptOptions opt = options.ipopt;
    VectorXd mu0;
    const bool same_rows = it > 1 && lin.row_family == rows_prev_family && lin.row_node == rows_prev_node;
    if (same_rows) {
      opt.warm_start = true;
      mu0 = mu_prev;
    }
    IpoptResult res;
    {
      ScopedPhase t(rep.times, "optimizer");
      res = solve_with_ipopt(problem, x, opt, same_rows ? &mu0 : nullptr);
      if (!res.success && friction) {
        // Stiff regularised friction (small α) can defeat IPOPT's line search from a start that is
        // already close; one cold retry from the start of the load step before giving up.
        log.detail("  IPOPT failed (" + res.status_text + "); retrying from the start of the load step");
        IpoptOptions cold = options.ipopt;
        VectorXd u_retry = friction->u_start;  // the start of the step, moved as at the first solve
        predict_dirichlet_increment(energy, fixed, u_retry);
        VectorXd x_retry = problem.restrict(u_retry);
        const IpoptResult retry = solve_with_ipopt(problem, x_retry, cold);
        rep.ipopt_iterations += res.iterations;
        res = retry;
      }
    }
    rep.ipopt_iterations += res.iterations;
    rep.ipopt_per_iteration.push_back(res.iterations);
    rep.ipopt_status = res.status_text;
    rep.geometry_iterations = it;
    if (!res.success) {
      u = problem.expand(res.x.size() == x.size() ? res.x : x);
      throw SolveError("IPOPT failed (" + res.status_text + ") at geometry iteration " + std::to_string(it));
    }
    auto relative_change = [&]() {
      return (res.x - x).lpNorm<Eigen::Infinity>() / std::max(res.x.lpNorm<Eigen::Infinity>(), 1e-300);
    };
    double change = relative_change();
    if (options.polish) {
      ScopedPhase t(rep.times, "polish");
      // Closing the active set fails for good when the two families of a curved symmetric pair cannot
      // all be closed at once; after one failure this solve only balances forces (cheaper).
      PolishResult pr;
      if (closing_polish_works) {
        pr = polish_active_set(problem, res.x, res.multipliers);
        if (!pr.applied) {
          closing_polish_works = false;
          log.detail("  active-set polish (closing) not applied: " + pr.reason + "; balancing forces only");
        }
      }
      if (!pr.applied) {
        pr = polish_active_set(problem, res.x, res.multipliers, true);
        if (!pr.applied) log.detail("  force-balance polish not applied: " + pr.reason);
      }
      log.debug("  polish: " + std::to_string(pr.iterations) + " iterations on " + std::to_string(pr.active) +
                " active constraints");
      change = relative_change();
      // With the active set closed exactly, the fixed point can have a growing mode that the barrier
      // offset of the force-balancing variant damps (measured: the V7 3D self-contact, whose change
      // falls to 2.7e-7 and then grows by 1.18 per iteration). Once the change has grown twice in a row
      // with the set closed, the rest of the solve only balances forces.
      const std::size_t n = rep.change_history.size();
      if (pr.applied && closing_polish_works && n >= 2 && change > rep.change_history[n - 1] &&
          rep.change_history[n - 1] > rep.change_history[n - 2]) {
        closing_polish_works = false;
        log.detail("  the change grew twice with the active set closed; balancing forces only from now on");
      }
    }
    rep.change_history.push_back(change);
    x = res.x;
    mu_prev = res.multipliers;
    rows_prev_family = lin.row_family;
    rows_prev_node = lin.row_node;
    {
      std::ostringstream s;
      s << "  geometry iteration " << it << ": " << lin.A.rows() << " constraints, IPOPT " << res.iterations
        << " iterations (" << res.status_text << "), change " << change;
      log.detail(s.str());
    }
    if (change < options.geometry_tolerance) {
      rep.multipliers = res.multipliers;
      break;
    }
    if (it >= options.max_geometry_iterations) {
      u = problem.expand(x);
      std::ostringstream s;
      s << "the geometry fixed point did not converge in " << options.max_geometry_iterations
        << " iterations (last relative change " << change << ", tolerance " << options.geometry_tolerance << ")";
      throw SolveError(s.str());
    }
  }
  u = problem.expand(x);
  rep.friction = friction_terms;
  // Contact forces: Aᵀμ (+ friction). On free DOFs the equilibrium residual ∇E(u) of the bodies' energy
  // equals Aᵀμ + the friction force at the KKT point and carries no optimiser tolerance (it balances the
  // applied loads to round-off), so it is used there; on fixed DOFs the residual also holds the support
  // reaction, and Aᵀμ is kept (friction forces on fixed DOFs are not recovered).
  rep.contact_force = rep.linearization.A.transpose() * rep.multipliers;
  rep.multiplier_force = rep.contact_force;
  VectorXd residual = VectorXd::Zero(u.size());
  energy.add_gradient(u, residual);
  std::vector<Index> free_index;
  fixed.free_numbering(u.size(), free_index);
  // The residual of the bodies' energy holds the whole interface force, normal and frictional.
  for (const ContactSurface& s : contacts.surfaces) {
    if (s.is_rigid()) continue;
    for (Index node : s.nodes)
      for (int i = 0; i < s.dim; ++i) {
        const Index d = dofs.dof(s.body, node, i);
        if (free_index[d] >= 0) rep.contact_force[d] = residual[d];
      }
  }
  return rep;
}

}  // namespace

ContactSolveReport solve_contact(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts,
                                 const DofMap& dofs, VectorXd& u, const ContactSolveOptions& options,
                                 const Logger& log, const FrictionState* friction) {
  // IPOPT and the polish back away from states the energy cannot be evaluated at; one left over (the
  // start point of a step) is a failed solve, not an internal error.
  try {
    return solve_contact_impl(energy, fixed, contacts, dofs, u, options, log, friction);
  } catch (const EvaluationError& e) {
    throw SolveError(std::string("the contact solve reached a state the energy cannot be evaluated at: ") + e.what() +
                     " — use smaller load steps");
  }
}

}  // namespace symcontact
