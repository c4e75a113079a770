// The dense primal interior point for min f(x) s.t. A x + b ≥ 0 (solvers/dense_primal_interior_point.hpp), on
// random convex problems shaped like the condensed frictional subproblem: a dense positive definite quadratic
// plus regularised |x_k| terms (the friction term's sqrt(|v|² + α²)), and sparse rows. Checked against the KKT
// conditions and against IPOPT on the same problem, under a change of units, from a warm start, with the
// weight of the |x_k| terms following the iterate (FollowIterate), and on the failures it must report as
// failures.
#include <cmath>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "symcontact/optim/ipopt_solver.hpp"
#include "symcontact/solvers/dense_primal_interior_point.hpp"
#include "support/friction_like_problem.hpp"

using namespace symcontact;
using symcontact::testing::FrictionLikeProblem;
using symcontact::testing::followed_weights;
using symcontact::testing::kkt_violation;
using symcontact::testing::weights_follower;

TEST(DensePrimalInteriorPoint, MeetsTheKktConditionsAndAgreesWithIpopt) {
  for (const unsigned seed : {1u, 2u, 3u}) {
    FrictionLikeProblem p(40, 60, seed);
    const VectorXd x0 = VectorXd::Zero(40);
    const IpoptResult r = solve_dense_primal(p, x0, DensePrimalOptions{});
    ASSERT_TRUE(r.success) << r.status_text;
    EXPECT_LT(kkt_violation(p, r, 3.0, 1.0), 1e-8) << "seed " << seed;
    IpoptOptions o;
    const IpoptResult ip = solve_with_ipopt(p, x0, o);
    ASSERT_TRUE(ip.success) << ip.status_text;
    EXPECT_LT((r.x - ip.x).lpNorm<Eigen::Infinity>(), 1e-7 * ip.x.lpNorm<Eigen::Infinity>()) << "seed " << seed;
    EXPECT_LT((r.multipliers - ip.multipliers).lpNorm<Eigen::Infinity>(), 1e-7 * ip.multipliers.lpNorm<Eigen::Infinity>());
    EXPECT_NEAR(r.objective, p.objective(r.x), 0.0);
    // some rows active, some open: the test exercises both
    const VectorXd c = r.constraint_values;
    EXPECT_GT((c.array() < 1e-8).count(), 0);
    EXPECT_GT((c.array() > 1e-3).count(), 0);
  }
}

// A problem whose Hessian is not dense (ConstrainedProblem::hessian_is_dense() false: the uncondensed contact
// problem) is solved with CHOLMOD's factor of the normal matrix instead of LAPACK's: the same iterates up to
// round-off, so the same answer and about the same iteration count, with the thresholds following too.
TEST(DensePrimalInteriorPoint, TheSparsePathGivesTheDensePathsAnswer) {
  for (const unsigned seed : {1u, 2u, 3u}) {
    FrictionLikeProblem p(40, 60, seed);
    const VectorXd x0 = VectorXd::Zero(40);
    DensePrimalOptions o;
    o.tolerance = 1e-12;
    const IpoptResult dense = solve_dense_primal(p, x0, o);
    p.set_dense(false);
    const IpoptResult sparse = solve_dense_primal(p, x0, o);
    ASSERT_TRUE(dense.success) << dense.status_text;
    ASSERT_TRUE(sparse.success) << sparse.status_text;
    EXPECT_LT((sparse.x - dense.x).lpNorm<Eigen::Infinity>(), 1e-9 * dense.x.lpNorm<Eigen::Infinity>()) << seed;
    EXPECT_LT((sparse.multipliers - dense.multipliers).lpNorm<Eigen::Infinity>(),
              1e-8 * dense.multipliers.lpNorm<Eigen::Infinity>())
        << seed;
    EXPECT_LT(kkt_violation(p, sparse, 3.0, 1.0), 1e-8) << seed;
    EXPECT_LE(std::abs(sparse.iterations - dense.iterations), 2) << sparse.iterations << " against " << dense.iterations;
  }
}

