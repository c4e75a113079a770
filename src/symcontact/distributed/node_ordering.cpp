#include "symcontact/distributed/node_ordering.hpp"

#include "symcontact/mesh/hilbert_curve.hpp"

namespace symcontact {

NodeOrdering::NodeOrdering(const Eigen::MatrixXd& x) : dim_(static_cast<int>(x.rows())) {
  const std::vector<Index> order = hilbert_order(x);
  position_.resize(order.size());
  for (std::size_t p = 0; p < order.size(); ++p) position_[static_cast<std::size_t>(order[p])] = static_cast<Index>(p);
}

VectorXd NodeOrdering::to_petsc(const VectorXd& v) const {
  VectorXd out(v.size());
  for (Index d = 0; d < v.size(); ++d) out[dof(d)] = v[d];
  return out;
}

VectorXd NodeOrdering::to_model(const VectorXd& v) const {
  VectorXd out(v.size());
  for (Index d = 0; d < v.size(); ++d) out[d] = v[dof(d)];
  return out;
}

Eigen::MatrixXd NodeOrdering::nodes_to_petsc(const Eigen::MatrixXd& x) const {
  Eigen::MatrixXd out(x.rows(), x.cols());
  for (Index k = 0; k < x.cols(); ++k) out.col(node(k)) = x.col(k);
  return out;
}

std::vector<Index> NodeOrdering::dofs_to_petsc(const std::vector<Index>& dofs) const {
  std::vector<Index> out;
  out.reserve(dofs.size());
  for (const Index d : dofs) out.push_back(dof(d));
  return out;
}

SparseMatrix NodeOrdering::columns_to_petsc(const SparseMatrix& A) const {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(A.nonZeros()));
  for (int col = 0; col < A.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(A, col); it; ++it)
      t.emplace_back(static_cast<int>(it.row()), static_cast<int>(dof(col)), it.value());
  SparseMatrix out(A.rows(), A.cols());
  out.setFromTriplets(t.begin(), t.end());
  return out;
}

NodalConstraints NodeOrdering::to_petsc(const NodalConstraints& c) const {
  NodalConstraints out = c;
  for (Index& k : out.node) k = node(k);
  if (c.rows.size() > 0) out.rows = columns_to_petsc(c.rows);
  if (c.slip_map.size() > 0) out.slip_map = columns_to_petsc(c.slip_map);
  return out;
}

}  // namespace symcontact
