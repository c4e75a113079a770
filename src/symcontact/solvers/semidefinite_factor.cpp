#include "symcontact/solvers/semidefinite_factor.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "symcontact/core/error.hpp"

extern "C" {
void dpstrf_(const char* uplo, const int* n, double* a, const int* lda, int* piv, int* rank, const double* tol,
             double* work, int* info);
void dpotri_(const char* uplo, const int* n, double* a, const int* lda, int* info);
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
  auto l11 = std::make_unique<AlignedMatrix>(r_, r_);
  l11->map() = am.topLeftCorner(r_, r_).triangularView<Eigen::Lower>();
  const Index k = n_ - r_;
  null_.resize(n_, k);
  if (k > 0) {
    // v₁ = −L₁₁⁻ᵀ L₂₁ᵀ, v₂ = I in the pivoted order; back to S's order, then orthonormalised.
    AlignedMatrix v1(r_, k);
    v1.map() = -am.block(r_, 0, k, r_).transpose();
    lower_solve(*l11, true, v1);
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
  // C₁₁ = (L₁₁ L₁₁ᵀ)⁻¹ in L₁₁'s place, then its upper triangle from the lower (columns are read whole).
  if (r_ > 0) {
    const int r = static_cast<int>(r_);
    dpotri_("L", &r, l11->data(), &r, &info);
    if (info != 0) throw SolveError("SemidefiniteFactor: dpotri failed (info " + std::to_string(info) + ")");
    auto c = l11->map();
    c.triangularView<Eigen::StrictlyUpper>() = c.transpose().triangularView<Eigen::StrictlyUpper>();
  }
  c11_ = std::move(l11);
}

VectorXd SemidefiniteFactor::solve(const VectorXd& r) const {
  if (r.size() != n_) throw std::invalid_argument("SemidefiniteFactor::solve: r must have S's size");
  VectorXd rp(r_);
  for (Index i = 0; i < r_; ++i) rp[i] = r[piv_[i]];
  const VectorXd yp = c11_->map() * rp;
  VectorXd y = VectorXd::Zero(n_);
  for (Index i = 0; i < r_; ++i) y[piv_[i]] = yp[i];
  return y;
}

std::unique_ptr<AlignedMatrix> SemidefiniteFactor::gram(const SparseMatrix& R) const {
  if (R.rows() != n_) throw std::invalid_argument("SemidefiniteFactor::gram: R has the wrong number of rows");
  const Index k = R.cols();
  std::vector<Index> position(n_, -1);  // row i of S → its place among the first r pivots, or −1
  for (Index i = 0; i < r_; ++i) position[piv_[i]] = i;
  // R's entries in the pivoted order, column by column (those beyond the rank dropped).
  std::vector<Index> start(k + 1, 0), place;
  std::vector<double> value;
  for (Index j = 0; j < k; ++j) {
    for (SparseMatrix::InnerIterator it(R, static_cast<int>(j)); it; ++it)
      if (position[it.row()] >= 0) {
        place.push_back(position[it.row()]);
        value.push_back(it.value());
      }
    start[j + 1] = static_cast<Index>(place.size());
  }
  // Tᵀ with T = C₁₁ (P R)₁..ᵣ: column j of T is a sum of the columns of C₁₁ that R's column j touches. By
  // blocks of kRows rows, summed in registers, so that the block of C₁₁ in use stays in cache while every
  // column of T passes; stored transposed (k × r) for the next product.
  constexpr Index kRows = 32;
  using Block = Eigen::Matrix<double, kRows, 1>;
  MatrixXd Tt(k, r_);
  const auto c = c11_->map();
  const Index full = r_ / kRows * kRows;
  for (Index i0 = 0; i0 < full; i0 += kRows)
    for (Index j = 0; j < k; ++j) {
      Block sum = Block::Zero();
      for (Index e = start[j]; e < start[j + 1]; ++e) sum += value[e] * c.col(place[e]).segment<kRows>(i0);
      Tt.row(j).segment<kRows>(i0) = sum.transpose();
    }
  for (Index j = 0; j < k; ++j) {
    VectorXd sum = VectorXd::Zero(r_ - full);
    for (Index e = start[j]; e < start[j + 1]; ++e) sum += value[e] * c.col(place[e]).tail(r_ - full);
    Tt.row(j).tail(r_ - full) = sum.transpose();
  }
  // G = (P R)₁..ᵣᵀ T, lower triangle: G_ab = Σ_{e ∈ R_b} R_eb T_{p_e a} (symmetry), so the part a ≥ b of G's
  // column b is a sum of the columns of Tᵀ that R's column b touches.
  auto G = std::make_unique<AlignedMatrix>(k, k);
  auto gm = G->map();
  for (Index b = 0; b < k; ++b) {
    auto column = gm.col(b).tail(k - b);
    column.setZero();
    for (Index e = start[b]; e < start[b + 1]; ++e) column += value[e] * Tt.col(place[e]).tail(k - b);
  }
  return G;
}

}  // namespace symcontact
