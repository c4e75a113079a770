#include "symcontact/optim/ipopt_solver.hpp"

#include <gtest/gtest.h>

#include <tuple>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "symcontact/core/error.hpp"

using namespace symcontact;

namespace {

SparseMatrix to_sparse(const MatrixXd& M) {
  SparseMatrix S = M.sparseView();
  S.makeCompressed();
  return S;
}

/// f(x) = scale · (½ xᵀQx − qᵀx) subject to A x + b ≥ 0.
class QuadraticProblem : public ConstrainedProblem {
 public:
  QuadraticProblem(MatrixXd Q, VectorXd q, const MatrixXd& A, VectorXd b, double scale = 1.0)
      : Q_(std::move(Q)), q_(std::move(q)), A_(to_sparse(A)), b_(std::move(b)), scale_(scale) {}
  Index num_variables() const override { return Q_.rows(); }
  double objective(const VectorXd& x) override { return scale_ * (0.5 * x.dot(Q_ * x) - q_.dot(x)); }
  void gradient(const VectorXd& x, VectorXd& g) override { g = scale_ * (Q_ * x - q_); }
  void hessian_lower(const VectorXd&, SparseMatrix& H) override {
    H = to_sparse(scale_ * MatrixXd(Q_.triangularView<Eigen::Lower>()));
  }
  bool hessian_is_constant() const override { return true; }
  const SparseMatrix& constraint_matrix() const override { return A_; }
  const VectorXd& constraint_offset() const override { return b_; }

 private:
  MatrixXd Q_;
  VectorXd q_;
  SparseMatrix A_;
  VectorXd b_;
  double scale_;
};

/// A fixed SPD 5×5 matrix and right-hand side.
MatrixXd spd5() {
  MatrixXd M(5, 5);
  M << 2.0, 0.3, -0.1, 0.0, 0.5,  //
      0.1, 1.5, 0.2, -0.4, 0.0,   //
      0.0, -0.3, 3.0, 0.1, 0.2,   //
      0.4, 0.0, 0.0, 1.2, -0.3,   //
      -0.2, 0.1, 0.3, 0.0, 2.5;
  return M.transpose() * M + MatrixXd::Identity(5, 5);
}
VectorXd rhs5() {
  VectorXd q(5);
  q << 1.0, -2.0, 0.5, 3.0, -1.0;
  return q;
}

/// A general QP used by the scaling and warm-start tests: min ½xᵀQx − qᵀx s.t. x ≥ 0, 2 − Σx ≥ 0.
MatrixXd general_A() {
  MatrixXd A(6, 5);
  A.topRows(5) = MatrixXd::Identity(5, 5);
  A.row(5).setConstant(-1.0);
  return A;
}
VectorXd general_b() {
  VectorXd b = VectorXd::Zero(6);
  b(5) = 2.0;
  return b;
}

/// Checks the KKT conditions ∇f = Aᵀμ, μ ≥ 0, c ≥ 0, μ∘c = 0 (relative to the gradient scale).
void expect_kkt(ConstrainedProblem& problem, const IpoptResult& r, double tol) {
  VectorXd g;
  problem.gradient(r.x, g);
  const SparseMatrix& A = problem.constraint_matrix();
  const VectorXd c = A * r.x + problem.constraint_offset();
  const double scale = std::max(1e-300, std::max(g.lpNorm<Eigen::Infinity>(),
                                                r.multipliers.size() ? r.multipliers.lpNorm<Eigen::Infinity>() : 0.0));
  EXPECT_LE((g - A.transpose() * r.multipliers).lpNorm<Eigen::Infinity>(), tol * scale);
  EXPECT_LE((c - r.constraint_values).lpNorm<Eigen::Infinity>(), 1e-12 * (1 + c.lpNorm<Eigen::Infinity>()));
  for (Index i = 0; i < c.size(); ++i) {
    EXPECT_GE(r.multipliers(i), -tol * scale) << "constraint " << i;
    EXPECT_GE(c(i), -tol) << "constraint " << i;
    EXPECT_LE(std::abs(r.multipliers(i) * c(i)), tol * scale) << "constraint " << i;
  }
}

/// f(x) = Σ (−log x_i + x_i), minimiser x = 1; EvaluationError when some x_i ≤ 0.
/// The Hessian is diagonal; its pattern at the first call holds an explicit zero at (1, 0) that later
/// calls leave out (a sub-pattern, which the adapter must accept). With `bad_pattern`, later calls
/// instead add a nonzero at (1, 0), which violates the ConstrainedProblem contract.
class LogProblem : public ConstrainedProblem {
 public:
  explicit LogProblem(Index n, bool bad_pattern = false) : n_(n), bad_pattern_(bad_pattern), A_(0, n), b_(0) {}
  Index num_variables() const override { return n_; }
  double objective(const VectorXd& x) override {
    check(x);
    return (x.array() - x.array().log()).sum();
  }
  void gradient(const VectorXd& x, VectorXd& g) override {
    check(x);
    g = (1.0 - x.array().inverse()).matrix();
  }
  void hessian_lower(const VectorXd& x, SparseMatrix& H) override {
    check(x);
    std::vector<Triplet> t;
    for (Index i = 0; i < n_; ++i) t.emplace_back(int(i), int(i), 1.0 / (x(i) * x(i)));
    if (n_ > 1 && hessian_calls_ == 0 && !bad_pattern_) t.emplace_back(1, 0, 0.0);
    if (n_ > 1 && hessian_calls_ > 0 && bad_pattern_) t.emplace_back(1, 0, 0.5);
    ++hessian_calls_;
    H.resize(int(n_), int(n_));
    H.setFromTriplets(t.begin(), t.end());
  }
  const SparseMatrix& constraint_matrix() const override { return A_; }
  const VectorXd& constraint_offset() const override { return b_; }
  int failed_evaluations = 0;

