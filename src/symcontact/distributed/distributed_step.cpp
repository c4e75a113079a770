#include "symcontact/distributed/distributed_step.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <sstream>

#include "symcontact/app/linear_solver_choice.hpp"
#include "symcontact/contact/surface_tractions.hpp"
#include "symcontact/core/error.hpp"
#include "symcontact/core/progress_clock.hpp"
#include "symcontact/distributed/gamg_elasticity.hpp"
#include "symcontact/distributed/node_ordering.hpp"
#include "symcontact/distributed/petsc_support.hpp"
#include "symcontact/fem/matrix_sink.hpp"
#include "symcontact/solvers/contact_forces.hpp"
#include "symcontact/solvers/coulomb_thresholds.hpp"
#include "symcontact/solvers/fixed_point_monitor.hpp"
#include "symcontact/solvers/friction_state.hpp"
#include "symcontact/solvers/lagged_fixed_point.hpp"

namespace symcontact {

void check_distributed_support(const ProblemSpec& spec) {
  if (spec.linear_solver == LinearSolverChoice::kDirect)
    throw InputError(spec.file, "contact_solver.linear_solver",
                     "\"direct\" cannot run under mpirun: run symcontact without mpirun, or choose \"iterative\"");
  const DistributedLimit limit = distributed_path_limit(spec);
  if (!limit.none())
    throw InputError(spec.file, limit.key,
                     limit.message + ": solve it with the direct solver (contact_solver.linear_solver = \"direct\" or \"automatic\", without mpirun)");
}

namespace {

/// The iterations without a new low of the geometry fixed point's change after which it is stagnated.
constexpr int kStagnationWindow = 10;
/// The first and the largest shift δ of a hyperelastic model's Hessian, K + δ diag K (shifted()), relative to
/// its diagonal: each failed solve multiplies it by 10, each solved iteration divides it by 10 (0 below the first).
constexpr double kFirstShift = 1e-6, kLargestShift = 1e2;
/// A solve whose interior point took a force scale above kLooseScale × its answer's (answer_force_scale()) has
/// met tests that loose: the geometry fixed point solves again, and every later solve of the run, at the scale
/// of the answer before it. 1e3 = the answer's equilibrium check (1e-6, post/step_checks.hpp) over the interior
/// point's default tolerance (1e-9): the dual residual of a solve within it stays within the check. The examples
/// measure 0.5–29 (the inclined interfaces, whose solves at tightened tolerances break down in round-off at the
/// answer's scale), the O-ring's steel lid 3e5.
constexpr double kLooseScale = 1e3;

/// The energy's second-order model at a displacement u, E(v) ≈ ½ vᵀKv − fᵀv + const with K = ∇²E(u) and
/// f = K u − ∇E(u), in the PETSc numbering of `ordering` (node_ordering.hpp). For a linear-elastic model K and
/// f do not depend on u (K the stiffness, f the load); for a hyperelastic one each solve on this model is a
/// Newton step of the step's program, taken inside the geometry fixed point (sequential quadratic programming:
/// Nocedal & Wright, Numerical Optimization, 2nd ed., §18.1).
struct QuadraticModel {
  SparseMatrix K_lower;  ///< the lower triangle of this rank's rows
  VectorXd f;
  Eigen::MatrixXd x;     ///< dim × nodes, reference coordinates
  VectorXd diagonal;     ///< diag K, every row (hyperelastic models only: for shifted())
  VectorXd u;            ///< where K was taken (hyperelastic models only)
};

/// The lower-triangle entries, in the PETSc numbering, of the rows a rank owns: each rank keeps 1/P of the
/// stiffness's entries.
class OwnedLowerSink : public MatrixSink {
 public:
  OwnedLowerSink(const petsc::RowRange& mine, const NodeOrdering& ordering) : mine_(mine), ordering_(ordering) {}
  void add(const Index* dofs, int n, const double* K) override {
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Index row = ordering_.dof(dofs[i]), col = ordering_.dof(dofs[j]);
        if (row >= col && mine_.owns(row))
          triplets_.emplace_back(static_cast<int>(row), static_cast<int>(col), K[i + j * n]);
      }
  }
  SparseMatrix matrix(Index n) const {
    SparseMatrix A(n, n);
    A.setFromTriplets(triplets_.begin(), triplets_.end());
    return A;
  }

