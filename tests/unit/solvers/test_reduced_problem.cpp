// Tests of the problem on the free DOFs (src/symcontact/solvers/reduced_problem.hpp): u = P x + u_D with the
// Dirichlet values imposed, restrict()/expand() inverse to each other, and the objective, gradient, Hessian
// and constraints those of the full problem seen through P.

#include "symcontact/solvers/reduced_problem.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <memory>

#include "support/quadratic_energy.hpp"
#include "symcontact/energy/energy_sum.hpp"

namespace symcontact {
namespace {

using testing::grid_laplacian;
using testing::QuadraticEnergy;

/// A 3 × 3 grid Laplacian (9 DOFs, shifted to be definite), DOFs 1, 4 and 8 fixed; DOF 1 is named twice and
/// keeps the last value.
struct SmallProblem {
  SparseMatrix k = grid_laplacian(3, 0.1);
  QuadraticEnergy energy{k, VectorXd::LinSpaced(9, 1.0, -1.0)};
  FixedDofs fixed;
  SmallProblem() {
    fixed.fix(1, 0.5);
    fixed.fix(4, -2.0);
    fixed.fix(8, 0.25);
    fixed.fix(1, 0.75);
  }
};

const std::vector<Index> kFreeDofs = {0, 2, 3, 5, 6, 7};

TEST(ReducedProblem, RestrictAndExpandRoundTripWithTheFixedValuesImposed) {
  SmallProblem p;
  ReducedProblem r(p.energy, p.fixed, 9);
  ASSERT_EQ(r.num_free(), 6);
  EXPECT_EQ(r.num_variables(), 6);
  for (Index k = 0; k < 6; ++k) EXPECT_EQ(r.free_index()[kFreeDofs[k]], k);
  for (Index d : {1, 4, 8}) EXPECT_EQ(r.free_index()[d], -1);

  const VectorXd x = VectorXd::LinSpaced(6, -3.0, 2.0);
  const VectorXd u = r.expand(x);
  ASSERT_EQ(u.size(), 9);
  for (Index k = 0; k < 6; ++k) EXPECT_EQ(u[kFreeDofs[k]], x[k]);
  EXPECT_EQ(u[1], 0.75);  // the last value given
  EXPECT_EQ(u[4], -2.0);
  EXPECT_EQ(u[8], 0.25);
  EXPECT_EQ(r.restrict(u), x);
  // The other way: the free entries of any u survive, its fixed entries are replaced by the values.
  const VectorXd v = VectorXd::LinSpaced(9, 10.0, 18.0);
  const VectorXd w = r.expand(r.restrict(v));
  for (Index d : kFreeDofs) EXPECT_EQ(w[d], v[d]);
  EXPECT_EQ(w[1], 0.75);
}

TEST(ReducedProblem, ObjectiveGradientAndHessianAreTheFullOnesThroughP) {
  SmallProblem p;
  ReducedProblem r(p.energy, p.fixed, 9);
  const VectorXd x = VectorXd::LinSpaced(6, 0.3, -0.8);
  const VectorXd u = r.expand(x);
  EXPECT_DOUBLE_EQ(r.objective(x), p.energy.value(u));
  VectorXd g_full = VectorXd::Zero(9), g;
  p.energy.add_gradient(u, g_full);
  r.gradient(x, g);
  ASSERT_EQ(g.size(), 6);
  for (Index k = 0; k < 6; ++k) EXPECT_DOUBLE_EQ(g[k], g_full[kFreeDofs[k]]);
  // ∇²f = K_ff: the free rows and columns of K, lower triangle.
  const MatrixXd k = MatrixXd(p.k).selfadjointView<Eigen::Lower>();
  SparseMatrix h;
  r.hessian_lower(x, h);
  ASSERT_EQ(h.rows(), 6);
  const MatrixXd hd = MatrixXd(h);
  for (Index i = 0; i < 6; ++i)
    for (Index j = 0; j < 6; ++j) EXPECT_DOUBLE_EQ(hd(i, j), j <= i ? k(kFreeDofs[i], kFreeDofs[j]) : 0.0);
  EXPECT_TRUE(r.hessian_is_constant());
  SparseMatrix again;
  r.hessian_lower(-x, again);  // constant: the same matrix at any x
  EXPECT_EQ(MatrixXd(again), hd);
}

TEST(ReducedProblem, ConstraintsMoveTheFixedColumnsIntoTheOffset) {
  SmallProblem p;
  ReducedProblem r(p.energy, p.fixed, 9);
  EXPECT_EQ(r.constraint_matrix().rows(), 0);  // none until set
  EXPECT_EQ(r.constraint_matrix().cols(), 6);
  // Two constraints on full DOFs, touching free and fixed ones.
  std::vector<Triplet> t = {{0, 0, 1.0}, {0, 1, -2.0}, {1, 4, 3.0}, {1, 7, 0.5}, {1, 8, -1.0}};
  SparseMatrix a(2, 9);
  a.setFromTriplets(t.begin(), t.end());
  const VectorXd b = (VectorXd(2) << 0.1, -0.2).finished();
  r.set_constraints(a, b);
  ASSERT_EQ(r.constraint_matrix().rows(), 2);
  ASSERT_EQ(r.constraint_matrix().cols(), 6);
  // (A P) x + (b + A u_D) = A (P x + u_D) + b for every x.
  for (const VectorXd& x : {VectorXd::Zero(6).eval(), VectorXd::LinSpaced(6, -1.0, 4.0).eval()}) {
    const VectorXd reduced = r.constraint_matrix() * x + r.constraint_offset();
    const VectorXd full = a * r.expand(x) + b;
    EXPECT_NEAR((reduced - full).lpNorm<Eigen::Infinity>(), 0.0, 1e-14);
  }
  // b + A u_D: 0.1 − 2 · 0.75 and −0.2 + 3 · (−2) − 0.25.
  EXPECT_DOUBLE_EQ(r.constraint_offset()[0], 0.1 - 1.5);
  EXPECT_DOUBLE_EQ(r.constraint_offset()[1], -0.2 - 6.0 - 0.25);
}

// split_energy: the constant part's quadratic form (its value and gradient at 0, its cached Hessian) plus the rest
// evaluated at x is the whole energy (the geometry subproblem's bodies plus friction terms): the same objective,
// gradient and Hessian at every call.
TEST(ReducedProblem, ASplitEnergyIsTheWholeOne) {
  SmallProblem p;
  const SparseMatrix k_rest = 0.3 * grid_laplacian(3, 1.0);
  EnergySum whole;
  whole.add(std::make_unique<QuadraticEnergy>(p.k, VectorXd::LinSpaced(9, 1.0, -1.0)));
  const QuadraticEnergy* rest =
      whole.add(std::make_unique<QuadraticEnergy>(k_rest, VectorXd::LinSpaced(9, -0.5, 2.0)));
  ReducedProblem unsplit(whole, p.fixed, 9), split(whole, p.fixed, 9), constant(p.energy, p.fixed, 9);
  split.split_energy(constant, {[rest](const VectorXd& u) { return rest->value(u); },
                                [rest](const VectorXd& u, VectorXd& g) { rest->add_gradient(u, g); },
                                [rest](const VectorXd& u, MatrixSink& sink) { rest->add_hessian(u, sink); }});
  SparseMatrix h_unsplit, h_split;
  VectorXd g_unsplit, g_split;
  for (const double s : {0.0, 1.0, -3.0}) {
    const VectorXd x = s * VectorXd::LinSpaced(6, -1.0, 1.0);
    EXPECT_NEAR(split.objective(x), unsplit.objective(x), 1e-14 * std::max(1.0, std::abs(unsplit.objective(x))));
    unsplit.gradient(x, g_unsplit);
    split.gradient(x, g_split);
    EXPECT_LT((g_split - g_unsplit).lpNorm<Eigen::Infinity>(), 1e-14 * std::max(1.0, g_unsplit.lpNorm<Eigen::Infinity>()));
    unsplit.hessian_lower(x, h_unsplit);
    split.hessian_lower(x, h_split);
    EXPECT_EQ(h_split.nonZeros(), h_unsplit.nonZeros());
    EXPECT_LT((MatrixXd(h_split) - MatrixXd(h_unsplit)).cwiseAbs().maxCoeff(), 1e-14);
    EXPECT_GT(MatrixXd(h_split).cwiseAbs().maxCoeff(), 0.0);
  }
  EXPECT_GT(g_unsplit.lpNorm<Eigen::Infinity>(), 1.0);  // the loads and the fixed values make it non-trivial
}

}  // namespace
}  // namespace symcontact
