#include "symcontact/distributed/node_ordering.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace symcontact {

std::uint64_t hilbert_index(std::vector<std::uint64_t> cell, int bits) {
  const std::size_t n = cell.size();
  if (n == 0 || bits < 1 || static_cast<std::size_t>(bits) * n > 64)
    throw std::invalid_argument("hilbert_index: 1 to 64 bits in all");
  // Skilling (2004): from the finest level's excess work back to the coarsest, each coordinate's bit either
  // reflects the lower bits of the first coordinate or swaps them with its own; then Gray encoding.
  for (std::uint64_t level = std::uint64_t{1} << (bits - 1); level > 1; level >>= 1) {
    const std::uint64_t lower = level - 1;
    for (std::size_t i = 0; i < n; ++i) {
      if (cell[i] & level) {
        cell[0] ^= lower;
      } else {
        const std::uint64_t swap = (cell[0] ^ cell[i]) & lower;
        cell[0] ^= swap;
        cell[i] ^= swap;
      }
    }
  }
  for (std::size_t i = 1; i < n; ++i) cell[i] ^= cell[i - 1];
  std::uint64_t flip = 0;
  for (std::uint64_t level = std::uint64_t{1} << (bits - 1); level > 1; level >>= 1)
    if (cell[n - 1] & level) flip ^= level - 1;
  for (std::uint64_t& c : cell) c ^= flip;
  // The transposed index: bit k of coordinate i is bit (k·n + n − 1 − i) of the index.
  std::uint64_t index = 0;
  for (int k = bits - 1; k >= 0; --k)
    for (std::size_t i = 0; i < n; ++i) index = (index << 1) | ((cell[i] >> k) & 1u);
  return index;
}

NodeOrdering::NodeOrdering(const Eigen::MatrixXd& x) : dim_(static_cast<int>(x.rows())) {
  const Index n = x.cols();
  const int bits = dim_ == 2 ? 31 : 21;
  const double top = static_cast<double>((std::uint64_t{1} << bits) - 1);
  std::vector<std::uint64_t> key(static_cast<std::size_t>(n), 0);
  if (n > 0) {
    const Eigen::VectorXd lo = x.rowwise().minCoeff();
    const double side = (x.rowwise().maxCoeff() - lo).maxCoeff();
    std::vector<std::uint64_t> cell(static_cast<std::size_t>(dim_));
    for (Index k = 0; k < n; ++k) {
      for (int i = 0; i < dim_; ++i)
        cell[static_cast<std::size_t>(i)] =
            side > 0.0 ? static_cast<std::uint64_t>(std::clamp((x(i, k) - lo[i]) / side, 0.0, 1.0) * top) : 0;
      key[static_cast<std::size_t>(k)] = hilbert_index(cell, bits);
    }
  }
  std::vector<Index> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), Index{0});
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) {
    return key[static_cast<std::size_t>(a)] < key[static_cast<std::size_t>(b)];
  });
  position_.resize(static_cast<std::size_t>(n));
  for (Index p = 0; p < n; ++p) position_[static_cast<std::size_t>(order[static_cast<std::size_t>(p)])] = p;
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