 private:
  petsc::RowRange mine_;
  const NodeOrdering& ordering_;
  std::vector<Triplet> triplets_;
};

/// The model's reference node coordinates, dim × nodes, in the DofMap's node order.
Eigen::MatrixXd reference_coordinates(const Model& model) {
  const DofMap& dofs = model.dofs();
  const Index dim = dofs.dim();
  Eigen::MatrixXd x(dim, dofs.num_dofs() / dim);
  for (int b = 0; b < dofs.num_bodies(); ++b)
    x.middleCols(dofs.offset(b) / dim, model.bodies()[b]->mesh.x.cols()) = model.bodies()[b]->mesh.x;
  return x;
}

/// Forwards every block to several sinks: the Hessian stored, multiplied and its diagonal read in one pass.
class FanOut : public MatrixSink {
 public:
  explicit FanOut(std::vector<MatrixSink*> sinks) : sinks_(std::move(sinks)) {}
  void add(const Index* dofs, int n, const double* K) override {
    for (MatrixSink* s : sinks_) s->add(dofs, n, K);
  }

 private:
  std::vector<MatrixSink*> sinks_;
};

/// out[dof] += K_ii: the diagonal, every row, in the model's numbering.
class DiagonalSink : public MatrixSink {
 public:
  explicit DiagonalSink(VectorXd& out) : out_(out) {}
  void add(const Index* dofs, int n, const double* K) override {
    for (int i = 0; i < n; ++i) out_[dofs[i]] += K[i + i * n];
  }

