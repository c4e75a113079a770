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
  // Factorised in place; where S has full rank this storage becomes C₁₁ (no second n × n copy).
  auto a = std::make_unique<AlignedMatrix>(n_, n_);
  auto am = a->map();
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
  dpstrf_("L", &n, a->data(), &n, piv_.data(), &rank, &tol, work.data(), &info);
  if (info < 0) throw SolveError("SemidefiniteFactor: dpstrf rejected argument " + std::to_string(-info));
  for (int& p : piv_) --p;  // 0-based
  r_ = rank;
  const Index k = n_ - r_;
  std::unique_ptr<AlignedMatrix> l11;
  if (k == 0) {
    l11 = std::move(a);
  } else {
    l11 = std::make_unique<AlignedMatrix>(r_, r_);
    l11->map() = am.topLeftCorner(r_, r_).triangularView<Eigen::Lower>();
  }
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
  const VectorXd yp = c11_->map().selfadjointView<Eigen::Lower>() * rp;  // half of C₁₁ read
  VectorXd y = VectorXd::Zero(n_);
  for (Index i = 0; i < r_; ++i) y[piv_[i]] = yp[i];
  return y;
}

namespace {

/// A sparse matrix R (n × k) in S's pivoted order, its rows beyond the rank dropped: by columns (start, place,
/// value) and by rows (row_start, column, row_value).
struct PivotedMatrix {
  std::vector<Index> start, place;
  std::vector<double> value;
  std::vector<Index> row_start, column;
  std::vector<double> row_value;
};

PivotedMatrix pivoted(const SparseMatrix& R, const std::vector<Index>& position, Index r) {
  const Index k = R.cols();
  PivotedMatrix m{std::vector<Index>(k + 1, 0), {}, {}, std::vector<Index>(r + 1, 0), {}, {}};
  for (Index j = 0; j < k; ++j) {
    for (SparseMatrix::InnerIterator it(R, static_cast<int>(j)); it; ++it)
      if (position[it.row()] >= 0) {
        m.place.push_back(position[it.row()]);
        m.value.push_back(it.value());
        ++m.row_start[position[it.row()] + 1];
      }
    m.start[j + 1] = static_cast<Index>(m.place.size());
  }
  for (Index p = 0; p < r; ++p) m.row_start[p + 1] += m.row_start[p];
  m.column.resize(m.place.size());
  m.row_value.resize(m.place.size());
  std::vector<Index> next(m.row_start.begin(), m.row_start.end() - 1);
  for (Index j = 0; j < k; ++j)
    for (Index e = m.start[j]; e < m.start[j + 1]; ++e) {
      m.column[next[m.place[e]]] = j;
      m.row_value[next[m.place[e]]++] = m.value[e];
    }
  return m;
}

}  // namespace

std::unique_ptr<AlignedMatrix> SemidefiniteFactor::gram(const SparseMatrix& R) const {
  if (R.rows() != n_) throw std::invalid_argument("SemidefiniteFactor::gram: R has the wrong number of rows");
  const Index k = R.cols();
  std::vector<Index> position(n_, -1);  // row i of S → its place among the first r pivots, or −1
  for (Index i = 0; i < r_; ++i) position[piv_[i]] = i;
  const PivotedMatrix m = pivoted(R, position, r_);
  // G = R̃ᵀ C₁₁ R̃ (R̃ = (P R)₁..ᵣ) by panels of 16 rows of C₁₁: the panel is copied transposed (16 × r,
  // contiguous; C₁₁ symmetric, so these are 16 of its columns), T = (its rows of C₁₁ R̃)ᵀ (k × 16) is summed
  // from it column of R̃ by column, and each of those 16 rows p of C₁₁ R̃ enters G's columns a with R̃_pa ≠ 0:
  // G(:, a) += R̃_pa T(:, p). C₁₁ is read once, C₁₁ R̃ never stored; both triangles of G come out.
  constexpr Index kPanel = 16;
  using Block = Eigen::Matrix<double, kPanel, 1>;
  auto G = std::make_unique<AlignedMatrix>(k, k);
  auto gm = G->map();
  gm.setZero();
  const auto c = c11_->map();
  Eigen::Matrix<double, kPanel, Eigen::Dynamic> panel(kPanel, r_);
  Eigen::Matrix<double, Eigen::Dynamic, kPanel> T(k, kPanel);
  for (Index i0 = 0; i0 < r_; i0 += kPanel) {
    const Index width = std::min(kPanel, r_ - i0);
    panel.topRows(width) = c.middleCols(i0, width).transpose();
    panel.bottomRows(kPanel - width).setZero();
    for (Index j = 0; j < k; ++j) {
      Block sum = Block::Zero();
      for (Index e = m.start[j]; e < m.start[j + 1]; ++e) sum += m.value[e] * panel.col(m.place[e]);
      T.row(j) = sum.transpose();
    }
    for (Index q = 0; q < width; ++q)
      for (Index f = m.row_start[i0 + q]; f < m.row_start[i0 + q + 1]; ++f)
        gm.col(m.column[f]) += m.row_value[f] * T.col(q);
  }
  return G;
}

}  // namespace symcontact
