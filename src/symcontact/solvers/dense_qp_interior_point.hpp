#pragma once
/// \file dense_qp_interior_point.hpp
/// A primal-dual interior point method for the dense convex quadratic program with simple bounds and a few
/// equality rows,
///
///     min_x  ½ xᵀW x − dᵀx   subject to   x ≥ 0,   G x = e,
///
/// W m × m symmetric positive SEMIdefinite (its lower triangle is read), G k × m with k small (k ≪ m). This is
/// the dual of the frictionless condensed contact problem (dual_condensed_problem.hpp), which IPOPT solves as
/// a sparse problem with a dense Hessian: MUMPS then factorises the m × m matrix as if it were sparse, more
/// slowly than LAPACK's dense Cholesky and with a workspace of ~10 m² doubles. Here each iteration is one
/// dense Cholesky factorisation (dpotrf, m³/3) and four triangular solves; the memory is W and one m × m
/// factor.
///
/// Optimality (KKT): r_d = W x − d − Gᵀβ − z = 0, r_p = G x − e = 0, x ∘ z = 0, x ≥ 0, z ≥ 0.
/// Newton on the perturbed conditions x ∘ z = σμ, with X = diag(x), Z = diag(z), eliminates Δz:
///     H Δx − Gᵀ Δβ = −r_d − X⁻¹ r_c =: f,    G Δx = −r_p =: g,    Δz = −X⁻¹ (r_c + Z Δx),
///     H = W + X⁻¹ Z (definite: X⁻¹Z > 0),  r_c = x ∘ z − σμ 1,
/// solved by the range-space method with H = L Lᵀ: Y = L⁻¹Gᵀ, v = L⁻¹f, (YᵀY) Δβ = g − Yᵀv, Δx = L⁻ᵀ(v + YΔβ)
/// (Nocedal & Wright, Numerical Optimization, 2nd ed. 2006, §16.2; k × k system by a complete orthogonal
/// decomposition, so a rigid motion no row sees — a zero row of G, e = 0 — does no harm).
/// Steps: Mehrotra's predictor-corrector (Mehrotra, SIAM J. Optim. 2, 1992; for QP as in Nocedal & Wright
/// Algorithm 16.4 and Gertz & Wright's OOQP, ACM TOMS 29, 2003): an affine step (σ = 0), σ = (μ_aff / μ)³, a
/// corrector with r_c = x ∘ z + Δx_aff ∘ Δz_aff − σμ 1, both with the same factor; one step length for x and
/// z (the quadratic couples them), the fraction to the boundary τ = 1 − μ/μ₀ kept in [0.99, 1 − 1e-10].
///
/// Stops when ‖r_d‖∞ ≤ tol · s_d, ‖r_p‖∞ ≤ tol · s_p and μ = xᵀz / m ≤ tol_μ · s_d · max(1, ‖x‖∞), with the
/// scales s_d = ‖d‖∞ (max diag W if d = 0) and s_p = ‖e‖∞ (1 if e = 0): relative, so that scaling W, d and z
/// together changes nothing (x is expected to be O(1), as DualCondensedProblem's scaling makes it); fails (success false, with the reason) after max_iterations, on a
/// factorisation that breaks down twice (the second with a diagonal shift of 1e-14 · max diag W), or on a
/// non-finite iterate. Never reports a point that does not pass the test as success.

#include <string>

#include "symcontact/core/types.hpp"
#include "symcontact/solvers/dense_kkt.hpp"

namespace symcontact {

struct DenseQpOptions {
  double tolerance = 1e-10;                  ///< of the residuals r_d and r_p
  /// Of μ. Far below `tolerance` because the contact solver reads the active set off the point (the closing
  /// of DualCondensedProblem): a closed row with a small λ_i — the two families of a symmetric pair share
  /// the load — stays open by μ / λ_i. On the inclined interface (symmetric pair, h = 0.1), with μ stopped
  /// at 1e-10 or 1e-14 the closing starts from 22 rows, cycles and is dropped, and the geometry fixed point
  /// stalls at a change of 4e-6; at 1e-16 it starts from IPOPT's 18 rows, closes in one round and the
  /// fixed point converges as with IPOPT. Mehrotra's method converges superlinearly, so this costs 2 to 4
  /// iterations per solve, and the closing that follows needs fewer rounds.
  double complementarity_tolerance = 1e-16;
  int max_iterations = 100;
};

struct DenseQpResult {
  bool success = false;
  std::string status;  ///< "converged", or why not
  int iterations = 0;
  VectorXd x;          ///< the solution (x ≥ 0, strictly: interior point)
  VectorXd z;          ///< the bounds' multipliers, z = W x − d − Gᵀβ ≥ 0
  VectorXd beta;       ///< the equality rows' multipliers (W x − d − Gᵀβ − z = 0)
};

/// Solves the problem above. `W_lower`: m × m, lower triangle read; `G`: k × m (k may be 0); `e`: size k.
/// `x0`, `z0` (both or neither; positive entries are used, others are lifted) and `beta0` start the iteration
/// (a warm start); without them it starts at x = 1, z = ‖W 1 − d‖∞ 1, β = 0.
DenseQpResult solve_dense_qp(const AlignedMatrix& W_lower, const VectorXd& d, const MatrixXd& G, const VectorXd& e,
                             const DenseQpOptions& options, const VectorXd* x0 = nullptr, const VectorXd* z0 = nullptr,
                             const VectorXd* beta0 = nullptr);

}  // namespace symcontact
