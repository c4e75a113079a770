#pragma once
/// \file equilibrium_solver.hpp
/// Minimises an energy E(u) without contact constraints, with Dirichlet DOFs fixed, by Newton's
/// method on the free DOFs: K_ff Δu_f = −g_f(u), K = ∇²E, g = ∇E, each linear system solved by sparse
/// Cholesky. A quadratic energy (linear elasticity) converges in one step; the loop stops when
/// ‖g_f‖ ≤ tolerance · max(‖f_ext‖, ‖g_f(u0)‖, the largest reaction norm ‖g_D‖ met, the largest
/// ‖K_fD Δu_D‖ of a Dirichlet increment below) or after max_iterations (then SolveError).
///
/// A non-quadratic energy (hyperelasticity) is globalised (Nocedal & Wright, Numerical Optimization,
/// 2006, §3.1 and §3.4):
///  - the step u + s Δu is backtracked (s = 1, ½, ¼, …) until it is admissible (no EvaluationError,
///    e.g. no inverted element) and decreases E by the Armijo rule E(u + sΔu) ≤ E(u) + c s gᵀΔu,
///    c = 1e-4 — or, near convergence where E no longer resolves the decrease in double precision,
///    decreases ‖g_f‖ by the same factor (1 − c s);
///  - when K_ff is not positive definite (past a buckling or an unstable state), K_ff + τ I is
///    factorised instead, τ = 1e-8·max diag(K_ff), multiplied by 10 until the factorisation succeeds
///    (the modified Newton of §3.4), which makes Δu a descent direction;
///  - the new Dirichlet values are not imposed at once (a jump of the boundary nodes alone would
///    invert the cells next to them): while fixed DOFs are short of their values by Δu_D, the Newton
///    step carries that jump and the free DOFs follow it linearly, K_ff Δu_f = −g_f − K_fD Δu_D, and
///    the step is only backtracked to admissibility (E is no merit function while the boundary moves);
///    a shortened step leaves the rest of the jump to the next iteration (automatic sub-stepping).

#include "symcontact/core/timer.hpp"
#include "symcontact/core/types.hpp"
#include "symcontact/energy/energy_term.hpp"
#include "symcontact/solvers/fixed_dofs.hpp"

namespace symcontact {

struct EquilibriumOptions {
  int max_iterations = 50;
  double tolerance = 1e-12;  ///< relative residual norm
  int max_backtracks = 30;   ///< halvings of one Newton step before giving up
};

struct EquilibriumReport {
  int iterations = 0;        ///< Newton iterations (linear solves)
  int backtracks = 0;        ///< step halvings of the line search, all iterations
  int shifted_factorizations = 0;  ///< factorisations of K_ff + τ I (K_ff not positive definite)
  double residual = 0.0;     ///< final ‖g_f‖
  double residual0 = 0.0;    ///< initial ‖g_f‖
  Index num_free = 0;
  double factor_nonzeros = 0.0;
  PhaseTimes times;          ///< "assembly", "factorization", "solve"
};

/// On entry u holds the starting guess (for a quadratic energy its fixed DOFs are overwritten by
/// `fixed`; otherwise they are moved there as above); on exit the minimiser. Throws SolveError on a
/// singular stiffness or when Newton does not converge.
EquilibriumReport solve_equilibrium(const EnergyTerm& energy, const FixedDofs& fixed, VectorXd& u,
                                    const EquilibriumOptions& options = {});

/// The linearised response to new Dirichlet values, for solvers that impose them at once (the contact
/// solver): with Δu_D = fixed values − u_D, solves K_ff Δu_f = −K_fD Δu_D at u (K = ∇²E, the forces
/// ∇E(u) held as they are — at a converged state they balance the contact forces) and moves u to
/// u + s Δu with the largest s ∈ {1, ½, ¼, …} at which E can be evaluated. Returns s (0 when even
/// a tiny step cannot be evaluated; u is then unchanged). A quadratic energy needs no predictor:
/// the function then only imposes the values and returns 1. The caller imposes the values afterwards
/// if s < 1.
double predict_dirichlet_increment(const EnergyTerm& energy, const FixedDofs& fixed, VectorXd& u);

}  // namespace symcontact