 private:
  void check(const VectorXd& x) {
    if ((x.array() <= 0.0).any()) {
      ++failed_evaluations;
      throw EvaluationError("log of a non-positive number");
    }
  }
  Index n_;
  bool bad_pattern_;
  int hessian_calls_ = 0;
  SparseMatrix A_;
  VectorXd b_;
};

}  // namespace

// 1. Unconstrained convex quadratic: x = Q⁻¹q.
TEST(IpoptSolver, UnconstrainedQuadratic) {
  const MatrixXd Q = spd5();
  const VectorXd q = rhs5();
  QuadraticProblem problem(Q, q, MatrixXd(0, 5), VectorXd(0));
  const IpoptResult r = solve_with_ipopt(problem, VectorXd::Zero(5), IpoptOptions{});
  ASSERT_TRUE(r.success) << r.status_text;
  EXPECT_EQ(r.status_text, "Solve_Succeeded");
  const VectorXd expected = Q.ldlt().solve(q);
  EXPECT_LE((r.x - expected).norm(), 1e-10 * expected.norm());
  EXPECT_NEAR(r.objective, -0.5 * q.dot(expected), 1e-12 * std::abs(q.dot(expected)));
  EXPECT_EQ(r.multipliers.size(), 0);
  EXPECT_GE(r.iterations, 1);
  EXPECT_GE(r.seconds, r.seconds_in_callbacks);
  EXPECT_GE(r.seconds_in_callbacks, 0.0);
  // ∇f(0) = −q: g_ref = ‖q‖∞, ℓ = g_ref / max|Q| (the lower triangle holds the largest entry: Q is symmetric).
  EXPECT_DOUBLE_EQ(r.scales.force, q.lpNorm<Eigen::Infinity>());
  EXPECT_DOUBLE_EQ(r.scales.length, q.lpNorm<Eigen::Infinity>() / Q.cwiseAbs().maxCoeff());
  std::printf("[ipopt] unconstrained QP: %d iterations\n", r.iterations);
}

