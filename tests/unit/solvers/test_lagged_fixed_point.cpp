// The outer loop of a load step (solvers/lagged_fixed_point.hpp) on a scalar lagged term whose "solve" returns
// its data as the answer, so that the loop iterates d ← P(d + ω (T(d) − d)) for a chosen map T: a contraction
// converges to its fixed point; a map of slope −1, on which the plain iteration cycles, converges through
// Aitken's relaxation; a cold start's first residual is not judged; inexact solves never end the loop; a
// noise floor is tightened against, then accepted below the acceptance or reported as a failure naming the
// loop, the remedies and the advice; a tightened solve that fails falls back on the iterate it started from.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "symcontact/core/error.hpp"
#include "symcontact/solvers/lagged_fixed_point.hpp"

using namespace symcontact;

namespace {

class ScalarTerm final : public LaggedTerm {
 public:
  ScalarTerm(std::function<double(double)> target, double d0, bool warm)
      : target_(std::move(target)), data_{Eigen::VectorXd::Constant(1, d0)}, warm_(warm) {}
  std::string loop_name() const override { return "scalar"; }
  std::string data_name() const override { return "datum"; }
  std::string advice() const override { return "change the map"; }
  bool lags() const override { return true; }
  bool warm() const override { return warm_; }
  void start_cold() override {
    warm_ = false;
    data_[0].setZero();
  }
  const std::vector<Eigen::VectorXd>& data() const override { return data_; }
  std::vector<Eigen::VectorXd> residual(const VectorXd& u, const SolveReport&) const override {
    return {Eigen::VectorXd::Constant(1, target_(u[0]) - data_[0][0])};
  }
  void update(const std::vector<Eigen::VectorXd>& r, double omega) override {
    data_[0] = (data_[0] + omega * r[0]).cwiseMax(0.0);
  }
  void set_data(const std::vector<Eigen::VectorXd>& data) override { data_ = data; }
  double datum() const { return data_[0][0]; }

 private:
  std::function<double(double)> target_;
  std::vector<Eigen::VectorXd> data_;
  bool warm_;
};

struct LoopRun {
  SolveReport report;
  std::vector<ContactSolveOptions> solves;  ///< the options of every solve, in order
  double datum = 0.0;
};

/// `tightened_fail`: a solve under options tightened past the first solve's throws a SolveError.
LoopRun run(std::function<double(double)> target, double d0, bool warm, bool inexact,
        FrictionalOptions options = FrictionalOptions(), bool tightened_fail = false) {
  ScalarTerm term(std::move(target), d0, warm);
  LoopRun out;
  VectorXd u = VectorXd::Zero(1);
  const LaggedSolve solve = [&](const ContactSolveOptions& o) {
    out.solves.push_back(o);
    if (tightened_fail && o.ipopt.tolerance < out.solves.front().ipopt.tolerance)
      throw SolveError("the inner solver broke down");
    u[0] = term.datum();
    SolveReport r;
    r.converged = !(o.loose_geometry_tolerance > o.geometry_tolerance);
    return r;
  };
  std::ostringstream sink;
  const Logger log(sink, Verbosity::kQuiet);
  out.report = solve_lagged(term, solve, u, VectorXd::Zero(1), options, inexact, log);
  out.datum = term.datum();
  return out;
}

}  // namespace

TEST(LaggedFixedPoint, AContractionConvergesToItsFixedPoint) {
  const LoopRun r = run([](double d) { return 0.5 * d + 1.0; }, 1.0, true, false);
  EXPECT_NEAR(r.datum, 2.0, 1e-5);
  ASSERT_FALSE(r.report.coulomb_change.empty());
  EXPECT_LT(r.report.coulomb_change.back(), FrictionalOptions().coulomb_tolerance);
  EXPECT_EQ(r.report.accepted_at_noise_floor, 0.0);
  EXPECT_EQ(static_cast<int>(r.solves.size()), r.report.coulomb_iterations + 1);
}

