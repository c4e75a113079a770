// The dense equality-constrained step (solvers/dense_kkt.hpp): the direct range-space solve against the
// KKT conditions, and projected CG preconditioned by one matrix's factor against the direct solve of
// another, changed by small blocks — what the polish's later Newton steps see when only the friction
// Hessian (one block per contact node) moved. Random SPD cases, with a dependent constraint row.
#include <memory>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "symcontact/solvers/dense_kkt.hpp"

using namespace symcontact;

namespace {

constexpr Index kN = 40, kM = 10;

/// m × n, each row touching 4 consecutive DOFs; the last row is twice row 0 (dependent rows, as the two
/// families of a symmetric contact pair nearly are).
SparseMatrix random_constraints(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Triplet> t;
  std::vector<double> row0(4);
  for (int i = 0; i < kM - 1; ++i)
    for (int k = 0; k < 4; ++k) {
      const double v = u(rng);
      if (i == 0) row0[k] = v;
      t.emplace_back(i, 4 * i + k, v);
    }
  for (int k = 0; k < 4; ++k) t.emplace_back(kM - 1, k, 2.0 * row0[k]);
  SparseMatrix A(kM, kN);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

MatrixXd random_spd(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  MatrixXd B(kN, kN);
  for (Index i = 0; i < kN; ++i)
    for (Index j = 0; j < kN; ++j) B(i, j) = u(rng);
  return B * B.transpose() + static_cast<double>(kN) * MatrixXd::Identity(kN, kN);
}

/// Rank-one 2 × 2 blocks s t tᵀ on `nodes` DOF pairs (s up to `scale`): a regularised friction Hessian.
MatrixXd block_change(std::mt19937& rng, int nodes, double scale) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  MatrixXd D = MatrixXd::Zero(kN, kN);
  for (int k = 0; k < nodes; ++k) {
    const Index d = 2 * static_cast<Index>(u(rng) * (kN / 2 - 1));
    const double a = 2 * M_PI * u(rng), s = scale * u(rng);
    Eigen::Vector2d t(std::cos(a), std::sin(a));
    D.block(d, d, 2, 2) += s * t * t.transpose();
  }
  return D;
}

/// The direct solver for K (M = K + ρ AᵀA factorised by Eigen, copied into dpotrf storage).
std::unique_ptr<DenseRangeSpace> factorise(const MatrixXd& K, const SparseMatrix& A, double rho) {
  const MatrixXd M = K + rho * MatrixXd(A.transpose() * A);
  Eigen::LLT<MatrixXd> llt(M);
  EXPECT_EQ(llt.info(), Eigen::Success);
  auto L = std::make_shared<AlignedMatrix>(kN, kN);
  L->map() = llt.matrixL();
  return std::make_unique<DenseRangeSpace>(L, A, rho);
}

struct Case {
  SparseMatrix A;
  MatrixXd K;
  VectorXd h, c;
};

Case random_case(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Case k{random_constraints(rng), random_spd(rng), VectorXd(kN), VectorXd(kM)};
  for (Index i = 0; i < kN; ++i) k.h[i] = u(rng);
  for (Index i = 0; i < kM; ++i) k.c[i] = u(rng);
  k.c[kM - 1] = 2.0 * k.c[0];  // consistent with the dependent row
  return k;
}

}  // namespace

TEST(DenseKkt, RangeSpaceSolveSatisfiesTheKktConditions) {
  const Case k = random_case(1);
  const auto f = factorise(k.K, k.A, 0.7);
  VectorXd y, lambda;
  f->solve(k.h, k.c, y, lambda);
  EXPECT_LE((k.K * y - k.A.transpose() * lambda + k.h).lpNorm<Eigen::Infinity>(), 1e-12 * k.h.lpNorm<Eigen::Infinity>());
  EXPECT_LE((k.A * y + k.c).lpNorm<Eigen::Infinity>(), 1e-12);
  // λ ∈ range(A): the dependent rows share the force as the minimum norm asks (row 9 = 2 row 0).
  EXPECT_NEAR(lambda[kM - 1], 2.0 * lambda[0], 1e-12 * lambda.lpNorm<Eigen::Infinity>());
}

