#pragma once
/// \file active_set_polish.hpp
/// Removes the barrier offset an interior point method leaves at a solution.
///
/// IPOPT stops at a barrier parameter μ_b > 0, where every active constraint is still open by
/// c_i ≈ μ_b / μ_i. In the symmetric contact formulation the two constraint families are nearly
/// dependent, some multipliers μ_i are small, and the interface stays open by far more than the
/// tolerance suggests. Given IPOPT's solution and multipliers, the polish takes the active set
/// S = {i : μ_i > 1e-6 max μ} and solves the equality-constrained problem
///     min f(x)  subject to  A_S x + b_S = 0
/// (equality_constrained_solve.hpp: Newton steps on f, one for a quadratic f, each solved directly in the
/// range space of the KKT system, with minimum-norm multipliers on dependent rows; where that leaves rows of
/// a final set unclosed (inconsistent rows), by the method of multipliers, which converges whatever the rank
/// of A_S: dependent rows get some split of the multiplier; A_Sᵀμ_S, the contact force, is unique). With no
/// active constraint it is plain Newton on f (removing the optimiser's stationarity error). The polished point
/// is accepted only if it is a KKT point of the inequality problem: μ_S ≥ 0 (up to round-off) and no other
/// constraint violated; otherwise the IPOPT point is kept.

#include "symcontact/optim/constrained_problem.hpp"

namespace symcontact {

struct PolishResult {
  bool applied = false;      ///< false: x and μ unchanged (rejected, see reason)
  int iterations = 0;
  int active = 0;            ///< |S|
  double max_violation = 0;  ///< max_i max(0, −c_i(x)) after the polish, in the scaled units of the rows
  std::string reason;        ///< why it was not applied
};

/// What the polish does with the active rows S.
enum class PolishMode {
  kClose,          ///< A_S x + b_S = 0: the barrier offset removed (a KKT point of the inequality problem, or rejected)
  /// A_S x + b_S = c_S(x_IPOPT): the active constraints keep the values the optimiser left. That always
  /// consistent variant only removes the optimiser's stationarity error (exact force balance), for when the
  /// families of a curved symmetric pair cannot all be closed at once.
  kBalanceForces,
};

/// x and mu (μ ≥ 0 convention, one per constraint row) are updated in place when the polish is accepted.
PolishResult polish_active_set(ConstrainedProblem& problem, VectorXd& x, VectorXd& mu,
                               PolishMode mode = PolishMode::kClose);

}  // namespace symcontact
