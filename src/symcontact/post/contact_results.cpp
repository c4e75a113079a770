#include "symcontact/post/contact_results.hpp"

#include <cmath>
#include <limits>

#include "symcontact/contact/surface_tractions.hpp"
#include "symcontact/fem/shape_functions.hpp"

namespace symcontact {

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Signed distance of every node of side `side` to the opposite side of its pair, and the interface normal
/// there (interface_normal(), contact_points.hpp: outward for this side); nodes that project onto nothing
/// get a NaN gap and keep their own normal.
Eigen::VectorXd nodal_gaps(const ContactSet& cs, const ContactPair& pair, int side, const DofMap& dofs,
                           const VectorXd& u, const Eigen::MatrixXd& xs, Eigen::MatrixXd& normals) {
  const ContactSurface& s = cs.surfaces[side == 0 ? pair.surface_a : pair.surface_b];
  Eigen::VectorXd gap = Eigen::VectorXd::Constant(s.num_nodes(), kNaN);
  const Eigen::MatrixXd own = normals;
  if (pair.obstacle >= 0) {
    for (Index k = 0; k < s.num_nodes(); ++k) {
      Eigen::Vector3d p = Eigen::Vector3d::Zero(), xbar, n;
      p.head(s.dim) = xs.col(k);
      cs.obstacles[pair.obstacle].project(p, xbar, n);
      gap[k] = (p - xbar).dot(n);
      normals.col(k) = -n.head(s.dim);
    }
    return gap;
  }
  const ContactSurface& other = cs.surfaces[side == 0 ? pair.surface_b : pair.surface_a];
  const MasterGeometry mg = prepare_master(other, current_positions(other, dofs, u));
  for (Index k = 0; k < s.num_nodes(); ++k) {
    Eigen::Vector3d n3 = Eigen::Vector3d::Zero();
    n3.head(s.dim) = own.col(k);
    ContactPoint cp;
    if (project_to_master(mg, xs.col(k), n3, pair.search_distance, cp, false, pair.bisector_ray() ? &n3 : nullptr)) {
      gap[k] = cp.gap;
      // With the bisector ray, cp.normal is already the interface normal (the master side's).
      normals.col(k) = interface_normal(own.col(k), cp.normal.head(s.dim), pair.two_sided() && !pair.bisector_ray());
    }
  }
  return gap;
}

/// Weak nodal average of the point slips of a friction term over its slave surface.
Eigen::MatrixXd nodal_slips(const ContactSurface& s, const FrictionTerm& term, const VectorXd& u) {
  const std::vector<Eigen::Vector3d> sq = term.slips(u);
  Eigen::MatrixXd num = Eigen::MatrixXd::Zero(s.dim, s.num_nodes());
  Eigen::VectorXd den = Eigen::VectorXd::Zero(s.num_nodes());
  double N[10];
  for (std::size_t q = 0; q < sq.size(); ++q) {
    const ContactPoint& p = term.points()[q];
    shape_functions(s.facet_type, p.xi, N, nullptr);
    for (int a = 0; a < s.nodes_per_facet(); ++a) {
      const Index k = s.facet(p.slave_facet)[a];
      num.col(k) += p.weight * N[a] * sq[q].head(s.dim);
      den[k] += p.weight * N[a];
    }
  }
  Eigen::MatrixXd out = Eigen::MatrixXd::Constant(s.dim, s.num_nodes(), kNaN);
  for (Index k = 0; k < s.num_nodes(); ++k)
    if (den[k] > 0) out.col(k) = num.col(k) / den[k];
  return out;
}

}  // namespace

std::vector<ContactPairResult> contact_results(const ContactSet& cs, const DofMap& dofs, const VectorXd& u,
                                               const ContactSolveReport& report) {
  const VectorXd& contact_force = report.contact_force;
  const auto& friction = report.friction;
  std::vector<ContactPairResult> out;
  for (int pi = 0; pi < static_cast<int>(cs.pairs.size()); ++pi) {
    const ContactPair& pair = cs.pairs[pi];
    ContactPairResult r;
    r.name = pair.name;
    const int nsides = pair.obstacle >= 0 ? 1 : 2;
    const bool has_friction = pi < static_cast<int>(friction.size()) && friction[pi];
    const int friction_surface = has_friction ? cs.families()[cs.friction_family(pi)].slave : -1;
    std::vector<Eigen::VectorXd> multiplier_pressure;
    double max_multiplier_pressure = 0.0;
    for (int side = 0; side < nsides; ++side) {
      const int si = side == 0 ? pair.surface_a : pair.surface_b;
      const ContactSurface& s = cs.surfaces[si];
      // Decompose along the interface normal of each node (see nodal_gaps).
      const Eigen::MatrixXd x = current_positions(s, dofs, u);
      Eigen::MatrixXd normals = nodal_normals(s, x);
      ContactSideResult sr;
      sr.gap = nodal_gaps(cs, pair, side, dofs, u, x, normals);
      const SurfaceTractions t = surface_tractions(s, dofs, u, contact_force, &normals);
      sr.surface = si;
      sr.x = t.x;
      sr.X = s.X;
      sr.force = t.force;
      sr.pressure = t.pressure;
      sr.tangential = t.tangential;
      sr.slip = si == friction_surface ? nodal_slips(s, *friction[pi], u)
                                       : Eigen::MatrixXd::Constant(s.dim, s.num_nodes(), kNaN);
      r.max_pressure = std::max(r.max_pressure, sr.pressure.maxCoeff());
      // Contact status from the multipliers' normal force (see the header).
      const SurfaceTractions tm = surface_tractions(s, dofs, u, report.multiplier_force, &normals);
      sr.status = Eigen::VectorXi::Zero(s.num_nodes());
      for (Index k = 0; k < s.num_nodes(); ++k) sr.status[k] = tm.pressure[k] > 0 ? 1 : 0;
      multiplier_pressure.push_back(tm.pressure);
      max_multiplier_pressure = std::max(max_multiplier_pressure, tm.pressure.maxCoeff());
      if (side == 0) {
        r.normal_force = Eigen::VectorXd::Zero(s.dim);
        for (Index k = 0; k < s.num_nodes(); ++k)
          r.normal_force += t.force.col(k).dot(t.normals.col(k)) * t.normals.col(k);
      }
      r.sides.push_back(std::move(sr));
    }
    // Round-off of the residual at open nodes (|p| ~ 1e-16 max p) is reported as 0; anything larger
    // — an adhesive pressure, which would be a bug — is left visible.
    for (auto& sr : r.sides)
      for (Index k = 0; k < sr.pressure.size(); ++k)
        if (std::abs(sr.pressure[k]) <= 1e-12 * r.max_pressure) sr.pressure[k] = 0.0;
    r.total_force = r.sides[0].force.rowwise().sum();
    r.tangential_force = r.total_force - r.normal_force;
    for (std::size_t side = 0; side < r.sides.size(); ++side) {
      auto& sr = r.sides[side];
      sr.status = (multiplier_pressure[side].array() > 1e-4 * max_multiplier_pressure).cast<int>();
      if (!(max_multiplier_pressure > 0)) sr.status.setZero();
      for (Index k = 0; k < sr.status.size(); ++k) {
        const double s = sr.slip.col(k).norm();
        if (sr.status[k] && std::isfinite(s) && s >= 7.0 * pair.alpha) sr.status[k] = 2;
      }
    }
    const ContactSurface& sa = cs.surfaces[pair.surface_a];
    for (Index k = 0; k < sa.num_nodes(); ++k)
      if (r.sides[0].status[k]) r.contact_measure += sa.nodal_area[k];
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace symcontact
