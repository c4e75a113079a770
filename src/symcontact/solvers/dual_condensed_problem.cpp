#include "symcontact/solvers/dual_condensed_problem.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace symcontact {

DualCondensedProblem::DualCondensedProblem(const SemidefiniteFactor& factor, const SparseMatrix& A, const VectorXd& b,
                                           const VectorXd& g_hat)
    : factor_(factor), m_(A.rows()) {
  const Index n = factor.size();
  if (A.cols() != n || b.size() != m_ || g_hat.size() != n)
    throw std::invalid_argument("DualCondensedProblem: sizes of S, A, b and ĝ differ");
  // Row scales: D_i = f_ref / max_j |A_ij| (see the header).
  VectorXd row_max = VectorXd::Zero(m_);
  for (int j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it)
      row_max[it.row()] = std::max(row_max[it.row()], std::abs(it.value()));
  double f_ref = g_hat.size() ? g_hat.lpNorm<Eigen::Infinity>() : 0.0;
  if (!(f_ref > 0)) {  // no load: the force that closes the largest gap, max diag(S) · max |b_i| / max_j |A_ij|
    double gap_max = 0.0;
    for (Index i = 0; i < m_; ++i)
      if (row_max[i] > 0) gap_max = std::max(gap_max, std::abs(b[i]) / row_max[i]);
    f_ref = factor.max_diagonal() * gap_max;
  }
  if (!(f_ref > 0) || !std::isfinite(f_ref)) f_ref = 1.0;
  D_.resize(m_);
  for (Index i = 0; i < m_; ++i) D_[i] = row_max[i] > 0 ? f_ref / row_max[i] : 1.0;
  A_scaled_ = D_.asDiagonal() * A;
  b_scaled_ = D_.cwiseProduct(b);

  // W = Zᵀ Z and d = Zᵀ t − D b with Z = half(Ãᵀ), t = half(ĝ).
  Z_ = factor.half_solve(MatrixXd(A_scaled_.transpose()));
  const auto t = factor.half_solve(MatrixXd(g_hat));
  t_ = t->map().col(0);
  W_ = std::make_unique<AlignedMatrix>(m_, m_);
  gram_lower(*Z_, *W_);
  d_ = Z_->map().transpose() * t_ - b_scaled_;
  {
    Eigen::VectorXi nnz(m_);
    for (Index j = 0; j < m_; ++j) nnz[j] = static_cast<int>(m_ - j);
    W_lower_.resize(m_, m_);
    W_lower_.reserve(nnz);
    const auto w = W_->map();
    for (Index j = 0; j < m_; ++j)
      for (Index i = j; i < m_; ++i) W_lower_.insert(i, j) = w(i, j);
    W_lower_.makeCompressed();
  }
  // G = (Ã N)ᵀ, e = Nᵀ ĝ.
  const MatrixXd& N = factor.null_basis();
  const MatrixXd AN = A_scaled_ * N;  // m × k
  G_ = AN.transpose().sparseView(0.0, 0.0);
  G_.makeCompressed();
  minus_e_ = -(N.transpose() * g_hat);
  zero_ = VectorXd::Zero(m_);
}

double DualCondensedProblem::objective(const VectorXd& l) {
  VectorXd wl = VectorXd::Zero(m_);
  symmetric_multiply_add(*W_, l, wl);
  return 0.5 * l.dot(wl) - d_.dot(l);
}

void DualCondensedProblem::gradient(const VectorXd& l, VectorXd& g) {
  g = -d_;
  symmetric_multiply_add(*W_, l, g);
}

void DualCondensedProblem::hessian_lower(const VectorXd&, SparseMatrix& H) { H = W_lower_; }

VectorXd DualCondensedProblem::multipliers(const VectorXd& lambda_hat) const {
  return D_.cwiseProduct(lambda_hat.cwiseMax(0.0));
}

VectorXd DualCondensedProblem::primal(const VectorXd& lambda_hat, const VectorXd& equality_multipliers) const {
  if (lambda_hat.size() != m_ || equality_multipliers.size() != G_.rows())
    throw std::invalid_argument("DualCondensedProblem::primal: sizes of λ̂ or of the equality multipliers");
  VectorXd y = factor_.back_solve(Z_->map() * lambda_hat - t_);
  if (G_.rows() > 0) y -= factor_.null_basis() * equality_multipliers;
  return y;
}

VectorXd DualCondensedProblem::scaled_gaps(const VectorXd& y) const { return A_scaled_ * y + b_scaled_; }

}  // namespace symcontact
