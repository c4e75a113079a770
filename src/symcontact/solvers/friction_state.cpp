#include "symcontact/solvers/friction_state.hpp"

#include "symcontact/contact/contact_points.hpp"
#include "symcontact/contact/surface_tractions.hpp"

namespace symcontact {

std::vector<ContactPoint> nodal_friction_points(const ContactSet& contacts, int p, const DofMap& dofs,
                                                const VectorXd& u_iterate) {
  const VectorXd u = contacts.geometry_displacement(p, u_iterate);
  const int f = contacts.friction_family(p);
  const ContactSurface& slave = contacts.surfaces[contacts.families()[f].slave];
  const ContactPair& pair = contacts.pairs[p];
  const OppositeSide other = contacts.opposite_side(f, dofs, u);
  std::vector<ContactPoint> nodal = nodal_contact_points(slave, current_positions(slave, dofs, u), other.master(),
                                                         other.obstacle, pair.search_distance, pair.bisector_ray());
  if (pair.surface_a == pair.surface_b)  // self-contact: each side carries half of the interface's j_τ
    for (ContactPoint& q : nodal) q.weight *= 0.5;
  return nodal;
}

std::vector<std::shared_ptr<FrictionTerm>> friction_terms(const FrictionState& state, const ContactSet& contacts,
                                                                const DofMap& dofs, const VectorXd& u) {
  const int num_pairs = static_cast<int>(contacts.pairs.size());
  std::vector<std::shared_ptr<FrictionTerm>> terms(num_pairs);
  for (int p = 0; p < num_pairs; ++p) {
    if (p >= static_cast<int>(state.nodal_tau.size()) || state.nodal_tau[p].size() == 0) continue;
    const ContactFamily& fam = contacts.families()[contacts.friction_family(p)];
    const ContactSurface& slave = contacts.surfaces[fam.slave];
    std::vector<ContactPoint> nodal = nodal_friction_points(contacts, p, dofs, u);
    const std::vector<double> tau = interpolate_at_points(slave, nodal, state.nodal_tau[p]);
    std::vector<double> alpha(nodal.size());
    for (std::size_t q = 0; q < nodal.size(); ++q) {
      const double h = nodal[q].slave_node >= 0 ? slave.nodal_size[nodal[q].slave_node]
                                                : facet_size(slave, nodal[q].slave_facet);
      alpha[q] = contacts.pairs[p].regularisation_length(h);
    }
    terms[p] = std::make_shared<FrictionTerm>("friction(" + contacts.pairs[p].name + ")", slave,
                                              fam.master >= 0 ? &contacts.surfaces[fam.master] : nullptr,
                                              std::move(nodal), tau, std::move(alpha), dofs, state.u_start);
    terms[p]->keep_zero_blocks(state.follower != nullptr);  // the follower may raise a zero τ
  }
  return terms;
}

}  // namespace symcontact
