// The active-set polish (solvers/active_set_polish.hpp) on a small quadratic problem with a known answer:
//   min ½ |x − t|²,  t = (−1, −1, 1),  subject to x ≥ 0  (A = I, b = 0),
// whose solution is x = (0, 0, 1) with multipliers μ = (1, 1, 0). The polish is handed the kind of
// interior point IPOPT leaves: every active constraint open by a barrier offset, and multipliers that
// misjudge the active set in either direction.
#include <gtest/gtest.h>

#include "symcontact/solvers/active_set_polish.hpp"

using namespace symcontact;

namespace {

class Projection : public ConstrainedProblem {
 public:
  Projection() : t_(3), b_(VectorXd::Zero(3)) {
    t_ << -1.0, -1.0, 1.0;
    A_.resize(3, 3);
    A_.setIdentity();
  }
  Index num_variables() const override { return 3; }
  double objective(const VectorXd& x) override { return 0.5 * (x - t_).squaredNorm(); }
  void gradient(const VectorXd& x, VectorXd& g) override { g = x - t_; }
  void hessian_lower(const VectorXd&, SparseMatrix& H) override {
    H.resize(3, 3);
    H.setIdentity();
  }
  bool hessian_is_constant() const override { return true; }
  const SparseMatrix& constraint_matrix() const override { return A_; }
  const VectorXd& constraint_offset() const override { return b_; }

 private:
  VectorXd t_, b_;
  SparseMatrix A_;
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
