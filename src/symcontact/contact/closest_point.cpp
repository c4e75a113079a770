#include "symcontact/contact/closest_point.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
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

/// Barycentric tolerance of "inside" for triangles: a point on an edge up to round-off is inside.
constexpr double kInsideTol = 1e-12;

/// x(η), ∂x/∂η_i (columns of d1) of a triangle or quadrilateral facet.
Eigen::Vector3d facet_point(CellType t, const Eigen::MatrixXd& xf, const double* eta, Eigen::Matrix<double, 3, 2>* d1) {
  double N[9], dN[18];
  shape_functions(t, eta, N, dN);
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  if (d1) d1->setZero();
  for (int a = 0; a < cell_num_nodes(t); ++a) {
    x += N[a] * xf.col(a).head<3>();
    if (d1) {
      d1->col(0) += dN[2 * a] * xf.col(a).head<3>();
      d1->col(1) += dN[2 * a + 1] * xf.col(a).head<3>();
    }
  }
  return x;
}

/// Closest point of the segment [a, b] to p: parameter t ∈ [0, 1].
double segment_parameter(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& p) {
  const Eigen::Vector3d ab = b - a;
  const double L2 = ab.squaredNorm();
  return L2 > 0 ? std::clamp((p - a).dot(ab) / L2, 0.0, 1.0) : 0.0;
}

/// The foot of the perpendicular from p on the plane of the vertex triangle, in (η1, η2) (unclamped).
Eigen::Vector2d plane_coordinates(const Eigen::MatrixXd& xf, const Eigen::Vector3d& p) {
  const Eigen::Vector3d a = xf.col(0).head<3>();
  const Eigen::Vector3d e1 = xf.col(1).head<3>() - a, e2 = xf.col(2).head<3>() - a;
  Eigen::Matrix2d G;
  G << e1.dot(e1), e1.dot(e2), e1.dot(e2), e2.dot(e2);
  const Eigen::Vector2d r((p - a).dot(e1), (p - a).dot(e2));
  const double det = G.determinant();
  if (!(std::abs(det) > 1e-300 * std::max(1.0, G.squaredNorm()))) return Eigen::Vector2d(1.0 / 3, 1.0 / 3);
  return G.inverse() * r;
}

bool inside_triangle(const double* eta) {
  return eta[0] >= -kInsideTol && eta[1] >= -kInsideTol && 1.0 - eta[0] - eta[1] >= -kInsideTol;
}

/// Edge parameter t ∈ [0, 1] → clamping report: a vertex at the ends, else the edge.
void report_edge(int e, double t, FacetProjection& r) {
  r.clamped_edge = -1;
  r.clamped_vertex = -1;
  if (t <= 0.0) r.clamped_vertex = triangle_edge(e)[0];
  else if (t >= 1.0) r.clamped_vertex = triangle_edge(e)[1];
  else r.clamped_edge = e;
}

/// The projection of p at the point η inside the facet (snapped onto it against round-off).
FacetProjection interior_projection(CellType type, const Eigen::MatrixXd& xf, const Eigen::Vector3d& p, double eta[2]) {
  FacetProjection r;
  snap_into_triangle(eta);
  r.eta[0] = eta[0];
  r.eta[1] = eta[1];
  r.point = facet_point(type, xf, eta, nullptr);
  r.distance2 = (r.point - p).squaredNorm();
  return r;
}

FacetProjection project_on_tri3(const Eigen::MatrixXd& xf, const Eigen::Vector3d& p) {
  FacetProjection r;
  const Eigen::Vector2d e = plane_coordinates(xf, p);
  double eta[2] = {e[0], e[1]};
  if (inside_triangle(eta)) return interior_projection(CellType::kTri3, xf, p, eta);
  r.distance2 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d a = xf.col(triangle_edge(k)[0]).head<3>(), b = xf.col(triangle_edge(k)[1]).head<3>();
    const double t = segment_parameter(a, b, p);
    const Eigen::Vector3d x = a + t * (b - a);
    const double d2 = (x - p).squaredNorm();
    if (d2 < r.distance2) {
      r.distance2 = d2;
      r.point = x;
      triangle_edge_point(k, t, r.eta);
      report_edge(k, t, r);
    }
  }
  return r;
}

