// The predictor of a load step under proportional loading (FrictionalOptions::extrapolate) without friction:
// the step starts from u_{n−1} + s (u_{n−1} − u_{n−2}), so the geometry fixed point's first linearisation is
// at the extrapolated displacement instead of the previous step's answer.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "support/solve_case.hpp"

using namespace symcontact;
using namespace symcontact::testing;

namespace {

const char* kPadGeo =
    "Point(1) = {-0.5, 0, 0, 0.02}; Point(2) = {0.5, 0, 0, 0.02}; Point(3) = {0.5, 0.25, 0, 0.02};\n"
    "Point(4) = {-0.5, 0.25, 0, 0.02};\nLine(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
    "Curve Loop(1) = {1, 2, 3, 4};\nPlane Surface(1) = {1};\n"
    "Physical Surface(\"solid\") = {1};\nPhysical Curve(\"bottom\") = {1};\nPhysical Curve(\"top\") = {3};\n";

}  // namespace

// A frictionless pad pressed onto a rigid plane in two equal steps (its top moved down, held in x; ν = 0.3: the
// bottom spreads along the plane). With a linear body and a plane, the second step's answer is the first's
// doubled, and the predictor's point is that answer: the second step's fixed point converges at its first
// iteration. From the previous step's answer instead, the first linearisation moves u by the whole step and a
// second iteration is needed to see the change fall below the tolerance.
TEST(LoadPredictor, ASecondEqualFrictionlessStepStartsAtItsAnswer) {
  const std::string dir = test_temp_dir("predicted_pad");
  write_text(dir, "pad.geo", kPadGeo);
  const std::string toml =
      "[problem]\ndimension = 2\n\n[steps]\nload_factors = [0.5, 1.0]\n\n"
      "[[body]]\nname = \"pad\"\nmesh = \"pad.geo\"\ngroup = \"solid\"\nmaterial = { E = 1.0, nu = 0.3 }\n"
      "[[body.dirichlet]]\nboundary = \"top\"\nux = 0.0\nuy = -0.02\n\n[[contact]]\nname = \"interface\"\n"
      "a = \"pad.bottom\"\n[contact.obstacle]\ntype = \"plane\"\npoint = [0.0, 0.0]\nnormal = [0.0, 1.0]\n";
  const auto c = solve_case(toml, dir);
  ASSERT_EQ(c->reactions.size(), 2u);
  ASSERT_EQ(c->geometry_iterations.size(), 2u);
  std::printf("  geometry iterations per step: %d, %d\n", c->geometry_iterations[0], c->geometry_iterations[1]);
  const Eigen::VectorXd& r1 = c->reactions[0][0];
  const Eigen::VectorXd& r2 = c->reactions[1][0];
  EXPECT_GT(std::abs(r1[1]), 0.0);
  EXPECT_LT((r2 - 2.0 * r1).lpNorm<Eigen::Infinity>(), 1e-8 * r2.lpNorm<Eigen::Infinity>());
  EXPECT_EQ(c->geometry_iterations[1], 1) << "the predictor's point is the second step's answer";
}
