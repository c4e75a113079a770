// solve_on_set (solvers/equality_constrained_solve.hpp) with a StartFactor shared by solves on different sets
// from the same point, as the rounds of the active-set polish do: min ½ xᵀH x − tᵀx subject to A_S x = 0 for a
// full 5 × 5 H, dense as the condensed problem's. The answer of each set is known in closed form (the KKT
// system solved densely); the shared factor of H must give it as the solve's own factor of H + ρ A_SᵀA_S does.
#include <gtest/gtest.h>
#include <Eigen/Dense>

#include <cmath>

#include "symcontact/solvers/equality_constrained_solve.hpp"

using namespace symcontact;

namespace {

/// ½ xᵀH x − tᵀx with H = RᵀR + shift·I, R 5 × 5 of full rank, or of rank 2 if `singular` (H then singular for
/// shift = 0, but definite on the null space of the three rows: the KKT system is regular); constraint rows:
/// three independent ones.
class DenseQuadratic : public ConstrainedProblem {
 public:
  DenseQuadratic(double shift, bool singular) {
    const Index n = 5;
    MatrixXd R(n, n);
    for (Index i = 0; i < n; ++i)
      for (Index j = 0; j < n; ++j) R(i, j) = std::cos(0.7 + 2.0 * i + 5.0 * j);
    if (singular) R.bottomRows(n - 2).setZero();
    H_ = R.transpose() * R + shift * MatrixXd::Identity(n, n);
    t_ = VectorXd::LinSpaced(n, 1.0, -1.0);
    MatrixXd A(3, n);
    for (Index i = 0; i < 3; ++i)
      for (Index j = 0; j < n; ++j) A(i, j) = std::sin(1.0 + i + 1.3 * (i + 1) * j);
    A_ = A.sparseView();
    b_ = VectorXd::Zero(3);
  }
  Index num_variables() const override { return H_.rows(); }
  double objective(const VectorXd& x) override { return 0.5 * x.dot(H_ * x) - t_.dot(x); }
  void gradient(const VectorXd& x, VectorXd& g) override { g = H_ * x - t_; }
  void hessian_lower(const VectorXd&, SparseMatrix& H) override {
    const SparseMatrix full = H_.sparseView();
    H = full.triangularView<Eigen::Lower>();
  }
  void add_hessian_lower(const VectorXd&, double s, Eigen::Ref<MatrixXd> M) override {
    M.triangularView<Eigen::Lower>() += s * H_;
  }
  bool hessian_is_constant() const override { return true; }
  bool hessian_is_dense() const override { return true; }
  const SparseMatrix& constraint_matrix() const override { return A_; }
  const VectorXd& constraint_offset() const override { return b_; }
  /// The rows `rows` of A, and the exact minimiser on them from the full KKT system.
  SparseMatrix rows(std::initializer_list<int> rows) const {
    MatrixXd A(rows.size(), H_.rows());
    int k = 0;
    for (int r : rows) A.row(k++) = MatrixXd(A_).row(r);
    return A.sparseView();
  }
  VectorXd exact(const SparseMatrix& AS) const {
    const Index n = H_.rows(), m = AS.rows();
    MatrixXd K = MatrixXd::Zero(n + m, n + m);
    K.topLeftCorner(n, n) = H_;
    K.topRightCorner(n, m) = MatrixXd(AS).transpose();
    K.bottomLeftCorner(m, n) = MatrixXd(AS);
    VectorXd r = VectorXd::Zero(n + m);
    r.head(n) = t_;
    return K.fullPivLu().solve(r).head(n);
  }

 private:
  MatrixXd H_;
  VectorXd t_, b_;
  SparseMatrix A_;
};

}  // namespace

// Two sets from the same x: the first solve factorises H(x) into the StartFactor, the second uses that same
// factor (not a new one), and both reach each set's exact minimiser.
TEST(EqualityConstrainedSolve, SolvesFromOnePointShareTheFactorOfTheHessian) {
  DenseQuadratic p(0.5, false);
  const VectorXd x0 = VectorXd::Constant(5, 0.1);
  StartFactor start;
  const AlignedMatrix* first = nullptr;
  for (const SparseMatrix& AS : {p.rows({0, 1, 2}), p.rows({0, 2})}) {
    VectorXd x = x0, nu = VectorXd::Zero(AS.rows());
    int iterations = 0;
    ASSERT_TRUE(solve_on_set(p, AS, VectorXd::Zero(AS.rows()), x, nu, iterations, true, &start));
    ASSERT_TRUE(start.tried);
    ASSERT_NE(start.L, nullptr) << "H is definite: its factor is kept";
    if (!first) first = start.L.get();
    EXPECT_EQ(start.L.get(), first) << "the second set reuses the first one's factor";
    EXPECT_EQ(iterations, 1);
    EXPECT_LT((x - p.exact(AS)).lpNorm<Eigen::Infinity>(), 1e-12);
  }
}

// A singular H (a body held by its constraints alone): no shared factor is kept, and each solve factorises
// H + ρ A_SᵀA_S of its own set, as without one: the same exact minimiser.
TEST(EqualityConstrainedSolve, ASingularHessianIsNotSharedAndEachSetIsStillSolved) {
  DenseQuadratic p(0.0, true);
  const SparseMatrix AS = p.rows({0, 1, 2});
  StartFactor start;
  VectorXd x = VectorXd::Constant(5, 0.1), nu = VectorXd::Zero(3);
  int iterations = 0;
  ASSERT_TRUE(solve_on_set(p, AS, VectorXd::Zero(3), x, nu, iterations, true, &start));
  EXPECT_TRUE(start.tried);
  EXPECT_EQ(start.L, nullptr);
  EXPECT_LT((x - p.exact(AS)).lpNorm<Eigen::Infinity>(), 1e-10);
}
