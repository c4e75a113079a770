// The active-set polish (solvers/active_set_polish.hpp) on a small quadratic problem with a known answer:
//   min ½ |x − t|²,  t = (−1, −1, 1),  subject to x ≥ 0  (A = I, b = 0),
// whose solution is x = (0, 0, 1) with multipliers μ = (1, 1, 0). The polish is handed the kind of
// interior point IPOPT leaves: every active constraint open by a barrier offset, and multipliers that
// misjudge the active set in either direction.
#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "symcontact/solvers/active_set_polish.hpp"

using namespace symcontact;

namespace {

/// min ½ |x − t|² subject to A x ≥ 0, A = I unless given (extra rows below the identity); `dense` only changes the
/// hint hessian_is_dense(), i.e. which factorisation the polish uses.
class Projection : public ConstrainedProblem {
 public:
  explicit Projection(const VectorXd& t = Eigen::Vector3d(-1.0, -1.0, 1.0),
                      const MatrixXd& A = MatrixXd::Identity(3, 3), bool dense = false)
      : t_(t), b_(VectorXd::Zero(A.rows())), A_(A.sparseView()), dense_(dense) {}
  Index num_variables() const override { return 3; }
  double objective(const VectorXd& x) override { return 0.5 * (x - t_).squaredNorm(); }
  void gradient(const VectorXd& x, VectorXd& g) override { g = x - t_; }
  void hessian_lower(const VectorXd&, SparseMatrix& H) override {
    H.resize(3, 3);
    H.setIdentity();
  }
  bool hessian_is_constant() const override { return true; }
  bool hessian_is_dense() const override { return dense_; }
  const SparseMatrix& constraint_matrix() const override { return A_; }
  const VectorXd& constraint_offset() const override { return b_; }

 private:
  VectorXd t_, b_;
  SparseMatrix A_;
  bool dense_;
};

void expect_exact_solution(const VectorXd& x, const VectorXd& mu) {
  EXPECT_NEAR(x[0], 0.0, 1e-12);
  EXPECT_NEAR(x[1], 0.0, 1e-12);
  EXPECT_NEAR(x[2], 1.0, 1e-12);
  EXPECT_NEAR(mu[0], 1.0, 1e-10);
  EXPECT_NEAR(mu[1], 1.0, 1e-10);
  EXPECT_EQ(mu[2], 0.0);
}

}  // namespace

// Constraint 1 is active but its multiplier is tiny (what a warm-started IPOPT solve leaves for a
// constraint that was open at the previous geometry iteration): closing constraint 0 alone violates it,
// so it must join the active set (primal-dual active set update) rather than the polish give up.
TEST(ActiveSetPolish, AViolatedConstraintWithATinyMultiplierJoinsTheActiveSet) {
  Projection p;
  VectorXd x(3), mu(3);
  x << 1e-9, 1e-9, 1.0;
  mu << 1.0, 1e-12, 1e-9;
  const PolishResult r = polish_active_set(p, x, mu);
  ASSERT_TRUE(r.applied) << r.reason;
  EXPECT_EQ(r.active, 2);
  expect_exact_solution(x, mu);
}

// Constraint 2 is open but its multiplier is above the threshold: the solve on the set would pull it
// (negative multiplier), so it leaves the set.
TEST(ActiveSetPolish, AConstraintThatWouldPullLeavesTheActiveSet) {
  Projection p;
  VectorXd x(3), mu(3);
  x << 1e-9, 1e-9, 1.0;
  mu << 1.0, 1.0, 1e-3;
  const PolishResult r = polish_active_set(p, x, mu);
  ASSERT_TRUE(r.applied) << r.reason;
  EXPECT_EQ(r.active, 2);
  expect_exact_solution(x, mu);
}

