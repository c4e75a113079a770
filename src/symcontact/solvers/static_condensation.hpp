#pragma once
/// \file static_condensation.hpp
/// The Schur complement of a sparse symmetric positive definite matrix onto a small set of indices,
/// from ONE sparse Cholesky factorisation.
///
/// Split the indices into the boundary set B (in contact: the DOFs the constraints and friction touch)
/// and the interior I. Then
///
///     K = [K_II  K_IB]        S = K_BB − K_BI K_II⁻¹ K_IB   (dense |B| × |B|).
///         [K_BI  K_BB],
///
/// CHOLMOD factorises K̃ = K + diag(0, D) with the interior ordered first (CHOLMOD's own fill-reducing
/// ordering of K_II) and B last, so that its factor has the block form
///
///     L = [L_II   0  ]   with   L_II L_IIᵀ = K_II,   L_BI = K_BI L_II⁻ᵀ,   L_BB L_BBᵀ = S + D,
///         [L_BI  L_BB]
///
/// and S is read off the trailing block (the classical partial-factorisation view of the Schur
/// complement; e.g. Saad, Iterative Methods for Sparse Linear Systems, 2003, §14.2). D = diag(K_BB)
/// keeps K̃ definite when K itself is only semi-definite — a body held by contact alone, whose rigid
/// motions S carries as (near-)zero eigenvalues — and is subtracted again. The same factor also
/// solves with K_II alone: L y = P r, y_B ← 0, Lᵀ z = y gives z_I = K_II⁻¹ r_I and z_B = 0.
///
/// Cost: one symbolic analysis of K_II (ordering), one of K̃ with that ordering, one numeric
/// factorisation — about one "Cholesky floor" plus |B|³/3 flops for the dense trailing block.
///
/// Contract: `lower` is the lower triangle (compressed, column-major) of K with every diagonal entry
/// stored; B is a set of distinct indices in [0, n). compute() throws SolveError when K_II is not
/// positive definite (a body with neither Dirichlet conditions nor enough points in B) or when CHOLMOD
/// fails (out of memory). CHOLMOD is called through its 64-bit interface (cholmod_long.hpp), so the factor
/// has no 2³¹-entry limit.
///
/// Memory: the factor of K̃ (8 bytes per entry of L, about the Cholesky floor's) plus, for S, two dense
/// |B| × |B| arrays while it is formed and its lower triangle afterwards (12 bytes per entry, about
/// 6 |B|² bytes): 1.5 GiB at |B| = 10,000 during compute(), 0.56 GiB kept.

#include <memory>
#include <vector>

#include "symcontact/core/types.hpp"

namespace symcontact {

class StaticCondensation {
 public:
  StaticCondensation();
  ~StaticCondensation();
  StaticCondensation(const StaticCondensation&) = delete;
  StaticCondensation& operator=(const StaticCondensation&) = delete;

  /// Factorises K with `boundary` last and forms S. Replaces any previous state.
  void compute(const SparseMatrix& lower, std::vector<Index> boundary);

  bool empty() const;
  Index size() const;                               ///< n
  const std::vector<Index>& boundary() const;       ///< B, sorted increasingly (the order of S)
  /// position of index k in B, or −1 (size n)
  const std::vector<Index>& boundary_position() const;
  /// K itself (the lower triangle given to compute()).
  const SparseMatrix& matrix() const;
  /// S, lower triangle, exact zeros dropped (bodies that share no interior give zero blocks).
  const SparseMatrix& schur_lower() const;
  /// z with z_I = K_II⁻¹ r_I and z_B = 0 (r of size n; its B entries are ignored).
  VectorXd solve_interior(const VectorXd& r) const;
  /// z with z_I = −K_II⁻¹ K_IB x_B and z_B = 0 (x of size n; only its B entries are read): the interior's
  /// response to the boundary values, by ONE triangular solve instead of solve_interior()'s two. With the
  /// factor of K̃ (B last), K_IB = L_II L_BIᵀ, so K_II⁻¹ K_IB x_B = L_II⁻ᵀ L_BIᵀ x_B: the backward solve on the
  /// interior columns with x_B in B's place. Both solves read the interior supernodes only, not L_BB.
  VectorXd boundary_response(const VectorXd& x) const;
  /// Number of nonzeros of the factor of K̃ (fill, for reports).
  double factor_nonzeros() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace symcontact
