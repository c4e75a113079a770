#pragma once
/// \file run.hpp
/// The run driver behind `symcontact run`: builds the model, solves the load steps in order and
/// writes results as each step finishes.
///
/// Outputs in `out_dir` (created only once the model has been built without input errors; none with
/// OutputFiles::kNone):
///  - `<body>_<step>.vtu` per body and load step (displacement, strain, stress, von Mises); on several processes
///    (RunOptions::parallel) `<body>_<step>.pvtu` naming the pieces `<body>_<step>_p<rank>.vtu`,
///  - `results.pvd`, a ParaView collection over the steps (one part per body), rewritten after each step,
///  - `summary.json`: status, sizes, per step the reactions on every Dirichlet boundary, iterations and
///    timings; rewritten after each step ("status": "running"), final status at the end.
/// All files are written atomically (temporary name, then rename), so a killed run leaves every
/// finished step's files valid; the temporaries a killed run left behind are removed when the next run
/// starts in the same folder.
///
/// After each step, before anything of it is written, the displacements and the recovered fields of
/// every body are checked to be finite: a solve that overflowed (E = 1e-300, a pressure of 1e200) ends
/// the run as a failed solve naming the body and the step, with the finished steps kept.
///
/// With RunOptions::signals = kStopCleanly, SIGINT and SIGTERM (interrupt.hpp) stop the run at the next
/// load step or IPOPT iteration: the file being written is finished, summary.json says "interrupted",
/// and the result carries the signal.

#include <exception>
#include <functional>
#include <string>

#include "symcontact/core/log.hpp"
#include "symcontact/io/json_writer.hpp"
#include "symcontact/model/model.hpp"
#include "symcontact/model/problem_spec.hpp"
#include "symcontact/post/contact_table.hpp"
#include "symcontact/post/stress_recovery.hpp"
#include "symcontact/solvers/load_step.hpp"
#include "symcontact/solvers/solve_report.hpp"

namespace symcontact {

/// What SIGINT and SIGTERM do during a run: the default (end the process at once), or stop cleanly.
enum class SignalHandling { kDefault, kStopCleanly };

/// Whether a run writes its output folder (the files listed above) or only reports (RunOptions::on_step,
/// RunResult::summary): the command line always writes, the Python module lets its caller choose.
enum class OutputFiles { kWrite, kNone };

/// What a run reports after each finished load step, before the progress line (references valid during
/// the call only).
struct StepRecord {
  int step = 0;                               ///< 1-based
  int num_steps = 0;
  const Model& model;
  const Json& summary_step;                   ///< the step's entry of summary.json "steps"
  const std::vector<BodyFields>& fields;      ///< per body: displacement, strain, stress, von Mises, J
  const std::vector<ContactTable>& contact;   ///< per pair: the table of its contact CSV
  const std::string& progress;                ///< the text of the step's progress line
};

/// A run shared by several processes (symcontact-mpi under mpirun, every process running the same steps): each
/// writes its piece of every body's VTU, the first the rest of the output folder (write_parallel_vtu() in run.cpp).
struct ParallelOutput {
  int rank = 0;
  int size = 1;
  /// Collective: whether `ok` holds on every process (each calls it at the same points of the run).
  std::function<bool(bool ok)> all_ranks;
};

struct RunOptions {
  std::string out_dir;        ///< output folder (OutputFiles::kWrite)
  OutputFiles files = OutputFiles::kWrite;
  /// Called after each finished load step; an exception it throws ends the run and propagates (as an
  /// internal error for summary.json, which then says "internal_error").
  std::function<void(const StepRecord&)> on_step;
  /// Called once the model is built and checked, before the first step (and before the output folder).
  std::function<void(const Model&)> on_model;
  MeshingOverrides meshing;   ///< --mesh-size (> 0 overrides problem.mesh_size) and the meshing limits
  bool write_vtu = true;      ///< and the problem's output.vtu
  /// On several processes, the VTU of each body and step is a .pvtu naming one piece per process (a process with
  /// OutputFiles::kNone writes its pieces and nothing else).
  ParallelOutput parallel;
  /// kStopCleanly installs the handlers once the output folder exists (before, a signal ends the
  /// process with nothing written).
  SignalHandling signals = SignalHandling::kDefault;
};

enum class RunStatus { kOk, kSolveFailed, kInterrupted };

struct RunResult {
  RunStatus status = RunStatus::kOk;
  std::string message;
  int steps_done = 0;
  int signal = 0;  ///< kInterrupted: the signal received (SIGINT, SIGTERM)
  Json summary;    ///< summary.json as written last (also with OutputFiles::kNone)
};

/// summary.json's last word when an exception other than a failed solve leaves the run (an internal error:
/// the program exits 4 with its message): on destruction during that exception's unwinding, "status":
/// "internal_error" and a message naming the load step it stopped at (steps_done + 1), written by `write`,
/// instead of a summary that still says "running". A failure to write is ignored (the exception in flight is
/// the one to report); on a normal exit it does nothing.
class SummaryOnError {
 public:
  SummaryOnError(Json& summary, std::function<void()> write, const int& steps_done)
      : summary_(summary), write_(std::move(write)), steps_done_(steps_done), uncaught_(std::uncaught_exceptions()) {}
  SummaryOnError(const SummaryOnError&) = delete;
  SummaryOnError& operator=(const SummaryOnError&) = delete;
  ~SummaryOnError();