// No constraint is closed (t = (1, 2, 1) is feasible), and the interior point left the barrier's multipliers
// μ_i ≈ μ_b / c_i on all of them: compared with each other they all look active, but every gap is open by far
// more than a barrier offset. Balancing forces holds none of them, and their multipliers become 0.
TEST(ActiveSetPolish, BalancingForcesDropsTheBarrierMultipliersOfOpenRows) {
  Projection p(Eigen::Vector3d(1.0, 2.0, 1.0));
  VectorXd x(3), mu(3);
  x << 1.0 + 1e-9, 2.0 - 1e-9, 1.0;
  mu << 1e-9, 5e-10, 1e-9;
  const PolishResult r = polish_active_set(p, x, mu, PolishMode::kBalanceForces);
  ASSERT_TRUE(r.applied) << r.reason;
  EXPECT_EQ(r.active, 0);
  EXPECT_EQ(mu.lpNorm<Eigen::Infinity>(), 0.0);
  EXPECT_NEAR(x[0], 1.0, 1e-14);
  EXPECT_NEAR(x[1], 2.0, 1e-14);
}

namespace {

/// The projection above with a fourth row x₀ + ε x₁ ≥ 0 nearly dependent on row 0 (as the two families of a
/// symmetric pair are), consistent: both rows are closed at the answer x = (0, 0, 1), whose force Aᵀμ =
/// x − t = (1, 1, 0) they share in a split that only ε fixes. Dense, as the condensed problem.
Projection nearly_dependent_rows(double eps) {
  MatrixXd A = MatrixXd::Zero(4, 3);
  A.topRows(3).setIdentity();
  A(3, 0) = 1.0;
  A(3, 1) = eps;
  return Projection(Eigen::Vector3d(-1.0, -1.0, 1.0), A, true);
}

}  // namespace

// The closing's first set holds the two nearly dependent rows and row 2, open, with a multiplier that would
// pull. The method of multipliers solves each set in several iterations (7 in all here; on the nearly dependent
// rows of the 3D plates of docs/performance.md thousands, its rate 1/(1 + ρσ²) with σ the rows' smallest
// singular value); the direct range-space solve tells row 2 to leave and closes the rest, one step per set, at
// the exact answer.
TEST(ActiveSetPolish, AClosingOnNearlyDependentRowsIsSolvedDirectly) {
  Projection p = nearly_dependent_rows(1e-5);
  VectorXd x(3), mu(4);
  x << 1e-9, 1e-9, 1.0;
  mu << 0.5, 1.0, 1e-3, 0.5;
  const PolishResult r = polish_active_set(p, x, mu);
  ASSERT_TRUE(r.applied) << r.reason;
  EXPECT_EQ(r.active, 3);
  EXPECT_EQ(r.iterations, 2);  // one direct step on each of the two sets
  EXPECT_NEAR(x[0], 0.0, 1e-12);
  EXPECT_NEAR(x[1], 0.0, 1e-12);
  EXPECT_NEAR(x[2], 1.0, 1e-12);
  EXPECT_EQ(mu[2], 0.0);
  const VectorXd force = p.constraint_matrix().transpose() * mu;
  EXPECT_NEAR(force[0], 1.0, 1e-10);
  EXPECT_NEAR(force[1], 1.0, 1e-10);
  EXPECT_NEAR(force[2], 0.0, 1e-10);
}

