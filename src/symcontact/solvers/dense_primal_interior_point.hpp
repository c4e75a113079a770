#pragma once
/// \file dense_primal_interior_point.hpp
/// A primal-dual interior point method for a convex problem with a dense Hessian and linear inequalities,
///
///     min_x f(x)   subject to   c(x) = A x + b ≥ 0,
///
/// f twice differentiable and convex, A sparse p × m. Where ∇²f is dense (ConstrainedProblem::hessian_is_dense():
/// the condensed frictional contact problem, the Schur complement S plus the friction term's node blocks,
/// condensed_problem.hpp) an iteration is one LAPACK Cholesky factorisation of the m × m normal matrix and a few
/// triangular solves, where IPOPT's MUMPS factorises the dense KKT matrix as a sparse one; where it is sparse
/// (the uncondensed problem of linear-elastic bodies: K_ff plus the friction blocks) one CHOLMOD factorisation,
/// the ordering and symbolic analysis made once per solve.
///
/// With slacks s = c(x) and multipliers λ (∇f(x) = Aᵀλ at a solution), the perturbed KKT conditions
///     r_d = ∇f(x) − Aᵀλ = 0,   r_p = A x + b − s = 0,   s ∘ λ = σμ 1,   s, λ > 0,
/// linearised, give with D = diag(λ / s) and r_c = s ∘ λ − σμ 1 (Nocedal & Wright, Numerical Optimization, 2nd
/// ed. 2006, §19.1 and §16.6, normal equations):
///     (∇²f + Aᵀ D A) Δx = −r_d − Aᵀ S⁻¹ (r_c + Λ r_p),   Δs = A Δx + r_p,   Δλ = −S⁻¹ (r_c + Λ Δs).
/// Steps: Mehrotra's predictor-corrector (σ = (μ_aff/μ)³, the corrector with Δs_aff ∘ Δλ_aff; its target σμ
/// not below tolerance/10 before the stopping test is met, as IPOPT's barrier parameter), one step length
/// for s and λ to the fraction τ = max(0.99, 1 − μ) of the boundary, then — f not being quadratic — a
/// backtracking line search on the norm of the residuals (r_d, r_p, s ∘ λ − σμ) at the step's target: halved
/// until that norm falls by 1e-4 α of itself (Armijo on ½‖F‖², whose derivative along a Newton direction is
/// −‖F‖²). A convex f makes the normal matrix positive semidefinite; a Cholesky that breaks down is retried once
/// with a diagonal shift of 1e-12 × its largest diagonal entry.
///
/// Scaling: the problem is solved in the dimensionless variables of IPOPT's user scaling (ipopt_solver.hpp:
/// x̃ = x/ℓ, f̃ = f/(g_ref ℓ), row i of c divided by ℓ max_j |A_ij|), so that `tolerance` is the same number as
/// IPOPT's `tol` and the method is unchanged by a consistent change of units. It stops when the scaled
/// stationarity, feasibility and complementarity (max_i s̃_i λ̃_i) are all at most `tolerance`; it fails
/// (success false, with the reason) after max_iterations, on a line search that cannot reduce the residual, on
/// a factorisation that breaks down twice, or on an f that cannot be evaluated. It never reports a point that
/// does not pass that test as a success.

#include <algorithm>
#include <functional>
#include <string>

#include "symcontact/optim/constrained_problem.hpp"
#include "symcontact/optim/ipopt_solver.hpp"

namespace symcontact {

struct DensePrimalOptions {
  double tolerance = 1e-10;  ///< of the scaled residuals (as IPOPT's `tol`)
  int max_iterations = 200;
  /// The scaled error below which a FollowIterate is called after each step. Followed from 0.1, the Coulomb
  /// thresholds of the pads of docs/performance.md took up to 40 % fewer iterations than from 1e-3 or 1e-2
  /// (none fewer on the 3D pad on a ball).
  double follow_below = 0.1;
  /// follow_below for a solve whose followed data start at the fixed point of a nearby problem (a later
  /// geometry iteration: the same thresholds, the rows moved a little). Followed from 0.1, each change of the
  /// data re-opens r_d in proportion to the step's change of λ and the method converges linearly, μ tenfold per
  /// iteration; followed near the end it converges first and adjusts the data once or twice (the 3D pad on a
  /// ball of docs/performance.md: 210 → 187 iterations at 4e3 DOFs). Not closer to the tolerance than 1e-8: a
  /// change of the data once μ has collapsed can leave the line search at the round-off floor.
  static double follow_below_near_fixed_point(double tolerance) { return std::max(1e-8, 10.0 * tolerance); }
};

/// Data of f that follow the iterate (the Coulomb thresholds τ = μ p of a friction term, p read from the
/// multipliers): called with x and λ (the problem's units) after each accepted step once the scaled error is at most `DensePrimalOptions::follow_below`, and at a
/// point that passes the stopping test. It may change f (not A, b) and returns whether it did; the method
/// then re-evaluates the residuals at the same iterate and stops only at a point where it returned false.
/// It must return false after finitely many calls (FollowedData).
using FollowIterate = std::function<bool(const VectorXd& x, const VectorXd& multipliers)>;

/// Solves `problem` (no equality rows, no bounds: throws std::invalid_argument otherwise) from x0; a warm start
/// when `multipliers0` (size p, λ ≥ 0) is given. The result is in IpoptResult's form (multipliers λ with
/// ∇f = Aᵀλ, constraint values c(x), status_text "converged" or why not) so that it takes IPOPT's place.
/// `follow`: data of f updated between iterations (null: f is fixed).
IpoptResult solve_dense_primal(ConstrainedProblem& problem, const VectorXd& x0, const DensePrimalOptions& options,
                               const VectorXd* multipliers0 = nullptr, const FollowIterate* follow = nullptr);

/// The scales solve_dense_primal takes from its start x0 (problem_scales at x0). Throws EvaluationError where f
/// cannot be evaluated at x0.
ProblemScales dense_primal_scales(ConstrainedProblem& problem, const VectorXd& x0);

/// The error of solve_dense_primal's stopping test, in its scaled variables (`scales`, from its start), at x
/// with multipliers λ ≥ 0 (the problem's units) and slacks s = max(c(x), 0): max(‖r_d‖∞, ‖c̃ − s̃‖∞, max s̃ ∘ λ̃).
/// A point found otherwise (active_set_start.hpp) whose error is within the tolerance is one the interior
/// point would have accepted.
double dense_primal_error(ConstrainedProblem& problem, const ProblemScales& scales, const VectorXd& x,
                          const VectorXd& multipliers);

}  // namespace symcontact
