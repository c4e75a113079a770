// RowUpdatedFactor (solvers/row_updated_factor.hpp): solves with M' = M ± ρ a aᵀ for rows that join or leave
// the set of a factorised M = H + ρ A_SᵀA_S, checked by the residual of M' itself, with the large ρ of the
// active-set start (the leaving rows' cancellation), and against a factorisation of M'.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/quadratic_energy.hpp"
#include "symcontact/solvers/row_updated_factor.hpp"

using namespace symcontact;
using symcontact::testing::grid_laplacian;

namespace {

/// Row r of A: three entries of unit largest size (the active-set start's scaled rows).
std::vector<Triplet> row_entries(int r, int n) {
  return {Triplet(r, (7 * r) % n, 1.0), Triplet(r, (7 * r + 3) % n, -0.5), Triplet(r, (7 * r + 11) % n, 0.25)};
}

/// A_S for the rows `set` (as rows 0, 1, … of the result).
SparseMatrix rows_of(const std::vector<int>& set, int n) {
  std::vector<Triplet> t;
  for (std::size_t k = 0; k < set.size(); ++k)
    for (const Triplet& e : row_entries(set[k], n)) t.emplace_back(static_cast<int>(k), e.col(), e.value());
  SparseMatrix A(static_cast<Index>(set.size()), n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

SparseMatrix gram_lower(const SparseMatrix& A) {
  return SparseMatrix(A.transpose() * A).triangularView<Eigen::Lower>();
}

}  // namespace

TEST(RowUpdatedFactor, SolvesWithTheMatrixOfTheNewSet) {
  const int m = 15, n = m * m;
  const double rho = 1e3 * 4.1;  // 1e3 × H's diagonal (kSparseRho)
  const SparseMatrix H = grid_laplacian(m, 0.1);
  std::vector<int> old_set, new_set, joined, left;
  for (int r = 0; r < 10; ++r) old_set.push_back(r);
  for (int r = 2; r < 13; ++r) new_set.push_back(r);
  left = {0, 1};
  joined = {10, 11, 12};
  SpdFactor factor(false);
  const SparseMatrix AtA_old = gram_lower(rows_of(old_set, n));
  ASSERT_TRUE(factor.compute(H, nullptr, &AtA_old, rho));

  std::vector<int> changed = joined;
  changed.insert(changed.end(), left.begin(), left.end());
  const SparseMatrix U = SparseMatrix(rows_of(changed, n).transpose());
  VectorXd c(static_cast<Index>(changed.size()));
  for (std::size_t k = 0; k < changed.size(); ++k) c[static_cast<Index>(k)] = k < joined.size() ? rho : -rho;
  const RowUpdatedFactor updated(factor, U, c);
  ASSERT_TRUE(updated.valid());

  const SparseMatrix M_new = SparseMatrix(H + rho * gram_lower(rows_of(new_set, n)));
  VectorXd r(n);
  for (int i = 0; i < n; ++i) r[i] = std::sin(1.0 + i);
  const VectorXd y = updated.solve(r);
  const VectorXd residual = VectorXd(M_new.selfadjointView<Eigen::Lower>() * y) - r;
  // Relative to ‖r‖: a solve that missed a changed row leaves a residual of order ρ ‖y‖.
  EXPECT_LT(residual.lpNorm<Eigen::Infinity>(), 1e-10 * r.lpNorm<Eigen::Infinity>());

  SpdFactor fresh(false);
  const SparseMatrix AtA_new = gram_lower(rows_of(new_set, n));
  ASSERT_TRUE(fresh.compute(H, nullptr, &AtA_new, rho));
  const VectorXd y_fresh = fresh.solve(r);
  EXPECT_LT((y - y_fresh).lpNorm<Eigen::Infinity>(), 1e-10 * y_fresh.lpNorm<Eigen::Infinity>());
  // Without the update the old factor is far off (the test can tell the two apart).
  EXPECT_GT((factor.solve(r) - y_fresh).lpNorm<Eigen::Infinity>(), 1e-3 * y_fresh.lpNorm<Eigen::Infinity>());
}

TEST(RowUpdatedFactor, NoChangedRowIsTheFactorItself) {
  const int m = 8, n = m * m;
  const SparseMatrix H = grid_laplacian(m, 1.0);
  SpdFactor factor(false);
  ASSERT_TRUE(factor.compute(H, nullptr, nullptr, 0.0));
  const RowUpdatedFactor updated(factor, SparseMatrix(n, 0), VectorXd(0));
  ASSERT_TRUE(updated.valid());
  const VectorXd r = VectorXd::LinSpaced(n, -1.0, 2.0);
  EXPECT_EQ(updated.solve(r), factor.solve(r));
}
