// The choice between the serial solver and the distributed path (src/symcontact/app/linear_solver_choice.hpp):
// the problem file's word when it gives one; automatic: the serial solver unless the distributed path solves
// the problem and either the serial solver's dense work on the contact surface costs more than the iterative
// solve, or the predicted peak of its contact solve is above the memory available.

#include "symcontact/app/linear_solver_choice.hpp"

#include <gtest/gtest.h>

#include <string>

#include "symcontact/core/error.hpp"

#include "support/model_case.hpp"
#include "support/problem_snippet.hpp"
#include "support/rectangle_msh.hpp"
#include "support/temp_folder.hpp"

namespace symcontact {
namespace {

/// The 2 × 1 block clamped at the bottom, its top against a rigid plane, with `contact` and `solver` added
/// to its [[contact]] and [contact_solver] tables.
std::unique_ptr<testing::ModelCase> block(const testing::TempFolder& folder, const std::string& contact,
                                          const std::string& solver) {
  testing::write_rectangle_msh(folder.path() / "block.msh", 2.0, 1.0, 4, 2);
  return testing::build_model(testing::clamped_block("E = 1000.0, nu = 0.25") +
                                  "[[contact]]\na = \"block.top\"\n" + contact +
                                  "[contact.obstacle]\ntype = \"plane\"\npoint = [0.0, 1.5]\nnormal = [0.0, -1.0]\n"
                                  "[contact_solver]\n" + solver,
                              folder.path());
}

TEST(LinearSolverChoice, TheProblemFilesWordIsKept) {
  const testing::TempFolder folder;
  const auto direct = block(folder, "", "linear_solver = \"direct\"\n");
  EXPECT_FALSE(choose_linear_solver(direct->spec, *direct->model, MemoryBudget{1.0, 0.0}).iterative);  // fits nowhere
  const auto iterative = block(folder, "", "linear_solver = \"iterative\"\n");
  EXPECT_TRUE(choose_linear_solver(iterative->spec, *iterative->model, MemoryBudget{1e15, 0.0}).iterative);
}

TEST(LinearSolverChoice, AutomaticTakesTheIterativePathWhenTheFactorDoesNotFit) {
  const testing::TempFolder folder;
  const auto c = block(folder, "", "linear_solver = \"automatic\"\n");
  const LinearSolverDecision fits = choose_linear_solver(c->spec, *c->model, MemoryBudget{1e12, 0.0});
  EXPECT_FALSE(fits.iterative) << fits.reason;
  EXPECT_NE(fits.reason.find("predicted peak"), std::string::npos) << fits.reason;
  const LinearSolverDecision tight = choose_linear_solver(c->spec, *c->model, MemoryBudget{1e3, 0.0});
  EXPECT_TRUE(tight.iterative) << tight.reason;
  // Below the size of the check, no prediction: the serial solver.
  EXPECT_FALSE(choose_linear_solver(c->spec, *c->model, MemoryBudget{1e3, 1e9}).iterative);
  // Unknown memory: the serial solver.
  EXPECT_FALSE(choose_linear_solver(c->spec, *c->model, MemoryBudget{-1.0, 0.0}).iterative);
}

TEST(LinearSolverChoice, AutomaticKeepsTheSerialSolverForWhatTheDistributedPathDoesNotSolve) {
  const testing::TempFolder folder;
  EXPECT_TRUE(distributed_path_limit(block(folder, "", "")->spec).none());
  // Coulomb friction on order-1 and order-2 elements (friction points that mix nodes: their slip maps): solved;
  // a hyperelastic body with friction: not; without: solved.
  const auto c = block(folder, "friction = \"coulomb\"\nmu = 0.3\n", "");
  EXPECT_TRUE(distributed_path_limit(c->spec).none());
  EXPECT_TRUE(choose_linear_solver(c->spec, *c->model, MemoryBudget{1e3, 0.0}).iterative);
  c->spec.order = 2;
  EXPECT_TRUE(distributed_path_limit(c->spec).none());
  MaterialSpec& material = c->spec.bodies[0].materials[0];
  material.model = "neo_hookean";
  const LinearSolverDecision d = choose_linear_solver(c->spec, *c->model, MemoryBudget{1e3, 0.0});
  EXPECT_FALSE(d.iterative);
  EXPECT_NE(d.reason.find(material.key + ".model"), std::string::npos) << d.reason;
  EXPECT_EQ(distributed_path_limit(c->spec).key, material.key + ".model");
  EXPECT_NE(distributed_path_limit(c->spec).message.find("contact[0].friction"), std::string::npos);
  c->spec.contacts[0].friction = "none";
  EXPECT_TRUE(distributed_path_limit(c->spec).none());
}

TEST(LinearSolverChoice, TheDistributedPathSolvesPairsOfEveryModeWithAndWithoutFriction) {
  const testing::TempFolder folder;
  const auto c = block(folder, "", "");
  ContactSpec& pair = c->spec.contacts[0];  // the rule reads the specification only: made a pair here
  pair.obstacle.reset();
  pair.body_b = "other";
  pair.boundary_b = "bottom";
  for (const char* mode : {"one-pass", "symmetric"})
    for (const char* friction : {"none", "tresca", "coulomb"}) {
      pair.mode = mode;
      pair.friction = friction;
      EXPECT_TRUE(distributed_path_limit(c->spec).none()) << mode << ", " << friction;
    }
  pair.body_b = pair.body_a;  // a surface in contact with itself
  pair.boundary_b = pair.boundary_a;
  EXPECT_TRUE(distributed_path_limit(c->spec).none());
  pair.body_b = "other";
  pair.boundary_b = "bottom";
  // Solved, but not measured for the cost part of the rule: the serial solver unless it does not fit.
  pair.friction = "none";
  const LinearSolverDecision d = choose_linear_solver(c->spec, *c->model, MemoryBudget{1e12, 1e9, 1e-3});
  EXPECT_FALSE(d.iterative) << d.reason;
  EXPECT_NE(d.reason.find("contact[0] is between elastic bodies"), std::string::npos) << d.reason;
}

TEST(LinearSolverChoice, PredictsTheCondensedDofsFromTheContactRows) {
  const testing::TempFolder folder;
  // The block's top: 5 nodes, free, their rows reading u_y (the plane's normal); with friction both DOFs.
  const auto frictionless = block(folder, "", "");
  EXPECT_EQ(predicted_condensed_dofs(frictionless->spec, *frictionless->model), 5);
  const auto coulomb = block(folder, "friction = \"coulomb\"\nmu = 0.3\n", "");
  EXPECT_EQ(predicted_condensed_dofs(coulomb->spec, *coulomb->model), 10);
}

TEST(LinearSolverChoice, AutomaticTakesTheIterativePathWhenTheDenseWorkCostsMore) {
  const testing::TempFolder folder;
  const auto c = block(folder, "friction = \"coulomb\"\nmu = 0.3\n", "");
  // |B| = 10 of 20 free DOFs: 333 flops of dense work against 20 × the iterative path's cost per DOF.
  const LinearSolverDecision cheap = choose_linear_solver(c->spec, *c->model, MemoryBudget{1e12, 1e9, 20.0});
  EXPECT_FALSE(cheap.iterative) << cheap.reason;
  const LinearSolverDecision dear = choose_linear_solver(c->spec, *c->model, MemoryBudget{1e12, 1e9, 10.0});
  EXPECT_TRUE(dear.iterative) << dear.reason;
  EXPECT_NE(dear.reason.find("|B| = 10 condensed DOFs"), std::string::npos) << dear.reason;
  // The measured cost: the serial solver on a problem this small.
  EXPECT_FALSE(choose_linear_solver(c->spec, *c->model, MemoryBudget{1e12, 1e9}).iterative);
  // Not against a curved obstacle (the distributed path solves it, the rule keeps it serial).
  const auto curved = block(folder, "", "");
  curved->spec.contacts[0].obstacle->type = "circle";
  const LinearSolverDecision d = choose_linear_solver(curved->spec, *curved->model, MemoryBudget{1e12, 1e9, 1e-3});
  EXPECT_FALSE(d.iterative) << d.reason;
  EXPECT_NE(d.reason.find("contact[0]"), std::string::npos) << d.reason;
  // Not for what the distributed path does not solve.
  c->spec.bodies[0].materials[0].model = "neo_hookean";
  EXPECT_FALSE(choose_linear_solver(c->spec, *c->model, MemoryBudget{1e12, 1e9, 1e-3}).iterative);
}

// With friction, where the condensation would cost more than a sparse factorisation of K_ff, the serial solver
// takes the uncondensed problem (solvers/condensation_cache.hpp, kDenseOverSparse), and the rule weighs that
// cost: a long 2D strip, |B| = 1,602 (the top's 801 nodes, both DOFs), 1.4e9 flops condensed against far less
// for the strip's banded K_ff, stays serial where the iterative path is worth 3.2e7.
TEST(LinearSolverChoice, AutomaticWeighsTheUncondensedSerialPathWithFriction) {
  const testing::TempFolder folder;
  testing::write_rectangle_msh(folder.path() / "block.msh", 800.0, 1.0, 800, 2);
  const auto c = testing::build_model(
      testing::clamped_block("E = 1000.0, nu = 0.25") +
          "[[contact]]\na = \"block.top\"\nfriction = \"coulomb\"\nmu = 0.3\n"
          "[contact.obstacle]\ntype = \"plane\"\npoint = [0.0, 1.5]\nnormal = [0.0, -1.0]\n",
      folder.path());
  ASSERT_EQ(predicted_condensed_dofs(c->spec, *c->model), 1602);
  const LinearSolverDecision d = choose_linear_solver(c->spec, *c->model, MemoryBudget{1e12, 1e9, 1e4});
  EXPECT_FALSE(d.iterative) << d.reason;
  EXPECT_NE(d.reason.find("uncondensed instead: a sparse factorisation of K_ff"), std::string::npos) << d.reason;
  // Without friction the serial solver stays condensed (the dual), and its dense work is what is weighed.
  c->spec.contacts[0].friction = "none";
  EXPECT_TRUE(choose_linear_solver(c->spec, *c->model, MemoryBudget{1e12, 1e9, 1e2}).iterative);
}

/// serial_only_choice(): the InputError it throws, or "" when it throws none.
std::string serial_only_error(const testing::ModelCase& c, const MemoryBudget& budget) {
  try {
    serial_only_choice(c.spec, *c.model, budget);
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "contact_solver.linear_solver");
    return e.message();
  }
  return "";
}

TEST(LinearSolverChoice, TheSerialOnlyProgramSaysWhatTheDirectSolverCannotDo) {
  const testing::TempFolder folder;
  const auto c = block(folder, "friction = \"coulomb\"\nmu = 0.3\n", "linear_solver = \"automatic\"\n");
  // Fits, and the dense work is cheap: the serial solver, as choose_linear_solver says.
  const LinearSolverDecision fits = serial_only_choice(c->spec, *c->model, MemoryBudget{1e12, 0.0, 20.0});
  EXPECT_FALSE(fits.iterative);
  EXPECT_EQ(fits.reason, choose_linear_solver(c->spec, *c->model, MemoryBudget{1e12, 0.0, 20.0}).reason);
  // The dense work costs more: still the serial solver, saying that `symcontact run` would not take it.
  const LinearSolverDecision dear = serial_only_choice(c->spec, *c->model, MemoryBudget{1e12, 0.0, 10.0});
  EXPECT_FALSE(dear.iterative);
  EXPECT_EQ(dear.basis, DecisionBasis::kDenseWork);
  EXPECT_NE(dear.reason.find("`symcontact run` would take the iterative path (|B| = 10 condensed DOFs"),
            std::string::npos) << dear.reason;
  // Predicted not to fit: an input error with the figures, before any solve.
  const std::string tight = serial_only_error(*c, MemoryBudget{1e3, 0.0, 20.0});
  EXPECT_NE(tight.find("predicted not to fit in memory (predicted peak"), std::string::npos) << tight;
  EXPECT_NE(tight.find("symcontact run"), std::string::npos) << tight;
  // Asked for in the file: an input error.
  const auto iterative = block(folder, "", "linear_solver = \"iterative\"\n");
  EXPECT_NE(serial_only_error(*iterative, MemoryBudget{1e12, 0.0}).find("asks for \"iterative\""), std::string::npos);
  // Not to fit where the distributed path does not solve the problem either: the serial solver, warned.
  c->spec.bodies[0].materials[0].model = "neo_hookean";
  const LinearSolverDecision hyperelastic = serial_only_choice(c->spec, *c->model, MemoryBudget{1e3, 0.0, 20.0});
  EXPECT_FALSE(hyperelastic.iterative);
  EXPECT_EQ(hyperelastic.basis, DecisionBasis::kMemory);
}

}  // namespace
}  // namespace symcontact
