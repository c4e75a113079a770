#pragma once
/// \file subproblem.hpp
/// The optimisation step of one geometry iteration (Algorithm 2 of METHOD.md): with the contact constraints
/// linearised at U_n,
///     U_{n+1} = argmin E(U)  subject to  A_n U + b_n ≥ 0,
/// and its multipliers μ ≥ 0 (one per row). A SubproblemMethod is one way of solving it; the geometry fixed
/// point (geometry_subproblem.hpp) chooses one per iteration and stays unaware of how it works:
///  - PrimalIpopt (primal_subproblem.hpp): IPOPT on the displacements, condensed or not; any energy.
///  - PrimalInteriorPoint (primal_subproblem.hpp): the primal interior point on condensed displacements (a dense
///    Hessian) or on the whole displacements of linear-elastic bodies (a sparse one), friction terms too;
///    PrimalIpopt where it fails.
///  - DualIpopt, DualInteriorPoint (dual_subproblem.hpp): the dual in the multipliers of a condensed
///    quadratic problem, by IPOPT or by the dense interior point; the displacements follow exactly.

#include <functional>

#include "symcontact/core/log.hpp"
#include "symcontact/core/timer.hpp"
#include "symcontact/optim/ipopt_solver.hpp"

namespace symcontact {

class CondensedProblem;
class SemidefiniteFactor;

/// One geometry iteration's problem, as the optimiser sees it.
struct Subproblem {
  ConstrainedProblem& target;          ///< the condensed problem, or the whole reduced one
  const CondensedProblem* condensed;   ///< target as a condensed problem (null when not condensed)
  const SemidefiniteFactor* schur;     ///< the pivoted factor of S for the dual (null: no dual)
  const VectorXd& start;               ///< the current geometry iterate, in target's variables
  int geometry_iteration;              ///< 1, 2, … within the solve
  const IpoptOptions& ipopt;           ///< the optimiser settings (IPOPT's; the interior point reads `tol`)
  bool close_active_set;               ///< close the active set exactly where the method does it itself (dual)
  /// The bodies' energy is quadratic (linear elasticity; friction terms aside), so that an uncondensed target is
  /// convex with a sparse Hessian of fixed pattern: the primal interior point takes it too, on CHOLMOD.
  bool quadratic_bodies;
  /// Another start to retry from when the solve fails from `start` (the primal with friction); empty: none.
  std::function<VectorXd()> restart;
  /// Data of the objective that follow the optimiser's iterate (Coulomb thresholds), for an optimiser that
  /// takes them (dense_primal_interior_point.hpp, FollowIterate); empty: none.
  std::function<bool(const VectorXd& x, const VectorXd& multipliers)> follow;
};

/// The previous solution's multipliers when this iteration's constraint rows are the same rows (same
/// families, same nodes) as theirs; null otherwise.
struct SubproblemWarmStart {
  /// The previous solve's multipliers, on the same rows: they start every method.
  const VectorXd* multipliers = nullptr;
  /// Where the rows changed since (the edge of a zone entering or leaving the search distance), the previous
  /// multipliers carried to these rows by family and node, 0 on a new row (values_on_rows()): the start set of
  /// the primal's active-set Newton only, whose own checks keep it from a wrong set; the interior points and
  /// IPOPT start cold then.
  const VectorXd* carried = nullptr;
};

struct SubproblemSolution {
  /// x in target's variables, μ ≥ 0 per row, c(x) = A x + b; `success` false when every attempt failed.
  IpoptResult result;
  int failed_iterations = 0;  ///< optimiser iterations of failed attempts before `result`
  /// The method closed the active set exactly (close_active_set): the dual's polish, or the primal's active-set
  /// start (active_set_start.hpp), whose point is exact on its set and stationary to round-off.
  bool closed = false;
  /// close_active_set was asked and the closing was not applied (why, for the log); empty otherwise.
  std::string closing_failure;
};

class SubproblemMethod {
 public:
  virtual ~SubproblemMethod() = default;
  /// One subproblem, logged at `log`'s detail level when an attempt fails, timed into `times`.
  virtual SubproblemSolution solve(const Subproblem& p, const SubproblemWarmStart& warm, const Logger& log,
                                   PhaseTimes& times) = 0;
};

}  // namespace symcontact
