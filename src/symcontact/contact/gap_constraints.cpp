#include "symcontact/contact/gap_constraints.hpp"

#include "symcontact/fem/shape_functions.hpp"

namespace symcontact {

GapConstraints assemble_gap_constraints(const ContactSurface& slave, const ContactSurface* master,
                                        const std::vector<ContactPoint>& points, const DofMap& dofs) {
  GapConstraints g;
  const int D = slave.dim;
  const int npf = slave.nodes_per_facet();
  const int mpf = master ? master->nodes_per_facet() : 0;
  std::vector<Index> row_of(slave.num_nodes(), -1);
  std::vector<double> N(npf), phi(npf), M(std::max(mpf, 1));
  // Consecutive points of one (slave facet, master facet) pair — a segment or a clip cell — are summed
  // into local blocks first (Ks: rows × slave facet DOFs, Km: rows × master facet DOFs), then scattered:
  // one triplet per block entry instead of one per point.
  Eigen::MatrixXd Ks = Eigen::MatrixXd::Zero(npf, npf * D), Km = Eigen::MatrixXd::Zero(npf, std::max(mpf, 1) * D);
  Eigen::VectorXd bl = Eigen::VectorXd::Zero(npf), sl = Eigen::VectorXd::Zero(npf);
  Index cur_slave = -1, cur_master = -1;
  auto flush = [&]() {
    if (cur_slave < 0) return;
    const Index* sn = slave.facet(cur_slave);
    for (int i = 0; i < npf; ++i) {
      if (sl[i] == 0.0) continue;
      Index& row = row_of[sn[i]];
      if (row < 0) {
        row = g.num_rows();
        g.b.push_back(0.0);
        g.slave_node.push_back(sn[i]);
        g.support.push_back(0.0);
      }
      g.b[row] += bl[i];
      g.support[row] += sl[i];
      if (!slave.is_rigid())
        for (int a = 0; a < npf; ++a)
          for (int c = 0; c < D; ++c)
            g.A.emplace_back(static_cast<int>(row), static_cast<int>(dofs.dof(slave.body, slave.nodes[sn[a]], c)),
                             Ks(i, D * a + c));
      if (master && !master->is_rigid() && cur_master >= 0) {
        const Index* mn = master->facet(cur_master);
        for (int b = 0; b < mpf; ++b)
          for (int c = 0; c < D; ++c)
            g.A.emplace_back(static_cast<int>(row), static_cast<int>(dofs.dof(master->body, master->nodes[mn[b]], c)),
                             Km(i, D * b + c));
      }
    }
    Ks.setZero();
    Km.setZero();
    bl.setZero();
    sl.setZero();
  };
  for (const ContactPoint& p : points) {
    if (p.slave_facet != cur_slave || p.master_facet != cur_master) {
      flush();
      cur_slave = p.slave_facet;
      cur_master = p.master_facet;
    }
    shape_functions(slave.facet_type, p.xi, N.data(), nullptr);
    test_functions(slave, p.xi, phi.data());
    if (master) shape_functions(master->facet_type, p.eta, M.data(), nullptr);
    const Index* sn = slave.facet(p.slave_facet);
    // Reference positions of the slave point and of the projection: b collects the u-independent part.
    Eigen::Vector3d Xs = Eigen::Vector3d::Zero(), Ym = p.xbar;
    for (int a = 0; a < npf; ++a) Xs.head(D) += N[a] * slave.X.col(sn[a]);
    if (master) {
      Ym.setZero();
      for (int b = 0; b < mpf; ++b) Ym.head(D) += M[b] * master->X.col(master->facet(p.master_facet)[b]);
    }
    const Eigen::Vector3d& dir = p.row_direction();
    const double theta0 = (Xs - Ym).dot(dir);
    for (int i = 0; i < npf; ++i) {
      const double wi = p.weight * phi[i];
      if (wi == 0.0) continue;
      bl[i] += wi * theta0;
      sl[i] += wi;
      for (int a = 0; a < npf; ++a)
        for (int c = 0; c < D; ++c) Ks(i, D * a + c) += wi * N[a] * dir[c];
      if (master)
        for (int b = 0; b < mpf; ++b)
          for (int c = 0; c < D; ++c) Km(i, D * b + c) -= wi * M[b] * dir[c];
    }
  }
  flush();
  // A row whose support Σ w φ_i is not positive has the wrong sign. With P2 test functions (negative
  // in parts of a facet) a node whose facets are only partly integrated — cut by the end or border of
  // the master, or, in self-contact, where the surface stops facing itself (the search distance selects
  // whole facets, contact_points.hpp) — can get g_i = (negative weight) × (a positive gap) < 0: a
  // violated constraint where nothing touches, which the solver can only meet by closing a gap that is
  // wide open (on a Line3 facet integrated over ξ ∈ [0, s], ∫ N_end = s²(4s − 3)/6 < 0 for s < 3/4).
  // Such rows are left out; the other nodes of the facet keep theirs.
  std::vector<Index> keep(g.num_rows(), -1);
  Index kept = 0;
  for (Index r = 0; r < g.num_rows(); ++r)
    if (g.support[r] > 1e-12 * slave.nodal_area[g.slave_node[r]]) keep[r] = kept++;
  if (kept < g.num_rows()) {
    GapConstraints f;
    for (Index r = 0; r < g.num_rows(); ++r)
      if (keep[r] >= 0) {
        f.b.push_back(g.b[r]);
        f.slave_node.push_back(g.slave_node[r]);
        f.support.push_back(g.support[r]);
      }
    for (const Triplet& t : g.A)
      if (keep[t.row()] >= 0) f.A.emplace_back(static_cast<int>(keep[t.row()]), t.col(), t.value());
    return f;
  }
  return g;
}

}  // namespace symcontact
