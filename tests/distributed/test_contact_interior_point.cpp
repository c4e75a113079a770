// The distributed interior point for contact with a rigid obstacle
// (src/symcontact/distributed/contact_interior_point.hpp) on a block pressed onto a rigid ball, on one rank
// and, registered a second time under mpirun, on two: its answer against the exact solution of the contact
// problem (the active set's equality-constrained problem solved by sparse Cholesky, checked for contact
// forces ≥ 0 and gaps ≥ 0), the same for a block loaded onto a plane it touches up to round-off and with a
// second family of rows that cannot close with the first; nearly dependent rows polished on their inequalities
// (KKT conditions), with friction too (a solve cut short, rescued); the Krylov iterations per Newton system as
// the mesh is refined, and Tresca and Coulomb friction on a block sliding on a rigid plane against their closed
// forms, its slip also given by maps; the block sticking, with the regularisation down to 10⁻⁷ of its elements.

#include "symcontact/distributed/contact_interior_point.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <vector>

#include "symcontact/distributed/model_problems.hpp"
#include "test_support.hpp"

namespace symcontact {
namespace {

ContactInteriorPointResult solve(const ObstacleSystem& o, const ContactInteriorPointOptions& options = {}) {
  const BlockSystem& b = o.block;
  return solve_contact_interior_point(b.K_lower, b.f, b.fixed, b.fixed_values, b.mesh.x, o.contact, options);
}

/// c_j(u) = n_jᵀ u_{p_j} − l_j.
VectorXd gaps(const NodalConstraints& c, const VectorXd& u) {
  const Index dim = c.normal.rows();
  VectorXd g(c.size());
  for (Index j = 0; j < c.size(); ++j) g[j] = c.normal.col(j).dot(u.segment(dim * c.node[j], dim)) - c.lower[j];
  return g;
}

/// The exact solution for the active set the interior point found (λ_j / F > c_j / L): the vertical DOFs
/// of the active nodes fixed at l_j, the rest of the problem solved by Cholesky; λ_ref the reactions there.
struct ActiveSetSolution {
  VectorXd u, lambda;
  std::vector<char> active;
};

ActiveSetSolution active_set_solution(const ObstacleSystem& o, const ContactInteriorPointResult& r) {
  const BlockSystem& whole = o.block;
  const NodalConstraints& c = o.contact;
  const Index dim = c.normal.rows();
  const VectorXd g = gaps(c, r.u);
  ActiveSetSolution a{{}, VectorXd::Zero(c.size()), std::vector<char>(static_cast<std::size_t>(c.size()), 0)};
  std::vector<Index> fixed = whole.fixed;
  std::vector<double> values(whole.fixed_values.data(), whole.fixed_values.data() + whole.fixed_values.size());
  for (Index j = 0; j < c.size(); ++j)
    if (r.lambda[j] / r.force_scale > g[j] / r.length_scale) {
      a.active[static_cast<std::size_t>(j)] = 1;
      fixed.push_back(dim * c.node[j] + dim - 1);  // the block's normals are vertical
      values.push_back(c.lower[j]);
    }
  a.u = cholesky_solution(whole.K_lower, whole.f, fixed,
                          Eigen::Map<VectorXd>(values.data(), static_cast<Index>(values.size())));
  const VectorXd reaction = SparseMatrix(whole.K_lower.selfadjointView<Eigen::Lower>()) * a.u - whole.f;
  for (Index j = 0; j < c.size(); ++j)
    if (a.active[static_cast<std::size_t>(j)]) a.lambda[j] = reaction[dim * c.node[j] + dim - 1];
  return a;
}

TEST(ContactInteriorPoint, FindsTheExactSolutionOfTheContactProblemIn2DAnd3D) {
  for (const auto& [dim, n] : {std::pair{2, 24}, std::pair{3, 8}}) {
    // This rank's share of the stiffness for the solve; the whole of it for the reference.
    const ObstacleSystem mine = block_on_ball_system(dim, n, 1.0, 0.02, g_petsc->rank(), g_petsc->size());
    const ObstacleSystem whole = block_on_ball_system(dim, n, 1.0, 0.02);
    const ContactInteriorPointResult r = solve(mine);
    ASSERT_TRUE(r.converged) << r.reason;
    const ActiveSetSolution a = active_set_solution(whole, r);
    const auto active = std::count(a.active.begin(), a.active.end(), 1);
    const double u_error = (r.u - a.u).lpNorm<Eigen::Infinity>() / a.u.lpNorm<Eigen::Infinity>();
    const double lambda_error = (r.lambda - a.lambda).lpNorm<Eigen::Infinity>() / a.lambda.maxCoeff();
    if (g_petsc->rank() == 0)
      std::printf("dim %d, %lld DOFs, %lld of %lld nodes in contact: %d iterations (%d polish), Krylov %d–%d, "
                  "against the active set's solution: u %.1e, λ %.1e\n",
                  dim, static_cast<long long>(r.u.size()), static_cast<long long>(active),
                  static_cast<long long>(whole.contact.size()), r.iterations, r.polishes,
                  *std::min_element(r.krylov_iterations.begin(), r.krylov_iterations.end()),
                  *std::max_element(r.krylov_iterations.begin(), r.krylov_iterations.end()), u_error, lambda_error);
    EXPECT_GE(active, 3);
    EXPECT_LE(active, whole.contact.size() - 3);
    // The active set's solution solves the contact problem: no pull, no penetration.
    const VectorXd g = gaps(whole.contact, a.u);
    for (Index j = 0; j < whole.contact.size(); ++j) {
      EXPECT_GE(a.lambda[j], -1e-9 * r.force_scale) << "node " << whole.contact.node[j];
      EXPECT_GE(g[j], -1e-9 * r.length_scale) << "node " << whole.contact.node[j];
    }
    EXPECT_LE(u_error, 1e-7);
    EXPECT_LE(lambda_error, 1e-6);
    // Where the polish on the active set ended the solve (on one rank in 2D: the interior point tells the rows
    // apart before its own test passes), the answer is the active set's exact solution to a hundredth of the
    // tolerance.
    if (dim == 2 && g_petsc->size() == 1) {
      EXPECT_EQ(r.polishes, 1);
    }
    if (r.polishes > 0) {
      EXPECT_LE(u_error, 1e-9);
      EXPECT_LE(lambda_error, 1e-9);
    }
    for (std::size_t k = 0; k < whole.block.fixed.size(); ++k)
      EXPECT_EQ(r.u[whole.block.fixed[k]], whole.block.fixed_values[static_cast<Index>(k)]) << "exactly";
  }
}

/// The block of block_on_plane_system, frictionless, its top free vertically and loaded downwards by a nodal
/// force of 1e-3 on each of its nodes, resting on the plane with gaps of round-off size (±1e-16, alternating):
/// no imposed displacement and no gap to set the length scale.
ObstacleSystem loaded_block_on_plane(int dim, int n, int part, int parts) {
  ObstacleSystem o = block_on_plane_system(dim, n, 0.0, 0.0, 0.0, 1.0, part, parts);
  o.contact.friction_bound.resize(0);
  o.contact.friction_alpha.resize(0);
  BlockSystem& b = o.block;
  std::vector<Index> fixed;
  std::vector<double> values;
  for (std::size_t k = 0; k < b.fixed.size(); ++k)
    if (b.fixed[k] % dim != dim - 1) {
      fixed.push_back(b.fixed[k]);
      values.push_back(b.fixed_values[static_cast<Index>(k)]);
    } else {
      b.f[b.fixed[k]] = -1e-3;
    }
  b.fixed = fixed;
  b.fixed_values = Eigen::Map<VectorXd>(values.data(), static_cast<Index>(values.size()));
  for (Index j = 0; j < o.contact.size(); ++j) o.contact.lower[j] = j % 2 ? 1e-16 : -1e-16;
  return o;
}

// Gaps of faces that coincide up to round-off are no length scale: the interior point takes the displacement
// the load makes instead and finds the exact solution (every bottom node in contact).
TEST(ContactInteriorPoint, SolvesALoadDrivenProblemWithRoundOffGaps) {
  for (const auto& [dim, n] : {std::pair{2, 16}, std::pair{3, 6}}) {
    const ObstacleSystem mine = loaded_block_on_plane(dim, n, g_petsc->rank(), g_petsc->size());
    const ObstacleSystem whole = loaded_block_on_plane(dim, n, 0, 1);
    const ContactInteriorPointResult r = solve(mine);
    ASSERT_TRUE(r.converged) << r.reason;
    EXPECT_GT(r.length_scale, 1e-6) << "the load's displacement, not the gaps' round-off";
    const ActiveSetSolution a = active_set_solution(whole, r);
    EXPECT_EQ(std::count(a.active.begin(), a.active.end(), 1), whole.contact.size());
    EXPECT_GT(a.lambda.minCoeff(), 0.0);
    EXPECT_LE((r.u - a.u).lpNorm<Eigen::Infinity>(), 1e-8 * a.u.lpNorm<Eigen::Infinity>());
    EXPECT_LE((r.lambda - a.lambda).lpNorm<Eigen::Infinity>(), 1e-8 * a.lambda.maxCoeff());
  }
}

/// o's rows and beside each a copy that asks its node to stay `offset` further away (the same normal, the lower
/// bound + offset): two families of rows as a curved symmetric pair has, the one held open by the other.
ObstacleSystem with_offset_copies(ObstacleSystem o, double offset) {
  NodalConstraints& c = o.contact;
  const Index m = c.size();
  c.node.insert(c.node.end(), c.node.begin(), c.node.end());
  c.normal.conservativeResize(Eigen::NoChange, 2 * m);
  c.normal.rightCols(m) = c.normal.leftCols(m);
  c.lower.conservativeResize(2 * m);
  c.lower.tail(m) = c.lower.head(m).array() + offset;
  return o;
}

// Two families of nearly dependent rows, one of each pair open by 1e-7 of the imposed displacement at the
// answer: the polish that first takes both into its active set finds that they cannot close together, drops the
// open ones and closes the rest: the answer of the tighter family alone, to a hundredth of the tolerance.
TEST(ContactInteriorPoint, ClosesOneOfEachPairOfRowsThatCannotCloseTogether) {
  const int dim = 2, n = 24;
  const double depth = 0.02, offset = 1e-7 * depth;
  const ObstacleSystem tight = block_on_ball_system(dim, n, 1.0, depth, g_petsc->rank(), g_petsc->size());
  ObstacleSystem alone = tight;
  alone.contact.lower.array() += offset;
  const ContactInteriorPointResult reference = solve(alone);
  ASSERT_TRUE(reference.converged) << reference.reason;
  const ContactInteriorPointResult r = solve(with_offset_copies(tight, offset));
  ASSERT_TRUE(r.converged) << r.reason;
  EXPECT_EQ(r.polishes, 1);
  EXPECT_EQ(r.polishes_rejected, 0) << "the first polish meets both families and keeps the tighter one";
  const Index m = tight.contact.size();
  const double u_error = (r.u - reference.u).lpNorm<Eigen::Infinity>() / reference.u.lpNorm<Eigen::Infinity>();
  const double lambda_error =
      (r.lambda.head(m) + r.lambda.tail(m) - reference.lambda).lpNorm<Eigen::Infinity>() / reference.lambda.maxCoeff();
  if (g_petsc->rank() == 0)
    std::printf("%d iterations (%d polish, %d rejected): u %.1e, λ %.1e from the tighter family's answer; "
                "the looser rows carry %.1e\n", r.iterations, r.polishes, r.polishes_rejected, u_error, lambda_error,
                r.lambda.head(m).lpNorm<Eigen::Infinity>());
  EXPECT_LE(u_error, 1e-10);
  EXPECT_LE(lambda_error, 1e-9);
  EXPECT_EQ(r.lambda.head(m).lpNorm<Eigen::Infinity>(), 0.0) << "the open rows carry no force";
}

/// o (a block on a ball of radius `radius`, 2D; radius 0: on a plane) with a second family of rows between each two neighbouring bottom
/// nodes a and b: u_y at the points a tenth and nine tenths of the way, (1 − t) u_y(a) + t u_y(b), above the ball
/// there. The ball being convex, these rows are a little tighter than the nodes' rows they combine: the nearly
/// dependent families of a curved symmetric pair on unmatched meshes, each row of one close to a combination of
/// rows of the other.
ObstacleSystem with_rows_between_nodes(ObstacleSystem o, double radius) {
  const bool frictional = o.contact.frictional();
  NodalConstraints& c = o.contact;
  const Index m = c.size(), dim = 2;
  const Eigen::MatrixXd& x = o.block.mesh.x;
  std::vector<Index> order = c.node;
  std::sort(order.begin(), order.end(), [&](Index a, Index b) { return x(0, a) < x(0, b); });
  std::vector<Eigen::Triplet<double>> entries;
  for (Index j = 0; j < m; ++j) entries.emplace_back(j, dim * c.node[j] + 1, 1.0);
  std::vector<double> lower(c.lower.data(), c.lower.data() + m);
  for (std::size_t k = 0; k + 1 < order.size(); ++k)
    for (const double t : {0.1, 0.9}) {
      const Index a = order[k], b = order[k + 1], row = c.size();
      entries.emplace_back(row, dim * a + 1, 1.0 - t);
      entries.emplace_back(row, dim * b + 1, t);
      const double r = (1.0 - t) * x(0, a) + t * x(0, b) - 0.5;
      lower.push_back(radius > 0.0 ? -(radius - std::sqrt(radius * radius - r * r)) : 0.0);
      c.node.push_back(t < 0.5 ? a : b);
    }
  const Index rows = c.size();
  c.lower = Eigen::Map<VectorXd>(lower.data(), rows);
  c.normal = Eigen::MatrixXd::Zero(dim, rows);
  c.normal.row(1).setOnes();
  c.rows.resize(rows, o.block.f.size());
  c.rows.setFromTriplets(entries.begin(), entries.end());
  if (frictional) {
    c.friction_bound.conservativeResize(rows);
    c.friction_bound.tail(rows - m).setZero();
    c.friction_alpha.conservativeResize(rows);
    c.friction_alpha.tail(rows - m).setConstant(c.friction_alpha[0]);
  }
  return o;
}

// On those two families the active-set polish cannot settle its set, and the method of multipliers on the
// inequalities polishes the answer instead: checked against the conditions it must meet (KKT to what the polish
// asks during the iterations: the forces balanced to 1e-2 tol F, every row closed or free of force to 1e-4 tol).
TEST(ContactInteriorPoint, PolishesNearlyDependentRowsOnTheirInequalities) {
  const double radius = 1.0;
  const ObstacleSystem mine =
      with_rows_between_nodes(block_on_ball_system(2, 48, radius, 0.02, g_petsc->rank(), g_petsc->size()), radius);
  const ObstacleSystem whole = with_rows_between_nodes(block_on_ball_system(2, 48, radius, 0.02), radius);
  const ContactInteriorPointResult r = solve(mine);
  ASSERT_TRUE(r.converged) << r.reason;
  EXPECT_EQ(r.inequality_polishes, 1);
  const double tol = ContactInteriorPointOptions{}.tolerance, F = r.force_scale, L = r.length_scale;
  const NodalConstraints& c = whole.contact;
  const VectorXd g = c.rows * r.u - c.lower;
  VectorXd rd = SparseMatrix(whole.block.K_lower.selfadjointView<Eigen::Lower>()) * r.u - whole.block.f -
                c.rows.transpose() * r.lambda;
  for (const Index i : whole.block.fixed) rd[i] = 0.0;
  double complementarity = 0.0;
  for (Index j = 0; j < c.size(); ++j) complementarity = std::max(complementarity, std::min(g[j] / L, r.lambda[j] / F));
  if (g_petsc->rank() == 0)
    std::printf("%lld rows: %d iterations (%d polish, %d on the inequalities, %d rejected); forces %.1e F, "
                "violation %.1e L, complementarity %.1e, %lld rows carry force\n",
                static_cast<long long>(c.size()), r.iterations, r.polishes, r.inequality_polishes,
                r.polishes_rejected, rd.lpNorm<Eigen::Infinity>() / F, std::max(0.0, -g.minCoeff()) / L,
                complementarity, static_cast<long long>((r.lambda.array() > 0.0).count()));
  EXPECT_LE(rd.lpNorm<Eigen::Infinity>(), 1e-2 * tol * F);
  EXPECT_GE(g.minCoeff(), -1e-4 * tol * L);
  EXPECT_GE(r.lambda.minCoeff(), 0.0);
  EXPECT_LE(complementarity, 1e-4 * tol);
}

/// The balance of a block dragged on a plane (block_on_plane_system), at its answer u: the top's reaction along x,
/// the friction forces' sum along x, Σ_j g_j s_x / √(|s|² + α²) with s node j's displacement along the plane's
/// tangents, and the smallest s_x.
struct DragBalance {
  double reaction = 0.0, friction = 0.0, smallest_slip = 1.0;
};

DragBalance drag_balance(const ObstacleSystem& whole, int dim, const VectorXd& u, double alpha) {
  DragBalance b;
  const VectorXd residual = SparseMatrix(whole.block.K_lower.selfadjointView<Eigen::Lower>()) * u - whole.block.f;
  for (const Index v : whole.block.mesh.group_nodes(dim == 2 ? "top" : "zmax")) b.reaction += residual[dim * v];
  for (Index j = 0; j < whole.contact.size(); ++j) {
    const VectorXd slip = u.segment(dim * whole.contact.node[j], dim - 1);
    b.friction += whole.contact.friction_bound[j] * slip[0] / std::sqrt(slip.squaredNorm() + alpha * alpha);
    b.smallest_slip = std::min(b.smallest_slip, slip[0]);
  }
  return b;
}

// With friction the same method of multipliers, the friction term in its inner problems, rescues a solve that
// stops short: the block of TrescaFrictionOfASlidingBlockIsItsBound dragged on the plane, with the second family
// of rows between its bottom nodes (on a plane, exact combinations of the nodes' rows), its interior point cut
// at 10 iterations where it needs 13. The rescued answer meets the friction law's closed form as the full solve
// does, and the full solve's displacements to its tolerance.
TEST(ContactInteriorPoint, RescuesAFrictionalSolveOnNearlyDependentRows) {
  const double tau = 0.002, alpha = 1e-4;
  const int dim = 2;
  const ObstacleSystem o = with_rows_between_nodes(
      block_on_plane_system(dim, 24, 0.01, 0.05, tau, alpha, g_petsc->rank(), g_petsc->size()), 0.0);
  const ObstacleSystem whole = with_rows_between_nodes(block_on_plane_system(dim, 24, 0.01, 0.05, tau, alpha), 0.0);
  const ContactInteriorPointResult full = solve(o);
  ASSERT_TRUE(full.converged) << full.reason;
  ContactInteriorPointOptions cut;
  cut.max_iterations = 10;
  ASSERT_GT(full.iterations, cut.max_iterations);
  const ContactInteriorPointResult r = solve(o, cut);
  ASSERT_TRUE(r.converged) << r.reason;
  EXPECT_EQ(r.inequality_polishes, 1);
  const auto [reaction, friction, smallest_slip] = drag_balance(whole, dim, r.u, alpha);
  const double u_change = (r.u - full.u).lpNorm<Eigen::Infinity>() / full.u.lpNorm<Eigen::Infinity>();
  if (g_petsc->rank() == 0)
    std::printf("%d iterations (%d on the inequalities) against %d: top reaction along x %.9f, friction forces "
                "%.9f, bound %.9f; u %.1e from the full solve's\n", r.iterations, r.inequality_polishes,
                full.iterations, reaction, friction, tau, u_change);
  EXPECT_NEAR(reaction, friction, 1e-6 * tau);
  EXPECT_LE(reaction, tau);
  EXPECT_GE(reaction, (1 - 1e-5) * tau);
  EXPECT_GE((whole.contact.rows * r.u - whole.contact.lower).minCoeff(), -cut.tolerance * r.length_scale);
  EXPECT_GE(r.lambda.minCoeff(), 0.0);
  EXPECT_LE(u_change, 1e-7);
}

int largest(const std::vector<int>& v) { return *std::max_element(v.begin(), v.end()); }

// With the filter, the largest CG iteration count of a Newton system stays within ±30 % of its mean as the
// cube is refined from 8 to 16 divisions (2.2e3 to 1.5e4 DOFs, 5 to 21 nodes in contact), down to the
// interior point's last iterations, where Σ spans ten orders of magnitude; GAMG alone needs more on the
// finest mesh.
TEST(ContactInteriorPoint, FilteringKeepsTheKrylovIterationsFlatUnderRefinement) {
  std::vector<int> its;
  ContactInteriorPointResult r;
  for (const int n : {8, 12, 16}) {
    r = solve(block_on_ball_system(3, n, 1.0, 0.02, g_petsc->rank(), g_petsc->size()));
    ASSERT_TRUE(r.converged) << r.reason;
    its.push_back(largest(r.krylov_iterations));
  }
  const double mean = std::accumulate(its.begin(), its.end(), 0.0) / static_cast<double>(its.size());
  for (const int i : its) EXPECT_NEAR(i, mean, 0.3 * mean);
  ContactInteriorPointOptions alone;
  alone.preconditioner = NewtonPreconditioner::kGamg;
  const ContactInteriorPointResult a = solve(block_on_ball_system(3, 16, 1.0, 0.02, g_petsc->rank(), g_petsc->size()), alone);
  if (g_petsc->rank() == 0)
    std::printf("largest CG iterations per Newton system, 8, 12, 16 divisions: %d, %d, %d; GAMG alone at 16: %d\n",
                its[0], its[1], its[2], a.krylov_iterations.empty() ? 0 : largest(a.krylov_iterations));
  ASSERT_FALSE(a.krylov_iterations.empty());
  EXPECT_GT(largest(a.krylov_iterations), its.back());
  EXPECT_LE((a.u - r.u).lpNorm<Eigen::Infinity>(), 1e-7 * r.u.lpNorm<Eigen::Infinity>()) << "the same answer";
}

// Regularised Tresca friction: the block pressed on a rigid plane and dragged by 0.05 along x, far past the
// stick limit τ H / G ≈ 0.005, slides at every bottom node (slip ≫ α). The reaction of its top along x equals
// the friction forces' sum Σ g_j s_x / √(|s|² + α²) (equilibrium and the friction law) and, in 2D, the bound
// τ × the face's length up to α² / 2 |s|²; in 3D the bottom also slides sideways by the Poisson effect,
// which takes 0.02–0.03 % of the force off the x axis.
TEST(ContactInteriorPoint, TrescaFrictionOfASlidingBlockIsItsBound) {
  const double tau = 0.002, alpha = 1e-4;
  for (const auto& [dim, n] : {std::pair{2, 24}, std::pair{3, 8}}) {
    const ObstacleSystem o = block_on_plane_system(dim, n, 0.01, 0.05, tau, alpha, g_petsc->rank(), g_petsc->size());
    const ObstacleSystem whole = block_on_plane_system(dim, n, 0.01, 0.05, tau, alpha);
    const ContactInteriorPointResult r = solve(o);
    ASSERT_TRUE(r.converged) << r.reason;
    const auto [reaction, friction, smallest_slip] = drag_balance(whole, dim, r.u, alpha);
    if (g_petsc->rank() == 0)
      std::printf("dim %d: %d iterations, top reaction along x %.9f, friction forces %.9f, bound %.9f, smallest "
                  "slip %.2e\n", dim, r.iterations, reaction, friction, tau, smallest_slip);
    EXPECT_GT(smallest_slip, 100 * alpha) << "every node slides forward";
    EXPECT_NEAR(reaction, friction, 1e-6 * tau);
    EXPECT_LE(reaction, tau);
    EXPECT_GE(reaction, (dim == 2 ? 1 - 1e-5 : 0.999) * tau);
  }
}

// The same block dragged by 0.002, below the stick limit: its bottom sticks but near the edges, where the
// Poisson effect makes it slip outward. With α down to 10⁻⁷ of the element size, each sticking node is a
// spring g/α that Newton's steps must leave within α, and a node that slips at an iterate and sticks at the
// answer had a curvature g α²/r³ along its slip: the exact Hessian's steps were (r/α)² too long there and the
// line search cut them (50 and 78 iterations at α = 10⁻⁵ h and 10⁻⁷ h). With the primal-dual linearisation
// of the friction law: at most 30, the friction forces balancing the top's reaction, which converges as α falls.
TEST(ContactInteriorPoint, ABlockThatSticksConvergesAsTheRegularisationFalls) {
  const double tau = 0.002, shift = 0.002;
  const int dim = 2, n = 24;
  ContactInteriorPointOptions options;
  options.max_iterations = 30;
  std::vector<double> reactions;
  for (const double alpha_over_h : {1e-5, 1e-7}) {
    const double alpha = alpha_over_h / n;
    const ObstacleSystem o =
        block_on_plane_system(dim, n, 0.01, shift, tau, alpha, g_petsc->rank(), g_petsc->size());
    const ObstacleSystem whole = block_on_plane_system(dim, n, 0.01, shift, tau, alpha);
    const ContactInteriorPointResult r = solve(o, options);
    ASSERT_TRUE(r.converged) << "alpha = " << alpha_over_h << " h: " << r.reason;
    const auto [reaction, friction, smallest_slip] = drag_balance(whole, dim, r.u, alpha);
    if (g_petsc->rank() == 0)
      std::printf("alpha = %.0e h: %d iterations, top reaction along x %.9f, friction forces %.9f, bound %.6f\n",
                  alpha_over_h, r.iterations, reaction, friction, tau);
    EXPECT_NEAR(reaction, friction, 1e-6 * tau);
    EXPECT_LT(reaction, 0.5 * tau) << "most of the bottom sticks";
    reactions.push_back(reaction);
  }
  EXPECT_NEAR(reactions[1], reactions[0], 1e-4 * reactions[0]);
}

// The slip measured by a slip map (NodalConstraints::slip_map, here for the same sliding block): each node's
// displacement written as a map explicitly, and again against a frame that moves with the dragged top (one of
// its fixed DOFs, along x, minus the shift d: that column moves into the slip origin, which then holds −d).
// Both describe the same energy as the nodes' own displacements: the same answer to the solver's tolerance.
TEST(ContactInteriorPoint, ASlipMapGivesTheNodalFrictionItDescribes) {
  const double tau = 0.002, alpha = 1e-4;
  for (const auto& [dim, n] : {std::pair{2, 24}, std::pair{3, 8}}) {
    const ObstacleSystem o = block_on_plane_system(dim, n, 0.01, 0.05, tau, alpha, g_petsc->rank(), g_petsc->size());
    const ContactInteriorPointResult nodal = solve(o);
    ASSERT_TRUE(nodal.converged) << nodal.reason;
    const Index num_dofs = o.block.f.size(), m = o.contact.size();
    Index dragged = -1;  // a fixed DOF along x with a nonzero value: the top's drag
    double shift = 0.0;
    for (std::size_t k = 0; k < o.block.fixed.size() && dragged < 0; ++k)
      if (o.block.fixed[k] % dim == 0 && o.block.fixed_values[static_cast<Index>(k)] != 0.0) {
        dragged = o.block.fixed[k];
        shift = o.block.fixed_values[static_cast<Index>(k)];
      }
    ASSERT_GE(dragged, 0);
    for (const bool moving_frame : {false, true}) {
      ObstacleSystem mapped = o;
      std::vector<Eigen::Triplet<double>> t;
      mapped.contact.slip_origin = Eigen::MatrixXd::Zero(dim, m);
      for (Index j = 0; j < m; ++j)
        for (int k = 0; k < dim; ++k)
          t.emplace_back(static_cast<int>(dim * j + k), static_cast<int>(dim * o.contact.node[j] + k), 1.0);
      if (moving_frame)
        for (Index j = 0; j < m; ++j) {
          t.emplace_back(static_cast<int>(dim * j), static_cast<int>(dragged), -1.0);
          mapped.contact.slip_origin(0, j) = -shift;
        }
      mapped.contact.slip_map.resize(dim * m, num_dofs);
      mapped.contact.slip_map.setFromTriplets(t.begin(), t.end());
      const ContactInteriorPointResult r = solve(mapped);
      ASSERT_TRUE(r.converged) << r.reason;
      const double difference = (r.u - nodal.u).lpNorm<Eigen::Infinity>() / nodal.u.lpNorm<Eigen::Infinity>();
      if (g_petsc->rank() == 0)
        std::printf("dim %d, %s: %d iterations against %d, largest difference in u %.1e of its scale\n", dim,
                    moving_frame ? "against the dragged top" : "the nodes' own map", r.iterations, nodal.iterations,
                    difference);
      EXPECT_LT(difference, 1e-7);
      EXPECT_LT((r.lambda - nodal.lambda).lpNorm<Eigen::Infinity>(), 1e-7 * nodal.lambda.lpNorm<Eigen::Infinity>());
    }
  }
}

// Coulomb friction as a fixed point of Tresca solves (VALIDATION.md, V4's gross-slip limit): the same sliding
// block with μ = 0.2; its top's reactions satisfy R_x = μ R_n, in 2D to the regularisation and the fixed
// point's tolerance, in 3D less the sideways share of the friction force (as above).
TEST(ContactInteriorPoint, CoulombFrictionOfASlidingBlockIsMuTimesTheNormalForce) {
  const double mu = 0.2, alpha = 1e-4;
  for (const auto& [dim, n] : {std::pair{2, 24}, std::pair{3, 8}}) {
    const ObstacleSystem o = block_on_plane_system(dim, n, 0.01, 0.05, 0.0, alpha, g_petsc->rank(), g_petsc->size());
    const ObstacleSystem whole = block_on_plane_system(dim, n, 0.01, 0.05, 0.0, alpha);
    const BlockSystem& b = o.block;
    const CoulombInteriorPointResult c =
        solve_coulomb_interior_point(b.K_lower, b.f, b.fixed, b.fixed_values, b.mesh.x, o.contact, mu);
    ASSERT_TRUE(c.converged) << c.last.reason << ", bound change " << c.bound_change;
    const VectorXd residual =
        SparseMatrix(whole.block.K_lower.selfadjointView<Eigen::Lower>()) * c.last.u - whole.block.f;
    double tangential = 0.0, normal = 0.0;
    for (const Index v : whole.block.mesh.group_nodes(dim == 2 ? "top" : "zmax")) {
      tangential += residual[dim * v];
      normal -= residual[dim * v + dim - 1];
    }
    if (g_petsc->rank() == 0)
      std::printf("dim %d: %d Tresca solves, %d interior-point iterations; R_x / R_n = %.9f, R_n / Σλ − 1 = %.1e\n",
                  dim, c.coulomb_iterations, c.all.iterations, tangential / normal,
                  normal / c.last.lambda.sum() - 1);
    EXPECT_NEAR(normal, c.last.lambda.sum(), 1e-8 * normal);
    EXPECT_LE(tangential / normal, mu * (1 + 1e-6));
    EXPECT_GE(tangential / normal, mu * (dim == 2 ? 1 - 1e-5 : 0.999));
  }
}

}  // namespace
}  // namespace symcontact
