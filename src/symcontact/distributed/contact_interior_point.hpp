#pragma once
/// \file contact_interior_point.hpp
/// Frictionless contact of a linear-elastic body with a rigid obstacle, solved across MPI ranks by a
/// primal-dual interior point whose Newton systems are solved by conjugate gradients with algebraic
/// multigrid (filtered_amg.hpp): the iterative path for problems whose Cholesky factor does not fit.
///
///     min_u ½ uᵀ K u − fᵀ u + j(u)   subject to   c_j(u) = n_jᵀ u_{p_j} − l_j ≥ 0  (j = 1 … m),   u = ū on the fixed DOFs,
///
/// one constraint per contact node p_j: its displacement along the unit normal n_j at least l_j (the
/// small-displacement gap to the obstacle along n_j, measured in the reference configuration). λ_j ≥ 0 is
/// the node's contact force along n_j. Any sparse constraint rows, one per node, may replace n_jᵀ u_{p_j}
/// (NodalConstraints::rows): below, A is the m × n matrix of the rows.
///
/// j is the optional regularised Tresca friction of NodalConstraints (convex: the problem stays convex).
///
/// Method: Mehrotra's predictor-corrector on the slack form c(u) − s = 0, s ≥ 0, λ ≥ 0 (Nocedal & Wright,
/// Numerical Optimization, 2nd ed., §16.6 and Algorithm 14.3). Each direction solves
///
///     (K + Aᵀ Σ A) Δu = −r_d − Aᵀ (S⁻¹ r_c + Σ r_p),   Σ = Λ S⁻¹,
///     Δs = A Δu + r_p,   Δλ = −S⁻¹ (r_c + Λ Δs),
///
/// with r_d = K u − f − Aᵀ λ, r_p = c(u) − s, r_c the complementarity target, both directions of an
/// iteration with the same matrix and preconditioner. One step length for u, s and λ: the largest that
/// keeps 0.5 % of s and λ (fraction to the boundary 0.995). With friction, r_d holds ∇j(u) and K above reads
/// K + H, H ∇²j(u) with each friction point's slip direction s/r in its curvature replaced by a dual estimate
/// w (|w| ≤ 1) that takes the interior point's steps (the primal-dual linearisation of Chan, Golub & Mulet,
/// 1999: the curvature along a slip no longer vanishes where the point slips at the iterate and sticks at the
/// answer); the step is then also halved until the barrier merit function
/// φ(u, s) = ½ uᵀKu − fᵀu + j(u) − μ_t Σ log s_j + ν ‖c(u) − s‖₁ (μ_t the corrector's target, ν = 2 ‖λ‖_∞ of
/// both ends of the step) decreases by at least 10⁻⁴ of its directional derivative (Armijo; Nocedal & Wright
/// §19.4); without friction the problem is a quadratic program and the full step is taken.
///
/// Scales (every test relative to the problem's own): F = ‖b‖_∞, b the load after the fixed values moved into
/// it, a nodal force (where it is 0: L times the largest diagonal entry k of K); L = max(‖ū‖_∞, max |l_j|,
/// F / k), a length — not below the displacement the largest load makes at the stiffest DOF, so that gaps
/// of faces that coincide up to round-off do not set it. Start: u = ū on the fixed DOFs, `start` (or 0) elsewhere, s = max(c(u), L),
/// λ = F. Stop when ‖r_d‖_∞ ≤ tol F on the free DOFs, ‖r_p‖_∞ ≤ tol L and min(s_j / L, λ_j / F) ≤ tol for
/// every j: each constraint is either active (s_j ≈ 0) or carries no force (λ_j ≈ 0) to tol — a test on the
/// answer, where the mean sᵀλ/m would let a node near the edge of the contact zone keep a force μ/s_j. The Krylov
/// solves stop at ‖residual‖₂ ≤ max(η ‖rhs‖₂, 0.1 tol F), η = min(0.01, μ/μ₀): loose while far from the
/// solution, down to the stopping test at the end.
///
/// Without friction the answer is polished on its active set once the interior point has told the rows apart
/// (dual and primal residuals and min(s_j/L, λ_j/F) within 10³ tol; again each time the last has fallen a
/// hundredfold): the program with the rows S = {j : λ_j/F ≥ s_j/L} held as equalities, solved by the method
/// of multipliers with the same conjugate gradients, rows added or dropped until the multipliers of S are ≥ 0
/// and no other row is violated; where that set does not settle (nearly dependent rows, as a symmetric pair's
/// two families on unmatched meshes), the method of multipliers on the inequalities themselves, which needs
/// no set. A polish that closes S to 10⁻⁴ tol L and balances the forces to 10⁻² tol F ends the solve at a
/// KKT point of the program, and is tried again where the interior point's own test ends it (the same point
/// whatever path led there); when the Krylov solve breaks down or the iterations run out, the polish of the
/// last iterate that met the dual and primal tests, to tol, rescues it. At a row at the edge of the zone,
/// degenerate (s_j/L ≈ λ_j/F ≈ 0), the interior point alone would need a barrier parameter near 10⁻²⁰ F L to
/// pass the per-row test, with Σ spanning 10⁻²² … 10¹⁵ and conjugate gradients breaking down in round-off
/// (two elastic bodies: examples/hertz_2d/two_cylinders). With friction the interior point's own test ends the
/// solve; where it breaks down or runs out of iterations, the method of multipliers on the inequalities, with
/// the friction term in its inner problems, rescues it from its last iterate within 10³ tol of the dual and
/// primal tests (a symmetric pair with Coulomb friction: examples/inclined_2d).
///
/// Distribution: as solve_elasticity_gamg() — each rank passes its share of K (the shares summing to K)
/// and owns the rows of a contiguous range of nodes; s and λ (m values) are kept whole on every rank. The
/// answer is gathered on every rank.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "symcontact/core/types.hpp"
#include "symcontact/distributed/filtered_amg.hpp"

