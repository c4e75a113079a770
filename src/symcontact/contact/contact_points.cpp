#include "symcontact/contact/contact_points.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "symcontact/contact/closest_point.hpp"
#include "symcontact/contact/polygon_clipping.hpp"
#include "symcontact/fem/quadrature.hpp"
#include "symcontact/fem/shape_functions.hpp"

namespace symcontact {

namespace {

Eigen::MatrixXd facet_nodes(const ContactSurface& s, const Eigen::MatrixXd& x, Index f) {
  const int npf = s.nodes_per_facet();
  Eigen::MatrixXd xf(x.rows(), npf);
  for (int a = 0; a < npf; ++a) xf.col(a) = x.col(s.facet(f)[a]);
  return xf;
}

Eigen::Vector3d pad3(const Eigen::VectorXd& v) {
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  r.head(v.size()) = v;
  return r;
}

/// The slave's smoothed normal at a point of facet f with shape function values N: the nodal normals
/// (dim × n) interpolated and normalised.
Eigen::Vector3d smoothed_at(const ContactSurface& s, const Eigen::MatrixXd& nodal, Index f, const double* N) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (int a = 0; a < s.nodes_per_facet(); ++a) n.head(s.dim) += N[a] * nodal.col(s.facet(f)[a]);
  return n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : n;
}

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Points of the slave facet (Line2/Line3, current nodes xf) where the line through v along n crosses it.
void breakpoints_2d(CellType type, const Eigen::MatrixXd& xf, const Eigen::Vector2d& v, const Eigen::Vector2d& n,
                    std::vector<double>& out) {
  // Monomial form x(ξ) = P0 + P1 ξ + P2 ξ².
  Eigen::Vector2d P0 = xf.col(0), P1 = xf.col(1) - xf.col(0), P2 = Eigen::Vector2d::Zero();
  if (type == CellType::kLine3) {
    P1 = -3.0 * xf.col(0) - xf.col(1) + 4.0 * xf.col(2);
    P2 = 2.0 * xf.col(0) + 2.0 * xf.col(1) - 4.0 * xf.col(2);
  }
  const double c0 = cross2(P0 - v, n), c1 = cross2(P1, n), c2 = cross2(P2, n);
  auto accept = [&](double xi) {
    if (xi > 1e-12 && xi < 1 - 1e-12) out.push_back(xi);
  };
  const double scale = std::abs(c1) + std::abs(c2);
  if (std::abs(c2) <= 1e-12 * scale) {
    if (std::abs(c1) > 0) accept(-c0 / c1);
    return;
  }
  const double disc = c1 * c1 - 4 * c2 * c0;
  if (disc < 0) return;
  const double s = std::sqrt(disc);
  // Numerically stable roots.
  const double q = -0.5 * (c1 + (c1 >= 0 ? s : -s));
  if (q != 0) {
    accept(q / c2);
    accept(c0 / q);
  }
}

}  // namespace

BoundingVolumeHierarchy::Box facet_box(CellType type, const Eigen::MatrixXd& xf, double pad) {
  BoundingVolumeHierarchy::Box box;
  box.setEmpty();
  const int nv = cell_num_vertices(type), npf = cell_num_nodes(type);
  for (int a = 0; a < npf; ++a) box.extend(pad3(xf.col(a)));
  if (npf > nv) {
    // Edge-midpoint nodes m of edge (a, b): the Bézier control point 2m − (x_a + x_b)/2 bounds the curve.
    static const int line[1][2] = {{0, 1}};
    const int edges = nv == 2 ? 1 : facet_num_edges(type);
    for (int e = 0; e < edges; ++e) {
      const int* ab = nv == 2 ? line[e] : facet_edge(type, e);
      box.extend(pad3(2.0 * xf.col(nv + e) - 0.5 * (xf.col(ab[0]) + xf.col(ab[1]))));
    }
    // Quad9: the centre's tensor Bézier control point 4c − Σ edge nodes + ¼ Σ vertices (the 1D map of
    // the edge nodes applied in both directions). A Quad8 facet is the biquadratic one whose centre is
    // its own point c = x(½, ½) = ½ Σ edge nodes − ¼ Σ vertices: control point Σ edge nodes − ¾ Σ vertices.
    if (type == CellType::kQuad8 || type == CellType::kQuad9) {
      const Eigen::VectorXd edge_sum = xf.col(4) + xf.col(5) + xf.col(6) + xf.col(7);
      const Eigen::VectorXd vertex_sum = xf.col(0) + xf.col(1) + xf.col(2) + xf.col(3);
      box.extend(pad3(type == CellType::kQuad9 ? Eigen::VectorXd(4.0 * xf.col(8) - edge_sum + 0.25 * vertex_sum)
                                               : Eigen::VectorXd(edge_sum - 0.75 * vertex_sum)));
    }
  }
  box.min().array() -= pad;
  box.max().array() += pad;
  return box;
}

