// The pivoted factor of a positive semidefinite matrix (solvers/semidefinite_factor.hpp): its rank, its
// null basis and its generalised inverse, on random matrices of known rank.
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "symcontact/core/error.hpp"
#include "symcontact/solvers/semidefinite_factor.hpp"

using namespace symcontact;

namespace {

/// S = B Bᵀ with B n × r random: positive semidefinite of rank r.
MatrixXd random_psd(Index n, Index r, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  MatrixXd B(n, r);
  for (Index i = 0; i < n; ++i)
    for (Index j = 0; j < r; ++j) B(i, j) = u(rng);
  return B * B.transpose();
}

SparseMatrix lower(const MatrixXd& S) { return MatrixXd(S.triangularView<Eigen::Lower>()).sparseView(); }

/// S⁺ R a column at a time.
MatrixXd apply_pinv(const SemidefiniteFactor& f, const MatrixXd& R) {
  MatrixXd out(R.rows(), R.cols());
  for (Index j = 0; j < R.cols(); ++j) out.col(j) = f.solve(R.col(j));
  return out;
}

}  // namespace

TEST(SemidefiniteFactor, FindsTheRankAndAnOrthonormalNullBasis) {
  for (const Index rank : {20, 19, 17, 12}) {
    const MatrixXd S = random_psd(20, rank, 7 + static_cast<unsigned>(rank));
    const SemidefiniteFactor f(lower(S), 1e-10);
    EXPECT_EQ(f.rank(), rank);
    const MatrixXd& N = f.null_basis();
    ASSERT_EQ(N.cols(), 20 - rank);
    if (N.cols() == 0) continue;
    EXPECT_LT((N.transpose() * N - MatrixXd::Identity(N.cols(), N.cols())).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((S * N).cwiseAbs().maxCoeff(), 1e-12 * S.cwiseAbs().maxCoeff());
    EXPECT_LT(f.null_residual(), 1e-12);
  }
}

TEST(SemidefiniteFactor, IsAGeneralisedInverseAndItsGramMatrixOfSparseRows) {
  for (const Index rank : {20, 18}) {
    const MatrixXd S = random_psd(20, rank, 3 + static_cast<unsigned>(rank));
    const SemidefiniteFactor f(lower(S), 1e-10);
    // S S⁺ S = S, and for a definite S, S⁺ = S⁻¹.
    const MatrixXd SpS = apply_pinv(f, S);
    EXPECT_LT((S * SpS - S).cwiseAbs().maxCoeff(), 1e-9 * S.cwiseAbs().maxCoeff()) << "rank " << rank;
    if (rank == 20) {
      EXPECT_LT((SpS - MatrixXd::Identity(20, 20)).cwiseAbs().maxCoeff(), 1e-8);
    }
    // gram(R) = Rᵀ S⁺ R, for a sparse R with an empty column (a zero row and column of the result).
    MatrixXd R = random_psd(20, 3, 99).leftCols(4);
    R.col(2).setZero();
    for (Index i = 0; i < 20; i += 3) R.row(i).setZero();
    const MatrixXd expected = R.transpose() * apply_pinv(f, R);
    const auto G = f.gram(SparseMatrix(R.sparseView()));
    ASSERT_EQ(G->rows(), 4);
    const MatrixXd lower_g = G->map().triangularView<Eigen::Lower>();
    const MatrixXd lower_e = expected.triangularView<Eigen::Lower>();
    EXPECT_LT((lower_g - lower_e).cwiseAbs().maxCoeff(), 1e-9 * expected.cwiseAbs().maxCoeff()) << "rank " << rank;
    EXPECT_EQ(G->map().col(2).cwiseAbs().maxCoeff() + G->map().row(2).cwiseAbs().maxCoeff(), 0.0);
  }
}

TEST(SemidefiniteFactor, ItsGramMatrixOverSeveralPanelsOfRowsAndColumns) {
  // n = 53 of rank 50 and k = 37 sparse columns: the product runs over 16-wide panels with a partial last one.
  const MatrixXd S = random_psd(53, 50, 11);
  const SemidefiniteFactor f(lower(S), 1e-10);
  ASSERT_EQ(f.rank(), 50);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  MatrixXd R = MatrixXd::Zero(53, 37);
  for (Index j = 0; j < 37; ++j)
    for (int e = 0; e < 1 + j % 9; ++e) R(static_cast<Index>(rng() % 53), j) = u(rng);
  const MatrixXd expected = R.transpose() * apply_pinv(f, R);
  const auto G = f.gram(SparseMatrix(R.sparseView()));
  ASSERT_EQ(G->rows(), 37);
  EXPECT_LT((G->map() - expected).cwiseAbs().maxCoeff(), 1e-9 * expected.cwiseAbs().maxCoeff());  // both triangles
}

TEST(SemidefiniteFactor, RejectsANegativeOrZeroDiagonal) {
  MatrixXd S = MatrixXd::Identity(3, 3);
  S(1, 1) = -1.0;
  EXPECT_THROW(SemidefiniteFactor(lower(S), 1e-10), SolveError);
  EXPECT_THROW(SemidefiniteFactor(lower(MatrixXd::Zero(3, 3)), 1e-10), SolveError);
}
