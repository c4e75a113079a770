#include "support/solve_case.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "symcontact/model/problem_reader.hpp"
#include "symcontact/solvers/equilibrium_solver.hpp"

namespace symcontact::testing {

std::unique_ptr<SolvedCase> solve_case(const std::string& toml, const std::string& base_dir) {
  auto c = std::make_unique<SolvedCase>();
  c->spec = parse_problem(toml, "case.toml", base_dir);
  static std::ostringstream sink;
  const Logger log(sink, Verbosity::kQuiet);
  PhaseTimes times;
  c->model = Model::build(c->spec, log, times);
  const DofMap& dofs = c->model->dofs();
  c->u = VectorXd::Zero(dofs.num_dofs());
  ContactSolveOptions opt;
  opt.geometry_tolerance = c->spec.contact_solver.geometry_tolerance;
  opt.max_geometry_iterations = c->spec.contact_solver.max_geometry_iterations;
  opt.ipopt.string_options = c->spec.contact_solver.ipopt_string;
  opt.ipopt.numeric_options = c->spec.contact_solver.ipopt_numeric;
  opt.ipopt.integer_options = c->spec.contact_solver.ipopt_integer;
  for (int step = 0; step < c->model->num_steps(); ++step) {
    c->model->set_step(step);
    const FixedDofs fixed = c->model->fixed_dofs(step);
    if (c->model->contacts().empty()) {
      solve_equilibrium(c->model->energy(), fixed, c->u);
      continue;
    }
    c->report = solve_contact(c->model->energy(), fixed, c->model->contacts(), dofs, c->u, opt, log);
    c->contact = contact_results(c->model->contacts(), dofs, c->u, c->report.contact_force);
    c->constraint_values = c->report.linearization.A * c->u + c->report.linearization.b;
  }
  return c;
}

std::string write_text(const std::string& dir, const std::string& name, const std::string& text) {
  std::filesystem::create_directories(dir);
  const std::string path = (std::filesystem::path(dir) / name).string();
  std::ofstream(path) << text;
  return path;
}

}  // namespace symcontact::testing