MasterGeometry prepare_master(const ContactSurface& master, const Eigen::MatrixXd& x) {
  MasterGeometry g;
  g.surface = &master;
  g.x = x;
  g.normals = nodal_normals(master, x);
  if (master.dim == 2) g.corner_normals = facet_end_normals(master, x);  // read at corner nodes only
  g.facet_x.resize(master.num_facets());
  std::vector<BoundingVolumeHierarchy::Box> boxes(master.num_facets());
  for (Index f = 0; f < master.num_facets(); ++f) {
    g.facet_x[f] = facet_nodes(master, x, f);
    boxes[f] = facet_box(master.facet_type, g.facet_x[f], 0.0);
  }
  g.tree.build(boxes);
  return g;
}

namespace {

/// Gauss–Legendre points on the sub-intervals of [0, 1] cut at `cuts`, calling f(ξ, w).
template <class F>
void for_each_sub_point(std::vector<double> cuts, int ng, F&& f) {
  cuts.push_back(0.0);
  cuts.push_back(1.0);
  std::sort(cuts.begin(), cuts.end());
  std::vector<double> gx, gw;
  gauss_legendre_01(ng, gx, gw);
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double a = cuts[k], b = cuts[k + 1];
    if (b - a < 1e-13) continue;
    for (int q = 0; q < ng; ++q) f(a + (b - a) * gx[q], (b - a) * gw[q]);
  }
}

/// The unit vector of the cone {a n1 + b n2 : a, b ≥ 0} (n1, n2 unit, not opposite) nearest in angle to v:
/// v normalised if it lies in the cone, else whichever of n1, n2 is nearer to it.
Eigen::Vector2d nearest_in_cone(const Eigen::Vector2d& n1, const Eigen::Vector2d& n2, const Eigen::Vector2d& v) {
  const double s = cross2(n1, n2) >= 0 ? 1.0 : -1.0;  // orientation from n1 to n2 through the cone
  if (v.norm() > 0 && s * cross2(n1, v) >= 0 && s * cross2(v, n2) >= 0 && v.dot(n1 + n2) > 0) return v.normalized();
  return v.dot(n1) >= v.dot(n2) ? n1 : n2;
}

/// A projection clamped onto an end of the surface: in 2D a vertex of valence 1, in 3D a border edge or a
/// vertex of one (contact_surface.hpp).
bool past_end(const ContactSurface& s, Index f, const FacetProjection& pr) {
  if (s.dim == 2) return pr.clamped_vertex >= 0 && s.valence[s.facet(f)[pr.clamped_vertex]] <= 1;
  if (pr.clamped_edge >= 0) return s.boundary_edge[facet_num_edges(s.facet_type) * f + pr.clamped_edge] != 0;
  return pr.clamped_vertex >= 0 && s.boundary_vertex[s.facet(f)[pr.clamped_vertex]] != 0;
}

/// The slave's smoothed nodal normals for the bisector ray (empty without it): a self-contact's slave is
/// its master, whose normals prepare_master() has computed at the same positions.
Eigen::MatrixXd slave_normals_for_ray(const ContactSurface& slave, const Eigen::MatrixXd& xs,
                                      const MasterGeometry& master, const ContactSearchOptions& options) {
  if (!options.bisector_ray) return Eigen::MatrixXd();
  return master.surface == &slave ? master.normals : nodal_normals(slave, xs);
}

int default_gauss(const ContactSurface& s, const ContactSearchOptions& o) {
  return o.gauss_points > 0 ? o.gauss_points : 2 * cell_order(s.facet_type) + 1;
}

/// How far the points of a slave facet (current nodes xf) are projected: the search distance plus the
/// diagonal of the facet's box (facet_box(), which bounds a curved facet), so that when one point of the
/// facet lies within `search` of the master every other point finds its projection too.
double facet_reach(CellType type, const Eigen::MatrixXd& xf, double search) {
  return search + facet_box(type, xf, 0.0).diagonal().norm();
}

/// Appends the points of one slave facet (all projected within facet_reach()) to `points` when at least
/// one of them has |θ| ≤ search, else none: a facet contributes whole or not at all. Cutting it point by
/// point at the search distance leaves a node's row g_i = Σ w φ_i θ integrated over part of its support;
/// with P2 test functions (negative on half of a Line3, and of a Tri6 facet's edges) the part kept can
/// be where φ_i < 0, so g_i = (negative weight) × (θ ≈ search) < 0: a violated row on a node a search
/// distance away from the master, which pulls the body towards it by about the search distance at every
/// geometry iteration (the P2 Hertz cases cycled so). Over a whole facet the row is ∫ θ φ_i, which for
/// a gap θ = θ0 + s ξ + c ξ² on a Line3 vertex is L (θ0/6 − c/60): positive away from contact.
void append_whole_facet(const std::vector<ContactPoint>& facet_points, double search, std::vector<ContactPoint>& points) {
  for (const ContactPoint& cp : facet_points)
    if (std::abs(cp.gap) <= search) {
      points.insert(points.end(), facet_points.begin(), facet_points.end());
      return;
    }
}

}  // namespace

