#include "symcontact/contact/polygon_clipping.hpp"

#include "symcontact/fem/quadrature.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace symcontact;

namespace {

Polygon2 square(double x0, double y0, double x1, double y1) {
  return {Eigen::Vector2d(x0, y0), Eigen::Vector2d(x1, y0), Eigen::Vector2d(x1, y1), Eigen::Vector2d(x0, y1)};
}

const Polygon2 kReference = {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1)};

}  // namespace

TEST(PolygonClipping, AreaIsSignedByOrientation) {
  const Polygon2 s = square(0, 0, 2, 1);
  EXPECT_DOUBLE_EQ(polygon_area(s), 2.0);
  EXPECT_DOUBLE_EQ(polygon_area(Polygon2(s.rbegin(), s.rend())), -2.0);
  EXPECT_DOUBLE_EQ(polygon_area(kReference), 0.5);
}

TEST(PolygonClipping, TriangleByHalfOverlappingSquare) {
  // The reference triangle clipped by [0, 0.5] × [0, 1]: a trapezoid of area 0.5 − 0.125.
  const Polygon2 c = clip_convex_polygon(kReference, square(0, 0, 0.5, 1));
  EXPECT_NEAR(polygon_area(c), 0.375, 1e-15);
  // Inside a bigger clip: unchanged; disjoint: empty.
  EXPECT_NEAR(polygon_area(clip_convex_polygon(kReference, square(-1, -1, 2, 2))), 0.5, 1e-15);
  EXPECT_TRUE(clip_convex_polygon(kReference, square(2, 2, 3, 3)).empty());
  // Touching along an edge only: no area.
  EXPECT_TRUE(clip_convex_polygon(kReference, square(-1, -1, 0, 1)).empty());
}

TEST(PolygonClipping, ClipsOfATilingSumToTheSubjectArea) {
  // The reference triangle against a tiling of the plane by triangles (a perturbed structured grid): the
  // clip areas add up to the triangle's area, and every clip polygon is convex and counter-clockwise.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-0.3, 0.3);
  const int n = 7;
  const double h = 2.0 / n;
  std::vector<Eigen::Vector2d> grid((n + 1) * (n + 1));
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const bool border = i == 0 || j == 0 || i == n || j == n;
      grid[i * (n + 1) + j] = Eigen::Vector2d(-0.5 + i * h + (border ? 0 : U(rng) * h), -0.5 + j * h + (border ? 0 : U(rng) * h));
    }
  double total = 0.0;
  int pieces = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const auto& a = grid[i * (n + 1) + j];
      const auto& b = grid[(i + 1) * (n + 1) + j];
      const auto& c = grid[(i + 1) * (n + 1) + j + 1];
      const auto& d = grid[i * (n + 1) + j + 1];
      for (const Polygon2& t : {Polygon2{a, b, c}, Polygon2{a, c, d}}) {
        ASSERT_GT(polygon_area(t), 0.0);
        const Polygon2 p = clip_convex_polygon(kReference, t);
        if (p.empty()) continue;
        ++pieces;
        total += polygon_area(p);
        for (std::size_t k = 0; k < p.size(); ++k) {
          const Eigen::Vector2d e1 = p[(k + 1) % p.size()] - p[k], e2 = p[(k + 2) % p.size()] - p[(k + 1) % p.size()];
          EXPECT_GE(e1.x() * e2.y() - e1.y() * e2.x(), -1e-14);
        }
        double fan = 0.0;
        for (const auto& tri : triangulate_from_centroid(p)) fan += polygon_area(Polygon2(tri.begin(), tri.end()));
        EXPECT_NEAR(fan, polygon_area(p), 1e-15);
        const auto from_vertex = triangulate_from_vertex(p);
        EXPECT_EQ(from_vertex.size(), p.size() - 2);
        double sum = 0.0;
        for (const auto& tri : from_vertex) {
          const double area = polygon_area(Polygon2(tri.begin(), tri.end()));
          EXPECT_GE(area, -1e-16);
          sum += area;
        }
        EXPECT_NEAR(sum, polygon_area(p), 1e-15);
      }
    }
  EXPECT_GT(pieces, 5);
  EXPECT_NEAR(total, 0.5, 1e-14);
}

// The mortar rule (degree 3 on each triangle) integrates a cubic over a clip polygon exactly on either
// fan, so the vertex fan, with two triangles fewer, gives the centroid fan's integral.
TEST(PolygonClipping, BothFansIntegrateACubicAlike) {
  const Polygon2 shifted = {Eigen::Vector2d(-0.2, 0.3), Eigen::Vector2d(0.7, -0.15), Eigen::Vector2d(0.6, 0.75)};
  const Polygon2 p = clip_convex_polygon(kReference, shifted);
  ASSERT_GE(p.size(), 5u);
  const QuadratureRule rule = simplex_quadrature(2, 3);
  const auto integral = [&](const std::vector<std::array<Eigen::Vector2d, 3>>& triangles, auto f) {
    double sum = 0.0;
    for (const auto& t : triangles) {
      const double jac = (t[1] - t[0]).x() * (t[2] - t[0]).y() - (t[1] - t[0]).y() * (t[2] - t[0]).x();
      for (int q = 0; q < rule.size(); ++q)
        sum += rule.weights[q] * jac * f(t[0] + rule.point(q)[0] * (t[1] - t[0]) + rule.point(q)[1] * (t[2] - t[0]));
    }
    return sum;
  };
  const auto cubic = [](const Eigen::Vector2d& x) {
    return 1.0 + x.x() * x.y() + std::pow(x.x(), 3) - 2.0 * std::pow(x.y(), 3) + x.x() * x.y() * x.y();
  };
  const double centroid = integral(triangulate_from_centroid(p), cubic);
  EXPECT_NEAR(integral(triangulate_from_vertex(p), cubic), centroid, 1e-15 * std::abs(centroid));
  EXPECT_GT(std::abs(centroid), 0.05);
  // An exponential is not integrated exactly: the two fans part on it, so the comparison above can fail.
  const auto exponential = [](const Eigen::Vector2d& x) { return std::exp(6.0 * x.x() - 4.0 * x.y()); };
  const double parted =
      integral(triangulate_from_centroid(p), exponential) - integral(triangulate_from_vertex(p), exponential);
  EXPECT_GT(std::abs(parted), 1e-6);
}