 private:
  VectorXd& out_;
};

/// 0, 1, …, n − 1: a ProductSink's index in the model's own numbering.
std::vector<Index> identity_index(Index n) {
  std::vector<Index> index(static_cast<std::size_t>(n));
  std::iota(index.begin(), index.end(), Index{0});
  return index;
}

/// The model at its current step, linearised at u (QuadraticModel). Where the energy's Hessian is constant,
/// K from `stiffness` when it holds one, into it otherwise (then the same for every step: only the load
/// changes), and f = −∇E(0), whatever u.
QuadraticModel quadratic_model(const Model& model, const NodeOrdering& ordering, std::optional<SparseMatrix>& stiffness,
                               const VectorXd& u) {
  const Index n = model.dofs().num_dofs(), dim = model.dofs().dim();
  const bool constant = model.energy().hessian_is_constant();
  const VectorXd at = constant ? VectorXd::Zero(n) : u;
  QuadraticModel q;
  VectorXd f = VectorXd::Zero(n);
  if (stiffness && stiffness->rows() == n) {
    q.K_lower = *stiffness;
  } else {
    OwnedLowerSink sink(petsc::my_rows(static_cast<int>(dim), n / dim), ordering);
    if (constant) {
      model.energy().add_hessian(at, sink);
    } else {
      const std::vector<Index> identity = identity_index(n);
      ProductSink product(identity, at, f);  // K u
      VectorXd diagonal = VectorXd::Zero(n);
      DiagonalSink diagonal_sink(diagonal);
      FanOut all({&sink, &product, &diagonal_sink});
      model.energy().add_hessian(at, all);
      q.diagonal = ordering.to_petsc(diagonal);
      q.u = ordering.to_petsc(at);
    }
    q.K_lower = sink.matrix(n);
    if (constant) stiffness = q.K_lower;
  }
  VectorXd gradient = VectorXd::Zero(n);
  model.energy().add_gradient(at, gradient);
  q.f = ordering.to_petsc(f - gradient);
  q.x = ordering.nodes_to_petsc(reference_coordinates(model));
  return q;
}

/// The scale of the forces at an answer u: the largest nodal force of ∇E(u) (the reactions on the fixed DOFs,
/// the contact and friction forces elsewhere) or of the external load. The interior point's force scale for
/// the solves after it (ContactInteriorPointOptions::force_scale) once its own has been found loose
/// (kLooseScale): its own, ‖b‖_∞, counts the force that moves a stiff body's fixed DOFs against its free ones,
/// 3e5 times the answer's forces where a steel lid is pressed by an imposed displacement onto rubber
/// (examples/oring_axisymmetric): tests that loose leave the Coulomb thresholds at the interior point's
/// accuracy, above the Coulomb loop's tolerance.
double answer_force_scale(const Model& model, const VectorXd& u) {
  VectorXd gradient = VectorXd::Zero(u.size());
  model.energy().add_gradient(u, gradient);
  return std::max(gradient.lpNorm<Eigen::Infinity>(), model.external_load().lpNorm<Eigen::Infinity>());
}

/// q's model with K + δ D in place of K, D = diag K (the same f − K u = −∇E(u)): a Levenberg–Marquardt step
/// for a Hessian that is not positive definite (Nocedal & Wright §10.3, §3.4), whose fixed points are q's.
QuadraticModel shifted(const QuadraticModel& q, double delta) {
  QuadraticModel s = q;
  for (Index k = 0; k < s.K_lower.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(s.K_lower, static_cast<int>(k)); it; ++it)
      if (it.row() == it.col()) it.valueRef() *= 1.0 + delta;
  s.f += delta * q.diagonal.cwiseProduct(q.u);
  return s;
}

/// The rows of `lin` divided by their supports, for the interior point; the normal of row j: its entries on
/// its own node's DOFs, made unit (read by the interior point with friction only).
NodalConstraints scaled_rows(const ContactLinearization& lin, const DofMap& dofs, const ContactSet& contacts) {
  const Index m = lin.A.rows(), dim = dofs.dim();
  NodalConstraints c;
  c.lower.resize(m);
  c.normal = Eigen::MatrixXd::Zero(dim, m);
  VectorXd inverse_support(m);
  for (Index j = 0; j < m; ++j) {
    inverse_support[j] = 1.0 / lin.row_support[static_cast<std::size_t>(j)];
    c.lower[j] = -lin.b[j] * inverse_support[j];
  }
  c.rows = inverse_support.asDiagonal() * lin.A;
  for (Index j = 0; j < m; ++j) {
    const ContactFamily& family = contacts.families()[static_cast<std::size_t>(lin.row_family[static_cast<std::size_t>(j)])];
    const ContactSurface& s = contacts.surfaces[static_cast<std::size_t>(family.slave)];
    const Index body_node = s.nodes[static_cast<std::size_t>(lin.row_node[static_cast<std::size_t>(j)])];
    c.node.push_back(dofs.dof(s.body, body_node, 0) / dim);
  }
  const Eigen::SparseMatrix<double, Eigen::RowMajor, int> rows = c.rows;
  for (Index j = 0; j < m; ++j) {
    for (Eigen::SparseMatrix<double, Eigen::RowMajor, int>::InnerIterator it(rows, j); it; ++it)
      if (it.col() / dim == c.node[j]) c.normal(it.col() % dim, j) = it.value();
    const double norm = c.normal.col(j).norm();
    if (norm > 0.0)
      c.normal.col(j) /= norm;
    else
      c.normal(dim - 1, j) = 1.0;
  }
  return c;
}

/// The row of each friction point: `visit(p, q, j, g)` for point q of pair p's term, row j of `lin` and the
/// point's bound g = w τ. The row of node k of family f takes the point of node k of the pair whose friction
/// family is f. Throws SolveError for a point with τ > 0 and no row (the interior point carries friction on its
/// rows only).
template <class Visit>
void for_each_friction_row(const std::vector<std::shared_ptr<FrictionTerm>>& terms, const ContactLinearization& lin,
                           const ContactSet& contacts, Visit visit) {
  std::map<std::pair<int, Index>, Index> row_of;
  for (Index j = 0; j < lin.A.rows(); ++j)
    row_of[{lin.row_family[static_cast<std::size_t>(j)], lin.row_node[static_cast<std::size_t>(j)]}] = j;
  for (std::size_t p = 0; p < terms.size(); ++p) {
    if (!terms[p]) continue;
    const int family = contacts.friction_family(static_cast<int>(p));
    const std::vector<ContactPoint>& points = terms[p]->points();
    const std::vector<double> bound = terms[p]->bounds();
    for (std::size_t q = 0; q < points.size(); ++q) {
      const auto it = row_of.find({family, points[q].slave_node});
      if (it != row_of.end()) {
        visit(p, q, it->second, bound[q]);
      } else if (bound[q] > 0.0) {
        throw SolveError("pair " + contacts.pairs[p].name + ": surface node " + std::to_string(points[q].slave_node) +
                         " has a friction threshold and no contact row; the distributed path carries friction at "
                         "the nodes within the search distance only");
      }
    }
  }
}

/// The serial friction terms (solvers/friction_state.hpp: one point per slave node of a pair's friction family)
/// as the interior point's friction on the rows of c (for_each_friction_row), each row with its point's bound,
/// α, normal n̄ (P = I − n̄ n̄ᵀ, as the term's), relative-displacement map B (FrictionTerm::slip_map: the slave
/// node against the master surface at its projection, or against a rigid obstacle) and slip origin B u_start,
/// so that the interior point's j(u) is the sum of the terms'.
void add_friction(const std::vector<std::shared_ptr<FrictionTerm>>& terms, const ContactLinearization& lin,
                  const ContactSet& contacts, const DofMap& dofs, const VectorXd& u_start, NodalConstraints& c) {
  const Index m = c.size(), dim = dofs.dim(), n = dofs.num_dofs();
  c.friction_bound = VectorXd::Zero(m);
  c.friction_alpha = VectorXd::Ones(m);  // any α > 0 where g = 0: such a row adds nothing
  c.slip_origin = Eigen::MatrixXd::Zero(dim, m);
  std::vector<Eigen::SparseMatrix<double, Eigen::RowMajor, int>> maps(terms.size());
  std::vector<VectorXd> origins(terms.size());
  for (std::size_t p = 0; p < terms.size(); ++p)
    if (terms[p]) {
      maps[p] = terms[p]->slip_map(n);
      origins[p] = maps[p] * u_start;
    }
  std::vector<Eigen::Triplet<double>> map;
  for_each_friction_row(terms, lin, contacts, [&](std::size_t p, std::size_t q, Index j, double bound) {
    c.friction_bound[j] = bound;
    c.friction_alpha[j] = terms[p]->alphas()[q];
    c.normal.col(j) = terms[p]->points()[q].normal.head(dim);
    for (Index k = 0; k < dim; ++k) {
      const Index point_row = dim * static_cast<Index>(q) + k;
      c.slip_origin(k, j) = origins[p][point_row];
      for (Eigen::SparseMatrix<double, Eigen::RowMajor, int>::InnerIterator e(maps[p], point_row); e; ++e)
        map.emplace_back(static_cast<int>(dim * j + k), static_cast<int>(e.col()), e.value());
    }
  });
  c.slip_map.resize(dim * m, n);
  c.slip_map.setFromTriplets(map.begin(), map.end());
}

/// The bounds of the thresholds followed at the iterate (u, λ), for FollowBounds: the bodies' force on the
/// surfaces there, ∇E(u) = Aᵀμ − ∇j(u) (μ = λ / support, zero on fixed DOFs), handed to the follower
/// (friction_state.hpp); where it moved τ, the Coulomb pairs' terms take the new thresholds (as the serial
/// GeometrySubproblem's hook) and the rows of `lin` their bounds. nullopt where τ did not move.
std::optional<VectorXd> followed_bounds(const FrictionState& friction, std::vector<std::shared_ptr<FrictionTerm>>& terms,
                                        const ContactLinearization& lin, const Model& model, const FixedDofs& fixed,
                                        const VectorXd& u, const VectorXd& lambda) {
  const ContactSet& contacts = model.contacts();
  VectorXd mu(lambda.size());
  for (Index j = 0; j < mu.size(); ++j) mu[j] = lambda[j] / lin.row_support[static_cast<std::size_t>(j)];
  VectorXd gradient = VectorXd::Zero(u.size());
  for (const auto& t : terms)
    if (t) t->add_gradient(u, gradient);
  VectorXd force = lin.A.transpose() * mu - gradient;
  for (const Index d : fixed.dofs) force[d] = 0.0;
  if (!friction.follower->follow(u, force)) return std::nullopt;
  for (std::size_t p = 0; p < terms.size(); ++p) {
    if (!terms[p] || contacts.pairs[p].friction != FrictionLaw::kCoulomb) continue;
    const ContactSurface& slave = contacts.surfaces[contacts.families()[contacts.friction_family(static_cast<int>(p))].slave];
    terms[p]->set_thresholds(interpolate_at_points(slave, terms[p]->points(), friction.nodal_tau[p]));
  }
  VectorXd bounds = VectorXd::Zero(lin.A.rows());
  for_each_friction_row(terms, lin, contacts, [&](std::size_t, std::size_t, Index j, double g) { bounds[j] = g; });
  return bounds;
}

bool same_rows(const ContactLinearization& a, const ContactLinearization& b) {
  return a.A.rows() == b.A.rows() && a.A.nonZeros() == b.A.nonZeros() && a.b == b.b &&
         (a.A - b.A).norm() == 0.0;
}

/// Ends a geometry fixed point that cannot converge: past its iteration limit, or with no new low of its change
/// in ten iterations (FixedPointMonitor: a cycle of period up to nine, or a floor above the tolerance, as the
/// rings' symmetric pair shows at geometry_tolerance = 1e-10). Its subproblems' answers are exact on their active
/// sets, so that, unlike the serial solver, a tighter interior point would not move the floor.
void fail_if_stuck(FixedPointMonitor& monitor, int iteration, double change, const ContactSolveOptions& o) {
  monitor.record(change);
  const bool stagnated = monitor.stagnated();
  if (!stagnated && iteration < o.max_geometry_iterations) return;
  std::ostringstream s;
  if (stagnated)
    s << "the geometry fixed point stagnated: no new low of its relative change in " << kStagnationWindow
      << " iterations (best " << monitor.best() << ", last " << change << ", tolerance " << o.geometry_tolerance
      << "); try a larger [contact_solver] geometry_tolerance";
  else
    s << "the geometry fixed point did not converge in " << o.max_geometry_iterations
      << " iterations (last relative change " << change << ", tolerance " << o.geometry_tolerance << ")";
  throw SolveError(s.str());
}

/// What to try when the interior point stops on a model with a symmetric pair of two surfaces: its two nearly
/// dependent families of rows are what the path closes least surely (docs/distributed.md); "" without one.
std::string symmetric_pair_hint(const ContactSet& contacts) {
  for (const ContactPair& p : contacts.pairs)
    if (p.two_sided() && p.surface_a != p.surface_b)
      return "; contact '" + p.name + "' is a symmetric pair, whose two nearly dependent families of rows this path "
             "closes least surely: mode = \"one-pass\" gives it one family (or run without mpirun)";
  return "";
}

class DistributedStep {
 public:
  DistributedStep(const ProblemSpec& spec, const ContactInteriorPointOptions& options, const Logger& log)
      : frictional_(spec.contact_solver.friction), options_(options), log_(log) {}