namespace {

/// The smoothed master normal (unit, or zero) at η of facet mf, away from corners: the nodal normals
/// interpolated, with a 2D corner node contributing this facet's own normal there.
Eigen::Vector3d smoothed_normal(const MasterGeometry& master, Index mf, const double* eta) {
  const ContactSurface& ms = *master.surface;
  double M[10];
  shape_functions(ms.facet_type, eta, M, nullptr);
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (int b = 0; b < ms.nodes_per_facet(); ++b) {
    const Index k = ms.facet(mf)[b];
    // At a corner node, this facet's own normal there (rows 0–1 when the facet ends at it: local node 1).
    if (ms.dim == 2 && b < 2 && ms.corner[k])
      n.head<2>() += M[b] * master.corner_normals.block<2, 1>(b == 1 ? 0 : 2, k);
    else
      n.head(ms.dim) += M[b] * master.normals.col(k);
  }
  return n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : n;
}

/// Where the line p − θ m meets the (extended) facet f of the master (current positions): Newton on
/// x(η) + θ m = p for (η, θ), from the η and θ given; one step on a flat facet. False if it does not
/// converge. Fixed-size and allocation-free: it runs for every point of a self-contact surface.
bool ray_meets_facet(const MasterGeometry& master, Index f, const Eigen::Vector3d& p, const Eigen::Vector3d& m,
                     double* eta, double& theta) {
  const ContactSurface& ms = *master.surface;
  const int D = ms.dim, d = D - 1, npf = ms.nodes_per_facet();
  const Index* nodes = ms.facet(f);
  double N[10], dN[20];
  for (int it = 0; it < 20; ++it) {
    shape_functions(ms.facet_type, eta, N, dN);
    // r = x(η) + θ m − p; J = [∂x/∂η_1 … ∂x/∂η_d, m] (the identity's last row and column in 2D).
    Eigen::Vector3d r = Eigen::Vector3d::Zero();
    Eigen::Matrix3d J = Eigen::Matrix3d::Identity();
    for (int c = 0; c < D; ++c) {
      r[c] = theta * m[c] - p[c];
      for (int i = 0; i < d; ++i) J(c, i) = 0.0;
      J(c, d) = m[c];
      for (int a = 0; a < npf; ++a) {
        const double xa = master.x(c, nodes[a]);
        r[c] += N[a] * xa;
        for (int i = 0; i < d; ++i) J(c, i) += dN[a * d + i] * xa;
      }
    }
    const Eigen::Vector3d dz = J.partialPivLu().solve(r);
    if (!dz.allFinite()) return false;
    double step = 0.0;
    for (int i = 0; i < d; ++i) {
      eta[i] -= dz[i];
      step = std::max(step, std::abs(dz[i]));
    }
    theta -= dz[d];
    if (std::abs(eta[0]) > 10 || (d == 2 && std::abs(eta[1]) > 10)) return false;
    if (step < 1e-15) return true;
  }
  return true;  // 20 Newton steps: as close as it gets
}

/// Is η in the reference facet (to `tol`)? Clamps it into the facet in any case (near enough to the
/// nearest point for evaluating normals on the way to a fixed point).
bool clamp_to_facet(CellType type, double* eta, double tol) {
  if (cell_dim(type) == 1) {
    const bool in = eta[0] >= -tol && eta[0] <= 1 + tol;
    eta[0] = std::clamp(eta[0], 0.0, 1.0);
    return in;
  }
  return snap_into_facet(type, eta, tol);
}

/// The bisector-ray projection (project_to_master(), `ray_normal`): from the closest-point projection in
/// cp, the fixed point  m = (n̄(x̄) − n_s)/|n̄(x̄) − n_s|,  x̄ = the point where the line p − θ m meets the
/// master,  updating cp (facet, η, x̄, normal m, gap θ) when it settles. The facet met: the current one,
/// else the facing facet nearest p along the line among those whose boxes meet the box of the line's
/// segment |θ| ≤ 2|p − x̄| (on a smooth patch the line meets the master within about |p − x̄| of p);
/// when the line meets none, the current facet's extension, clamped into it, stands in for x̄ for the
/// next pass (near the master's end the first bisector can miss it while the fixed point is inside).
/// Left unchanged (the closest point) when the iteration does not settle inside the master within 50
/// passes.
void project_along_bisector(const MasterGeometry& master, const Eigen::Vector3d& p, const Eigen::Vector3d& slave_normal,
                            const Eigen::Vector3d& ns, ContactPoint& cp) {
  const ContactSurface& ms = *master.surface;
  const int d = ms.dim - 1;
  Index f = cp.master_facet;
  double eta[2] = {cp.eta[0], cp.eta[1]};
  double theta = cp.gap;
  Eigen::Vector3d n = cp.normal;
  const double pad = 1e-6 * facet_box(ms.facet_type, master.facet_x[f], 0.0).diagonal().norm();
  const double reach = 2.0 * (p - cp.xbar).norm() + pad;
  for (int it = 0; it < 50; ++it) {
    Eigen::Vector3d m = n - ns;
    if (!(m.norm() > 0)) return;
    m.normalize();
    Index hit = -1;
    bool inside = false;
    double hit_eta[2] = {eta[0], eta[1]}, hit_theta = theta;
    {
      double e[2] = {eta[0], eta[1]}, t = theta;
      if (ray_meets_facet(master, f, p, m, e, t)) {
        hit = f;
        inside = clamp_to_facet(ms.facet_type, e, 1e-10);
        hit_eta[0] = e[0];
        hit_eta[1] = e[1];
        hit_theta = t;
      }
    }
    if (!inside) {
      // A facet the line meets within |θ| ≤ reach of p overlaps the box of that segment of the line.
      BoundingVolumeHierarchy::Box segment(p, p);
      segment.extend(Eigen::Vector3d(p + reach * m));
      segment.extend(Eigen::Vector3d(p - reach * m));
      segment.min().array() -= pad;
      segment.max().array() += pad;
      master.tree.for_each_overlap(segment, [&](int k) {
        if (k == f) return;
        const double start = cell_shape(ms.facet_type) == CellShape::kTensor ? 0.5 : 1.0 / 3.0;
        double e[2] = {d == 1 ? 0.5 : start, start}, t = theta;
        if (!ray_meets_facet(master, k, p, m, e, t) || !clamp_to_facet(ms.facet_type, e, 1e-10)) return;
        if (pad3(facet_normal(ms.facet_type, master.facet_x[k], e)).dot(slave_normal) >= 0) return;
        if (inside && std::abs(t) >= std::abs(hit_theta)) return;
        hit = k;
        inside = true;
        hit_eta[0] = e[0];
        hit_eta[1] = e[1];
        hit_theta = t;
      });
    }
    if (hit < 0) return;
    const double change = std::abs(hit_eta[0] - eta[0]) + std::abs(hit_eta[1] - eta[1]);
    const Eigen::Vector3d n_new = smoothed_normal(master, hit, hit_eta);
    const bool settled = inside && hit == f && change < 1e-14 && (n_new - n).norm() < 1e-14;
    f = hit;
    eta[0] = hit_eta[0];
    eta[1] = hit_eta[1];
    theta = hit_theta;
    n = n_new;
    if (!(n.norm() > 0) || slave_normal.dot(n) >= 0) return;
    if (settled) {
      cp.master_facet = f;
      cp.eta[0] = eta[0];
      cp.eta[1] = d == 2 ? eta[1] : 0.0;
      double M[10];
      shape_functions(ms.facet_type, cp.eta, M, nullptr);
      cp.xbar.setZero();
      for (int b = 0; b < ms.nodes_per_facet(); ++b) cp.xbar.head(ms.dim) += M[b] * master.x.col(ms.facet(f)[b]);
      cp.normal = m;
      cp.gap = (p - cp.xbar).dot(m);
      const Eigen::Vector3d nf = pad3(facet_normal(ms.facet_type, master.facet_x[f], cp.eta)).normalized();
      cp.gap_direction = nf / nf.dot(m);  // n_f·m > 0: the facet faces the slave point, m is near n̄
      return;
    }
  }
}

}  // namespace

