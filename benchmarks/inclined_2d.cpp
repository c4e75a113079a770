#include "inclined_2d.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "bench_support.hpp"

namespace symcontact::bench {

double inclined_exact_ratio() {
  constexpr double tan_alpha = 0.1, mu = 0.2;
  return (tan_alpha + mu) / (1 - mu * tan_alpha);
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

  run->problem = solve_problem(toml, "inclined.toml", work_dir);
  const Eigen::VectorXd reaction = run->problem->body_reaction("upper");
  run->ratio = std::abs(reaction[0] / reaction[1]);
  return run;
}

}  // namespace symcontact::bench