  /// The quadratic program on the rows of `lin`; without rows (no contact point within any pair's search
  /// distance) the stiffness system alone.
  /// With `friction` (the step's thresholds and slip origin), the friction terms at u, added to the rows
  /// (add_friction) and kept in `terms`.
  ContactInteriorPointResult solve_rows(const QuadraticModel& q, const FixedDofs& fixed, const VectorXd& fixed_values,
                                        const ContactLinearization& lin, const Model& model, const VectorXd& u,
                                        const FrictionState* friction, const ContactInteriorPointOptions& options,
                                        std::vector<std::shared_ptr<FrictionTerm>>& terms) const {
    NodalConstraints rows = scaled_rows(lin, model.dofs(), model.contacts());
    terms.assign(model.contacts().pairs.size(), nullptr);
    if (friction) {
      terms = friction_terms(*friction, model.contacts(), model.dofs(), u);
      add_friction(terms, lin, model.contacts(), model.dofs(), friction->u_start, rows);
    }
    FollowBounds follow;
    if (friction && friction->follower) {
      friction->follower->start_solve();
      follow = [&](const VectorXd& u_now, const VectorXd& lambda) {
        return followed_bounds(*friction, terms, lin, model, fixed, ordering().to_model(u_now), lambda);
      };
    }
    const std::vector<Index> fixed_dofs = ordering().dofs_to_petsc(fixed.dofs);
    if (lin.A.rows() > 0) {
      const VectorXd start = friction ? ordering().to_petsc(u) : VectorXd();
      ContactInteriorPointResult r =
          solve_contact_interior_point(q.K_lower, q.f, fixed_dofs, fixed_values, q.x, ordering().to_petsc(rows),
                                       options, friction ? &start : nullptr, follow ? &follow : nullptr);
      r.u = ordering().to_model(r.u);
      return r;
    }
    const GamgResult g = solve_elasticity_gamg(q.K_lower, q.f, fixed_dofs, fixed_values, q.x);
    if (!g.converged)
      throw SolveError("no contact point within any pair's search distance, and the stiffness system alone did not "
                       "solve (" + g.reason + "): a body held by contact alone?");
    ContactInteriorPointResult r;
    r.u = ordering().to_model(g.u);
    r.converged = true;
    r.total_seconds = g.setup_seconds + g.solve_seconds;
    return r;
  }

