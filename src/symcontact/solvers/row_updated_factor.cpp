#include "symcontact/solvers/row_updated_factor.hpp"

#include <stdexcept>

namespace symcontact {

RowUpdatedFactor::RowUpdatedFactor(const SpdFactor& factor, const SparseMatrix& rows_t, const VectorXd& c)
    : factor_(factor), u_t_(rows_t.transpose()) {
  const Index k = rows_t.cols();
  if (c.size() != k) throw std::invalid_argument("RowUpdatedFactor: one coefficient per row");
  z_.resize(rows_t.rows(), k);
  for (Index j = 0; j < k; ++j) z_.col(j) = factor.solve(VectorXd(rows_t.col(j)));
  MatrixXd cap = u_t_ * z_;
  for (Index j = 0; j < k; ++j) {
    if (!(c[j] != 0.0)) return;
    cap(j, j) += 1.0 / c[j];
  }
  capacitance_.compute(cap);
  valid_ = k == 0 || capacitance_.isInvertible();
}

VectorXd RowUpdatedFactor::solve(const VectorXd& r) const {
  VectorXd y = factor_.solve(r);
  if (z_.cols() > 0) y -= z_ * capacitance_.solve(VectorXd(u_t_ * y));
  return y;
}

}  // namespace symcontact
