#pragma once
/// \file load_step.hpp
/// One load step of a model's contact problem: solvers/load_step.hpp (automatic step cutting around the
/// frictional contact solve) on the model's energy, contact pairs and DOF numbering, its loads moved
/// through the step by Model::set_step and its Dirichlet conditions by Model::fixed_dofs.

#include "symcontact/core/log.hpp"
#include "symcontact/model/model.hpp"
#include "symcontact/solvers/load_step.hpp"

namespace symcontact {

/// Solves load step `step` (0-based) of `model` from u (on exit the solution; on a SolveError, the last
/// iterate of the final failed attempt). `friction` holds the friction state the previous step ended with
/// (empty nodal_tau for the first step) and is updated. Leaves the model's loads at the step. Contact
/// models only. Throws SolveError when the step fails after options.max_step_cuts halvings.
SolveReport solve_load_step(Model& model, int step, VectorXd& u, FrictionState& friction,
                            const LoadStepOptions& options, const Logger& log);

}  // namespace symcontact