/// The curvature part S_ij = (x − p) · x_,ij of the Hessian of f(η) = ½ |x(η) − p|², res = x(η) − p, by
/// central differences of ∂x/∂η with step 1/2 (exact where ∂x/∂η_i is at most quadratic in η_j).
Eigen::Matrix2d curvature_term(CellType type, const Eigen::MatrixXd& xf, const Eigen::Vector2d& eta,
                               const Eigen::Vector3d& res) {
  Eigen::Matrix<double, 3, 2> dp, dm;
  Eigen::Matrix2d S;
  for (int j = 0; j < 2; ++j) {
    Eigen::Vector2d ep = eta, em = eta;
    ep[j] += 0.5;
    em[j] -= 0.5;
    facet_point(type, xf, ep.data(), &dp);
    facet_point(type, xf, em.data(), &dm);
    for (int i = 0; i < 2; ++i) S(i, j) = res.dot(dp.col(i) - dm.col(i));
  }
  return 0.5 * (S + S.transpose());
}

/// One Newton step on ∇f = 0 with gradient g, Gauss–Newton part H = JᵀJ and curvature part S: the full
/// Hessian H + S where it is positive definite, H alone elsewhere (away from a minimum); steps longer than
/// 1/2 are shortened to it. Returns false when the loop is to stop: a singular Hessian, or a step below
/// 1e-14 (then `converged`, and `local_min` when the full Hessian was used).
bool newton_step(const Eigen::Vector2d& g, const Eigen::Matrix2d& H, const Eigen::Matrix2d& S, Eigen::Vector2d& eta,
                 bool& converged, bool& local_min) {
  const Eigen::Matrix2d Hn = H + S;
  const bool spd = Hn(0, 0) > 0 && Hn.determinant() > 1e-14 * Hn.squaredNorm();
  const Eigen::Matrix2d& Hs = spd ? Hn : H;
  if (!(std::abs(Hs.determinant()) > 0)) return false;
  Eigen::Vector2d step = -Hs.inverse() * g;
  const double len = step.norm();
  if (len > 0.5) step *= 0.5 / len;
  eta += step;
  if (len < 1e-14) {
    converged = true;
    local_min = spd;
    return false;
  }
  return true;
}

