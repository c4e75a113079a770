#include "problem_run.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "bench_support.hpp"
#include "symcontact/app/run.hpp"
#include "symcontact/core/error.hpp"
#include "symcontact/core/log.hpp"
#include "symcontact/core/timer.hpp"
#include "symcontact/model/load_step.hpp"
#include "symcontact/model/problem_reader.hpp"
#include "symcontact/solvers/equilibrium_solver.hpp"

namespace symcontact::bench {

double ProblemRun::contact_seconds() const {
  return times.get("search") + times.get("assembly") + times.get("optimizer") + times.get("polish") +
         times.get("predictor") + times.get("condensation");
}

Eigen::VectorXd ProblemRun::body_reaction(const std::string& name) const {
  const int b = model->body_index(name);
  if (b < 0) throw std::runtime_error(spec.file + ": no body named \"" + name + "\"");
  VectorXd g = VectorXd::Zero(model->dofs().num_dofs());
  model->energy().add_gradient(u, g);
  const std::vector<Eigen::VectorXd> r = model->reactions(fixed, g);
  Eigen::VectorXd total = Eigen::VectorXd::Zero(spec.dim);
  for (std::size_t k = 0; k < r.size(); ++k)
    if (model->dirichlet_boundaries()[k].body == b) total += r[k];
  return total;
}

std::unique_ptr<ProblemRun> solve_problem(const std::string& toml, const std::string& file_name,
                                          const std::string& base_dir) {
  auto run = std::make_unique<ProblemRun>();
  run->spec = parse_problem(toml, file_name, base_dir);
  std::ostringstream quiet;
  const Logger log(quiet, Verbosity::kQuiet);
  run->model = Model::build(run->spec, log, run->build_times);
  Model& model = *run->model;
  const DofMap& dofs = model.dofs();
  // As `symcontact run` solves each step (app/run_serial.cpp): with the problem's step cutting.
  const LoadStepOptions opt = contact_options(run->spec, log);
  const bool contact = !model.contacts().empty();
  run->u = VectorXd::Zero(dofs.num_dofs());
  run->steps = model.num_steps();
  FrictionState friction;  // the last step's thresholds (Coulomb warm start)
  for (int step = 0; step < run->steps; ++step) {
    model.set_step(step);
    run->fixed = model.fixed_dofs(step);
    const double cpu0 = process_cpu_seconds();
    const double t0 = wall_seconds();
    StepFigures f;
    if (contact) {
      SolveReport rep;
      try {
        rep = solve_load_step(model, step, run->u, friction, opt, log);
      } catch (const SolveError& e) {
        throw SolveError("load step " + std::to_string(step + 1) + " of " + std::to_string(run->steps) + " (" +
                         std::to_string(dofs.num_dofs()) + " DOFs): " + e.what());
      }
      run->times.merge(rep.times);
      f.contact_solves = static_cast<int>(std::max<std::size_t>(1, rep.substeps.size())) + rep.coulomb_iterations;
      f.geometry_iterations = rep.geometry_iterations;
      f.ipopt_iterations = rep.ipopt_iterations;
      run->coulomb_iterations += rep.coulomb_iterations;
      run->num_free = rep.num_free;
      run->num_constraints = rep.num_constraints;
      run->ipopt_status = rep.ipopt_status;
    } else {
      const EquilibriumReport rep = solve_equilibrium(model.energy(), run->fixed, run->u);
      run->times.merge(rep.times);
      f.newton_iterations = rep.iterations;
      run->num_free = rep.num_free;
    }
    f.wall = wall_seconds() - t0;
    run->solve_wall += f.wall;
    run->solve_cpu += process_cpu_seconds() - cpu0;
    run->contact_solves += f.contact_solves;
    run->geometry_iterations += f.geometry_iterations;
    run->ipopt_iterations += f.ipopt_iterations;
    run->newton_iterations += f.newton_iterations;
    run->per_step.push_back(f);
  }
  return run;
}

CholeskyFloor measure_problem_floor(const ProblemRun& run, int repeat, Index& num_free) {
  const Model& model = *run.model;
  std::vector<Index> free_index;
  num_free = run.fixed.free_numbering(model.dofs().num_dofs(), free_index);
  VectorXd u_d = VectorXd::Zero(model.dofs().num_dofs());
  run.fixed.impose(u_d);
  VectorXd g = VectorXd::Zero(u_d.size());
  VectorXd load_free(num_free);
  try {
    model.energy().add_gradient(u_d, g);
    for (Index d = 0; d < g.size(); ++d)
      if (free_index[d] >= 0) load_free[free_index[d]] = -g[d];
  } catch (const EvaluationError&) {
    // A finite-strain body with its boundary moved alone is inverted: any right-hand side times the same.
    load_free.setOnes();
  }
  return measure_cholesky_floor(model.energy(), free_index, num_free, load_free, repeat);
}

using Kind = ResultTable::Kind;

std::vector<ResultTable::Column> problem_run_columns() {
  return {
      {"nodes", "", Kind::kInteger, 0},
      {"dofs", "DOFs", Kind::kInteger, 0},
      {"free_dofs", "free", Kind::kInteger, 0},
      {"constraints", "constr.", Kind::kInteger, 0},
      {"steps", "steps", Kind::kInteger, 0},
      {"contact_solves", "solves", Kind::kInteger, 0},
      {"coulomb_iterations", "Coulomb it", Kind::kInteger, 0},
      {"geometry_iterations", "geom it", Kind::kInteger, 0},
      {"ipopt_iterations", "IPOPT it", Kind::kInteger, 0},
      {"newton_iterations", "", Kind::kInteger, 0},
      {"max_step_ipopt_iterations", "max IPOPT it/step", Kind::kInteger, 0},
      {"meshing_s", "mesh [s]", Kind::kFixed, 3},
      {"setup_s", "", Kind::kFixed, 3},
      {"search_s", "search [s]", Kind::kFixed, 3},
      {"assembly_s", "assembly [s]", Kind::kFixed, 3},
      {"optimizer_s", "optimizer [s]", Kind::kFixed, 2},
      {"polish_s", "polish [s]", Kind::kFixed, 2},
      {"contact_s", "contact [s]", Kind::kFixed, 2},
      {"solve_wall_s", "", Kind::kFixed, 3},
      {"max_step_wall_s", "max step [s]", Kind::kFixed, 2},
      {"total_s", "total [s]", Kind::kFixed, 2},
      {"peak_rss_contact_mib", "peak RSS [MiB]", Kind::kInteger, 0},
      {"floor_free_dofs", "", Kind::kInteger, 0},
      {"floor_assembly_s", "", Kind::kFixed, 4},
      {"floor_analyze_s", "", Kind::kFixed, 4},
      {"floor_factorize_s", "", Kind::kFixed, 4},
      {"floor_solve_s", "", Kind::kFixed, 4},
      {"floor_s", "floor [s]", Kind::kFixed, 4},
      {"ratio", "ratio", Kind::kInteger, 0},
      {"ratio_per_step", "ratio/step", Kind::kFixed, 1},
      {"ratio_per_ipopt_iteration", "ratio/IPOPT it", Kind::kFixed, 1},
      {"solve_cpu_s", "contact CPU [s]", Kind::kFixed, 2},
      {"floor_cpu_s", "", Kind::kFixed, 4},
      {"ratio_cpu", "CPU ratio", Kind::kInteger, 0},
      {"nnz_l", "", Kind::kInteger, 0},
      {"floor_relative_residual", "", Kind::kScientific, 1},
      {"ipopt_status", "", Kind::kText, 0},
      {"repeat", "", Kind::kInteger, 0},
      {"openblas_threads", "", Kind::kInteger, 0},
  };
}

const char* const kProblemRunLegend =
    "# iterations and times summed over the load steps; solves = frictionless + Tresca solves;\n"
    "# contact = search + assembly + optimizer + polish + predictor; total = mesh + setup + solve wall;\n"
    "# floor = analyze + factorize + solve of K_ff = Hessian at u = 0 (the problem's own Dirichlet conditions);\n"
    "# ratio = contact / floor; ratio/step = ratio / load steps; ratio/IPOPT it = ratio / IPOPT iterations;\n"
    "# CPU ratio = process CPU time of the solves / of the floor\n\n";

std::vector<ResultTable::Value> problem_run_values(const ProblemRun& run, const CholeskyFloor& floor, Index floor_free,
                                                   double peak_rss, int repeat, const MachineInfo& machine) {
  Index nodes = 0;
  for (const auto& b : run.model->bodies()) nodes += b->mesh.num_nodes();
  int max_ipopt = 0;
  double max_wall = 0.0;
  for (const StepFigures& f : run.per_step) {
    max_ipopt = std::max(max_ipopt, f.ipopt_iterations);
    max_wall = std::max(max_wall, f.wall);
  }
  const PhaseTimes& t = run.times;
  const double meshing = run.build_times.get("meshing"), setup = run.build_times.get("setup");
  const double contact = run.contact_seconds(), fs = floor.factor_and_solve();
  return {static_cast<double>(nodes), static_cast<double>(run.model->dofs().num_dofs()),
          static_cast<double>(run.num_free), static_cast<double>(run.num_constraints),
          static_cast<double>(run.steps), static_cast<double>(run.contact_solves),
          static_cast<double>(run.coulomb_iterations), static_cast<double>(run.geometry_iterations),
          static_cast<double>(run.ipopt_iterations), static_cast<double>(run.newton_iterations),
          static_cast<double>(max_ipopt), meshing, setup, t.get("search"), t.get("assembly"), t.get("optimizer"),
          t.get("polish"), contact, run.solve_wall, max_wall, meshing + setup + run.solve_wall, peak_rss,
          static_cast<double>(floor_free), floor.assembly, floor.analyze, floor.factorize, floor.solve, fs,
          contact / fs, contact / fs / std::max(run.steps, 1), contact / fs / std::max(run.ipopt_iterations, 1),
          run.solve_cpu, floor.cpu_factor_and_solve, run.solve_cpu / floor.cpu_factor_and_solve, floor.nnz_factor,
          floor.relative_residual, run.ipopt_status, static_cast<double>(repeat),
          static_cast<double>(machine.openblas_threads)};
}

std::vector<ResultTable::Column> problem_sweep_columns(int h_precision, const std::vector<ResultTable::Column>& tail) {
  std::vector<ResultTable::Column> c = {{"case", "", Kind::kText, 0}, {"h", "h", Kind::kFixed, h_precision}};
  for (auto& col : problem_run_columns()) c.push_back(col);
  c.push_back({"peak_rss_floor_mib", "floor RSS [MiB]", Kind::kInteger, 0});
  c.insert(c.end(), tail.begin(), tail.end());
  return c;
}

void add_problem_sweep_row(ResultTable& table, const std::string& name, double h, const ProblemRun& run,
                           double peak_rss, const std::vector<ResultTable::Value>& tail, int repeat,
                           const MachineInfo& machine) {
  Index floor_free = 0;
  reset_peak_rss();  // when refused, the caller's sweep says that peak RSS is monotone
  const CholeskyFloor floor = measure_problem_floor(run, repeat, floor_free);
  const double peak_floor = peak_rss_mib();
  std::vector<ResultTable::Value> row = {name, h};
  for (auto& v : problem_run_values(run, floor, floor_free, peak_rss, repeat, machine)) row.push_back(v);
  row.push_back(peak_floor);
  row.insert(row.end(), tail.begin(), tail.end());
  table.add_row(row);
}

}  // namespace symcontact::bench
