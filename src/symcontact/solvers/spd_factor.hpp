#pragma once
/// \file spd_factor.hpp
/// M = L Lᵀ for the active-set polish (equality_constrained_solve.hpp), with M = H + ρ A_Sᵀ A_S symmetric
/// positive definite. A sparse M goes to CHOLMOD. A dense one — the condensed problem, whose Schur complement
/// fills its |B| × |B| Hessian (ConstrainedProblem::hessian_is_dense()) — goes to LAPACK's dpotrf (OpenBLAS
/// here), which also leaves the triangular factor for the multi-column (BLAS-3) range-space solve of
/// DenseRangeSpace (dense_kkt.hpp); CHOLMOD's supernodal factor of a full matrix is the same algorithm, but
/// its solves come one column at a time.

#include <memory>

#include "symcontact/solvers/cholesky.hpp"
#include "symcontact/solvers/dense_kkt.hpp"

namespace symcontact {

class SpdFactor {
 public:
  explicit SpdFactor(bool dense) : dense_(dense) {}
  /// Factorises M = H + ρ AtA from their lower triangles (`dense_h`: H as a dense matrix, the dense path, where
  /// `h` is not read; `h`: H sparse, the sparse one; AtA null: M = H); false when M is not (numerically)
  /// positive definite.
  bool compute(const SparseMatrix& h, const AlignedMatrix* dense_h, const SparseMatrix* AtA, double rho);
  /// M⁻¹ b.
  VectorXd solve(const VectorXd& b) const;
  bool dense() const { return dense_; }
  int size() const { return n_; }
  /// L of M = L Lᵀ in its lower triangle (only when dense()).
  std::shared_ptr<const AlignedMatrix> dense_factor() const { return factor_; }

 private:
  bool dense_;
  int n_ = 0;
  CholeskySolver sparse_;
  std::shared_ptr<AlignedMatrix> factor_;
};

}  // namespace symcontact