FacetProjection project_on_tri6(const Eigen::MatrixXd& xf, const Eigen::Vector3d& p) {
  FacetProjection r;
  r.distance2 = std::numeric_limits<double>::infinity();
  // Interior: Newton on ∇f = 0, f(η) = ½ |x(η) − p|², from the vertex triangle's foot point.
  Eigen::Vector2d eta = plane_coordinates(xf, p);
  Eigen::Matrix<double, 3, 2> d1;
  bool converged = false, local_min = false;
  for (int it = 0; it < 40; ++it) {
    eta = eta.cwiseMax(-0.5).cwiseMin(1.5);
    const Eigen::Vector3d x = facet_point(CellType::kTri6, xf, eta.data(), &d1);
    const Eigen::Vector3d res = x - p;
    const Eigen::Vector2d g(res.dot(d1.col(0)), res.dot(d1.col(1)));
    // Second derivatives x_,ij: ∂x/∂η_i is linear in η, so a central difference of it is exact.
    if (!newton_step(g, d1.transpose() * d1, curvature_term(CellType::kTri6, xf, eta, res), eta, converged, local_min))
      break;
    // Heading well outside the facet: the boundary decides, no need to converge out there.
    if (it >= 6 && std::min({eta[0], eta[1], 1.0 - eta[0] - eta[1]}) < -0.1) break;
  }
  double e[2] = {eta[0], eta[1]};
  const bool inside = converged && inside_triangle(e);
  if (inside && local_min) {
    // A local minimum inside the facet: on a facet whose curvature radius exceeds its size (any
    // sensible mesh), the squared distance is convex over the facet and this is the closest point.
    return interior_projection(CellType::kTri6, xf, p, e);
  }
  // Boundary: the three edges are Line3 curves (vertex a, vertex b, edge node).
  Eigen::MatrixXd xe(xf.rows(), 3);
  for (int k = 0; k < 3; ++k) {
    xe.col(0) = xf.col(triangle_edge(k)[0]);
    xe.col(1) = xf.col(triangle_edge(k)[1]);
    xe.col(2) = xf.col(3 + k);
    const FacetProjection q = project_on_line(CellType::kLine3, xe, p);
    if (q.distance2 < r.distance2) {
      r.distance2 = q.distance2;
      r.point = q.point;
      triangle_edge_point(k, q.eta[0], r.eta);
      report_edge(k, q.eta[0], r);
    }
  }
  if (inside) {
    snap_into_triangle(e);
    const Eigen::Vector3d x = facet_point(CellType::kTri6, xf, e, nullptr);
    const double d2 = (x - p).squaredNorm();
    if (d2 <= r.distance2 * (1 + 1e-14) + 1e-300) {
      r.eta[0] = e[0];
      r.eta[1] = e[1];
      r.point = x;
      r.distance2 = d2;
      r.clamped_vertex = r.clamped_edge = -1;
    }
  }
  return r;
}

/// Quadrilateral reference coordinates of the point at parameter t along edge e (from its vertex a to b).
void quad_edge_point(int e, double t, double* eta) {
  switch (e) {
    case 0: eta[0] = t; eta[1] = 0.0; break;
    case 1: eta[0] = 1.0; eta[1] = t; break;
    case 2: eta[0] = 1.0 - t; eta[1] = 1.0; break;
    default: eta[0] = 0.0; eta[1] = 1.0 - t; break;
  }
}

bool inside_square(const double* eta) {
  return eta[0] >= -kInsideTol && eta[1] >= -kInsideTol && eta[0] <= 1 + kInsideTol && eta[1] <= 1 + kInsideTol;
}

/// Newton on ∇f = 0, f(η) = ½ |x(η) − p|², over the quadrilateral (Gauss–Newton where the Hessian is not
/// positive definite); `converged` and `local_min` report how it ended.
Eigen::Vector2d quad_newton(CellType type, const Eigen::MatrixXd& xf, const Eigen::Vector3d& p, bool& converged,
                            bool& local_min) {
  Eigen::Vector2d eta(0.5, 0.5);
  Eigen::Matrix<double, 3, 2> d1;
  converged = local_min = false;
  for (int it = 0; it < 40; ++it) {
    eta = eta.cwiseMax(-0.5).cwiseMin(1.5);
    const Eigen::Vector3d res = facet_point(type, xf, eta.data(), &d1) - p;
    const Eigen::Vector2d g(res.dot(d1.col(0)), res.dot(d1.col(1)));
    // Second derivatives by central differences of ∂x/∂η: exact, since ∂x/∂η_i of a bilinear, serendipity or
    // biquadratic map is at most quadratic in each variable, and central differences are exact on quadratics.
    if (!newton_step(g, d1.transpose() * d1, curvature_term(type, xf, eta, res), eta, converged, local_min)) break;
    if (it >= 6 && std::min({eta[0], eta[1], 1.0 - eta[0], 1.0 - eta[1]}) < -0.1) break;
  }
  return eta;
}

