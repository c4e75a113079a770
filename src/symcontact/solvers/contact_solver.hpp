#pragma once
/// \file contact_solver.hpp
/// Algorithm 2 of the talk (METHOD.md): the geometry fixed point of the symmetric contact problem.
///
///   repeat:  linearise the contact constraints at U_n (projections, smoothed normals, contact zone);
///            U_{n+1} = argmin E(U) subject to A_n U + b_n ≥ 0, by the interior point method (IPOPT),
///            warm-started from U_n and the previous multipliers when the constraint rows match;
///   until    ‖U_{n+1} − U_n‖∞ / ‖U_{n+1}‖∞ < tolerance.
///
/// The multipliers μ ≥ 0 of the final solve give the contact forces F_c = Aᵀ μ (both constraint
/// families together: one force per node, from which a single interface pressure is recovered).

#include <string>
#include <vector>

#include <memory>

#include "symcontact/contact/contact_set.hpp"
#include "symcontact/contact/contact_state.hpp"
#include "symcontact/contact/friction_term.hpp"
#include "symcontact/core/log.hpp"
#include "symcontact/core/timer.hpp"
#include "symcontact/energy/energy_term.hpp"
#include "symcontact/optim/ipopt_solver.hpp"
#include "symcontact/solvers/fixed_dofs.hpp"