TEST(DensePrimalInteriorPoint, AChangeOfUnitsChangesNeitherTheIteratesNorTheAnswer) {
  FrictionLikeProblem si(30, 45, 7);
  FrictionLikeProblem mm(30, 45, 7, 1e3, 1e-6);  // lengths × 1e3, forces × 1e-6 (say N/m → ...)
  const IpoptResult a = solve_dense_primal(si, VectorXd::Zero(30), DensePrimalOptions{});
  const IpoptResult b = solve_dense_primal(mm, VectorXd::Zero(30), DensePrimalOptions{});
  ASSERT_TRUE(a.success && b.success) << a.status_text << " / " << b.status_text;
  EXPECT_NEAR(a.iterations, b.iterations, 2);
  EXPECT_LT((b.x / 1e3 - a.x).lpNorm<Eigen::Infinity>(), 1e-8 * a.x.lpNorm<Eigen::Infinity>());
  EXPECT_LT((b.multipliers / 1e-6 - a.multipliers).lpNorm<Eigen::Infinity>(), 1e-8 * a.multipliers.lpNorm<Eigen::Infinity>());
}

// The weight w of the friction-like terms follows the iterate, w = 0.3 (1 + ½ tanh(mean x)) (as the Coulomb
// thresholds follow the pressure): the answer is the fixed point, the solution of the problem with w fixed at
// the value it ends with, and w is the rule's value there.
TEST(DensePrimalInteriorPoint, DataThatFollowTheIterateEndAtTheirFixedPoint) {
  const auto rule = [](const VectorXd& x) { return 0.3 * (1.0 + 0.5 * std::tanh(x.mean())); };
  FrictionLikeProblem p(40, 60, 2);
  int changes = 0;
  const FollowIterate follow = [&](const VectorXd& x, const VectorXd&) {
    const double w = rule(x);
    if (std::abs(w - p.weight()) <= 1e-12 * w) return false;
    p.set_weight(w);
    ++changes;
    return true;
  };
  const IpoptResult r = solve_dense_primal(p, VectorXd::Zero(40), DensePrimalOptions{}, nullptr, &follow);
  ASSERT_TRUE(r.success) << r.status_text;
  EXPECT_GE(changes, 2);
  EXPECT_LT(std::abs(p.weight() - rule(r.x)), 1e-9 * p.weight());
  EXPECT_GT(std::abs(p.weight() - 0.3), 1e-3) << "the rule moved w: the test exercises the hook";
  EXPECT_LT(kkt_violation(p, r, 3.0, 1.0), 1e-8);
  FrictionLikeProblem fixed(40, 60, 2);
  fixed.set_weight(p.weight());
  const IpoptResult f = solve_dense_primal(fixed, VectorXd::Zero(40), DensePrimalOptions{});
  ASSERT_TRUE(f.success) << f.status_text;
  EXPECT_LT((r.x - f.x).lpNorm<Eigen::Infinity>(), 1e-8 * f.x.lpNorm<Eigen::Infinity>());
}

