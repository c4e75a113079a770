// The dual of a frictionless condensed contact problem (solvers/dual_condensed_problem.hpp) against the
// primal solved by IPOPT: two "bodies" of 12 DOFs each, the first held (S₁ definite), the second held by
// contact alone (S₂ has the rigid translation in its null space), pressed onto the first by a load; eight
// contact rows, some of them open at the solution.
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "symcontact/optim/ipopt_solver.hpp"
#include "symcontact/solvers/dual_condensed_problem.hpp"
#include "symcontact/solvers/semidefinite_factor.hpp"

using namespace symcontact;

namespace {

constexpr Index kBody = 12, kN = 2 * kBody, kRows = 8;

/// min ½ yᵀS y + gᵀy  s.t.  A y + b ≥ 0, S dense.
class DenseQp : public ConstrainedProblem {
 public:
  DenseQp(MatrixXd S, VectorXd g, SparseMatrix A, VectorXd b)
      : S_(std::move(S)), g_(std::move(g)), A_(std::move(A)), b_(std::move(b)) {}
  Index num_variables() const override { return S_.rows(); }
  double objective(const VectorXd& y) override { return 0.5 * y.dot(S_ * y) + g_.dot(y); }
  void gradient(const VectorXd& y, VectorXd& g) override { g = S_ * y + g_; }
  void hessian_lower(const VectorXd&, SparseMatrix& H) override {
    H = MatrixXd(S_.triangularView<Eigen::Lower>()).sparseView(0.0, 0.0);
  }
  bool hessian_is_constant() const override { return true; }
  const SparseMatrix& constraint_matrix() const override { return A_; }
  const VectorXd& constraint_offset() const override { return b_; }

 private:
  MatrixXd S_;
  VectorXd g_;
  SparseMatrix A_;
  VectorXd b_;
};

struct Case {
  MatrixXd S;
  VectorXd g;
  SparseMatrix A;
  VectorXd b;
};

/// `floating`: the second body has no support of its own (S singular).
Case make_case(bool floating, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto spd = [&](Index n) {
    MatrixXd B(n, n);
    for (Index i = 0; i < n; ++i)
      for (Index j = 0; j < n; ++j) B(i, j) = u(rng);
    return MatrixXd(B * B.transpose() + 0.5 * MatrixXd::Identity(n, n));
  };
  Case c;
  c.S = MatrixXd::Zero(kN, kN);
  c.S.topLeftCorner(kBody, kBody) = spd(kBody);
  MatrixXd s2 = spd(kBody);
  if (floating) {  // remove the uniform motion: P s2 P with P = I − 11ᵀ/n
    const MatrixXd P = MatrixXd::Identity(kBody, kBody) - MatrixXd::Constant(kBody, kBody, 1.0 / kBody);
    s2 = P * s2 * P;
  }
  c.S.bottomRightCorner(kBody, kBody) = s2;
  // Load: the second body pushed down (energy ĝᵀy falls as its DOFs fall), the first one loaded at random.
  c.g = VectorXd::Zero(kN);
  for (Index i = 0; i < kBody; ++i) c.g[i] = 0.1 * u(rng);
  c.g.tail(kBody).setConstant(0.05);
  // Gaps y₂ᵢ − y₁ᵢ + bᵢ ≥ 0 with a little of the neighbours, initial gaps growing with i.
  std::vector<Triplet> t;
  c.b.resize(kRows);
  for (int i = 0; i < kRows; ++i) {
    t.emplace_back(i, static_cast<int>(kBody + i), 1.0 + 0.1 * u(rng));
    t.emplace_back(i, i, -1.0);
    t.emplace_back(i, i + 1, 0.2 * u(rng));
    c.b[i] = 0.02 * i * i;
  }
  c.A.resize(kRows, kN);
  c.A.setFromTriplets(t.begin(), t.end());
  return c;
}

IpoptOptions tight() {
  IpoptOptions o;
  o.tolerance = 1e-12;
  return o;
}

/// IPOPT on the primal of the case, to a tight tolerance: the reference.
IpoptResult solve_primal(const Case& c) {
  DenseQp primal(c.S, c.g, c.A, c.b);
  return solve_with_ipopt(primal, VectorXd::Zero(kN), tight());
}

/// The dual by its dense interior point, to a tight tolerance.
DenseQpResult tight_interior_point(const DualCondensedProblem& dual) {
  DenseQpOptions o;
  o.tolerance = 1e-12;
  return dual.solve_interior_point(o);
}

SemidefiniteFactor schur_factor(const Case& c) {
  return SemidefiniteFactor(MatrixXd(c.S.triangularView<Eigen::Lower>()).sparseView(), 1e-10);
}

}  // namespace

