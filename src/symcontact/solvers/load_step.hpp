#pragma once
/// \file load_step.hpp
/// One load step of a contact problem, with automatic step cutting.
///
/// The step goes from the state u (the previous step's solution) to the loads and imposed displacements
/// of the step. When its solve fails (SolveError: IPOPT failing, the geometry or the Coulomb fixed
/// point not converging, an inverted element), u and the friction state are put back to the start of the
/// failed increment and the increment is halved, up to `max_step_cuts` times: after c cuts the increment is
/// 1/2^c of the step. The sub-steps then go on at that size to the end of the step (no growing back
/// within a step; the next step starts whole again). Within a step every load and imposed displacement
/// is interpolated linearly between its factors at step − 1 and step (LoadStepProblem::move_to; for a
/// model, Model::set_step), which is the load curve itself between its whole-numbered points. Each
/// sub-step is a load step of its own for friction: its slip increments are measured from its start, and
/// its Coulomb iteration starts from the thresholds the previous sub-step converged to.
/// With max_step_cuts = 0 (the default) this is one solve, as without cutting.

#include <functional>
#include <string>
#include <vector>

#include "symcontact/contact/contact_set.hpp"
#include "symcontact/core/log.hpp"
#include "symcontact/energy/energy_term.hpp"
#include "symcontact/fem/dof_map.hpp"
#include "symcontact/solvers/fixed_dofs.hpp"
#include "symcontact/solvers/frictional_contact.hpp"

namespace symcontact {

/// The cutting schedule alone. Calls attempt(from, to) on increments of the step [0, 1] in order, from
/// (0, 1); an attempt that throws SolveError must leave the state as it was at `from`: the increment is
/// then halved (at most max_cuts times in all) and tried again. Returns the end fraction of every
/// converged sub-step (the last is 1). Rethrows the SolveError of an attempt made after max_cuts cuts —
/// as it is when max_cuts = 0, else with the sub-step and the number of cuts appended to its message.
/// `on_cut(from, to, error, cuts)` (optional) is told of every failed attempt that is cut.
std::vector<double> solve_in_substeps(
    int max_cuts, const std::function<void(double from, double to)>& attempt,
    const std::function<void(double from, double to, const std::string& error, int cuts)>& on_cut = nullptr);

/// What a load step solves: the bodies' energy, the contact pairs and the DOF numbering (the same through
/// the step), and how the loads move. `move_to(fraction)` sets the loads of `energy` to `fraction` ∈ (0, 1]
/// of the way from the previous step to this one and returns the Dirichlet conditions there; it is called
/// with fraction 1 last when the step converges.
struct LoadStepProblem {
  const EnergyTerm& energy;
  const ContactSet& contacts;
  const DofMap& dofs;
  std::function<FixedDofs(double fraction)> move_to;
  int step = 0;  ///< 0-based, for messages
};

/// The settings of a run's contact solve, as the problem file's [contact_solver] and [ipopt] tables give
/// them (docs/input.md), under the same names: the problem reader fills this tree directly. The Coulomb and
/// geometry fixed points and the subproblem solver are in `friction` (FrictionalOptions, its `contact`
/// ContactSolveOptions, and their `ipopt`); the step cutting around them is here.
struct LoadStepOptions {
  FrictionalOptions friction;
  /// Automatic step cutting: a load step whose solve fails is retried in halves, up to this many halvings
  /// (solve_in_substeps); 0: no cutting, a failed step ends the run.
  int max_step_cuts = 0;
};

/// Solves the load step from u (on exit the solution; on a SolveError, the last iterate of the final failed
/// attempt). `friction` holds the friction state the previous step ended with (empty nodal_tau for the first
/// step) and is updated. On success the loads are left at the step's end. The report's counters sum over the
/// converged sub-steps; the rest is the last sub-step's (solve_report.hpp). Throws SolveError when the step
/// fails after options.max_step_cuts halvings.
SolveReport solve_load_step(const LoadStepProblem& problem, VectorXd& u, FrictionState& friction,
                            const LoadStepOptions& options, const Logger& log);

}  // namespace symcontact
