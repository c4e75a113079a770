// Newton on the active set of a warm-started frictional solve (solvers/active_set_start.hpp) on symcontact-bench's
// pad-ball-2d at h = 0.0046 (2.8e4 DOFs): the pad [−½, ½] × [0, ¼], plane strain, pressed by 0.03 in four steps
// onto a rigid cylinder of radius 1 that touches it at the origin (the zone grows from a point), then dragged along
// x by 0.05 in two, Coulomb μ = 0.3. Each step's solves are warm-started from the last, so Newton on the set is
// what solves them; where it does not converge the interior point solves instead, and the step costs both.
// Whole Newton steps without a line search up to 1e-3 of max|x| make the fourth step cycle between two iterates
// for 100 steps before the interior point takes over: 141 optimizer iterations against 30–45 for the others.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "support/pad_geo.hpp"
#include "support/solve_case.hpp"

using namespace symcontact;
using namespace symcontact::testing;

namespace {

const char* kPadToml = R"(title = "pad on a cylinder"
[problem]
dimension = 2
mesh_size = 0.0046
[steps]
load_factors = [0.25, 0.5, 0.75, 1.0, 1.0, 1.0]
[[body]]
name = "pad"
mesh = "pad.geo"
group = "solid"
material = { E = 1.0, nu = 0.3 }
[[body.dirichlet]]
boundary = "top"
uy = -0.03
[[body.dirichlet]]
boundary = "top"
ux = 0.05
factors = [0.0, 0.0, 0.0, 0.0, 0.5, 1.0]
[[contact]]
name = "interface"
a = "pad.bottom"
friction = "coulomb"
mu = 0.3
[contact.obstacle]
type = "circle"
center = [0.0, -1.0]
radius = 1.0
)";

}  // namespace

TEST(ActiveSetNewton, EveryStepOfThePadOnACylinderConvergesWithoutFallingBack) {
  const std::string dir = test_temp_dir("active_set_newton");
  write_text(dir, "pad.geo", pad_geo_2d());
  const auto c = solve_case(kPadToml, dir);
  ASSERT_EQ(c->optimizer_iterations.size(), 6u);
  for (std::size_t k = 0; k < c->optimizer_iterations.size(); ++k)
    std::printf("  step %zu: %d optimizer iterations\n", k + 1, c->optimizer_iterations[k]);
  EXPECT_LE(*std::max_element(c->optimizer_iterations.begin(), c->optimizer_iterations.end()), 60);
  // The dragged pad slides over its whole zone: the top's reaction leans at about μ (0.3015 at this size,
  // docs/performance.md's pad-ball-2d table).
  Eigen::Vector2d r = Eigen::Vector2d::Zero();  // the top's two Dirichlet entries: u_y, then u_x
  for (const Eigen::VectorXd& entry : c->reactions.back()) r += entry.head<2>();
  EXPECT_NEAR(std::abs(r[0] / r[1]), 0.301474, 1e-5);
}
