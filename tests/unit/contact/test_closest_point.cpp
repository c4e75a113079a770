#include "symcontact/contact/closest_point.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>

#include "symcontact/fem/shape_functions.hpp"

using namespace symcontact;

namespace {

/// x(η) and x'(η) of a Line2/Line3 facet, computed from the shape functions independently of the projector.
void curve_at(CellType t, const Eigen::MatrixXd& xf, double eta, Eigen::VectorXd& x, Eigen::VectorXd& dx) {
  double N[3], dN[3];
  shape_functions(t, &eta, N, dN);
  x.setZero(xf.rows());
  dx.setZero(xf.rows());
  for (int a = 0; a < cell_num_nodes(t); ++a) {
    x += N[a] * xf.col(a);
    dx += dN[a] * xf.col(a);
  }
}

Eigen::MatrixXd line2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  Eigen::MatrixXd xf(2, 2);
  xf << a, b;
  return xf;
}

/// Line3 on the circle of radius R centred at c, from angle t0 to t1 (middle node at the mean angle).
Eigen::MatrixXd arc(const Eigen::Vector2d& c, double R, double t0, double t1) {
  Eigen::MatrixXd xf(2, 3);
  const double t[3] = {t0, t1, 0.5 * (t0 + t1)};
  for (int a = 0; a < 3; ++a) xf.col(a) = c + R * Eigen::Vector2d(std::cos(t[a]), std::sin(t[a]));
  return xf;
}

/// Minimum of |x(η) − p|² over a dense sampling of η ∈ [0, 1], refined by golden-section search.
double sampled_min_distance2(CellType t, const Eigen::MatrixXd& xf, const Eigen::VectorXd& p, double* eta_min) {
  Eigen::VectorXd x, dx;
  auto f = [&](double e) {
    curve_at(t, xf, e, x, dx);
    return (x - p).squaredNorm();
  };
  const int n = 20000;
  int best = 0;
  double fb = f(0.0);
  for (int k = 1; k <= n; ++k) {
    const double v = f(static_cast<double>(k) / n);
    if (v < fb) {
      fb = v;
      best = k;
    }
  }
  double lo = std::max(0.0, (best - 1.0) / n), hi = std::min(1.0, (best + 1.0) / n);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 80; ++it) {
    const double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
    if (f(a) < f(b)) hi = b; else lo = a;
  }
  const double e = 0.5 * (lo + hi);
  if (eta_min) *eta_min = e;
  return std::min(fb, f(e));
}

double stationarity(CellType t, const Eigen::MatrixXd& xf, const Eigen::VectorXd& p, double eta) {
  Eigen::VectorXd x, dx;
  curve_at(t, xf, eta, x, dx);
  return (x - p).dot(dx);
}

}  // namespace

TEST(ClosestPointLine2, InteriorPointIsTheFootOfThePerpendicular) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Vector2d a(U(rng), U(rng));
    Eigen::Vector2d b(U(rng), U(rng));
    if ((b - a).norm() < 0.2) b = a + Eigen::Vector2d(0.5, 0.3);
    const Eigen::Vector2d t = (b - a).normalized(), n(-t.y(), t.x());
    const double s = 0.05 + 0.9 * (0.5 * (U(rng) + 1.0));  // foot at fraction s of the segment
    const double off = U(rng);
    const Eigen::Vector2d foot = a + s * (b - a);
    const Eigen::VectorXd p = foot + off * n;
    const FacetProjection r = project_on_facet(CellType::kLine2, line2(a, b), p);
    EXPECT_EQ(r.clamped_vertex, -1);
    EXPECT_NEAR(r.eta[0], s, 1e-12);
    EXPECT_NEAR((r.point.head<2>() - foot).norm(), 0.0, 1e-12);
    EXPECT_NEAR(r.point.z(), 0.0, 0.0);
    EXPECT_NEAR(r.distance2, off * off, 1e-12);
    EXPECT_NEAR(stationarity(CellType::kLine2, line2(a, b), p, r.eta[0]), 0.0, 1e-12);
  }
}

