#include "symcontact/contact/contact_set.hpp"

#include <algorithm>
#include <map>
#include <utility>

namespace symcontact {

void ContactSet::finalize() {
  families_.clear();
  for (int p = 0; p < static_cast<int>(pairs.size()); ++p) {
    const ContactPair& cp = pairs[p];
    if (cp.obstacle >= 0) {
      families_.push_back({p, cp.surface_a, -1});
    } else if (cp.surface_a == cp.surface_b) {
      // Self-contact: one family, the surface against itself — every point is a slave point and every
      // facet a master facet, so the family is already symmetric; a second, identical family would
      // only duplicate the constraints (IPOPT then leaves a barrier offset the polish cannot remove).
      families_.push_back({p, cp.surface_a, cp.surface_a});
    } else if (cp.mode == ContactMode::kSymmetric) {
      families_.push_back({p, cp.surface_a, cp.surface_b});
      families_.push_back({p, cp.surface_b, cp.surface_a});
    } else {
      families_.push_back(cp.slave_is_b ? ContactFamily{p, cp.surface_b, cp.surface_a}
                                        : ContactFamily{p, cp.surface_a, cp.surface_b});
    }
  }
}

int ContactSet::friction_family(int pair) const {
  for (int f = 0; f < static_cast<int>(families_.size()); ++f)
    if (families_[f].pair == pair) return f;
  return -1;
}

OppositeSide ContactSet::opposite_side(int f, const DofMap& dofs, const VectorXd& u) const {
  const ContactFamily& fam = families_[f];
  OppositeSide side;
  if (fam.master >= 0) {
    const ContactSurface& ms = surfaces[fam.master];
    side.master_geometry = prepare_master(ms, current_positions(ms, dofs, u));
  } else {
    side.obstacle = &obstacles[pairs[fam.pair].obstacle];
  }
  return side;
}

VectorXd ContactSet::geometry_displacement(int pair, const VectorXd& u) const {
  return pairs[pair].geometry == ContactGeometry::kReference ? VectorXd::Zero(u.size()) : u;
}

ContactLinearization ContactSet::linearize(const DofMap& dofs, const VectorXd& u) const {
  ContactLinearization lin;
  // Positions and master geometries per (surface, configuration): entry s for X + u, entry n + s for X
  // (a surface may belong to pairs of both kinds).
  const std::size_t n = surfaces.size();
  std::vector<Eigen::MatrixXd> x(2 * n);
  std::vector<MasterGeometry> master(2 * n);
  std::vector<char> prepared(2 * n, 0);
  for (std::size_t s = 0; s < n; ++s) {
    x[s] = current_positions(surfaces[s], dofs, u);
    x[n + s] = surfaces[s].X;
  }
  std::vector<Triplet> triplets;
  std::vector<double> b;
  for (int f = 0; f < static_cast<int>(families_.size()); ++f) {
    const ContactFamily& fam = families_[f];
    const ContactPair& pair = pairs[fam.pair];
    ContactSearchOptions opt;
    opt.search_distance = pair.search_distance;
    opt.bisector_ray = pair.bisector_ray();
    const ContactSurface& slave = surfaces[fam.slave];
    const std::size_t at = pair.geometry == ContactGeometry::kReference ? n : 0;
    std::vector<ContactPoint> pts;
    if (fam.master >= 0) {
      const std::size_t m = at + fam.master;
      if (!prepared[m]) {
        master[m] = prepare_master(surfaces[fam.master], x[m]);
        prepared[m] = 1;
      }
      pts = contact_points(slave, x[at + fam.slave], master[m], opt);
    } else {
      pts = contact_points(slave, x[at + fam.slave], obstacles[pair.obstacle], opt);
    }
    const GapConstraints g = assemble_gap_constraints(slave, fam.master >= 0 ? &surfaces[fam.master] : nullptr, pts, dofs);
    const int offset = static_cast<int>(b.size());
    for (const Triplet& t : g.A) triplets.emplace_back(t.row() + offset, t.col(), t.value());
    b.insert(b.end(), g.b.begin(), g.b.end());
    lin.row_family.insert(lin.row_family.end(), g.num_rows(), f);
    lin.row_node.insert(lin.row_node.end(), g.slave_node.begin(), g.slave_node.end());
    lin.row_support.insert(lin.row_support.end(), g.support.begin(), g.support.end());
    lin.points.push_back(std::move(pts));
  }
  lin.A.resize(static_cast<Index>(b.size()), dofs.num_dofs());
  lin.A.setFromTriplets(triplets.begin(), triplets.end());
  lin.b = Eigen::Map<const VectorXd>(b.data(), static_cast<Index>(b.size()));
  return lin;
}

double ContactSet::automatic_search_distance(const ContactSurface& a, const ContactSurface* b) {
  Eigen::VectorXd lo = a.X.rowwise().minCoeff(), hi = a.X.rowwise().maxCoeff();
  double hmax = 0.0;
  for (Index f = 0; f < a.num_facets(); ++f) hmax = std::max(hmax, facet_size(a, f));
  if (b) {
    lo = lo.cwiseMin(b->X.rowwise().minCoeff());
    hi = hi.cwiseMax(b->X.rowwise().maxCoeff());
    for (Index f = 0; f < b->num_facets(); ++f) hmax = std::max(hmax, facet_size(*b, f));
  }
  return 0.1 * (hi - lo).norm() + 2.0 * hmax;
}

VectorXd values_on_rows(const std::vector<int>& family, const std::vector<Index>& node, const VectorXd& values,
                        const ContactLinearization& to) {
  std::map<std::pair<int, Index>, double> value;
  for (Index j = 0; j < values.size(); ++j)
    value[{family[static_cast<std::size_t>(j)], node[static_cast<std::size_t>(j)]}] = values[j];
  VectorXd out = VectorXd::Zero(to.A.rows());
  for (Index j = 0; j < out.size(); ++j) {
    const auto it = value.find({to.row_family[static_cast<std::size_t>(j)], to.row_node[static_cast<std::size_t>(j)]});
    if (it != value.end()) out[j] = it->second;
  }
  return out;
}

}  // namespace symcontact
