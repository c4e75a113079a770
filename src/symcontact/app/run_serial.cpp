/// \file run_serial.cpp
/// run_problem() with the serial contact solver (model/load_step.hpp: IPOPT and CHOLMOD), apart from the run
/// driver so that a program without IPOPT (the distributed run) links the driver alone.

#include "symcontact/app/run.hpp"
#include "symcontact/model/load_step.hpp"
#include "symcontact/solvers/frictional_contact.hpp"

namespace symcontact {

namespace {

/// Whether a hyperelastic body takes part in a problem with Coulomb friction.
bool finite_strain_coulomb(const ProblemSpec& spec) {
  bool hyperelastic = false, coulomb = false;
  for (const BodySpec& b : spec.bodies)
    for (const MaterialSpec& m : b.materials) hyperelastic = hyperelastic || m.model != "linear_elastic";
  for (const ContactSpec& c : spec.contacts) coulomb = coulomb || c.friction == "coulomb";
  return hyperelastic && coulomb;
}

}  // namespace

LoadStepOptions contact_options(const ProblemSpec& spec, const Logger& log) {
  LoadStepOptions options = spec.contact_solver;
  ContactSolveOptions& o = options.friction.contact;
  o.workspace = std::make_shared<ContactWorkspace>();  // one factorisation for the whole run
  if (log.level() >= Verbosity::kDebug) o.ipopt.print_level = 5;
  // As an [ipopt] tol of the problem file (which it does not override): IPOPT's acceptable_tol keeps
  // following IpoptOptions::tolerance.
  if (finite_strain_coulomb(spec)) o.ipopt.numeric_options.emplace("tol", kFiniteStrainCoulombIpoptTolerance);
  return options;
}

RunResult run_problem(const ProblemSpec& spec, const RunOptions& options, const Logger& log) {
  const LoadStepOptions solver_options = contact_options(spec, log);  // its workspace serves every step
  return run_problem(spec, options, log, [&](Model& model, int step, VectorXd& u, FrictionState& friction) {
    return solve_load_step(model, step, u, friction, solver_options, log);
  });
}

}  // namespace symcontact
