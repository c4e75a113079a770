// summary.json when an unexpected exception leaves a run (app/run.hpp, SummaryOnError): "internal_error" and the
// load step, written once; nothing on a normal exit; a failing write does not replace the exception in flight.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "symcontact/app/run.hpp"

using namespace symcontact;

TEST(SummaryOnError, AnExceptionLeavingTheRunMarksTheSummary) {
  Json summary = Json::object();
  summary["status"] = "running";
  int writes = 0, steps_done = 2;
  std::string written;
  try {
    const SummaryOnError guard(summary, [&] { ++writes; written = summary.dump(0); }, steps_done);
    throw std::logic_error("a bug");
  } catch (const std::logic_error& e) {
    EXPECT_STREQ(e.what(), "a bug");
  }
  EXPECT_EQ(writes, 1);
  EXPECT_NE(written.find("\"internal_error\""), std::string::npos) << written;
  EXPECT_NE(written.find("load step 3"), std::string::npos) << written;
}

TEST(SummaryOnError, ANormalExitLeavesTheSummaryAlone) {
  Json summary = Json::object();
  summary["status"] = "ok";
  int writes = 0, steps_done = 1;
  { const SummaryOnError guard(summary, [&] { ++writes; }, steps_done); }
  EXPECT_EQ(writes, 0);
  EXPECT_NE(summary.dump(0).find("\"ok\""), std::string::npos);
}

TEST(SummaryOnError, AFailedWriteDoesNotReplaceTheExceptionInFlight) {
  Json summary = Json::object();
  int steps_done = 0;
  try {
    const SummaryOnError guard(summary, [] { throw std::runtime_error("disk full"); }, steps_done);
    throw std::logic_error("a bug");
  } catch (const std::exception& e) {
    EXPECT_STREQ(e.what(), "a bug");
  }
}
