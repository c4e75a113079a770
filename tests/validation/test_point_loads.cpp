// Point loads and total-force tractions ([[body.point_load]], [[body.traction]] total_force) on the bar of
// examples/point_load_2d (length L = 10, height H = 1, plane stress, E = 1000): pulled along its axis by a
// point force F at the middle of its right edge, left edge on rollers.
//  - Equilibrium: the reactions of the supports add up to −F exactly, at every step (its factor 0.5, 1).
//  - Saint-Venant: 5 heights from the loaded end the stress is uniform, σ_xx = F / H, so that the axial
//    displacement at mid-length is F L / (2 E H) as for the same resultant spread over the end.
//  - The same resultant as total_force on the right edge: a uniform traction F / H, whose P1 solution is
//    the exact linear field, u_x(mid) = F L / (2 E H) to round-off.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "support/problem_snippet.hpp"
#include "support/solve_case.hpp"

namespace symcontact::testing {
namespace {

const std::string kExample = std::string(SYMCONTACT_EXAMPLES) + "/point_load_2d/bar.toml";
constexpr double kF = 1.0, kL = 10.0, kH = 1.0, kE = 1000.0;

/// The example with its point load replaced by `loads` (the rest of the file as shipped).
std::string example_with(const std::string& loads) {
  return replaced(read_text(kExample), "[[body.point_load]]\ngroup = \"tip\"\nforce = [1.0, 0.0]\n", loads);
}

/// u_x at the node of the physical point `point` ("mid", "tip") at the last step.
double displacement_at(const SolvedCase& c, const std::string& point = "mid") {
  const Body& bar = *c.model->bodies()[0];
  const std::vector<Index> nodes = bar.mesh.group_nodes(point);
  EXPECT_EQ(nodes.size(), 1u);
  return c.u[c.model->dofs().dof(0, nodes.at(0), 0)];
}

TEST(PointLoad, ReactionsBalanceThePointForceExactlyAtEveryStep) {
  const auto c = solve_case(read_text(kExample), std::string(SYMCONTACT_EXAMPLES) + "/point_load_2d");
  const double factors[] = {0.5, 1.0};
  ASSERT_EQ(c->reactions.size(), 2u);
  for (int step = 0; step < 2; ++step) {
    Eigen::Vector2d total = Eigen::Vector2d::Zero();
    for (const Eigen::VectorXd& r : c->reactions[step]) total += r;
    EXPECT_NEAR(total[0], -kF * factors[step], 1e-10) << "step " << step + 1;
    EXPECT_NEAR(total[1], 0.0, 1e-10) << "step " << step + 1;
  }
  const double exact = kF * kL / (2 * kE * kH), ux = displacement_at(*c);
  std::printf("point load: u_x(mid) %.9f, F L / (2 E H) %.9f (%+.2e relative)\n", ux, exact, ux / exact - 1);
  EXPECT_NEAR(ux / exact, 1.0, 1e-8);  // measured 1.1e-10
}

TEST(PointLoad, AgreesWithTheSameResultantAsATotalForceOnTheEnd) {
  const std::string dir = std::string(SYMCONTACT_EXAMPLES) + "/point_load_2d";
  const auto point = solve_case(read_text(kExample), dir);
  const auto spread = solve_case(
      example_with("[[body.traction]]\nboundary = \"right\"\ntotal_force = [1.0, 0.0]\n"), dir);
  const double exact = kF * kL / (2 * kE * kH);
  // A uniform traction: the exact (linear) field, reproduced by P1 elements.
  EXPECT_NEAR(displacement_at(*spread) / exact, 1.0, 1e-10);
  // Five heights away, the point force gives the same displacement (Saint-Venant).
  EXPECT_NEAR(displacement_at(*point) / displacement_at(*spread), 1.0, 1e-8);
  // Under the force, the point load is concentrated: its node moves further than under the spread load.
  EXPECT_GT(displacement_at(*point, "tip"), 1.1 * displacement_at(*spread, "tip"));
  // The traction's resultant is F: the reactions balance it as they balance the point force.
  Eigen::Vector2d total = Eigen::Vector2d::Zero();
  for (const Eigen::VectorXd& r : spread->reactions.back()) total += r;
  EXPECT_NEAR(total[0], -kF, 1e-10);
}

}  // namespace
}  // namespace symcontact::testing