// 1b. The same constrained problem in other units (x' = L x, f' = F L f, rows × c): the same iterates, so the
// same iterations and x'/L = x to round-off. Fails when any tolerance is absolute in the units of x, of f or
// of the constraints.
TEST(IpoptSolver, ChangeOfUnitsChangesNothing) {
  const MatrixXd Q = spd5();
  const VectorXd q = rhs5();
  MatrixXd A(2, 5);
  A << 1.0, 0.5, 0.0, -0.2, 0.0,  //
      0.0, 0.3, -1.0, 0.0, 0.4;
  const VectorXd b = VectorXd::Constant(2, -0.05);
  QuadraticProblem reference(Q, q, A, b);
  const IpoptResult r0 = solve_with_ipopt(reference, VectorXd::Zero(5), IpoptOptions{});
  ASSERT_TRUE(r0.success) << r0.status_text;
  ASSERT_GT(r0.multipliers.maxCoeff(), 0.0);  // a constraint is active
  for (const auto& [L, F, c] : {std::tuple{1e3, 1.0, 1e6}, std::tuple{1e-4, 1e5, 1e-8}}) {
    QuadraticProblem scaled(F / L * Q, F * q, c / L * A, c * b);
    const IpoptResult r = solve_with_ipopt(scaled, VectorXd::Zero(5), IpoptOptions{});
    ASSERT_TRUE(r.success) << r.status_text;
    EXPECT_EQ(r.iterations, r0.iterations) << "L = " << L;
    EXPECT_LE((r.x / L - r0.x).norm(), 1e-10 * r0.x.norm()) << "L = " << L;
    EXPECT_LE((r.multipliers * c / (F * L) - r0.multipliers).norm(), 1e-8 * r0.multipliers.norm()) << "L = " << L;
  }
}

// 2. Projection onto the positive orthant: x = max(p, 0), μ = max(−p, 0).
TEST(IpoptSolver, ProjectionQpMultipliersHaveContactSign) {
  VectorXd p(6);
  p << 1.5, -2.0, 0.3, -0.7, 4.0, -0.25;
  QuadraticProblem problem(MatrixXd::Identity(6, 6), p, MatrixXd::Identity(6, 6), VectorXd::Zero(6));
  const IpoptResult r = solve_with_ipopt(problem, VectorXd::Zero(6), IpoptOptions{});
  ASSERT_TRUE(r.success) << r.status_text;
  const VectorXd x_expected = p.cwiseMax(0.0);
  const VectorXd mu_expected = (-p).cwiseMax(0.0);
  // The interior point stops with x_i μ_i at tol relative to the problem's scales (the header): the active x_i
  // are off by about 1e-9 of the displacement scale ℓ = ‖p‖∞ / max|Q| = 4.
  EXPECT_DOUBLE_EQ(r.scales.length, 4.0);
  for (Index i = 0; i < 6; ++i) {
    EXPECT_NEAR(r.x(i), x_expected(i), 1e-9 * r.scales.length) << i;
    EXPECT_NEAR(r.multipliers(i), mu_expected(i), 1e-7) << i;
  }
  EXPECT_LE((r.constraint_values - r.x).norm(), 1e-14);  // c(x) = x here
  expect_kkt(problem, r, 1e-8);
  std::printf("[ipopt] projection QP: %d iterations\n", r.iterations);
}

// A weakly active constraint (tiny multiplier): IPOPT's complementarity test is absolute, so its gap
// is only known to about tol · g_ref / μ_i (here μ = x − p, so the multiplier has the same error).
TEST(IpoptSolver, WeaklyActiveConstraintGapIsToleranceOverMultiplier) {
  VectorXd p(2);
  p << 4.0, -1e-3;
  QuadraticProblem problem(MatrixXd::Identity(2, 2), p, MatrixXd::Identity(2, 2), VectorXd::Zero(2));
  const IpoptOptions options;
  const IpoptResult r = solve_with_ipopt(problem, VectorXd::Zero(2), options);
  ASSERT_TRUE(r.success) << r.status_text;
  const double g_ref = 4.0;  // ‖∇f(0)‖∞
  EXPECT_GE(r.x(1), 0.0);
  EXPECT_LE(r.x(1), 10 * options.tolerance * g_ref / 1e-3);
  EXPECT_NEAR(r.multipliers(1), r.x(1) + 1e-3, 1e-12);  // stationarity holds much more tightly
  std::printf("[ipopt] weakly active constraint: gap %.3g with multiplier %.3g\n", r.x(1), r.multipliers(1));
}

