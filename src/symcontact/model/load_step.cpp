#include "symcontact/model/load_step.hpp"

namespace symcontact {

SolveReport solve_load_step(Model& model, int step, VectorXd& u, FrictionState& friction,
                            const LoadStepOptions& options, const Logger& log) {
  const auto move_to = [&model, step](double fraction) {
    model.set_step(step, fraction);
    return model.fixed_dofs(step, fraction);
  };
  const LoadStepProblem problem{model.energy(), model.contacts(), model.dofs(), move_to, step};
  SolveReport report = solve_load_step(problem, u, friction, options, log);
  model.set_step(step);
  return report;
}

}  // namespace symcontact
