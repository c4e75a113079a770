#pragma once
/// \file hertz_2d.hpp
/// The contact benchmark problems: the Hertz 2D cases of examples/hertz_2d (VALIDATION.md, V1), solved
/// through the library exactly as a problem file is (parse_problem → Model::build → solve_contact), at a
/// chosen fine mesh size h, with the accuracy against the closed form and the Cholesky floor of the
/// same stiffness.
///
///  - kCylinderOnPlane  (cylinder_on_plane.toml): half cylinder R = 1 on the rigid plane y = 0.
///  - kTwoCylinders     (two_cylinders.toml): two elastic half cylinders R = 1 touching at the origin.
/// Both: E = 1, ν = 0.3, plane strain, P = 0.01 (the half model carries P/2 on its cut), so
/// a = sqrt(4 P R_eff / (π E*)) = 0.107641 and p0 = 2 P / (π a) = 0.059143 (E* = E / (1 − ν²), R_eff = 1
/// for the plane; R_eff = 1/2 and E* halved for two cylinders, which gives the same a and p0).
///
/// Mesh size: the example's .geo is included, unchanged, from a wrapper "h = …; Include "…";" written
/// into a temporary directory (the tests do the same). The .geo keeps its coarse size H = 0.08 beyond
/// distance 0.6 of the contact point and size h within 0.2 of it, so the DOF count grows as h⁻².

#include <memory>
#include <string>
#include <vector>

#include "elastic_block.hpp"
#include "symcontact/model/model.hpp"
#include "symcontact/solvers/contact_solver.hpp"

namespace symcontact::bench {

enum class HertzCase { kCylinderOnPlane, kTwoCylinders };

/// "hertz2d" or "hertz2d-cylinders" (the --case names).
std::string hertz_case_name(HertzCase c);

/// Closed form of both cases (see the file comment).
struct HertzReference {
  static constexpr double kLoad = 0.01;  ///< P, the resultant on the whole cylinder
  double a = 0.0;                        ///< half-width of the contact zone
  double p0 = 0.0;                       ///< peak pressure
};
HertzReference hertz_reference();

/// One solved instance. Not copyable (the model refers to the spec).
struct HertzRun {
  HertzCase which = HertzCase::kCylinderOnPlane;
  double h = 0.0;
  ProblemSpec spec;
  std::unique_ptr<Model> model;
  PhaseTimes build_times;      ///< "meshing" (Gmsh), "setup" (DOFs, energy, contact surfaces)
  FixedDofs fixed;             ///< the problem's Dirichlet conditions
  VectorXd u;                  ///< solution, full DOF vector
  ContactSolveReport report;
  double solve_wall = 0.0;     ///< wall time of solve_contact() as a whole, s
  double solve_cpu = 0.0;      ///< process CPU time of solve_contact() as a whole, s

  // Accuracy (side a of the first contact pair: the cylinder, resp. the upper cylinder).
  double p0 = 0.0;             ///< largest nodal pressure
  double a = 0.0;              ///< largest |x| of a node with pressure > 1e-3 p0 (nodal: known to ~h)
  double force = 0.0;          ///< |vertical contact force| on the half model (P/2 expected)
  double min_constraint = 0.0; ///< min (A u + b) at the last linearisation (≥ 0 up to round-off)

  /// search + assembly + optimizer + polish of report.times (the contact solve proper).
  double contact_seconds() const;
};

/// Writes the wrapper .geo and a copy of the example's TOML (pointing at it) into `work_dir`, builds the
/// model and solves it. `examples_dir` is the examples/ folder of the source tree. Throws what the
/// library throws (InputError, SolveError).
/// `condense` false switches the static condensation off (contact_solver.static_condensation).
std::unique_ptr<HertzRun> solve_hertz(HertzCase which, double h, const std::string& examples_dir,
                                      const std::string& work_dir, bool condense = true);

/// The Cholesky floor of run.model: K_ff of the whole energy (all bodies), factorised and solved for the
/// external load. The free DOFs are those of the contact problem except that u_y is additionally fixed
/// at the node(s) at the initial contact point (x = 0, y = 0) of every body: without contact the
/// cylinder (and the upper cylinder of the two-cylinder case) is free to translate vertically and K_ff
/// is singular. One (resp. two) fewer row than the contact problem; no regularisation.
/// `pinned` receives the number of DOFs so fixed.
CholeskyFloor measure_hertz_floor(const HertzRun& run, int repeat, Index& num_free, int& pinned);

}  // namespace symcontact::bench
