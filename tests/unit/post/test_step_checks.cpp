// Tests of the equilibrium check of a load step's answer (src/symcontact/post/step_checks.hpp): a solved
// step passes; the same answer moved off equilibrium fails, also when the step's forces are all round-off
// and the force scale is the body's floor F_b = kRoundOffStrain (λ + 2μ) L^(dim−1).

#include "symcontact/post/step_checks.hpp"

#include <gtest/gtest.h>

#include <string>

#include "support/model_case.hpp"
#include "support/problem_snippet.hpp"
#include "support/rectangle_msh.hpp"
#include "support/temp_folder.hpp"
#include "symcontact/core/error.hpp"
#include "symcontact/solvers/equilibrium_solver.hpp"

namespace symcontact {
namespace {

/// The 2 × 1 block (4 × 2 squares: 3 interior nodes) clamped at the bottom, E = 1000, ν = 0.25
/// (λ + 2μ = 1200), with `extra` appended.
std::unique_ptr<testing::ModelCase> block(const testing::TempFolder& folder, const std::string& extra) {
  testing::write_rectangle_msh(folder.path() / "block.msh", 2.0, 1.0, 4, 2);
  return testing::build_model(testing::clamped_block("E = 1000.0, nu = 0.25") + extra, folder.path());
}

/// The displacement DOF of component `comp` at the node (x, y).
Index dof_at(const Model& model, double x, double y, int comp) {
  const Mesh& mesh = model.bodies()[0]->mesh;
  for (Index a = 0; a < mesh.num_nodes(); ++a)
    if (std::abs(mesh.x(0, a) - x) < 1e-12 && std::abs(mesh.x(1, a) - y) < 1e-12) return model.dofs().dof(0, a, comp);
  ADD_FAILURE() << "no node at (" << x << ", " << y << ")";
  return 0;
}

TEST(StepChecks, SolvedStepPassesAndAMovedNodeFails) {
  const testing::TempFolder folder;
  const auto c = block(folder, "[[body.traction]]\nboundary = \"top\"\ntraction = [0.5, -1.0]\n");
  Model& model = *c->model;
  model.set_step(1);
  const FixedDofs fixed = model.fixed_dofs(1);
  VectorXd u = VectorXd::Zero(model.dofs().num_dofs());
  solve_equilibrium(model.energy(), fixed, u);
  EXPECT_LT(check_step(model, u, fixed, nullptr).equilibrium, 1e-12);
  u[dof_at(model, 1.0, 0.5, 0)] += 1e-4;  // an interior node off its place: a force of order E × 1e-4
  EXPECT_THROW(check_step(model, u, fixed, nullptr), SolveError);
}

TEST(StepChecks, WithoutLoadsTheFloorStillCatchesAMovedNode) {
  // No load, nothing imposed but zero: every force is 0 and the scale is the floor
  // F = 1e-8 × 1200 × √5 (L = √5, the diagonal of the 2 × 1 block).
  const testing::TempFolder folder;
  const auto c = block(folder, "");
  Model& model = *c->model;
  const FixedDofs fixed = model.fixed_dofs(1);
  VectorXd u = VectorXd::Zero(model.dofs().num_dofs());
  EXPECT_EQ(check_step(model, u, fixed, nullptr).equilibrium, 0.0);
  u[dof_at(model, 1.0, 0.5, 1)] = 1e-12;  // a residual of order E × 1e-12 = 1e-9, 37 times 1e-6 F
  try {
    check_step(model, u, fixed, nullptr);
    FAIL() << "expected a SolveError";
  } catch (const SolveError& e) {
    EXPECT_NE(std::string(e.what()).find("force scale 2.68e-05"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace symcontact
