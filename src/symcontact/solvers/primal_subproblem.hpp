#pragma once
/// \file primal_subproblem.hpp
/// The subproblem solved by IPOPT on the displacements (the reference formulation; any energy).
/// Warm-started from the previous rows' multipliers when the rows are the same; a Restoration_Failed (a
/// line search that fails at an iterate already feasible) resumes once from that iterate; a warm start that
/// fails on the first geometry iteration (its multipliers come from another solve) is retried cold, and a
/// failure with friction once more from Subproblem::restart (stiff regularised friction, small α, can defeat
/// the line search from a start that is already close).
/// PrimalInteriorPoint solves a condensed subproblem by the dense interior point first
/// (dense_primal_interior_point.hpp), from the same start and multipliers — with WarmStart::kActiveSet and
/// those multipliers, by the active set strategy before it (active_set_start.hpp) — and falls back to
/// PrimalIpopt's attempts where it fails or where the subproblem is not condensed.

#include "symcontact/solvers/subproblem.hpp"
#include "symcontact/solvers/subproblem_solver.hpp"

namespace symcontact {

class PrimalIpopt : public SubproblemMethod {
 public:
  SubproblemSolution solve(const Subproblem& p, const SubproblemWarmStart& warm, const Logger& log,
                           PhaseTimes& times) override;
};

class PrimalInteriorPoint : public PrimalIpopt {
 public:
  explicit PrimalInteriorPoint(WarmStart warm = WarmStart::kActiveSet) : warm_(warm) {}
  SubproblemSolution solve(const Subproblem& p, const SubproblemWarmStart& warm, const Logger& log,
                           PhaseTimes& times) override;

 private:
  WarmStart warm_;
};

}  // namespace symcontact