class DualCondensed : public ::testing::TestWithParam<bool> {};

TEST_P(DualCondensed, SameDisplacementsAndMultipliersAsThePrimal) {
  const bool floating = GetParam();
  for (unsigned seed : {1u, 2u, 3u}) {
    const Case c = make_case(floating, seed);
    const IpoptResult rp = solve_primal(c);
    ASSERT_TRUE(rp.success) << rp.status_text;

    const SemidefiniteFactor f = schur_factor(c);
    EXPECT_EQ(f.rank(), floating ? kN - 1 : kN);
    DualCondensedProblem dual(f, c.A, c.b, c.g);
    EXPECT_EQ(dual.num_rigid_modes(), floating ? 1 : 0);
    const IpoptResult rd = solve_with_ipopt(dual, VectorXd::Zero(kRows), tight());
    ASSERT_TRUE(rd.success) << rd.status_text;
    const VectorXd y = dual.primal(rd.x, rd.multipliers);
    const VectorXd lambda = dual.multipliers(rd.x);

    const double yscale = rp.x.lpNorm<Eigen::Infinity>(), mscale = rp.multipliers.lpNorm<Eigen::Infinity>();
    ASSERT_GT(mscale, 0.0);
    EXPECT_LT((y - rp.x).lpNorm<Eigen::Infinity>(), 1e-7 * yscale) << "seed " << seed;
    EXPECT_LT((lambda - rp.multipliers).lpNorm<Eigen::Infinity>(), 1e-7 * mscale) << "seed " << seed;
    // Some rows open, some closed: the test sees the active set, not a trivial one.
    int open = 0;
    for (Index i = 0; i < kRows; ++i) open += lambda[i] < 1e-8 * mscale;
    EXPECT_GT(open, 0);
    EXPECT_LT(open, kRows);
    // The displacements balance the forces exactly, whatever the optimiser's tolerance: S y + ĝ = Aᵀλ.
    const VectorXd residual = c.S * y + c.g - c.A.transpose() * lambda;
    EXPECT_LT(residual.lpNorm<Eigen::Infinity>(), 1e-10 * c.g.lpNorm<Eigen::Infinity>()) << "seed " << seed;
    // The bounds' multipliers are the (scaled) gaps.
    const VectorXd gaps = dual.scaled_gaps(y);
    EXPECT_LT((rd.bound_multipliers - gaps).lpNorm<Eigen::Infinity>(), 1e-7 * gaps.lpNorm<Eigen::Infinity>());
    EXPECT_GE((c.A * y + c.b).minCoeff(), -1e-9 * yscale);
  }
}