bool project_to_master(const MasterGeometry& master, const Eigen::VectorXd& p, const Eigen::Vector3d& slave_normal,
                       double search, ContactPoint& cp, bool allow_past_end, const Eigen::Vector3d* ray_normal,
                       Index candidate) {
  const ContactSurface& ms = *master.surface;
  const Eigen::Vector3d p3 = pad3(p);
  // The nearest FACING master facet: back-facing facets (a point's own facet in self-contact, the far
  // face of a thin master) are skipped so that the search goes on to the one that matters.
  const auto distance2 = [&](int k, double bound) {
    const Eigen::MatrixXd& xk = master.facet_x[k];
    const FacetProjection q = project_on_facet(ms.facet_type, xk, p);
    if (q.distance2 > bound || pad3(facet_normal(ms.facet_type, xk, q.eta)).dot(slave_normal) >= 0)
      return std::numeric_limits<double>::infinity();
    return q.distance2;
  };
  // The candidate's distance as the first bound prunes the tree without changing the winner: the depth-first
  // order is p's alone, and every facet at the final distance lies within any bound on the way, so the last
  // of them in that order is found either way (ties go to the later one, as in nearest_within_bound()). The
  // bound exceeds the candidate's distance by (1e-8 search)²: a box's distance to p, which prunes, may exceed
  // the projection's distance to its facet by round-off.
  double bound = search * search;
  if (candidate >= 0)
    bound = std::min(bound, distance2(static_cast<int>(candidate), bound) + 1e-16 * search * search);
  const int mf = master.tree.nearest_within_bound(p3, bound, distance2);
  if (mf < 0) return false;
  const FacetProjection pr = project_on_facet(ms.facet_type, master.facet_x[mf], p);
  if (!allow_past_end && past_end(ms, mf, pr)) return false;
  Eigen::Vector3d nbar = Eigen::Vector3d::Zero();
  const bool at_corner = ms.dim == 2 && pr.clamped_vertex >= 0 && ms.corner[ms.facet(mf)[pr.clamped_vertex]];
  if (at_corner) {
    const Index k = ms.facet(mf)[pr.clamped_vertex];
    nbar.head<2>() = nearest_in_cone(master.corner_normals.block<2, 1>(0, k), master.corner_normals.block<2, 1>(2, k),
                                     -slave_normal.head<2>());
  } else {
    nbar = smoothed_normal(master, mf, pr.eta);
  }
  if (nbar.norm() == 0) return false;
  nbar.normalize();
  if (slave_normal.dot(nbar) >= 0) return false;  // not facing each other
  cp.master_facet = mf;
  cp.eta[0] = pr.eta[0];
  cp.eta[1] = pr.eta[1];
  cp.x = p3;
  cp.xbar = pr.point;
  cp.normal = nbar;
  cp.gap = (p3 - pr.point).dot(nbar);
  if (ray_normal && !at_corner) project_along_bisector(master, p3, slave_normal, *ray_normal, cp);
  return std::abs(cp.gap) <= search;
}

