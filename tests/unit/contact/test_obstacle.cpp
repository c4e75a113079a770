#include "symcontact/contact/obstacle.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

using namespace symcontact;

namespace {

double gap(const Obstacle& o, const Eigen::Vector3d& x, Eigen::Vector3d* xbar_out = nullptr,
           Eigen::Vector3d* n_out = nullptr) {
  Eigen::Vector3d xbar, n;
  o.project(x, xbar, n);
  if (xbar_out) *xbar_out = xbar;
  if (n_out) *n_out = n;
  return (x - xbar).dot(n);
}

}  // namespace

TEST(Obstacle, PlaneProjectionAndSignedGap) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    Obstacle o;
    o.kind = Obstacle::Kind::kPlane;
    o.point = Eigen::Vector3d(U(rng), U(rng), U(rng));
    o.normal = Eigen::Vector3d(U(rng), U(rng), U(rng)).normalized();
    const Eigen::Vector3d x(U(rng), U(rng), U(rng));
    Eigen::Vector3d xbar, n;
    const double g = gap(o, x, &xbar, &n);
    EXPECT_NEAR(n.norm(), 1.0, 1e-14);
    EXPECT_NEAR((n - o.normal).norm(), 0.0, 1e-15);
    EXPECT_NEAR((xbar - o.point).dot(o.normal), 0.0, 1e-14);          // x̄ on the plane
    EXPECT_NEAR((x - xbar).cross(o.normal).norm(), 0.0, 1e-14);       // x − x̄ along n
    EXPECT_NEAR(g, (x - o.point).dot(o.normal), 1e-14);              // signed distance
  }
  // The sign: above the floor y = 0 (normal +y) is admissible, below is penetration.
  Obstacle floor;
  floor.point = Eigen::Vector3d(3.0, 0.0, 0.0);
  floor.normal = Eigen::Vector3d::UnitY();
  EXPECT_NEAR(gap(floor, Eigen::Vector3d(-2.0, 0.25, 0.0)), 0.25, 1e-15);
  EXPECT_NEAR(gap(floor, Eigen::Vector3d(7.0, -0.5, 0.0)), -0.5, 1e-15);
  EXPECT_NEAR(gap(floor, Eigen::Vector3d(1.0, 0.0, 0.0)), 0.0, 0.0);
}

TEST(Obstacle, SphereWithTheBodyOutside) {
  Obstacle o;
  o.kind = Obstacle::Kind::kSphere;
  o.point = Eigen::Vector3d(0.5, -1.0, 0.25);
  o.radius = 2.0;
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Vector3d dir = Eigen::Vector3d(U(rng), U(rng), U(rng)).normalized();
    const double r = 4.0 * std::abs(U(rng)) + 0.01;
    const Eigen::Vector3d x = o.point + r * dir;
    Eigen::Vector3d xbar, n;
    const double g = gap(o, x, &xbar, &n);
    EXPECT_NEAR(g, r - o.radius, 1e-13);
    EXPECT_NEAR((xbar - o.point).norm(), o.radius, 1e-13);
    EXPECT_NEAR((n - dir).norm(), 0.0, 1e-13);  // outward from the centre
  }
}

TEST(Obstacle, SphereWithTheBodyInside) {
  Obstacle o;
  o.kind = Obstacle::Kind::kSphere;
  o.inside = true;
  o.point = Eigen::Vector3d(1.0, 1.0, 0.0);
  o.radius = 1.5;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    // 2D: z = 0.
    const double t = M_PI * U(rng), r = 2.5 * std::abs(U(rng)) + 0.01;
    const Eigen::Vector3d dir(std::cos(t), std::sin(t), 0.0);
    const Eigen::Vector3d x = o.point + r * dir;
    Eigen::Vector3d xbar, n;
    const double g = gap(o, x, &xbar, &n);
    EXPECT_NEAR(g, o.radius - r, 1e-13);
    EXPECT_NEAR((xbar - o.point).norm(), o.radius, 1e-13);
    EXPECT_NEAR((n + dir).norm(), 0.0, 1e-13);  // towards the centre
    EXPECT_EQ(xbar.z(), 0.0);
  }
}

TEST(Obstacle, PointAtTheCentreGivesNoNaN) {
  for (bool inside : {false, true}) {
    Obstacle o;
    o.kind = Obstacle::Kind::kSphere;
    o.inside = inside;
    o.point = Eigen::Vector3d(2.0, 3.0, 0.0);
    o.radius = 0.5;
    Eigen::Vector3d xbar, n;
    const double g = gap(o, o.point, &xbar, &n);
    EXPECT_TRUE(xbar.allFinite());
    EXPECT_TRUE(n.allFinite());
    EXPECT_NEAR(n.norm(), 1.0, 1e-15);
    EXPECT_NEAR((xbar - o.point).norm(), 0.5, 1e-15);
    EXPECT_NEAR(g, inside ? 0.5 : -0.5, 1e-15);
  }
}