// The closing in the dual's form: from IPOPT's point, the closed rows' gaps vanish to round-off, the open rows
// keep λ = 0 and positive gaps, and the result is the exact solution of the QP on that active set.
TEST_P(DualCondensed, ClosingMakesTheActiveGapsExactlyZero) {
  const bool floating = GetParam();
  for (unsigned seed : {1u, 2u, 3u}) {
    const Case c = make_case(floating, seed);
    const SemidefiniteFactor f = schur_factor(c);
    DualCondensedProblem dual(f, c.A, c.b, c.g);
    const IpoptResult rd = solve_with_ipopt(dual, VectorXd::Zero(kRows), IpoptOptions{});
    ASSERT_TRUE(rd.success) << rd.status_text;
    VectorXd lambda_hat = rd.x, eq = rd.multipliers;
    const VectorXd y_ipopt = dual.primal(lambda_hat, eq);
    const DualCondensedProblem::Closing cl = dual.close_contact_set(lambda_hat, eq);
    ASSERT_TRUE(cl.applied) << cl.reason;
    const VectorXd y = dual.primal(lambda_hat, eq);
    const VectorXd lambda = dual.multipliers(lambda_hat);
    const VectorXd gaps = c.A * y + c.b;
    const double yscale = y.lpNorm<Eigen::Infinity>();
    int closed = 0;
    for (Index i = 0; i < kRows; ++i) {
      if (lambda[i] > 0) {
        ++closed;
        EXPECT_LT(std::abs(gaps[i]), 1e-12 * yscale) << "seed " << seed << " row " << i;
      } else {
        EXPECT_GT(gaps[i], -1e-12 * yscale) << "seed " << seed << " row " << i;
      }
    }
    EXPECT_EQ(closed, cl.active);
    EXPECT_GT(closed, 0);
    // Still balanced, and the IPOPT point was not already closed to this level (the closing did something).
    EXPECT_LT((c.S * y + c.g - c.A.transpose() * lambda).lpNorm<Eigen::Infinity>(), 1e-10 * c.g.lpNorm<Eigen::Infinity>());
    double open_before = 0.0;
    const VectorXd gaps_before = c.A * y_ipopt + c.b;
    for (Index i = 0; i < kRows; ++i)
      if (lambda[i] > 0) open_before = std::max(open_before, std::abs(gaps_before[i]));
    EXPECT_GT(open_before, 1e-12 * yscale) << "seed " << seed;
  }
}

// The dense interior point (the dual's optimiser where the rows are independent) on the same dual: the primal's displacements and multipliers,
// its z the scaled gaps, its β in IPOPT's μ_eq convention (primal() with it gives the balanced y; a flipped sign
// fails the floating case), and the closing from its point.
TEST_P(DualCondensed, InteriorPointGivesThePrimalSolution) {
  const bool floating = GetParam();
  for (unsigned seed : {1u, 2u, 3u}) {
    const Case c = make_case(floating, seed);
    const IpoptResult rp = solve_primal(c);
    ASSERT_TRUE(rp.success) << rp.status_text;
    const SemidefiniteFactor f = schur_factor(c);
    DualCondensedProblem dual(f, c.A, c.b, c.g);
    const DenseQpResult r = tight_interior_point(dual);
    ASSERT_TRUE(r.success) << r.status;
    ASSERT_EQ(r.beta.size(), floating ? 1 : 0);
    const VectorXd y = dual.primal(r.x, r.beta);
    const VectorXd lambda = dual.multipliers(r.x);
    const double yscale = rp.x.lpNorm<Eigen::Infinity>(), mscale = rp.multipliers.lpNorm<Eigen::Infinity>();
    EXPECT_LT((y - rp.x).lpNorm<Eigen::Infinity>(), 1e-7 * yscale) << "seed " << seed;
    EXPECT_LT((lambda - rp.multipliers).lpNorm<Eigen::Infinity>(), 1e-7 * mscale) << "seed " << seed;
    const VectorXd gaps = dual.scaled_gaps(y);
    EXPECT_LT((r.z - gaps).lpNorm<Eigen::Infinity>(), 1e-7 * gaps.lpNorm<Eigen::Infinity>()) << "seed " << seed;

    VectorXd lambda_hat = r.x, eq = r.beta;
    const DualCondensedProblem::Closing cl = dual.close_contact_set(lambda_hat, eq);
    ASSERT_TRUE(cl.applied) << cl.reason;
    const VectorXd yc = dual.primal(lambda_hat, eq);
    EXPECT_LT((yc - rp.x).lpNorm<Eigen::Infinity>(), 1e-7 * yscale) << "seed " << seed;
    const VectorXd lc = dual.multipliers(lambda_hat), gc = c.A * yc + c.b;
    for (Index i = 0; i < kRows; ++i) {
      if (lc[i] > 0) {
        EXPECT_LT(std::abs(gc[i]), 1e-12 * yscale) << "seed " << seed << " row " << i;
      }
    }
  }
}

