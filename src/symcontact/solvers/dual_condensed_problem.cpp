#include "symcontact/solvers/dual_condensed_problem.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>

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
  f_ref_ = f_ref;
  D_.resize(m_);
  for (Index i = 0; i < m_; ++i) D_[i] = row_max[i] > 0 ? f_ref / row_max[i] : 1.0;
  A_scaled_ = D_.asDiagonal() * A;
  b_scaled_ = D_.cwiseProduct(b);

  // W = Ã S⁺ Ãᵀ and d = Ã S⁺ ĝ − D b.
  W_ = factor.gram(SparseMatrix(A_scaled_.transpose()));
  s_g_ = factor.solve(g_hat);
  d_ = A_scaled_ * s_g_ - b_scaled_;
  // G = (Ã N)ᵀ, e = Nᵀ ĝ.
  const MatrixXd& N = factor.null_basis();
  const MatrixXd AN = A_scaled_ * N;  // m × k
  G_dense_ = AN.transpose();
  G_ = G_dense_.sparseView(0.0, 0.0);
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

void DualCondensedProblem::hessian_lower(const VectorXd&, SparseMatrix& H) {
  if (W_lower_.rows() != m_) {  // 12 bytes an entry of the lower triangle: only when IPOPT is the backend
    Eigen::VectorXi nnz(m_);
    for (Index j = 0; j < m_; ++j) nnz[j] = static_cast<int>(m_ - j);
    W_lower_.resize(m_, m_);
    W_lower_.reserve(nnz);
    const auto w = W_->map();
    for (Index j = 0; j < m_; ++j)
      for (Index i = j; i < m_; ++i) W_lower_.insert(i, j) = w(i, j);
    W_lower_.makeCompressed();
  }
  H = W_lower_;
}

DenseQpResult DualCondensedProblem::solve_interior_point(const DenseQpOptions& options, const VectorXd* lambda_hat0,
                                                         const VectorXd* gaps0,
                                                         const VectorXd* equality_multipliers0) const {
  // KKT of the interior point: W λ − d − Gᵀβ − z = 0; IPOPT's (header): W λ − d + Gᵀλ_ip − z = 0 and μ_eq = −λ_ip,
  // so β = μ_eq and the warm start and the result pass through unchanged.
  return solve_dense_qp(*W_, d_, G_dense_, -minus_e_, options, lambda_hat0, gaps0, equality_multipliers0);
}

VectorXd DualCondensedProblem::multipliers(const VectorXd& lambda_hat) const {
  return D_.cwiseProduct(lambda_hat.cwiseMax(0.0));
}

VectorXd DualCondensedProblem::primal(const VectorXd& lambda_hat, const VectorXd& equality_multipliers) const {
  if (lambda_hat.size() != m_ || equality_multipliers.size() != G_.rows())
    throw std::invalid_argument("DualCondensedProblem::primal: sizes of λ̂ or of the equality multipliers");
  const VectorXd force = A_scaled_.transpose() * lambda_hat;
  VectorXd y = factor_.solve(force) - s_g_;
  if (G_.rows() > 0) y -= factor_.null_basis() * equality_multipliers;
  return y;
}

VectorXd DualCondensedProblem::scaled_gaps(const VectorXd& y) const { return A_scaled_ * y + b_scaled_; }

std::vector<char> DualCondensedProblem::closing_start_set(const VectorXd& lambda_hat) {
  const double lmax = lambda_hat.size() ? lambda_hat.maxCoeff() : 0.0;
  std::vector<char> in_set(lambda_hat.size());
  for (Index i = 0; i < lambda_hat.size(); ++i) in_set[i] = lambda_hat[i] > 1e-6 * lmax;
  return in_set;
}