namespace symcontact {

/// c_j(u) = n_jᵀ u_{node_j} − lower_j ≥ 0, at most one constraint per node; or, when `rows` is given,
/// c_j(u) = (rows u)_j − lower_j ≥ 0, row j still node_j's (its force λ_j, its friction), such as the weak
/// gap rows of contact/gap_constraints.hpp, each divided by its support Σ w φ_j so that c_j is a length and
/// λ_j a force. The entries of `rows` on fixed DOFs move into the constant (c is affine in the free DOFs).
struct NodalConstraints {
  std::vector<Index> node;
  Eigen::MatrixXd normal;  ///< dim × m, unit columns
  VectorXd lower;          ///< m
  SparseMatrix rows;       ///< m × num_dofs, or empty: the rows n_jᵀ at node_j
  /// Regularised Tresca friction at the same nodes, optional (empty: frictionless; else m values each):
  /// the energy j(u) = Σ_j g_j η_α_j(P_j (B_j u − v⁰_j)), η_α(v) = √(|v|² + α²), P_j = I − n_j n_jᵀ (METHOD.md,
  /// "Friction"; talk eq. 16–18 with one point per node), g_j ≥ 0 the node's friction force bound (its
  /// lumped area times the threshold τ), α_j > 0 its regularisation length. B_j (dim × num_dofs) maps u to
  /// the relative displacement of row j's friction point: rows dim·j … dim·j + dim − 1 of slip_map, or, where
  /// slip_map is empty, node p_j's displacement (an obstacle that does not move). The slip is measured from
  /// v⁰_j = B_j u⁰ in slip_origin (dim × m: u⁰ the displacement at the start of the load step), from u = 0
  /// where it is empty. Entries of B on fixed DOFs move into v⁰ (j is a function of the free DOFs).
  VectorXd friction_bound, friction_alpha;
  SparseMatrix slip_map;
  Eigen::MatrixXd slip_origin;
  Index size() const { return static_cast<Index>(node.size()); }
  bool frictional() const { return friction_bound.size() > 0; }
};

struct ContactInteriorPointOptions {
  double tolerance = 1e-9;
  /// The scaled residuals (dual, primal, complementarity of the stopping test) below which FollowBounds is
  /// called after each step (as DensePrimalOptions::follow_below).
  double follow_below = 0.1;
  int max_iterations = 80;
  int max_krylov_iterations = 2000;  ///< per Newton system
  /// F of the scales above when > 0, in place of ‖b‖_∞, which can be far above the forces of the answer (a
  /// stiff body moved by fixed values: distributed_step.cpp takes the forces of the previous answer).
  double force_scale = 0.0;
  NewtonPreconditioner preconditioner = NewtonPreconditioner::kFilteredGamg;
};

struct ContactInteriorPointResult {
  VectorXd u;       ///< every DOF, on every rank
  VectorXd lambda;  ///< m contact forces along the normals
  bool converged = false;
  std::string reason;                  ///< why it stopped when it did not converge
  int iterations = 0;                  ///< interior-point iterations (two Newton solves each)
  int polishes = 0;                    ///< accepted polishes (0 or 1: the last one ends the solve)
  int polishes_rejected = 0;           ///< polishes tried and not kept (the iterations went on from before them)
  int inequality_polishes = 0;         ///< accepted polishes made on the inequalities (no active set)
  std::vector<int> krylov_iterations;  ///< conjugate-gradient iterations of every Newton solve, in order
  double setup_seconds = 0.0;          ///< Newton matrices and preconditioners
  double krylov_seconds = 0.0;         ///< conjugate gradients
  double total_seconds = 0.0;
  double dual_residual = 0.0;    ///< ‖r_d‖_∞ / F at the end
  double primal_residual = 0.0;  ///< ‖r_p‖_∞ / L
  double complementarity = 0.0;  ///< max_j min(s_j / L, λ_j / F)
  double force_scale = 0.0, length_scale = 0.0;  ///< F and L
};

/// Friction bounds that follow the iterate (Coulomb's g_j = A_j μ p_j, p read from the iterate; as
/// FollowIterate of solvers/dense_primal_interior_point.hpp): called with u (every DOF) and λ after each
/// accepted step once the scaled residuals are at most ContactInteriorPointOptions::follow_below, while the
/// complementarity is above a thousandth of the tolerance. Returns the new bounds g (m values) when they changed, nullopt
/// otherwise. The bounds at the point the method stops are not checked here: the caller's Coulomb loop checks
/// them. Collective: every rank returns the same.
using FollowBounds = std::function<std::optional<VectorXd>(const VectorXd& u, const VectorXd& lambda)>;

/// K_share, f, fixed, fixed_values, x: as solve_elasticity_gamg() takes them. Collective over
/// PETSC_COMM_WORLD; every rank passes the same f, fixed DOFs, coordinates and constraints. `start`: u to
/// start from on the free DOFs (every DOF; null: 0), the slacks and multipliers starting as above.
/// `follow`: friction bounds that follow the iterate (null: fixed; constraints must be frictional).
ContactInteriorPointResult solve_contact_interior_point(const SparseMatrix& K_share, const VectorXd& f,
                                                        const std::vector<Index>& fixed, const VectorXd& fixed_values,
                                                        const Eigen::MatrixXd& x, const NodalConstraints& constraints,
                                                        const ContactInteriorPointOptions& options = {},
                                                        const VectorXd* start = nullptr,
                                                        const FollowBounds* follow = nullptr);

/// Coulomb friction of coefficient `mu` at the constrained nodes as a fixed point of Tresca problems (METHOD.md,
/// "Coulomb as a fixed point"): the first solve frictionless, then each with the bounds g_j = μ λ_j of the
/// previous solve's contact forces, until max_j |Δg_j| ≤ coulomb_tolerance × max_j g_j. constraints'
/// friction_alpha gives the regularisation lengths (its friction_bound is not read).
struct CoulombInteriorPointResult {
  ContactInteriorPointResult last;  ///< the last solve: the answer
  ContactInteriorPointResult all;   ///< iterations, Krylov iterations and times over every solve
  int coulomb_iterations = 0;       ///< Tresca solves after the frictionless one
  double bound_change = 0.0;          ///< max_j |Δg_j| / max_j g_j of the last update
  bool converged = false;
};

CoulombInteriorPointResult solve_coulomb_interior_point(const SparseMatrix& K_share, const VectorXd& f,
                                                        const std::vector<Index>& fixed, const VectorXd& fixed_values,
                                                        const Eigen::MatrixXd& x, NodalConstraints constraints,
                                                        double mu, double coulomb_tolerance = 1e-6,
                                                        int max_coulomb_iterations = 30,
                                                        const ContactInteriorPointOptions& options = {});

}  // namespace symcontact
