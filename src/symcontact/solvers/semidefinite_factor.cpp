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
  const VectorXd yp = c11_->map() * rp;
  VectorXd y = VectorXd::Zero(n_);
  for (Index i = 0; i < r_; ++i) y[piv_[i]] = yp[i];
  return y;
}

namespace {

/// The columns of a sparse matrix R (n × k) in S's pivoted order, rows beyond the rank dropped.
struct PivotedColumns {
  std::vector<Index> start, place;
  std::vector<double> value;
};

/// Which entries of Z = Xᵀ R a product computes: all, or for each panel of X's columns i0 … i0 + 15 the
/// columns j ≥ i0 of Z (when Z is symmetric, its lower triangle and a few entries above the diagonal).
enum class Part { kAll, kFromPanel };

/// Z = Xᵀ R for a dense X (n_x × m) and R as `columns` (places < n_x), by panels of 16 columns of X: each
/// panel is copied transposed (16 × n_x, contiguous), so that the 16 entries of R's place p are one short
/// contiguous read and the panel, reused by every column of R, stays in cache. `store(i0, j, z)` receives
/// Z(i0 … i0 + 15, j) (entries beyond m are zero and are not to be stored). A fixed order of sums.
template <class Store>
void panel_product(Eigen::Ref<const MatrixXd> X, const PivotedColumns& columns, Part part, Store&& store) {
  constexpr Index kPanel = 16;
  using Block = Eigen::Matrix<double, kPanel, 1>;
  const Index m = X.cols(), k = static_cast<Index>(columns.start.size()) - 1;
  Eigen::Matrix<double, kPanel, Eigen::Dynamic> panel(kPanel, X.rows());
  for (Index i0 = 0; i0 < m; i0 += kPanel) {
    const Index width = std::min(kPanel, m - i0);
    panel.topRows(width) = X.middleCols(i0, width).transpose();
    panel.bottomRows(kPanel - width).setZero();
    for (Index j = part == Part::kAll ? 0 : i0; j < k; ++j) {
      Block sum = Block::Zero();
      for (Index e = columns.start[j]; e < columns.start[j + 1]; ++e)
        sum += columns.value[e] * panel.col(columns.place[e]);
      store(i0, j, sum);
    }
  }
}

}  // namespace

std::unique_ptr<AlignedMatrix> SemidefiniteFactor::gram(const SparseMatrix& R) const {
  if (R.rows() != n_) throw std::invalid_argument("SemidefiniteFactor::gram: R has the wrong number of rows");
  const Index k = R.cols();
  std::vector<Index> position(n_, -1);  // row i of S → its place among the first r pivots, or −1
  for (Index i = 0; i < r_; ++i) position[piv_[i]] = i;
  PivotedColumns columns{std::vector<Index>(k + 1, 0), {}, {}};
  for (Index j = 0; j < k; ++j) {
    for (SparseMatrix::InnerIterator it(R, static_cast<int>(j)); it; ++it)
      if (position[it.row()] >= 0) {
        columns.place.push_back(position[it.row()]);
        columns.value.push_back(it.value());
      }
    columns.start[j + 1] = static_cast<Index>(columns.place.size());
  }
  // T = C₁₁ (P R)₁..ᵣ = C₁₁ᵀ (P R)₁..ᵣ (C₁₁ symmetric), r × k; then G = Tᵀ (P R)₁..ᵣ, k × k, from its
  // lower triangle's panels: G(a, b) for a ≥ the panel's first b (entries above the diagonal are G's too).
  MatrixXd T(r_, k);
  panel_product(c11_->map(), columns, Part::kAll, [&](Index i0, Index j, const auto& z) {
    const Index width = std::min<Index>(z.size(), r_ - i0);
    T.col(j).segment(i0, width) = z.head(width);
  });
  auto G = std::make_unique<AlignedMatrix>(k, k);
  auto gm = G->map();
  panel_product(T, columns, Part::kFromPanel, [&](Index b0, Index a, const auto& z) {
    const Index width = std::min<Index>(z.size(), k - b0);
    gm.row(a).segment(b0, width) = z.head(width).transpose();
  });
  return G;
}

}  // namespace symcontact
