// Progress times (core/progress_clock.hpp): durations written for a reader, and the elapsed time and time left of a
// loop, silent while the loop is short.
#include <gtest/gtest.h>

#include <chrono>
#include <sstream>
#include <thread>

#include "symcontact/core/progress_clock.hpp"

using namespace symcontact;

TEST(ProgressTimes, DurationsAreRoundedToWhatAReaderNeeds) {
  EXPECT_EQ(format_duration(0.4), "0 s");
  EXPECT_EQ(format_duration(44.6), "45 s");
  EXPECT_EQ(format_duration(200.0), "3 min 20 s");
  EXPECT_EQ(format_duration(7500.0), "2 h 05 min");
  EXPECT_EQ(format_duration(-3.0), "0 s");
}

TEST(ProgressTimes, AShortLoopPrintsNoTimes) {
  const ProgressClock clock(5.0);
  EXPECT_EQ(clock.suffix(1, 10), "");
}

TEST(ProgressTimes, ALongLoopPrintsElapsedAndTimeLeftFromTheMeanPerItem) {
  const ProgressClock clock(0.0);  // always "long"
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const std::string s = clock.suffix(1, 4);
  EXPECT_EQ(s.rfind(", elapsed ", 0), 0u) << s;
  EXPECT_NE(s.find(", about "), std::string::npos) << s;
  EXPECT_NE(s.find(" left"), std::string::npos) << s;
  EXPECT_EQ(clock.suffix(4, 4).find("left"), std::string::npos) << "nothing left at the end";
  EXPECT_GT(clock.elapsed(), 0.015);
}

TEST(ProgressTimes, AnIterationLineShowsAtTheDefaultVerbosityOnlyOnceTheLoopIsLong) {
  std::ostringstream out;
  const Logger log(out, Verbosity::kNormal);
  const ProgressClock clock;
  log_iteration(log, clock, "  iteration 1", 1e9);
  EXPECT_EQ(out.str(), "") << "a short loop: -v only";
  log_iteration(log, clock, "  iteration 2", -1.0);
  EXPECT_EQ(out.str().rfind("  iteration 2 (elapsed ", 0), 0u) << out.str();
}
