#include "support/solve_case.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <sstream>

#include "symcontact/app/run.hpp"
#include "symcontact/model/load_step.hpp"
#include "symcontact/model/problem_reader.hpp"
#include "symcontact/model/setup_checks.hpp"
#include "symcontact/solvers/equilibrium_solver.hpp"

namespace symcontact::testing {

std::unique_ptr<SolvedCase> solve_case(const std::string& toml, const std::string& base_dir) {
  auto c = std::make_unique<SolvedCase>();
  c->spec = parse_problem(toml, "case.toml", base_dir);
  static std::ostringstream sink;
  const Logger log(sink, Verbosity::kQuiet);
  PhaseTimes times;
  c->model = Model::build(c->spec, log, times);
  check_setup(*c->model);  // as `symcontact run` does
  const DofMap& dofs = c->model->dofs();
  c->u = VectorXd::Zero(dofs.num_dofs());
  const LoadStepOptions opt = contact_options(c->spec, log);
  for (int step = 0; step < c->model->num_steps(); ++step) {
    c->model->set_step(step);
    const FixedDofs fixed = c->model->fixed_dofs(step);
    if (c->model->contacts().empty()) {
      solve_equilibrium(c->model->energy(), fixed, c->u);
      c->checks.push_back(check_step(*c->model, c->u, fixed, nullptr));
    } else {
      FrictionState friction = step > 0 ? c->report.friction_state : FrictionState();
      c->report = solve_load_step(*c->model, step, c->u, friction, opt, log);
      c->step_cuts.push_back(c->report.cuts);
      c->coulomb_iterations.push_back(c->report.coulomb_iterations);
      c->optimizer_iterations.push_back(c->report.ipopt_iterations);
      c->geometry_iterations.push_back(c->report.geometry_iterations);
      c->checks.push_back(check_step(*c->model, c->u, fixed, &c->report));
      c->contact = contact_results(c->model->contacts(), dofs, c->u, c->report);
      c->history.push_back(c->contact);
      c->constraint_values = c->report.linearization.A * c->u + c->report.linearization.b;
    }
    VectorXd g = VectorXd::Zero(dofs.num_dofs());
    c->model->energy().add_gradient(c->u, g);
    c->reactions.push_back(c->model->reactions(fixed, g));
  }
  return c;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string test_temp_dir(const std::string& prefix) {
  std::string id = "no_test";
  if (const ::testing::TestInfo* t = ::testing::UnitTest::GetInstance()->current_test_info())
    id = std::string(t->test_suite_name()) + "." + t->name();
  for (char& c : id)
    if (c == '/') c = '_';
  return ::testing::TempDir() + prefix + "." + id + "/";
}

std::string write_text(const std::string& dir, const std::string& name, const std::string& text) {
  std::filesystem::create_directories(dir);
  const std::string path = (std::filesystem::path(dir) / name).string();
  std::ofstream(path) << text;
  return path;
}

}  // namespace symcontact::testing
