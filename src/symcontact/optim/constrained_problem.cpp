#include "symcontact/optim/constrained_problem.hpp"

#include <algorithm>

namespace symcontact {

void ConstrainedProblem::add_hessian_lower(const VectorXd& x, double s, Eigen::Ref<MatrixXd> M) {
  SparseMatrix H;
  hessian_lower(x, H);
  for (Index j = 0; j < H.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(H, j); it; ++it)
      M(std::max(it.row(), j), std::min(it.row(), j)) += s * it.value();
}

void ConstrainedProblem::hessian_product(const VectorXd& x, const VectorXd& v, VectorXd& out) {
  SparseMatrix H;
  hessian_lower(x, H);
  out = H.selfadjointView<Eigen::Lower>() * v;
}

}  // namespace symcontact