// The polish's use: K' = K + a change of block rank one per node; projected CG preconditioned by K's
// factor against the refactorised direct solve of K', to 1e-12.
TEST(DenseKkt, ProjectedCgWithAnOldFactorEqualsTheRefactorisedSolve) {
  for (const unsigned seed : {2u, 3u, 4u}) {
    for (const double scale : {1.0, 1e3}) {
      const Case k = random_case(seed);
      std::mt19937 rng(seed + 100);
      const MatrixXd K1 = k.K + block_change(rng, 6, scale);
      const auto f0 = factorise(k.K, k.A, 0.7);
      const auto f1 = factorise(K1, k.A, 0.7);
      VectorXd y_ref, lambda_ref;
      f1->solve(k.h, k.c, y_ref, lambda_ref);
      const double scale_y = y_ref.lpNorm<Eigen::Infinity>();
      VectorXd y, lambda;
      f0->solve(k.h, k.c, y, lambda);  // the old matrix's step: visibly another answer
      EXPECT_GT((y - y_ref).lpNorm<Eigen::Infinity>(), 1e-4 * scale_y);
      auto multiply = [&](const VectorXd& x, VectorXd& out) { out = K1 * x; };
      const ProjectedCgResult r = projected_cg(*f0, multiply, k.h, k.c, y, lambda, 1e-15 * scale_y, 50);
      ASSERT_TRUE(r.converged) << "seed " << seed << " scale " << scale;
      // six rank-one blocks: at most 7 iterations in exact arithmetic
      EXPECT_LE(r.iterations, 12) << "seed " << seed << " scale " << scale;
      EXPECT_LE((y - y_ref).lpNorm<Eigen::Infinity>(), 1e-12 * scale_y) << "seed " << seed << " scale " << scale;
      EXPECT_LE((lambda - lambda_ref).lpNorm<Eigen::Infinity>(), 1e-12 * lambda_ref.lpNorm<Eigen::Infinity>())
          << "seed " << seed << " scale " << scale;
      EXPECT_LE((k.A * y + k.c).lpNorm<Eigen::Infinity>(), 1e-12);
    }
  }
}

TEST(DenseKkt, ProjectedCgWithTheSameMatrixNeedsNoIteration) {
  const Case k = random_case(5);
  const auto f = factorise(k.K, k.A, 0.7);
  VectorXd y_ref, lambda_ref, y, lambda;
  f->solve(k.h, k.c, y_ref, lambda_ref);
  auto multiply = [&](const VectorXd& x, VectorXd& out) { out = k.K * x; };
  const ProjectedCgResult r = projected_cg(*f, multiply, k.h, k.c, y, lambda, 1e-13 * y_ref.lpNorm<Eigen::Infinity>(), 50);
  ASSERT_TRUE(r.converged);
  EXPECT_LE(r.iterations, 1);
  EXPECT_LE((y - y_ref).lpNorm<Eigen::Infinity>(), 1e-12 * y_ref.lpNorm<Eigen::Infinity>());
  EXPECT_LE((lambda - lambda_ref).lpNorm<Eigen::Infinity>(), 1e-12 * lambda_ref.lpNorm<Eigen::Infinity>());
}

// K' indefinite on null(A): a direction of negative curvature stops the iteration unconverged (the polish
// then refactorises, and its factorisation reports the failure).
TEST(DenseKkt, ProjectedCgReportsAnIndefiniteMatrix) {
  const Case k = random_case(6);
  const auto f = factorise(k.K, k.A, 0.7);
  const MatrixXd K1 = k.K - 10.0 * static_cast<double>(kN) * MatrixXd::Identity(kN, kN);
  VectorXd y, lambda;
  auto multiply = [&](const VectorXd& x, VectorXd& out) { out = K1 * x; };
  const ProjectedCgResult r = projected_cg(*f, multiply, k.h, k.c, y, lambda, 1e-13, 50);
  EXPECT_FALSE(r.converged);
}

// The polish's rounds: the range space on a subset of the rows, restricted from the one on all of them,
// solves as the one formed on the subset itself, to 1e-12; rows that are not increasing are refused.
TEST(DenseKkt, RangeSpaceOnASubsetOfTheRowsEqualsTheOneFormedOnIt) {
  const Case k = random_case(5);
  const auto all = factorise(k.K, k.A, 0.0);
  const std::vector<Index> keep = {0, 2, 3, 7, kM - 1};
  std::vector<Triplet> t;
  for (int j = 0; j < k.A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(k.A, j); it; ++it)
      for (std::size_t r = 0; r < keep.size(); ++r)
        if (it.row() == keep[r]) t.emplace_back(static_cast<int>(r), j, it.value());
  SparseMatrix As(static_cast<Index>(keep.size()), kN);
  As.setFromTriplets(t.begin(), t.end());
  VectorXd cs(static_cast<Index>(keep.size()));
  for (std::size_t r = 0; r < keep.size(); ++r) cs[static_cast<Index>(r)] = k.c[keep[r]];
  const DenseRangeSpace restricted(*all, keep, As);
  const auto formed = factorise(k.K, As, 0.0);
  VectorXd y1, l1, y2, l2;
  restricted.solve(k.h, cs, y1, l1);
  formed->solve(k.h, cs, y2, l2);
  EXPECT_LE((y1 - y2).lpNorm<Eigen::Infinity>(), 1e-12 * y2.lpNorm<Eigen::Infinity>());
  EXPECT_LE((l1 - l2).lpNorm<Eigen::Infinity>(), 1e-12 * l2.lpNorm<Eigen::Infinity>());
  EXPECT_LE((As * y1 + cs).lpNorm<Eigen::Infinity>(), 1e-12);
  EXPECT_THROW(DenseRangeSpace(*all, std::vector<Index>{2, 0, 3, 7, 9}, As), std::invalid_argument);
}