namespace {

/// min ½ xᵀH x − tᵀx subject to A x + b ≥ 0, H symmetric positive definite and full (6 × 6), A with two
/// dependent rows (the second twice the first, as the two families of a symmetric pair nearly are);
/// `dense` only changes the hint hessian_is_dense(), i.e. which factorisation the polish uses.
class FullQuadratic : public ConstrainedProblem {
 public:
  explicit FullQuadratic(bool dense) : dense_(dense) {
    const Index n = 6;
    MatrixXd R(n, n);
    for (Index i = 0; i < n; ++i)
      for (Index j = 0; j < n; ++j) R(i, j) = std::sin(1.0 + 3.0 * i + 7.0 * j);
    const MatrixXd H = R.transpose() * R + MatrixXd::Identity(n, n);
    const SparseMatrix Hs = H.sparseView();
    H_ = Hs.triangularView<Eigen::Lower>();
    Hfull_ = H;
    VectorXd pull(n);  // the unconstrained minimiser, which violates rows 0 (and 1) and 2
    pull << -1.0, 1.0, 0.3, -1.0, -0.2, 0.1;
    t_ = H * pull;
    MatrixXd A = MatrixXd::Zero(3, n);
    A(0, 0) = 1.0;
    A(0, 1) = -0.5;
    A.row(1) = 2.0 * A.row(0);
    A(2, 3) = 1.0;
    A_ = A.sparseView();
    b_ = VectorXd::Zero(3);
  }
  Index num_variables() const override { return 6; }
  double objective(const VectorXd& x) override { return 0.5 * x.dot(Hfull_ * x) - t_.dot(x); }
  void gradient(const VectorXd& x, VectorXd& g) override { g = Hfull_ * x - t_; }
  void hessian_lower(const VectorXd&, SparseMatrix& H) override { H = H_; }
  bool hessian_is_constant() const override { return true; }
  bool hessian_is_dense() const override { return dense_; }
  const SparseMatrix& constraint_matrix() const override { return A_; }
  const VectorXd& constraint_offset() const override { return b_; }

 private:
  bool dense_;
  MatrixXd Hfull_;
  SparseMatrix H_, A_;
  VectorXd t_, b_;
};

}  // namespace

// The dense factorisation (multi-column range-space solve) and the sparse one (CHOLMOD, column by column)
// are the same algebra: the polished points and the contact forces Aᵀμ agree to round-off, for the closing
// polish (method of multipliers) and for the force-balancing one (range-space solve on dependent rows).
// Round-off here is ε times the condition of M = H + ρ A_SᵀA_S: ρ = 1e6 · mean|diag H| / max diag(A_SᵀA_S)
// in the method of multipliers, so 1e-9 relative there, 1e-12 in the direct solve (ρ balanced).
TEST(ActiveSetPolish, DenseAndSparseFactorisationsAgree) {
  for (const PolishMode mode : {PolishMode::kClose, PolishMode::kBalanceForces}) {
    VectorXd x0(6), mu0(3);
    x0 << 1e-7, 2e-7, 0.3, 1e-7, -0.2, 0.1;
    mu0 << 0.4, 0.3, 0.2;
    FullQuadratic sparse(false), dense(true);
    VectorXd xs = x0, ms = mu0, xd = x0, md = mu0;
    const PolishResult rs = polish_active_set(sparse, xs, ms, mode);
    const PolishResult rd = polish_active_set(dense, xd, md, mode);
    ASSERT_TRUE(rs.applied) << rs.reason;
    ASSERT_TRUE(rd.applied) << rd.reason;
    EXPECT_EQ(rs.active, rd.active);
    EXPECT_GT((xs - x0).lpNorm<Eigen::Infinity>(), 1e-8) << "the polish should have moved the point";
    const double tol = mode == PolishMode::kBalanceForces ? 1e-12 : 1e-9;
    EXPECT_LT((xs - xd).lpNorm<Eigen::Infinity>(), tol * xs.lpNorm<Eigen::Infinity>()) << "balance forces " << (mode == PolishMode::kBalanceForces);
    const SparseMatrix& A = sparse.constraint_matrix();
    const VectorXd fs = A.transpose() * ms, fd = A.transpose() * md;
    EXPECT_GT(fs.lpNorm<Eigen::Infinity>(), 0.1) << "the constraints should carry a force";
    EXPECT_LT((fs - fd).lpNorm<Eigen::Infinity>(), tol * fs.lpNorm<Eigen::Infinity>()) << "balance forces " << (mode == PolishMode::kBalanceForces);
  }
}

