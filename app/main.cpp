/// symcontact — command-line program.
///   symcontact run CASE.toml [--out DIR] [--mesh-size H] [--allow-large-mesh] [--allow-geo-commands] [-v|-q]
///   symcontact check CASE.toml [--mesh-size H] [...]   (read and build the model, solve nothing)
/// Exit codes: 0 success, 2 input error, 3 solve did not converge, 4 internal error, 130 / 143 run
/// interrupted by SIGINT / SIGTERM (128 + the signal number, the shell's convention).

#include <CLI/CLI.hpp>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "symcontact/app/run.hpp"
#include "symcontact/core/blas_kernels.hpp"
#include "symcontact/core/blas_threads.hpp"
#include "symcontact/core/error.hpp"
#include "symcontact/core/timer.hpp"
#include "symcontact/io/output_folder.hpp"
#include "symcontact/model/model.hpp"
#include "symcontact/model/problem_reader.hpp"
#include "symcontact/model/setup_checks.hpp"

using namespace symcontact;

namespace {

/// --mesh-size: a finite number > 0, shown as typed when it is not ("0", "nan", "-1", "inf"), not
/// CLI11's fixed-point rendering of the parsed double.
CLI::Validator finite_positive_size() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double h = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0') return "expected a number, got '" + text + "'";
        if (!std::isfinite(h) || !(h > 0))
          return "expected a finite element size > 0, got '" + text + "'";
        return "";
      },
      "SIZE > 0");
}

struct MeshingFlags {
  double mesh_size = 0.0;
  bool allow_large_mesh = false;
  bool allow_geo_commands = false;

  void add_to(CLI::App& command) {
    command.add_option("--mesh-size", mesh_size, "maximum element size for .geo meshes (overrides the file)")
        ->check(finite_positive_size());
    command.add_flag("--allow-large-mesh", allow_large_mesh,
                     "mesh even when the predicted cell count is above the limit (docs/checks.md)");
    command.add_flag("--allow-geo-commands", allow_geo_commands,
                     "let .geo files run programs (SystemCall, ...): only for files you trust");
  }
  MeshingOverrides overrides() const {
    MeshingOverrides m;
    m.mesh_size = mesh_size;
    if (allow_large_mesh) m.max_predicted_cells = 0.0;
    m.geo_commands = allow_geo_commands ? GeoCommands::kAllow : GeoCommands::kRefuse;
    return m;
  }
};

}  // namespace

int main(int argc, char** argv) {
  restart_with_better_blas_kernels(argv);  // OpenBLAS's fallback kernels on a CPU it does not know
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
  MeshingFlags meshing;
  auto* run = app.add_subcommand("run", "solve a problem file and write results");
  run->add_option("case", case_file, "problem file (TOML, see docs/input.md)")->required();
  run->add_option("-o,--out", out_dir, "output folder (default: <case name>_results)");
  meshing.add_to(*run);
  auto* check = app.add_subcommand("check", "read the problem and its meshes, report sizes, solve nothing");
  check->add_option("case", case_file, "problem file")->required();
  meshing.add_to(*check);

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
  if (const std::string note = blas_kernel_note(); !note.empty()) log.detail(note);
  try {
    RunOptions opt;
    if (*run) {
      // Before any work: a folder that cannot take the results would only fail after the solve.
      opt.out_dir = out_dir.empty() ? std::filesystem::path(case_file).stem().string() + "_results" : out_dir;
      if (const std::string problem = output_folder_problem(opt.out_dir); !problem.empty())
        throw InputError("", "--out", "the output folder '" + opt.out_dir + "' " + problem);
    }
    const ProblemSpec spec = read_problem_file(case_file);
    if (*check) {
      PhaseTimes times;
      auto model = Model::build(spec, log, times, meshing.overrides());
      check_setup(*model);
      std::cout << case_file << ": OK, " << model->bodies().size() << " bodies, " << model->dofs().num_dofs()
                << " DOFs, " << model->num_steps() << " load steps\n";
      return kExitOk;
    }
    opt.meshing = meshing.overrides();
    opt.signals = SignalHandling::kStopCleanly;
    const RunResult r = run_problem(spec, opt, log);
    if (r.status == RunStatus::kInterrupted) {
      std::cerr << "symcontact: " << r.message << "\n"
                << "  finished steps and summary.json are in " << opt.out_dir << "\n";
      return kExitSignalBase + r.signal;
    }
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