TEST(ClosestPointLine2, PastEitherEndClampsToTheEndNode) {
  const Eigen::Vector2d a(0.0, 0.0), b(2.0, 1.0);
  const Eigen::MatrixXd xf = line2(a, b);
  // Before a: along −(b − a) and off to the side.
  const Eigen::VectorXd p0 = a - 0.3 * (b - a) + Eigen::Vector2d(-0.1, 0.2);
  const FacetProjection r0 = project_on_facet(CellType::kLine2, xf, p0);
  EXPECT_EQ(r0.clamped_vertex, 0);
  EXPECT_DOUBLE_EQ(r0.eta[0], 0.0);
  EXPECT_NEAR(r0.distance2, (p0 - a).squaredNorm(), 1e-14);
  EXPECT_NEAR((r0.point.head<2>() - a).norm(), 0.0, 1e-15);
  // After b.
  const Eigen::VectorXd p1 = b + 0.4 * (b - a) + Eigen::Vector2d(0.2, -0.3);
  const FacetProjection r1 = project_on_facet(CellType::kLine2, xf, p1);
  EXPECT_EQ(r1.clamped_vertex, 1);
  EXPECT_DOUBLE_EQ(r1.eta[0], 1.0);
  EXPECT_NEAR(r1.distance2, (p1 - b).squaredNorm(), 1e-14);
  EXPECT_NEAR((r1.point.head<2>() - b).norm(), 0.0, 1e-15);
}

TEST(ClosestPointLine2, PointOnTheFacetHasZeroDistance) {
  const Eigen::Vector2d a(1.0, -1.0), b(3.0, 2.0);
  for (double s : {0.0, 0.25, 0.5, 1.0}) {
    const Eigen::VectorXd p = a + s * (b - a);
    const FacetProjection r = project_on_facet(CellType::kLine2, line2(a, b), p);
    EXPECT_NEAR(r.distance2, 0.0, 1e-28) << "s = " << s;
    EXPECT_NEAR(r.eta[0], s, 1e-14);
    EXPECT_NEAR((r.point.head<2>() - p).norm(), 0.0, 1e-14);
  }
}

TEST(ClosestPointLine2, DegenerateZeroLengthFacetGivesNoNaN) {
  const Eigen::Vector2d a(0.5, 0.5);
  const Eigen::VectorXd p = Eigen::Vector2d(1.5, -0.5);
  const FacetProjection r = project_on_facet(CellType::kLine2, line2(a, a), p);
  EXPECT_TRUE(std::isfinite(r.eta[0]));
  EXPECT_TRUE(r.point.allFinite());
  EXPECT_NEAR(r.distance2, 2.0, 1e-14);
  EXPECT_NEAR((r.point.head<2>() - a).norm(), 0.0, 1e-15);
  EXPECT_GE(r.eta[0], 0.0);
  EXPECT_LE(r.eta[0], 1.0);
}

TEST(ClosestPointLine3, StraightLine3MatchesLine2) {
  const Eigen::Vector2d a(0.0, 0.0), b(1.0, 0.5);
  Eigen::MatrixXd xf(2, 3);
  xf << a, b, 0.5 * (a + b);
  for (const Eigen::Vector2d& p : {Eigen::Vector2d(0.3, 0.7), Eigen::Vector2d(-0.5, 0.1), Eigen::Vector2d(1.7, 0.2)}) {
    const FacetProjection r3 = project_on_facet(CellType::kLine3, xf, p);
    const FacetProjection r2 = project_on_facet(CellType::kLine2, line2(a, b), p);
    EXPECT_EQ(r3.clamped_vertex, r2.clamped_vertex);
    EXPECT_NEAR(r3.eta[0], r2.eta[0], 1e-12);
    EXPECT_NEAR(r3.distance2, r2.distance2, 1e-12);
  }
}