  /// The forces on the rows of `next` when u, the solve's answer on the rows of `lin`, also solves the
  /// quadratic program on `next` to the interior point's tolerance (a plane obstacle whose search distance
  /// now takes in a few more rows, none of them violated): each row keeps the force of the row of `lin` at
  /// the same family and node, 0 for a new one, and the interior point's stopping test holds for them with
  /// s the rows' gaps (contact_interior_point.hpp); nullopt otherwise.
  std::optional<VectorXd> forces_if_still_optimal(const ContactLinearization& next, const ContactLinearization& lin,
                                                  const ContactInteriorPointResult& solve, const Model& model,
                                                  const FixedDofs& fixed, const VectorXd& u) const {
    const VectorXd lambda = values_on_rows(lin.row_family, lin.row_node, solve.lambda, next);
    const double tol = options_.tolerance, F = solve.force_scale, L = solve.length_scale;
    const VectorXd gap = next.A * u + next.b;
    VectorXd mu(next.A.rows());
    for (Index j = 0; j < next.A.rows(); ++j) {
      const double support = next.row_support[static_cast<std::size_t>(j)], g = gap[j] / support;
      if (g < -tol * L || std::min(std::max(g, 0.0) / L, lambda[j] / F) > tol) return std::nullopt;
      mu[j] = lambda[j] / support;
    }
    VectorXd residual = -(next.A.transpose() * mu);
    model.energy().add_gradient(u, residual);
    for (const Index d : fixed.dofs) residual[d] = 0.0;
    if (residual.lpNorm<Eigen::Infinity>() > tol * F) return std::nullopt;
    return lambda;
  }