namespace {

/// A non-quadratic f with a sticking friction term: ½ xᵀH x − tᵀx + w Σ_{k=2,3} sqrt(x_k² + α²), α = 1e-6,
/// subject to x_0 ≥ 0. The unconstrained minimiser pulls x_0 below zero, and the quadratic part's force on
/// x_2, x_3 stays below w: they stick, x_k = O(α), where the term's curvature w/α is 1e6 times H's.
class StickingFriction : public ConstrainedProblem {
 public:
  StickingFriction() {
    H_.resize(4, 4);
    H_ << 2.0, 0.5, 0.3, 0.0, 0.5, 2.0, 0.0, 0.3, 0.3, 0.0, 2.0, 0.5, 0.0, 0.3, 0.5, 2.0;
    VectorXd pull(4);
    pull << -1.0, 0.5, 0.05, -0.05;
    t_ = H_ * pull;
    A_.resize(1, 4);
    A_.insert(0, 0) = 1.0;
    b_ = VectorXd::Zero(1);
  }
  Index num_variables() const override { return 4; }
  double objective(const VectorXd& x) override {
    return 0.5 * x.dot(H_ * x) - t_.dot(x) + kW * (std::hypot(x[2], kAlpha) + std::hypot(x[3], kAlpha));
  }
  void gradient(const VectorXd& x, VectorXd& g) override {
    g = H_ * x - t_;
    for (int k = 2; k < 4; ++k) g[k] += kW * x[k] / std::hypot(x[k], kAlpha);
  }
  void hessian_lower(const VectorXd& x, SparseMatrix& H) override {
    MatrixXd h = H_;
    for (int k = 2; k < 4; ++k) h(k, k) += kW * kAlpha * kAlpha / std::pow(std::hypot(x[k], kAlpha), 3);
    H = SparseMatrix(h.sparseView()).triangularView<Eigen::Lower>();
  }
  bool hessian_is_constant() const override { return false; }
  const SparseMatrix& constraint_matrix() const override { return A_; }
  const VectorXd& constraint_offset() const override { return b_; }

 private:
  static constexpr double kW = 1.0, kAlpha = 1e-6;
  MatrixXd H_;
  VectorXd t_, b_;
  SparseMatrix A_;
};

}  // namespace

// Closing the active set of a non-quadratic f whose friction term sticks, then balancing forces on the closed
// point (what the polish strategy does at the end of a fixed point): closed, and stationary to round-off
// (‖∇f − Aᵀμ‖∞ at the level of ε times the forces), which the closing alone is not: its method of multipliers
// has a ρ scaled by the friction curvature.
TEST(ActiveSetPolish, ClosingThenBalancingWithAStickingFrictionTermIsStationaryToRoundOff) {
  StickingFriction p;
  VectorXd x(4), mu(1);
  x << 1e-8, 0.4, 1e-9, -1e-9;  // an interior point's kind of answer: x_0 open by a barrier offset
  mu << 1.5;
  const PolishResult closed = polish_active_set(p, x, mu, PolishMode::kClose);
  ASSERT_TRUE(closed.applied) << closed.reason;
  EXPECT_EQ(closed.active, 1);
  EXPECT_LE(std::abs(x[0]), 1e-14);
  auto stationarity = [&] {
    VectorXd g;
    p.gradient(x, g);
    return (g - p.constraint_matrix().transpose() * mu).lpNorm<Eigen::Infinity>();
  };
  const double force = (p.constraint_matrix().transpose() * mu).lpNorm<Eigen::Infinity>();
  ASSERT_GT(force, 0.1);
  const double after_closing = stationarity();
  const PolishResult balanced = polish_active_set(p, x, mu, PolishMode::kBalanceForces);
  ASSERT_TRUE(balanced.applied) << balanced.reason;
  EXPECT_LE(std::abs(x[0]), 1e-14) << "the closed value is held";
  EXPECT_LE(stationarity(), 1e-13 * force);
  EXPECT_GT(after_closing, 10 * stationarity()) << "the balance is what brought it to round-off";
  EXPECT_LT(std::abs(x[2]), 1e-6);  // sticks
  EXPECT_LT(std::abs(x[3]), 1e-6);
}