// A face resting on a plane under load: every row closed at y = 0 (rows y_i ≥ 0, ĝ > 0 pushing every DOF
// down: λ = ĝ, y = 0 solve the KKT conditions). The closed rows' gaps are then measured against the load's own
// gaps, ‖d‖∞, not against ‖y‖∞, which is round-off there: the set closes in one round, exactly.
TEST(DualCondensedResting, AFaceRestingOnAPlaneClosesInOneRound) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  MatrixXd B(kBody, kBody);
  for (Index i = 0; i < kBody; ++i)
    for (Index j = 0; j < kBody; ++j) B(i, j) = u(rng);
  Case c;
  c.S = B * B.transpose() + 0.5 * MatrixXd::Identity(kBody, kBody);
  c.g = VectorXd::Constant(kBody, 0.05);
  for (Index i = 0; i < kBody; ++i) c.g[i] += 0.02 * (u(rng) + 1.0);
  c.A = MatrixXd::Identity(kBody, kBody).sparseView();
  c.b = VectorXd::Zero(kBody);
  const SemidefiniteFactor f = schur_factor(c);
  DualCondensedProblem dual(f, c.A, c.b, c.g);
  const DenseQpResult r = tight_interior_point(dual);
  ASSERT_TRUE(r.success) << r.status;
  VectorXd lambda_hat = r.x, eq = r.beta;
  const DualCondensedProblem::Closing cl = dual.close_contact_set(lambda_hat, eq);
  ASSERT_TRUE(cl.applied) << cl.reason;
  EXPECT_EQ(cl.rounds, 1);
  EXPECT_EQ(cl.active, kBody);
  const VectorXd y = dual.primal(lambda_hat, eq);
  EXPECT_LT(y.lpNorm<Eigen::Infinity>(), 1e-14);
  EXPECT_LT((dual.multipliers(lambda_hat) - c.g).lpNorm<Eigen::Infinity>(), 1e-12 * c.g.lpNorm<Eigen::Infinity>());
}

// The closing started from the rows the load alone violates (cold_start: no previous solution) reaches the
// primal's answer; with each row given twice (two nearly dependent families, as a symmetric pair has) it closes
// only where any split of the force between the copies is allowed (Rows::kAny), and Rows::kIndependent
// refuses the set instead of picking one split.
TEST(DualCondensedCold, ClosesFromTheViolatedRowsAndRefusesDependentRowsWhenAsked) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const Case c = make_case(false, seed);
    const IpoptResult rp = solve_primal(c);
    ASSERT_TRUE(rp.success) << rp.status_text;
    const SemidefiniteFactor f = schur_factor(c);
    DualCondensedProblem dual(f, c.A, c.b, c.g);
    VectorXd lambda_hat = dual.cold_start(), eq = VectorXd::Zero(0);
    ASSERT_GT(lambda_hat.maxCoeff(), 0.0);
    const DualCondensedProblem::Closing cl =
        dual.close_contact_set(lambda_hat, eq, 30, DualCondensedProblem::Rows::kIndependent);
    ASSERT_TRUE(cl.applied) << cl.reason << " (seed " << seed << ")";
    const VectorXd y = dual.primal(lambda_hat, eq);
    EXPECT_LT((y - rp.x).lpNorm<Eigen::Infinity>(), 1e-7 * rp.x.lpNorm<Eigen::Infinity>()) << "seed " << seed;

    SparseMatrix twice(2 * kRows, kN);
    std::vector<Triplet> t;
    for (int j = 0; j < c.A.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(c.A, j); it; ++it) {
        t.emplace_back(static_cast<int>(it.row()), j, it.value());
        t.emplace_back(static_cast<int>(it.row() + kRows), j, it.value());
      }
    twice.setFromTriplets(t.begin(), t.end());
    VectorXd b2(2 * kRows);
    b2 << c.b, c.b;
    DualCondensedProblem doubled(f, twice, b2, c.g);
    VectorXd l2 = doubled.cold_start(), e2 = VectorXd::Zero(0);
    EXPECT_FALSE(doubled.close_contact_set(l2, e2, 30, DualCondensedProblem::Rows::kIndependent).applied);
    l2 = doubled.cold_start();
    ASSERT_TRUE(doubled.close_contact_set(l2, e2, 30, DualCondensedProblem::Rows::kAny).applied);
    EXPECT_LT((doubled.primal(l2, e2) - rp.x).lpNorm<Eigen::Infinity>(), 1e-7 * rp.x.lpNorm<Eigen::Infinity>());
  }
}

INSTANTIATE_TEST_SUITE_P(HeldAndFloating, DualCondensed, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& p) { return p.param ? "Floating" : "Held"; });