  /// One load step: the geometry fixed point, within the Coulomb fixed point of the serial solver
  /// (lagged_fixed_point.hpp, coulomb_thresholds.hpp) where a pair has friction.
  SolveReport operator()(Model& model, int step, VectorXd& u, FrictionState& friction) const {
    bool frictional = false;
    for (const ContactPair& p : model.contacts().pairs) frictional = frictional || p.friction != FrictionLaw::kNone;
    if (!frictional) return solve_geometry(model, step, u, nullptr, frictional_.contact);
    CoulombThresholds coulomb(model.contacts(), model.dofs(), u, friction.nodal_tau.empty() ? nullptr : &friction,
                              0.0, log_);
    // The thresholds follow the interior point's iterates (coulomb_update = "inside_optimizer"), settling
    // below a tenth of the loop's tolerance, as in the serial solver (frictional_contact.cpp).
    if (frictional_.coulomb_update == CoulombUpdate::kInsideOptimizer)
      coulomb.follow_iterates(0.1 * frictional_.coulomb_tolerance);
    const VectorXd u_start = u;
    const LaggedSolve solve = [&](const ContactSolveOptions& o) {
      return solve_geometry(model, step, u, &coulomb.state(), o);
    };
    SolveReport r = solve_lagged(coulomb, solve, u, u_start, frictional_, false, log_);
    r.friction_state = coulomb.state();
    friction = r.friction_state;
    return r;
  }

