#pragma once
/// \file solve_case.hpp
/// Test helper: reads a problem from TOML text, builds the model and solves every load step (contact or
/// not) through the library, returning what the validation tests inspect.

#include <memory>
#include <string>
#include <vector>

#include "symcontact/model/model.hpp"
#include "symcontact/post/contact_results.hpp"
#include "symcontact/post/step_checks.hpp"
#include "symcontact/solvers/frictional_contact.hpp"
#include "symcontact/solvers/solve_report.hpp"

namespace symcontact::testing {

struct SolvedCase {
  ProblemSpec spec;
  std::unique_ptr<Model> model;
  VectorXd u;
  SolveReport report;                         ///< of the last step (its contact state: its last contact solve's)
  std::vector<std::vector<ContactPairResult>> history;  ///< contact results of every step
  std::vector<ContactPairResult> contact;     ///< of the last step
  VectorXd constraint_values;                 ///< A u + b at the last linearisation
  /// Reactions of every step: reactions[step][k] for model->dirichlet_boundaries()[k].
  std::vector<std::vector<Eigen::VectorXd>> reactions;
  /// Automatic step cuts of every step (contact problems; [contact_solver] max_step_cuts).
  std::vector<int> step_cuts;
  /// Coulomb iterations of every step (contact problems: the solves after each step's first).
  std::vector<int> coulomb_iterations;
  /// Optimizer iterations of every step (contact problems), those of attempts that failed included.
  std::vector<int> optimizer_iterations;
  /// Geometry iterations of every step (contact problems: summed over its solves and sub-steps).
  std::vector<int> geometry_iterations;
  /// What the checks of each step's answer measured (post/step_checks.hpp); solve_case runs the checks of
  /// `symcontact run` (model/setup_checks.hpp before the solve, check_step() after each step) and throws
  /// what they throw.
  std::vector<StepCheckFigures> checks;
};

/// `base_dir` resolves relative mesh paths. Throws what the library throws, the checks of the run driver
/// included.
std::unique_ptr<SolvedCase> solve_case(const std::string& toml, const std::string& base_dir);

/// The whole file at `path`; throws std::runtime_error when it cannot be read.
std::string read_text(const std::string& path);

/// A folder of its own for the running test: ::testing::TempDir() + prefix + "." + suite + "." + name + "/"
/// ('/' of parameterised names replaced). Cases of one parameterised test run as separate processes
/// under `ctest -j`: files written under a shared name race (one case meshes the other's .geo).
std::string test_temp_dir(const std::string& prefix);

/// Writes `text` to `dir/name` (creating dir) and returns the path.
std::string write_text(const std::string& dir, const std::string& name, const std::string& text);

}  // namespace symcontact::testing