namespace {

std::vector<ContactPoint> contact_points_2d(const ContactSurface& slave, const Eigen::MatrixXd& xs,
                                            const MasterGeometry& master, const ContactSearchOptions& options) {
  const ContactSurface& ms = *master.surface;
  const double search = options.search_distance;
  const int ng = default_gauss(slave, options);
  const int npf = slave.nodes_per_facet();
  std::vector<ContactPoint> points, facet_points;
  std::vector<double> cuts;
  std::vector<double> N(npf);
  const Eigen::MatrixXd ns_nodal = slave_normals_for_ray(slave, xs, master, options);
  for (Index f = 0; f < slave.num_facets(); ++f) {
    const Eigen::MatrixXd xf = facet_nodes(slave, xs, f);
    const Eigen::MatrixXd Xf = facet_nodes(slave, slave.X, f);
    const double reach = facet_reach(slave.facet_type, xf, search);
    // Segmentation: master vertices near this facet.
    cuts.clear();
    facet_points.clear();
    master.tree.for_each_overlap(facet_box(slave.facet_type, xf, reach), [&](int mf) {
      for (int a = 0; a < 2; ++a) {
        const Index v = ms.facet(mf)[a];
        // At a corner, the edge of the fan on this facet's side (the facet's own normal there).
        const Eigen::Vector2d n = ms.corner[v] ? Eigen::Vector2d(master.corner_normals.block<2, 1>(a == 1 ? 0 : 2, v))
                                               : Eigen::Vector2d(master.normals.col(v).head<2>());
        breakpoints_2d(slave.facet_type, xf, master.x.col(v).head<2>(), n, cuts);
      }
    });
    for_each_sub_point(cuts, ng, [&](double xi, double w) {
      shape_functions(slave.facet_type, &xi, N.data(), nullptr);
      const Eigen::VectorXd p = xf * Eigen::Map<const Eigen::VectorXd>(N.data(), npf);
      const Eigen::Vector3d ns = pad3(facet_normal(slave.facet_type, xf, &xi));
      const Eigen::Vector3d ray = options.bisector_ray ? smoothed_at(slave, ns_nodal, f, N.data()) : Eigen::Vector3d();
      ContactPoint cp;
      if (!project_to_master(master, p, ns, reach, cp, false, options.bisector_ray ? &ray : nullptr)) return;
      cp.slave_facet = f;
      cp.xi[0] = xi;
      cp.weight = w * surface_measure(slave, Xf, &xi);
      facet_points.push_back(cp);
    });
    append_whole_facet(facet_points, search, points);
  }
  return points;
}

std::vector<ContactPoint> contact_points_3d(const ContactSurface& slave, const Eigen::MatrixXd& xs,
                                            const MasterGeometry& master, const ContactSearchOptions& options) {
  const int npf = slave.nodes_per_facet();
  // Degree 2·order + 1 per clip triangle (exact for the flat-interface integrand θ φ: θ linear in ξ,
  // φ of degree order on a triangle, 2·order on a parallelogram), unless gauss_points is given:
  // 2·gauss_points − 1 as on segments.
  const int degree = options.gauss_points > 0 ? 2 * options.gauss_points - 1 : 2 * cell_order(slave.facet_type) + 1;
  const QuadratureRule rule = simplex_quadrature(2, degree);
  // On flat (Tri3) facets the integrand is a cubic in ξ within a cell (θ quadratic: x and x̄ affine, the
  // master's smoothed normal linear; φ linear), which any triangulation of the cell integrates exactly:
  // the fan from one vertex takes the fewest triangles, n − 2 of an n-gon. Curved and bilinear facets
  // keep the fan from the centroid, whose better-shaped triangles suit an integrand that is not a polynomial.
  const bool flat = slave.facet_type == CellType::kTri3;
  std::vector<ContactPoint> points, facet_points;
  std::vector<double> N(npf);
  const Eigen::MatrixXd ns_nodal = slave_normals_for_ray(slave, xs, master, options);
  for (Index f = 0; f < slave.num_facets(); ++f) {
    const Eigen::MatrixXd xf = facet_nodes(slave, xs, f);
    const Eigen::MatrixXd Xf = facet_nodes(slave, slave.X, f);
    const double reach = facet_reach(slave.facet_type, xf, options.search_distance);
    facet_points.clear();
    for (const MortarCell& cell : mortar_cells(slave, xs, f, master, reach)) {
      const auto triangles = flat ? triangulate_from_vertex(cell.polygon) : triangulate_from_centroid(cell.polygon);
      for (const auto& tri : triangles) {
        // ξ(ζ) = t0 + ζ1 (t1 − t0) + ζ2 (t2 − t0): the rule's weights (sum 1/2) times 2 × the sub-area.
        const double jac = (tri[1] - tri[0]).x() * (tri[2] - tri[0]).y() - (tri[1] - tri[0]).y() * (tri[2] - tri[0]).x();
        if (!(jac > 0)) continue;
        for (int q = 0; q < rule.size(); ++q) {
          const double* z = rule.point(q);
          const Eigen::Vector2d xi2 = tri[0] + z[0] * (tri[1] - tri[0]) + z[1] * (tri[2] - tri[0]);
          const double xi[2] = {xi2.x(), xi2.y()};
          shape_functions(slave.facet_type, xi, N.data(), nullptr);
          const Eigen::VectorXd p = xf * Eigen::Map<const Eigen::VectorXd>(N.data(), npf);
          const Eigen::Vector3d ns = facet_normal(slave.facet_type, xf, xi).head<3>();
          const Eigen::Vector3d ray = options.bisector_ray ? smoothed_at(slave, ns_nodal, f, N.data()) : Eigen::Vector3d();
          ContactPoint cp;
          if (!project_to_master(master, p, ns, reach, cp, false, options.bisector_ray ? &ray : nullptr,
                                 cell.master_facet))
            continue;
          cp.slave_facet = f;
          cp.xi[0] = xi[0];
          cp.xi[1] = xi[1];
          cp.weight = rule.weights[q] * jac * surface_measure(slave, Xf, xi);
          facet_points.push_back(cp);
        }
      }
    }
    append_whole_facet(facet_points, options.search_distance, points);
  }
  return points;
}

}  // namespace