TEST(LaggedFixedPoint, AitkenRelaxationEndsTheTwoCycleOfASlopeOfMinusOne) {
  // T(d) = 4 − d: the plain iteration from 1 goes 3, 1, 3, …; with ω_2 = 0.5 the second update lands on 2.
  const LoopRun r = run([](double d) { return 4.0 - d; }, 1.0, true, false);
  EXPECT_NEAR(r.datum, 2.0, 1e-12);
  ASSERT_GE(r.report.coulomb_relaxation.size(), 2u);
  EXPECT_EQ(r.report.coulomb_relaxation[0], 1.0);
  EXPECT_DOUBLE_EQ(r.report.coulomb_relaxation[1], 0.5);
  EXPECT_EQ(r.report.coulomb_iterations, 2);
}

TEST(LaggedFixedPoint, AColdStartsFirstResidualSetsTheDataUnjudged) {
  // From d = 0 the first change would be 1 (relative to nothing); it is neither recorded nor counted.
  const LoopRun cold = run([](double d) { return 0.5 * d + 1.0; }, 0.0, false, false);
  const LoopRun warm = run([](double d) { return 0.5 * d + 1.0; }, 1.0, true, false);
  EXPECT_NEAR(cold.datum, 2.0, 1e-5);
  EXPECT_EQ(cold.report.coulomb_change.size() + 1, cold.solves.size());
  EXPECT_EQ(warm.report.coulomb_change.size(), warm.solves.size());
}

TEST(LaggedFixedPoint, InexactSolvesNeverEndTheLoop) {
  const LoopRun r = run([](double d) { return 0.5 * d + 1.0; }, 1.0, true, true);
  ASSERT_GE(r.solves.size(), 2u);
  EXPECT_EQ(r.solves.front().loose_geometry_tolerance, FrictionalOptions().inner_tolerance_factor)
      << "the first solve is inexact, at factor × 1";
  EXPECT_FALSE(r.solves.back().loose_geometry_tolerance > r.solves.back().geometry_tolerance)
      << "the last solve is to the full geometry tolerance";
  EXPECT_TRUE(r.report.converged);
  EXPECT_NEAR(r.datum, 2.0, 1e-5);
}

TEST(LaggedFixedPoint, ANoiseFloorIsTightenedAgainstThenAcceptedBelowTheAcceptance) {
  // T alternates ±1e-5 around 2: the relative change never falls below 1e-5 (tolerance 1e-6).
  int calls = 0;
  const LoopRun r = run([&](double) { return 2.0 * (1.0 + ((calls++ % 2) ? 1e-5 : -1e-5)); }, 2.0, true, false);
  EXPECT_GT(r.report.accepted_at_noise_floor, FrictionalOptions().coulomb_tolerance);
  EXPECT_LE(r.report.accepted_at_noise_floor, FrictionalOptions().stagnation_acceptance);
  const IpoptOptions first = r.solves.front().ipopt, last = r.solves.back().ipopt;
  EXPECT_NEAR(last.tolerance, first.tolerance * 1e-2 * 1e-2, 1e-6 * first.tolerance) << "tightened twice";
  EXPECT_NEAR(r.solves.back().geometry_tolerance, r.solves.front().geometry_tolerance * 1e-2,
              1e-6 * r.solves.front().geometry_tolerance);
}

TEST(LaggedFixedPoint, ANoiseFloorAboveTheAcceptanceFailsNamingLoopRemediesAndAdvice) {
  int calls = 0;
  try {
    run([&](double) { return 2.0 * (1.0 + ((calls++ % 2) ? 1e-3 : -1e-3)); }, 2.0, true, false);
    FAIL() << "a loop that cannot converge must throw";
  } catch (const SolveError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("the scalar fixed point stagnated"), std::string::npos) << m;
    EXPECT_NE(m.find("inner solves tightened 2 time(s)"), std::string::npos) << m;
    EXPECT_NE(m.find("change the map"), std::string::npos) << m;
  }
}

