#include "symcontact/solvers/contact_forces.hpp"

namespace symcontact {

ContactForces recover_contact_forces(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts,
                                     const DofMap& dofs, const VectorXd& u, const SparseMatrix& A, const VectorXd& mu,
                                     const std::vector<std::shared_ptr<const FrictionTerm>>& friction,
                                     const CondensedResidual& condensed) {
  ContactForces f;
  f.contact_force = A.transpose() * mu;
  f.multiplier_force = f.contact_force;
  std::vector<Index> free_index;
  fixed.free_numbering(u.size(), free_index);
  VectorXd residual;
  if (!condensed.residual) {
    residual = VectorXd::Zero(u.size());
    energy.add_gradient(u, residual);
  }
  VectorXd friction_gradient = VectorXd::Zero(u.size());
  for (const auto& t : friction)
    if (t) t->add_gradient(u, friction_gradient);
  f.force_defect = VectorXd::Zero(u.size());
  for (const ContactSurface& s : contacts.surfaces) {
    if (s.is_rigid()) continue;
    for (Index node : s.nodes)
      for (int i = 0; i < s.dim; ++i) {
        const Index d = dofs.dof(s.body, node, i);
        const Index k = free_index[d];
        if (k < 0) continue;
        if (!condensed.residual) {
          f.contact_force[d] = residual[d];
        } else if ((*condensed.b_position)[k] >= 0) {
          f.contact_force[d] = (*condensed.residual)[(*condensed.b_position)[k]];
        } else {
          continue;
        }
        f.force_defect[d] = f.contact_force[d] - (f.multiplier_force[d] - friction_gradient[d]);
      }
  }
  return f;
}

}  // namespace symcontact
