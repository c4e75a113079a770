#pragma once
/// \file contact_solver.hpp
/// Algorithm 2 of the talk (METHOD.md): the geometry fixed point of the symmetric contact problem, in stages.
///
///   repeat:  linearise the contact constraints at U_n: projections, smoothed normals, contact zone
///              (contact/contact_set.hpp);
///            add the friction terms of the thresholds τ at U_n (friction_state.hpp);
///            condense onto the contact DOFs when the bodies' energy is quadratic (condensation_cache.hpp);
///            U_{n+1} = argmin E(U) + j_τ(U) subject to A_n U + b_n ≥ 0 (subproblem.hpp): the primal by the
///              dense primal interior point (condensed; independent rows, any in 2D) or IPOPT
///              (primal_subproblem.hpp) or, condensed and frictionless, the dual by the dense interior point
///              or IPOPT (dual_subproblem.hpp), each warm-started from the previous multipliers when the
///              constraint rows match;
///            remove the interior point's barrier offset (polish_strategy.hpp);
///            accelerate while the map is smooth (anderson_acceleration.hpp);
///   until    ‖U_{n+1} − U_n‖∞ / ‖U_{n+1}‖∞ < tolerance.
///
/// The multipliers μ ≥ 0 of the final solve and the bodies' residual give the contact forces
/// (contact_forces.hpp: both constraint families together, one force per node, from which a single
/// interface pressure is recovered). The Coulomb fixed point around it: frictional_contact.hpp.

#include <memory>
#include <string>
#include <vector>

#include "symcontact/contact/contact_set.hpp"
#include "symcontact/contact/contact_state.hpp"
#include "symcontact/contact/friction_term.hpp"
#include "symcontact/core/log.hpp"
#include "symcontact/core/timer.hpp"
#include "symcontact/energy/energy_term.hpp"
#include "symcontact/optim/ipopt_solver.hpp"
#include "symcontact/solvers/condensation_cache.hpp"
#include "symcontact/solvers/fixed_dofs.hpp"
#include "symcontact/solvers/friction_state.hpp"
#include "symcontact/solvers/solve_report.hpp"
#include "symcontact/solvers/subproblem_solver.hpp"

