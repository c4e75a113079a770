// The geometry fixed point and its stages (solvers/contact_solver.hpp) on the 2D contact patch of V3 (two
// blocks pressed together through a non-matching interface, 4 and 5 divisions): every subproblem method
// and the static condensation on or off give the same answer, each method is taken where it should be, the
// workspace carries the factorisation and the warm start to the next solve, and a fixed point that cannot
// converge in its iterations fails with a message naming them.
#include <gtest/gtest.h>

#include <memory>
#include <sstream>

#include "support/contact_patch_case.hpp"
#include "support/model_case.hpp"
#include "support/temp_folder.hpp"
#include "symcontact/core/error.hpp"
#include "symcontact/solvers/contact_solver.hpp"

using namespace symcontact;

namespace {

struct Solved {
  VectorXd u;
  SolveReport report;
};

class ContactSolverTest : public ::testing::Test {
 protected:
  /// The patch in `mode` ("symmetric": two-sided rows; "one-pass": independent rows), at its one load step.
  void build(const std::string& mode) {
    symcontact::testing::ContactPatchCase c;
    c.mode = mode;
    case_ = symcontact::testing::contact_patch_model(c, folder_.path(), fixed_);
  }
  Solved solve(const ContactSolveOptions& options) {
    const Model& m = *case_->model;
    Solved s;
    s.u = VectorXd::Zero(m.dofs().num_dofs());
    s.report = solve_contact(m.energy(), fixed_, m.contacts(), m.dofs(), s.u, options, log_);
    return s;
  }
  static ContactSolveOptions options(SubproblemSolver method, bool condensed) {
    ContactSolveOptions o;
    o.subproblem_solver = method;
    o.static_condensation = condensed;
    o.ipopt.tolerance = 1e-11;
    o.geometry_tolerance = 1e-9;
    return o;
  }

  symcontact::testing::TempFolder folder_{"contact_solver"};
  std::unique_ptr<symcontact::testing::ModelCase> case_;
  FixedDofs fixed_;
  std::ostringstream sink_;
  Logger log_{sink_, Verbosity::kQuiet};
};

double relative_difference(const VectorXd& a, const VectorXd& b) {
  return (a - b).lpNorm<Eigen::Infinity>() / b.lpNorm<Eigen::Infinity>();
}

void expect_same_answer(const Solved& s, const Solved& ref, const std::string& what) {
  EXPECT_LT(relative_difference(s.u, ref.u), 1e-7) << what;
  EXPECT_LT(relative_difference(s.report.contact_force, ref.report.contact_force), 1e-7) << what;
}

}  // namespace

TEST_F(ContactSolverTest, EveryMethodGivesTheSameAnswerOnSymmetricAndOnePassPairs) {
  for (const std::string mode : {"symmetric", "one-pass"}) {
    SCOPED_TRACE(mode);
    build(mode);
    const Solved primal_whole = solve(options(SubproblemSolver::kPrimalIpopt, false));
    EXPECT_EQ(primal_whole.report.num_condensed, 0);
    EXPECT_EQ(primal_whole.report.dual_solves, 0);
    EXPECT_TRUE(primal_whole.report.converged);
    const Solved primal = solve(options(SubproblemSolver::kPrimalIpopt, true));
    EXPECT_GT(primal.report.num_condensed, 0);
    EXPECT_EQ(primal.report.dual_solves, 0);
    expect_same_answer(primal, primal_whole, "condensed primal");
    for (SubproblemSolver dual : {SubproblemSolver::kDualIpopt, SubproblemSolver::kDualInteriorPoint}) {
      const Solved s = solve(options(dual, true));
      EXPECT_EQ(s.report.dual_solves, s.report.geometry_iterations) << "every iteration through the dual";
      expect_same_answer(s, primal_whole, "dual");
      // The dense interior point on both kinds of rows (the symmetric pair's nearly dependent ones too).
      const bool interior_point = dual == SubproblemSolver::kDualInteriorPoint;
      // (its later solves may close the previous solution's active set instead: dual_subproblem.hpp)
      const std::string& status = s.report.ipopt_status;
      const bool dense = status.rfind("interior point", 0) == 0 || status.rfind("previous active set closed", 0) == 0;
      EXPECT_EQ(dense, interior_point) << status;
    }
    // Without condensation there is no dual: the primal is solved whatever the choice.
    const Solved whole = solve(options(SubproblemSolver::kDualInteriorPoint, false));
    EXPECT_EQ(whole.report.dual_solves, 0);
    expect_same_answer(whole, primal_whole, "whole, dual asked");
  }
}

TEST_F(ContactSolverTest, TheRecoveredContactForcesBalanceTheLoadAndTheMultipliers) {
  build("symmetric");
  const Solved s = solve(options(SubproblemSolver::kDualIpopt, true));
  const SolveReport& r = s.report;
  // Each side of the interface carries the load p × 1 = 0.01, the two sides in opposite directions.
  const Model& m = *case_->model;
  std::vector<double> vertical;
  for (const ContactSurface& surface : m.contacts().surfaces) {
    double f = 0.0;
    for (Index node : surface.nodes) f += r.contact_force[m.dofs().dof(surface.body, node, 1)];
    vertical.push_back(f);
  }
  ASSERT_EQ(vertical.size(), 2u);
  EXPECT_NEAR(std::abs(vertical[0]), 0.01, 1e-9);
  EXPECT_NEAR(vertical[0] + vertical[1], 0.0, 1e-12);
  // Closed by the dual, the multipliers' force is the residual's to round-off.
  EXPECT_LT(r.force_defect.lpNorm<Eigen::Infinity>(), 1e-10 * r.contact_force.lpNorm<Eigen::Infinity>());
  EXPECT_LT(relative_difference(r.multiplier_force, r.contact_force), 1e-8);
}

TEST_F(ContactSolverTest, TheWorkspaceCarriesTheFactorisationAndTheWarmStart) {
  build("symmetric");
  ContactSolveOptions o = options(SubproblemSolver::kDualIpopt, true);
  o.workspace = std::make_shared<ContactWorkspace>();
  const Solved first = solve(o);
  EXPECT_GE(first.report.condensation_factorisations, 1);  // more when the zone leaves the condensed set
  EXPECT_EQ(o.workspace->multipliers.size(), first.report.num_constraints);
  const Solved again = solve(o);
  EXPECT_EQ(again.report.condensation_factorisations, 0) << "the factor of the first solve serves";
  EXPECT_LE(again.report.ipopt_iterations, first.report.ipopt_iterations);
  expect_same_answer(again, first, "second solve");
}

TEST_F(ContactSolverTest, AFixedPointOutOfIterationsFailsNamingThem) {
  build("symmetric");
  ContactSolveOptions o = options(SubproblemSolver::kDualIpopt, true);
  o.max_geometry_iterations = 1;
  const Model& m = *case_->model;
  VectorXd u = VectorXd::Zero(m.dofs().num_dofs());
  try {
    solve_contact(m.energy(), fixed_, m.contacts(), m.dofs(), u, o, log_);
    FAIL() << "no SolveError";
  } catch (const SolveError& e) {
    EXPECT_NE(std::string(e.what()).find("did not converge in 1 iterations"), std::string::npos) << e.what();
  }
  EXPECT_GT(u.lpNorm<Eigen::Infinity>(), 0.0) << "u holds the last iterate";
}
