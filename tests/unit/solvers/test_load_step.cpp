// The automatic step-cutting schedule (solvers/load_step.hpp), with attempts that fail by rule; the solve
// itself is exercised by tests/validation/test_step_cutting.cpp and the frictional ironing test.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "symcontact/core/error.hpp"
#include "symcontact/solvers/load_step.hpp"

using namespace symcontact;

namespace {
/// Attempts that fail while the increment is longer than `longest` (or covers `hard` and is longer than
/// `longest_at_hard`), recording every attempt.
struct FakeSolve {
  double longest = 1.0;
  double hard = -1.0, longest_at_hard = 1.0;
  std::vector<std::pair<double, double>> tried;
  void operator()(double from, double to) {
    tried.emplace_back(from, to);
    if (to - from > longest + 1e-15) throw SolveError("too long");
    if (from < hard && hard < to && to - from > longest_at_hard + 1e-15) throw SolveError("hard spot");
  }
};
}  // namespace

TEST(StepCutting, AStepThatConvergesIsSolvedWhole) {
  FakeSolve f;
  EXPECT_EQ(solve_in_substeps(3, std::ref(f)), std::vector<double>{1.0});
  EXPECT_EQ(f.tried.size(), 1u);
}

TEST(StepCutting, HalvesUntilTheIncrementConvergesThenGoesOnAtThatSize) {
  FakeSolve f;
  f.longest = 0.3;
  int cuts_told = 0;
  const std::vector<double> ends =
      solve_in_substeps(3, std::ref(f), [&](double, double, const std::string& e, int cuts) {
        EXPECT_EQ(e, "too long");
        cuts_told = cuts;
      });
  EXPECT_EQ(ends, (std::vector<double>{0.25, 0.5, 0.75, 1.0}));
  EXPECT_EQ(cuts_told, 2);
  // 1 and 1/2 fail, then four quarters.
  const std::vector<std::pair<double, double>> expected = {{0, 1}, {0, 0.5}, {0, 0.25}, {0.25, 0.5}, {0.5, 0.75},
                                                           {0.75, 1}};
  EXPECT_EQ(f.tried, expected);
}

TEST(StepCutting, CutsOnlyWhereNeededAndKeepsTheSmallerSizeAfterwards) {
  FakeSolve f;
  f.hard = 0.6;
  f.longest_at_hard = 0.25;
  const std::vector<double> ends = solve_in_substeps(4, std::ref(f));
  // [0, 1] fails, [0, 1/2] converges, [1/2, 1] fails, then quarters to the end.
  EXPECT_EQ(ends, (std::vector<double>{0.5, 0.75, 1.0}));
  EXPECT_EQ(f.tried.size(), 5u);
}

TEST(StepCutting, GivesUpAfterTheAllowedCutsNamingThem) {
  FakeSolve f;
  f.longest = 0.1;
  try {
    solve_in_substeps(2, std::ref(f));
    FAIL() << "expected a SolveError";
  } catch (const SolveError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("too long"), std::string::npos) << m;
    EXPECT_NE(m.find("after 2 halvings"), std::string::npos) << m;
    EXPECT_NE(m.find("max_step_cuts"), std::string::npos) << m;
  }
  EXPECT_EQ(f.tried.size(), 3u);  // 1, 1/2, 1/4
}

TEST(StepCutting, WithoutCutsTheErrorIsPassedOnUnchanged) {
  FakeSolve f;
  f.longest = 0.5;
  try {
    solve_in_substeps(0, std::ref(f));
    FAIL() << "expected a SolveError";
  } catch (const SolveError& e) {
    EXPECT_EQ(std::string(e.what()), "too long");
  }
  EXPECT_EQ(f.tried.size(), 1u);
}
