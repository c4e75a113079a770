#pragma once
/// \file row_updated_factor.hpp
/// Solves with M' = M + Σ_i c_i a_i a_iᵀ from a factor of M, for a few rows a_i: the constraint rows that
/// join (c_i = +ρ) or leave (c_i = −ρ) the set S of a factorised M = H + ρ A_SᵀA_S (active_set_start.hpp),
/// by the Sherman–Morrison–Woodbury identity (Hager, "Updating the inverse of a matrix", SIAM Review 31, 1989):
///     M'⁻¹ r = M⁻¹ r − Z (C⁻¹ + UᵀZ)⁻¹ Uᵀ M⁻¹ r,   U = [a_1 … a_k],  C = diag(c_i),  Z = M⁻¹ U,
/// k solves with the factor to set up and one per solve, instead of a factorisation of M'. For a row that
/// leaves, M holds ρ a aᵀ and C⁻¹ + UᵀZ = −1/(ρ (1 + ρ s)) with s = aᵀ(M − ρ a aᵀ)⁻¹a: the difference of two
/// terms of size 1/ρ loses about log₁₀(1 + ρ s) digits, which the multiplier method's iterations absorb.

#include <Eigen/LU>

#include "symcontact/solvers/spd_factor.hpp"

namespace symcontact {

class RowUpdatedFactor {
 public:
  /// `factor`: of M (must outlive the object); `rows_t`: the a_i as the columns of an n × k matrix; `c`: the c_i.
  RowUpdatedFactor(const SpdFactor& factor, const SparseMatrix& rows_t, const VectorXd& c);
  /// Whether C⁻¹ + UᵀZ is invertible (M' is then nonsingular); solve() is meaningful only then.
  bool valid() const { return valid_; }
  /// M'⁻¹ r.
  VectorXd solve(const VectorXd& r) const;

 private:
  const SpdFactor& factor_;
  SparseMatrix u_t_;  ///< Uᵀ, k × n
  MatrixXd z_;        ///< M⁻¹ U, n × k
  Eigen::FullPivLU<MatrixXd> capacitance_;
  bool valid_ = false;
};

}  // namespace symcontact
