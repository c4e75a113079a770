/// symcontact — command-line program.
///   symcontact run CASE.toml [--out DIR] [--mesh-size H] [--allow-large-mesh] [--allow-geo-commands] [-v|-q]
///   symcontact check CASE.toml [--mesh-size H] [...]   (read and build the model, solve nothing)
/// Exit codes: 0 success, 2 input error, 3 solve did not converge, 4 internal error, 130 / 143 run
/// interrupted by SIGINT / SIGTERM (128 + the signal number, the shell's convention).
///
/// Started by mpirun (OpenMPI's or MPICH's environment), `symcontact` replaces itself with `symcontact-mpi`,
/// its sibling: this file built with SYMCONTACT_DISTRIBUTED_RUN, which solves the contact steps on the
/// distributed path (distributed/distributed_step.hpp) and never loads IPOPT (src/CMakeLists.txt). Rank 0
/// writes the output folder and the log, every rank its pieces of the VTU files; every rank exits with the same code.

#include <CLI/CLI.hpp>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <unistd.h>

#include "symcontact/app/linear_solver_choice.hpp"
#include "symcontact/app/run.hpp"
#include "symcontact/core/blas_kernels.hpp"
#include "symcontact/core/blas_threads.hpp"
#include "symcontact/core/error.hpp"
#include "symcontact/core/timer.hpp"
#include "symcontact/io/output_folder.hpp"
#include "symcontact/model/model.hpp"
#include "symcontact/model/problem_reader.hpp"
#include "symcontact/model/setup_checks.hpp"
#ifdef SYMCONTACT_DISTRIBUTED_RUN
#include "symcontact/distributed/distributed_step.hpp"
#include "symcontact/distributed/gamg_elasticity.hpp"
#endif

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

#ifdef SYMCONTACT_DISTRIBUTED_RUN
/// The problem file read and checked for the distributed path: [ipopt] is not asked to IPOPT (not loaded).
ProblemSpec read_case(const std::string& file) {
  ProblemSpec spec = parse_problem(read_problem_text(file), file, problem_folder(file));
  check_distributed_support(spec);
  return spec;
}

RunResult solve_case(const ProblemSpec& spec, RunOptions opt, const Logger& log, const PetscSession& petsc, char**) {
  // Every rank writes its pieces of the VTU files (run.hpp); rank 0 the rest of the folder.
  opt.parallel = ParallelOutput{petsc.rank(), petsc.size(), [&petsc](bool ok) { return petsc.all_ranks(ok); }};
  if (petsc.rank() != 0) opt.files = OutputFiles::kNone;
  return run_problem(spec, opt, log, distributed_step_solver(spec, ContactInteriorPointOptions{}, log));
}
#else
ProblemSpec read_case(const std::string& file) { return read_problem_file(file); }

/// The distributed program, symcontact-mpi, beside this one.
std::filesystem::path distributed_program() {
  return std::filesystem::read_symlink("/proc/self/exe").parent_path() / "symcontact-mpi";
}

/// Under mpirun: replaced by symcontact-mpi (returns only when that fails).
int start_distributed_run(char** argv) {
  if (!std::getenv("OMPI_COMM_WORLD_SIZE") && !std::getenv("PMI_SIZE")) return -1;
  execv(distributed_program().c_str(), argv);
  std::cerr << "symcontact: started by mpirun, but " << distributed_program().string()
            << " (the distributed path, built with PETSc and MPI) cannot be run: run symcontact without mpirun\n";
  return kExitInputError;
}

/// Replaced by symcontact-mpi as a single process; throws InputError when that cannot be run.
[[noreturn]] void switch_to_distributed(const ProblemSpec& spec, const std::string& why, char** argv) {
  execv(distributed_program().c_str(), argv);
  throw InputError(spec.file, "contact_solver.linear_solver",
                   why + ", but " + distributed_program().string() +
                       " (the distributed path, built with PETSc and MPI: scripts/install-deps) cannot be run");
}

/// Thrown by the run's model hook when the distributed path is to solve the problem.
struct StartDistributed {};

