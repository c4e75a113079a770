// Tests of the Newton solver without contact (src/symcontact/solvers/equilibrium_solver.hpp): a quadratic
// energy solved exactly in one step, a Neo-Hookean block compressed by its Dirichlet values to a small
// residual (and to the linear answer at small strain), the Dirichlet predictor, and the SolveErrors.

#include "symcontact/solvers/equilibrium_solver.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <memory>
#include <string>

#include "support/model_case.hpp"
#include "support/problem_snippet.hpp"
#include "support/quadratic_energy.hpp"
#include "support/rectangle_msh.hpp"
#include "support/temp_folder.hpp"
#include "symcontact/core/error.hpp"

namespace symcontact {
namespace {

using testing::ProblemSnippet;

/// ‖∇E(u)‖ on the free DOFs of `fixed`, and on the fixed ones (the reactions).
struct Residuals {
  double free = 0.0, fixed = 0.0;
};
Residuals residuals(const EnergyTerm& energy, const FixedDofs& fixed, const VectorXd& u) {
  VectorXd g = VectorXd::Zero(u.size());
  energy.add_gradient(u, g);
  std::vector<Index> free_index;
  fixed.free_numbering(u.size(), free_index);
  Residuals r;
  for (Index d = 0; d < u.size(); ++d) (free_index[d] >= 0 ? r.free : r.fixed) += g[d] * g[d];
  r.free = std::sqrt(r.free);
  r.fixed = std::sqrt(r.fixed);
  return r;
}

TEST(EquilibriumSolver, QuadraticEnergyIsSolvedExactlyInOneStep) {
  // E = ½ uᵀK u − fᵀu on a 5 × 5 grid Laplacian (singular alone), held by three Dirichlet DOFs.
  const SparseMatrix k = testing::grid_laplacian(5, 0.0);
  const VectorXd f = VectorXd::LinSpaced(25, 1.0, -0.5);
  const testing::QuadraticEnergy energy(k, f);
  FixedDofs fixed;
  fixed.fix(0, 0.2);
  fixed.fix(12, -0.1);
  fixed.fix(24, 0.3);
  VectorXd u = VectorXd::Constant(25, 7.0);  // any start: the fixed values are imposed, the rest solved
  const EquilibriumReport rep = solve_equilibrium(energy, fixed, u);
  EXPECT_EQ(rep.iterations, 1);
  EXPECT_EQ(rep.num_free, 22);
  EXPECT_EQ(u[0], 0.2);
  EXPECT_EQ(u[12], -0.1);
  EXPECT_EQ(u[24], 0.3);
  // Dense reference: K_ff u_f = f_f − K_fD u_D.
  const MatrixXd kd = MatrixXd(k).selfadjointView<Eigen::Lower>();
  std::vector<Index> free;
  for (Index d = 0; d < 25; ++d)
    if (d != 0 && d != 12 && d != 24) free.push_back(d);
  MatrixXd kff(22, 22);
  VectorXd rhs(22);
  for (Index i = 0; i < 22; ++i) {
    rhs[i] = f[free[i]] - kd(free[i], 0) * 0.2 - kd(free[i], 12) * -0.1 - kd(free[i], 24) * 0.3;
    for (Index j = 0; j < 22; ++j) kff(i, j) = kd(free[i], free[j]);
  }
  const VectorXd uf = kff.llt().solve(rhs);
  for (Index i = 0; i < 22; ++i) EXPECT_NEAR(u[free[i]], uf[i], 1e-12 * uf.lpNorm<Eigen::Infinity>());
}

TEST(EquilibriumSolver, RigidMotionLeftFreeIsASolveError) {
  // The same Laplacian with nothing fixed: constants are in its kernel and the loads do not balance.
  const testing::QuadraticEnergy energy(testing::grid_laplacian(4, 0.0), VectorXd::Ones(16));
  VectorXd u = VectorXd::Zero(16);
  EXPECT_THROW(solve_equilibrium(energy, FixedDofs(), u), SolveError);
}

TEST(EquilibriumSolver, PredictorOfAQuadraticEnergyOnlyImposesTheValues) {
  const testing::QuadraticEnergy energy(testing::grid_laplacian(3, 0.1), VectorXd::Zero(9));
  FixedDofs fixed;
  fixed.fix(4, 1.5);
  VectorXd u = VectorXd::LinSpaced(9, 0.0, 8.0);
  const VectorXd before = u;
  EXPECT_EQ(predict_dirichlet_increment(energy, fixed, u), 1.0);
  EXPECT_EQ(u[4], 1.5);
  for (Index d = 0; d < 9; ++d)
    if (d != 4) {
      EXPECT_EQ(u[d], before[d]);
    }
}

/// A unit square of Neo-Hookean material (E = 1, ν = 0.3; 4 × 4 squares), clamped at its bottom, its top
/// moved down by `down` (times the load factors 0.5, 1) with ux = 0.
const ProblemSnippet kSquare = testing::clamped_block("model = \"neo_hookean\", E = 1.0, nu = 0.3") +
                               testing::dirichlet_toml("top", "ux = 0.0\nuy = -0.2\n");

class EquilibriumSolverModel : public ::testing::Test {
 protected:
  std::unique_ptr<testing::ModelCase> build(const std::string& text) const {
    testing::write_rectangle_msh(folder_ / "block.msh", 1.0, 1.0, 4, 4);
    return testing::build_model(text, folder_.path());
  }
  const testing::TempFolder folder_;
};

TEST_F(EquilibriumSolverModel, NeoHookeanCompressionConvergesToASmallResidual) {
  const auto c = build(kSquare);
  const Model& m = *c->model;
  const FixedDofs fixed = m.fixed_dofs(1);  // 20 % compression in one solve: the boundary is sub-stepped
  VectorXd u = VectorXd::Zero(m.dofs().num_dofs());
  const EquilibriumReport rep = solve_equilibrium(m.energy(), fixed, u);
  EXPECT_GT(rep.iterations, 1);  // not quadratic
  VectorXd imposed = u;
  fixed.impose(imposed);
  EXPECT_LT((u - imposed).lpNorm<Eigen::Infinity>(), 1e-15) << "the Dirichlet values are reached";
  const Residuals r = residuals(m.energy(), fixed, u);
  EXPECT_GT(r.fixed, 0.01);  // the support's reactions: the block is compressed
  EXPECT_LT(r.free, 1e-11 * r.fixed);
  EXPECT_NEAR(rep.residual, r.free, 1e-14);
}

TEST_F(EquilibriumSolverModel, NeoHookeanAtSmallStrainIsLinearElasticity) {
  const std::string small = kSquare.replaced("uy = -0.2", "uy = -1e-6");
  const auto nh = build(small);
  const auto lin = build(ProblemSnippet(small).replaced("model = \"neo_hookean\", ", ""));
  VectorXd u_nh = VectorXd::Zero(nh->model->dofs().num_dofs()), u_lin = u_nh;
  solve_equilibrium(nh->model->energy(), nh->model->fixed_dofs(1), u_nh);
  solve_equilibrium(lin->model->energy(), lin->model->fixed_dofs(1), u_lin);
  // The difference is of the order of the strain (1e-6) relative to u.
  EXPECT_LT((u_nh - u_lin).lpNorm<Eigen::Infinity>(), 1e-4 * u_lin.lpNorm<Eigen::Infinity>());
  EXPECT_GT(u_lin.lpNorm<Eigen::Infinity>(), 0.9e-6);
}

TEST_F(EquilibriumSolverModel, DirichletPredictorFollowsTheTangent) {
  const auto c = build(kSquare.replaced("uy = -0.2", "uy = -0.1"));
  const Model& m = *c->model;
  VectorXd u = VectorXd::Zero(m.dofs().num_dofs());
  solve_equilibrium(m.energy(), m.fixed_dofs(0), u);  // converged at 5 % compression
  const FixedDofs next = m.fixed_dofs(1);              // 10 %
  // Imposing the new values alone leaves the free DOFs out of balance; the predictor's linearised
  // response K_ff Δu_f = −K_fD Δu_D leaves a residual of second order in the increment.
  VectorXd jumped = u;
  next.impose(jumped);
  VectorXd predicted = u;
  EXPECT_EQ(predict_dirichlet_increment(m.energy(), next, predicted), 1.0);
  VectorXd imposed = predicted;
  next.impose(imposed);
  EXPECT_LT((predicted - imposed).lpNorm<Eigen::Infinity>(), 1e-15) << "a full step reaches the new values";
  const double before = residuals(m.energy(), next, jumped).free;
  const double after = residuals(m.energy(), next, predicted).free;
  EXPECT_LT(after, 0.02 * before) << "before " << before << ", after " << after;
  // At the values already imposed there is nothing to predict.
  VectorXd same = imposed;
  EXPECT_EQ(predict_dirichlet_increment(m.energy(), next, same), 1.0);
  EXPECT_EQ(same, imposed);
}

TEST_F(EquilibriumSolverModel, NewtonThatDoesNotConvergeInTimeIsASolveError) {
  const auto c = build(kSquare);
  VectorXd u = VectorXd::Zero(c->model->dofs().num_dofs());
  EquilibriumOptions options;
  options.max_iterations = 1;
  EXPECT_THROW(solve_equilibrium(c->model->energy(), c->model->fixed_dofs(1), u, options), SolveError);
}

}  // namespace
}  // namespace symcontact
