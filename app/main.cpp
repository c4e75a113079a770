/// symcontact — command-line program.
///   symcontact run CASE.toml [--out DIR] [--mesh-size H] [-v|-q]
///   symcontact check CASE.toml       (read and build the model, solve nothing)
/// Exit codes: 0 success, 2 input error, 3 solve did not converge, 4 internal error.

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "symcontact/app/run.hpp"
#include "symcontact/core/blas_threads.hpp"
#include "symcontact/core/error.hpp"
#include "symcontact/core/timer.hpp"
#include "symcontact/model/model.hpp"
#include "symcontact/model/problem_reader.hpp"
#include "symcontact/model/setup_checks.hpp"

using namespace symcontact;

int main(int argc, char** argv) {
  CLI::App app{"symcontact — symmetric frictional contact by interior point (FEM, 2D/3D)", "symcontact"};
  app.set_version_flag("--version", std::string("symcontact ") + SYMCONTACT_VERSION);
  app.require_subcommand(1);
  app.fallthrough();  // -v/-q also after the subcommand
  int verbose = 0;
  bool quiet = false;
  app.add_flag("-v,--verbose", verbose, "more output (-vv: debug, including Gmsh's log)");
  app.add_flag("-q,--quiet", quiet, "errors only");
  int threads = 0;
  app.add_option("--threads", threads,
                 "BLAS threads for the sparse factorisations (default 1, or OPENBLAS_NUM_THREADS when set)")
      ->check(CLI::PositiveNumber);

  std::string case_file, out_dir;
  double mesh_size = 0.0;
  auto* run = app.add_subcommand("run", "solve a problem file and write results");
  run->add_option("case", case_file, "problem file (TOML, see docs/input.md)")->required();
  run->add_option("-o,--out", out_dir, "output folder (default: <case name>_results)");
  run->add_option("--mesh-size", mesh_size, "maximum element size for .geo meshes (overrides the file)")
      ->check(CLI::PositiveNumber);
  auto* check = app.add_subcommand("check", "read the problem and its meshes, report sizes, solve nothing");
  check->add_option("case", case_file, "problem file")->required();
  check->add_option("--mesh-size", mesh_size, "maximum element size for .geo meshes")->check(CLI::PositiveNumber);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : kExitInputError;
  }
  if (threads > 0)
    set_blas_threads(threads);
  else if (!std::getenv("OPENBLAS_NUM_THREADS"))
    set_blas_threads(1);
  const Verbosity level = quiet ? Verbosity::kQuiet
                                : (verbose >= 2 ? Verbosity::kDebug : (verbose == 1 ? Verbosity::kVerbose : Verbosity::kNormal));
  const Logger log(std::cerr, level);
  try {
    const ProblemSpec spec = read_problem_file(case_file);
    if (*check) {
      PhaseTimes times;
      auto model = Model::build(spec, log, times, mesh_size);
      check_setup(*model);
      std::cout << case_file << ": OK, " << model->bodies().size() << " bodies, " << model->dofs().num_dofs()
                << " DOFs, " << model->num_steps() << " load steps\n";
      return kExitOk;
    }
    RunOptions opt;
    opt.out_dir = out_dir.empty() ? std::filesystem::path(case_file).stem().string() + "_results" : out_dir;
    opt.mesh_size = mesh_size;
    const RunResult r = run_problem(spec, opt, log);
    if (r.status != RunStatus::kOk) {
      std::cerr << "symcontact: solve failed: " << r.message << "\n"
                << "  finished steps and summary.json are in " << opt.out_dir << "\n";
      return kExitSolveError;
    }
    log.info("results written to " + opt.out_dir);
    return kExitOk;
  } catch (const InputError& e) {
    std::cerr << "symcontact: input error: " << e.what() << "\n";
    return kExitInputError;
  } catch (const SolveError& e) {
    std::cerr << "symcontact: solve failed: " << e.what() << "\n";
    return kExitSolveError;
  } catch (const std::exception& e) {
    std::cerr << "symcontact: internal error: " << e.what() << "\n";
    return kExitInternalError;
  }
}
