// Tests of the condensed problem (src/symcontact/solvers/condensed_problem.hpp) against dense linear algebra
// on a small quadratic problem with Dirichlet DOFs: F(y) is the full energy minimised over the interior, its
// Hessian the Schur complement, and the condensed minimiser expands to the full one. (The value, gradient
// and finite differences with a surface term: test_static_condensation.cpp.)

#include "symcontact/solvers/condensed_problem.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "support/quadratic_energy.hpp"

namespace symcontact {
namespace {

/// E = ½ uᵀK u − fᵀu on a 6 × 6 grid Laplacian (36 DOFs), held by two Dirichlet DOFs, condensed onto
/// eight of its 34 free DOFs; the dense blocks of K_ff for the references.
class CondensedProblemTest : public ::testing::Test {
 protected:
  CondensedProblemTest() {
    SparseMatrix kff;
    bulk_.hessian_lower(VectorXd::Zero(bulk_.num_free()), kff);
    sc_.compute(kff, boundary_);
    load_ = std::make_shared<const CondensedLoad>(condense_load(bulk_, sc_));
    k_ = MatrixXd(kff).selfadjointView<Eigen::Lower>();
    for (Index i = 0; i < bulk_.num_free(); ++i)
      if (std::find(boundary_.begin(), boundary_.end(), i) == boundary_.end()) interior_.push_back(i);
    bulk_.gradient(VectorXd::Zero(bulk_.num_free()), r0_);
  }
  MatrixXd block(const std::vector<Index>& rows, const std::vector<Index>& cols) const {
    MatrixXd s(rows.size(), cols.size());
    for (std::size_t i = 0; i < rows.size(); ++i)
      for (std::size_t j = 0; j < cols.size(); ++j) s(i, j) = k_(rows[i], cols[j]);
    return s;
  }
  VectorXd part(const VectorXd& v, const std::vector<Index>& index) const {
    VectorXd p(index.size());
    for (std::size_t i = 0; i < index.size(); ++i) p[i] = v[index[i]];
    return p;
  }
  static FixedDofs two_fixed() {
    FixedDofs f;
    f.fix(0, 0.1);
    f.fix(35, -0.3);
    return f;
  }
  CondensedProblem problem() {
    return CondensedProblem(bulk_, sc_, load_, {}, SparseMatrix(0, bulk_.num_free()), VectorXd(),
                            VectorXd::Zero(bulk_.num_free()));
  }

