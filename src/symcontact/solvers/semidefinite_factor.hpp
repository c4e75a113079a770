#pragma once
/// \file semidefinite_factor.hpp
/// A dense symmetric positive semidefinite matrix, factorised with symmetric pivoting, and the two things
/// the dual of the condensed contact problem needs from it: a basis of its null space and a generalised
/// inverse.
///
/// LAPACK's dpstrf (Cholesky with complete pivoting; Higham, Accuracy and Stability of Numerical
/// Algorithms, 2nd ed., 2002, §10.3; Lucas, LAPACK Working Note 161, 2004) gives
///     P S Pᵀ = [L₁₁; L₂₁] [L₁₁; L₂₁]ᵀ,   L₁₁ r × r lower triangular,
/// stopping at the first pivot below tol · max diag(S): r is the numerical rank. Then
///  - null(S) is spanned by the columns of Pᵀ [−L₁₁⁻ᵀ L₂₁ᵀ; I] (orthonormalised here): for the Schur
///    complement of a contact problem, the rigid motions of the bodies held by contact alone;
///  - S⁺ = Pᵀ [L₁₁⁻ᵀ L₁₁⁻¹, 0; 0, 0] P is a generalised inverse (S S⁺ S = S), applied in halves:
///    half_solve(R) = L₁₁⁻¹ (P R)₁..ᵣ, so that Rᵀ S⁺ R = half_solve(R)ᵀ half_solve(R), and
///    back_solve(z) = Pᵀ [L₁₁⁻ᵀ z; 0], so that S⁺ R = back_solve(half_solve(R)).
/// For r ∈ range(S), y = S⁺ r solves S y = r (every solution is y + N α).

#include <memory>
#include <vector>

#include "symcontact/core/types.hpp"
#include "symcontact/solvers/dense_kkt.hpp"

namespace symcontact {

class SemidefiniteFactor {
 public:
  /// `s_lower`: S by its lower triangle (entries above the diagonal are ignored). Pivots below
  /// `relative_tolerance` · max diag(S) count as zero. Throws SolveError when S has a negative or
  /// non-finite diagonal, or is zero.
  SemidefiniteFactor(const SparseMatrix& s_lower, double relative_tolerance);

  Index size() const { return n_; }
  Index rank() const { return r_; }
  double max_diagonal() const { return max_diag_; }
  /// n × (n − r), orthonormal columns spanning null(S).
  const MatrixXd& null_basis() const { return null_; }
  /// max |S N| / max |S| over the null basis (0 when S is definite): how null the null space is.
  double null_residual() const { return null_residual_; }

  /// Z = L₁₁⁻¹ (P R)₁..ᵣ for R n × k (Z is r × k).
  std::unique_ptr<AlignedMatrix> half_solve(const MatrixXd& R) const;
  /// The same for a sparse R, scattered straight into Z (no dense n × k copy of R).
  std::unique_ptr<AlignedMatrix> half_solve(const SparseMatrix& R) const;
  /// Pᵀ [L₁₁⁻ᵀ z; 0] for z of size r.
  VectorXd back_solve(const VectorXd& z) const;

 private:
  Index n_ = 0, r_ = 0;
  std::vector<int> piv_;  ///< P: row k of P S Pᵀ is row piv_[k] of S (0-based)
  std::unique_ptr<AlignedMatrix> l11_;
  MatrixXd null_;
  double null_residual_ = 0.0;
  double max_diag_ = 0.0;
};

}  // namespace symcontact
