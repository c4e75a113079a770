#pragma once
/// \file frictional_contact.hpp
/// One load step of frictional contact: Algorithm 1 of the talk (METHOD.md) around Algorithm 2.
///
///  - Tresca pairs: the threshold τ is given; one regularised-Tresca solve (solve_contact).
///  - Coulomb pairs: the thresholds are the lagged term of the step's outer loop (lagged_fixed_point.hpp: the
///    loop, its relaxation, inexact inner solves and stagnation remedies; coulomb_thresholds.hpp: τ = μ p, the
///    start from the previous step). A loop that does not converge throws SolveError — never reported as
///    success.
///  - Under proportional loading a step of linear-elastic bodies starts from u and τ extrapolated along the
///    previous step's increment (FrictionalOptions::extrapolate), frictionless or not.
/// With a condensed workspace the solves of the step leave u's interior out of date, and u is made whole once,
/// when the step ends, also when it throws (ContactSolveOptions::lazy_interior).

#include <optional>
#include <string>
#include <vector>

#include "symcontact/solvers/contact_solver.hpp"

namespace symcontact {

/// When the Coulomb thresholds τ = μ p are updated.
enum class CoulombUpdate {
  /// Between contact solves only: each solve is a regularised-Tresca problem with τ fixed (Algorithm 1).
  kBetweenSolves,
  /// Also inside each solve, between the iterations of the dense primal interior point where it solves the
  /// subproblem (condensed, independent rows or a 2D pair: subproblem_solver.hpp), from the pressure of its
  /// iterate, so that one solve gives a nearly consistent τ (coulomb_thresholds.hpp). The fixed point, its test
  /// and the outer loop are those of kBetweenSolves: only the number of solves and iterations changes.
  kInsideOptimizer,
};

/// The problem file's names of the choices ([contact_solver] coulomb_update): "between_solves",
/// "inside_optimizer"; nullopt for any other string. (Inline: the problem reader calls them without linking
/// the solver.)
inline const char* coulomb_update_name(CoulombUpdate u) {
  return u == CoulombUpdate::kBetweenSolves ? "between_solves" : "inside_optimizer";
}
inline std::optional<CoulombUpdate> parse_coulomb_update(const std::string& name) {
  for (const CoulombUpdate u : {CoulombUpdate::kBetweenSolves, CoulombUpdate::kInsideOptimizer})
    if (name == coulomb_update_name(u)) return u;
  return std::nullopt;
}

struct FrictionalOptions {
  /// The Tresca solves' options. Their lazy_interior is on here: the solves of a load step leave u's interior
  /// out of date (where they condense: a workspace and linear elasticity) and u is made whole once, at the end
  /// of the step — one backward solve per load step instead of one per solve. Off only to compare.
  ContactSolveOptions contact = [] {
    ContactSolveOptions o;
    o.lazy_interior = true;
    return o;
  }();
  /// ‖τ_{k+1} − τ_k‖∞ / ‖τ_k‖∞ below which the Coulomb fixed point stops.
  double coulomb_tolerance = 1e-6;
  /// Past the tolerance while it is cheap, with finite-strain bodies: a loop whose change, already below
  /// coulomb_tolerance, fell tenfold from the previous iteration takes one more, down to 1e-2 ×
  /// coulomb_tolerance at most (lagged_fixed_point.hpp). The error of a fixed point converging at a rate ρ is
  /// about ρ/(1 − ρ) × its last change, so two paths that both stop just below the tolerance still differ by
  /// about that. With finite-strain bodies the Tresca solves' IPOPT paths part within IPOPT's tolerance from
  /// one unit system to another, and converging on makes the answer independent of the path. With linear
  /// elasticity (quadratic energies) the same problem in other units takes the same path to round-off, and a
  /// second stopping decision would only add one that round-off can tip: the option does not apply there
  /// (solve_frictional_contact). Off: stop at the first change below the tolerance.
  bool converge_past_tolerance = true;
  int max_coulomb_iterations = 50;
  CoulombUpdate coulomb_update = CoulombUpdate::kInsideOptimizer;
  /// Inexact inner solves: while τ still moves, solving each Tresca problem to the geometry tolerance is
  /// wasted, so each solve's geometry fixed point stops at max(geometry_tolerance, factor × c), c the
  /// relative threshold change ‖r_k‖∞ / ‖τ_k‖∞ that set its τ (1 for the first solve of a step); such an
  /// inexact solve is not force-balanced (ContactSolveOptions::loose_geometry_tolerance). The loop still
  /// ends only on a solve to geometry_tolerance, with c below coulomb_tolerance (one more solve when τ
  /// settles on an inexact one): the same fixed point to the same tolerances. 0: every solve to
  /// geometry_tolerance. Quadratic energies (linear elasticity) only: with finite-strain bodies every
  /// solve goes to geometry_tolerance, because there the intermediate answers of inexact solves steer the
  /// load path itself (on the frictional ironing test they change its deepest penetration beyond the
  /// bound the test holds).
  double inner_tolerance_factor = 0.1;
  /// Predictor of a warm-started step (quadratic energies: linear elasticity): when this step's Dirichlet
  /// increment is s times the previous step's (proportional loading), the Coulomb fixed point starts from
  /// τ_{n−1} + s (τ_{n−1} − τ_{n−2}) (clamped at 0) and the solve from u_{n−1} + s (u_{n−1} − u_{n−2}) instead
  /// of τ_{n−1} and u_{n−1}, τ_{n−2} = 0 when step n−1 was the first (from the unloaded start, as u_{n−2} = 0);
  /// the slip increments are still measured from u_{n−1}. Without Coulomb pairs (frictionless, Tresca) only u
  /// is extrapolated: the geometry fixed point's first linearisation is then at the extrapolated u; with
  /// Coulomb pairs only where the thresholds start warm. A start only: the fixed point and its tolerances
  /// are the same. (Loads other than Dirichlet values are assumed to follow the same
  /// proportion; where they do not, the start is merely worse.)
  bool extrapolate = true;
  /// A fixed point that stagnates (FixedPointMonitor: no new low of the change in six iterations — a cycle, or
  /// the noise floor of the inner solves) has its inner solves tightened, at most twice (IPOPT's tolerance
  /// × 1e-2 and the geometry tolerance × 0.1 each time, inexact solves off). Stagnated after that, its
  /// iterate is accepted, with a warning and SolveReport::accepted_at_noise_floor, only when the last
  /// solve converged and the friction law holds to this relative tolerance: max |μ p − τ| ≤ it × max τ.
  /// Otherwise the step fails (SolveError naming what was tried).
  double stagnation_acceptance = 1e-4;
};

/// u: on entry the start of the step (also the reference of the slip increments), on exit the solution. The
/// report holds the last Tresca solve's contact state and the Coulomb loop's fields (solve_report.hpp).
/// `previous`: the friction state the previous load step ended with (its report's `friction`), or null
/// for the first step.
SolveReport solve_frictional_contact(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts,
                                          const DofMap& dofs, VectorXd& u, const FrictionalOptions& options,
                                          const Logger& log, const FrictionState* previous = nullptr);

}  // namespace symcontact
