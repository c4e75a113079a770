#include "symcontact/solvers/spd_factor.hpp"

#include "symcontact/core/error.hpp"

// BLAS and LAPACK (Fortran interfaces; column-major, every argument by address).
extern "C" {
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
void dtrsv_(const char* uplo, const char* trans, const char* diag, const int* n, const double* a, const int* lda,
            double* x, const int* incx);
}

namespace symcontact {

bool SpdFactor::compute(const SparseMatrix& h, const AlignedMatrix* dense_h, const SparseMatrix* AtA, double rho) {
  if (!dense_) {
    try {
      sparse_.compute(AtA ? SparseMatrix(h + rho * *AtA) : h);
      return true;
    } catch (const SolveError&) {
      return false;
    }
  }
  n_ = static_cast<int>(dense_h->rows());
  factor_ = std::make_shared<AlignedMatrix>(n_, n_);
  auto m = factor_->map();
  m = dense_h->map();
  if (AtA)
    for (int j = 0; j < AtA->outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(*AtA, j); it; ++it) m(it.row(), j) += rho * it.value();
  int info = 0;
  dpotrf_("L", &n_, factor_->data(), &n_, &info);
  return info == 0;
}

VectorXd SpdFactor::solve(const VectorXd& b) const {
  if (!dense_) return sparse_.solve(b);
  AlignedMatrix x(n_, 1);
  x.map() = b;
  const int inc = 1;
  dtrsv_("L", "N", "N", &n_, factor_->data(), &n_, x.data(), &inc);
  dtrsv_("L", "T", "N", &n_, factor_->data(), &n_, x.data(), &inc);
  return x.map();
}

}  // namespace symcontact
