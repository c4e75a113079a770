#include "symcontact/solvers/contact_solver.hpp"

#include "symcontact/core/error.hpp"
#include "symcontact/solvers/geometry_fixed_point.hpp"

namespace symcontact {

SolveReport solve_contact(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts,
                                 const DofMap& dofs, VectorXd& u, const ContactSolveOptions& options,
                                 const Logger& log, const FrictionState* friction) {
  // A solve that is not lazy starts from a whole u; one that fails leaves a whole last iterate.
  auto complete = [&] {
    if (options.workspace) complete_interior(energy, fixed, u, *options.workspace);
  };
  if (!options.lazy_interior) complete();
  // IPOPT and the polish back away from states the energy cannot be evaluated at; one left over (the
  // start point of a step) is a failed solve, not an internal error.
  try {
    try {
      return GeometryFixedPoint(energy, fixed, contacts, dofs, options, log, friction).solve(u);
    } catch (const EvaluationError& e) {
      throw SolveError(std::string("the contact solve reached a state the energy cannot be evaluated at: ") +
                       e.what() + " — use smaller load steps");
    }
  } catch (const SolveError&) {
    complete();
    throw;
  }
}

}  // namespace symcontact
