// The dense interior point for min ½xᵀWx − dᵀx, x ≥ 0, Gx = e (solvers/dense_qp_interior_point.hpp): a case
// with a known solution, random semidefinite cases checked against the KKT conditions (which, the problem
// being convex, characterise the minimum), a warm start, and the failures it must report as failures.
#include <memory>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "symcontact/solvers/dense_qp_interior_point.hpp"

using namespace symcontact;

namespace {

std::unique_ptr<AlignedMatrix> aligned(const MatrixXd& A) {
  auto M = std::make_unique<AlignedMatrix>(A.rows(), A.cols());
  M->map() = A;
  return M;
}

struct RandomQp {
  MatrixXd W, G;
  VectorXd d, e;
};

/// W = BᵀB of rank r < m (semidefinite, as W = A S⁺ Aᵀ with dependent rows), k equality rows with a feasible
/// x ≥ 0 (e = G x_f), d such that part of the bounds is active at the solution.
RandomQp random_qp(Index m, Index r, Index k, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  RandomQp q;
  MatrixXd B(r, m);
  for (Index i = 0; i < r; ++i)
    for (Index j = 0; j < m; ++j) B(i, j) = u(rng);
  q.W = B.transpose() * B;
  q.d.resize(m);
  for (Index i = 0; i < m; ++i) q.d[i] = 2.0 * u(rng);
  q.G.resize(k, m);
  for (Index i = 0; i < k; ++i)
    for (Index j = 0; j < m; ++j) q.G(i, j) = 1.0 + 0.5 * u(rng);  // positive rows: bounded feasible set
  VectorXd xf(m);
  for (Index j = 0; j < m; ++j) xf[j] = 0.5 + 0.5 * u(rng);
  q.e = q.G * xf;
  return q;
}

/// max of the KKT violations, each relative to its scale.
double kkt_violation(const RandomQp& q, const DenseQpResult& r) {
  const VectorXd rd = q.W * r.x - q.d - q.G.transpose() * r.beta - r.z;
  const double s = std::max(1.0, q.d.lpNorm<Eigen::Infinity>());
  double v = rd.lpNorm<Eigen::Infinity>() / s;
  if (q.G.rows() > 0) v = std::max(v, (q.G * r.x - q.e).lpNorm<Eigen::Infinity>() / std::max(1.0, q.e.lpNorm<Eigen::Infinity>()));
  v = std::max(v, -r.x.minCoeff());
  v = std::max(v, -r.z.minCoeff() / s);
  v = std::max(v, r.x.cwiseProduct(r.z).maxCoeff() / s);
  return v;
}

}  // namespace

TEST(DenseQpInteriorPoint, DiagonalProblemHasTheClosedFormSolution) {
  // W = diag(w): x_i = max(0, d_i / w_i), z_i = max(0, −d_i). (No d_i = 0: there x_i = z_i = 0 is degenerate, and
  // an interior point reaches it only to about √μ.)
  const VectorXd w = (VectorXd(6) << 1.0, 2.0, 4.0, 0.5, 3.0, 1.5).finished();
  const VectorXd d = (VectorXd(6) << 1.0, -2.0, 0.4, -0.1, 3.0, -0.7).finished();
  const auto W = aligned(w.asDiagonal().toDenseMatrix());
  DenseQpOptions o;
  o.tolerance = 1e-12;
  const DenseQpResult r = solve_dense_qp(*W, d, MatrixXd(0, 6), VectorXd(0), o);
  ASSERT_TRUE(r.success) << r.status;
  for (Index i = 0; i < 6; ++i) {
    EXPECT_NEAR(r.x[i], std::max(0.0, d[i] / w[i]), 1e-10) << i;
    EXPECT_NEAR(r.z[i], std::max(0.0, -d[i]), 1e-10) << i;
  }
}

TEST(DenseQpInteriorPoint, ScalingTheObjectiveScalesOnlyTheBoundMultipliers) {
  // W and d times 1e-9 (the dual of a lightly loaded contact problem: measured ‖d‖∞ = 2e-9 on the inclined
  // interface): the same x, z times 1e-9, to the same relative accuracy — the tests are relative, not absolute.
  const RandomQp q = random_qp(30, 20, 1, 11);
  DenseQpOptions o;
  o.tolerance = 1e-11;
  const DenseQpResult r1 = solve_dense_qp(*aligned(q.W), q.d, q.G, q.e, o);
  const DenseQpResult r2 = solve_dense_qp(*aligned(1e-9 * q.W), 1e-9 * q.d, q.G, q.e, o);
  ASSERT_TRUE(r1.success) << r1.status;
  ASSERT_TRUE(r2.success) << r2.status;
  EXPECT_LT((r2.x - r1.x).lpNorm<Eigen::Infinity>(), 1e-7 * r1.x.lpNorm<Eigen::Infinity>());
  EXPECT_LT((1e9 * r2.z - r1.z).lpNorm<Eigen::Infinity>(), 1e-7 * r1.z.lpNorm<Eigen::Infinity>());
}

