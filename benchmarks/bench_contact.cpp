#include "bench_contact.hpp"

#include <stdlib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace symcontact::bench {

namespace {

using Kind = ResultTable::Kind;

/// Ends a size after check_hertz_fits() under --check-only.
struct CheckedOnly {};

std::vector<ResultTable::Column> columns() {
  return {
      {"case", "", Kind::kText, 0},
      {"h", "h", Kind::kFixed, 5},
      {"nodes", "", Kind::kInteger, 0},
      {"dofs", "DOFs", Kind::kInteger, 0},
      {"free_dofs", "free", Kind::kInteger, 0},
      {"constraints", "constr.", Kind::kInteger, 0},
      {"geometry_iterations", "geom it", Kind::kInteger, 0},
      {"ipopt_iterations", "IPOPT it", Kind::kInteger, 0},
      {"meshing_s", "mesh [s]", Kind::kFixed, 3},
      {"setup_s", "setup [s]", Kind::kFixed, 3},
      {"search_s", "search [s]", Kind::kFixed, 3},
      {"assembly_s", "assembly [s]", Kind::kFixed, 3},
      {"optimizer_s", "optimizer [s]", Kind::kFixed, 3},
      {"polish_s", "polish [s]", Kind::kFixed, 3},
      {"condensation_s", "condens. [s]", Kind::kFixed, 3},
      {"condensed_dofs", "condensed", Kind::kInteger, 0},
      {"condensation_factorisations", "cond. fact.", Kind::kInteger, 0},
      {"contact_s", "contact [s]", Kind::kFixed, 3},
      {"solve_contact_wall_s", "", Kind::kFixed, 3},
      {"total_s", "total [s]", Kind::kFixed, 3},
      {"peak_rss_contact_mib", "peak RSS [MiB]", Kind::kInteger, 0},
      {"floor_free_dofs", "", Kind::kInteger, 0},
      {"floor_pinned_dofs", "", Kind::kInteger, 0},
      {"floor_assembly_s", "", Kind::kFixed, 3},
      {"floor_analyze_s", "", Kind::kFixed, 3},
      {"floor_factorize_s", "", Kind::kFixed, 3},
      {"floor_solve_s", "", Kind::kFixed, 3},
      {"floor_s", "floor [s]", Kind::kFixed, 3},
      {"ratio", "ratio", Kind::kFixed, 1},
      {"ratio_wall", "", Kind::kFixed, 1},
      {"solve_contact_cpu_s", "contact CPU [s]", Kind::kFixed, 3},
      {"floor_cpu_s", "floor CPU [s]", Kind::kFixed, 3},
      {"ratio_cpu", "CPU ratio", Kind::kFixed, 1},
      {"nnz_l", "", Kind::kInteger, 0},
      {"floor_relative_residual", "", Kind::kScientific, 1},
      {"peak_rss_floor_mib", "", Kind::kInteger, 0},
      {"surface_nodes", "surf. nodes", Kind::kInteger, 0},
      {"surface_facets", "", Kind::kInteger, 0},
      {"search_distance", "", Kind::kScientific, 3},
      {"search_per_iteration_s", "search/it [s]", Kind::kFixed, 4},
      {"contact_search_s", "geom. search [s]", Kind::kFixed, 4},
      {"load", "", Kind::kScientific, 9},
      {"load_error_pct", "", Kind::kFixed, 3},
      {"p0", "", Kind::kScientific, 6},
      {"p0_error_pct", "p0 err [%]", Kind::kFixed, 3},
      {"a", "", Kind::kScientific, 6},
      {"a_error_pct", "a err [%]", Kind::kFixed, 2},
      {"force_relative_error", "force err", Kind::kScientific, 1},
      {"min_constraint", "", Kind::kScientific, 2},
      {"ipopt_status", "", Kind::kText, 0},
      {"repeat", "", Kind::kInteger, 0},
      {"openblas_threads", "", Kind::kInteger, 0},
  };
}


}  // namespace

std::vector<double> default_hertz_sizes(HertzCase which, bool large) {
  if (large && which != HertzCase::kSphereOnPlane)
    throw std::runtime_error("--large is the large 3D sweep: --case hertz3d only");
  switch (which) {
    case HertzCase::kCylinderOnPlane: return {0.003, 0.0015, 0.00085, 0.0006, 0.0004, 0.00027};
    case HertzCase::kTwoCylinders: return {0.003, 0.0015, 0.00085, 0.0006, 0.0004};
    case HertzCase::kSphereOnPlane:
      if (large) return {0.0045, 0.0035, 0.0028, 0.0025};
      return {0.04, 0.02, 0.01, 0.007, 0.005};
    case HertzCase::kTwoSpheres: return {0.04, 0.02, 0.014};
  }
  throw std::logic_error("default_hertz_sizes: unknown Hertz case");
}

