#pragma once
/// \file semidefinite_factor.hpp
/// A dense symmetric positive semidefinite matrix, factorised with symmetric pivoting, and the two things
/// the dual of the condensed contact problem needs from it: a basis of its null space and a generalised
/// inverse, formed explicitly.
///
/// LAPACK's dpstrf (Cholesky with complete pivoting; Higham, Accuracy and Stability of Numerical
/// Algorithms, 2nd ed., 2002, §10.3; Lucas, LAPACK Working Note 161, 2004) gives
///     P S Pᵀ = [L₁₁; L₂₁] [L₁₁; L₂₁]ᵀ,   L₁₁ r × r lower triangular,
/// stopping at the first pivot below tol · max diag(S): r is the numerical rank. Then
///  - null(S) is spanned by the columns of Pᵀ [−L₁₁⁻ᵀ L₂₁ᵀ; I] (orthonormalised here): for the Schur
///    complement of a contact problem, the rigid motions of the bodies held by contact alone;
///  - S⁺ = Pᵀ [C₁₁, 0; 0, 0] P with C₁₁ = (L₁₁ L₁₁ᵀ)⁻¹ is a generalised inverse (S S⁺ S = S).
/// For r ∈ range(S), y = S⁺ r solves S y = r (every solution is y + N α).
///
/// C₁₁ is formed once, in place of L₁₁ (LAPACK dpotri, 2r³/3 flops), because the dual needs Rᵀ S⁺ R for a
/// new sparse R (the contact rows, m of them) at every geometry iteration: through the explicit inverse that
/// costs O(nnz(R) · (r + m)), where triangular solves with L₁₁ cost r² m + r m² flops each time (with
/// m ≈ r/3, a 3D face in contact, the inverse pays from the second set of rows). Products with the explicit
/// inverse are not backward stable, but their forward error is of the order cond(S₁₁) u, as that of the
/// triangular solves (Higham, ch. 14); the dual's answer is checked against the primal in the unit tests.

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

  /// S⁺ r for r of size n.
  VectorXd solve(const VectorXd& r) const;
  /// Rᵀ S⁺ R for a sparse R (n × k), k × k, both triangles.
  /// O(nnz(R) · (r + k)) flops; deterministic (no threads, a fixed order of sums).
  std::unique_ptr<AlignedMatrix> gram(const SparseMatrix& R) const;

 private:
  Index n_ = 0, r_ = 0;
  std::vector<int> piv_;  ///< P: row k of P S Pᵀ is row piv_[k] of S (0-based)
  std::unique_ptr<AlignedMatrix> c11_;  ///< C₁₁ = (L₁₁ L₁₁ᵀ)⁻¹, r × r, both triangles
  MatrixXd null_;
  double null_residual_ = 0.0;
  double max_diag_ = 0.0;
};

}  // namespace symcontact