TEST(ClosestPointLine3, CircularArcInteriorMatchesDenseSampling) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const Eigen::Vector2d c(0.3, -0.2);
  const double R = 1.5;
  for (int trial = 0; trial < 40; ++trial) {
    const double t0 = 2.0 * M_PI * U(rng), span = 0.2 + 0.8 * U(rng);
    const Eigen::MatrixXd xf = arc(c, R, t0, t0 + span);
    // A point at a radius from 0.5 R to 1.5 R, at an angle inside the arc's span.
    const double ang = t0 + span * (0.1 + 0.8 * U(rng)), rad = R * (0.5 + U(rng));
    const Eigen::VectorXd p = c + rad * Eigen::Vector2d(std::cos(ang), std::sin(ang));
    const FacetProjection r = project_on_facet(CellType::kLine3, xf, p);
    double eta_ref = 0.0;
    const double d2_ref = sampled_min_distance2(CellType::kLine3, xf, p, &eta_ref);
    EXPECT_EQ(r.clamped_vertex, -1) << "trial " << trial;
    EXPECT_NEAR(r.distance2, d2_ref, 1e-12) << "trial " << trial;
    EXPECT_NEAR(r.eta[0], eta_ref, 1e-6) << "trial " << trial;
    EXPECT_NEAR(stationarity(CellType::kLine3, xf, p, r.eta[0]), 0.0, 1e-12) << "trial " << trial;
    // The reported point is x(η).
    Eigen::VectorXd x, dx;
    curve_at(CellType::kLine3, xf, r.eta[0], x, dx);
    EXPECT_NEAR((r.point.head<2>() - x).norm(), 0.0, 1e-14);
    // Close to the true circle: the parabola through three points of the arc is within O(span⁴).
    EXPECT_NEAR(std::sqrt(r.distance2), std::abs(rad - R), 1e-2 * R);
  }
}

TEST(ClosestPointLine3, PastEitherEndOfAnArcClampsToTheEndNode) {
  const Eigen::Vector2d c(0.0, 0.0);
  const double R = 1.0;
  const Eigen::MatrixXd xf = arc(c, R, 0.0, 0.6);
  const Eigen::VectorXd before = 1.2 * Eigen::Vector2d(std::cos(-0.4), std::sin(-0.4));
  const FacetProjection r0 = project_on_facet(CellType::kLine3, xf, before);
  EXPECT_EQ(r0.clamped_vertex, 0);
  EXPECT_DOUBLE_EQ(r0.eta[0], 0.0);
  EXPECT_NEAR(r0.distance2, (before - xf.col(0)).squaredNorm(), 1e-14);
  const Eigen::VectorXd after = 0.9 * Eigen::Vector2d(std::cos(1.1), std::sin(1.1));
  const FacetProjection r1 = project_on_facet(CellType::kLine3, xf, after);
  EXPECT_EQ(r1.clamped_vertex, 1);
  EXPECT_DOUBLE_EQ(r1.eta[0], 1.0);
  EXPECT_NEAR(r1.distance2, (after - xf.col(1)).squaredNorm(), 1e-14);
}

TEST(ClosestPointLine3, PointOnTheCurvedFacetHasZeroDistance) {
  const Eigen::MatrixXd xf = arc(Eigen::Vector2d(1.0, 2.0), 0.7, 0.3, 1.2);
  for (double s : {0.1, 0.37, 0.5, 0.93}) {
    Eigen::VectorXd x, dx;
    curve_at(CellType::kLine3, xf, s, x, dx);
    const FacetProjection r = project_on_facet(CellType::kLine3, xf, x);
    EXPECT_EQ(r.clamped_vertex, -1);
    EXPECT_NEAR(r.distance2, 0.0, 1e-26) << "s = " << s;
    EXPECT_NEAR(r.eta[0], s, 1e-12);
  }
}

TEST(ClosestPointLine3, StronglyCurvedFacetIsStationaryAndGlobal) {
  // A parabola with a large bow (middle node far off the chord); points on both sides of it.
  Eigen::MatrixXd xf(2, 3);
  xf << 0.0, 1.0, 0.5,  //
      0.0, 0.0, 0.4;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int trial = 0; trial < 60; ++trial) {
    const Eigen::VectorXd p = Eigen::Vector2d(-0.3 + 1.6 * U(rng), -0.5 + 1.2 * U(rng));
    const FacetProjection r = project_on_facet(CellType::kLine3, xf, p);
    const double d2_ref = sampled_min_distance2(CellType::kLine3, xf, p, nullptr);
    EXPECT_NEAR(r.distance2, d2_ref, 1e-10) << "p = " << p.transpose();
    if (r.clamped_vertex < 0) {
      EXPECT_NEAR(stationarity(CellType::kLine3, xf, p, r.eta[0]), 0.0, 1e-12) << "p = " << p.transpose();
      EXPECT_GE(r.eta[0], 0.0);
      EXPECT_LE(r.eta[0], 1.0);
    }
  }
}