void run_hertz_sweep(const ContactBenchOptions& opt, const MachineInfo& machine) {
  const HertzReference nominal = hertz_reference(opt.which);
  const std::string name = hertz_case_name(opt.which);
  const char* vertical = hertz_dimension(opt.which) == 2 ? "u_y" : "u_z";
  std::cout << "\n## " << name << ": " << hertz_case_description(opt.which) << "; closed form at P = "
            << nominal.load << ": a = " << std::setprecision(6) << nominal.a << ", p0 = " << nominal.p0
            << " (errors against the closed form at the applied load P_h, CSV column load)"
            << "; floor phases min of " << opt.repeat << " run(s), contact solve once; search distance "
            << (opt.search_distance > 0 ? std::to_string(opt.search_distance) : std::string("of the example"))
            << " (CSV column search_distance)\n";
  std::cout << "# contact = search + assembly + optimizer + polish + condensation (factorisation, Schur complement,"
               " expansions); total = mesh + setup + solve_contact wall;\n"
            << "# condensed = DOFs IPOPT worked on (0: the full problem); search/it = search phase per geometry"
               " iteration;\n# geom. search = the search alone (time_contact_search(): projections, segmentation, BVH),"
               " at the solution; surf. nodes = nodes of the contact surfaces;\n"
            << "# floor = analyze + factorize + solve of K_ff (" << vertical
            << " also pinned at the contact point); ratio = contact / floor;\n# CPU ratio = process CPU time of"
               " solve_contact() / of the floor (less sensitive to other load on the machine)\n\n";
  ResultTable table(columns(), std::cout, opt.markdown);
  if (!opt.csv.empty()) table.write_csv(opt.csv);

  const std::string work = make_work_dir();
  const auto t_sweep = std::chrono::steady_clock::now();
  bool rss_reset_ok = true;
  std::vector<double> facets, search_per_it, search_geometry;
  for (const double h : opt.h) {
    rss_reset_ok = reset_peak_rss() && rss_reset_ok;
    std::unique_ptr<HertzRun> run;
    try {
      run = solve_hertz(opt.which, h, opt.examples_dir, work, opt.condense, opt.search_distance, [&](const HertzRun& r) {
        std::cout << "# h = " << std::defaultfloat << std::setprecision(6) << h << ": " << r.model->dofs().num_dofs()
                  << " DOFs; " << std::flush;
        const double nnz = check_hertz_fits(r);
        std::cout << "nnz(L) predicted " << static_cast<long long>(nnz) << " (" << std::fixed << std::setprecision(1)
                  << 8 * nnz / (1 << 30) << " GiB), " << available_memory_bytes() / (1 << 30)
                  << " GiB available" << (opt.check_only ? ": fits (not solved, --check-only)\n" : ": solving\n")
                  << std::defaultfloat << std::flush;
        if (opt.check_only) throw CheckedOnly();
      }, opt.dual);
    } catch (const CheckedOnly&) {
      continue;
    } catch (const FactorTooLarge& e) {
      std::cout << "# stopped at h = " << std::defaultfloat << std::setprecision(6) << h << ": " << e.what() << "\n";
      break;
    }
    const double peak_contact = peak_rss_mib();
    const double search_alone = time_contact_search(*run, std::max(opt.repeat, 5));

    rss_reset_ok = reset_peak_rss() && rss_reset_ok;
    Index floor_free = 0;
    int pinned = 0;
    const CholeskyFloor floor = measure_hertz_floor(*run, opt.repeat, floor_free, pinned);
    const double peak_floor = peak_rss_mib();

    Index nodes = 0;
    for (const auto& b : run->model->bodies()) nodes += b->mesh.num_nodes();
    const PhaseTimes& t = run->report.times;
    const double meshing = run->build_times.get("meshing"), setup = run->build_times.get("setup");
    const double contact = run->contact_seconds();
    const HertzReference ref = run->reference();
    const double symmetry = hertz_symmetry_factor(opt.which);
    const double search_it = t.get("search") / std::max(run->report.geometry_iterations, 1);
    facets.push_back(static_cast<double>(run->surface_facets));
    search_per_it.push_back(search_it);
    search_geometry.push_back(search_alone);
    table.add_row({name, h, static_cast<double>(nodes), static_cast<double>(run->model->dofs().num_dofs()),
                   static_cast<double>(run->report.num_free), static_cast<double>(run->report.num_constraints),
                   static_cast<double>(run->report.geometry_iterations),
                   static_cast<double>(run->report.ipopt_iterations), meshing, setup, t.get("search"),
                   t.get("assembly"), t.get("optimizer"), t.get("polish"), t.get("condensation"),
                   static_cast<double>(run->report.num_condensed),
                   static_cast<double>(run->report.condensation_factorisations), contact, run->solve_wall,
                   meshing + setup + run->solve_wall, peak_contact, static_cast<double>(floor_free),
                   static_cast<double>(pinned), floor.assembly, floor.analyze, floor.factorize, floor.solve,
                   floor.factor_and_solve(), contact / floor.factor_and_solve(),
                   run->solve_wall / floor.factor_and_solve(), run->solve_cpu, floor.cpu_factor_and_solve,
                   run->solve_cpu / floor.cpu_factor_and_solve, floor.nnz_factor, floor.relative_residual,
                   peak_floor, static_cast<double>(run->surface_nodes), static_cast<double>(run->surface_facets),
                   run->search_distance, search_it, search_alone, run->load, 100 * (run->load / nominal.load - 1),
                   run->p0, 100 * (run->p0 / ref.p0 - 1), run->a, 100 * (run->a / ref.a - 1),
                   std::abs(symmetry * run->force - run->load) / run->load,
                   run->min_constraint, run->report.ipopt_status, static_cast<double>(opt.repeat),
                   static_cast<double>(machine.openblas_threads)});
  }
  finish_sweep(name, t_sweep, rss_reset_ok, "meshing + setup + contact solve", work, opt.keep_work);
  if (facets.size() >= 2) {
    std::vector<double> n_log_n;
    for (const double n : facets) n_log_n.push_back(n * std::log(n));
    std::cout << std::fixed << std::setprecision(2)
              << "# search ∝ (contact surface facets)^α, least squares over " << facets.size()
              << " sizes: geom. search (projections, segmentation, BVH; min of " << std::max(opt.repeat, 5)
              << " runs at the solution) α = " << loglog_slope(facets, search_geometry)
              << "; search phase per geometry iteration (also assembles A over all DOFs) α = "
              << loglog_slope(facets, search_per_it) << "; n log n over the same sizes: α = "
              << loglog_slope(facets, n_log_n) << "\n"
              << std::defaultfloat;
  }
}

}  // namespace symcontact::bench