// 3. Rank-deficient constraints (LICQ fails): duplicates and multiples of a constraint.
TEST(IpoptSolver, RankDeficientConstraints) {
  VectorXd p(3);
  p << -1.0, -2.0, 0.5;
  MatrixXd A(6, 3);
  A << 1, 0, 0,  // x0 ≥ 0
      1, 0, 0,   // the same again
      0, 2, 0,   // 2 x1 ≥ 0
      0, 1, 0,   // x1 ≥ 0 (a multiple of the previous row)
      0, 0, 1,   // x2 ≥ 0 (inactive)
      1, 1, 0;   // x0 + x1 ≥ 0 (active, dependent on rows 0 and 3)
  QuadraticProblem problem(MatrixXd::Identity(3, 3), p, A, VectorXd::Zero(6));
  const IpoptResult r = solve_with_ipopt(problem, VectorXd::Constant(3, 1.0), IpoptOptions{});
  ASSERT_TRUE(r.success) << r.status_text;
  EXPECT_NEAR(r.x(0), 0.0, 1e-9);
  EXPECT_NEAR(r.x(1), 0.0, 1e-9);
  EXPECT_NEAR(r.x(2), 0.5, 1e-9);
  // The multipliers are not unique; what is determined: ∇f = Aᵀμ, i.e. the force on each variable.
  const VectorXd& mu = r.multipliers;
  EXPECT_NEAR(mu(0) + mu(1) + mu(5), 1.0, 1e-7);
  EXPECT_NEAR(2 * mu(2) + mu(3) + mu(5), 2.0, 1e-7);
  EXPECT_NEAR(mu(4), 0.0, 1e-7);
  expect_kkt(problem, r, 1e-8);
  std::printf("[ipopt] rank-deficient constraints: %d iterations, mu = %g %g %g %g %g %g\n", r.iterations,
              mu(0), mu(1), mu(2), mu(3), mu(4), mu(5));
}

// 4. Badly scaled objectives (×1e-9, ×1e+6) give the same x: the objective scaling works.
TEST(IpoptSolver, BadlyScaledObjectiveSameSolution) {
  const MatrixXd A = general_A();
  const VectorXd b = general_b();
  QuadraticProblem reference_problem(spd5(), 5.0 * rhs5(), A, b);
  const IpoptResult ref = solve_with_ipopt(reference_problem, VectorXd::Zero(5), IpoptOptions{});
  ASSERT_TRUE(ref.success) << ref.status_text;
  expect_kkt(reference_problem, ref, 1e-8);
  // The reference has active and inactive bounds and an active sum constraint.
  int active = 0;
  for (Index i = 0; i < 6; ++i) active += ref.constraint_values(i) < 1e-8;
  EXPECT_GE(active, 2);
  EXPECT_LE(active, 5);
  std::printf("[ipopt] general QP scale 1: %d iterations\n", ref.iterations);
  for (double scale : {1e-9, 1e+6}) {
    QuadraticProblem problem(spd5(), 5.0 * rhs5(), A, b, scale);
    const IpoptResult r = solve_with_ipopt(problem, VectorXd::Zero(5), IpoptOptions{});
    ASSERT_TRUE(r.success) << r.status_text << " at scale " << scale;
    EXPECT_LE((r.x - ref.x).lpNorm<Eigen::Infinity>(), 1e-9) << "scale " << scale;
    EXPECT_LE((r.multipliers / scale - ref.multipliers).lpNorm<Eigen::Infinity>(),
              1e-7 * ref.multipliers.lpNorm<Eigen::Infinity>())
        << "scale " << scale;
    std::printf("[ipopt] general QP scale %g: %d iterations\n", scale, r.iterations);
  }
}