TEST(ClosestPointLine3, DegenerateFacetGivesNoNaN) {
  // All three nodes at one point, and a Line3 whose ends coincide (a closed loop).
  Eigen::MatrixXd point(2, 3), loop(2, 3);
  point << 0.5, 0.5, 0.5, 0.5, 0.5, 0.5;
  loop << 0.0, 0.0, 1.0, 0.0, 0.0, 0.0;
  const Eigen::VectorXd p = Eigen::Vector2d(2.0, 1.0);
  for (const Eigen::MatrixXd* xf : {&point, &loop}) {
    const FacetProjection r = project_on_facet(CellType::kLine3, *xf, p);
    EXPECT_TRUE(std::isfinite(r.eta[0]));
    EXPECT_TRUE(r.point.allFinite());
    EXPECT_TRUE(std::isfinite(r.distance2));
    EXPECT_NEAR(r.distance2, sampled_min_distance2(CellType::kLine3, *xf, p, nullptr), 1e-10);
  }
}

TEST(ClosestPointLine3, UnsupportedFacetTypeThrows) {
  Eigen::MatrixXd xf = Eigen::MatrixXd::Identity(3, 4);
  EXPECT_THROW(project_on_facet(CellType::kTet4, xf, Eigen::Vector3d(0.1, 0.1, 1.0)), std::logic_error);
}

// ---------------------------------------------------------------------------------------------------
// Triangles (3D).

namespace {

Eigen::Vector3d surface_at(CellType t, const Eigen::MatrixXd& xf, double e1, double e2,
                           Eigen::Matrix<double, 3, 2>* d = nullptr) {
  const double eta[2] = {e1, e2};
  double N[9], dN[18];
  shape_functions(t, eta, N, dN);
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  if (d) d->setZero();
  for (int a = 0; a < cell_num_nodes(t); ++a) {
    x += N[a] * xf.col(a);
    if (d) {
      d->col(0) += dN[2 * a] * xf.col(a);
      d->col(1) += dN[2 * a + 1] * xf.col(a);
    }
  }
  return x;
}

/// Minimum of |x(η) − p|² over a dense grid of the reference triangle, refined by a finer grid around the
/// best sample (brute force, independent of the projector).
double sampled_min_distance2_tri(CellType t, const Eigen::MatrixXd& xf, const Eigen::Vector3d& p, double* eta_min) {
  double best = std::numeric_limits<double>::infinity(), b1 = 0, b2 = 0;
  const int n = 400;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const double d2 = (surface_at(t, xf, double(i) / n, double(j) / n) - p).squaredNorm();
      if (d2 < best) {
        best = d2;
        b1 = double(i) / n;
        b2 = double(j) / n;
      }
    }
  // Refine around the best sample, staying in the triangle.
  double h = 1.0 / n;
  for (int level = 0; level < 30; ++level) {
    const double c1 = b1, c2 = b2;
    for (int i = -4; i <= 4; ++i)
      for (int j = -4; j <= 4; ++j) {
        const double e1 = c1 + 0.25 * i * h, e2 = c2 + 0.25 * j * h;
        if (e1 < 0 || e2 < 0 || e1 + e2 > 1) continue;
        const double d2 = (surface_at(t, xf, e1, e2) - p).squaredNorm();
        if (d2 < best) {
          best = d2;
          b1 = e1;
          b2 = e2;
        }
      }
    h *= 0.5;
  }
  if (eta_min) {
    eta_min[0] = b1;
    eta_min[1] = b2;
  }
  return best;
}

Eigen::MatrixXd tri3(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  Eigen::MatrixXd xf(3, 3);
  xf << a, b, c;
  return xf;
}

