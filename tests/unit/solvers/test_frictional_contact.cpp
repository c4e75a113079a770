// The Coulomb fixed point of a load step (solvers/frictional_contact.hpp) on the 2D contact patch of V3 with
// Coulomb friction μ = 0.3: identical materials, so nothing slips and the answer is the frictionless one; the
// loop converges on a solve to the geometry tolerance, with the thresholds' change below its tolerance and
// the workspace's interior made whole; a loop that cannot converge in its iterations fails, naming them.
#include <gtest/gtest.h>

#include <memory>
#include <sstream>

#include "support/contact_patch_case.hpp"
#include "support/model_case.hpp"
#include "support/temp_folder.hpp"
#include "symcontact/core/error.hpp"
#include "symcontact/solvers/frictional_contact.hpp"

using namespace symcontact;

namespace {

class FrictionalContactTest : public ::testing::Test {
 protected:
  void build(double mu) {
    symcontact::testing::ContactPatchCase c;
    c.mu = mu;
    case_ = symcontact::testing::contact_patch_model(c, folder_.path(), fixed_);
  }
  SolveReport solve(const FrictionalOptions& options, VectorXd& u) {
    const Model& m = *case_->model;
    u = VectorXd::Zero(m.dofs().num_dofs());
    return solve_frictional_contact(m.energy(), fixed_, m.contacts(), m.dofs(), u, options, log_);
  }
  void check_no_slip_answer(const FrictionalOptions& o, const VectorXd& u_frictionless);
  static FrictionalOptions options() {
    FrictionalOptions o;
    o.contact.workspace = std::make_shared<ContactWorkspace>();
    return o;
  }

  symcontact::testing::TempFolder folder_{"frictional_contact"};
  std::unique_ptr<symcontact::testing::ModelCase> case_;
  FixedDofs fixed_;
  std::ostringstream sink_;
  Logger log_{sink_, Verbosity::kQuiet};
};

}  // namespace

TEST_F(FrictionalContactTest, CoulombConvergesToTheFrictionlessAnswerWhenNothingSlips) {
  build(-1.0);
  VectorXd u_frictionless;
  const SolveReport none = solve(options(), u_frictionless);
  EXPECT_EQ(none.coulomb_iterations, 0) << "no Coulomb pair: one solve";
  build(0.3);
  for (const CoulombUpdate update : {CoulombUpdate::kBetweenSolves, CoulombUpdate::kInsideOptimizer}) {
    SCOPED_TRACE(update == CoulombUpdate::kBetweenSolves ? "between solves" : "inside the optimiser");
    FrictionalOptions o = options();
    o.coulomb_update = update;
    check_no_slip_answer(o, u_frictionless);
  }
}

// The thresholds of a 2D pair follow the dense primal interior point (subproblem_solver.hpp,
// pairs_on_dense_primal): its first solve ends at the fixed point; updated between solves, τ = 0 at first,
// the loop iterates.
void FrictionalContactTest::check_no_slip_answer(const FrictionalOptions& o, const VectorXd& u_frictionless) {
  VectorXd u;
  const SolveReport r = solve(o, u);
  if (o.coulomb_update == CoulombUpdate::kBetweenSolves)
    EXPECT_GE(r.coulomb_iterations, 1);
  else
    EXPECT_EQ(r.coulomb_iterations, 0);
  ASSERT_FALSE(r.coulomb_change.empty());
  EXPECT_LT(r.coulomb_change.back(), o.coulomb_tolerance);
  EXPECT_TRUE(r.converged) << "the loop ends on a solve to the geometry tolerance";
  EXPECT_EQ(r.accepted_at_noise_floor, 0.0);
  EXPECT_EQ(r.coulomb_relaxation.size(), r.coulomb_change.size());
  EXPECT_FALSE(o.contact.workspace->interior_pending) << "u is whole when the step ends";
  EXPECT_LT((u - u_frictionless).lpNorm<Eigen::Infinity>(), 1e-6 * u_frictionless.lpNorm<Eigen::Infinity>());
  // The thresholds the step ends with: μ times a pressure close to the patch's p = 0.01 at every node.
  ASSERT_EQ(r.friction_state.nodal_tau.size(), 1u);
  EXPECT_NEAR(r.friction_state.nodal_tau[0].maxCoeff(), 0.3 * 0.01, 0.3 * 0.01 * 0.05);
  EXPECT_GT(r.friction_state.nodal_tau[0].minCoeff(), 0.0);
}

TEST_F(FrictionalContactTest, ALoopOutOfIterationsFailsNamingThemAndLeavesUWhole) {
  build(0.3);
  FrictionalOptions o = options();
  o.coulomb_tolerance = 1e-300;  // unreachable
  o.max_coulomb_iterations = 2;
  VectorXd u;
  try {
    solve(o, u);
    FAIL() << "no SolveError";
  } catch (const SolveError& e) {
    EXPECT_NE(std::string(e.what()).find("the Coulomb fixed point did not converge after 2 iterations"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(o.contact.workspace->interior_pending) << "a failed step leaves u whole too";
  EXPECT_GT(u.lpNorm<Eigen::Infinity>(), 0.0);
}
