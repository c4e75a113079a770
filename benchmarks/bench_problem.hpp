#pragma once
/// \file bench_problem.hpp
/// --case problem of symcontact-bench: any problem files, each solved through the library as
/// `symcontact run` solves it (problem_run.hpp), one row per file: DOFs, steps, iterations, time per
/// phase, the largest step, peak RSS, and the ratio to one Cholesky factor-and-solve of the same
/// stiffness. For problems without a closed form (ironing), where the figures that matter are the run
/// time and the iterations per step; every step's figures go to an optional per-step CSV.

#include <string>
#include <vector>

#include "bench_support.hpp"

namespace symcontact::bench {

struct ProblemBenchOptions {
  std::vector<std::string> files;  ///< problem files (.toml), one row each
  int repeat = 1;                  ///< floor phases: minimum over this many runs
  std::string csv;
  std::string steps_csv;           ///< per-step figures of every file, or empty
  bool markdown = false;
};

/// Runs every file, printing the table as rows finish. Throws what the library throws.
void run_problem_files(const ProblemBenchOptions& opt, const MachineInfo& machine);

}  // namespace symcontact::bench