/// A Tri6 on the sphere of radius R about the origin: vertices at the given unit directions, edge nodes
/// on the sphere above the chord midpoints.
Eigen::MatrixXd spherical_tri6(double R, const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  Eigen::MatrixXd xf(3, 6);
  const Eigen::Vector3d v[3] = {a.normalized(), b.normalized(), c.normalized()};
  for (int k = 0; k < 3; ++k) xf.col(k) = R * v[k];
  for (int e = 0; e < 3; ++e) xf.col(3 + e) = R * (v[triangle_edge(e)[0]] + v[triangle_edge(e)[1]]).normalized();
  return xf;
}

}  // namespace

TEST(ClosestPointTri3, InsideEdgeAndVertexRegions) {
  const Eigen::Vector3d a(0, 0, 0), b(2, 0, 0), c(0, 1, 0.5);
  const Eigen::MatrixXd xf = tri3(a, b, c);
  const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
  // Inside: the foot of the perpendicular, at (η1, η2) = (0.3, 0.4).
  const Eigen::Vector3d foot = a + 0.3 * (b - a) + 0.4 * (c - a);
  FacetProjection r = project_on_facet(CellType::kTri3, xf, foot + 0.7 * n);
  EXPECT_TRUE(r.inside());
  EXPECT_NEAR(r.eta[0], 0.3, 1e-14);
  EXPECT_NEAR(r.eta[1], 0.4, 1e-14);
  EXPECT_NEAR(r.distance2, 0.49, 1e-14);
  EXPECT_NEAR((r.point - foot).norm(), 0.0, 1e-14);
  // Past edge 0 (a, b), in the triangle's plane: clamped onto that edge.
  const Eigen::Vector3d below = a + 0.6 * (b - a) - 0.3 * n.cross(b - a).normalized();
  r = project_on_facet(CellType::kTri3, xf, below + 0.2 * n);
  EXPECT_EQ(r.clamped_edge, 0);
  EXPECT_EQ(r.clamped_vertex, -1);
  EXPECT_FALSE(r.inside());
  EXPECT_NEAR(r.eta[0], 0.6, 1e-14);
  EXPECT_NEAR(r.eta[1], 0.0, 1e-14);
  EXPECT_NEAR(r.distance2, 0.09 + 0.04, 1e-14);
  // Beyond vertex b along its outward bisector: clamped to vertex 1.
  r = project_on_facet(CellType::kTri3, xf, b + 0.5 * ((b - a).normalized() + (b - c).normalized()) + 0.1 * n);
  EXPECT_EQ(r.clamped_vertex, 1);
  EXPECT_EQ(r.clamped_edge, -1);
  EXPECT_NEAR(r.eta[0], 1.0, 0.0);
  EXPECT_NEAR(r.eta[1], 0.0, 0.0);
  // A point on the facet, on edge 2 (c, a): inside, zero distance.
  r = project_on_facet(CellType::kTri3, xf, 0.5 * (a + c));
  EXPECT_TRUE(r.inside());
  EXPECT_NEAR(r.distance2, 0.0, 1e-28);
}

TEST(ClosestPointTri3, RandomPointsMatchBruteForceSampling) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  int inside = 0, edge = 0, vertex = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Eigen::MatrixXd xf = tri3(Eigen::Vector3d(U(rng), U(rng), U(rng)), Eigen::Vector3d(U(rng), U(rng), U(rng)),
                                    Eigen::Vector3d(U(rng), U(rng), U(rng)));
    if (Eigen::Vector3d(xf.col(1) - xf.col(0)).cross(Eigen::Vector3d(xf.col(2) - xf.col(0))).norm() < 0.1) continue;
    const Eigen::Vector3d p(1.5 * U(rng), 1.5 * U(rng), 1.5 * U(rng));
    const FacetProjection r = project_on_facet(CellType::kTri3, xf, p);
    double eta_ref[2];
    const double d2_ref = sampled_min_distance2_tri(CellType::kTri3, xf, p, eta_ref);
    EXPECT_NEAR(r.distance2, d2_ref, 1e-10) << "trial " << trial;
    EXPECT_LE(r.distance2, d2_ref + 1e-14) << "trial " << trial;
    EXPECT_NEAR(r.eta[0], eta_ref[0], 1e-5) << "trial " << trial;
    EXPECT_NEAR(r.eta[1], eta_ref[1], 1e-5) << "trial " << trial;
    EXPECT_NEAR((surface_at(CellType::kTri3, xf, r.eta[0], r.eta[1]) - r.point).norm(), 0.0, 1e-14);
    // The report agrees with where η is.
    const double l[3] = {1 - r.eta[0] - r.eta[1], r.eta[0], r.eta[1]};
    if (r.inside()) {
      ++inside;
    } else if (r.clamped_edge >= 0) {
      ++edge;
      EXPECT_NEAR(l[(r.clamped_edge + 2) % 3], 0.0, 1e-14);  // the barycentric of the opposite vertex
    } else {
      ++vertex;
      EXPECT_NEAR(l[r.clamped_vertex], 1.0, 1e-14);
    }
  }
  // The random points visit all three kinds of region.
  EXPECT_GT(inside, 0);
  EXPECT_GT(edge, 0);
  EXPECT_GT(vertex, 0);
}

