// Tests of the equilibrium check of a load step's answer (src/symcontact/post/step_checks.hpp): a solved
// step passes; the same answer moved off equilibrium fails, also when the step's forces are all round-off
// and the force scale is the body's floor F_b = kRoundOffStrain (λ + 2μ) L^(dim−1). A contact surface whose
// nodes are all held by Dirichlet conditions: held into the obstacle it fails, held on it in contact it warns
// (an overconstraint).

#include "symcontact/post/step_checks.hpp"

#include <gtest/gtest.h>

#include <string>

#include "support/model_case.hpp"
#include "support/problem_snippet.hpp"
#include "support/rectangle_msh.hpp"
#include "support/temp_folder.hpp"
#include "symcontact/contact/contact_state.hpp"
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


/// The clamped block's bottom in contact with the plane y = 0 (every row of the contact held: each is a
/// combination of the bottom nodes' uy, all prescribed), its state at u with multipliers μ = `force`.
struct HeldContact {
  testing::TempFolder folder;
  std::unique_ptr<testing::ModelCase> c = block(folder, "[[contact]]\nname = \"floor\"\na = \"block.bottom\"\n"
                                                        "[contact.obstacle]\ntype = \"plane\"\npoint = [0.0, 0.0]\n"
                                                        "normal = [0.0, 1.0]\n");
  ContactState state(const VectorXd& u, double force) const {
    ContactState s;
    s.linearization = c->model->contacts().linearize(c->model->dofs(), u);
    s.multipliers = VectorXd::Constant(s.linearization.A.rows(), force);
    return s;
  }
};

TEST(StepChecks, ANodeHeldIntoTheObstacleFailsAndOneHeldInContactWarns) {
  const HeldContact h;
  Model& model = *h.c->model;
  const FixedDofs fixed = model.fixed_dofs(1);
  VectorXd u = VectorXd::Zero(model.dofs().num_dofs());
  const ContactState open = h.state(u, 0.0), pressed = h.state(u, 1.0);
  EXPECT_TRUE(check_step(model, u, fixed, &open).warnings.empty());
  const std::vector<std::string> warnings = check_step(model, u, fixed, &pressed).warnings;
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("(an overconstraint)"), std::string::npos) << warnings[0];
  // 2 % of the element size 0.5 into the plane: within the weak contact's slack of the global check, yet
  // every DOF of the gaps is prescribed.
  for (const double x : {0.0, 0.5, 1.0, 1.5, 2.0}) u[dof_at(model, x, 0.0, 1)] = -0.01;
  const ContactState inside = h.state(u, 1.0);
  try {
    check_step(model, u, fixed, &inside);
    FAIL() << "expected a SolveError";
  } catch (const SolveError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("contact 'floor'"), std::string::npos) << what;
    EXPECT_NE(what.find("held there by its Dirichlet conditions"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace symcontact
