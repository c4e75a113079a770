#pragma once
/// \file active_set_start.hpp
/// A warm-started subproblem  min f(x) s.t. c(x) = A x + b ≥ 0  (f convex) solved from its predicted active
/// set, before any interior point.
///
/// Between load steps and geometry iterations the active set changes little, yet an interior point started
/// at the previous solution takes 10–25 iterations (its slacks and multipliers must leave the boundary and
/// come back to it), each a dense factorisation. The primal-dual active set strategy (Hintermüller, Ito &
/// Kunisch, SIAM J. Optim. 13, 2003) from the previous solution's set costs about one factorisation per change
/// of the set instead:
///  1. S = the rows with a positive warm multiplier (above 1e-6 of the largest) and the rows violated at x0;
///  2. Newton on  min f  subject to  c_S(x) = 0: each step the range-space solve of its KKT system
///     (dense_kkt.hpp), by a new factorisation of ∇²f + ρ A_SᵀA_S or, where only the friction blocks of ∇²f
///     changed since the last one, by projected CG preconditioned with it (O(m²) an iteration); with a sparse
///     ∇²f (the uncondensed problem), the method of multipliers on CHOLMOD's factor of the same matrix, kept
///     for the later steps while they are small and still fall (a modified Newton method); an Armijo line
///     search on f for steps above 1e-6 of max|x|;
///  3. data of f that follow the iterate (the Coulomb thresholds, FollowIterate) are set after each Newton
///     step below a tenth of max|x|, and Newton goes on until its step is at round-off and they no longer
///     change;
///  4. rows of S with a negative multiplier leave it and rows the point violates join it — as soon as a
///     whole step below a tenth of max|x| finds such rows, not only once Newton has converged on S; 2–4 again
///     until S settles.
/// Newton on f's regularised friction term from a start far from its solution can fail to converge within
/// step 2's budget, which then ends the attempt. The point is returned as a success only where it passes
/// the dense interior point's own stopping test (dense_primal_error, in the scales of the same start): it is
/// then a point that the interior point could have returned, and — f strictly convex on the condensed DOFs —
/// the same solution up to the tolerance. Otherwise the caller solves by the interior point.

#include "symcontact/solvers/dense_primal_interior_point.hpp"

namespace symcontact {

struct ActiveSetStartOptions {
  double tolerance = 1e-10;   ///< of the stopping test (DensePrimalOptions::tolerance)
  int max_set_rounds = 20;    ///< changes of S before the attempt is given up (step 4 changes it at small steps too)
  int max_newton_steps = 100;  ///< Newton steps on one S, followed data included
  int max_follows = 100;       ///< changes of the followed data; then the point stands for the data it has
};

/// From x0 with the previous solution's multipliers (size p, μ ≥ 0). The result is in IpoptResult's form
/// (iterations: Newton steps on every S; status_text "converged (active set: N factorisations)" or why not).
IpoptResult solve_from_active_set(ConstrainedProblem& problem, const VectorXd& x0, const VectorXd& multipliers0,
                                  const ActiveSetStartOptions& options, const FollowIterate* follow = nullptr);

}  // namespace symcontact