TEST(ClosestPointTri6, FlatTri6MatchesTri3) {
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0.2), c(0.1, 1, 0);
  Eigen::MatrixXd xf6(3, 6);
  xf6 << a, b, c, 0.5 * (a + b), 0.5 * (b + c), 0.5 * (c + a);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(-1.0, 1.5);
  for (int trial = 0; trial < 30; ++trial) {
    const Eigen::Vector3d p(U(rng), U(rng), U(rng));
    const FacetProjection r6 = project_on_facet(CellType::kTri6, xf6, p);
    const FacetProjection r3 = project_on_facet(CellType::kTri3, tri3(a, b, c), p);
    EXPECT_NEAR(r6.distance2, r3.distance2, 1e-12) << "trial " << trial;
    EXPECT_NEAR(r6.eta[0], r3.eta[0], 1e-9) << "trial " << trial;
    EXPECT_NEAR(r6.eta[1], r3.eta[1], 1e-9) << "trial " << trial;
    EXPECT_EQ(r6.clamped_edge, r3.clamped_edge) << "trial " << trial;
    EXPECT_EQ(r6.clamped_vertex, r3.clamped_vertex) << "trial " << trial;
  }
}

TEST(ClosestPointTri6, CurvedFacetNewtonIsStationaryAndMatchesSampling) {
  // A spherical Tri6 patch (R = 1, an octant-sized curved facet) and points inside and outside it.
  const Eigen::MatrixXd xf = spherical_tri6(1.0, Eigen::Vector3d(1, 0.1, 0.1), Eigen::Vector3d(0.1, 1, 0.1),
                                            Eigen::Vector3d(0.1, 0.1, 1));
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int interior = 0, boundary = 0;
  for (int trial = 0; trial < 60; ++trial) {
    // Directions spread over and beyond the patch, radii 0.6–1.4.
    const Eigen::Vector3d dir = Eigen::Vector3d(U(rng), U(rng), U(rng)) * 1.2 - Eigen::Vector3d::Constant(0.1);
    if (dir.norm() < 0.2) continue;
    const Eigen::Vector3d p = (0.6 + 0.8 * U(rng)) * dir.normalized();
    const FacetProjection r = project_on_facet(CellType::kTri6, xf, p);
    double eta_ref[2];
    const double d2_ref = sampled_min_distance2_tri(CellType::kTri6, xf, p, eta_ref);
    EXPECT_NEAR(r.distance2, d2_ref, 1e-10) << "trial " << trial;
    EXPECT_LE(r.distance2, d2_ref + 1e-13) << "trial " << trial;
    EXPECT_NEAR((surface_at(CellType::kTri6, xf, r.eta[0], r.eta[1]) - r.point).norm(), 0.0, 1e-14);
    if (r.inside()) {
      ++interior;
      // Stationarity: the residual is normal to the facet, (x − p)·∂x/∂η_i = 0.
      Eigen::Matrix<double, 3, 2> d;
      const Eigen::Vector3d x = surface_at(CellType::kTri6, xf, r.eta[0], r.eta[1], &d);
      EXPECT_NEAR((x - p).dot(d.col(0)), 0.0, 1e-12) << "trial " << trial;
      EXPECT_NEAR((x - p).dot(d.col(1)), 0.0, 1e-12) << "trial " << trial;
      EXPECT_NEAR(r.eta[0], eta_ref[0], 1e-5) << "trial " << trial;
      EXPECT_NEAR(r.eta[1], eta_ref[1], 1e-5) << "trial " << trial;
    } else {
      ++boundary;
      const double l[3] = {1 - r.eta[0] - r.eta[1], r.eta[0], r.eta[1]};
      EXPECT_NEAR(std::min({l[0], l[1], l[2]}), 0.0, 1e-14) << "trial " << trial;
    }
  }
  EXPECT_GT(interior, 10);
  EXPECT_GT(boundary, 5);
}