// 5. Warm start from the solution and its multipliers: fewer iterations, same x.
TEST(IpoptSolver, WarmStartTakesFewerIterations) {
  QuadraticProblem problem(spd5(), 5.0 * rhs5(), general_A(), general_b());
  const IpoptResult cold = solve_with_ipopt(problem, VectorXd::Zero(5), IpoptOptions{});
  ASSERT_TRUE(cold.success) << cold.status_text;
  IpoptOptions warm_options;
  warm_options.warm_start = true;
  const IpoptResult warm = solve_with_ipopt(problem, cold.x, warm_options, &cold.multipliers);
  ASSERT_TRUE(warm.success) << warm.status_text;
  EXPECT_LT(warm.iterations, cold.iterations);
  EXPECT_LE((warm.x - cold.x).lpNorm<Eigen::Infinity>(), 1e-9);
  EXPECT_LE((warm.multipliers - cold.multipliers).lpNorm<Eigen::Infinity>(), 1e-7);
  std::printf("[ipopt] cold start %d iterations, warm start %d iterations\n", cold.iterations, warm.iterations);

  // Warm start near (not at) the solution of a slightly changed problem, as in a fixed point.
  QuadraticProblem changed(spd5(), 5.0 * rhs5() + VectorXd::Constant(5, 0.01), general_A(), general_b());
  const IpoptResult changed_cold = solve_with_ipopt(changed, VectorXd::Zero(5), IpoptOptions{});
  const IpoptResult changed_warm = solve_with_ipopt(changed, cold.x, warm_options, &cold.multipliers);
  ASSERT_TRUE(changed_cold.success && changed_warm.success);
  EXPECT_LE((changed_warm.x - changed_cold.x).lpNorm<Eigen::Infinity>(), 1e-9);
  std::printf("[ipopt] perturbed problem: cold %d iterations, warm %d iterations\n", changed_cold.iterations,
              changed_warm.iterations);
}

// 6. Infeasible constraints (x ≥ 1 and −x ≥ 0): a failed status, no exception.
TEST(IpoptSolver, InfeasibleProblemReportsFailure) {
  MatrixXd A(2, 1);
  A << 1.0, -1.0;
  VectorXd b(2);
  b << -1.0, 0.0;
  QuadraticProblem problem(MatrixXd::Identity(1, 1), VectorXd::Zero(1), A, b);
  IpoptResult r;
  EXPECT_NO_THROW(r = solve_with_ipopt(problem, VectorXd::Constant(1, 0.5), IpoptOptions{}));
  EXPECT_FALSE(r.success);
  EXPECT_FALSE(r.status_text.empty());
  EXPECT_NE(r.status_text, "Solve_Succeeded");
  EXPECT_EQ(r.x.size(), 1);
  std::printf("[ipopt] infeasible problem: %s (%d) after %d iterations\n", r.status_text.c_str(), r.status,
              r.iterations);
}

// 7. An objective that cannot be evaluated for x ≤ 0: IPOPT backs off and converges to x = 1.
TEST(IpoptSolver, EvaluationErrorMakesIpoptBackOff) {
  LogProblem problem(1);
  const IpoptResult r = solve_with_ipopt(problem, VectorXd::Constant(1, 2.0), IpoptOptions{});
  ASSERT_TRUE(r.success) << r.status_text;
  EXPECT_NEAR(r.x(0), 1.0, 1e-9);
  EXPECT_GT(problem.failed_evaluations, 0);  // the full Newton step from 2 lands on x = 0
  std::printf("[ipopt] -log(x) + x from 2: %d iterations, %d failed evaluations\n", r.iterations,
              problem.failed_evaluations);

  // From x0 = 3 the Newton step lands on x = −3, and the halved one on 0: two failures in a row.
  LogProblem from3(1);
  const IpoptResult r3 = solve_with_ipopt(from3, VectorXd::Constant(1, 3.0), IpoptOptions{});
  ASSERT_TRUE(r3.success) << r3.status_text;
  EXPECT_NEAR(r3.x(0), 1.0, 1e-9);
  EXPECT_GE(from3.failed_evaluations, 2);
  std::printf("[ipopt] -log(x) + x from 3: %d iterations, %d failed evaluations\n", r3.iterations,
              from3.failed_evaluations);

  // Two variables; the Hessian pattern of later calls is a sub-pattern of the first one.
  LogProblem problem2(2);
  const IpoptResult r2 = solve_with_ipopt(problem2, VectorXd::Constant(2, 2.0), IpoptOptions{});
  ASSERT_TRUE(r2.success) << r2.status_text;
  EXPECT_NEAR(r2.x(0), 1.0, 1e-9);
  EXPECT_NEAR(r2.x(1), 1.0, 1e-9);
}

TEST(IpoptSolver, EvaluationErrorAtStartIsAFailedSolve) {
  LogProblem problem(1);
  IpoptResult r;
  EXPECT_NO_THROW(r = solve_with_ipopt(problem, VectorXd::Constant(1, -1.0), IpoptOptions{}));
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.status_text.find("Evaluation_Error"), std::string::npos) << r.status_text;
}

