#include "symcontact/contact/friction_term.hpp"

#include <cmath>

#include "symcontact/fem/shape_functions.hpp"

namespace symcontact {

FrictionTerm::FrictionTerm(std::string name, const ContactSurface& slave, const ContactSurface* master,
                           std::vector<ContactPoint> points, std::vector<double> tau, double alpha,
                           const DofMap& dofs, const VectorXd& u_start)
    : name_(std::move(name)), points_(std::move(points)), alpha_(alpha), dim_(slave.dim) {
  const int D = dim_;
  const int npf = slave.nodes_per_facet();
  const int mpf = master ? master->nodes_per_facet() : 0;
  std::vector<double> N(npf), M(std::max(mpf, 1));
  local_.reserve(points_.size());
  for (std::size_t q = 0; q < points_.size(); ++q) {
    const ContactPoint& p = points_[q];
    Local l;
    shape_functions(slave.facet_type, p.xi, N.data(), nullptr);
    std::vector<std::pair<Index, double>> cols;  // (node-major DOF base, coefficient)
    if (!slave.is_rigid())
      for (int a = 0; a < npf; ++a) cols.emplace_back(dofs.dof(slave.body, slave.nodes[slave.facet(p.slave_facet)[a]], 0), N[a]);
    if (master && !master->is_rigid()) {
      shape_functions(master->facet_type, p.eta, M.data(), nullptr);
      for (int b = 0; b < mpf; ++b)
        cols.emplace_back(dofs.dof(master->body, master->nodes[master->facet(p.master_facet)[b]], 0), -M[b]);
    }
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
    j += l.wt * std::sqrt(slip(l, u).squaredNorm() + alpha_ * alpha_);
  }
  return j;
}

void FrictionTerm::add_gradient(const VectorXd& u, VectorXd& g) const {
  for (const Local& l : local_) {
    if (l.wt == 0.0) continue;
    const Eigen::VectorXd s = slip(l, u);
    const double r = std::sqrt(s.squaredNorm() + alpha_ * alpha_);
    const Eigen::VectorXd gl = (l.wt / r) * (l.B.transpose() * (l.P * s));
    for (std::size_t k = 0; k < l.dofs.size(); ++k) g[l.dofs[k]] += gl[k];
  }
}

void FrictionTerm::add_hessian(const VectorXd& u, MatrixSink& sink) const {
  const int D = dim_;
  for (const Local& l : local_) {
    if (l.wt == 0.0) continue;
    const Eigen::VectorXd s = slip(l, u);
    const double r2 = s.squaredNorm() + alpha_ * alpha_;
    const double r = std::sqrt(r2);
    const Eigen::MatrixXd Hs = (Eigen::MatrixXd::Identity(D, D) - s * s.transpose() / r2) * (l.wt / r);
    const Eigen::MatrixXd PB = l.P * l.B;
    const Eigen::MatrixXd K = PB.transpose() * Hs * PB;
    sink.add(l.dofs.data(), static_cast<int>(l.dofs.size()), K.data());
  }
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
