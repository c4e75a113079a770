// The stiffness system solved on PETSc by CG + GAMG (src/symcontact/distributed/gamg_elasticity.hpp) against
// the sparse Cholesky solve of the same system, on one rank and, registered a second time under mpirun, on
// two, each rank assembling the stiffness of its own cells: the same answer to 1e-8, and iteration counts
// that stay flat as the mesh is refined.

#include "symcontact/distributed/gamg_elasticity.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "symcontact/distributed/model_problems.hpp"
#include "test_support.hpp"

namespace symcontact {
namespace {

/// The block's system solved with this rank's share of the stiffness (its cells).
GamgResult solve(int dim, int n) {
  const BlockSystem b = clamped_block_system(dim, n, g_petsc->rank(), g_petsc->size());
  return solve_elasticity_gamg(b.K_lower, b.f, b.fixed, b.fixed_values, b.mesh.x);
}

TEST(GamgElasticity, EqualsTheCholeskySolveIn2DAnd3D) {
  for (const auto& [dim, n] : {std::pair{2, 24}, std::pair{3, 8}}) {
    const BlockSystem b = clamped_block_system(dim, n);
    const GamgResult r = solve(dim, n);
    ASSERT_TRUE(r.converged) << r.reason;
    const VectorXd u = cholesky_solution(b.K_lower, b.f, b.fixed, b.fixed_values);
    const double error = (r.u - u).norm() / u.norm();
    if (g_petsc->rank() == 0)
      std::printf("dim %d, %lld DOFs: %d CG iterations, %d levels, relative residual %.2e, against Cholesky %.2e\n",
                  dim, static_cast<long long>(u.size()), r.iterations, r.levels, r.relative_residual, error);
    EXPECT_LE(r.relative_residual, 1e-10);
    EXPECT_LE(error, 1e-8);
    for (std::size_t k = 0; k < b.fixed.size(); ++k)
      EXPECT_EQ(r.u[b.fixed[k]], b.fixed_values[static_cast<Index>(k)]) << "the fixed values, exactly";
  }
}

// The parts' shares of the stiffness (their cells') sum to the whole stiffness, whatever the number of parts.
TEST(GamgElasticity, TheSharesOfTheStiffnessSumToIt) {
  const SparseMatrix whole = clamped_block_system(3, 5).K_lower;
  for (const int parts : {2, 3}) {
    SparseMatrix sum(whole.rows(), whole.cols());
    for (int p = 0; p < parts; ++p) {
      const SparseMatrix share = clamped_block_system(3, 5, p, parts).K_lower;
      EXPECT_LT(share.nonZeros(), whole.nonZeros());
      sum += share;
    }
    EXPECT_LE((sum - whole).cwiseAbs().sum(), 1e-12 * whole.cwiseAbs().sum()) << parts << " parts";
  }
}

// Smoothed aggregation with the rigid-body modes: the CG iterations stay within ±30 % of their mean as the
// cube is refined from 8 to 20 divisions (3D: 2.2e3 to 2.8e4 DOFs).
TEST(GamgElasticity, IterationsStayFlatUnderRefinement) {
  std::vector<int> its;
  for (const int n : {8, 12, 16, 20}) {
    const GamgResult r = solve(3, n);
    ASSERT_TRUE(r.converged) << r.reason;
    its.push_back(r.iterations);
    if (g_petsc->rank() == 0)
      std::printf("3D, %d divisions, %lld DOFs: %d CG iterations, %d levels\n", n, static_cast<long long>(r.u.size()),
                  r.iterations, r.levels);
  }
  double mean = 0.0;
  for (int i : its) mean += i;
  mean /= static_cast<double>(its.size());
  for (int i : its) EXPECT_NEAR(i, mean, 0.3 * mean);
}

}  // namespace
}  // namespace symcontact