 private:
  Json& summary_;
  std::function<void()> write_;
  const int& steps_done_;
  int uncaught_;
};

/// IPOPT's default `tol` when a hyperelastic body takes part in a problem with Coulomb friction, instead of
/// IpoptOptions::tolerance (1e-10), as if the problem file's [ipopt] table gave it. There the Coulomb thresholds are read from pressures that the
/// geometry fixed point settles, and a fixed point that wanders (a corner coming into contact) carries the
/// inner solves' tolerance-level differences to different converged states: at 1e-10 the same problem in m
/// and in mm gave reactions 1e-2 apart for a few steps (ironing_2d/ironing_mu0.3) and 1e-4 apart
/// (oring_axisymmetric), both within every check; at 1e-12 they agree to 3e-9 (docs/validation-friction.md).
/// acceptable_tol (ipopt_solver.cpp) still follows IpoptOptions::tolerance: with it at 1e-8 instead of 1e-6
/// the ironing in m and in mm parted again, by 2e-4 from step 25 on.
constexpr double kFiniteStrainCoulombIpoptTolerance = 1e-12;

/// The contact-solver settings of a run: the problem's [contact_solver] and [ipopt] tables
/// (ProblemSpec::contact_solver) with a workspace for the run, IPOPT's console log at the debug verbosity,
/// and the problem-dependent default kFiniteStrainCoulombIpoptTolerance (an `[ipopt] tol` of the file is
/// kept over it).
LoadStepOptions contact_options(const ProblemSpec& spec, const Logger& log);

/// Solves load step `step` (0-based) of a model with contact, from u (on exit the solution), from and into
/// the friction thresholds of the last step; throws SolveError when it fails. The serial contact solver
/// (model/load_step.hpp) or the distributed one (distributed/distributed_step.hpp).
using StepSolver = std::function<SolveReport(Model& model, int step, VectorXd& u, FrictionState& friction)>;

/// Runs the problem, its steps with contact solved by `solve_step`. Input errors propagate as InputError
/// before any file is written; a failed solve (including non-finite results) is recorded in summary.json
/// (status "solve_failed", the message) and returned, finished steps kept; so is an interruption (status
/// "interrupted").
RunResult run_problem(const ProblemSpec& spec, const RunOptions& options, const Logger& log,
                      const StepSolver& solve_step);

/// run_problem() with the serial contact solver and the settings of contact_options() (run_serial.cpp).
RunResult run_problem(const ProblemSpec& spec, const RunOptions& options, const Logger& log);

}  // namespace symcontact
