#include "inclined_2d.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "bench_support.hpp"
#include "symcontact/app/run.hpp"
#include "symcontact/core/log.hpp"
#include "symcontact/core/timer.hpp"
#include "symcontact/model/problem_reader.hpp"

namespace symcontact::bench {

namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read '" + path + "'");
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  out.close();
  if (!out) throw std::runtime_error("cannot write '" + path + "'");
}

}  // namespace

double inclined_exact_ratio() {
  constexpr double tan_alpha = 0.1, mu = 0.2;
  return (tan_alpha + mu) / (1 - mu * tan_alpha);
}

double InclinedRun::contact_seconds() const {
  return times.get("search") + times.get("assembly") + times.get("optimizer") + times.get("polish");
}

std::unique_ptr<InclinedRun> solve_inclined(double h, const std::string& examples_dir, const std::string& work_dir) {
  auto run = std::make_unique<InclinedRun>();
  run->h = h;
  const std::string dir = examples_dir + "/inclined_2d";
  std::filesystem::create_directories(work_dir);
  char h_line[64];
  std::snprintf(h_line, sizeof h_line, "h = %.9g;\n", h);
  write_file(work_dir + "/inclined_h.geo",
             std::string(h_line) + "Include \"" + std::filesystem::absolute(dir + "/inclined.geo").string() + "\";\n");
  std::string toml = read_file(dir + "/inclined.toml");
  const std::string from = "mesh = \"inclined.geo\"", to = "mesh = \"inclined_h.geo\"";
  int count = 0;
  for (std::size_t at = 0; (at = toml.find(from, at)) != std::string::npos; at += to.size(), ++count)
    toml.replace(at, from.size(), to);
  if (count != 2) throw std::runtime_error("inclined.toml: expected both bodies to read inclined.geo");

  run->spec = parse_problem(toml, "inclined.toml", work_dir);
  std::ostringstream quiet;
  const Logger log(quiet, Verbosity::kQuiet);
  run->model = Model::build(run->spec, log, run->build_times);
  Model& model = *run->model;
  const DofMap& dofs = model.dofs();
  const int upper = model.body_index("upper");
  if (upper < 0) throw std::runtime_error("inclined.toml: no body named \"upper\"");
  const FrictionalOptions opt = contact_options(run->spec, log);
  run->u = VectorXd::Zero(dofs.num_dofs());
  run->steps = model.num_steps();
  for (int step = 0; step < run->steps; ++step) {
    model.set_step(step);
    run->fixed = model.fixed_dofs(step);
    const double cpu0 = process_cpu_seconds();
    const double t0 = wall_seconds();
    const FrictionalReport rep =
        solve_frictional_contact(model.energy(), run->fixed, model.contacts(), dofs, run->u, opt, log);
    run->solve_wall += wall_seconds() - t0;
    run->solve_cpu += process_cpu_seconds() - cpu0;
    run->times.merge(rep.times);
    run->coulomb_iterations += rep.coulomb_iterations;
    run->contact_solves += 1 + rep.coulomb_iterations;
    run->geometry_iterations += rep.geometry_iterations;
    run->ipopt_iterations += rep.ipopt_iterations;
    run->num_free = rep.last.num_free;
    run->num_constraints = rep.last.num_constraints;
    run->ipopt_status = rep.last.ipopt_status;
  }
  VectorXd g = VectorXd::Zero(dofs.num_dofs());
  model.energy().add_gradient(run->u, g);
  const std::vector<Eigen::VectorXd> r = model.reactions(run->fixed, g);
  Eigen::Vector2d reaction = Eigen::Vector2d::Zero();
  for (std::size_t k = 0; k < r.size(); ++k)
    if (model.dirichlet_boundaries()[k].body == upper) reaction += r[k];
  run->ratio = std::abs(reaction[0] / reaction[1]);
  return run;
}

CholeskyFloor measure_inclined_floor(const InclinedRun& run, int repeat, Index& num_free) {
  const Model& model = *run.model;
  std::vector<Index> free_index;
  num_free = run.fixed.free_numbering(model.dofs().num_dofs(), free_index);
  // The imposed displacements alone (zero on the free DOFs); the load they put on the free DOFs is
  // −(K u_D)_f = −∇E(u_D)_f (no external load in this problem).
  VectorXd u_d = VectorXd::Zero(model.dofs().num_dofs());
  run.fixed.impose(u_d);
  VectorXd g = VectorXd::Zero(u_d.size());
  model.energy().add_gradient(u_d, g);
  VectorXd load_free(num_free);
  for (Index d = 0; d < g.size(); ++d)
    if (free_index[d] >= 0) load_free[free_index[d]] = -g[d];
  return measure_cholesky_floor(model.energy(), free_index, num_free, load_free, repeat);
}

}  // namespace symcontact::bench
