#include "symcontact/solvers/fixed_point_monitor.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace symcontact {
namespace {

TEST(FixedPointMonitor, LinearConvergenceIsNotStagnation) {
  FixedPointMonitor m;
  for (int k = 0; k < 40; ++k) {
    m.record(std::pow(0.9, k));
    EXPECT_FALSE(m.stagnated()) << k;
  }
}

TEST(FixedPointMonitor, CyclesOfPeriodTwoToFiveAreStagnation) {
  for (int period = 2; period <= 5; ++period) {
    FixedPointMonitor m;
    bool seen = false;
    for (int k = 0; k < 20 && !seen; ++k) {
      m.record(1e-6 * (1.0 + 0.3 * (k % period)));
      seen = m.stagnated();
    }
    EXPECT_TRUE(seen) << "period " << period;
  }
}

TEST(FixedPointMonitor, NoiseFloorAfterProgressIsStagnation) {
  FixedPointMonitor m;
  const double changes[] = {1e-2, 1e-3, 1e-4, 1e-5, 1.7e-6, 1.6e-6, 1.8e-6, 1.65e-6, 1.7e-6, 1.62e-6, 1.75e-6};
  int first = -1;
  for (int k = 0; k < 11; ++k) {
    m.record(changes[k]);
    if (m.stagnated() && first < 0) first = k;
  }
  EXPECT_EQ(first, 10);  // six changes (1.6e-6 … 1.75e-6) without a new low below 0.7 × 1.7e-6
  EXPECT_DOUBLE_EQ(m.best(), 1.6e-6);
}

TEST(FixedPointMonitor, RestartJudgesTheNewRegimeAlone) {
  FixedPointMonitor m;
  for (int k = 0; k < 8; ++k) m.record(1e-6);
  ASSERT_TRUE(m.stagnated());
  m.restart();
  EXPECT_FALSE(m.stagnated());
  EXPECT_TRUE(std::isinf(m.best()));
  for (int k = 0; k < 6; ++k) m.record(std::pow(0.5, k));
  EXPECT_FALSE(m.stagnated());
  EXPECT_EQ(m.changes().size(), 14u);
}

}  // namespace
}  // namespace symcontact
