#include "symcontact/contact/surface_tractions.hpp"

#include "symcontact/contact/contact_points.hpp"
#include "symcontact/fem/shape_functions.hpp"

namespace symcontact {

SurfaceTractions surface_tractions(const ContactSurface& s, const DofMap& dofs, const VectorXd& u,
                                   const VectorXd& force, const Eigen::MatrixXd* normals) {
  SurfaceTractions t;
  t.x = current_positions(s, dofs, u);
  t.normals = normals ? *normals : nodal_normals(s, t.x);
  t.force = Eigen::MatrixXd::Zero(s.dim, s.num_nodes());
  t.pressure = Eigen::VectorXd::Zero(s.num_nodes());
  t.tangential = Eigen::MatrixXd::Zero(s.dim, s.num_nodes());
  if (!s.is_rigid())
    for (Index k = 0; k < s.num_nodes(); ++k)
      for (int i = 0; i < s.dim; ++i) t.force(i, k) = force[dofs.dof(s.body, s.nodes[k], i)];
  // In the test basis (the identity but on Tri6 surfaces), whose lumped areas A_k are all positive.
  const Eigen::MatrixXd f = test_basis_forces(s, t.force);
  for (Index k = 0; k < s.num_nodes(); ++k) {
    if (s.nodal_area[k] <= 0) continue;
    const double fn = f.col(k).dot(t.normals.col(k));
    t.pressure[k] = -fn / s.nodal_area[k];
    t.tangential.col(k) = (f.col(k) - fn * t.normals.col(k)) / s.nodal_area[k];
  }
  return t;
}

std::vector<double> interpolate_at_points(const ContactSurface& s, const std::vector<ContactPoint>& points,
                                          const Eigen::VectorXd& nodal) {
  std::vector<double> out(points.size());
  double N[10];
  for (std::size_t q = 0; q < points.size(); ++q) {
    shape_functions(s.facet_type, points[q].xi, N, nullptr);
    double v = 0.0;
    for (int a = 0; a < s.nodes_per_facet(); ++a) v += N[a] * nodal[s.facet(points[q].slave_facet)[a]];
    out[q] = v;
  }
  return out;
}

}  // namespace symcontact
