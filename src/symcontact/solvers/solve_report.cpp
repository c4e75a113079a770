#include "symcontact/solvers/solve_report.hpp"

#include <utility>

namespace symcontact {

namespace {

/// The counters of `earlier` added to those of `later`, the solve that came after it (the phases in the order
/// they first appeared).
void add_counters(SolveReport& later, const SolveReport& earlier) {
  later.geometry_iterations += earlier.geometry_iterations;
  later.ipopt_iterations += earlier.ipopt_iterations;
  later.coulomb_iterations += earlier.coulomb_iterations;
  PhaseTimes times = earlier.times;
  times.merge(later.times);
  later.times = std::move(times);
}

}  // namespace

void add_geometry_solve(SolveReport& into, SolveReport&& solve) {
  add_counters(solve, into);
  solve.coulomb_change = std::move(into.coulomb_change);
  solve.coulomb_relaxation = std::move(into.coulomb_relaxation);
  solve.accepted_at_noise_floor = into.accepted_at_noise_floor;
  solve.friction_state = std::move(into.friction_state);
  solve.cuts = into.cuts;
  solve.substeps = std::move(into.substeps);
  into = std::move(solve);
}

void add_substep(SolveReport& into, SolveReport&& substep) {
  add_counters(substep, into);
  substep.cuts = into.cuts;
  substep.substeps = std::move(into.substeps);
  into = std::move(substep);
}

}  // namespace symcontact