 private:
  /// The geometry fixed point of the file comment under `o` (its geometry tolerance; its optimiser tolerance,
  /// relative to the problem's, scales the interior point's), with the friction terms of `friction` (null: none).
  SolveReport solve_geometry(Model& model, int step, VectorXd& u, const FrictionState* friction,
                             const ContactSolveOptions& o) const {
    SolveReport r;
    const ProgressClock clock;
    const auto t0 = std::chrono::steady_clock::now();
    if (!*ordering_) *ordering_ = std::make_shared<const NodeOrdering>(reference_coordinates(model));
    const bool quadratic = model.energy().hessian_is_constant();
    QuadraticModel q = quadratic_model(model, ordering(), *stiffness_, u);
    const FixedDofs fixed = model.fixed_dofs(step);
    const VectorXd fixed_values = Eigen::Map<const VectorXd>(fixed.values.data(), static_cast<Index>(fixed.values.size()));
    r.times.add("assembly", petsc::seconds_since(t0));
    ContactInteriorPointOptions options = options_;
    options.tolerance *= o.ipopt.tolerance / frictional_.contact.ipopt.tolerance;
    options.force_scale = *force_scale_;
    ContactLinearization lin;
    ContactInteriorPointResult solve;
    std::vector<std::shared_ptr<FrictionTerm>> terms;
    FixedPointMonitor monitor(kStagnationWindow);
    double delta = 0.0;  // the shift of a hyperelastic model's Hessian (solve_model)
    bool loose = false;  // the last solve's force scale above kLooseScale × its answer's: not an end
    for (r.geometry_iterations = 1;; ++r.geometry_iterations) {
      if (!quadratic && r.geometry_iterations > 1) {  // the next Newton step's model
        const auto t_model = std::chrono::steady_clock::now();
        q = quadratic_model(model, ordering(), *stiffness_, u);
        r.times.add("assembly", petsc::seconds_since(t_model));
      }
      const auto t_search = std::chrono::steady_clock::now();
      ContactLinearization next = model.contacts().linearize(model.dofs(), u);
      r.times.add("search", petsc::seconds_since(t_search));
      if (quadratic && r.geometry_iterations > 1 && !loose && same_rows(lin, next)) break;
      if (r.geometry_iterations > 1 && lin.A.rows() > 0 && !friction && !loose) {
        if (std::optional<VectorXd> forces = forces_if_still_optimal(next, lin, solve, model, fixed, u)) {
          solve.lambda = std::move(*forces);  // the rows changed, the answer did not: no new solve
          lin = std::move(next);
          break;
        }
      }
      lin = std::move(next);
      // A later geometry iteration starts from thresholds at the previous one's fixed point: follow near the end.
      options.follow_below = r.geometry_iterations > 1 ? std::max(1e-8, 10.0 * options.tolerance) : 0.1;
      solve = solve_model(q, quadratic, delta, fixed, fixed_values, lin, model, u, friction, options, terms, r);
      if (!solve.converged)
        throw SolveError("geometry iteration " + std::to_string(r.geometry_iterations) +
                         ": the distributed interior point stopped: " + solve.reason +
                         symmetric_pair_hint(model.contacts()));
      const double answer_scale = answer_force_scale(model, solve.u);
      loose = solve.force_scale > kLooseScale * answer_scale;
      if (loose || *force_scale_ > 0.0) options.force_scale = *force_scale_ = answer_scale;
      const double change = (solve.u - u).lpNorm<Eigen::Infinity>() / solve.u.lpNorm<Eigen::Infinity>();
      r.change_history.push_back(change);
      u = solve.u;
      std::ostringstream m;
      m << "  geometry iteration " << r.geometry_iterations << ": " << lin.A.rows() << " constraints, optimizer "
        << solve.iterations << " iterations (distributed interior point: converged), change " << change;
      if (delta > 0.0) m << ", Hessian shifted by " << delta << " × its diagonal";
      log_iteration(log_, clock, m.str());
      // A shifted step is shortened: only Newton's own step may end the fixed point.
      if (change <= o.geometry_tolerance && delta == 0.0 && !loose) break;
      delta = delta > kFirstShift ? 0.1 * delta : 0.0;
      fail_if_stuck(monitor, r.geometry_iterations, change, o);
    }
    set_contact_state(model, fixed, u, std::move(lin), solve.lambda, terms, r);
    return r;
  }

