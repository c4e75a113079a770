// The distributed path's tests: every rank runs every test (the solves are collective); only rank 0 reports.

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>

#include "test_support.hpp"

namespace symcontact {

const PetscSession* g_petsc = nullptr;

VectorXd cholesky_solution(const SparseMatrix& K_lower, const VectorXd& f, const std::vector<Index>& fixed,
                           const VectorXd& fixed_values) {
  const Index n = f.size();
  VectorXd u = VectorXd::Zero(n);
  std::vector<Index> free_index(n, 0);
  for (std::size_t k = 0; k < fixed.size(); ++k) {
    u[fixed[k]] = fixed_values[static_cast<Index>(k)];
    free_index[fixed[k]] = -1;
  }
  Index nf = 0;
  for (Index& i : free_index)
    if (i == 0) i = nf++;
  const SparseMatrix K = SparseMatrix(K_lower.selfadjointView<Eigen::Lower>());
  const VectorXd rhs_all = f - K * u;
  std::vector<Triplet> t;
  for (int j = 0; j < K.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(K, j); it; ++it)
      if (free_index[it.row()] >= 0 && free_index[j] >= 0) t.emplace_back(free_index[it.row()], free_index[j], it.value());
  SparseMatrix Kff(nf, nf);
  Kff.setFromTriplets(t.begin(), t.end());
  VectorXd rhs(nf);
  for (Index i = 0; i < n; ++i)
    if (free_index[i] >= 0) rhs[free_index[i]] = rhs_all[i];
  const VectorXd uf = Eigen::SimplicialLLT<SparseMatrix>(Kff).solve(rhs);
  for (Index i = 0; i < n; ++i)
    if (free_index[i] >= 0) u[i] = uf[free_index[i]];
  return u;
}

}  // namespace symcontact

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  const symcontact::PetscSession petsc(&argc, &argv);
  symcontact::g_petsc = &petsc;
  if (petsc.rank() != 0) delete ::testing::UnitTest::GetInstance()->listeners().Release(
      ::testing::UnitTest::GetInstance()->listeners().default_result_printer());
  return RUN_ALL_TESTS();
}