TEST(ClosestPointTri6, PointOnTheCurvedFacetHasZeroDistance) {
  const Eigen::MatrixXd xf = spherical_tri6(2.0, Eigen::Vector3d(1, 0.2, 0), Eigen::Vector3d(0.2, 1, 0.1),
                                            Eigen::Vector3d(0.3, 0.3, 1));
  for (const auto& e : {std::array<double, 2>{0.2, 0.3}, std::array<double, 2>{0.6, 0.1}, std::array<double, 2>{1.0 / 3, 1.0 / 3}}) {
    const Eigen::Vector3d x = surface_at(CellType::kTri6, xf, e[0], e[1]);
    const FacetProjection r = project_on_facet(CellType::kTri6, xf, x);
    EXPECT_TRUE(r.inside());
    EXPECT_NEAR(r.distance2, 0.0, 1e-26);
    EXPECT_NEAR(r.eta[0], e[0], 1e-12);
    EXPECT_NEAR(r.eta[1], e[1], 1e-12);
  }
}

// ---------------------------------------------------------------------------------------------------
// Quadrilaterals (3D): the faces of Hex8 and Hex27 cells.

namespace {

/// Minimum of |x(η) − p|² over a grid of [0, 1]², refined around the best sample (brute force).
double sampled_min_distance2_quad(CellType t, const Eigen::MatrixXd& xf, const Eigen::Vector3d& p, double* eta_min) {
  double best = std::numeric_limits<double>::infinity(), b1 = 0, b2 = 0;
  const int n = 300;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double d2 = (surface_at(t, xf, double(i) / n, double(j) / n) - p).squaredNorm();
      if (d2 < best) best = d2, b1 = double(i) / n, b2 = double(j) / n;
    }
  double h = 1.0 / n;
  for (int level = 0; level < 30; ++level, h *= 0.5) {
    const double c1 = b1, c2 = b2;
    for (int i = -4; i <= 4; ++i)
      for (int j = -4; j <= 4; ++j) {
        const double e1 = std::clamp(c1 + 0.25 * i * h, 0.0, 1.0), e2 = std::clamp(c2 + 0.25 * j * h, 0.0, 1.0);
        const double d2 = (surface_at(t, xf, e1, e2) - p).squaredNorm();
        if (d2 < best) best = d2, b1 = e1, b2 = e2;
      }
  }
  eta_min[0] = b1;
  eta_min[1] = b2;
  return best;
}

/// A Quad9 on the sphere of radius R about the origin: vertices at the given directions (counter-clockwise
/// seen from outside), edge nodes and centre on the sphere above the chord midpoints and the vertices' mean.
Eigen::MatrixXd spherical_quad9(double R, const Eigen::Vector3d* v) {
  Eigen::MatrixXd xf(3, 9);
  for (int k = 0; k < 4; ++k) {
    xf.col(k) = R * v[k].normalized();
    xf.col(4 + k) = R * (v[k].normalized() + v[(k + 1) % 4].normalized()).normalized();
  }
  xf.col(8) = R * (v[0].normalized() + v[1].normalized() + v[2].normalized() + v[3].normalized()).normalized();
  return xf;
}

}  // namespace

