#include "symcontact/post/step_checks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "symcontact/contact/penetration.hpp"
#include "symcontact/core/error.hpp"

namespace symcontact {

namespace {

void check_finite(const Model& model, const VectorXd& u, const VectorXd& g,
                  const ContactState* contact) {
  const DofMap& dofs = model.dofs();
  for (Index d = 0; d < u.size(); ++d) {
    if (std::isfinite(u[d]) && std::isfinite(g[d])) continue;
    for (int b = 0; b < dofs.num_bodies(); ++b) {
      const Body& body = *model.bodies()[b];
      if (d < dofs.dof(b, 0, 0) || d >= dofs.dof(b, 0, 0) + dofs.num_body_dofs(b)) continue;
      const Index node = (d - dofs.dof(b, 0, 0)) / model.dim();
      throw SolveError("check of the answer: body '" + body.name + "', " +
                       body.mesh.node_label(node) + ": " +
                       (std::isfinite(u[d]) ? "the force ∇E" : "the displacement") +
                       " is not a finite number");
    }
  }
  if (contact && !contact->multipliers.allFinite())
    throw SolveError("check of the answer: a contact multiplier is not a finite number");
}

/// "contact 'C': node N of 'S' is D inside body 'B' (P % of the element size h; ...)": what and where.
std::string describe(const Model& model, const Penetration& p, const char* inside,
                     double tolerance = kPenetrationRelativeTolerance) {
  const ContactSet& cs = model.contacts();
  const ContactSurface& slave = cs.surfaces[p.slave];
  std::string into = "the obstacle";
  if (p.master >= 0) {
    const ContactSurface& m = cs.surfaces[p.master];
    into = p.passed_through || m.is_rigid() ? "'" + m.name + "'" : "body '" + model.bodies()[m.body]->name + "'";
  }
  std::ostringstream s;
  s.precision(4);
  s << "contact '" << cs.pairs[p.pair].name << "': "
    << model.bodies()[slave.body]->mesh.node_label(slave.nodes[p.node]) << " of '" << slave.name << "' is "
    << p.depth << (p.passed_through ? " behind " : inside) << into << " (" << 100.0 * p.depth / p.size
    << " % of the element size " << p.size << "; at most " << 100.0 * tolerance
    << " % is tolerated)";
  return s.str();
}

bool small_sliding(const Model& model, const Penetration& p) {
  return model.contacts().pairs[p.pair].geometry == ContactGeometry::kReference;
}

/// The largest depth / h over the pairs' nodes; throws when one exceeds the tolerance. A pair in
/// ContactGeometry::kReference is held to its linearised gaps (the constraint its solve enforces); its depth
/// in the deformed configuration beyond the tolerance is a warning: the motion is not small sliding.
double check_penetration(const Model& model, const VectorXd& u, const ContactState& contact,
                         std::vector<std::string>& warnings) {
  std::vector<const Mesh*> meshes;
  for (const auto& b : model.bodies()) meshes.push_back(&b->mesh);
  const ContactSet& cs = model.contacts();
  const std::vector<Penetration> deformed = find_penetrations(cs, meshes, model.dofs(), u);
  const std::vector<Penetration> linearized = find_linearized_penetrations(cs, contact.linearization, u);
  double worst = 0.0;
  std::vector<char> warned(cs.pairs.size(), 0);
  for (const Penetration& p : deformed) {
    if (!small_sliding(model, p)) {
      if (p.exceeds())
        throw SolveError("check of the answer: " + describe(model, p, " inside ") +
                         ": the bodies went through each other, the contact was not enforced (the search distance "
                         "may be smaller than the motion of a step: more load steps or a larger search_distance)");
      worst = std::max(worst, p.ratio());
    } else if (p.exceeds() && !warned[p.pair]++) {
      warnings.push_back(describe(model, p, " inside ") +
                         " in the deformed configuration: the contact has geometry = \"reference\" (small sliding), "
                         "whose gaps are those of the reference configuration, and the surfaces moved too far for "
                         "it; geometry = \"current\" follows the motion");
    }
  }
  for (const Penetration& p : linearized) {
    if (p.exceeds())
      throw SolveError("check of the answer: " + describe(model, p, " behind its linearised gap to ") +
                       " (geometry = \"reference\": the gap of the reference configuration plus the linearised "
                       "motion): the small-sliding contact was not enforced");
    worst = std::max(worst, p.ratio());
  }
  return worst;
}

/// Whether row r's own node (the slave node it belongs to) has every DOF the row involves prescribed: the node
/// is held along its contact normal.
bool held_along_normal(const Model& model, const ContactLinearization& lin, Index r,
                       const std::vector<char>& is_fixed) {
  const ContactSet& cs = model.contacts();
  const ContactSurface& slave = cs.surfaces[cs.families()[lin.row_family[r]].slave];
  bool involved = false;
  for (int k = 0; k < model.dim(); ++k) {
    const Index d = model.dofs().dof(slave.body, slave.nodes[lin.row_node[r]], k);
    if (lin.A.coeff(r, d) == 0.0) continue;
    if (!is_fixed[static_cast<std::size_t>(d)]) return false;
    involved = true;
  }
  return involved;
}

/// Contact rows whose every DOF is prescribed (held_rows()): a depth beyond kHeldDepthTolerance × h is the
/// prescribed displacements' own (an error: contact cannot push the node out). A node held along its contact
/// normal and in contact shares its force with the support in a split the problem leaves open (an
/// overconstraint: one row more than the free DOFs along the normals): a warning, once per pair.
void check_held_rows(const Model& model, const VectorXd& u, const FixedDofs& fixed, const ContactState& contact,
                     std::vector<std::string>& warnings) {
  std::vector<Index> free_index;
  fixed.free_numbering(u.size(), free_index);
  std::vector<char> is_fixed(free_index.size());
  for (std::size_t d = 0; d < free_index.size(); ++d) is_fixed[d] = free_index[d] < 0;
  const ContactLinearization& lin = contact.linearization;
  for (const Penetration& p : find_held_penetrations(model.contacts(), lin, u, held_rows(lin, is_fixed)))
    if (p.depth > kHeldDepthTolerance * p.size)
      throw SolveError("check of the answer: " + describe(model, p, " inside ", kHeldDepthTolerance) +
                       ", held there by its Dirichlet conditions: every DOF of its gap is prescribed, so that no "
                       "contact force can move it; change the prescribed displacements, or leave the node out "
                       "of the contact surface");
  if (contact.multipliers.size() != lin.A.rows() || lin.A.rows() == 0) return;
  const ContactSet& cs = model.contacts();
  const double force_floor = 1e-6 * contact.multipliers.cwiseAbs().maxCoeff();
  std::vector<char> warned(cs.pairs.size(), 0);
  for (Index r = 0; r < lin.A.rows(); ++r) {
    const ContactFamily& fam = cs.families()[lin.row_family[r]];
    if (warned[fam.pair] || !(std::abs(contact.multipliers[r]) > force_floor) ||
        !held_along_normal(model, lin, r, is_fixed))
      continue;
    warned[fam.pair] = 1;
    const ContactSurface& slave = cs.surfaces[fam.slave];
    warnings.push_back("contact '" + cs.pairs[fam.pair].name + "': " +
                       model.bodies()[slave.body]->mesh.node_label(slave.nodes[lin.row_node[r]]) + " of '" +
                       slave.name + "' is held along its contact normal by Dirichlet conditions and in contact: its "
                       "force is shared with the support in a split the problem leaves open, so that the contact "
                       "pressures there and next to it are not determined by the contact (an overconstraint)");
  }
}

/// The floor of body b's force scale (step_checks.hpp): kRoundOffStrain × (λ + 2μ) × L^(dim−1), L the
/// diagonal of the body's bounding box (reference configuration), λ + 2μ of its stiffest material.
double force_floor(const Body& body, int dim) {
  const Mesh& m = body.mesh;
  const double L = m.num_nodes() > 0 ? (m.x.rowwise().maxCoeff() - m.x.rowwise().minCoeff()).norm() : 0.0;
  double modulus = 0.0;
  for (const LinearElastic& law : body.materials) modulus = std::max(modulus, law.lambda + 2.0 * law.mu);
  return kRoundOffStrain * modulus * std::pow(L, dim - 1);
}

/// Largest ‖r_b‖ / F over the bodies (step_checks.hpp); throws when above the tolerance.
double check_equilibrium(const Model& model, const VectorXd& u, const VectorXd& g, const FixedDofs& fixed,
                         const ContactState* contact) {
  const DofMap& dofs = model.dofs();
  VectorXd r = g;
  double contact_scale = 0.0;
  if (contact) {
    if (contact->multipliers.size() > 0) {
      const VectorXd am = contact->linearization.A.transpose() * contact->multipliers;
      r -= am;
      contact_scale = am.norm();
    }
    for (const auto& f : contact->friction)
      if (f) f->add_gradient(u, r);
  }
  std::vector<Index> free_index;
  fixed.free_numbering(u.size(), free_index);
  double reactions2 = 0.0;
  std::vector<double> body_r2(dofs.num_bodies(), 0.0);
  for (int b = 0; b < dofs.num_bodies(); ++b)
    for (Index d = dofs.dof(b, 0, 0); d < dofs.dof(b, 0, 0) + dofs.num_body_dofs(b); ++d) {
      if (free_index[d] < 0)
        reactions2 += g[d] * g[d];
      else
        body_r2[b] += r[d] * r[d];
    }
  const double scale = std::max({model.external_load().norm(), std::sqrt(reactions2), contact_scale});
  double worst = 0.0;
  for (int b = 0; b < dofs.num_bodies(); ++b) {
    const double body_scale = std::max(scale, force_floor(*model.bodies()[b], model.dim()));
    const double rel = body_scale > 0 ? std::sqrt(body_r2[b]) / body_scale : 0.0;
    worst = std::max(worst, rel);
    if (rel > kEquilibriumRelativeTolerance) {
      std::ostringstream s;
      s.precision(3);
      s << "check of the answer: body '" << model.bodies()[b]->name
        << "' is not in equilibrium: the force residual ‖∇E − contact forces‖ on its free DOFs is " << rel
        << " of the step's force scale " << body_scale << " (at most " << kEquilibriumRelativeTolerance << ")";
      throw SolveError(s.str());
    }
  }
  return worst;
}

}  // namespace

StepCheckFigures check_step(const Model& model, const VectorXd& u, const FixedDofs& fixed,
                            const ContactState* contact) {
  VectorXd g = VectorXd::Zero(u.size());
  try {
    if (u.allFinite()) model.energy().add_gradient(u, g);
  } catch (const EvaluationError& e) {
    throw SolveError(std::string("check of the answer: the energy cannot be evaluated at the answer: ") + e.what());
  }
  check_finite(model, u, g, contact);
  StepCheckFigures f;
  if (contact) {
    f.penetration = check_penetration(model, u, *contact, f.warnings);
    check_held_rows(model, u, fixed, *contact, f.warnings);
  }
  f.equilibrium = check_equilibrium(model, u, g, fixed, contact);
  return f;
}

}  // namespace symcontact
