// Automatic step cutting ([contact_solver] max_step_cuts, solvers/load_step.hpp) on a real solve: a
// Neo-Hookean block (2 × 1, E = 1, ν = 0.3) whose top is pushed down 0.25 onto a rigid cylinder
// (radius 0.5) under its bottom. In one step the geometry fixed point needs 12 iterations; in two, 7 and
// 11. With max_geometry_iterations = 11 the whole step therefore fails, and with one cut allowed the run
// goes on in two halves — which must give exactly the run in two load steps (the same solves in the same
// order: a failed attempt leaves no trace).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "support/solve_case.hpp"
#include "symcontact/core/error.hpp"

using namespace symcontact;
using namespace symcontact::testing;

namespace {
const char* kGeo = R"(lc = 0.1;
Point(1) = {0, 0, 0, lc};
Point(2) = {2, 0, 0, lc};
Point(3) = {2, 1, 0, lc};
Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("block") = {1};
Physical Curve("bottom") = {1};
Physical Curve("top") = {3};
)";

std::string problem(int steps, int max_cuts) {
  return "[problem]\ndimension = 2\n[steps]\ncount = " + std::to_string(steps) + R"(
[[body]]
name = "block"
mesh = "block.geo"
group = "block"
[body.material]
model = "neo_hookean"
E = 1.0
nu = 0.3
[[body.dirichlet]]
boundary = "top"
ux = 0.0
uy = -0.25
[[contact]]
name = "roller"
a = "block.bottom"
search_distance = 0.5
[contact.obstacle]
type = "circle"
center = [1.0, -0.5]
radius = 0.5
inside = false
[contact_solver]
max_geometry_iterations = 11
max_step_cuts = )" + std::to_string(max_cuts) + "\n";
}
}  // namespace

TEST(StepCutting, AFailedStepSolvedInHalvesEqualsTwoLoadSteps) {
  const std::string dir = test_temp_dir("step_cutting");
  write_text(dir, "block.geo", kGeo);
  // Without cutting, the one step fails (the premise of the test).
  EXPECT_THROW(solve_case(problem(1, 0), dir), SolveError);
  const auto cut = solve_case(problem(1, 1), dir);
  ASSERT_EQ(cut->step_cuts.size(), 1u);
  EXPECT_EQ(cut->step_cuts[0], 1);
  const auto two = solve_case(problem(2, 0), dir);
  ASSERT_EQ(two->step_cuts, (std::vector<int>{0, 0}));
  const double diff = (cut->u - two->u).lpNorm<Eigen::Infinity>() / two->u.lpNorm<Eigen::Infinity>();
  const double rdiff = (cut->reactions.back()[0] - two->reactions.back()[0]).norm() / two->reactions.back()[0].norm();
  std::printf("step cutting: |u_cut - u_two| / |u| = %.2e, reaction %.2e (R_y = %.6f)\n", diff, rdiff,
              two->reactions.back()[0].y());
  EXPECT_LT(diff, 1e-12);
  EXPECT_LT(rdiff, 1e-12);
  EXPECT_GT(two->reactions.back()[0].norm(), 0.0);  // the block does touch the cylinder
}