bool DualCondensedProblem::solve_closed_rows(const std::vector<Index>& F, Rows rows, VectorXd& lam, VectorXd& alpha,
                                             double& df_max) const {
  const Index nf = static_cast<Index>(F.size()), k = G_.rows();
  const auto w = W_->map();
  // W_FF (lower triangle), G_F and d_F of the closed rows.
  AlignedMatrix wff(nf, nf);
  MatrixXd gf(k, nf);
  VectorXd df(nf);
  {
    auto wm = wff.map();
    for (Index a = 0; a < nf; ++a) {
      for (Index bb = a; bb < nf; ++bb) wm(bb, a) = w(F[bb], F[a]);  // F ascending: F[bb] ≥ F[a]
      gf.col(a) = G_dense_.col(F[a]);
      df[a] = d_[F[a]];
    }
  }
  df_max = nf ? df.lpNorm<Eigen::Infinity>() : 0.0;
  const VectorXd e = -minus_e_;
  // An empty set: every contact open, λ = 0. A definite W_FF (independent rows, as on a rigid obstacle): the
  // unique solution by Cholesky. Otherwise (the nearly dependent families of a symmetric pair) the minimum-norm
  // least-squares solution (LAPACK's blocked complete orthogonal factorisation). The O(|F|³) of this step
  // is most of the closing's time.
  VectorXd lf = VectorXd::Zero(nf);
  alpha = VectorXd::Zero(k);
  if (nf + k > 0 && !(nf > 0 && definite_saddle_solve(wff, gf, df, e, lf, alpha))) {
    if (rows == Rows::kIndependent) return false;
    MatrixXd K = MatrixXd::Zero(nf + k, nf + k);
    const auto wm = wff.map();
    for (Index a = 0; a < nf; ++a)
      for (Index bb = a; bb < nf; ++bb) K(bb, a) = K(a, bb) = wm(bb, a);
    K.topRightCorner(nf, k) = gf.transpose();
    K.bottomLeftCorner(k, nf) = gf;
    VectorXd rhs(nf + k);
    rhs << df, e;
    const VectorXd sol = min_norm_solve(K, rhs, 1e-12);
    lf = sol.head(nf);
    alpha = sol.tail(k);
  }
  lam = VectorXd::Zero(m_);
  for (Index a = 0; a < nf; ++a) lam[F[a]] = lf[a];
  return true;
}

DualCondensedProblem::Closing DualCondensedProblem::close_contact_set(VectorXd& lambda_hat,
                                                                      VectorXd& equality_multipliers,
                                                                      int max_rounds, Rows rows) const {
  // Gaps, relative to ‖y‖∞ (the primal polish's kViolationTolerance); the closed rows' gaps, the residual of the
  // system they were solved from, also relative to its right-hand side d_F: y alone vanishes where the
  // condensed DOFs do not move (a face resting on a plane, only u_n condensed), and such a set would never close.
  constexpr double kTolerance = 1e-10;
  Closing c;
  const Index k = G_.rows();
  if (m_ == 0 || lambda_hat.size() != m_ || equality_multipliers.size() != k) {
    c.reason = "sizes";
    return c;
  }
  const double lmax = lambda_hat.maxCoeff();
  if (!(lmax > 0)) {
    c.reason = "no contact";
    return c;
  }
  std::vector<char> in_set = closing_start_set(lambda_hat);
  std::set<std::vector<char>> seen;
  VectorXd lam, alpha;
  for (int round = 0; round < max_rounds; ++round) {
    c.rounds = round + 1;
    if (!seen.insert(in_set).second) {
      c.reason = "the active set cycles";
      return c;
    }
    std::vector<Index> F;
    for (Index i = 0; i < m_; ++i)
      if (in_set[i]) F.push_back(i);
    const Index nf = static_cast<Index>(F.size());
    c.active = nf;
    double df_max = 0.0;
    if (!solve_closed_rows(F, rows, lam, alpha, df_max)) {
      c.reason = "the closed rows are nearly dependent";
      return c;
    }
    // Gaps (scaled rows): W λ − d + Gᵀα, and the tolerance in those units.
    VectorXd gaps = -d_;
    symmetric_multiply_add(*W_, lam, gaps);
    if (k > 0) gaps += G_dense_.transpose() * alpha;
    const double lam_max = nf ? lam.cwiseAbs().maxCoeff() : 0.0;
    bool changed = false;
    for (Index a = 0; a < nf; ++a)
      if (lam[F[a]] < -1e-8 * lam_max) {
        in_set[F[a]] = 0;
        changed = true;
      }
    if (changed) continue;
    // The displacements only for the tolerance's scale, once no row left the set (a product with S⁺).
    const VectorXd y = primal(lam, -alpha);
    const double tol = kTolerance * f_ref_ * std::max(y.lpNorm<Eigen::Infinity>(), 1e-300);
    for (Index i = 0; i < m_; ++i)
      if (!in_set[i] && gaps[i] < -tol) {
        in_set[i] = 1;
        changed = true;
      }
    if (changed) continue;
    double open = 0.0;
    for (Index a = 0; a < nf; ++a) open = std::max(open, std::abs(gaps[F[a]]));
    if (open > std::max(tol, kTolerance * df_max)) {
      c.reason = "the active set does not close consistently";
      return c;
    }
    lambda_hat = lam.cwiseMax(0.0);
    equality_multipliers = -alpha;
    c.applied = true;
    return c;
  }
  c.reason = "the active set did not settle";
  return c;
}

}  // namespace symcontact
