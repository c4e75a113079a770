#pragma once
/// \file run.hpp
/// The run driver behind `symcontact run`: builds the model, solves the load steps in order and
/// writes results as each step finishes.
///
/// Outputs in `out_dir` (created only once the model has been built without input errors):
///  - `<body>_<step>.vtu` per body and load step (displacement, strain, stress, von Mises),
///  - `results.pvd`, a ParaView collection over the steps (one part per body), rewritten after each step,
///  - `summary.json`: status, sizes, per step the reactions on every Dirichlet boundary, iterations and
///    timings; rewritten after each step ("status": "running"), final status at the end.
/// All files are written atomically (temporary name, then rename), so a killed run leaves every
/// finished step's files valid.

#include <string>

#include "symcontact/core/log.hpp"
#include "symcontact/model/problem_spec.hpp"
#include "symcontact/solvers/frictional_contact.hpp"

namespace symcontact {

struct RunOptions {
  std::string out_dir;        ///< output folder
  double mesh_size = 0.0;     ///< > 0 overrides problem.mesh_size
  bool write_vtu = true;      ///< and the problem's output.vtu
};

enum class RunStatus { kOk, kSolveFailed };

struct RunResult {
  RunStatus status = RunStatus::kOk;
  std::string message;
  int steps_done = 0;
};

/// The contact-solver settings of a problem (its [contact_solver] and [ipopt] tables).
FrictionalOptions contact_options(const ProblemSpec& spec, const Logger& log);

/// Runs the problem. Input errors propagate as InputError before any file is written; a failed solve
/// is recorded in summary.json (status "solve_failed", the message) and returned, finished steps kept.
RunResult run_problem(const ProblemSpec& spec, const RunOptions& options, const Logger& log);

}  // namespace symcontact
