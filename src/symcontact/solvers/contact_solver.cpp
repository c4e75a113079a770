#include "symcontact/solvers/contact_solver.hpp"

#include "symcontact/solvers/equilibrium_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

#include "symcontact/core/error.hpp"
#include "symcontact/contact/surface_tractions.hpp"
#include "symcontact/solvers/active_set_polish.hpp"
#include "symcontact/solvers/anderson_acceleration.hpp"
#include "symcontact/solvers/equilibrium_solver.hpp"
#include "symcontact/solvers/condensed_problem.hpp"
#include "symcontact/solvers/fixed_point_monitor.hpp"
#include "symcontact/solvers/dual_condensed_problem.hpp"
#include "symcontact/solvers/semidefinite_factor.hpp"
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

ContactWorkspace::ContactWorkspace() = default;
ContactWorkspace::~ContactWorkspace() = default;

namespace {

/// Widens the condensed set along each contact surface, so that a contact zone that grows over the geometry
/// iterations and load steps stays inside it (each refactorisation costs about one Cholesky floor): the
/// surface nodes holding condensed DOFs are grown by k rings of facet neighbours, k = max(2, ⌈n^{1/(d−1)}/4⌉)
/// for n such nodes (in 2D the zone's node count grows by about half, in 3D its radius by a quarter), and
/// the grown nodes' free DOFs of the components already condensed on that surface are added.
void add_condensation_margin(const ContactSet& contacts, const DofMap& dofs, const std::vector<Index>& free_index,
                             std::vector<char>& in_b) {
  for (const ContactSurface& s : contacts.surfaces) {
    if (s.is_rigid()) continue;
    const Index nn = s.num_nodes();
    std::vector<char> grown(nn, 0);
    std::vector<char> component(s.dim, 0);
    Index seeds = 0;
    for (Index k = 0; k < nn; ++k)
      for (int i = 0; i < s.dim; ++i) {
        const Index f = free_index[dofs.dof(s.body, s.nodes[k], i)];
        if (f >= 0 && in_b[f]) {
          if (!grown[k]) ++seeds;
          grown[k] = 1;
          component[i] = 1;
        }
      }
    if (seeds == 0) continue;
    const int rings = std::max(2, static_cast<int>(std::ceil(
                                      0.25 * std::pow(static_cast<double>(seeds), 1.0 / std::max(1, s.dim - 1)))));
    const int npf = s.nodes_per_facet();
    for (int r = 0; r < rings; ++r) {
      std::vector<char> next = grown;
      for (Index f = 0; f < s.num_facets(); ++f) {
        bool touches = false;
        for (int a = 0; a < npf && !touches; ++a) touches = grown[s.facet(f)[a]];
        if (touches)
          for (int a = 0; a < npf; ++a) next[s.facet(f)[a]] = 1;
      }
      grown.swap(next);
    }
    for (Index k = 0; k < nn; ++k) {
      if (!grown[k]) continue;
      for (int i = 0; i < s.dim; ++i) {
        const Index f = free_index[dofs.dof(s.body, s.nodes[k], i)];
        if (component[i] && f >= 0) in_b[f] = 1;
      }
    }
  }
}

/// The condensed form of the current geometry iterate's problem, or null when condensing does not apply
/// or pay (see ContactSolveOptions::condense). Reuses the workspace's factorisation when its condensed set
/// holds every DOF the constraints and friction terms touch; otherwise refactorises with the union.
std::unique_ptr<CondensedProblem> condense_problem(ReducedProblem& bulk, const ReducedProblem& problem,
                                                   const ContactSet& contacts, const DofMap& dofs,
                                                   const std::vector<std::shared_ptr<const FrictionTerm>>& friction,
                                                   const VectorXd& u, const VectorXd& x, const EnergyTerm& energy,
                                                   ContactWorkspace& ws, const ContactSolveOptions& options,
                                                   const Logger& log, ContactSolveReport& rep,
                                                   std::shared_ptr<const CondensedLoad>& load) {
  const Index n = problem.num_free();
  const auto& free_index = problem.free_index();
  // B: the free DOFs of the constraint rows and of the friction terms.
  std::vector<char> in_b(n, 0);
  const SparseMatrix& A = problem.constraint_matrix();
  for (int j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it)
      if (it.value() != 0.0) in_b[j] = 1;
  std::vector<std::shared_ptr<const EnergyTerm>> extras;
  for (const auto& t : friction) {
    if (!t) continue;
    extras.push_back(t);
    for (Index d : support_of(*t, u))
      if (free_index[d] >= 0) in_b[free_index[d]] = 1;
  }
  const bool same_model = ws.condensation && !ws.condensation->empty() && ws.energy == &energy &&
                          ws.free_index == free_index;
  bool covered = same_model;
  if (same_model) {
    const auto& pos = ws.condensation->boundary_position();
    for (Index k = 0; k < n && covered; ++k)
      if (in_b[k] && pos[k] < 0) covered = false;
  }
  if (!covered) {
    if (same_model)  // grow: keep what was condensed before, so that a zone moving back and forth settles
      for (Index k : ws.condensation->boundary()) in_b[k] = 1;
    add_condensation_margin(contacts, dofs, free_index, in_b);
    std::vector<Index> boundary;
    for (Index k = 0; k < n; ++k)
      if (in_b[k]) boundary.push_back(k);
    if (boundary.empty() || static_cast<Index>(boundary.size()) > options.max_condensed_dofs ||
        2 * static_cast<Index>(boundary.size()) > n)
      return nullptr;
    if (!ws.condensation) ws.condensation = std::make_unique<StaticCondensation>();
    try {
      SparseMatrix K;
      bulk.hessian_lower(VectorXd::Zero(n), K);
      ws.condensation->compute(K, std::move(boundary));
    } catch (const SolveError& e) {
      log.detail(std::string("  static condensation not used: ") + e.what());
      ws.energy = nullptr;
      ws.condensation.reset();
      return nullptr;
    }
    ws.energy = &energy;
    ws.free_index = free_index;
    ++ws.factorisations;
    ++rep.condensation_factorisations;
    load.reset();
    log.debug("  static condensation onto " + std::to_string(ws.condensation->boundary().size()) + " of " +
              std::to_string(n) + " free DOFs");
  }
  if (!load && options.same_loads && ws.load && ws.load_of == ws.factorisations && ws.load->r0.size() == n) {
    load = ws.load;  // the caller vouches for r₀ (ContactSolveOptions::same_loads)
  }
  if (!load) {
    // The load part (one interior solve) depends on the loads and Dirichlet values only, through r₀ = ∇E(0):
    // the Coulomb iterations of a load step share it.
    VectorXd r0;
    bulk.gradient(VectorXd::Zero(n), r0);
    if (ws.load && ws.load_of == ws.factorisations && ws.load->r0.size() == n && ws.load->r0 == r0) {
      load = ws.load;
    } else {
      load = std::make_shared<const CondensedLoad>(condense_load(bulk, *ws.condensation));
      ws.load = load;
      ws.load_of = ws.factorisations;
    }
  }
  return std::make_unique<CondensedProblem>(bulk, *ws.condensation, load, std::move(extras), A,
                                            problem.constraint_offset(), x);
}

/// Whether the condensed set holds every free DOF of the contact surfaces (rigid ones have none): then the
/// search, the friction points and the surface pressures read nothing outside B.
bool surfaces_condensed(const ContactSet& contacts, const DofMap& dofs, const std::vector<Index>& free_index,
                        const std::vector<Index>& b_position) {
  for (const ContactSurface& s : contacts.surfaces) {
    if (s.is_rigid()) continue;
    for (Index node : s.nodes)
      for (int i = 0; i < s.dim; ++i) {
        const Index f = free_index[dofs.dof(s.body, node, i)];
        if (f >= 0 && b_position[f] < 0) return false;
      }
  }
  return true;
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

/// The pivoted factor of the workspace's Schur complement (computed once per condensation), or null when
/// the dual cannot be used: a null space that is not clean (max |S N| above 1e-8 of max |S|: a pivot
/// between round-off and stiffness, no clear rank) is left to the primal.
const SemidefiniteFactor* dual_schur_factor(ContactWorkspace& ws, const Logger& log) {
  // Pivots below this fraction of max diag(S) are rigid motions: theirs are round-off (1e-16 relative),
  // the softest deformation seen from the contact DOFs of a body is far above it.
  constexpr double kRankTolerance = 1e-10;
  constexpr double kNullResidual = 1e-8;
  if (!ws.condensation || ws.condensation->empty()) return nullptr;
  if (ws.schur_factor_of != ws.factorisations) {
    ws.schur_factor.reset();
    ws.schur_factor_of = ws.factorisations;
    try {
      auto f = std::make_unique<SemidefiniteFactor>(ws.condensation->schur_lower(), kRankTolerance);
      std::ostringstream s;
      s << "  dual solve: Schur complement of rank " << f->rank() << " of " << f->size() << " ("
        << f->size() - f->rank() << " rigid motion(s), null residual " << f->null_residual() << ")";
      if (f->null_residual() <= kNullResidual) {
        ws.schur_factor = std::move(f);
      } else {
        s << ": not clean, the primal is solved instead";
      }
      log.debug(s.str());
    } catch (const SolveError& e) {
      log.debug(std::string("  dual solve not used: ") + e.what());
    }
  }
  return ws.schur_factor.get();
}

ContactSolveReport solve_contact_impl(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts,
                                      const DofMap& dofs, VectorXd& u, const ContactSolveOptions& options,
                                      const Logger& log, const FrictionState* friction) {
  ContactSolveReport rep;
  CompositeEnergy total(energy);
  ReducedProblem problem(total, fixed, dofs.num_dofs());
  ReducedProblem bulk(energy, fixed, dofs.num_dofs());  // the bodies' energy alone (static condensation)
  rep.num_free = problem.num_free();
  const bool condense = options.condense && energy.hessian_is_constant();
  const std::shared_ptr<ContactWorkspace> workspace =
      options.workspace ? options.workspace : std::make_shared<ContactWorkspace>();
  std::shared_ptr<const CondensedLoad> condensed_load;  ///< of this solve's Dirichlet values and loads
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
  VectorXd dual_equality_prev;  ///< the dual's rigid-motion multipliers of the previous geometry iteration
  std::vector<int> rows_prev_family;
  std::vector<Index> rows_prev_node;
  bool closing_polish_works = true;
  // The dense interior point on the dual only where the constraint rows are independent (obstacles and one-pass
  // pairs): there λ is unique. The two families of a symmetric pair (or self-contact) are nearly dependent, the
  // optimal λ form a face, and the interior point ends on another point of it than IPOPT does, from which the
  // closing found a smaller set or none (measured: the stacked P2 blocks of V3 then missed their 1e-6 on the
  // pressure, 5.4e-6); IPOPT stays the dual's optimiser there.
  const bool independent_rows = std::none_of(contacts.pairs.begin(), contacts.pairs.end(),
                                             [](const ContactPair& p) { return p.two_sided(); });
  // Anderson acceleration of the geometry fixed point: with the set closed, the self-contact's map can
  // have a slowly alternating mode and a growing one (V7 3D: −0.63 and 1.18 per iteration, a mirror-
  // breaking slide of the arms along each other; docs/validation.md). Quadratic energies only, where
  // the closed polish solves each subproblem exactly (a finite-strain block on a roller took 7 geometry
  // iterations instead of 12 with it, but the finite-strain cases were not re-measured).
  std::unique_ptr<AndersonAcceleration> anderson;
  if (options.geometry_acceleration > 0 && energy.hessian_is_constant())
    anderson = std::make_unique<AndersonAcceleration>(options.geometry_acceleration);
  std::vector<char> active_prev;  ///< rows with μ > 0 after the previous closed polish
  double best_closed_change = std::numeric_limits<double>::infinity();  ///< smallest change with the set closed
  int closed_since_best = 0;  ///< closed iterations since that smallest change
  VectorXd residual_b;  ///< ∇E on the condensed set B at the solution, when the last iteration was condensed
  std::vector<std::shared_ptr<const FrictionTerm>> friction_terms;  ///< per pair, for the reported slips
  // Where the fixed point stops (ContactSolveOptions::loose_geometry_tolerance). An inexact solve is never
  // balanced at the end nor reported converged, even where its change happens to fall below
  // geometry_tolerance: its answer is an intermediate.
  const bool inexact = options.loose_geometry_tolerance > options.geometry_tolerance;
  // The IPOPT settings of this solve: tightened when the fixed point stagnates at their noise floor.
  IpoptOptions ipopt = options.ipopt;
  FixedPointMonitor monitor;
  int tightenings = 0;
  const double stop_tolerance = inexact ? options.loose_geometry_tolerance : options.geometry_tolerance;
  bool lazy = false;  ///< the current iterate's interior is out of date (ContactSolveOptions::lazy_interior)
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
                                         contacts.pairs[p].search_distance, contacts.pairs[p].bisector_ray());
          } else {
            nodal = nodal_contact_points(slave, current_positions(slave, dofs, up), nullptr,
                                         &contacts.obstacles[contacts.pairs[p].obstacle], contacts.pairs[p].search_distance);
          }
          // A self-contact surface holds both sides of its interface, and every node of it carries a
          // friction point: j_τ = ∫_Γc τ |[u_T]| counts the interface once (METHOD.md, eq. 16), so each
          // side carries half of it (with the full weight the friction force doubles; measured: an arm
          // dragged over its own body, SelfContactFriction2D).
          if (contacts.pairs[p].surface_a == contacts.pairs[p].surface_b)
            for (ContactPoint& q : nodal) q.weight *= 0.5;
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
    std::unique_ptr<CondensedProblem> condensed;
    if (condense) {
      ScopedPhase t(rep.times, "condensation");
      condensed = condense_problem(bulk, problem, contacts, dofs, total.extra, problem.expand(x), x, energy, *workspace, options,
                                   log, rep, condensed_load);
    }
    rep.num_condensed = condensed ? condensed->num_variables() : 0;
    // ContactSolveOptions::lazy_interior: this iteration updates B only.
    lazy = options.lazy_interior && options.workspace && condensed &&
           surfaces_condensed(contacts, dofs, problem.free_index(), workspace->condensation->boundary_position());
    if (lazy) workspace->interior_pending = true;  // from here on until an iteration expands (a failure completes u)
    ConstrainedProblem& target = condensed ? static_cast<ConstrainedProblem&>(*condensed) : problem;
    auto to_target = [&](const VectorXd& xf) { return condensed ? condensed->restrict(xf) : xf; };
    auto from_target = [&](const VectorXd& xt) { return condensed ? condensed->expand(xt) : xt; };
    // Warm start when the rows are the same (same families, same nodes).
    IpoptOptions opt = ipopt;
    VectorXd mu0;
    // The first geometry iteration starts from the previous solve of the run (the previous Coulomb iteration
    // or load step) when its rows are the same: IPOPT then needs a few iterations instead of a cold start's 15.
    const bool from_previous_solve = it == 1 && workspace->multipliers.size() == lin.A.rows();
    if (from_previous_solve) {
      mu_prev = workspace->multipliers;
      rows_prev_family = workspace->row_family;
      rows_prev_node = workspace->row_node;
    }
    const bool same_rows = (it > 1 || from_previous_solve) && lin.row_family == rows_prev_family &&
                           lin.row_node == rows_prev_node;
    if (same_rows) {
      opt.warm_start = true;
      mu0 = mu_prev;
    }
    IpoptResult res;
    bool dual = false;
    if (condensed && options.dual && condensed->hessian_is_constant() && lin.A.rows() > 0) {
      ScopedPhase t(rep.times, "condensation");  // the Schur complement's factor: once per condensation
      dual = dual_schur_factor(*workspace, log) != nullptr;
    }
    bool polished_closed = false;  ///< the closing polish was applied at this iteration
    std::unique_ptr<DualCondensedProblem> dual_problem;
    if (dual) {
      // IPOPT on the multipliers; then, as the primal polish below, the active set closed exactly (in the
      // dual's own, cheaper form); the displacements need no force-balancing polish.
      {
        ScopedPhase t(rep.times, "optimizer");  // forming W and d included
        dual_problem = std::make_unique<DualCondensedProblem>(*workspace->schur_factor, condensed->constraint_matrix(),
                                                              condensed->constraint_offset(), condensed->linear_term());
        // Warm start from the previous geometry iteration (same rows, same condensation): its multipliers and,
        // as the bounds' multipliers, the new gaps at its displacements.
        const bool warm = same_rows && mu_prev.size() == lin.A.rows() &&
                          dual_equality_prev.size() == dual_problem->num_rigid_modes() &&
                          rep.dual_solves > 0;
        VectorXd l0, z0;
        if (warm) {
          l0 = dual_problem->scaled_multipliers(mu_prev);
          z0 = dual_problem->scaled_gaps(to_target(x)).cwiseMax(0.0);
        }
        bool solved = false;
        if (options.dual_interior_point && independent_rows) {
          DenseQpOptions qp;
          // IPOPT's tolerance, also when the problem file sets it ([ipopt] tol).
          const auto tol = ipopt.numeric_options.find("tol");
          qp.tolerance = tol != ipopt.numeric_options.end() ? tol->second : ipopt.tolerance;
          qp.complementarity_tolerance = 1e-6 * qp.tolerance;
          DenseQpResult r = dual_problem->solve_interior_point(qp, warm ? &l0 : nullptr, warm ? &z0 : nullptr,
                                                               warm ? &dual_equality_prev : nullptr);
          if (!r.success && warm) {
            log.detail("  the interior point failed on the dual from the previous iteration (" + r.status +
                       "); cold start");
            rep.ipopt_iterations += r.iterations;
            r = dual_problem->solve_interior_point(qp);
          }
          if (r.success) {
            res.success = true;
            res.status_text = "interior point: " + r.status;
            res.iterations = r.iterations;
            res.x = std::move(r.x);
            res.multipliers = std::move(r.beta);
            res.bound_multipliers = std::move(r.z);
            solved = true;
          } else {
            log.detail("  the interior point failed on the dual (" + r.status + "); IPOPT instead");
            rep.ipopt_iterations += r.iterations;
          }
        }
        if (!solved && warm) {
          res = solve_with_ipopt(*dual_problem, l0, opt, &dual_equality_prev, &z0);
          if (!res.success) {
            log.detail("  IPOPT failed on the dual from the previous iteration (" + res.status_text + "); cold start");
            rep.ipopt_iterations += res.iterations;
          }
        }
        if (!solved && (!warm || !res.success))
          res = solve_with_ipopt(*dual_problem, VectorXd::Zero(dual_problem->num_variables()), ipopt);
      }
      ++rep.dual_solves;
      if (!res.success) {
        // The primal is the reference formulation: a dual IPOPT fails to solve goes to it (this iteration).
        log.detail("  IPOPT failed on the dual (" + res.status_text + "); the primal is solved instead");
        rep.ipopt_iterations += res.iterations;
        dual = false;
      }
    }
    if (dual) {
      VectorXd lambda_hat = res.x, eq = res.multipliers;
      if (options.polish && closing_polish_works) {
        ScopedPhase t(rep.times, "polish");
        const DualCondensedProblem::Closing cl = dual_problem->close_contact_set(lambda_hat, eq);
        polished_closed = cl.applied;
        if (!cl.applied) {
          closing_polish_works = false;
          log.detail("  active-set polish (closing, dual) not applied: " + cl.reason + "; the optimiser's point is kept");
        }
        log.debug("  polish (dual): " + std::to_string(cl.rounds) + " rounds on " + std::to_string(cl.active) +
                  " active constraints");
      }
      dual_equality_prev = eq;
      res.x = dual_problem->primal(lambda_hat, eq);
      res.multipliers = dual_problem->multipliers(lambda_hat);
      res.constraint_values = condensed->constraint_matrix() * res.x + condensed->constraint_offset();
    }
    if (!dual) {
      ScopedPhase t(rep.times, "optimizer");
      res = solve_with_ipopt(target, to_target(x), opt, same_rows ? &mu0 : nullptr);
      if (!res.success && it == 1 && same_rows) {
        log.detail("  IPOPT failed from the previous solve's multipliers (" + res.status_text + "); cold start");
        rep.ipopt_iterations += res.iterations;
        res = solve_with_ipopt(target, to_target(x), ipopt);
      }
      if (!res.success && friction) {
        // Stiff regularised friction (small α) can defeat IPOPT's line search from a start that is
        // already close; one cold retry from the start of the load step before giving up.
        log.detail("  IPOPT failed (" + res.status_text + "); retrying from the start of the load step");
        IpoptOptions cold = ipopt;
        VectorXd u_retry = friction->u_start;  // the start of the step, moved as at the first solve
        predict_dirichlet_increment(energy, fixed, u_retry);
        const IpoptResult retry = solve_with_ipopt(target, to_target(problem.restrict(u_retry)), cold);
        rep.ipopt_iterations += res.iterations;
        res = retry;
      }
    }
    rep.ipopt_iterations += res.iterations;
    rep.ipopt_per_iteration.push_back(res.iterations);
    rep.ipopt_status = res.status_text;
    rep.geometry_iterations = it;
    if (!res.success) {
      u = problem.expand(res.x.size() == target.num_variables() ? from_target(res.x) : x);
      throw SolveError("IPOPT failed (" + res.status_text + ") at geometry iteration " + std::to_string(it));
    }
    // Closing the active set fails for good when the two families of a curved symmetric pair cannot
    // all be closed at once; after one failure this solve only balances forces (cheaper).
    // With a non-quadratic energy (friction), a rejection in the previous solve of the run is taken as
    // this solve's too (ContactWorkspace::closing_polish_rejected).
    const bool nonquadratic = !target.hessian_is_constant();
    if (options.polish && !dual && closing_polish_works && nonquadratic && workspace->closing_polish_rejected) {
      closing_polish_works = false;
      log.detail("  active-set polish (closing) rejected in the previous solve; balancing forces only");
    }
    // Balancing forces only, with friction: that polish moves the iterate by no more than the optimiser's
    // tolerance (far below the geometry tolerance), so it is applied once, to the iterate that ends the
    // fixed point, instead of at every geometry iteration (a dense factorisation each; on the inclined
    // interface with Coulomb friction about 2.4 geometry iterations per solve). An inexact solve
    // (loose_geometry_tolerance) is left unbalanced: its iterate is a Coulomb iteration's intermediate.
    const bool balance_at_end = options.polish && !dual && nonquadratic && !closing_polish_works;
    if (options.polish && !dual && !balance_at_end) {
      ScopedPhase t(rep.times, "polish");
      PolishResult pr;
      if (closing_polish_works) {
        pr = polish_active_set(target, res.x, res.multipliers);
        if (nonquadratic) workspace->closing_polish_rejected = !pr.applied;
        if (!pr.applied) {
          closing_polish_works = false;
          log.detail("  active-set polish (closing) not applied: " + pr.reason + "; balancing forces only");
        }
      }
      if (!pr.applied) {
        pr = polish_active_set(target, res.x, res.multipliers, true);
        if (!pr.applied) log.detail("  force-balance polish not applied: " + pr.reason);
      }
      log.debug("  polish: " + std::to_string(pr.iterations) + " iterations on " + std::to_string(pr.active) +
                " active constraints");
      polished_closed = pr.applied && closing_polish_works;
    }
    if (condensed) {
      ScopedPhase t(rep.times, "condensation");
      res.x = lazy ? condensed->with_boundary(x, res.x) : condensed->expand(res.x);
    }
    const double change =
        (res.x - x).lpNorm<Eigen::Infinity>() / std::max(res.x.lpNorm<Eigen::Infinity>(), 1e-300);
    if (balance_at_end && !inexact && change < options.geometry_tolerance) {
      VectorXd xt;
      {
        ScopedPhase t(rep.times, "polish");
        xt = to_target(res.x);
        const PolishResult pr = polish_active_set(target, xt, res.multipliers, true);
        if (!pr.applied) log.detail("  force-balance polish not applied: " + pr.reason);
        log.debug("  polish (at the end): " + std::to_string(pr.iterations) + " iterations on " +
                  std::to_string(pr.active) + " active constraints");
      }
      ScopedPhase t(rep.times, "condensation");
      res.x = lazy ? condensed->with_boundary(res.x, xt) : from_target(xt);
    }
    {
      // With the active set closed exactly, the fixed point can have a growing mode that the barrier
      // offset of the force-balancing variant damps (measured: the V7 3D self-contact, whose change
      // falls to 1.5e-7 and then grows by 1.18 per iteration). Without acceleration: once the change has
      // grown twice in a row with the set closed, the rest of the solve only balances forces. With it the
      // change is not monotone (and that mode converges): the same fallback, once the change has made no
      // new low in memory + 2 closed iterations.
      const std::size_t n = rep.change_history.size();
      bool stalls = false;
      if (polished_closed) {
        if (change < best_closed_change) {
          best_closed_change = change;
          closed_since_best = 0;
        } else {
          ++closed_since_best;
        }
        stalls = anderson ? closed_since_best > options.geometry_acceleration + 2
                          : n >= 2 && change > rep.change_history[n - 1] &&
                                rep.change_history[n - 1] > rep.change_history[n - 2];
      }
      if (stalls) {
        closing_polish_works = false;
        log.detail("  the change stalled or grew with the active set closed; balancing forces only from now on");
      }
    }
    rep.change_history.push_back(change);
    if (log.level() >= Verbosity::kDebug) log_geometry_change(problem.expand(res.x) - problem.expand(x), dofs, lin,
                                                               rows_prev_family, rows_prev_node, log);
    const VectorXd x_in = x;
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
    if (change < stop_tolerance) {
      if (condensed) {
        // The bodies' residual on B, for the contact forces below: ∇E = ĝ + S y there (condensed_problem.hpp),
        // O(|B|²) instead of an assembly over the whole mesh.
        const VectorXd y = condensed->restrict(res.x);
        residual_b = condensed->linear_term() +
                     condensed->condensation().schur_lower().selfadjointView<Eigen::Lower>() * y;
      }
      rep.converged = !inexact && change < options.geometry_tolerance;
      rep.multipliers = res.multipliers;
      workspace->multipliers = res.multipliers;
      workspace->row_family = lin.row_family;
      workspace->row_node = lin.row_node;
      break;
    }
    monitor.record(change);
    if (monitor.stagnated() && tightenings < kMaxTightenings) {
      // No new low in six iterations: the subproblems' answers carry the optimiser's tolerance (where the closing
      // polish does not apply, the interior point's barrier offset), a noise floor above the geometry tolerance.
      ++tightenings;
      tighten_optimiser(ipopt);
      std::ostringstream s;
      s << "  the geometry fixed point stagnated (no new low below " << monitor.best() << "); IPOPT tol tightened to "
        << ipopt.tolerance;
      log.detail(s.str());
      monitor.restart();
    }
    if (it >= options.max_geometry_iterations) {
      u = problem.expand(x);
      std::ostringstream s;
      s << "the geometry fixed point did not converge in " << options.max_geometry_iterations
        << " iterations (last relative change " << change << ", tolerance " << stop_tolerance << ")";
      if (tightenings > 0) s << "; tried: IPOPT tol tightened " << tightenings << " time(s), to " << ipopt.tolerance;
      s << "; try smaller load steps ([contact_solver] max_step_cuts = 4, or more [steps])";
      throw SolveError(s.str());
    }
    if (anderson) {
      // The next geometry: accelerated while the map stays the same smooth one (same rows, set closed
      // exactly on the same active set), else the plain step, restarting the history.
      std::vector<char> active(res.multipliers.size());
      for (Index r = 0; r < res.multipliers.size(); ++r) active[r] = res.multipliers[r] > 0.0;
      const bool smooth = polished_closed && same_rows && active == active_prev;
      if (!smooth) anderson->reset();
      if (polished_closed) {
        x = anderson->next(x_in, res.x);
        if (anderson->columns() > 0)
          log.debug("  next geometry: Anderson step on " + std::to_string(anderson->columns()) + " differences");
      }
      active_prev = polished_closed ? active : std::vector<char>();
    }
  }
  u = problem.expand(x);
  workspace->interior_pending = lazy;
  rep.interior_deferred = lazy;
  rep.friction = friction_terms;
  // Contact forces: Aᵀμ (+ friction). On free DOFs the equilibrium residual ∇E(u) of the bodies' energy
  // equals Aᵀμ + the friction force at the KKT point and carries no optimiser tolerance (it balances the
  // applied loads to round-off), so it is used there; on fixed DOFs the residual also holds the support
  // reaction, and Aᵀμ is kept (friction forces on fixed DOFs are not recovered).
  // Condensed, the residual on B is ĝ + S y (exactly ∇E there, x_I being x_I(y)); a surface DOF outside B
  // is touched by no constraint or friction term, and its residual is zero but for round-off: Aᵀμ = 0 is kept.
  rep.contact_force = rep.linearization.A.transpose() * rep.multipliers;
  rep.multiplier_force = rep.contact_force;
  std::vector<Index> free_index;
  fixed.free_numbering(u.size(), free_index);
  const bool condensed_residual = residual_b.size() > 0;
  const std::vector<Index>* b_position = condensed_residual ? &workspace->condensation->boundary_position() : nullptr;
  VectorXd residual;
  if (!condensed_residual) {
    residual = VectorXd::Zero(u.size());
    energy.add_gradient(u, residual);
  }
  // The residual of the bodies' energy holds the whole interface force, normal and frictional.
  VectorXd friction_gradient = VectorXd::Zero(u.size());
  for (const auto& t : friction_terms)
    if (t) t->add_gradient(u, friction_gradient);
  rep.force_defect = VectorXd::Zero(u.size());
  for (const ContactSurface& s : contacts.surfaces) {
    if (s.is_rigid()) continue;
    for (Index node : s.nodes)
      for (int i = 0; i < s.dim; ++i) {
        const Index d = dofs.dof(s.body, node, i);
        const Index f = free_index[d];
        if (f < 0) continue;
        if (!condensed_residual) {
          rep.contact_force[d] = residual[d];
        } else if ((*b_position)[f] >= 0) {
          rep.contact_force[d] = residual_b[(*b_position)[f]];
        } else {
          continue;
        }
        rep.force_defect[d] = rep.contact_force[d] - (rep.multiplier_force[d] - friction_gradient[d]);
      }
  }
  return rep;
}

}  // namespace

ContactSolveReport solve_contact(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts,
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
      return solve_contact_impl(energy, fixed, contacts, dofs, u, options, log, friction);
    } catch (const EvaluationError& e) {
      throw SolveError(std::string("the contact solve reached a state the energy cannot be evaluated at: ") +
                       e.what() + " — use smaller load steps");
    }
  } catch (const SolveError&) {
    complete();
    throw;
  }
}

void complete_interior(const EnergyTerm& energy, const FixedDofs& fixed, VectorXd& u, ContactWorkspace& workspace) {
  if (!workspace.interior_pending) return;
  workspace.interior_pending = false;
  if (!workspace.condensation || !workspace.load)
    throw std::logic_error("complete_interior: the workspace holds no condensation to complete u with");
  const ReducedProblem bulk(energy, fixed, u.size());
  const VectorXd y = boundary_values(*workspace.condensation, bulk.restrict(u));
  u = bulk.expand(expand_condensed(*workspace.condensation, *workspace.load, y));
}

}  // namespace symcontact