// A re-solve whose followed data start at their fixed point, the rows moved a little (a later geometry
// iteration): following near the end (DensePrimalOptions::follow_below_near_fixed_point, as PrimalInteriorPoint
// does there) succeeds at a tight tolerance and ends at the fixed point that following from the default 0.1
// reaches. (Followed from 1e-9 here, it stops at the line search's round-off floor; the iterations it saves on
// the pads on a ball are measured in docs/performance.md.)
TEST(DensePrimalInteriorPoint, FollowingNearTheEndFromAFixedPointEndsAtTheSameFixedPoint) {
  // w_k = 0.2 (1 + λ_k) (followed_weights): each term's weight follows one row's multiplier, as τ = μ p follows
  // the pressure.
  const Index n = 40, m = 60;
  DensePrimalOptions tight;  // solutions within 1e-8 of the exact one (as in the warm start's test below)
  tight.tolerance = 1e-12;
  FrictionLikeProblem p(n, m, 2);
  p.set_weights(VectorXd::Constant(n / 2, 0.2));
  const FollowIterate follow = weights_follower(p);
  const IpoptResult first = solve_dense_primal(p, VectorXd::Zero(n), tight, nullptr, &follow);
  ASSERT_TRUE(first.success) << first.status_text;
  const auto resolve = [&](double follow_below, FrictionLikeProblem& q) {
    q.shift_offset(1e-3);  // the rows moved by 1e-3 of b
    q.set_weights(p.weights());
    const FollowIterate f = weights_follower(q);
    DensePrimalOptions o = tight;
    o.follow_below = follow_below;
    return solve_dense_primal(q, first.x, o, &first.multipliers, &f);
  };
  FrictionLikeProblem qe(n, m, 2), ql(n, m, 2);
  const IpoptResult early = resolve(0.1, qe);
  const IpoptResult late = resolve(DensePrimalOptions::follow_below_near_fixed_point(tight.tolerance), ql);
  ASSERT_TRUE(early.success && late.success) << early.status_text << " / " << late.status_text;
  const double w_scale = ql.weights().lpNorm<Eigen::Infinity>();
  EXPECT_GT((ql.weights() - p.weights()).lpNorm<Eigen::Infinity>(), 1e-6 * w_scale) << "the hook moved the weights";
  EXPECT_LT((ql.weights() - followed_weights(late.multipliers, n)).lpNorm<Eigen::Infinity>(), 1e-9 * w_scale);
  EXPECT_LT((ql.weights() - qe.weights()).lpNorm<Eigen::Infinity>(), 1e-9 * w_scale);
  EXPECT_LT((late.x - early.x).lpNorm<Eigen::Infinity>(), 1e-8 * early.x.lpNorm<Eigen::Infinity>());
  EXPECT_LE(late.iterations, early.iterations + 1);
}

TEST(DensePrimalInteriorPoint, AWarmStartFromTheSolutionTakesFewIterations) {
  FrictionLikeProblem p(40, 60, 11);
  DensePrimalOptions tight;  // both solutions within 1e-8 of the exact one (the regularised |x| makes the
  tight.tolerance = 1e-12;   // minimum's conditioning about 1e4 here)
  const IpoptResult cold = solve_dense_primal(p, VectorXd::Zero(40), tight);
  ASSERT_TRUE(cold.success) << cold.status_text;
  const IpoptResult warm = solve_dense_primal(p, cold.x, tight, &cold.multipliers);
  ASSERT_TRUE(warm.success) << warm.status_text;
  EXPECT_LT(warm.iterations, cold.iterations);
  EXPECT_LT((warm.x - cold.x).lpNorm<Eigen::Infinity>(), 1e-8 * cold.x.lpNorm<Eigen::Infinity>());
}

TEST(DensePrimalInteriorPoint, ReportsAFailureAsAFailure) {
  FrictionLikeProblem p(20, 30, 5);
  DensePrimalOptions few;
  few.max_iterations = 2;
  const IpoptResult r = solve_dense_primal(p, VectorXd::Zero(20), few);
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.status_text.find("no convergence in 2 iterations"), std::string::npos) << r.status_text;
}

namespace {
/// x₀ ≥ 1 and x₀ ≤ −1 at once: no feasible point.
class InfeasibleProblem : public ConstrainedProblem {
 public:
  InfeasibleProblem() {
    A_.resize(2, 2);
    A_.insert(0, 0) = 1.0;
    A_.insert(1, 0) = -1.0;
    A_.makeCompressed();
    b_ = VectorXd::Constant(2, -1.0);
  }
  Index num_variables() const override { return 2; }
  double objective(const VectorXd& x) override { return 0.5 * x.squaredNorm(); }
  void gradient(const VectorXd& x, VectorXd& g) override { g = x; }
  void hessian_lower(const VectorXd&, SparseMatrix& H) override {
    H.resize(2, 2);
    H.setIdentity();
  }
  const SparseMatrix& constraint_matrix() const override { return A_; }
  const VectorXd& constraint_offset() const override { return b_; }

 private:
  SparseMatrix A_;
  VectorXd b_;
};
}  // namespace

TEST(DensePrimalInteriorPoint, AnInfeasibleProblemIsNotASuccess) {
  InfeasibleProblem p;
  const IpoptResult r = solve_dense_primal(p, VectorXd::Zero(2), DensePrimalOptions{});
  EXPECT_FALSE(r.success);
  EXPECT_FALSE(r.status_text.empty());
}
