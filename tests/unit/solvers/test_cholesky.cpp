// CholeskySolver (solvers/cholesky.hpp): CHOLMOD through its 64-bit interface (cholmod_long.hpp), the one
// code path at every size. Solves checked by their residual (no Eigen decomposition in the test
// executable: under ASan it breaks Gmsh), the analysis reused for a second factorisation, several
// right-hand sides, the failure on an indefinite matrix, and the factor's entry count.
#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>
#include <vector>

#include "symcontact/core/error.hpp"
#include "symcontact/solvers/cholesky.hpp"
#include "symcontact/solvers/cholmod_long.hpp"

using namespace symcontact;

namespace {

/// Lower triangle of the 7-point Laplacian of an m × m × m grid plus shift·I (SPD for shift > 0; with
/// shift < 0 below the smallest eigenvalue, indefinite).
SparseMatrix grid_laplacian_3d(int m, double shift) {
  std::vector<Triplet> t;
  auto id = [m](int i, int j, int k) { return (i * m + j) * m + k; };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < m; ++k) {
        const int a = id(i, j, k);
        t.emplace_back(a, a, 6.0 + shift);
        if (i + 1 < m) t.emplace_back(id(i + 1, j, k), a, -1.0);
        if (j + 1 < m) t.emplace_back(id(i, j + 1, k), a, -1.0);
        if (k + 1 < m) t.emplace_back(id(i, j, k + 1), a, -1.0);
      }
  SparseMatrix lower(m * m * m, m * m * m);
  lower.setFromTriplets(t.begin(), t.end());
  lower.makeCompressed();
  return lower;
}

double relative_residual(const SparseMatrix& lower, const VectorXd& x, const VectorXd& b) {
  return (lower.selfadjointView<Eigen::Lower>() * x - b).norm() / b.norm();
}

}  // namespace

TEST(CholmodLong, IndexIs64Bit) {
  static_assert(std::is_same_v<CholmodSparseMatrix::StorageIndex, CholmodIndex>);
  EXPECT_EQ(sizeof(CholmodIndex), 8u);
  const SparseMatrix a = grid_laplacian_3d(3, 0.5);
  const CholmodSparseMatrix b = to_cholmod_long(a);
  ASSERT_TRUE(b.isCompressed());
  ASSERT_EQ(b.nonZeros(), a.nonZeros());
  for (Index k = 0; k < a.nonZeros(); ++k) {
    EXPECT_EQ(b.innerIndexPtr()[k], a.innerIndexPtr()[k]);
    EXPECT_EQ(b.valuePtr()[k], a.valuePtr()[k]);
  }
}

TEST(CholeskySolver, SolvesToRoundOff) {
  const SparseMatrix k = grid_laplacian_3d(12, 0.1);  // 1,728 unknowns: a supernodal factor
  VectorXd b(k.rows());
  for (Index i = 0; i < b.size(); ++i) b[i] = std::sin(0.37 * static_cast<double>(i)) + 0.5;
  CholeskySolver chol;
  chol.compute(k);
  EXPECT_LT(relative_residual(k, chol.solve(b), b), 1e-13);
  // L holds at least the lower triangle of K, and fills in.
  EXPECT_GT(chol.factor_nonzeros(), static_cast<double>(k.nonZeros()));

  MatrixXd B(k.rows(), 3);
  for (int c = 0; c < 3; ++c) B.col(c) = b * (c + 1.0) + VectorXd::Constant(b.size(), c);
  const MatrixXd X = chol.solve(B);
  for (int c = 0; c < 3; ++c) EXPECT_LT(relative_residual(k, X.col(c), B.col(c)), 1e-13) << "column " << c;
}

TEST(CholeskySolver, ReusesTheAnalysisForANewMatrixOfTheSamePattern) {
  const SparseMatrix k1 = grid_laplacian_3d(8, 0.1);
  const SparseMatrix k2 = grid_laplacian_3d(8, 2.0);
  const VectorXd b = VectorXd::LinSpaced(k1.rows(), -1.0, 2.0);
  CholeskySolver chol;
  chol.analyze(k1);
  chol.factorize(k1);
  const VectorXd x1 = chol.solve(b);
  chol.factorize(k2);  // same pattern, no new analysis
  const VectorXd x2 = chol.solve(b);
  EXPECT_LT(relative_residual(k1, x1, b), 1e-13);
  EXPECT_LT(relative_residual(k2, x2, b), 1e-13);
  EXPECT_GT((x1 - x2).norm(), 0.1 * x1.norm());  // really the second matrix's solution
}

TEST(CholeskySolver, ThrowsOnAnIndefiniteMatrix) {
  // Eigenvalues 3 − 2Σcos: some negative. 2,744 unknowns, so that CHOLMOD chooses a supernodal LLᵀ factor.
  // (On a small matrix, 6³ unknowns, it chooses a simplicial LDLᵀ factor, which factorises this matrix:
  // see factorize() in cholesky.hpp.)
  CholeskySolver chol;
  EXPECT_THROW(chol.compute(grid_laplacian_3d(14, -3.0)), SolveError);
}

TEST(CholeskySolver, SmallSimplicialFactorSolvesToRoundOff) {
  const SparseMatrix k = grid_laplacian_3d(4, 0.5);
  const VectorXd b = VectorXd::LinSpaced(k.rows(), -1.0, 2.0);
  CholeskySolver chol;
  chol.compute(k);
  EXPECT_LT(relative_residual(k, chol.solve(b), b), 1e-13);
}