FacetProjection project_on_quad(CellType type, const Eigen::MatrixXd& xf, const Eigen::Vector3d& p) {
  FacetProjection r;
  r.distance2 = std::numeric_limits<double>::infinity();
  bool converged = false, local_min = false;
  const Eigen::Vector2d eta = quad_newton(type, xf, p, converged, local_min);
  double e[2] = {std::clamp(eta[0], 0.0, 1.0), std::clamp(eta[1], 0.0, 1.0)};
  const bool inside = converged && inside_square(eta.data());
  const auto interior = [&] {
    r.eta[0] = e[0];
    r.eta[1] = e[1];
    r.point = facet_point(type, xf, e, nullptr);
    r.distance2 = (r.point - p).squaredNorm();
    r.clamped_vertex = r.clamped_edge = -1;
  };
  if (inside && local_min) {  // as on a Tri6 (project_on_tri6())
    interior();
    return r;
  }
  const CellType edge_type = type == CellType::kQuad4 ? CellType::kLine2 : CellType::kLine3;
  Eigen::MatrixXd xe(xf.rows(), cell_num_nodes(edge_type));
  for (int k = 0; k < 4; ++k) {
    xe.col(0) = xf.col(k);
    xe.col(1) = xf.col((k + 1) % 4);
    if (edge_type == CellType::kLine3) xe.col(2) = xf.col(4 + k);
    const FacetProjection q = project_on_line(edge_type, xe, p);
    if (q.distance2 < r.distance2) {
      r.distance2 = q.distance2;
      r.point = q.point;
      quad_edge_point(k, q.eta[0], r.eta);
      r.clamped_edge = r.clamped_vertex = -1;
      if (q.eta[0] <= 0.0) r.clamped_vertex = k;
      else if (q.eta[0] >= 1.0) r.clamped_vertex = (k + 1) % 4;
      else r.clamped_edge = k;
    }
  }
  if (inside) {
    const double d2 = (facet_point(type, xf, e, nullptr) - p).squaredNorm();
    if (d2 <= r.distance2 * (1 + 1e-14) + 1e-300) interior();
  }
  return r;
}

}  // namespace

int facet_num_edges(CellType t) { return cell_shape(t) == CellShape::kTensor ? 4 : 3; }

const int* facet_edge(CellType t, int e) {
  static const int quad[4][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  return cell_shape(t) == CellShape::kTensor ? quad[e] : triangle_edge(e);
}

bool snap_into_facet(CellType t, double* eta, double tol) {
  if (cell_shape(t) != CellShape::kTensor) {
    const bool in = eta[0] >= -tol && eta[1] >= -tol && eta[0] + eta[1] <= 1 + tol;
    snap_into_triangle(eta);
    return in;
  }
  const bool in = eta[0] >= -tol && eta[1] >= -tol && eta[0] <= 1 + tol && eta[1] <= 1 + tol;
  eta[0] = std::clamp(eta[0], 0.0, 1.0);
  eta[1] = std::clamp(eta[1], 0.0, 1.0);
  return in;
}

void triangle_edge_point(int e, double t, double* eta) {
  switch (e) {
    case 0: eta[0] = t; eta[1] = 0.0; break;
    case 1: eta[0] = 1.0 - t; eta[1] = t; break;
    default: eta[0] = 0.0; eta[1] = 1.0 - t; break;
  }
}

FacetProjection project_on_facet(CellType type, const Eigen::MatrixXd& xf, const Eigen::VectorXd& p) {
  switch (type) {
    case CellType::kLine2:
    case CellType::kLine3: return project_on_line(type, xf, p);
    case CellType::kTri3: return project_on_tri3(xf, p.head<3>());
    case CellType::kTri6: return project_on_tri6(xf, p.head<3>());
    case CellType::kQuad4:
    case CellType::kQuad8:
    case CellType::kQuad9: return project_on_quad(type, xf, p.head<3>());
    default: break;
  }
  throw std::logic_error("project_on_facet: " + cell_name(type) + " is not a contact facet type");
}

void snap_into_triangle(double* eta) {
  eta[0] = std::max(eta[0], 0.0);
  eta[1] = std::max(eta[1], 0.0);
  const double s = eta[0] + eta[1];
  if (s > 1.0) {
    eta[0] /= s;
    eta[1] /= s;
  }
}

}  // namespace symcontact
