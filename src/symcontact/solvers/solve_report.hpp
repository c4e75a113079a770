#pragma once
/// \file solve_report.hpp
/// What a contact solve did and the contact state it ended with: one report for every level of the solver,
/// a geometry fixed point (solve_contact, contact_solver.hpp), the Coulomb fixed point of a load step around it
/// (solve_frictional_contact, frictional_contact.hpp) and a load step with its sub-steps (solve_load_step,
/// load_step.hpp). Each level fills the fields it owns and takes the others from the solves it ran:
///  - the counters sum over everything the level ran;
///  - the contact state (ContactState: the post-processing reads it) and the fields of the last geometry fixed
///    point are those of the last solve;
///  - the fields of the Coulomb fixed point are those of the last (sub-)step's.

#include <string>
#include <vector>

#include "symcontact/contact/contact_state.hpp"
#include "symcontact/core/timer.hpp"
#include "symcontact/solvers/friction_state.hpp"

namespace symcontact {

struct SolveReport : ContactState {
  // Over everything the solve ran.
  int geometry_iterations = 0;
  int ipopt_iterations = 0;                 ///< summed over the geometry iterations
  int coulomb_iterations = 0;               ///< solves after the first (frictionless, or warm) one; 0: no Coulomb pair
  PhaseTimes times;                         ///< "search" (geometry), "optimizer", "assembly", "polish", …

  // The last geometry fixed point.
  std::vector<int> ipopt_per_iteration;
  std::vector<double> change_history;       ///< relative change after each geometry iteration
  /// A solve to geometry_tolerance (not an inexact one: ContactSolveOptions::loose_geometry_tolerance) that
  /// reached it (always, unless inexact); a non-quadratic energy's last iterate was then force-balanced.
  bool converged = false;
  std::string ipopt_status;
  Index num_free = 0;
  Index num_constraints = 0;                ///< of the last linearisation
  Index num_condensed = 0;                  ///< DOFs IPOPT worked on when condensed (0: not condensed)
  int condensation_factorisations = 0;      ///< factorisations for the condensation in that solve
  int dual_solves = 0;                      ///< geometry iterations solved through the dual (SubproblemSolver)
  /// geometry iterations IPOPT optimised uncondensed for the condensed polish (IpoptProblem)
  int uncondensed_solves = 0;
  bool interior_deferred = false;           ///< u's interior was left out of date (ContactSolveOptions::lazy_interior)

  // The Coulomb fixed point of the last (sub-)step.
  std::vector<double> coulomb_change;       ///< ‖r_k‖∞ / ‖τ_k‖∞ per iteration
  std::vector<double> coulomb_relaxation;   ///< ω_k per iteration
  /// The relative threshold change at which a stagnated fixed point was accepted (above coulomb_tolerance, at
  /// most FrictionalOptions::stagnation_acceptance); 0 when it converged.
  double accepted_at_noise_floor = 0.0;
  FrictionState friction_state;             ///< the thresholds of the final solve

  // The load step.
  int cuts = 0;                             ///< halvings of the increment (0: solved whole)
  std::vector<double> substeps;             ///< end fraction of every converged sub-step ({1} when solved whole)
};

/// `solve`, a geometry fixed point run after those `into` counts: its counters are added to `into`'s, its
/// contact state and the fields of the last geometry fixed point replace `into`'s.
void add_geometry_solve(SolveReport& into, SolveReport&& solve);

/// `substep`, a converged (sub-)step of a load step: its counters are added to `into`'s, and every other field
/// but the load step's own (cuts, substeps) replaces `into`'s.
void add_substep(SolveReport& into, SolveReport&& substep);

}  // namespace symcontact