namespace symcontact {

struct ContactSolveOptions {
  /// ‖U_{n+1} − U_n‖∞ / ‖U_{n+1}‖∞ below which the geometry fixed point stops.
  double geometry_tolerance = 1e-6;
  /// An inexact solve when above geometry_tolerance: the fixed point stops once the change is below this,
  /// and its answer is taken as an intermediate one: the force-balancing polish of a non-quadratic energy
  /// (applied once, to the iterate that ends the fixed point) is left out and SolveReport::converged
  /// is false, even where the change happens to fall below geometry_tolerance. Set by the Coulomb fixed
  /// point while the thresholds still move (frictional_contact.hpp), where a solve to geometry_tolerance
  /// (and its polish) would be wasted. 0: a solve to geometry_tolerance.
  double loose_geometry_tolerance = 0.0;
  int max_geometry_iterations = 50;
  /// Memory of the Anderson acceleration of the geometry fixed point (anderson_acceleration.hpp); 0: the
  /// plain iteration. Quadratic energies (linear elasticity) only. It is applied only between iterations
  /// with the same constraint rows, each closed exactly by the active-set polish on the same active set
  /// (there the map U_n → U_{n+1} = G(U_n) is smooth); any other iteration restarts it. The fixed point is
  /// the same: the solve still stops when ‖G(U_n) − U_n‖∞ / ‖G(U_n)‖∞ is below `geometry_tolerance`, and
  /// returns G(U_n).
  int geometry_acceleration = 5;
  /// IPOPT settings. An interior point leaves every active constraint open by about μ_barrier/μ_i; with
  /// the nearly dependent families of the symmetric formulation some μ_i are small and the interface
  /// stays open by ~1e5·tol (relative; the V3 patch test) — hence the polish below.
  IpoptOptions ipopt;
  /// Remove that offset after each IPOPT solve (active_set_polish.hpp); quadratic energies only.
  bool polish = true;
  /// Static condensation onto the contact DOFs when the bodies' energy is quadratic (linear elasticity):
  /// one Cholesky factorisation of the stiffness serves every IPOPT iteration, geometry iteration and
  /// load step, and IPOPT works on the condensed set only. Same solution (to the optimiser's tolerance);
  /// off only to compare.
  bool static_condensation = true;
  /// Largest condensed set |B| (DOFs) for which the solver condenses; above it the whole problem goes to
  /// IPOPT (which in 3D costs 10–30 times more already at 2e4 DOFs: docs/performance.md). S is dense, so the
  /// condensed problem costs memory and time that grow with |B|², resp. |B|³, besides the factor of K:
  /// S itself (static_condensation.hpp), its pivoted Cholesky factor, W = A S⁺ Aᵀ of the dual and the
  /// interior point's factor of it (or, on the primal path, IPOPT's KKT factorisation, dense in effect):
  /// about 25 bytes per entry of the |B| × |B| matrix with the dual's dense interior point, 73–84 with IPOPT
  /// on the dual (docs/performance.md: peak memory of the 3D Hertz solve beyond the factor and the model),
  /// i.e. about 3.4 GiB at 12,000, and O(|B|³) time per optimiser iteration. The 3D Hertz sphere on its plane
  /// has |B| = 5,224 at 4e5 DOFs and about 9,500 at 1e6.
  Index max_condensed_dofs = 12000;
  /// How each geometry iteration's subproblem is solved (SubproblemSolver).
  SubproblemSolver subproblem_solver = SubproblemSolver::kDualInteriorPoint;
  /// How the dense primal interior point's warm-started subproblems start (WarmStart).
  WarmStart warm_start = WarmStart::kActiveSet;
  /// Which form of a condensed frictional subproblem IPOPT optimises (IpoptProblem).
  IpoptProblem ipopt_problem = IpoptProblem::kAutomatic;
  /// Reused between calls when set (create one per run); a fresh one per call when null.
  std::shared_ptr<ContactWorkspace> workspace;
  /// The caller vouches that the loads and Dirichlet values are those of the previous solve with this
  /// workspace (the Coulomb iterations of a load step): the condensation's load part is then reused without
  /// evaluating ∇E(0) to compare (an assembly over the whole mesh per solve).
  bool same_loads = false;
  /// Leave the interior DOFs of u out of date, where the solve is condensed onto a set B that holds every free
  /// DOF of the contact surfaces: on exit u's B entries (the surfaces among them) are the solution's, the others
  /// as they were, and the workspace records it (ContactWorkspace::interior_pending); complete_interior() makes
  /// u whole (one backward solve). Each geometry iteration and each solve otherwise expands the interior by one
  /// backward solve with the factor, which nothing between two Tresca solves of a Coulomb fixed point reads
  /// (pressures and slips live on the surfaces, the next search too). Its fixed point's change is then that of
  /// B (the interior does not move). Needs `workspace`. Off by default, so a lone solve returns u whole; the
  /// Coulomb loop's options turn it on (FrictionalOptions::contact), and a caller that solves once with a copy
  /// of those turns it off again.
  bool lazy_interior = false;
};

/// A fixed point that stagnates at the noise floor of its optimiser (the geometry fixed point here, the Coulomb
/// fixed point of frictional_contact.hpp) tightens it at most this many times, by tighten_optimiser() each.
constexpr int kMaxTightenings = 2;
/// IPOPT's tolerance × 1e-2 (also a `tol` given in the problem file's [ipopt] table); the dense interior point of
/// the dual reads the same tolerance. Inline: the distributed program's Coulomb loop uses it without IPOPT.
inline void tighten_optimiser(IpoptOptions& o) {
  o.tolerance *= 1e-2;
  if (auto it = o.numeric_options.find("tol"); it != o.numeric_options.end()) it->second *= 1e-2;
}

/// On entry u is the starting point (previous load step); on exit the solution. The report's fields of the
/// Coulomb fixed point and of the load step are left empty. `energy` is the bodies'
/// energy (elastic + loads); friction terms, rebuilt at each geometry iteration from `friction`, are
/// added to it. Throws SolveError (with the IPOPT status or the fixed-point history) when a solve fails
/// or the fixed point does not converge; u then holds the last iterate.
SolveReport solve_contact(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts,
                                 const DofMap& dofs, VectorXd& u, const ContactSolveOptions& options,
                                 const Logger& log, const FrictionState* friction = nullptr);

}  // namespace symcontact
