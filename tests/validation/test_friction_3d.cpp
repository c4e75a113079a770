// Coulomb friction in 3D (the V4 block of VALIDATION.md, in 3D): an elastic block [0,2]×[0,2]×[0,1]
// (E = 1, ν = 0) pressed on the rigid plane z = 0 by p = 0.01 on its top, then its top dragged by U = 0.03
// along a direction d at 30° to the x axis, μ = 0.3. U ≫ U* = μ p H / G = 0.006: gross slip. At every
// contact node the regularised law σ_T = −μ σ_n s / sqrt(|s|² + α²) holds with the node's own slip
// increment s, which has two components in the tangent plane (the friction term, friction_term.hpp,
// works with P = I − n nᵀ). The block is not symmetric about d, so the local slip directions deviate
// slightly from d (by ~1e-3 rad here): the tangential contact force is then μ × the normal one up to that
// misalignment, and opposed to d up to it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/solve_case.hpp"

using namespace symcontact;
using namespace symcontact::testing;

TEST(Friction3D, GrossSlipAlongAnOffAxisDirectionFollowsCoulomb) {
  const double mu = 0.3, p = 0.01, U = 0.03, angle = M_PI / 6;
  const Eigen::Vector3d d(std::cos(angle), std::sin(angle), 0.0);
  const std::string dir = test_temp_dir("friction3d");
  write_text(dir, "block.geo",
             "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 2, 2, 1};\nMeshSize{PointsOf{Volume{1};}} = 0.34;\n"
             "Physical Volume(\"block\") = {1};\nPhysical Surface(\"bottom\") = {5};\nPhysical Surface(\"top\") = {6};\n");
  char buf[2048];
  std::snprintf(buf, sizeof buf, R"(
[problem]
dimension = 3
order = 1
[steps]
load_factors = [0.0, 0.5, 1.0]
[[body]]
name = "block"
mesh = "block.geo"
group = "block"
material = { E = 1.0, nu = 0.0 }
[[body.pressure]]
boundary = "top"
pressure = %.17g
factors = [1.0, 1.0, 1.0]
[[body.dirichlet]]
boundary = "top"
ux = %.17g
uy = %.17g
[[contact]]
name = "floor"
a = "block.bottom"
friction = "coulomb"
mu = %.17g
alpha = 1e-5
[contact.obstacle]
type = "plane"
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]
)",
                p, U * d.x(), U * d.y(), mu);
  auto c = solve_case(buf, dir);
  ASSERT_EQ(c->history.size(), 3u);
  const ContactPairResult& r = c->contact.at(0);
  const double Fn = r.normal_force.norm(), Ft = r.tangential_force.norm();
  const double cosine = -r.tangential_force.dot(d) / Ft;
  std::printf("  normal force %.10f (p A = %.4f), tangential %.10f: ratio %.8f (mu %.1f), direction cos %.10f, "
              "%d Coulomb iterations\n",
              Fn, p * 4, Ft, Ft / Fn, mu, cosine, c->report.coulomb_iterations);
  EXPECT_NEAR(Fn, p * 4.0, 1e-8 * p * 4.0);
  EXPECT_NEAR(Ft / Fn, mu, 1e-4 * mu);
  EXPECT_GT(cosine, 1 - 1e-5);
  // Node by node: the regularised law with the node's slip, wherever the block is in contact.
  const ContactSideResult& side = r.sides.at(0);
  double worst = 0.0;
  int nodes = 0;
  for (Index k = 0; k < side.pressure.size(); ++k) {
    if (side.pressure[k] <= 1e-3 * p) continue;
    ++nodes;
    const Eigen::Vector3d slip = side.slip.col(k);
    const Eigen::Vector3d law = -mu * side.pressure[k] * slip / std::sqrt(slip.squaredNorm() + 1e-10);
    worst = std::max(worst, (side.tangential.col(k) - law).norm() / (mu * side.pressure[k]));
  }
  std::printf("  %d contact nodes: max |sigma_T + mu sigma_n s/r| / (mu sigma_n) = %.2e\n", nodes, worst);
  EXPECT_GT(nodes, 10);
  EXPECT_LT(worst, 1e-3);
}
