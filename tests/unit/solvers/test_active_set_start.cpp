// The active-set start of a warm-started subproblem (solvers/active_set_start.hpp) on the random convex problems
// of the dense primal interior point's tests (support/friction_like_problem.hpp): from the solution of a nearby
// problem it reaches the interior point's solution of the new one, with data that follow the iterate too, in
// any units, and what it cannot solve it reports as a failure.
#include <gtest/gtest.h>

#include "support/friction_like_problem.hpp"
#include "symcontact/solvers/active_set_start.hpp"

using namespace symcontact;
using symcontact::testing::FrictionLikeProblem;
using symcontact::testing::followed_weights;
using symcontact::testing::kkt_violation;
using symcontact::testing::weights_follower;

namespace {

constexpr Index kN = 40, kM = 60;

/// Options at a tight tolerance, the interior point's and the active-set start's: solutions within 1e-8 of
/// the exact one (the regularised |x| makes the minimum's conditioning about 1e4).
template <class Options>
Options tight() {
  Options o;
  o.tolerance = 1e-12;
  return o;
}

/// The number N of a status "converged (active set: N factorisation(s))"; -1 for any other.
int factorisations(const IpoptResult& r) {
  const std::string prefix = "converged (active set: ";
  if (r.status_text.rfind(prefix, 0) != 0) return -1;
  return std::stoi(r.status_text.substr(prefix.size()));
}

double relative(const VectorXd& a, const VectorXd& b) {
  return (a - b).lpNorm<Eigen::Infinity>() / b.lpNorm<Eigen::Infinity>();
}

}  // namespace

// The next problem is the last one with its rows moved by 1e-3 of b (a load step or geometry iteration later):
// started from the last solution and multipliers, the active set strategy ends at the interior point's solution
// of the new problem, a KKT point, after a few factorisations where the interior point takes more iterations.
TEST(ActiveSetStart, FromANearbySolutionItEndsAtTheInteriorPointsSolution) {
  for (const unsigned seed : {2u, 11u}) {
    FrictionLikeProblem p(kN, kM, seed);
    const IpoptResult last = solve_dense_primal(p, VectorXd::Zero(kN), tight<DensePrimalOptions>());
    ASSERT_TRUE(last.success) << last.status_text;
    p.shift_offset(1e-3);
    const IpoptResult ip = solve_dense_primal(p, last.x, tight<DensePrimalOptions>(), &last.multipliers);
    const IpoptResult as = solve_from_active_set(p, last.x, last.multipliers, tight<ActiveSetStartOptions>());
    ASSERT_TRUE(ip.success) << ip.status_text;
    ASSERT_TRUE(as.success) << as.status_text;
    EXPECT_LT(relative(as.x, ip.x), 1e-8) << "seed " << seed;
    EXPECT_LT(relative(as.multipliers, ip.multipliers), 1e-7) << "seed " << seed;
    EXPECT_LT(kkt_violation(p, as, 3.0, 1.0), 1e-10) << "seed " << seed;
    EXPECT_LE(dense_primal_error(p, as.scales, as.x, as.multipliers), 1e-12);
    EXPECT_GE(factorisations(as), 1) << as.status_text;
    EXPECT_LT(factorisations(as), ip.iterations) << as.status_text << " against " << ip.iterations;
    EXPECT_NEAR(as.objective, p.objective(as.x), 0.0);
    EXPECT_EQ(as.constraint_values, p.constraint_matrix() * as.x + p.constraint_offset());
  }
}

// The same with a Hessian that is not dense (the uncondensed problem): each Newton direction on the set by
// CHOLMOD's factor of ∇²f + ρ A_SᵀA_S and the method of multipliers instead of the dense range space; the same
// solution, a KKT point.
TEST(ActiveSetStart, TheSparsePathEndsAtTheSameSolution) {
  for (const unsigned seed : {2u, 11u}) {
    FrictionLikeProblem p(kN, kM, seed);
    const IpoptResult last = solve_dense_primal(p, VectorXd::Zero(kN), tight<DensePrimalOptions>());
    ASSERT_TRUE(last.success) << last.status_text;
    p.shift_offset(1e-3);
    const IpoptResult dense = solve_from_active_set(p, last.x, last.multipliers, tight<ActiveSetStartOptions>());
    p.set_dense(false);
    const IpoptResult sparse = solve_from_active_set(p, last.x, last.multipliers, tight<ActiveSetStartOptions>());
    ASSERT_TRUE(dense.success) << dense.status_text;
    ASSERT_TRUE(sparse.success) << sparse.status_text;
    EXPECT_LT(relative(sparse.x, dense.x), 1e-9) << "seed " << seed;
    EXPECT_LT(relative(sparse.multipliers, dense.multipliers), 1e-8) << "seed " << seed;
    EXPECT_LT(kkt_violation(p, sparse, 3.0, 1.0), 1e-10) << "seed " << seed;
    EXPECT_GE(factorisations(sparse), 1) << sparse.status_text;
  }
}

