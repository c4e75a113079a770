#include "symcontact/post/contact_results.hpp"

#include <cmath>
#include <limits>

namespace symcontact {

namespace {

/// Signed distance of every node of `s` to the opposite side of its pair.
Eigen::VectorXd nodal_gaps(const ContactSet& cs, const ContactPair& pair, int side, const DofMap& dofs,
                           const VectorXd& u, const Eigen::MatrixXd& xs, const Eigen::MatrixXd& ns) {
  const ContactSurface& s = cs.surfaces[side == 0 ? pair.surface_a : pair.surface_b];
  Eigen::VectorXd gap = Eigen::VectorXd::Constant(s.num_nodes(), std::numeric_limits<double>::quiet_NaN());
  if (pair.obstacle >= 0) {
    for (Index k = 0; k < s.num_nodes(); ++k) {
      Eigen::Vector3d p = Eigen::Vector3d::Zero(), xbar, n;
      p.head(s.dim) = xs.col(k);
      cs.obstacles[pair.obstacle].project(p, xbar, n);
      gap[k] = (p - xbar).dot(n);
    }
    return gap;
  }
  const ContactSurface& other = cs.surfaces[side == 0 ? pair.surface_b : pair.surface_a];
  const MasterGeometry mg = prepare_master(other, current_positions(other, dofs, u));
  for (Index k = 0; k < s.num_nodes(); ++k) {
    Eigen::Vector3d n3 = Eigen::Vector3d::Zero();
    n3.head(s.dim) = ns.col(k);
    ContactPoint cp;
    if (project_to_master(mg, xs.col(k), n3, pair.search_distance, cp)) gap[k] = cp.gap;
  }
  return gap;
}

}  // namespace

std::vector<ContactPairResult> contact_results(const ContactSet& cs, const DofMap& dofs, const VectorXd& u,
                                               const VectorXd& contact_force) {
  std::vector<ContactPairResult> out;
  for (const ContactPair& pair : cs.pairs) {
    ContactPairResult r;
    r.name = pair.name;
    const int nsides = pair.obstacle >= 0 ? 1 : 2;
    for (int side = 0; side < nsides; ++side) {
      const int si = side == 0 ? pair.surface_a : pair.surface_b;
      const ContactSurface& s = cs.surfaces[si];
      ContactSideResult sr;
      sr.surface = si;
      sr.x = current_positions(s, dofs, u);
      const Eigen::MatrixXd n = nodal_normals(s, sr.x);
      sr.force = Eigen::MatrixXd::Zero(s.dim, s.num_nodes());
      sr.pressure = Eigen::VectorXd::Zero(s.num_nodes());
      for (Index k = 0; k < s.num_nodes(); ++k) {
        if (!s.is_rigid())
          for (int i = 0; i < s.dim; ++i) sr.force(i, k) = contact_force[dofs.dof(s.body, s.nodes[k], i)];
        if (s.nodal_area[k] > 0) sr.pressure[k] = -sr.force.col(k).dot(n.col(k)) / s.nodal_area[k];
      }
      sr.gap = nodal_gaps(cs, pair, side, dofs, u, sr.x, n);
      r.max_pressure = std::max(r.max_pressure, sr.pressure.maxCoeff());
      r.sides.push_back(std::move(sr));
    }
    r.total_force = r.sides[0].force.rowwise().sum();
    for (auto& sr : r.sides) {
      sr.status = (sr.pressure.array() > 1e-4 * r.max_pressure).cast<int>();
    }
    const ContactSurface& sa = cs.surfaces[pair.surface_a];
    for (Index k = 0; k < sa.num_nodes(); ++k)
      if (r.sides[0].status[k]) r.contact_measure += sa.nodal_area[k];
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace symcontact
