// The Coulomb law as a lagged term (solvers/coulomb_thresholds.hpp) on the 2D contact patch of V3 with
// Coulomb friction μ = 0.3: a first step starts cold (τ = 0); a later one from the previous step's thresholds,
// extrapolated along their increment (from 0 after a first step) and clamped at 0; start_cold() drops that
// start; the residual of a frictionless solve is μ p with p the patch's pressure at every node; the update is
// projected onto τ ≥ 0.
#include <gtest/gtest.h>

#include <memory>
#include <sstream>

#include "support/contact_patch_case.hpp"
#include "support/model_case.hpp"
#include "support/temp_folder.hpp"
#include "symcontact/solvers/contact_solver.hpp"
#include "symcontact/solvers/coulomb_thresholds.hpp"

using namespace symcontact;

namespace {

class CoulombThresholdsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    symcontact::testing::ContactPatchCase c;
    c.mu = 0.3;
    case_ = symcontact::testing::contact_patch_model(c, folder_.path(), fixed_);
    u_ = VectorXd::Zero(model().dofs().num_dofs());
  }
  const Model& model() const { return *case_->model; }
  CoulombThresholds make(const FrictionState* previous, double s = 0.0) const {
    return CoulombThresholds(model().contacts(), model().dofs(), u_, previous, s, log_);
  }

  symcontact::testing::TempFolder folder_{"coulomb_thresholds"};
  std::unique_ptr<symcontact::testing::ModelCase> case_;
  FixedDofs fixed_;
  VectorXd u_;
  std::ostringstream sink_;
  Logger log_{sink_, Verbosity::kQuiet};
};

}  // namespace

TEST_F(CoulombThresholdsTest, AFirstStepStartsCold) {
  const CoulombThresholds t = make(nullptr);
  EXPECT_TRUE(t.any_friction());
  EXPECT_TRUE(t.lags());
  EXPECT_FALSE(t.warm());
  ASSERT_EQ(t.data().size(), 1u);
  ASSERT_GT(t.data()[0].size(), 0);
  EXPECT_EQ(t.data()[0].lpNorm<Eigen::Infinity>(), 0.0);
  EXPECT_EQ(t.state().u_start.size(), u_.size());
}

TEST_F(CoulombThresholdsTest, ALaterStepStartsFromThePreviousThresholdsExtrapolatedAndClamped) {
  const Index n = make(nullptr).data()[0].size();
  FrictionState previous;
  previous.nodal_tau = {Eigen::VectorXd::Constant(n, 2e-3)};
  previous.previous_tau = {Eigen::VectorXd::Constant(n, 1e-3)};
  previous.previous_tau[0][0] = 6e-3;  // a node whose threshold fell: extrapolated below 0, clamped
  CoulombThresholds warm = make(&previous);
  EXPECT_TRUE(warm.warm());
  EXPECT_EQ(warm.data()[0], previous.nodal_tau[0]) << "without extrapolation: the previous thresholds";
  EXPECT_EQ(warm.state().previous_tau[0], previous.nodal_tau[0]) << "kept for the next step's predictor";
  const CoulombThresholds extrapolated = make(&previous, 0.5);
  EXPECT_DOUBLE_EQ(extrapolated.data()[0][1], 2e-3 + 0.5 * (2e-3 - 1e-3));
  EXPECT_EQ(extrapolated.data()[0][0], 0.0);
  FrictionState first = make(nullptr).state();  // a first step's: the unloaded start's thresholds before it, 0
  first.nodal_tau = previous.nodal_tau;
  EXPECT_DOUBLE_EQ(make(&first, 0.5).data()[0][1], 2e-3 + 0.5 * 2e-3);
  EXPECT_EQ(make(&first).data()[0], first.nodal_tau[0]);
  warm.start_cold();
  EXPECT_FALSE(warm.warm());
  EXPECT_EQ(warm.data()[0].lpNorm<Eigen::Infinity>(), 0.0);
}

TEST_F(CoulombThresholdsTest, TheResidualOfAFrictionlessSolveIsMuTimesThePressureAndTheUpdateIsProjected) {
  CoulombThresholds t = make(nullptr);
  ContactSolveOptions o;
  const SolveReport solve = solve_contact(model().energy(), fixed_, model().contacts(), model().dofs(), u_, o, log_,
                                          &t.state());
  const std::vector<Eigen::VectorXd> r = t.residual(u_, solve);
  ASSERT_EQ(r.size(), 1u);
  ASSERT_EQ(r[0].size(), t.data()[0].size());
  // The patch carries p = 0.01 at every interface node; nodal recovery is exact to a few per cent at the ends.
  EXPECT_NEAR(r[0].maxCoeff(), 0.3 * 0.01, 0.3 * 0.01 * 0.05);
  EXPECT_GT(r[0].minCoeff(), 0.0);
  t.update(r, 1.0);
  EXPECT_EQ(t.data()[0], r[0]) << "τ_1 = μ p_0 from a cold start";
  std::vector<Eigen::VectorXd> down{-2.0 * r[0]};
  t.update(down, 1.0);
  EXPECT_EQ(t.data()[0].minCoeff(), 0.0) << "projected onto τ ≥ 0";
  EXPECT_EQ(t.data()[0].maxCoeff(), 0.0);
}