TEST(IpoptSolver, HessianOutsideItsPatternIsAContractViolation) {
  LogProblem problem(2, /*bad_pattern=*/true);
  EXPECT_THROW(solve_with_ipopt(problem, VectorXd::Constant(2, 2.0), IpoptOptions{}), std::logic_error);
}

// 8. Invalid user options: std::invalid_argument naming the option.
TEST(IpoptSolver, InvalidUserOptionsThrowNamingTheOption) {
  QuadraticProblem problem(MatrixXd::Identity(2, 2), VectorXd::Ones(2), MatrixXd(0, 2), VectorXd(0));
  auto expect_invalid = [&](const IpoptOptions& o, const std::string& name) {
    try {
      solve_with_ipopt(problem, VectorXd::Zero(2), o);
      ADD_FAILURE() << "no exception for " << name;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  };
  IpoptOptions unknown;
  unknown.string_options["no_such_ipopt_option"] = "yes";
  expect_invalid(unknown, "no_such_ipopt_option");
  IpoptOptions bad_value;
  bad_value.string_options["mu_strategy"] = "sideways";
  expect_invalid(bad_value, "mu_strategy");
  IpoptOptions out_of_range;
  out_of_range.numeric_options["tol"] = -1.0;
  expect_invalid(out_of_range, "tol");
  IpoptOptions not_an_integer;
  not_an_integer.numeric_options["max_iter"] = 2.5;
  expect_invalid(not_an_integer, "max_iter");
  IpoptOptions unknown_int;
  unknown_int.integer_options["max_iterations"] = 3;
  expect_invalid(unknown_int, "max_iterations");

  // Valid user options override the defaults; numbers may come as text (as from a problem file).
  IpoptOptions valid;
  valid.string_options["mu_strategy"] = "monotone";
  valid.string_options["tol"] = "1e-9";
  valid.integer_options["max_iter"] = 50;
  const IpoptResult r = solve_with_ipopt(problem, VectorXd::Zero(2), valid);
  EXPECT_TRUE(r.success) << r.status_text;
  EXPECT_NEAR(r.x(0), 1.0, 1e-9);

  // The same options checked without a solve (as the problem reader does): the same verdicts, the
  // option's name, and for a value out of range the range IPOPT registered.
  try {
    check_ipopt_options(out_of_range);
    ADD_FAILURE() << "tol = -1 accepted";
  } catch (const IpoptOptionError& e) {
    EXPECT_EQ(e.name(), "tol");
    EXPECT_NE(std::string(e.what()).find("out of range, expected a number > 0"), std::string::npos) << e.what();
  }
  for (const IpoptOptions* o : {&unknown, &bad_value, &not_an_integer, &unknown_int})
    EXPECT_THROW(check_ipopt_options(*o), IpoptOptionError);
  EXPECT_NO_THROW(check_ipopt_options(valid));

  IpoptOptions few_iterations;
  few_iterations.integer_options["max_iter"] = 0;
  const IpoptResult r0 = solve_with_ipopt(problem, VectorXd::Zero(2), few_iterations);
  EXPECT_FALSE(r0.success);
  EXPECT_EQ(r0.status_text, "Maximum_Iterations_Exceeded");
}

// 9. Nothing on stdout at print level 0 (successful, failed and logged-to-file solves).
TEST(IpoptSolver, SilentOnStdoutAtPrintLevelZero) {
  VectorXd p(3);
  p << 1.0, -1.0, 2.0;
  QuadraticProblem problem(MatrixXd::Identity(3, 3), p, MatrixXd::Identity(3, 3), VectorXd::Zero(3));
  MatrixXd A(2, 1);
  A << 1.0, -1.0;
  VectorXd b(2);
  b << -1.0, 0.0;
  QuadraticProblem infeasible(MatrixXd::Identity(1, 1), VectorXd::Zero(1), A, b);
  const std::string log_file = ::testing::TempDir() + "symcontact_ipopt_test.log";
  std::remove(log_file.c_str());
  IpoptOptions with_file;
  with_file.output_file = log_file;

  ::testing::internal::CaptureStdout();
  const IpoptResult r = solve_with_ipopt(problem, VectorXd::Zero(3), IpoptOptions{});
  const IpoptResult f = solve_with_ipopt(infeasible, VectorXd::Zero(1), IpoptOptions{});
  const IpoptResult l = solve_with_ipopt(problem, VectorXd::Zero(3), with_file);
  const std::string out = ::testing::internal::GetCapturedStdout();
  EXPECT_TRUE(r.success);
  EXPECT_FALSE(f.success);
  EXPECT_TRUE(l.success);
  EXPECT_EQ(out, "");

  std::ifstream in(log_file);
  std::stringstream log;
  log << in.rdbuf();
  EXPECT_NE(log.str().find("EXIT: Optimal Solution Found"), std::string::npos) << log.str().substr(0, 500);
  std::remove(log_file.c_str());
}

namespace {

/// f(x) = ½ xᵀK x − qᵀx with K the 5-point Laplacian of a g × g grid plus the identity, stored sparse, subject
/// to x_i ≥ −0.01 on every seventh unknown and to one row over them all, Σ x_i ≤ 1: a KKT system with more
/// than 1e4 rows and a dense row, on which MUMPS, left to choose its ordering, takes SCOTCH's nested dissection.
class GridProblem : public ConstrainedProblem {
 public:
  explicit GridProblem(int g) : n_(static_cast<Index>(g) * g) {
    std::vector<Triplet> k, a;
    for (int i = 0; i < g; ++i)
      for (int j = 0; j < g; ++j) {
        const int p = i * g + j;
        k.emplace_back(p, p, 5.0);
        if (i > 0) k.emplace_back(p, p - g, -1.0);
        if (j > 0) k.emplace_back(p, p - 1, -1.0);
      }
    K_.resize(n_, n_);
    K_.setFromTriplets(k.begin(), k.end());
    q_ = VectorXd(n_);
    for (Index p = 0; p < n_; ++p) q_[p] = std::sin(0.37 * static_cast<double>(p));
    int rows = 0;
    for (Index p = 0; p < n_; p += 7) a.emplace_back(rows++, static_cast<int>(p), 1.0);
    for (Index p = 0; p < n_; ++p) a.emplace_back(rows, static_cast<int>(p), -1.0);
    A_.resize(rows + 1, n_);
    A_.setFromTriplets(a.begin(), a.end());
    b_ = VectorXd::Constant(A_.rows(), 0.01);
    b_[rows] = 1.0;
  }
  Index num_variables() const override { return n_; }
  double objective(const VectorXd& x) override {
    return 0.5 * x.dot(K_.selfadjointView<Eigen::Lower>() * x) - q_.dot(x);
  }
  void gradient(const VectorXd& x, VectorXd& g) override { g = K_.selfadjointView<Eigen::Lower>() * x - q_; }
  void hessian_lower(const VectorXd&, SparseMatrix& H) override { H = K_; }
  bool hessian_is_constant() const override { return true; }
  const SparseMatrix& constraint_matrix() const override { return A_; }
  const VectorXd& constraint_offset() const override { return b_; }

 private:
  Index n_;
  SparseMatrix K_, A_;
  VectorXd q_, b_;
};

}  // namespace

// 10. The same sparse problem twice gives the same digits: MUMPS orders it by SCOTCH, whose random sequence
// each solve restarts (optim/ordering_seed.hpp; without that, 6,719 of the 12,100 unknowns differed).
TEST(IpoptSolver, SparseProblemTwiceGivesTheSameDigits) {
  GridProblem problem(110);
  const IpoptResult a = solve_with_ipopt(problem, VectorXd::Zero(problem.num_variables()), IpoptOptions{});
  const IpoptResult b = solve_with_ipopt(problem, VectorXd::Zero(problem.num_variables()), IpoptOptions{});
  ASSERT_TRUE(a.success) << a.status_text;
  ASSERT_TRUE(b.success) << b.status_text;
  EXPECT_GT((a.multipliers.array() > 0).count(), 100);  // many active rows: a real inequality problem
  EXPECT_EQ(a.iterations, b.iterations);
  Index differ = 0;
  for (Index i = 0; i < a.x.size(); ++i) differ += a.x[i] != b.x[i];
  for (Index i = 0; i < a.multipliers.size(); ++i) differ += a.multipliers[i] != b.multipliers[i];
  EXPECT_EQ(differ, 0);
}
