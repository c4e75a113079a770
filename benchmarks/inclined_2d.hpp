#pragma once
/// \file inclined_2d.hpp
/// The frictional contact benchmark problem: the inclined interface of examples/inclined_2d
/// (VALIDATION.md, V5) with Coulomb friction μ = 0.2 (inclined.toml), solved through the library exactly
/// as `symcontact run` solves a problem file (parse_problem → Model::build → per load step
/// solve_frictional_contact), at a chosen element size h of the lower body (the upper body gets 0.75 h).
///
/// Ten load steps: two of compression (top edge u_y = −5e-4), eight of push up the slope (u_x to 1.5e-3).
/// Each step is a Coulomb fixed point (Algorithm 1): one frictionless solve, then regularised-Tresca solves
/// until the threshold settles; each solve is a geometry fixed point (Algorithm 2) of IPOPT solves, each
/// followed by the active-set polish. Accuracy: the reaction ratio |R_x / R_y| on the upper top edge in
/// gross slip (the last step) against (tan α + μ)/(1 − μ tan α) = 0.306122.
///
/// Mesh size: inclined.geo is included, unchanged, from a wrapper "h = …; Include "…";" written into a
/// temporary directory (as the tests do).

#include <memory>
#include <string>

#include "elastic_block.hpp"
#include "symcontact/model/model.hpp"
#include "symcontact/solvers/frictional_contact.hpp"

namespace symcontact::bench {

/// (tan α + μ) / (1 − μ tan α) with tan α = 0.1, μ = 0.2.
double inclined_exact_ratio();

/// One solved instance. Not copyable (the model refers to the spec).
struct InclinedRun {
  double h = 0.0;
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
  Index num_free = 0, num_constraints = 0;  ///< of the last solve
  PhaseTimes times;            ///< "search", "assembly", "optimizer", "polish", … summed over the steps
  double solve_wall = 0.0;     ///< wall time of all the steps' solve_frictional_contact(), s
  double solve_cpu = 0.0;      ///< process CPU time of the same, s
  double ratio = 0.0;          ///< |R_x / R_y| on the upper body at the last step
  std::string ipopt_status;    ///< of the last solve

  /// search + assembly + optimizer + polish (the contact solves proper).
  double contact_seconds() const;
};

/// Writes the wrapper .geo and a copy of inclined.toml (pointing at it) into `work_dir`, builds the model
/// and solves every load step. `examples_dir` is the examples/ folder of the source tree. Throws what
/// the library throws (InputError, SolveError).
std::unique_ptr<InclinedRun> solve_inclined(double h, const std::string& examples_dir, const std::string& work_dir);

/// The Cholesky floor of run.model: K_ff of the whole energy with the problem's own Dirichlet conditions
/// (lower body clamped at the bottom, upper body's top edge fully imposed, so K_ff is positive definite
/// without contact), solved for the load of the last step's imposed displacements, −(K u_D)_f.
CholeskyFloor measure_inclined_floor(const InclinedRun& run, int repeat, Index& num_free);

}  // namespace symcontact::bench
