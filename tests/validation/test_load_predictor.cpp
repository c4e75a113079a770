// How a frictionless load step starts: under proportional loading (FrictionalOptions::extrapolate) from
// u_{n−1} + s (u_{n−1} − u_{n−2}), so that the geometry fixed point's first linearisation is at the extrapolated
// displacement instead of the previous step's answer; and the first solve of a run, without a previous active
// set, from the rows the load alone would violate (dual_subproblem.hpp).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "support/pad_geo.hpp"
#include "support/solve_case.hpp"

using namespace symcontact;
using namespace symcontact::testing;

namespace {

const char* kPadOnPlane =
    "[problem]\ndimension = 2\n\n[steps]\nload_factors = [0.5, 1.0]\n\n"
    "[[body]]\nname = \"pad\"\nmesh = \"pad.geo\"\ngroup = \"solid\"\nmaterial = { E = 1.0, nu = 0.3 }\n"
    "[[body.dirichlet]]\nboundary = \"top\"\nux = 0.0\nuy = -0.02\n\n[[contact]]\nname = \"interface\"\n"
    "a = \"pad.bottom\"\n[contact.obstacle]\ntype = \"plane\"\npoint = [0.0, 0.0]\nnormal = [0.0, 1.0]\n";

}  // namespace

// A frictionless pad pressed onto a rigid plane in two equal steps (its top moved down, held in x; ν = 0.3: the
// bottom spreads along the plane). With a linear body and a plane, the second step's answer is the first's
// doubled, and the predictor's point is that answer: the second step's fixed point converges at its first
// iteration. From the previous step's answer instead, the first linearisation moves u by the whole step and a
// second iteration is needed to see the change fall below the tolerance.
TEST(LoadPredictor, ASecondEqualFrictionlessStepStartsAtItsAnswer) {
  const std::string dir = test_temp_dir("predicted_pad");
  write_text(dir, "pad.geo", pad_geo_2d(0.02));
  const auto c = solve_case(kPadOnPlane, dir);
  ASSERT_EQ(c->reactions.size(), 2u);
  ASSERT_EQ(c->geometry_iterations.size(), 2u);
  std::printf("  geometry iterations per step: %d, %d\n", c->geometry_iterations[0], c->geometry_iterations[1]);
  const Eigen::VectorXd& r1 = c->reactions[0][0];
  const Eigen::VectorXd& r2 = c->reactions[1][0];
  EXPECT_GT(std::abs(r1[1]), 0.0);
  EXPECT_LT((r2 - 2.0 * r1).lpNorm<Eigen::Infinity>(), 1e-8 * r2.lpNorm<Eigen::Infinity>());
  EXPECT_EQ(c->geometry_iterations[1], 1) << "the predictor's point is the second step's answer";
}

// The same pad's first step: every bottom row is violated by the pressed top alone, and that set is the
// answer's, closed in one round without an optimizer iteration. The interior point from the same start
// ([contact_solver] warm_start = "interior_point", which closes no set before it) reaches the same answer.
TEST(LoadPredictor, AFirstFrictionlessSolveClosesTheViolatedRows) {
  const std::string dir = test_temp_dir("violated_rows_pad");
  write_text(dir, "pad.geo", pad_geo_2d(0.02));
  const auto closed = solve_case(kPadOnPlane, dir);
  const auto interior =
      solve_case(std::string(kPadOnPlane) + "\n[contact_solver]\nwarm_start = \"interior_point\"\n", dir);
  ASSERT_EQ(closed->optimizer_iterations.size(), 2u);
  std::printf("  optimizer iterations of the first step: %d closing the violated rows, %d by the interior point\n",
              closed->optimizer_iterations[0], interior->optimizer_iterations[0]);
  EXPECT_EQ(closed->optimizer_iterations[0], 0);
  EXPECT_GT(interior->optimizer_iterations[0], 0);
  const double u_size = interior->u.lpNorm<Eigen::Infinity>();
  EXPECT_LT((closed->u - interior->u).lpNorm<Eigen::Infinity>(), 1e-10 * u_size);
}