namespace {

/// The auxiliary plane of a slave facet (current vertices) and the map from it to the facet's reference
/// coordinates: affine through the vertex triangle (Tri3, Tri6), or the inverse of the bilinear map of
/// the vertex quadrilateral projected on the plane (Quad4, Quad9), by Newton's method.
struct AuxiliaryPlane {
  CellType type;
  Eigen::Vector3d x0, e1, e2, n0;  ///< origin, in-plane directions, unit normal
  Eigen::Matrix2d Ginv;            ///< inverse Gram matrix of e1, e2
  Eigen::Vector2d corner[4];       ///< quadrilaterals: the projected vertices in (e1, e2) coordinates

  /// False when the facet is degenerate (no plane).
  bool build(CellType t, const Eigen::MatrixXd& xf) {
    type = t;
    x0 = xf.col(0);
    if (cell_shape(t) == CellShape::kTensor) {
      // The diagonals' cross product: the plane's normal of a warped quadrilateral as of a flat one.
      e1 = xf.col(1) - x0;
      e2 = xf.col(3) - x0;
      n0 = Eigen::Vector3d(xf.col(2) - x0).cross(Eigen::Vector3d(xf.col(3) - xf.col(1)));
    } else {
      e1 = xf.col(1) - x0;
      e2 = xf.col(2) - x0;
      n0 = e1.cross(e2);
    }
    if (!(n0.norm() > 0)) return false;
    n0.normalize();
    Eigen::Matrix2d G;
    G << e1.dot(e1), e1.dot(e2), e1.dot(e2), e2.dot(e2);
    if (!(std::abs(G.determinant()) > 0)) return false;
    Ginv = G.inverse();
    if (cell_shape(t) == CellShape::kTensor)
      for (int a = 0; a < 4; ++a) corner[a] = plane(xf.col(a));
    return true;
  }
  /// Coordinates in (e1, e2) of y projected along n0 (the n0 component drops out of the normal equations).
  Eigen::Vector2d plane(const Eigen::Vector3d& y) const { return Ginv * Eigen::Vector2d((y - x0).dot(e1), (y - x0).dot(e2)); }
  /// The facet's reference coordinates of y projected along n0.
  Eigen::Vector2d reference(const Eigen::Vector3d& y) const {
    const Eigen::Vector2d q = plane(y);
    if (cell_shape(type) != CellShape::kTensor) return q;
    Eigen::Vector2d xi(0.5, 0.5);
    for (int it = 0; it < 30; ++it) {
      double N[4], dN[8];
      shape_functions(CellType::kQuad4, xi.data(), N, dN);
      Eigen::Vector2d r = -q;
      Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
      for (int a = 0; a < 4; ++a) {
        r += N[a] * corner[a];
        J.col(0) += dN[2 * a] * corner[a];
        J.col(1) += dN[2 * a + 1] * corner[a];
      }
      const Eigen::Vector2d step = J.partialPivLu().solve(r);
      if (!step.allFinite()) break;
      xi -= step;
      if (step.norm() < 1e-15) break;
    }
    return xi;
  }
};

}  // namespace

