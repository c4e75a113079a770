#include "hertz_2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "bench_support.hpp"
#include "symcontact/core/log.hpp"
#include "symcontact/model/problem_reader.hpp"
#include "symcontact/post/contact_results.hpp"

namespace symcontact::bench {

namespace {

/// Replaces every occurrence of `from` in `s` by `to`; throws if there is none.
void replace_all(std::string& s, const std::string& from, const std::string& to) {
  std::size_t count = 0;
  for (std::size_t at = 0; (at = s.find(from, at)) != std::string::npos; at += to.size(), ++count)
    s.replace(at, from.size(), to);
  if (count == 0) throw std::runtime_error("'" + from + "' not found in the example's problem file");
}

}  // namespace

std::string hertz_case_name(HertzCase c) {
  return c == HertzCase::kCylinderOnPlane ? "hertz2d" : "hertz2d-cylinders";
}

HertzReference hertz_reference() {
  constexpr double E = 1.0, nu = 0.3, R = 1.0;
  const double e_star = E / (1 - nu * nu);
  HertzReference r;
  r.a = std::sqrt(4 * HertzReference::kLoad * R / (M_PI * e_star));
  r.p0 = 2 * HertzReference::kLoad / (M_PI * r.a);
  return r;
}

double HertzRun::contact_seconds() const {
  return report.times.get("search") + report.times.get("assembly") + report.times.get("optimizer") +
         report.times.get("polish") + report.times.get("condensation");
}

std::unique_ptr<HertzRun> solve_hertz(HertzCase which, double h, const std::string& examples_dir,
                                      const std::string& work_dir, bool condense) {
  auto run = std::make_unique<HertzRun>();
  run->which = which;
  run->h = h;
  const std::string stem = which == HertzCase::kCylinderOnPlane ? "cylinder_on_plane" : "two_cylinders";
  const std::string example = examples_dir + "/hertz_2d/" + stem;

  std::filesystem::create_directories(work_dir);
  char h_line[64];
  std::snprintf(h_line, sizeof h_line, "h = %.9g;\n", h);
  const std::string geo_name = stem + "_h.geo";
  write_file(work_dir + "/" + geo_name,
             std::string(h_line) + "Include \"" + std::filesystem::absolute(example + ".geo").string() + "\";\n");
  std::string toml = read_file(example + ".toml");
  replace_all(toml, stem + ".geo", geo_name);

  run->spec = parse_problem(toml, stem + ".toml", work_dir);
  std::ostringstream quiet;
  const Logger log(quiet, Verbosity::kQuiet);
  run->model = Model::build(run->spec, log, run->build_times);
  Model& model = *run->model;
  if (model.num_steps() != 1) throw std::runtime_error(stem + ".toml: expected a single load step");
  model.set_step(0);
  run->fixed = model.fixed_dofs(0);

  ContactSolveOptions opt;
  opt.geometry_tolerance = run->spec.contact_solver.geometry_tolerance;
  opt.max_geometry_iterations = run->spec.contact_solver.max_geometry_iterations;
  opt.condense = condense && run->spec.contact_solver.static_condensation;
  opt.ipopt.string_options = run->spec.contact_solver.ipopt_string;
  opt.ipopt.numeric_options = run->spec.contact_solver.ipopt_numeric;
  opt.ipopt.integer_options = run->spec.contact_solver.ipopt_integer;
  run->u = VectorXd::Zero(model.dofs().num_dofs());
  const double cpu0 = process_cpu_seconds();
  const double t0 = wall_seconds();
  run->report = solve_contact(model.energy(), run->fixed, model.contacts(), model.dofs(), run->u, opt, log);
  run->solve_wall = wall_seconds() - t0;
  run->solve_cpu = process_cpu_seconds() - cpu0;

  const std::vector<ContactPairResult> pairs =
      contact_results(model.contacts(), model.dofs(), run->u, run->report);
  const ContactSideResult& side = pairs.at(0).sides.at(0);
  for (Index k = 0; k < side.pressure.size(); ++k) run->p0 = std::max(run->p0, side.pressure[k]);
  for (Index k = 0; k < side.pressure.size(); ++k)
    if (side.pressure[k] > 1e-3 * run->p0) run->a = std::max(run->a, std::abs(side.x(0, k)));
  run->force = std::abs(pairs[0].total_force[1]);
  const ContactLinearization& lin = run->report.linearization;
  run->min_constraint = (lin.A * run->u + lin.b).minCoeff();
  return run;
}

CholeskyFloor measure_hertz_floor(const HertzRun& run, int repeat, Index& num_free, int& pinned) {
  const Model& model = *run.model;
  FixedDofs fixed = run.fixed;
  pinned = 0;
  for (int b = 0; b < static_cast<int>(model.bodies().size()); ++b) {
    const Mesh& mesh = model.bodies()[b]->mesh;
    for (Index node = 0; node < mesh.num_nodes(); ++node)
      if (mesh.x.col(node).norm() < 1e-12) {
        fixed.fix(model.dofs().dof(b, node, 1), 0.0);
        ++pinned;
      }
  }
  if (pinned == 0) throw std::runtime_error("measure_hertz_floor: no mesh node at the contact point (0, 0)");

  std::vector<Index> free_index;
  num_free = fixed.free_numbering(model.dofs().num_dofs(), free_index);
  const VectorXd f = model.external_load();
  VectorXd load_free(num_free);
  for (Index d = 0; d < f.size(); ++d)
    if (free_index[d] >= 0) load_free[free_index[d]] = f[d];
  return measure_cholesky_floor(model.energy(), free_index, num_free, load_free, repeat);
}

}  // namespace symcontact::bench