// Rows moved by 5 % of b: the last solution's set is no longer the active set, and the updates of the set
// find the new one (a quadratic f here: the primal-dual active set strategy as its authors state it).
TEST(ActiveSetStart, AChangedActiveSetIsFoundByItsUpdates) {
  for (const unsigned seed : {3u, 4u, 5u}) {
    FrictionLikeProblem p(kN, kM, seed);
    p.set_weight(0.0);
    const IpoptResult last = solve_dense_primal(p, VectorXd::Zero(kN), tight<DensePrimalOptions>());
    ASSERT_TRUE(last.success) << last.status_text;
    p.shift_offset(0.05);
    const IpoptResult now = solve_dense_primal(p, VectorXd::Zero(kN), tight<DensePrimalOptions>());
    ASSERT_TRUE(now.success) << now.status_text;
    const auto active = [](const IpoptResult& r) { return (r.multipliers.array() > 1e-8).cast<int>().eval(); };
    ASSERT_NE(active(last).matrix(), active(now).matrix()) << "seed " << seed << ": the set changed";
    const IpoptResult as = solve_from_active_set(p, last.x, last.multipliers, tight<ActiveSetStartOptions>());
    ASSERT_TRUE(as.success) << as.status_text;
    EXPECT_GE(factorisations(as), 2) << as.status_text;
    EXPECT_LT(relative(as.x, now.x), 1e-9) << "seed " << seed;
    EXPECT_LT(kkt_violation(p, as, 3.0, 1.0), 1e-10) << "seed " << seed;
  }
}

// The weights of the |x_k| terms follow the multipliers of their rows, w_k = 0.2 (1 + λ_k) (as τ = μ p follows
// the pressure), from the fixed point of the last problem: the answer is the new problem's fixed point, the one
// the interior point reaches with the same rule.
TEST(ActiveSetStart, DataThatFollowTheIterateEndAtTheirFixedPoint) {
  FrictionLikeProblem p(kN, kM, 2);
  p.set_weights(VectorXd::Constant(kN / 2, 0.2));
  int changes = 0;
  const FollowIterate follow = weights_follower(p, &changes);
  const IpoptResult last = solve_dense_primal(p, VectorXd::Zero(kN), tight<DensePrimalOptions>(), nullptr, &follow);
  ASSERT_TRUE(last.success) << last.status_text;
  FrictionLikeProblem qi(kN, kM, 2), qa(kN, kM, 2);
  for (FrictionLikeProblem* q : {&qi, &qa}) {
    q->shift_offset(1e-3);
    q->set_weights(p.weights());
  }
  int changes_ip = 0, changes_as = 0;
  const FollowIterate fi = weights_follower(qi, &changes_ip), fa = weights_follower(qa, &changes_as);
  auto o = tight<DensePrimalOptions>();
  o.follow_below = DensePrimalOptions::follow_below_near_fixed_point(o.tolerance);
  const IpoptResult ip = solve_dense_primal(qi, last.x, o, &last.multipliers, &fi);
  const IpoptResult as = solve_from_active_set(qa, last.x, last.multipliers, tight<ActiveSetStartOptions>(), &fa);
  ASSERT_TRUE(ip.success) << ip.status_text;
  ASSERT_TRUE(as.success) << as.status_text;
  EXPECT_GE(changes_as, 2) << "the hook moved the weights: the test exercises it";
  const double w_scale = qa.weights().lpNorm<Eigen::Infinity>();
  EXPECT_LT((qa.weights() - followed_weights(as.multipliers, kN)).lpNorm<Eigen::Infinity>(), 1e-9 * w_scale);
  EXPECT_LT((qa.weights() - qi.weights()).lpNorm<Eigen::Infinity>(), 1e-8 * w_scale);
  EXPECT_LT(relative(as.x, ip.x), 1e-8);
}

// The same followed weights on the sparse path: once its steps are small and falling, they keep the factor of
// an earlier step (a modified Newton method), so it factorises less often than it steps, and it still ends at
// the fixed point, the dense path's answer.
TEST(ActiveSetStart, TheSparsePathKeepsItsFactorWhileTheFollowedDataSettle) {
  FrictionLikeProblem p(kN, kM, 2);
  p.set_weights(VectorXd::Constant(kN / 2, 0.2));
  const FollowIterate follow = weights_follower(p);
  const IpoptResult last = solve_dense_primal(p, VectorXd::Zero(kN), tight<DensePrimalOptions>(), nullptr, &follow);
  ASSERT_TRUE(last.success) << last.status_text;
  FrictionLikeProblem qd(kN, kM, 2), qs(kN, kM, 2);
  for (FrictionLikeProblem* q : {&qd, &qs}) {
    q->shift_offset(1e-3);
    q->set_weights(p.weights());
  }
  qs.set_dense(false);
  const FollowIterate fd = weights_follower(qd), fs = weights_follower(qs);
  const IpoptResult dense = solve_from_active_set(qd, last.x, last.multipliers, tight<ActiveSetStartOptions>(), &fd);
  const IpoptResult sparse = solve_from_active_set(qs, last.x, last.multipliers, tight<ActiveSetStartOptions>(), &fs);
  ASSERT_TRUE(dense.success) << dense.status_text;
  ASSERT_TRUE(sparse.success) << sparse.status_text;
  EXPECT_GE(factorisations(sparse), 1) << sparse.status_text;
  EXPECT_LT(factorisations(sparse), sparse.iterations) << sparse.status_text;
  const double w_scale = qs.weights().lpNorm<Eigen::Infinity>();
  EXPECT_LT((qs.weights() - followed_weights(sparse.multipliers, kN)).lpNorm<Eigen::Infinity>(), 1e-9 * w_scale);
  EXPECT_LT(relative(sparse.x, dense.x), 1e-8);
}

