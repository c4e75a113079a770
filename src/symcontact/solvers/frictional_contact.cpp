#include "symcontact/solvers/frictional_contact.hpp"

#include <sstream>

#include "symcontact/contact/surface_tractions.hpp"
#include "symcontact/core/error.hpp"

namespace symcontact {

namespace {
/// Nodal pressures (clamped at 0) on the friction-slave surface of pair p.
Eigen::VectorXd friction_side_pressure(const ContactSet& cs, int p, const DofMap& dofs, const VectorXd& u,
                                       const VectorXd& force) {
  // Along the interface normal, as the friction term and the contact results decompose.
  const ContactFamily& fam = cs.families()[cs.friction_family(p)];
  const ContactSurface& s = cs.surfaces[fam.slave];
  const Eigen::MatrixXd xs = current_positions(s, dofs, u);
  Eigen::MatrixXd normals;
  if (fam.master >= 0) {
    const ContactSurface& ms = cs.surfaces[fam.master];
    const MasterGeometry mg = prepare_master(ms, current_positions(ms, dofs, u));
    normals = interface_normals(s, xs, &mg, nullptr, cs.pairs[p].search_distance);
  } else {
    normals = interface_normals(s, xs, nullptr, &cs.obstacles[cs.pairs[p].obstacle], cs.pairs[p].search_distance);
  }
  return surface_tractions(s, dofs, u, force, &normals).pressure.cwiseMax(0.0);
}
}  // namespace

FrictionalReport solve_frictional_contact(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts,
                                          const DofMap& dofs, VectorXd& u, const FrictionalOptions& options,
                                          const Logger& log) {
  FrictionalReport rep;
  const int np = static_cast<int>(contacts.pairs.size());
  rep.friction.u_start = u;
  rep.friction.nodal_tau.assign(np, Eigen::VectorXd());
  bool any_friction = false, any_coulomb = false;
  for (int p = 0; p < np; ++p) {
    const ContactPair& pair = contacts.pairs[p];
    if (pair.friction == FrictionLaw::kNone) continue;
    any_friction = true;
    const ContactSurface& s = contacts.surfaces[contacts.families()[contacts.friction_family(p)].slave];
    // Tresca: the given threshold; Coulomb: 0 for the frictionless first solve.
    rep.friction.nodal_tau[p] =
        Eigen::VectorXd::Constant(s.num_nodes(), pair.friction == FrictionLaw::kTresca ? pair.tau : 0.0);
    any_coulomb = any_coulomb || pair.friction == FrictionLaw::kCoulomb;
  }
  auto solve = [&]() {
    ContactSolveReport r =
        solve_contact(energy, fixed, contacts, dofs, u, options.contact, log, any_friction ? &rep.friction : nullptr);
    rep.geometry_iterations += r.geometry_iterations;
    rep.ipopt_iterations += r.ipopt_iterations;
    rep.times.merge(r.times);
    rep.last = std::move(r);
  };
  solve();
  if (!any_coulomb) return rep;
  for (int k = 1;; ++k) {
    // τ_{k} = μ p from the last solve, for every Coulomb pair; the change against the thresholds used.
    double num = 0.0, den = 0.0;
    std::vector<Eigen::VectorXd> next = rep.friction.nodal_tau;
    for (int p = 0; p < np; ++p) {
      if (contacts.pairs[p].friction != FrictionLaw::kCoulomb) continue;
      next[p] = contacts.pairs[p].mu * friction_side_pressure(contacts, p, dofs, u, rep.last.contact_force);
      if (k > 1) {
        num = std::max(num, (next[p] - rep.friction.nodal_tau[p]).lpNorm<Eigen::Infinity>());
        den = std::max(den, rep.friction.nodal_tau[p].lpNorm<Eigen::Infinity>());
      }
    }
    if (k > 1) {
      const double change = den > 0 ? num / den : (num > 0 ? 1.0 : 0.0);
      rep.coulomb_change.push_back(change);
      std::ostringstream s;
      s << "  Coulomb iteration " << k - 1 << ": threshold change " << change;
      log.detail(s.str());
      if (change < options.coulomb_tolerance) break;
      if (k - 1 >= options.max_coulomb_iterations) {
        std::ostringstream e;
        e << "the Coulomb fixed point did not converge in " << options.max_coulomb_iterations
          << " iterations (last relative change of the threshold " << change << ", tolerance "
          << options.coulomb_tolerance << ")";
        throw SolveError(e.str());
      }
    }
    rep.friction.nodal_tau = next;
    rep.coulomb_iterations = k;
    solve();
  }
  return rep;
}

}  // namespace symcontact
