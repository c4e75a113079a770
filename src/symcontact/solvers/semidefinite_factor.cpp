#include "symcontact/solvers/semidefinite_factor.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <string>

#include "symcontact/core/error.hpp"

extern "C" {
void dpstrf_(const char* uplo, const int* n, double* a, const int* lda, int* piv, int* rank, const double* tol,
             double* work, int* info);
}

namespace symcontact {

SemidefiniteFactor::SemidefiniteFactor(const SparseMatrix& s_lower, double relative_tolerance) : n_(s_lower.rows()) {
  if (s_lower.cols() != n_ || n_ == 0) throw SolveError("SemidefiniteFactor: S must be square and non-empty");
  const int n = static_cast<int>(n_);
  AlignedMatrix a(n_, n_);
  auto am = a.map();
  am.setZero();
  for (int j = 0; j < s_lower.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(s_lower, j); it; ++it)
      if (it.row() >= j) am(it.row(), j) = it.value();
  const double max_diag = am.diagonal().maxCoeff();
  max_diag_ = max_diag;
  if (!(max_diag > 0) || !std::isfinite(max_diag) || am.diagonal().minCoeff() < 0)
    throw SolveError("SemidefiniteFactor: S has a negative, zero or non-finite diagonal");
  piv_.assign(n_, 0);
  std::vector<double> work(2 * n_);
  int rank = 0, info = 0;
  const double tol = relative_tolerance * max_diag;
  dpstrf_("L", &n, a.data(), &n, piv_.data(), &rank, &tol, work.data(), &info);
  if (info < 0) throw SolveError("SemidefiniteFactor: dpstrf rejected argument " + std::to_string(-info));
  for (int& p : piv_) --p;  // 0-based
  r_ = rank;
  l11_ = std::make_unique<AlignedMatrix>(r_, r_);
  l11_->map() = am.topLeftCorner(r_, r_).triangularView<Eigen::Lower>();
  const Index k = n_ - r_;
  null_.resize(n_, k);
  if (k > 0) {
    // v₁ = −L₁₁⁻ᵀ L₂₁ᵀ, v₂ = I in the pivoted order; back to S's order, then orthonormalised.
    AlignedMatrix v1(r_, k);
    v1.map() = -am.block(r_, 0, k, r_).transpose();
    lower_solve(*l11_, true, v1);
    MatrixXd v(n_, k);
    for (Index i = 0; i < r_; ++i) v.row(piv_[i]) = v1.map().row(i);
    for (Index i = 0; i < k; ++i) {
      v.row(piv_[r_ + i]).setZero();
      v(piv_[r_ + i], i) = 1.0;
    }
    Eigen::HouseholderQR<MatrixXd> qr(v);
    null_ = qr.householderQ() * MatrixXd::Identity(n_, k);
    // From S itself (sparse storage, read only here): no dense copy of S is kept for this check.
    const MatrixXd sn = s_lower.selfadjointView<Eigen::Lower>() * null_;
    null_residual_ = sn.cwiseAbs().maxCoeff() / s_lower.coeffs().cwiseAbs().maxCoeff();
  }
}

std::unique_ptr<AlignedMatrix> SemidefiniteFactor::half_solve(const MatrixXd& R) const {
  if (R.rows() != n_) throw std::invalid_argument("SemidefiniteFactor::half_solve: R has the wrong number of rows");
  auto z = std::make_unique<AlignedMatrix>(r_, R.cols());
  auto zm = z->map();
  for (Index i = 0; i < r_; ++i) zm.row(i) = R.row(piv_[i]);
  if (r_ > 0 && R.cols() > 0) lower_solve(*l11_, false, *z);
  return z;
}

std::unique_ptr<AlignedMatrix> SemidefiniteFactor::half_solve(const SparseMatrix& R) const {
  if (R.rows() != n_) throw std::invalid_argument("SemidefiniteFactor::half_solve: R has the wrong number of rows");
  std::vector<Index> position(n_, -1);  // row i of S → its place among the first r pivots, or −1
  for (Index i = 0; i < r_; ++i) position[piv_[i]] = i;
  auto z = std::make_unique<AlignedMatrix>(r_, R.cols());
  auto zm = z->map();
  zm.setZero();
  for (int j = 0; j < R.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(R, j); it; ++it)
      if (position[it.row()] >= 0) zm(position[it.row()], j) += it.value();
  if (r_ > 0 && R.cols() > 0) lower_solve(*l11_, false, *z);
  return z;
}

VectorXd SemidefiniteFactor::back_solve(const VectorXd& z) const {
  if (z.size() != r_) throw std::invalid_argument("SemidefiniteFactor::back_solve: z must have the rank's size");
  AlignedMatrix w(r_, 1);
  w.map() = z;
  if (r_ > 0) lower_solve(*l11_, true, w);
  VectorXd y = VectorXd::Zero(n_);
  for (Index i = 0; i < r_; ++i) y[piv_[i]] = w.data()[i];
  return y;
}

}  // namespace symcontact
