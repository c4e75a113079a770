#include "bench_inclined.hpp"

#include <stdlib.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <stdexcept>

#include "inclined_2d.hpp"

namespace symcontact::bench {

namespace {

using Kind = ResultTable::Kind;

std::vector<ResultTable::Column> columns() {
  return {
      {"case", "", Kind::kText, 0},
      {"h", "h", Kind::kFixed, 4},
      {"nodes", "", Kind::kInteger, 0},
      {"dofs", "DOFs", Kind::kInteger, 0},
      {"free_dofs", "free", Kind::kInteger, 0},
      {"constraints", "constr.", Kind::kInteger, 0},
      {"steps", "steps", Kind::kInteger, 0},
      {"contact_solves", "solves", Kind::kInteger, 0},
      {"coulomb_iterations", "Coulomb it", Kind::kInteger, 0},
      {"geometry_iterations", "geom it", Kind::kInteger, 0},
      {"ipopt_iterations", "IPOPT it", Kind::kInteger, 0},
      {"meshing_s", "mesh [s]", Kind::kFixed, 3},
      {"setup_s", "", Kind::kFixed, 3},
      {"search_s", "search [s]", Kind::kFixed, 3},
      {"assembly_s", "assembly [s]", Kind::kFixed, 3},
      {"optimizer_s", "optimizer [s]", Kind::kFixed, 2},
      {"polish_s", "polish [s]", Kind::kFixed, 2},
      {"contact_s", "contact [s]", Kind::kFixed, 2},
      {"solve_wall_s", "", Kind::kFixed, 3},
      {"total_s", "total [s]", Kind::kFixed, 2},
      {"peak_rss_contact_mib", "peak RSS [MiB]", Kind::kInteger, 0},
      {"floor_free_dofs", "", Kind::kInteger, 0},
      {"floor_assembly_s", "", Kind::kFixed, 4},
      {"floor_analyze_s", "", Kind::kFixed, 4},
      {"floor_factorize_s", "", Kind::kFixed, 4},
      {"floor_solve_s", "", Kind::kFixed, 4},
      {"floor_s", "floor [s]", Kind::kFixed, 4},
      {"ratio", "ratio", Kind::kInteger, 0},
      {"ratio_per_ipopt_iteration", "ratio/IPOPT it", Kind::kFixed, 1},
      {"solve_cpu_s", "contact CPU [s]", Kind::kFixed, 2},
      {"floor_cpu_s", "", Kind::kFixed, 4},
      {"ratio_cpu", "CPU ratio", Kind::kInteger, 0},
      {"nnz_l", "", Kind::kInteger, 0},
      {"floor_relative_residual", "", Kind::kScientific, 1},
      {"reaction_ratio", "Rx/Ry ratio", Kind::kFixed, 6},
      {"reaction_ratio_error_pct", "err [%]", Kind::kFixed, 3},
      {"ipopt_status", "", Kind::kText, 0},
      {"repeat", "", Kind::kInteger, 0},
      {"openblas_threads", "", Kind::kInteger, 0},
  };
}

/// A fresh directory under the system temporary directory.
std::string make_work_dir() {
  std::string templ = (std::filesystem::temp_directory_path() / "symcontact-bench-XXXXXX").string();
  if (!mkdtemp(templ.data())) throw std::runtime_error("cannot create a temporary directory " + templ);
  return templ;
}

}  // namespace

std::vector<double> default_inclined_sizes() { return {0.05, 0.025, 0.0125}; }

void run_inclined_sweep(const InclinedBenchOptions& opt, const MachineInfo& machine) {
  const double exact = inclined_exact_ratio();
  std::cout << "\n## inclined: two bodies on an interface of slope 0.1, Coulomb mu = 0.2, plane strain, P1,"
               " 10 load steps (2 press, 8 push); exact |Rx/Ry| in gross slip "
            << std::setprecision(6) << exact << "; floor phases min of " << opt.repeat
            << " run(s), contact solves once\n";
  std::cout << "# h: lower body (upper 0.75 h); iterations and times summed over the 10 steps;"
               " solves = frictionless + Tresca solves;\n"
               "# contact = search + assembly + optimizer + polish; total = mesh + setup + solve wall;\n"
               "# floor = analyze + factorize + solve of K_ff (the problem's own Dirichlet conditions);"
               " ratio = contact / floor;\n# ratio/IPOPT it = ratio / IPOPT iterations;"
               " CPU ratio = process CPU time of the solves / of the floor\n\n";
  ResultTable table(columns(), std::cout, opt.markdown);
  if (!opt.csv.empty()) table.write_csv(opt.csv);

  const std::string work = make_work_dir();
  const auto t_sweep = std::chrono::steady_clock::now();
  bool rss_reset_ok = true;
  for (const double h : opt.h) {
    rss_reset_ok = reset_peak_rss() && rss_reset_ok;
    const auto run = solve_inclined(h, opt.examples_dir, work);
    const double peak_contact = peak_rss_mib();
    Index floor_free = 0;
    const CholeskyFloor floor = measure_inclined_floor(*run, opt.repeat, floor_free);

    Index nodes = 0;
    for (const auto& b : run->model->bodies()) nodes += b->mesh.num_nodes();
    const PhaseTimes& t = run->times;
    const double meshing = run->build_times.get("meshing"), setup = run->build_times.get("setup");
    const double contact = run->contact_seconds();
    const double fs = floor.factor_and_solve();
    table.add_row({"inclined", h, static_cast<double>(nodes), static_cast<double>(run->model->dofs().num_dofs()),
                   static_cast<double>(run->num_free), static_cast<double>(run->num_constraints),
                   static_cast<double>(run->steps), static_cast<double>(run->contact_solves),
                   static_cast<double>(run->coulomb_iterations), static_cast<double>(run->geometry_iterations),
                   static_cast<double>(run->ipopt_iterations), meshing, setup, t.get("search"), t.get("assembly"),
                   t.get("optimizer"), t.get("polish"), contact, run->solve_wall,
                   meshing + setup + run->solve_wall, peak_contact, static_cast<double>(floor_free),
                   floor.assembly, floor.analyze, floor.factorize, floor.solve, fs, contact / fs,
                   contact / fs / std::max(run->ipopt_iterations, 1), run->solve_cpu, floor.cpu_factor_and_solve,
                   run->solve_cpu / floor.cpu_factor_and_solve, floor.nnz_factor, floor.relative_residual,
                   run->ratio, 100 * (run->ratio / exact - 1), run->ipopt_status, static_cast<double>(opt.repeat),
                   static_cast<double>(machine.openblas_threads)});
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_sweep).count();
  std::cout << "\n# inclined sweep: " << std::fixed << std::setprecision(1) << wall << std::defaultfloat
            << " s wall\n";
  if (!rss_reset_ok)
    std::cout << "# note: /proc/self/clear_refs refused the peak-RSS reset: peak RSS is monotone over the run\n";
  else
    std::cout << "# peak RSS: of meshing + setup + the contact solves, per size (VmHWM reset before each size)\n";
  if (opt.keep_work)
    std::cout << "# wrapper .geo and .toml kept in " << work << "\n";
  else
    std::filesystem::remove_all(work);
}

}  // namespace symcontact::bench