std::vector<MortarCell> mortar_cells(const ContactSurface& slave, const Eigen::MatrixXd& xs, Index f,
                                     const MasterGeometry& master, double search) {
  std::vector<MortarCell> cells;
  const ContactSurface& ms = *master.surface;
  const Eigen::MatrixXd xf = facet_nodes(slave, xs, f);
  // The slave facet's auxiliary plane: origin, in-plane edges, unit normal n0.
  AuxiliaryPlane aux;
  if (!aux.build(slave.facet_type, xf)) return cells;
  const Eigen::Vector3d& n0 = aux.n0;
  const bool square = cell_shape(slave.facet_type) == CellShape::kTensor;
  const Polygon2 reference = square ? Polygon2{Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(1, 1),
                                               Eigen::Vector2d(0, 1)}
                                    : Polygon2{Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1)};
  const int master_vertices = cell_num_vertices(ms.facet_type);
  // The query: the box of the prism swept by the slave facet along ±search n0, i.e. the facet's box
  // padded by search |n0_i| along axis i — not by search in every direction. A master facet that can
  // give a cell within n0-distance `search` lies in that prism; padding the box by `search` laterally
  // too returned (search / h)² facets per query on a fine master, O(n²) in all (docs/performance.md,
  // "The search with a master surface").
  BoundingVolumeHierarchy::Box query = facet_box(slave.facet_type, xf, 0.0);
  const Eigen::Vector3d reach = search * n0.cwiseAbs();
  query.min() -= reach;
  query.max() += reach;
  master.tree.for_each_overlap(query, [&](int mf) {
    const Index* mn = ms.facet(mf);
    Eigen::Vector3d y[4];
    for (int a = 0; a < master_vertices; ++a) y[a] = master.x.col(mn[a]);
    // Facing: the master's normal (its diagonals' cross product for a quadrilateral) against n0.
    const Eigen::Vector3d nm = master_vertices == 4 ? Eigen::Vector3d((y[2] - y[0]).cross(y[3] - y[1]))
                                                    : Eigen::Vector3d((y[1] - y[0]).cross(y[2] - y[0]));
    if (nm.dot(n0) >= 0) return;  // not facing the slave facet
    // Master vertices projected along n0 onto the auxiliary plane, in the slave's reference coordinates.
    Polygon2 poly;
    Eigen::AlignedBox2d box;
    box.setEmpty();
    for (int a = 0; a < master_vertices; ++a) {
      poly.push_back(aux.reference(y[a]));
      box.extend(poly.back());
    }
    // Most facets of the query lie beside the slave facet (the box of a tilted prism is wide): a polygon
    // whose box misses the reference cell's [0, 1]² by more than the clipping's round-off gives no cell.
    const double margin = 1e-9 * std::max(1.0, box.max().cwiseAbs().maxCoeff() + box.min().cwiseAbs().maxCoeff());
    if ((box.min().array() > 1.0 + margin).any() || (box.max().array() < -margin).any()) return;
    const double area = polygon_area(poly);
    if (std::abs(area) < 1e-14) return;
    if (area < 0) std::reverse(poly.begin(), poly.end());
    MortarCell c;
    c.master_facet = mf;
    c.polygon = clip_convex_polygon(reference, poly);
    if (c.polygon.size() >= 3 && polygon_area(c.polygon) > 1e-14) cells.push_back(std::move(c));
  });
  return cells;
}

std::vector<ContactPoint> contact_points(const ContactSurface& slave, const Eigen::MatrixXd& xs,
                                         const MasterGeometry& master, const ContactSearchOptions& options) {
  return slave.dim == 2 ? contact_points_2d(slave, xs, master, options) : contact_points_3d(slave, xs, master, options);
}

