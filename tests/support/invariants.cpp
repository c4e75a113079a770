#include "support/invariants.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace symcontact::testing {

namespace {

double equilibrium(const SolvedCase& c) {
  const Model& m = *c.model;
  const DofMap& dofs = m.dofs();
  const Index n = dofs.num_dofs();
  VectorXd grad = VectorXd::Zero(n);
  m.energy().add_gradient(c.u, grad);
  VectorXd r = grad;
  for (const auto& t : c.report.friction)
    if (t) t->add_gradient(c.u, r);
  const VectorXd contact = c.report.linearization.A.rows() > 0 && c.report.multipliers.size() > 0
                               ? VectorXd(c.report.linearization.A.transpose() * c.report.multipliers)
                               : VectorXd::Zero(n);
  r -= contact;
  const double scale = std::max(grad.lpNorm<Eigen::Infinity>(), contact.lpNorm<Eigen::Infinity>());
  std::vector<Index> free_index;
  m.fixed_dofs(m.num_steps() - 1).free_numbering(n, free_index);
  double worst = 0.0;
  for (Index d = 0; d < n; ++d)
    if (free_index[d] >= 0) worst = std::max(worst, std::abs(r[d]));
  return scale > 0 ? worst / scale : worst;
}

double smallest_facet(const ContactSurface& s) {
  double h = std::numeric_limits<double>::infinity();
  const int npf = s.nodes_per_facet();
  for (Index f = 0; f < s.num_facets(); ++f)
    for (int a = 0; a < npf; ++a)
      for (int b = a + 1; b < npf; ++b)
        h = std::min(h, (s.X.col(s.facet(f)[a]) - s.X.col(s.facet(f)[b])).norm());
  return h;
}

}  // namespace

Invariants measure_invariants(const SolvedCase& c) {
  Invariants inv;
  inv.equilibrium = equilibrium(c);
  const ContactSet& cs = c.model->contacts();
  for (std::size_t p = 0; p < c.contact.size(); ++p) {
    const ContactPairResult& pr = c.contact[p];
    for (const ContactSideResult& side : pr.sides) {
      const double h = smallest_facet(cs.surfaces[side.surface]);
      for (Index k = 0; k < side.gap.size(); ++k)
        if (std::isfinite(side.gap[k])) inv.penetration = std::max(inv.penetration, -side.gap[k] / h);
    }
    const ContactPair& pair = cs.pairs[p];
    if (pair.friction != FrictionLaw::kCoulomb || pr.sides.empty() || pair.mu <= 0) continue;
    // The friction side: where the slips are defined (NaN on the other).
    const auto friction_side = std::find_if(pr.sides.begin(), pr.sides.end(), [](const ContactSideResult& s) {
      return s.slip.size() > 0 && s.slip.array().isFinite().any();
    });
    if (friction_side == pr.sides.end()) continue;
    const ContactSideResult& a = *friction_side;
    const double p_max = a.pressure.maxCoeff();
    if (!(p_max > 0)) continue;
    for (Index k = 0; k < a.pressure.size(); ++k) {
      const double excess = a.tangential.col(k).norm() - pair.mu * std::max(0.0, a.pressure[k]);
      inv.friction_excess = std::max(inv.friction_excess, excess / (pair.mu * p_max));
    }
  }
  return inv;
}

}  // namespace symcontact::testing
