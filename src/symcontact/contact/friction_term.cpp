#include "symcontact/contact/friction_term.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "symcontact/contact/closest_point.hpp"
#include "symcontact/fem/shape_functions.hpp"

namespace symcontact {

namespace {

/// A relative-displacement map B as DOF columns: (node-major DOF base, coefficient) pairs, the slave
/// side's (+N_a at ξ) and the master side's (−M_b at η) apart. One dim × dim block c·I per entry.
struct SlipColumns {
  std::vector<std::pair<Index, double>> slave, master;
};

/// The map of point p: s = u_s(ξ_p) − u_m(η_p) (no master part for an obstacle or a rigid master).
SlipColumns point_columns(const ContactSurface& slave, const ContactSurface* master, const DofMap& dofs,
                          const ContactPoint& p) {
  SlipColumns c;
  double N[10];
  if (!slave.is_rigid()) {
    shape_functions(slave.facet_type, p.xi, N, nullptr);
    for (int a = 0; a < slave.nodes_per_facet(); ++a)
      c.slave.emplace_back(dofs.dof(slave.body, slave.nodes[slave.facet(p.slave_facet)[a]], 0), N[a]);
  }
  if (master && !master->is_rigid()) {
    shape_functions(master->facet_type, p.eta, N, nullptr);
    for (int b = 0; b < master->nodes_per_facet(); ++b)
      c.master.emplace_back(dofs.dof(master->body, master->nodes[master->facet(p.master_facet)[b]], 0), -N[b]);
  }
  return c;
}

/// into += a · from, entries with the same DOF base merged.
void add_scaled(std::vector<std::pair<Index, double>>& into, const std::vector<std::pair<Index, double>>& from,
                double a) {
  for (const auto& entry : from) {
    const Index base = entry.first;
    auto it = std::find_if(into.begin(), into.end(), [base](const auto& e) { return e.first == base; });
    if (it == into.end())
      into.emplace_back(base, a * entry.second);
    else
      it->second += a * entry.second;
  }
}

/// Nodal points on a Tri6 or Quad8 slave: the maps of the slip's coefficients in the test basis (the header),
///   B̃_v = B_v,   B̃_e = (B_e − c (B_v1 + B_v2)) / (1 − 2c).
/// A vertex without a point of its own (it projects onto nothing) enters with its slave displacement
/// against the master's at the edge node's projection: slave part δ_v, master part that of B_e.
std::vector<SlipColumns> test_basis_columns(const ContactSurface& slave, const DofMap& dofs,
                                            const std::vector<ContactPoint>& points,
                                            const std::vector<SlipColumns>& nodal) {
  constexpr double c = kModifiedTri6Coefficient;
  std::vector<Index> point_of(slave.num_nodes(), -1);
  for (std::size_t q = 0; q < points.size(); ++q) point_of[points[q].slave_node] = static_cast<Index>(q);
  std::vector<SlipColumns> out = nodal;
  const int nv = cell_num_vertices(slave.facet_type), npf = slave.nodes_per_facet();
  for (std::size_t q = 0; q < points.size(); ++q) {
    const Index* facet = slave.facet(points[q].slave_facet);
    const int a = static_cast<int>(std::find(facet, facet + npf, points[q].slave_node) - facet);
    if (a < nv) continue;  // a vertex: s̃_v = s_v
    SlipColumns& e = out[q];
    for (std::pair<Index, double>& entry : e.slave) entry.second = entry.second / (1.0 - 2.0 * c);
    for (std::pair<Index, double>& entry : e.master) entry.second = entry.second / (1.0 - 2.0 * c);
    const double w = -c / (1.0 - 2.0 * c);
    for (int end = 0; end < 2; ++end) {
      const Index v = facet[basis_edge(slave.facet_type, a - nv)[end]];
      if (point_of[v] >= 0) {
        add_scaled(e.slave, nodal[point_of[v]].slave, w);
        add_scaled(e.master, nodal[point_of[v]].master, w);
      } else {
        if (!slave.is_rigid()) add_scaled(e.slave, {{dofs.dof(slave.body, slave.nodes[v], 0), 1.0}}, w);
        add_scaled(e.master, nodal[q].master, w);
      }
    }
  }
  return out;
}

}  // namespace

FrictionTerm::FrictionTerm(std::string name, const ContactSurface& slave, const ContactSurface* master,
                           std::vector<ContactPoint> points, std::vector<double> tau, std::vector<double> alpha,
                           const DofMap& dofs, const VectorXd& u_start)
    : name_(std::move(name)), points_(std::move(points)), alpha_(std::move(alpha)), dim_(slave.dim) {
  const int D = dim_;
  std::vector<SlipColumns> columns;
  columns.reserve(points_.size());
  for (const ContactPoint& p : points_) columns.push_back(point_columns(slave, master, dofs, p));
  const bool nodal = !points_.empty() && std::all_of(points_.begin(), points_.end(),
                                                     [](const ContactPoint& p) { return p.slave_node >= 0; });
  if (nodal && has_modified_test_basis(slave)) columns = test_basis_columns(slave, dofs, points_, columns);
  local_.reserve(points_.size());
  for (std::size_t q = 0; q < points_.size(); ++q) {
    const ContactPoint& p = points_[q];
    Local l;
    std::vector<std::pair<Index, double>> cols = columns[q].slave;
    cols.insert(cols.end(), columns[q].master.begin(), columns[q].master.end());
    const int n = static_cast<int>(cols.size()) * D;
    l.dofs.resize(n);
    l.B = Eigen::MatrixXd::Zero(D, n);
    for (std::size_t k = 0; k < cols.size(); ++k)
      for (int i = 0; i < D; ++i) {
        l.dofs[D * k + i] = cols[k].first + i;
        l.B(i, D * k + i) = cols[k].second;
      }
    const Eigen::VectorXd nv = p.normal.head(D);
    l.P = Eigen::MatrixXd::Identity(D, D) - nv * nv.transpose();
    l.wt = p.weight * tau[q];
    l.alpha2 = alpha_[q] * alpha_[q];
    Eigen::VectorXd u0(n);
    for (int k = 0; k < n; ++k) u0[k] = u_start[l.dofs[k]];
    l.s0 = l.P * (l.B * u0);
    local_.push_back(std::move(l));
  }
}

Eigen::VectorXd FrictionTerm::slip(const Local& l, const VectorXd& u) const {
  Eigen::VectorXd ul(l.dofs.size());
  for (std::size_t k = 0; k < l.dofs.size(); ++k) ul[k] = u[l.dofs[k]];
  return l.P * (l.B * ul) - l.s0;
}

double FrictionTerm::value(const VectorXd& u) const {
  double j = 0.0;
  for (const Local& l : local_) {
    if (l.wt == 0.0) continue;
    j += l.wt * std::sqrt(slip(l, u).squaredNorm() + l.alpha2);
  }
  return j;
}

void FrictionTerm::add_gradient(const VectorXd& u, VectorXd& g) const {
  for (const Local& l : local_) {
    if (l.wt == 0.0) continue;
    const Eigen::VectorXd s = slip(l, u);
    const double r = std::sqrt(s.squaredNorm() + l.alpha2);
    const Eigen::VectorXd gl = (l.wt / r) * (l.B.transpose() * (l.P * s));
    for (std::size_t k = 0; k < l.dofs.size(); ++k) g[l.dofs[k]] += gl[k];
  }
}

Eigen::MatrixXd FrictionTerm::slip_curvature(std::size_t q, const Eigen::VectorXd& s) const {
  const Local& l = local_[q];
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(dim_, dim_);
  const double r2 = s.squaredNorm() + l.alpha2;
  const double r = std::sqrt(r2);
  if (hessian_model_ == FrictionHessian::kExact) return (I - s * s.transpose() / r2) * (l.wt / r);
  // The primal-dual model (FrictionHessian::kPrimalDual): z moved from the previous evaluation's by the
  // linearisation of z r = s there; kept where s has not changed.
  if (dual_.size() != local_.size()) dual_.assign(local_.size(), Dual{});
  Dual& d = dual_[q];
  if (d.z.size() == 0) {
    d.z = s / r;
  } else if (s != d.s) {
    const double r0 = std::sqrt(d.s.squaredNorm() + l.alpha2);
    const Eigen::VectorXd ds = s - d.s;
    d.z = d.s / r0 + (ds - d.z * (d.s.dot(ds) / r0)) / r0;
    d.z /= std::max(1.0, d.z.norm());
  }
  d.s = s;
  return (I - 0.5 * (d.z * s.transpose() + s * d.z.transpose()) / r) * (l.wt / r);
}

void FrictionTerm::add_hessian(const VectorXd& u, MatrixSink& sink) const {
  for (std::size_t q = 0; q < local_.size(); ++q) {
    const Local& l = local_[q];
    if (l.wt == 0.0) {
      if (!keep_zero_blocks_) continue;
      const Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(l.dofs.size(), l.dofs.size());
      sink.add(l.dofs.data(), static_cast<int>(l.dofs.size()), zero.data());
      continue;
    }
    const Eigen::MatrixXd Hs = slip_curvature(q, slip(l, u));
    const Eigen::MatrixXd PB = l.P * l.B;
    const Eigen::MatrixXd K = PB.transpose() * Hs * PB;
    sink.add(l.dofs.data(), static_cast<int>(l.dofs.size()), K.data());
  }
}

void FrictionTerm::set_thresholds(const std::vector<double>& tau) {
  if (tau.size() != local_.size()) throw std::invalid_argument("FrictionTerm::set_thresholds: one τ per point");
  for (std::size_t q = 0; q < local_.size(); ++q) local_[q].wt = points_[q].weight * tau[q];
}

std::vector<double> FrictionTerm::bounds() const {
  std::vector<double> g;
  g.reserve(local_.size());
  for (const Local& l : local_) g.push_back(l.wt);
  return g;
}

SparseMatrix FrictionTerm::slip_map(Index num_dofs) const {
  std::vector<Eigen::Triplet<double>> t;
  for (std::size_t q = 0; q < local_.size(); ++q)
    for (std::size_t k = 0; k < local_[q].dofs.size(); ++k)
      for (int i = 0; i < dim_; ++i)
        if (local_[q].B(i, static_cast<Index>(k)) != 0.0)
          t.emplace_back(static_cast<int>(dim_ * static_cast<Index>(q) + i), static_cast<int>(local_[q].dofs[k]),
                         local_[q].B(i, static_cast<Index>(k)));
  SparseMatrix B(dim_ * static_cast<Index>(local_.size()), num_dofs);
  B.setFromTriplets(t.begin(), t.end());
  return B;
}

std::vector<Eigen::Vector3d> FrictionTerm::slips(const VectorXd& u) const {
  std::vector<Eigen::Vector3d> out;
  out.reserve(local_.size());
  for (const Local& l : local_) {
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    s.head(dim_) = slip(l, u);
    out.push_back(s);
  }
  return out;
}

}  // namespace symcontact