std::vector<ContactPoint> contact_points(const ContactSurface& slave, const Eigen::MatrixXd& xs,
                                         const Obstacle& obstacle, const ContactSearchOptions& options) {
  const int npf = slave.nodes_per_facet();
  const int d = cell_dim(slave.facet_type);
  // Facets of a smooth obstacle need no segmentation: a Gauss rule per facet.
  const QuadratureRule rule = d == 1 ? [&] {
    QuadratureRule r;
    r.dim = 1;
    gauss_legendre_01(default_gauss(slave, options), r.points, r.weights);
    return r;
  }()
                                     : cell_quadrature(slave.facet_type, 2 * default_gauss(slave, options) - 1);
  std::vector<ContactPoint> points, facet_points;
  std::vector<double> N(npf);
  for (Index f = 0; f < slave.num_facets(); ++f) {
    const Eigen::MatrixXd xf = facet_nodes(slave, xs, f);
    const Eigen::MatrixXd Xf = facet_nodes(slave, slave.X, f);
    facet_points.clear();
    for (int q = 0; q < rule.size(); ++q) {
      const double* xi = rule.point(q);
      shape_functions(slave.facet_type, xi, N.data(), nullptr);
      const Eigen::Vector3d p = pad3(xf * Eigen::Map<const Eigen::VectorXd>(N.data(), npf));
      Eigen::Vector3d xbar, n;
      obstacle.project(p, xbar, n);
      const Eigen::Vector3d ns = pad3(facet_normal(slave.facet_type, xf, xi));
      if (ns.dot(n) >= 0) continue;
      const double theta = (p - xbar).dot(n);
      ContactPoint cp;
      cp.slave_facet = f;
      for (int i = 0; i < d; ++i) cp.xi[i] = xi[i];
      cp.weight = rule.weights[q] * surface_measure(slave, Xf, xi);
      cp.x = p;
      cp.xbar = xbar;
      cp.normal = n;
      cp.gap = theta;
      facet_points.push_back(cp);
    }
    append_whole_facet(facet_points, options.search_distance, points);
  }
  return points;
}

std::vector<ContactPoint> nodal_contact_points(const ContactSurface& slave, const Eigen::MatrixXd& xs,
                                               const MasterGeometry* master, const Obstacle* obstacle,
                                               double search_distance, bool bisector_ray) {
  const int npf = slave.nodes_per_facet();
  const int d = cell_dim(slave.facet_type);
  const std::vector<double> ref = reference_nodes(slave.facet_type);
  const Eigen::MatrixXd normals = nodal_normals(slave, xs);
  // The first facet (and local index) holding each node.
  std::vector<std::pair<Index, int>> where(slave.num_nodes(), {-1, -1});
  for (Index f = 0; f < slave.num_facets(); ++f)
    for (int a = 0; a < npf; ++a)
      if (where[slave.facet(f)[a]].first < 0) where[slave.facet(f)[a]] = {f, a};
  std::vector<ContactPoint> points;
  for (Index k = 0; k < slave.num_nodes(); ++k) {
    if (where[k].first < 0 || slave.nodal_area[k] <= 0) continue;
    const Eigen::Vector3d ns = pad3(normals.col(k));
    ContactPoint cp;
    if (master) {
      if (!project_to_master(*master, xs.col(k), ns, search_distance, cp, true, bisector_ray ? &ns : nullptr)) continue;
    } else {
      const Eigen::Vector3d p = pad3(xs.col(k));
      Eigen::Vector3d xbar, n;
      obstacle->project(p, xbar, n);
      if (ns.dot(n) >= 0) continue;
      const double theta = (p - xbar).dot(n);
      if (std::abs(theta) > search_distance) continue;
      cp.x = p;
      cp.xbar = xbar;
      cp.normal = n;
      cp.gap = theta;
    }
    cp.slave_facet = where[k].first;
    for (int i = 0; i < d; ++i) cp.xi[i] = ref[where[k].second * d + i];
    cp.weight = slave.nodal_area[k];
    cp.slave_node = k;
    points.push_back(cp);
  }
  return points;
}

Eigen::VectorXd interface_normal(const Eigen::VectorXd& own, const Eigen::VectorXd& nbar, bool two_sided) {
  if (!two_sided) return -nbar;
  const Eigen::VectorXd nu = own - nbar;  // n_s·n̄ < 0 (project_to_master): |ν| > √2
  return nu / nu.norm();
}

Eigen::MatrixXd interface_normals(const ContactSurface& slave, const Eigen::MatrixXd& xs, const MasterGeometry* master,
                                  const Obstacle* obstacle, double search_distance, bool bisector_ray) {
  Eigen::MatrixXd n = nodal_normals(slave, xs);
  for (const ContactPoint& p : nodal_contact_points(slave, xs, master, obstacle, search_distance, bisector_ray))
    n.col(p.slave_node) = -p.normal.head(slave.dim);
  return n;
}

}  // namespace symcontact
