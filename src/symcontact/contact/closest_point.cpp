#include "symcontact/contact/closest_point.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "symcontact/fem/shape_functions.hpp"

namespace symcontact {

namespace {

Eigen::VectorXd point_at(CellType t, const Eigen::MatrixXd& xf, double eta, Eigen::VectorXd* d1,
                         Eigen::VectorXd* d2) {
  double N[3], dN[3];
  shape_functions(t, &eta, N, dN);
  const int n = cell_num_nodes(t);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(xf.rows());
  if (d1) d1->setZero(xf.rows());
  for (int a = 0; a < n; ++a) {
    x += N[a] * xf.col(a);
    if (d1) *d1 += dN[a] * xf.col(a);
  }
  if (d2) {
    // Line3: x'' = 4 x0 + 4 x1 − 8 x2 (constant); Line2: 0.
    d2->setZero(xf.rows());
    if (n == 3) *d2 = 4.0 * xf.col(0) + 4.0 * xf.col(1) - 8.0 * xf.col(2);
  }
  return x;
}

FacetProjection project_on_line(CellType t, const Eigen::MatrixXd& xf, const Eigen::VectorXd& p) {
  FacetProjection r;
  const Eigen::VectorXd a = xf.col(0), b = xf.col(1);
  const Eigen::VectorXd ab = b - a;
  double eta = ab.squaredNorm() > 0 ? (p - a).dot(ab) / ab.squaredNorm() : 0.0;
  if (t == CellType::kLine3) {
    // Newton on φ(η) = (x(η) − p)·x'(η), from the chord's projection.
    Eigen::VectorXd d1, d2;
    for (int it = 0; it < 30; ++it) {
      const double e = std::clamp(eta, -0.5, 1.5);
      const Eigen::VectorXd x = point_at(t, xf, e, &d1, &d2);
      const double phi = (x - p).dot(d1);
      const double dphi = d1.squaredNorm() + (x - p).dot(d2);
      const double step = dphi > 0 ? -phi / dphi : -phi / std::max(d1.squaredNorm(), 1e-300);
      eta = e + step;
      if (std::abs(step) < 1e-14) break;
    }
  }
  const bool inside = eta >= 0.0 && eta <= 1.0;
  double best = std::numeric_limits<double>::infinity();
  auto consider = [&](double e, int clamped) {
    const Eigen::VectorXd x = point_at(t, xf, e, nullptr, nullptr);
    const double d2 = (x - p).squaredNorm();
    if (d2 < best) {
      best = d2;
      r.eta[0] = e;
      r.point.setZero();
      r.point.head(x.size()) = x;
      r.distance2 = d2;
      r.clamped_vertex = clamped;
    }
  };
  if (inside) consider(eta, -1);
  consider(0.0, 0);
  consider(1.0, 1);
  // A stationary point inside beats an end only if strictly closer; ties go to the interior point.
  if (inside) {
    const Eigen::VectorXd x = point_at(t, xf, eta, nullptr, nullptr);
    if ((x - p).squaredNorm() <= r.distance2 * (1 + 1e-14)) {
      r.eta[0] = eta;
      r.point.head(x.size()) = x;
      r.distance2 = (x - p).squaredNorm();
      r.clamped_vertex = -1;
    }
  }
  return r;
}

}  // namespace

FacetProjection project_on_facet(CellType type, const Eigen::MatrixXd& xf, const Eigen::VectorXd& p) {
  switch (type) {
    case CellType::kLine2:
    case CellType::kLine3: return project_on_line(type, xf, p);
    default: break;
  }
  throw std::logic_error("project_on_facet: " + cell_name(type) + " facets are not supported yet (3D contact)");
}

}  // namespace symcontact
