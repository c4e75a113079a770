#pragma once
/// \file large_contact.hpp
/// Contact benchmarks whose contact zone is a whole face (--case pad-flat | pad-ball | clamped-plates and
/// their 2D plane-strain analogues pad-flat-2d | pad-ball-2d | clamped-plates-2d), where the Hertz and
/// inclined cases have a small zone or a single line. Each problem is written here as problem-file text
/// (the meshes as .geo text, meshed by Gmsh at problem.mesh_size = h) and solved through the library as
/// `symcontact run` solves a file (problem_run.hpp): every load step a Coulomb fixed point, μ = 0.3.
/// E = 1, ν = 0.3 throughout; lengths in units of the pad's or the plate's width.
///
///  - pad-flat: a pad [−½, ½]² × [0, ¼] (2D: [−½, ½] × [0, ¼]) on the rigid plane z = 0 (2D: y = 0); its top
///    face pressed down by 0.005 in two steps, then dragged along x by 0.02 in two more, the top held in y
///    (3D). The whole bottom face is in contact from the first step and slides in the last two: in gross
///    slip the top's reaction has |R_t / R_n| = μ exactly, which the table checks.
///  - pad-ball: the same pad pressed by 0.03 in four steps onto a rigid sphere (2D: a cylinder) of radius 1
///    touching its bottom at the origin, so that the contact zone grows from a point step by step, then
///    dragged along x by 0.05 in two more steps.
///  - clamped-plates: two plates [−½, ½]² × [0, 0.2] and [−½, ½]² × [−0.2, 0] with a hole of radius 0.1 through
///    both, in contact over their whole common face (a symmetric pair, non-matching only where Gmsh makes it
///    so), held like a bolted joint: the lower plate's bottom annulus 0.1 ≤ r ≤ 0.2 (the washer) clamped,
///    the upper plate's top annulus pressed down by 0.002 in two steps, then moved along x by 5e-4 (a small
///    in-plane shear) in two more. The 2D analogue is the plane-strain section x ∈ [0.1, 0.5] of one side
///    of the hole (washer x ∈ [0.1, 0.2]).
///
/// With LargeContactFriction::kNone the same problems are solved frictionless (the drag then slides the
/// pad freely; the plates' shear is carried by the washers alone).
///
/// Each case reports, besides the columns of problem_run.hpp, the peak RSS of its floor and |R_t / R_n| of
/// the reaction of the body that is moved (pad, upper plate) at the last step.

#include <optional>
#include <string>
#include <vector>

#include "bench_support.hpp"

namespace symcontact::bench {

enum class LargeContactCase { kPadFlat, kPadBall, kClampedPlates, kPadFlat2d, kPadBall2d, kClampedPlates2d };

/// Every case, in the order --case suite runs them.
const std::vector<LargeContactCase>& large_contact_cases();
/// "pad-flat", "pad-ball", "clamped-plates", "pad-flat-2d", "pad-ball-2d", "clamped-plates-2d".
std::string large_contact_name(LargeContactCase c);
/// The case of a --case name; none when `name` is not one.
std::optional<LargeContactCase> large_contact_case(const std::string& name);

/// The friction law of the contact pair: the cases' Coulomb μ = 0.3, or none (--frictionless), to compare.
enum class LargeContactFriction { kCoulomb, kNone };

struct LargeContactBenchOptions {
  LargeContactCase which = LargeContactCase::kPadFlat;
  LargeContactFriction friction = LargeContactFriction::kCoulomb;
  std::vector<double> h;  ///< element sizes (problem.mesh_size), one row each, in the order given
  int repeat = 1;         ///< floor phases: minimum over this many runs (the contact solves run once)
  std::string csv;
  bool markdown = false;
  bool keep_work = false; ///< keep the temporary directory with the .geo and .toml files
  /// [contact_solver] subproblem_solver of the problems (subproblem_solver.hpp names); empty: the default.
  std::string subproblem_solver;
  /// [contact_solver] static_condensation of the problems (--no-condense: false, the whole problem to the
  /// optimiser, its Newton systems sparse).
  bool condense = true;
  /// [contact_solver] coulomb_update of the problems ("inside_optimizer", "between_solves"); empty: the default.
  std::string coulomb_update;
  /// [contact_solver] warm_start of the problems ("active_set", "interior_point"); empty: the default.
  std::string warm_start;
};

/// The ladder of h of each case: by default sizes that each take at most a couple of minutes on two cores
/// (2D: about 1e4 to 3e5 DOFs; 3D: 1e3 to 8e3, the contact solve of a whole face at 1e4 DOFs taking 1.5 to 7
/// minutes), with `large` (--large) the larger ones beyond them.
std::vector<double> default_large_contact_sizes(LargeContactCase c, bool large = false);

/// Runs the sweep, printing the table as rows finish. A size whose solve fails (SolveError) is reported
/// with its h and message and the sweep goes on with the next; at the end the first such failure is
/// thrown again as a SolveError naming the smallest h that failed. Stops, with a message, at the first
/// size whose floor's factor does not fit in memory (FactorTooLarge).
void run_large_contact_sweep(const LargeContactBenchOptions& opt, const MachineInfo& machine);

}  // namespace symcontact::bench