// A first solve (no earlier multipliers) on the sparse path, from x = 0 with the weights following: the set
// starts from the rows x = 0 violates, and the answer is the interior point's fixed point from the same start,
// one that passes its stopping test (a modified Newton step that falls linearly is not taken for round-off).
TEST(ActiveSetStart, AColdStartOnTheSparsePathEndsAtTheInteriorPointsFixedPoint) {
  for (const unsigned seed : {2u, 11u}) {
    FrictionLikeProblem qi(kN, kN / 2, seed), qa(kN, kN / 2, seed);
    for (FrictionLikeProblem* q : {&qi, &qa}) q->set_weights(VectorXd::Constant(kN / 2, 0.2));
    qa.set_dense(false);
    int changes = 0;
    const FollowIterate fi = weights_follower(qi), fa = weights_follower(qa, &changes);
    const IpoptResult ip = solve_dense_primal(qi, VectorXd::Zero(kN), tight<DensePrimalOptions>(), nullptr, &fi);
    const IpoptResult as =
        solve_from_active_set(qa, VectorXd::Zero(kN), VectorXd::Zero(kN / 2), tight<ActiveSetStartOptions>(), &fa);
    ASSERT_TRUE(ip.success) << ip.status_text;
    ASSERT_TRUE(as.success) << "seed " << seed << ": " << as.status_text;
    EXPECT_GE(changes, 2) << "the hook moved the weights: the test exercises it";
    EXPECT_LT(relative(as.x, ip.x), 1e-8) << "seed " << seed;
    EXPECT_LE(dense_primal_error(qa, as.scales, as.x, as.multipliers), 1e-12);
  }
}

TEST(ActiveSetStart, AChangeOfUnitsChangesNeitherTheStepsNorTheAnswer) {
  FrictionLikeProblem si(30, 45, 7), mm(30, 45, 7, 1e3, 1e-6);  // lengths × 1e3, forces × 1e-6
  const IpoptResult a0 = solve_dense_primal(si, VectorXd::Zero(30), tight<DensePrimalOptions>());
  const IpoptResult b0 = solve_dense_primal(mm, VectorXd::Zero(30), tight<DensePrimalOptions>());
  ASSERT_TRUE(a0.success && b0.success) << a0.status_text << " / " << b0.status_text;
  si.shift_offset(1e-3);
  mm.shift_offset(1e-3);
  const IpoptResult a = solve_from_active_set(si, a0.x, a0.multipliers, tight<ActiveSetStartOptions>());
  const IpoptResult b = solve_from_active_set(mm, b0.x, b0.multipliers, tight<ActiveSetStartOptions>());
  ASSERT_TRUE(a.success && b.success) << a.status_text << " / " << b.status_text;
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_EQ(a.status_text, b.status_text);
  EXPECT_LT(relative(b.x / 1e3, a.x), 1e-9);
  EXPECT_LT(relative(b.multipliers / 1e-6, a.multipliers), 1e-8);
}

// What it cannot solve within its budget, or at all, is a failure with the reason, never a success.
TEST(ActiveSetStart, ReportsAFailureAsAFailure) {
  FrictionLikeProblem p(kN, kM, 5);
  const IpoptResult last = solve_dense_primal(p, VectorXd::Zero(kN), tight<DensePrimalOptions>());
  ASSERT_TRUE(last.success) << last.status_text;
  p.shift_offset(0.2);
  auto one_step = tight<ActiveSetStartOptions>();
  one_step.max_newton_steps = 1;
  const IpoptResult r = solve_from_active_set(p, last.x, last.multipliers, one_step);
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.status_text.find("did not converge"), std::string::npos) << r.status_text;
  auto one_set = tight<ActiveSetStartOptions>();
  one_set.max_set_rounds = 1;
  const IpoptResult s = solve_from_active_set(p, VectorXd::Zero(kN), VectorXd::Ones(kM), one_set);
  EXPECT_FALSE(s.success);
  EXPECT_NE(s.status_text.find("did not settle"), std::string::npos) << s.status_text;
  const IpoptResult sizes = solve_from_active_set(p, last.x, VectorXd::Ones(kM + 1), tight<ActiveSetStartOptions>());
  EXPECT_FALSE(sizes.success);
}