  testing::QuadraticEnergy energy_{testing::grid_laplacian(6, 0.0), VectorXd::LinSpaced(36, 0.4, -0.6)};
  FixedDofs fixed_ = two_fixed();
  ReducedProblem bulk_{energy_, fixed_, 36};
  std::vector<Index> boundary_ = {1, 4, 9, 15, 20, 22, 27, 33};  // free numbering, sorted
  std::vector<Index> interior_;
  StaticCondensation sc_;
  std::shared_ptr<const CondensedLoad> load_;
  MatrixXd k_;   ///< K_ff, dense
  VectorXd r0_;  ///< ∇f(0) on the free DOFs
};

TEST_F(CondensedProblemTest, ValueIsTheFullEnergyMinimisedOverTheInterior) {
  CondensedProblem cp = problem();
  ASSERT_EQ(cp.num_variables(), 8);
  const VectorXd y = VectorXd::LinSpaced(8, -0.5, 0.7);
  // Dense: x_I = −K_II⁻¹ (r₀_I + K_IB y), then F(y) = f(x).
  const VectorXd xi = -block(interior_, interior_).llt().solve(part(r0_, interior_) + block(interior_, boundary_) * y);
  VectorXd x = VectorXd::Zero(bulk_.num_free());
  for (std::size_t i = 0; i < interior_.size(); ++i) x[interior_[i]] = xi[i];
  for (std::size_t i = 0; i < boundary_.size(); ++i) x[boundary_[i]] = y[i];
  const double f_min = bulk_.objective(x);
  EXPECT_NEAR(cp.objective(y), f_min, 1e-12 * std::abs(f_min));
  // expand() is that interior; any other interior gives a larger energy.
  const VectorXd expanded = cp.expand(y);
  EXPECT_LT((expanded - x).lpNorm<Eigen::Infinity>(), 1e-12 * x.lpNorm<Eigen::Infinity>());
  for (int trial = 0; trial < 3; ++trial) {
    VectorXd other = x;
    for (Index i : interior_) other[i] += 1e-3 * std::sin(3.0 * i + trial);
    EXPECT_GT(bulk_.objective(other), f_min);
  }
}

TEST_F(CondensedProblemTest, HessianIsTheSchurComplementAndConstant) {
  CondensedProblem cp = problem();
  EXPECT_TRUE(cp.hessian_is_constant());  // no surface terms
  EXPECT_TRUE(cp.hessian_is_dense());
  SparseMatrix h;
  cp.hessian_lower(VectorXd::Zero(8), h);
  const MatrixXd s = MatrixXd(h).selfadjointView<Eigen::Lower>();
  const MatrixXd kib = block(interior_, boundary_);
  const MatrixXd s_ref = block(boundary_, boundary_) - kib.transpose() * block(interior_, interior_).llt().solve(kib);
  EXPECT_LT((s - s_ref).cwiseAbs().maxCoeff(), 1e-12 * s_ref.cwiseAbs().maxCoeff());
  // The gradient is affine with that Hessian and ĝ at y = 0.
  const VectorXd y = VectorXd::LinSpaced(8, 1.0, -1.0);
  VectorXd g0, g;
  cp.gradient(VectorXd::Zero(8), g0);
  cp.gradient(y, g);
  EXPECT_LT((g0 - cp.linear_term()).lpNorm<Eigen::Infinity>(), 1e-12 * g0.lpNorm<Eigen::Infinity>());
  EXPECT_LT((g - g0 - s_ref * y).lpNorm<Eigen::Infinity>(), 1e-12 * g.lpNorm<Eigen::Infinity>());
}

TEST_F(CondensedProblemTest, CondensedMinimiserExpandsToTheFullSolution) {
  CondensedProblem cp = problem();
  SparseMatrix h;
  cp.hessian_lower(VectorXd::Zero(8), h);
  const MatrixXd s = MatrixXd(h).selfadjointView<Eigen::Lower>();
  const VectorXd y = -s.llt().solve(cp.linear_term());  // S y + ĝ = 0
  const VectorXd x_full = -k_.llt().solve(r0_);          // K_ff x + r₀ = 0
  const VectorXd x = cp.expand(y);
  EXPECT_LT((x - x_full).lpNorm<Eigen::Infinity>(), 1e-11 * x_full.lpNorm<Eigen::Infinity>());
  EXPECT_EQ(cp.restrict(x), y);
  // The same through the free functions the contact solver uses, and back to all DOFs with u_D.
  EXPECT_LT((expand_condensed(sc_, *load_, y) - x).lpNorm<Eigen::Infinity>(), 1e-15 * x.lpNorm<Eigen::Infinity>());
  const VectorXd u = bulk_.expand(x);
  EXPECT_EQ(u[0], 0.1);
  EXPECT_EQ(u[35], -0.3);
  VectorXd g = VectorXd::Zero(36);
  energy_.add_gradient(u, g);
  EXPECT_LT(bulk_.restrict(g).lpNorm<Eigen::Infinity>(), 1e-11 * r0_.lpNorm<Eigen::Infinity>());
}

TEST_F(CondensedProblemTest, WithBoundaryReplacesOnlyTheBoundaryEntries) {
  CondensedProblem cp = problem();
  const VectorXd x = VectorXd::LinSpaced(bulk_.num_free(), 2.0, 5.0);
  const VectorXd y = VectorXd::LinSpaced(8, -1.0, -8.0);
  const VectorXd z = cp.with_boundary(x, y);
  EXPECT_EQ(cp.restrict(z), y);
  EXPECT_EQ(boundary_values(sc_, z), y);
  for (Index i : interior_) EXPECT_EQ(z[i], x[i]);
  EXPECT_EQ(with_boundary_values(sc_, x, y), z);
}

}  // namespace
}  // namespace symcontact