TEST(DenseQpInteriorPoint, SemidefiniteWithEqualitiesSatisfiesKkt) {
  for (unsigned seed : {1u, 2u, 3u, 4u}) {
    for (Index k : {0, 1, 3}) {
      const RandomQp q = random_qp(40, 25, k, seed);
      DenseQpOptions o;
      o.tolerance = 1e-11;
      const DenseQpResult r = solve_dense_qp(*aligned(q.W), q.d, q.G, q.e, o);
      ASSERT_TRUE(r.success) << r.status << " seed " << seed << " k " << k;
      EXPECT_LT(kkt_violation(q, r), 1e-9) << "seed " << seed << " k " << k;
      EXPECT_LT(r.iterations, 40);
      // Not a trivial case: some bounds active, some not.
      int active = 0;
      for (Index i = 0; i < 40; ++i) active += r.x[i] < 1e-8;
      EXPECT_GT(active, 0) << "seed " << seed;
      EXPECT_LT(active, 40) << "seed " << seed;
    }
  }
}

TEST(DenseQpInteriorPoint, WarmStartFromTheSolutionNeedsFewerIterations) {
  const RandomQp q = random_qp(40, 25, 2, 7);
  const auto W = aligned(q.W);
  DenseQpOptions o;
  o.tolerance = 1e-11;
  const DenseQpResult cold = solve_dense_qp(*W, q.d, q.G, q.e, o);
  ASSERT_TRUE(cold.success) << cold.status;
  // Start from a nearby problem's solution: d perturbed by 1 %.
  RandomQp p = q;
  p.d *= 1.01;
  const DenseQpResult near = solve_dense_qp(*W, p.d, p.G, p.e, o);
  ASSERT_TRUE(near.success);
  const DenseQpResult warm = solve_dense_qp(*W, q.d, q.G, q.e, o, &near.x, &near.z, &near.beta);
  ASSERT_TRUE(warm.success) << warm.status;
  EXPECT_LT(kkt_violation(q, warm), 1e-9);
  EXPECT_LT(warm.iterations, cold.iterations);
  EXPECT_LT((warm.x - cold.x).lpNorm<Eigen::Infinity>(), 1e-7 * cold.x.lpNorm<Eigen::Infinity>());
}

TEST(DenseQpInteriorPoint, InfeasibleOrUnboundedProblemsAreNotReportedAsSolved) {
  // x ≥ 0 with Σx = −1: infeasible.
  const auto W = aligned(MatrixXd::Identity(3, 3));
  const VectorXd d = VectorXd::Ones(3);
  DenseQpOptions o;
  o.max_iterations = 60;
  const DenseQpResult r = solve_dense_qp(*W, d, MatrixXd::Ones(1, 3), VectorXd::Constant(1, -1.0), o);
  EXPECT_FALSE(r.success);
  EXPECT_FALSE(r.status.empty());
  // W = 0 and d > 0: the objective falls without bound along x ≥ 0.
  const DenseQpResult u = solve_dense_qp(*aligned(MatrixXd::Zero(3, 3)), d, MatrixXd(0, 3), VectorXd(0), o);
  EXPECT_FALSE(u.success);
}

TEST(DenseQpInteriorPoint, SizesAreChecked) {
  const auto W = aligned(MatrixXd::Identity(3, 3));
  EXPECT_THROW(solve_dense_qp(*W, VectorXd::Ones(2), MatrixXd(0, 3), VectorXd(0), {}), std::invalid_argument);
  EXPECT_THROW(solve_dense_qp(*W, VectorXd::Ones(3), MatrixXd::Ones(1, 2), VectorXd::Ones(1), {}),
               std::invalid_argument);
  const VectorXd x0 = VectorXd::Ones(3);
  EXPECT_THROW(solve_dense_qp(*W, VectorXd::Ones(3), MatrixXd(0, 3), VectorXd(0), {}, &x0, nullptr),
               std::invalid_argument);
}
