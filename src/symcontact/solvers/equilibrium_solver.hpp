#pragma once
/// \file equilibrium_solver.hpp
/// Minimises an energy E(u) without contact constraints, with Dirichlet DOFs fixed, by Newton's
/// method on the free DOFs: K_ff Δu_f = −g_f(u), K = ∇²E, g = ∇E, each linear system solved by sparse
/// Cholesky. A quadratic energy (linear elasticity) converges in one step; the loop stops when
/// ‖g_f‖ ≤ tolerance · max(‖f_ext‖, ‖g_f(u0)‖) or after max_iterations (then SolveError).

#include "symcontact/core/timer.hpp"
#include "symcontact/core/types.hpp"
#include "symcontact/energy/energy_term.hpp"
#include "symcontact/solvers/fixed_dofs.hpp"

namespace symcontact {

struct EquilibriumOptions {
  int max_iterations = 25;
  double tolerance = 1e-12;  ///< relative residual norm
};

struct EquilibriumReport {
  int iterations = 0;        ///< Newton iterations (linear solves)
  double residual = 0.0;     ///< final ‖g_f‖
  double residual0 = 0.0;    ///< initial ‖g_f‖
  Index num_free = 0;
  double factor_nonzeros = 0.0;
  PhaseTimes times;          ///< "assembly", "factorization", "solve"
};

/// On entry u holds the starting guess (its fixed DOFs are overwritten by `fixed`); on exit the
/// minimiser. Throws SolveError on a singular stiffness or when Newton does not converge.
EquilibriumReport solve_equilibrium(const EnergyTerm& energy, const FixedDofs& fixed, VectorXd& u,
                                    const EquilibriumOptions& options = {});

}  // namespace symcontact