namespace symcontact {

class StaticCondensation;
class SemidefiniteFactor;
struct CondensedLoad;

/// What solve_contact keeps between calls: the static condensation of a quadratic bulk energy (its
/// Cholesky factor and Schur complement, see condensed_problem.hpp), reused while the energy object,
/// the set of free DOFs and the condensed DOFs still fit. One per run (all load steps and Coulomb
/// iterations of one model); it is rebuilt, never misused, when given another energy or Dirichlet set.
struct ContactWorkspace {
  ContactWorkspace();
  ~ContactWorkspace();
  const EnergyTerm* energy = nullptr;   ///< the energy the condensation belongs to
  std::vector<Index> free_index;        ///< its DOF → free numbering
  std::unique_ptr<StaticCondensation> condensation;
  int factorisations = 0;               ///< condensations computed (for reports and tests)
  /// The pivoted factor of the condensation's Schur complement for the dual solve, and the value of
  /// `factorisations` it belongs to.
  std::unique_ptr<SemidefiniteFactor> schur_factor;
  int schur_factor_of = -1;
  /// The load part of the condensed problem (condensed_problem.hpp) of the last solve and the value of
  /// `factorisations` it belongs to: reused while ∇E(0) (loads, Dirichlet values) is the same.
  std::shared_ptr<const CondensedLoad> load;
  int load_of = -1;
  /// The last converged solve's multipliers and the identity of its rows (family, node): the warm start of
  /// the next solve's first IPOPT call when its rows are the same.
  VectorXd multipliers;
  std::vector<int> row_family;
  std::vector<Index> row_node;
  /// The closing polish was rejected in the previous solve with a non-quadratic energy (friction): the
  /// next such solve balances forces only and skips that attempt. On the inclined interface with Coulomb
  /// friction it was rejected in every solve (the point it reaches violates a constraint outside its set,
  /// and for a non-quadratic energy the set does not grow), at more than half the contact time.
  bool closing_polish_rejected = false;
  /// The last solve left u's interior out of date (ContactSolveOptions::lazy_interior): complete_interior().
  bool interior_pending = false;
};

struct ContactSolveOptions {
  double geometry_tolerance = 1e-6;
  /// An inexact solve when above geometry_tolerance: the fixed point stops once the change is below this,
  /// and its answer is taken as an intermediate one: the force-balancing polish of a non-quadratic energy
  /// (applied once, to the iterate that ends the fixed point) is left out and ContactSolveReport::converged
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
  /// stays open by ~1e5·tol (relative, measured on the V3 patch test) — hence the polish below.
  IpoptOptions ipopt;
  /// Remove that offset after each IPOPT solve (active_set_polish.hpp); quadratic energies only.
  bool polish = true;
  /// Static condensation onto the contact DOFs when the bodies' energy is quadratic (linear elasticity):
  /// one Cholesky factorisation of the stiffness serves every IPOPT iteration, geometry iteration and
  /// load step, and IPOPT works on the condensed set only. Same solution (to the optimiser's tolerance);
  /// off only to compare.
  bool condense = true;
  /// Largest condensed set |B| (DOFs) for which the solver condenses; above it the whole problem goes to
  /// IPOPT (which in 3D costs 10–30 times more already at 2e4 DOFs: docs/performance.md). S is dense, so the
  /// condensed problem costs memory and time that grow with |B|², resp. |B|³, besides the factor of K:
  /// S itself (static_condensation.hpp), its pivoted Cholesky factor, W = A S⁺ Aᵀ of the dual and the
  /// interior point's factor of it (or, on the primal path, IPOPT's KKT factorisation, dense in effect):
  /// about 25 bytes per entry of the |B| × |B| matrix with the dual's dense interior point, 73–84 with IPOPT
  /// on the dual (peak RSS of the 3D Hertz solve beyond the factor and the model, at |B| = 3,282 and 5,224;
  /// docs/performance.md), i.e. about 3.4 GiB at 12,000, and O(|B|³) time per optimiser iteration. The 3D
  /// Hertz sphere on its plane has |B| = 5,224 at 4e5 DOFs (the limit was 4,000 until that size was run) and
  /// about 9,500 at 1e6.
  Index max_condensed_dofs = 12000;
  /// Solve a condensed problem without friction terms through its dual (dual_condensed_problem.hpp): IPOPT
  /// works on the m contact multipliers with bounds, on a Hessian formed once per geometry iteration, instead
  /// of on the |B| condensed DOFs with m inequalities and a dense |B| × |B| KKT factorisation at each of its
  /// iterations; the displacements follow exactly from the multipliers (forces balanced with no optimiser
  /// error). Same solution to the optimiser's tolerance; off only to compare.
  bool dual = true;
  /// The optimiser of that dual: the dense interior point of dense_qp_interior_point.hpp (default: each of its
  /// iterations one LAPACK Cholesky of the m × m matrix), or IPOPT (MUMPS factorising the dense matrix as a
  /// sparse one: about 3 times the time and 10 m² doubles of workspace). Same solution to the tolerance
  /// (IpoptOptions::tolerance is used by both). A failed interior point solve falls back to IPOPT. Used only
  /// where the rows are independent (no symmetric pair, no self-contact: the dual's λ is unique); IPOPT
  /// otherwise.
  bool dual_interior_point = true;
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
  /// B (the interior does not move). Needs `workspace`.
  bool lazy_interior = false;
};

/// A fixed point that stagnates at the noise floor of its optimiser (the geometry fixed point here, the Coulomb
/// fixed point of frictional_contact.hpp) tightens it at most this many times, by tighten_optimiser() each.
constexpr int kMaxTightenings = 2;
/// IPOPT's tolerance × 1e-2 (also a `tol` given in the problem file's [ipopt] table); the dense interior point of
/// the dual reads the same tolerance.
void tighten_optimiser(IpoptOptions& o);

/// Makes u whole after solves with ContactSolveOptions::lazy_interior: the interior DOFs from u's condensed
/// entries and the workspace's factor and load part (those of the last solve), x_I = −K_II⁻¹(r₀_I + K_IB x_B).
/// Does nothing when the workspace has nothing pending. `energy` and `fixed` must be those of the last solve.
void complete_interior(const EnergyTerm& energy, const FixedDofs& fixed, VectorXd& u, ContactWorkspace& workspace);

/// Friction thresholds for one solve (regularised Tresca, Algorithm 2 with j_{α,τ} added).
struct FrictionState {
  /// Per pair: τ at the nodes of the slave surface of the pair's friction family (empty: no friction).
  std::vector<Eigen::VectorXd> nodal_tau;
  VectorXd u_start;  ///< displacement at the start of the load step (slip increments are measured from it)
  /// The thresholds the previous load step converged to (empty on the first step): with nodal_tau, the
  /// last two steps' τ for the predictor of the next step (FrictionalOptions::extrapolate).
  std::vector<Eigen::VectorXd> previous_tau;
};

/// The statistics of a solve and the contact state it ended with (contact/contact_state.hpp: linearization,
/// multipliers, forces, friction terms), which is what the post-processing reads.
struct ContactSolveReport : ContactState {
  int geometry_iterations = 0;
  int ipopt_iterations = 0;                 ///< summed over the geometry iterations
  std::vector<int> ipopt_per_iteration;
  std::vector<double> change_history;       ///< relative change after each geometry iteration
  /// A solve to geometry_tolerance (not an inexact one: ContactSolveOptions::loose_geometry_tolerance) that
  /// reached it (always, unless inexact); a non-quadratic energy's last iterate was then force-balanced.
  bool converged = false;
  std::string ipopt_status;                 ///< of the last solve
  Index num_free = 0;
  Index num_constraints = 0;                ///< of the last linearisation
  Index num_condensed = 0;                  ///< DOFs IPOPT worked on when condensed (0: not condensed)
  int condensation_factorisations = 0;      ///< factorisations for the condensation in this call
  int dual_solves = 0;                      ///< geometry iterations solved through the dual (ContactSolveOptions::dual)
  bool interior_deferred = false;           ///< u's interior was left out of date (ContactSolveOptions::lazy_interior)
  PhaseTimes times;                         ///< "search" (geometry), "optimizer", "assembly"
};

/// On entry u is the starting point (previous load step); on exit the solution. `energy` is the bodies'
/// energy (elastic + loads); friction terms, rebuilt at each geometry iteration from `friction`, are
/// added to it. Throws SolveError (with the IPOPT status or the fixed-point history) when a solve fails
/// or the fixed point does not converge; u then holds the last iterate.
ContactSolveReport solve_contact(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts,
                                 const DofMap& dofs, VectorXd& u, const ContactSolveOptions& options,
                                 const Logger& log, const FrictionState* friction = nullptr);

}  // namespace symcontact