// The same noise floor where every solve tightened past the first one fails: the loop goes back to the iterate
// the first tightened solve started from, solves it again under the first options, and accepts it there (the
// datum the last successful solve had, not the update the failed one took); above the acceptance, the failed
// solve's error stands.
TEST(LaggedFixedPoint, ATightenedSolveThatFailsAcceptsTheIterateItStartedFromAtTheNoiseFloor) {
  int calls = 0;
  std::vector<double> data;
  const auto noisy = [&](double d) {
    data.push_back(d);
    return 2.0 * (1.0 + ((calls++ % 2) ? 1e-5 : -1e-5));
  };
  const LoopRun r = run(noisy, 2.0, true, false, FrictionalOptions(), true);
  EXPECT_GT(r.report.accepted_at_noise_floor, FrictionalOptions().coulomb_tolerance);
  EXPECT_LE(r.report.accepted_at_noise_floor, FrictionalOptions().stagnation_acceptance);
  ASSERT_GE(r.solves.size(), 3u);
  const ContactSolveOptions &failed = r.solves[r.solves.size() - 2], &again = r.solves.back();
  EXPECT_LT(failed.ipopt.tolerance, again.ipopt.tolerance) << "the failed solve was tightened, the last one not";
  EXPECT_EQ(again.ipopt.tolerance, r.solves.front().ipopt.tolerance);
  ASSERT_GE(data.size(), 2u);
  EXPECT_EQ(r.datum, data[data.size() - 2]) << "the data of the iterate the failed solve started from";

  calls = 0;
  FrictionalOptions strict;
  strict.stagnation_acceptance = 1e-6;
  try {
    run(noisy, 2.0, true, false, strict, true);
    FAIL() << "a floor above the acceptance must throw";
  } catch (const SolveError& e) {
    EXPECT_EQ(std::string(e.what()), "the inner solver broke down");
  }
}

TEST(LaggedFixedPoint, TheIterationLimitIsAFailure) {
  FrictionalOptions o;
  o.max_coulomb_iterations = 1;
  try {
    run([](double d) { return 0.9 * d + 0.2; }, 1.0, true, false, o);  // a first change of 0.1
    FAIL() << "one iteration cannot reach 1e-6";
  } catch (const SolveError& e) {
    EXPECT_NE(std::string(e.what()).find("the scalar fixed point did not converge after 1 iterations"),
              std::string::npos)
        << e.what();
  }
}

TEST(LaggedFixedPoint, AFastContractionGoesPastTheToleranceAndASlowOneDoesNot) {
  // T(d) = 0.05 d + 1.9 contracts twentyfold per iteration: the first change below 1e-6 (1.5e-7) fell
  // tenfold, so one more iteration takes it to 7e-9, below 1e-2 × the tolerance, where the loop stops.
  const auto fast = [](double d) { return 0.05 * d + 1.9; };
  FrictionalOptions off;
  off.converge_past_tolerance = false;
  const LoopRun on_run = run(fast, 1.0, true, false), off_run = run(fast, 1.0, true, false, off);
  EXPECT_GT(off_run.report.coulomb_change.back(), 1e-2 * off.coulomb_tolerance);
  EXPECT_LE(on_run.report.coulomb_change.back(), 1e-2 * off.coulomb_tolerance);
  EXPECT_EQ(on_run.solves.size(), off_run.solves.size() + 1);
  EXPECT_LT(std::abs(on_run.datum - 2.0), std::abs(off_run.datum - 2.0));
  // T(d) = 0.5 d + 1 halves the change per iteration: it stops at the first change below the tolerance.
  const auto slow = [](double d) { return 0.5 * d + 1.0; };
  EXPECT_EQ(run(slow, 1.0, true, false).solves.size(), run(slow, 1.0, true, false, off).solves.size());
}
