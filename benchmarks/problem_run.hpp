#pragma once
/// \file problem_run.hpp
/// A problem file solved through the library exactly as `symcontact run` solves it (parse_problem →
/// Model::build → per load step solve_frictional_contact, or solve_equilibrium without contact), with
/// what a benchmark reports: iterations and time per phase summed over the steps, per-step figures, and
/// the Cholesky floor of the same model. Used by --case problem (any file) and --case inclined.

#include <memory>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "elastic_block.hpp"
#include "symcontact/model/model.hpp"
#include "symcontact/solvers/frictional_contact.hpp"

namespace symcontact::bench {

/// One load step's figures.
struct StepFigures {
  double wall = 0.0;            ///< wall time of the step's solve, s
  int contact_solves = 0;       ///< frictionless + Tresca solves (0 without contact)
  int geometry_iterations = 0;
  int ipopt_iterations = 0;
  int newton_iterations = 0;    ///< without contact
};

/// One solved problem. Not copyable (the model refers to the spec).
struct ProblemRun {
  ProblemSpec spec;
  std::unique_ptr<Model> model;
  PhaseTimes build_times;      ///< "meshing" (Gmsh), "setup"
  FixedDofs fixed;             ///< the Dirichlet conditions of the last step
  VectorXd u;                  ///< solution of the last step, full DOF vector
  int steps = 0;
  int coulomb_iterations = 0;  ///< Σ over the steps (Tresca solves after each step's frictionless one)
  int contact_solves = 0;      ///< Σ over the steps of the contact solves (frictionless + Tresca)
  int geometry_iterations = 0; ///< Σ over every contact solve
  int ipopt_iterations = 0;    ///< Σ over every contact solve
  int newton_iterations = 0;   ///< Σ over the steps without contact
  Index num_free = 0, num_constraints = 0;  ///< of the last solve
  PhaseTimes times;            ///< "search", "assembly", "optimizer", "polish", … summed over the steps
  double solve_wall = 0.0;     ///< wall time of all the steps' solves, s
  double solve_cpu = 0.0;      ///< process CPU time of the same, s
  std::string ipopt_status;    ///< of the last solve
  std::vector<StepFigures> per_step;

  /// search + assembly + optimizer + polish (+ predictor): the contact solves proper.
  double contact_seconds() const;
  /// Σ of the reactions of the Dirichlet conditions of body `name` at the last step (dim entries).
  Eigen::VectorXd body_reaction(const std::string& name) const;
};

/// Solves every load step of the problem in `toml` (`file_name` names it in messages; relative mesh
/// paths resolve against `base_dir`). Throws what the library throws (InputError, SolveError; the latter
/// with "load step k of n (N DOFs): " put before its message).
std::unique_ptr<ProblemRun> solve_problem(const std::string& toml, const std::string& file_name,
                                          const std::string& base_dir);

/// The Cholesky floor of run.model: K_ff = ∇²E(0) of the whole energy with the last step's Dirichlet
/// conditions (which must hold every body, so that K_ff is positive definite without contact), solved
/// for the load of the imposed displacements and external loads, −∇E(u_D)_f (a vector of ones where E
/// cannot be evaluated at u_D: a finite-strain body whose boundary alone is moved far; the time is the same).
CholeskyFloor measure_problem_floor(const ProblemRun& run, int repeat, Index& num_free);

/// The columns every problem-run table shares (after a "case" column and the caller's own leading
/// columns): sizes, iterations, time per phase, peak RSS, the floor and the ratios.
std::vector<ResultTable::Column> problem_run_columns();
/// The values of problem_run_columns() for one run and its floor (`peak_rss`: MiB during the solves).
std::vector<ResultTable::Value> problem_run_values(const ProblemRun& run, const CholeskyFloor& floor, Index floor_free,
                                                   double peak_rss, int repeat, const MachineInfo& machine);
/// The legend printed above such a table.
extern const char* const kProblemRunLegend;

/// The columns of a sweep of one problem over element sizes: "case", "h" (printed with `h_precision`
/// digits), problem_run_columns(), the peak RSS of the floor (VmHWM reset before it, the solved model
/// still in memory), then the case's own `tail`.
std::vector<ResultTable::Column> problem_sweep_columns(int h_precision, const std::vector<ResultTable::Column>& tail);
/// Measures the floor of `run` (measure_problem_floor, min of `repeat`) and adds the row of
/// problem_sweep_columns() to `table`: `name`, `h`, problem_run_values(), the floor's peak RSS, then `tail`.
void add_problem_sweep_row(ResultTable& table, const std::string& name, double h, const ProblemRun& run,
                           double peak_rss, const std::vector<ResultTable::Value>& tail, int repeat,
                           const MachineInfo& machine);

}  // namespace symcontact::bench
