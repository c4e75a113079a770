#pragma once
/// \file primal_subproblem.hpp
/// The subproblem solved by IPOPT on the displacements (the reference formulation; any energy).
/// Warm-started from the previous rows' multipliers when the rows are the same; a Restoration_Failed (a
/// line search that fails at an iterate already feasible) resumes once from that iterate; a warm start that
/// fails on the first geometry iteration (its multipliers come from another solve) is retried cold, and a
/// failure with friction once more from Subproblem::restart (stiff regularised friction, small α, can defeat
/// the line search from a start that is already close).
/// PrimalInteriorPoint solves a condensed subproblem (a dense Hessian), or the uncondensed one of linear-elastic
/// bodies (Subproblem::quadratic_bodies: a sparse Hessian on CHOLMOD), by the primal interior point first
/// (dense_primal_interior_point.hpp), from the same start and multipliers — with WarmStart::kActiveSet and
/// those multipliers, or on the uncondensed problem without them, by the active set strategy before it
/// (active_set_start.hpp) — and falls back to
/// PrimalIpopt's attempts where it fails or where neither applies (finite-strain bodies). Where thresholds follow the
/// iterates, the interior point's answer is closed by the same active set strategy, the thresholds following
/// to the closed answer.

#include "symcontact/solvers/dense_primal_interior_point.hpp"
#include "symcontact/solvers/subproblem.hpp"
#include "symcontact/solvers/subproblem_solver.hpp"

namespace symcontact {

class PrimalIpopt : public SubproblemMethod {
 public:
  SubproblemSolution solve(const Subproblem& p, const SubproblemWarmStart& warm, const Logger& log,
                           PhaseTimes& times) override;
};

/// Which forms of the subproblem the primal interior point takes (the others go to IPOPT).
enum class PrimalForms {
  /// The condensed problem, and the uncondensed one of linear-elastic bodies (a sparse Newton matrix).
  kCondensedAndUncondensed,
  /// The condensed problem only (symmetric pairs and self-contact): on their uncondensed problem the
  /// active-set Newton cannot close the nearly dependent rows of both sides of one zone (its method of
  /// multipliers stalled on every solve of the 3D clamped plates at 1e4 DOFs), and each interior-point
  /// iteration factorises K_ff + AᵀDA with the mortar rows' wide coupling (6 floors a factorisation there).
  kCondensedOnly,
};

class PrimalInteriorPoint : public PrimalIpopt {
 public:
  explicit PrimalInteriorPoint(WarmStart warm = WarmStart::kActiveSet,
                               PrimalForms forms = PrimalForms::kCondensedAndUncondensed)
      : warm_(warm), forms_(forms) {}
  SubproblemSolution solve(const Subproblem& p, const SubproblemWarmStart& warm, const Logger& log,
                           PhaseTimes& times) override;

 private:
  /// After the interior point's success `s` with thresholds that follow the iterates: its active set closed
  /// by Newton with them following (s.closed); s unchanged where that fails (the polish closes it then).
  void close_with_followed_data(const Subproblem& p, double tolerance, const FollowIterate& follow,
                                SubproblemSolution& s, const Logger& log) const;

  WarmStart warm_;
  PrimalForms forms_;
};

}  // namespace symcontact
