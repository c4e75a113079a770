#include "symcontact/solvers/dense_kkt.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

// BLAS and LAPACK (Fortran interfaces; column-major, every argument by address).
extern "C" {
void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m, const int* n,
            const double* alpha, const double* a, const int* lda, double* b, const int* ldb);
void dsymv_(const char* uplo, const int* n, const double* alpha, const double* a, const int* lda, const double* x,
            const int* incx, const double* beta, double* y, const int* incy);
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
void dgelsy_(const int* m, const int* n, const int* nrhs, double* a, const int* lda, double* b, const int* ldb,
             int* jpvt, const double* rcond, int* rank, double* work, const int* lwork, int* info);
void dsyrk_(const char* uplo, const char* trans, const int* n, const int* k, const double* alpha, const double* a,
            const int* lda, const double* beta, double* c, const int* ldc);
}

namespace symcontact {

AlignedMatrix::AlignedMatrix(Index rows, Index cols)
    : rows_(rows), cols_(cols),
      data_(static_cast<double*>(std::aligned_alloc(64, ((std::max<Index>(rows * cols, 1) * 8 + 63) / 64) * 64))) {
  if (!data_) throw std::bad_alloc();
}

AlignedMatrix::~AlignedMatrix() { std::free(data_); }

void lower_solve(const AlignedMatrix& L, bool transpose, AlignedMatrix& B) {
  const int n = static_cast<int>(L.rows()), k = static_cast<int>(B.cols());
  const double one = 1.0;
  dtrsm_("L", "L", transpose ? "T" : "N", "N", &n, &k, &one, L.data(), &n, B.data(), &n);
}

void gram_lower(const AlignedMatrix& Z, AlignedMatrix& G) {
  if (G.rows() != Z.cols() || G.cols() != Z.cols()) throw std::invalid_argument("gram_lower: G must be k × k for Z n × k");
  const int n = static_cast<int>(Z.rows()), k = static_cast<int>(Z.cols());
  const double one = 1.0, zero = 0.0;
  dsyrk_("L", "T", &k, &n, &one, Z.data(), &n, &zero, G.data(), &k);
}

VectorXd min_norm_solve(const MatrixXd& K, const VectorXd& r, double rcond) {
  const int n = static_cast<int>(K.rows()), one = 1;
  if (K.cols() != K.rows() || r.size() != K.rows()) throw std::invalid_argument("min_norm_solve: K must be square, r of its size");
  if (n == 0) return VectorXd();
  AlignedMatrix a(n, n), b(n, 1);
  a.map() = K;
  b.map() = r;
  std::vector<int> jpvt(n, 0);
  int rank = 0, info = 0, lwork = -1;
  double query = 0.0;
  dgelsy_(&n, &n, &one, a.data(), &n, b.data(), &n, jpvt.data(), &rcond, &rank, &query, &lwork, &info);
  lwork = static_cast<int>(query);
  std::vector<double> work(std::max(lwork, 1));
  dgelsy_(&n, &n, &one, a.data(), &n, b.data(), &n, jpvt.data(), &rcond, &rank, work.data(), &lwork, &info);
  if (info != 0) throw std::runtime_error("min_norm_solve: dgelsy failed (info " + std::to_string(info) + ")");
  return b.map();
}

bool definite_saddle_solve(const AlignedMatrix& H, const MatrixXd& C, const VectorXd& f, const VectorXd& g, VectorXd& x,
                           VectorXd& z) {
  const Index n = H.rows(), k = C.rows();
  if (H.cols() != n || C.cols() != n || f.size() != n || g.size() != k)
    throw std::invalid_argument("definite_saddle_solve: sizes of H, C, f and g differ");
  if (n == 0) return false;
  auto L = std::make_shared<AlignedMatrix>(n, n);
  L->map() = H.map();
  const int ni = static_cast<int>(n);
  int info = 0;
  dpotrf_("L", &ni, L->data(), &ni, &info);
  if (info != 0) return false;
  const auto d = L->map().diagonal();
  if (!(d.minCoeff() > 1e-6 * d.maxCoeff())) return false;
  AlignedMatrix v(n, 1);
  v.map() = f;
  lower_solve(*L, false, v);
  AlignedMatrix w(n, 1);
  w.map() = v.map();
  z = VectorXd::Zero(k);
  if (k > 0) {
    AlignedMatrix Y(n, k);
    Y.map() = C.transpose();
    lower_solve(*L, false, Y);
    const MatrixXd M = Y.map().transpose() * Y.map();
    Eigen::LDLT<MatrixXd> ldlt(M);
    const VectorXd md = M.diagonal().cwiseAbs();
    if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().cwiseAbs().minCoeff() > 1e-12 * md.maxCoeff())) return false;
    z = ldlt.solve(Y.map().transpose() * v.map() - g);
    w.map() -= Y.map() * z;
  }
  lower_solve(*L, true, w);
  x = w.map();
  return x.allFinite() && z.allFinite();
}

void symmetric_multiply_add(const AlignedMatrix& H, const VectorXd& x, VectorXd& y) {
  const int n = static_cast<int>(x.size()), inc = 1;
  AlignedMatrix xa(n, 1), ya(n, 1);
  xa.map() = x;
  ya.map() = y;
  const double one = 1.0;
  dsymv_("L", &n, &one, H.data(), &n, xa.data(), &inc, &one, ya.data(), &inc);
  y = ya.map();
}