// A skewed flat Quad4 and a spherical Quad9 (and the Quad8 of its vertices and edge nodes): the projection is the brute-force minimum, stationary inside
// (the residual normal to both tangents), on an edge (ξ or η at 0 or 1) otherwise, with the edge or vertex
// reported; a point of the facet projects onto itself.
TEST(ClosestPointQuad, MatchesSamplingStationaryInsideAndOnTheBorderOutside) {
  Eigen::MatrixXd q4(3, 4);
  q4 << 0, 1.2, 1.4, 0.1, 0, 0.1, 1.1, 0.9, 0, 0, 0.1, 0.05;
  const Eigen::Vector3d dirs[4] = {Eigen::Vector3d(1, 0.1, 0.1), Eigen::Vector3d(0.2, 1, 0.1),
                                   Eigen::Vector3d(0.1, 0.6, 1), Eigen::Vector3d(0.8, 0.1, 1)};
  const Eigen::MatrixXd q9 = spherical_quad9(1.0, dirs);
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const Eigen::MatrixXd q8 = q9.leftCols(8);  // the serendipity facet through the same vertices and edge nodes
  for (const auto& [type, xf] : {std::pair<CellType, Eigen::MatrixXd>{CellType::kQuad4, q4}, {CellType::kQuad8, q8},
                                 {CellType::kQuad9, q9}}) {
    int interior = 0, boundary = 0;
    for (int trial = 0; trial < 40; ++trial) {
      const Eigen::Vector3d c = surface_at(type, xf, 1.6 * U(rng) - 0.3, 1.6 * U(rng) - 0.3);
      const Eigen::Vector3d p = type == CellType::kQuad4 ? Eigen::Vector3d(c + Eigen::Vector3d(0, 0, U(rng) - 0.5))
                                                         : Eigen::Vector3d((0.7 + 0.6 * U(rng)) * c.normalized());
      const FacetProjection r = project_on_facet(type, xf, p);
      double eta_ref[2];
      const double d2_ref = sampled_min_distance2_quad(type, xf, p, eta_ref);
      EXPECT_NEAR(r.distance2, d2_ref, 1e-10) << cell_name(type) << " trial " << trial;
      EXPECT_LE(r.distance2, d2_ref + 1e-13) << cell_name(type) << " trial " << trial;
      EXPECT_NEAR((surface_at(type, xf, r.eta[0], r.eta[1]) - r.point).norm(), 0.0, 1e-14);
      if (r.inside()) {
        ++interior;
        Eigen::Matrix<double, 3, 2> d;
        const Eigen::Vector3d x = surface_at(type, xf, r.eta[0], r.eta[1], &d);
        EXPECT_NEAR((x - p).dot(d.col(0)), 0.0, 1e-12) << cell_name(type) << " trial " << trial;
        EXPECT_NEAR((x - p).dot(d.col(1)), 0.0, 1e-12) << cell_name(type) << " trial " << trial;
      } else {
        ++boundary;
        const double to_border = std::min({r.eta[0], r.eta[1], 1 - r.eta[0], 1 - r.eta[1]});
        EXPECT_NEAR(to_border, 0.0, 1e-14) << cell_name(type) << " trial " << trial;
        // The reported edge or vertex holds η: edge e0 at η2 = 0, e1 at η1 = 1, e2 at η2 = 1, e3 at η1 = 0.
        const double vertex[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        if (r.clamped_edge >= 0) {
          const int e = r.clamped_edge;
          EXPECT_EQ(r.eta[e % 2 == 0 ? 1 : 0], e == 1 || e == 2 ? 1.0 : 0.0) << "edge " << e;
        } else {
          ASSERT_GE(r.clamped_vertex, 0);
          EXPECT_EQ(r.eta[0], vertex[r.clamped_vertex][0]);
          EXPECT_EQ(r.eta[1], vertex[r.clamped_vertex][1]);
        }
      }
    }
    EXPECT_GT(interior, 5) << cell_name(type);
    EXPECT_GT(boundary, 5) << cell_name(type);
    const Eigen::Vector3d on = surface_at(type, xf, 0.3, 0.7);
    const FacetProjection r = project_on_facet(type, xf, on);
    EXPECT_TRUE(r.inside());
    EXPECT_NEAR(r.distance2, 0.0, 1e-26);
    EXPECT_NEAR(r.eta[0], 0.3, 1e-12);
    EXPECT_NEAR(r.eta[1], 0.7, 1e-12);
  }
}