/// The serial run, unless [contact_solver] linear_solver (or its automatic choice, app/linear_solver_choice.hpp)
/// gives the problem to the distributed path: then the process becomes symcontact-mpi, before any output.
RunResult solve_case(const ProblemSpec& spec, RunOptions opt, const Logger& log, char** argv) {
  if (spec.linear_solver == LinearSolverChoice::kIterative)
    switch_to_distributed(spec, "linear_solver = \"iterative\"", argv);
  std::string why;
  opt.on_model = [&](const Model& model) {
    const LinearSolverDecision d = choose_linear_solver(spec, model);
    log.detail(d.reason);
    if (!d.iterative) return;
    why = off_direct_reason(d);
    throw StartDistributed{};
  };
  try {
    return run_problem(spec, opt, log);
  } catch (const StartDistributed&) {
    switch_to_distributed(spec, why, argv);
  }
}
#endif

/// The exit code of a finished run; what went wrong, if anything, on `err`.
int exit_code(const RunResult& r, const std::string& out_dir, const Logger& log, std::ostream& err) {
  if (r.status == RunStatus::kInterrupted) {
    err << "symcontact: " << r.message << "\n  finished steps and summary.json are in " << out_dir << "\n";
    return kExitSignalBase + r.signal;
  }
  if (r.status != RunStatus::kOk) {
    err << "symcontact: solve failed: " << r.message << "\n  finished steps and summary.json are in " << out_dir << "\n";
    return kExitSolveError;
  }
  log.info("results written to " + out_dir);
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
#ifndef SYMCONTACT_DISTRIBUTED_RUN
  if (const int code = start_distributed_run(argv); code >= 0) return code;
#endif
  restart_with_better_blas_kernels(argv);  // OpenBLAS's fallback kernels on a CPU it does not know
#ifdef SYMCONTACT_DISTRIBUTED_RUN
  int petsc_argc = 1;  // PETSc reads its options from PETSC_OPTIONS, not from this command line
  const PetscSession petsc(&petsc_argc, &argv);
  const bool root = petsc.rank() == 0;
#else
  const bool root = true;
#endif
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
  apply_thread_setting(threads);
  const Verbosity level = quiet ? Verbosity::kQuiet
                                : (verbose >= 2 ? Verbosity::kDebug : (verbose == 1 ? Verbosity::kVerbose : Verbosity::kNormal));
  static std::ostream nowhere(nullptr);
  std::ostream& err = root ? std::cerr : nowhere;  // messages and the log from rank 0 alone
  const Logger log(err, level);
  if (const std::string note = blas_kernel_note(); !note.empty()) log.detail(note);
  try {
    RunOptions opt;
    if (*run) {
      // Before any work: a folder that cannot take the results would only fail after the solve.
      opt.out_dir = out_dir.empty() ? std::filesystem::path(case_file).stem().string() + "_results" : out_dir;
      if (const std::string problem = output_folder_problem(opt.out_dir); !problem.empty())
        throw InputError("", "--out", "the output folder '" + opt.out_dir + "' " + problem);
    }
    const ProblemSpec spec = read_case(case_file);
    if (*check) {
      PhaseTimes times;
      auto model = Model::build(spec, log, times, meshing.overrides());
      check_setup(*model);
      if (root) std::cout << case_file << ": OK, " << model->bodies().size() << " bodies, " << model->dofs().num_dofs()
                << " DOFs, " << model->num_steps() << " load steps\n";
      return kExitOk;
    }
    opt.meshing = meshing.overrides();
    opt.signals = SignalHandling::kStopCleanly;
#ifdef SYMCONTACT_DISTRIBUTED_RUN
    return exit_code(solve_case(spec, opt, log, petsc, argv), opt.out_dir, log, err);
#else
    return exit_code(solve_case(spec, opt, log, argv), opt.out_dir, log, err);
#endif
  } catch (const InputError& e) {
    err << "symcontact: input error: " << e.what() << "\n";
    return kExitInputError;
  } catch (const SolveError& e) {
    err << "symcontact: solve failed: " << e.what() << "\n";
    return kExitSolveError;
  } catch (const std::exception& e) {
    err << "symcontact: internal error: " << e.what() << "\n";
    return kExitInternalError;
  }
}