DenseRangeSpace::DenseRangeSpace(std::shared_ptr<const AlignedMatrix> L, const SparseMatrix& A, double rho)
    : L_(std::move(L)), A_(A), rho_(rho), n_(A.cols()), m_(A.rows()) {
  if (!L_ || L_->rows() != n_ || L_->cols() != n_ || m_ < 1)
    throw std::invalid_argument("DenseRangeSpace: the factor and the constraints differ in size, or no constraint");
  W_ = std::make_unique<AlignedMatrix>(n_, m_);
  W_->map() = MatrixXd(A_.transpose());
  lower_solve(*L_, false, *W_);
  AlignedMatrix WtW(m_, m_);
  gram_lower(*W_, WtW);
  WtW_ = WtW.map();
  WtW_.triangularView<Eigen::StrictlyUpper>() = WtW_.transpose();
  decompose();
}

DenseRangeSpace::DenseRangeSpace(const DenseRangeSpace& parent, const std::vector<Index>& keep, const SparseMatrix& A)
    : L_(parent.L_), A_(A), rho_(parent.rho_), n_(parent.n_), m_(static_cast<Index>(keep.size())) {
  if (A_.rows() != m_ || A_.cols() != n_ || m_ < 1)
    throw std::invalid_argument("DenseRangeSpace: the subset's rows and constraints differ in size, or no constraint");
  for (Index j = 0; j < m_; ++j)
    if (keep[j] < 0 || keep[j] >= parent.m_ || (j > 0 && keep[j] <= keep[j - 1]))
      throw std::invalid_argument("DenseRangeSpace: the subset's rows are not increasing rows of the parent");
  W_ = std::make_unique<AlignedMatrix>(n_, m_);
  WtW_.resize(m_, m_);
  for (Index j = 0; j < m_; ++j) {
    W_->map().col(j) = parent.W_->map().col(keep[j]);
    for (Index i = 0; i < m_; ++i) WtW_(i, j) = parent.WtW_(keep[i], keep[j]);
  }
  decompose();
}

void DenseRangeSpace::decompose() {
  // The threshold before compute(): the rank it fixes decides how many Householder reflections of Z are
  // formed, and solve() must use that same rank.
  cod_.setThreshold(1e-12);
  cod_.compute(WtW_);
}

void DenseRangeSpace::solve(const VectorXd& h, const VectorXd& c, VectorXd& y, VectorXd& lambda,
                            double* load_norm) const {
  const VectorXd h_hat = h + rho_ * (A_.transpose() * c);
  AlignedMatrix v(n_, 1);
  v.map() = h_hat;
  lower_solve(*L_, false, v);
  if (load_norm) *load_norm = v.map().norm();
  const VectorXd rhs = W_->map().transpose() * v.map() - c;
  lambda = cod_.solve(rhs);
  AlignedMatrix dx(n_, 1);
  dx.map() = W_->map() * lambda - v.map();
  lower_solve(*L_, true, dx);
  y = dx.map();
}

VectorXd DenseRangeSpace::project(VectorXd& r) const {
  VectorXd z, nu;
  solve(-r, VectorXd::Zero(m_), z, nu);
  r += A_.transpose() * nu;
  return z;
}

ProjectedCgResult projected_cg(const DenseRangeSpace& factor,
                               const std::function<void(const VectorXd&, VectorXd&)>& multiply, const VectorXd& h,
                               const VectorXd& c, VectorXd& y, VectorXd& lambda, double step_tolerance, int max_iterations) {
  const SparseMatrix& A = factor.constraints();
  const double rho = factor.rho();
  // M' x = K' x + ρ Aᵀ(A x)
  auto apply = [&](const VectorXd& x, VectorXd& out) {
    multiply(x, out);
    out += rho * (A.transpose() * (A * x));
  };
  const VectorXd h_hat = h + rho * (A.transpose() * c);
  ProjectedCgResult res;
  double load_norm = 0.0;
  factor.solve(h, c, y, lambda, &load_norm);
  VectorXd r, q;
  apply(y, r);
  r += h_hat;
  VectorXd z = factor.project(r);
  double rz = r.dot(z);
  VectorXd p = -z;
  while (true) {
    res.relative_residual = std::sqrt(std::max(rz, 0.0)) / std::max(load_norm, 1e-300);
    if (!(rz > 0)) {  // exactly solved (or NaN)
      res.converged = rz == 0;
      break;
    }
    if (res.iterations >= max_iterations) break;
    apply(p, q);
    const double pq = p.dot(q);
    if (!(pq > 0)) break;  // not definite on null(A) (or NaN)
    const double alpha = rz / pq;
    y += alpha * p;
    r += alpha * q;
    ++res.iterations;
    if (!(alpha * p.lpNorm<Eigen::Infinity>() > step_tolerance)) {
      res.converged = std::isfinite(alpha);
      break;
    }
    z = factor.project(r);
    const double rz_new = r.dot(z);
    p = -z + (rz_new / rz) * p;
    rz = rz_new;
  }
  if (!res.converged) return res;
  // The multiplier from the recomputed gradient: Aᵀλ = M'y + ĥ.
  apply(y, r);
  r += h_hat;
  VectorXd unused;
  factor.solve(r, VectorXd::Zero(A.rows()), unused, lambda);
  return res;
}

double step_to_boundary(const VectorXd& v, const VectorXd& dv, double tau) {
  double alpha = 1.0;
  for (Index i = 0; i < v.size(); ++i)
    if (dv[i] < 0) alpha = std::min(alpha, -tau * v[i] / dv[i]);
  return alpha;
}

}  // namespace symcontact
