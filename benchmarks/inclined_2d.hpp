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

#include "problem_run.hpp"

namespace symcontact::bench {

/// (tan α + μ) / (1 − μ tan α) with tan α = 0.1, μ = 0.2.
double inclined_exact_ratio();

/// One solved instance: the problem run and the accuracy measure.
struct InclinedRun {
  double h = 0.0;
  std::unique_ptr<ProblemRun> problem;
  double ratio = 0.0;          ///< |R_x / R_y| on the upper body at the last step
};

/// Writes the wrapper .geo and a copy of inclined.toml (pointing at it) into `work_dir`, builds the model
/// and solves every load step. `examples_dir` is the examples/ folder of the source tree. Throws what
/// the library throws (InputError, SolveError).
std::unique_ptr<InclinedRun> solve_inclined(double h, const std::string& examples_dir, const std::string& work_dir);


}  // namespace symcontact::bench
