#include "bench_problem.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include "problem_run.hpp"

namespace symcontact::bench {

void run_problem_files(const ProblemBenchOptions& opt, const MachineInfo& machine) {
  std::cout << "\n## problem files, solved as `symcontact run` solves them; floor phases min of " << opt.repeat
            << " run(s), solves once\n"
            << kProblemRunLegend;
  std::vector<ResultTable::Column> columns = {{"case", "", ResultTable::Kind::kText, 0}};
  for (auto& c : problem_run_columns()) columns.push_back(c);
  ResultTable table(columns, std::cout, opt.markdown);
  if (!opt.csv.empty()) table.write_csv(opt.csv);
  std::ofstream steps;
  if (!opt.steps_csv.empty()) {
    steps.open(opt.steps_csv);
    if (!steps) throw std::runtime_error("cannot write '" + opt.steps_csv + "'");
    steps << "case,step,wall_s,contact_solves,geometry_iterations,ipopt_iterations,newton_iterations\n";
  }
  for (const std::string& file : opt.files) {
    const std::string toml = read_file(file);
    const std::filesystem::path path(file);
    reset_peak_rss();
    const auto run = solve_problem(toml, file, path.parent_path().string());
    const double peak = peak_rss_mib();
    Index floor_free = 0;
    const CholeskyFloor floor = measure_problem_floor(*run, opt.repeat, floor_free);
    const std::string name = path.stem().string();
    std::vector<ResultTable::Value> row = {name};
    for (auto& v : problem_run_values(*run, floor, floor_free, peak, opt.repeat, machine)) row.push_back(v);
    table.add_row(row);
    for (std::size_t k = 0; steps.is_open() && k < run->per_step.size(); ++k) {
      const StepFigures& f = run->per_step[k];
      steps << name << ',' << k + 1 << ',' << f.wall << ',' << f.contact_solves << ',' << f.geometry_iterations << ','
            << f.ipopt_iterations << ',' << f.newton_iterations << '\n';
    }
  }
}

}  // namespace symcontact::bench
