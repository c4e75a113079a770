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
  return problem_sweep_columns(4, {{"reaction_ratio", "Rx/Ry ratio", Kind::kFixed, 6},
                                   {"reaction_ratio_error_pct", "err [%]", Kind::kFixed, 3}});
}

}  // namespace

std::vector<double> default_inclined_sizes() { return {0.025, 0.0125, 0.00625, 0.003125, 0.0015625}; }

void run_inclined_sweep(const InclinedBenchOptions& opt, const MachineInfo& machine) {
  const double exact = inclined_exact_ratio();
  std::cout << "\n## inclined: two bodies on an interface of slope 0.1, Coulomb mu = 0.2, plane strain, P1,"
               " 10 load steps (2 press, 8 push); exact |Rx/Ry| in gross slip "
            << std::setprecision(6) << exact << "; floor phases min of " << opt.repeat
            << " run(s), contact solves once\n";
  std::cout << "# h: lower body (upper 0.75 h)\n" << kProblemRunLegend;
  ResultTable table(columns(), std::cout, opt.markdown);
  if (!opt.csv.empty()) table.write_csv(opt.csv);

  const std::string work = make_work_dir();
  const auto t_sweep = std::chrono::steady_clock::now();
  bool rss_reset_ok = true;
  for (const double h : opt.h) {
    rss_reset_ok = reset_peak_rss() && rss_reset_ok;
    const auto run = solve_inclined(h, opt.examples_dir, work);
    const double peak_contact = peak_rss_mib();
    add_problem_sweep_row(table, "inclined", h, *run->problem, peak_contact, {run->ratio, 100 * (run->ratio / exact - 1)},
                          opt.repeat, machine);
  }
  finish_sweep("inclined", t_sweep, rss_reset_ok, "meshing + setup + the contact solves", work, opt.keep_work);
}

}  // namespace symcontact::bench