  /// solve_rows on q; where q's Hessian is not constant and that solve fails (a Hessian that is not positive
  /// definite, whose conjugate gradients break down), on shifted(q, δ), δ from max(delta, kFirstShift) up by
  /// tens to kLargestShift. `delta` is left at the shift of the answer (0: q's own). Iterations and times in r.
  ContactInteriorPointResult solve_model(const QuadraticModel& q, bool quadratic, double& delta, const FixedDofs& fixed,
                                         const VectorXd& fixed_values, const ContactLinearization& lin,
                                         const Model& model, const VectorXd& u, const FrictionState* friction,
                                         const ContactInteriorPointOptions& options,
                                         std::vector<std::shared_ptr<FrictionTerm>>& terms, SolveReport& r) const {
    for (;;) {
      ContactInteriorPointResult solve =
          solve_rows(delta > 0.0 ? shifted(q, delta) : q, fixed, fixed_values, lin, model, u, friction, options, terms);
      r.times.add("optimizer", solve.total_seconds);
      r.ipopt_iterations += solve.iterations;
      r.ipopt_per_iteration.push_back(solve.iterations);
      if (solve.converged || quadratic || delta >= kLargestShift) return solve;
      log_.detail("  the Newton step's program did not solve (" + solve.reason + "): its Hessian shifted");
      delta = delta > 0.0 ? 10.0 * delta : kFirstShift;
    }
  }

  /// r's contact state at the answer u on the rows of `lin` with their forces λ (the interior point's) and
  /// the friction terms of the solve (none when empty): the forces recovered as the serial solver does.
  static void set_contact_state(const Model& model, const FixedDofs& fixed, const VectorXd& u,
                                ContactLinearization&& lin, const VectorXd& lambda,
                                const std::vector<std::shared_ptr<FrictionTerm>>& terms, SolveReport& r) {
    VectorXd mu(lin.A.rows());
    for (Index j = 0; j < mu.size(); ++j) mu[j] = lambda[j] / lin.row_support[static_cast<std::size_t>(j)];
    r.friction.assign(terms.begin(), terms.end());
    if (r.friction.empty()) r.friction.assign(model.contacts().pairs.size(), nullptr);
    ContactForces forces = recover_contact_forces(model.energy(), fixed, model.contacts(), model.dofs(), u, lin.A, mu,
                                                  r.friction, CondensedResidual{});
    r.contact_force = std::move(forces.contact_force);
    r.multiplier_force = std::move(forces.multiplier_force);
    r.force_defect = std::move(forces.force_defect);
    r.multipliers = std::move(mu);
    r.num_constraints = lin.A.rows();
    r.num_free = model.dofs().num_dofs() - static_cast<Index>(fixed.dofs.size());
    r.linearization = std::move(lin);
    r.converged = true;
    r.ipopt_status = "distributed interior point: converged";
    r.substeps = {1.0};
  }

  FrictionalOptions frictional_;  ///< the problem's [contact_solver] settings
  ContactInteriorPointOptions options_;
  const Logger& log_;
  const NodeOrdering& ordering() const { return **ordering_; }

  /// K of the first step, kept for the next ones (this rank's rows, PETSc's numbering), and that numbering;
  /// shared by the copies a StepSolver makes.
  std::shared_ptr<std::optional<SparseMatrix>> stiffness_ = std::make_shared<std::optional<SparseMatrix>>();
  std::shared_ptr<std::shared_ptr<const NodeOrdering>> ordering_ =
      std::make_shared<std::shared_ptr<const NodeOrdering>>();
  /// answer_force_scale() of the last answer once a solve's own force scale was loose (kLooseScale; 0 until
  /// then): the interior point's force scale for the solves after it.
  std::shared_ptr<double> force_scale_ = std::make_shared<double>(0.0);
};

}  // namespace

StepSolver distributed_step_solver(const ProblemSpec& spec, const ContactInteriorPointOptions& options,
                                   const Logger& log) {
  return DistributedStep(spec, options, log);
}

}  // namespace symcontact
