#pragma once
/// \file contact_results.hpp
/// Contact quantities of every pair, from the final solve's multipliers μ and friction terms
/// (ContactState::linearization, multipliers, friction; contact/contact_state.hpp). Each pair's force is its own:
///
///   F_p = A_pᵀ μ_p − ∇j_p(u),   normal part A_pᵀ μ_p,   tangential part −∇j_p,
///
/// A_p the pair's constraint rows (both families of a symmetric pair; gap_constraints.hpp), j_p its friction
/// term (friction_term.hpp). The normal part is, row by row, along the row's own normals (those of the
/// frozen gaps θ_q), so a frictionless pair has a tangential part of exactly zero; nothing is projected on
/// nodal normals. At the KKT point Aᵀμ − Σ_p ∇j_p = ∇E(u) on the free DOFs, to the optimiser's tolerance
/// (round-off where the polish or the dual closed the solve); that defect (ContactState::force_defect)
/// is added to the normal part of the pair whose rows alone reach the DOF, so that the reported forces
/// balance the loads as the residual does (the frictional patch tests: 1e-6 of p otherwise). Per side and
/// per pair, total = normal + tangential as vectors; Σ over the pairs of the forces on a body's surface is
/// the body's contact force, ∇E(u) on its free surface DOFs (but for the defect at DOFs two pairs reach);
/// by action and reaction (each row's slave and master parts cancel, as do each friction point's) side b
/// carries −side a where both are deformable (to the defect).
///
/// Sides: side a (surface a) and side b (surface b) of a two-body pair; an obstacle pair has side a only;
/// a self-contact pair has one side, the surface, whose total force is zero by action and reaction (its
/// magnitude is `normal_load`). A rigid meshed side has no DOFs and reports zero force.
///
/// Per node k of a side (f_k = n_k + t_k the nodal force of the pair, n_k from A_pᵀμ_p, t_k from −∇j_p):
///  - pressure p_k = −(T n)_k·ν_k / A_k and tangential traction (T t)_k / A_k (force per reference area:
///    A_k = ∫ φ_k dS the lumped reference area of THIS side, T the test basis of surface_tractions.hpp),
///    with ν_k the interface normal (contact_points.hpp, interface_normal()): minus the opposite surface's
///    smoothed normal n̄ at the node's projection for an obstacle or a one-pass pair; the bisector of the
///    node's own normal and −n̄ for a symmetric pair; −m, the bisector ray's normal, for self-contact; the
///    node's own where it projects onto nothing. Both sides of a symmetric pair carry the same force over
///    the same current interface, each per its own reference area: their pressures differ by the ratio of
///    the two sides' tangential stretches (1 + O(p/E)), besides discretisation error,
///  - current_pressure p_k A_k / a_k, a_k the lumped area in the current configuration (lumped_areas(),
///    contact_surface.hpp): the same force per current area, in which the sides share one interface, so
///    that both sides' agree to discretisation error (two-material Hertz cylinders, peak: 2.1 % apart per
///    reference length, 2.3e-4 per current length),
///  - gap: the signed distance θ of the node to the opposite surface (closest point, smoothed normal),
///    NaN when the node projects onto nothing. For a pair in ContactGeometry::kReference
///    (contact_geometry.hpp) the normals ν_k and the gap are those the solver used: ν_k of X, and the
///    linearised gap θ(X) + d·(u_s − u_m(η̄)) at the node's projection η̄ of X,
///  - slip (friction side only, NaN elsewhere): the tangential slip increment of the load step at the
///    node, the weak average Σ_q w_q N_k s_q / Σ_q w_q N_k of the friction term's point slips (with the
///    solver's nodal points the node's own point slip: on a Tri6 surface its coefficient s̃_k in the test
///    basis, friction_term.hpp, the slip the law's traction τ s̃_k / r_k and the status below read),
///  - in 2D, along the tangent τ_k = (−ν_y, ν_x) (ν_k turned by +90°: the direction in which the side is
///    traversed with its body on the left, counter-clockwise round a body's outer boundary; the two sides of
///    a pair have opposite tangents): the signed magnitudes tangential_along_k = ±|t_k| and slip_along_k = ±|s_k|,
///    the sign that of t_k·τ_k (of s_k·τ_k), so that |tangential_along| is exactly the norm of the traction.
///    Friction opposes slip: on a slipping node of the friction side the two have opposite signs,
///  - status: 0 open, 1 in contact (frictionless) or sticking, 2 slipping. In contact where the pressure of
///    Aᵀμ_p alone exceeds kContactPressureFraction × its maximum (exactly zero where no active row reaches the
///    node; an unpolished interior point leaves multipliers of order barrier/gap, far below that, on open
///    constraints), open elsewhere. Slipping where, in contact, the regularised law's traction has reached
///    the threshold: |t|/τ = |s|/√(|s|² + α²) ≥ kSlipRatio (|s| ≥ 22.3 α), sticking otherwise.
/// Pair totals: the force on side a (the surface for self-contact) and its normal and tangential parts,
/// normal_load = Σ_r μ_r Σ_q w_q φ_r(ξ_q) = ∫ λ dΓ over the pair's rows (the interface counted once; for
/// a flat interface |normal_force|), the maximum pressure over the sides, and the contact length (2D) or
/// area (3D) Σ A_k over side-a nodes in contact.

#include <string>
#include <vector>

#include "symcontact/contact/contact_set.hpp"
#include "symcontact/contact/contact_state.hpp"
#include "symcontact/fem/dof_map.hpp"

namespace symcontact {

/// A node is in contact where its pressure exceeds this fraction of the pair's largest.
constexpr double kContactPressureFraction = 1e-4;
/// A node in contact slips where |t| ≥ kSlipRatio τ, t the regularised law's traction.
constexpr double kSlipRatio = 1.0 - 1e-3;

struct ContactSideResult {
  int surface = -1;
  Eigen::MatrixXd x;           ///< dim × n current positions x = X + u
  Eigen::MatrixXd X;           ///< dim × n reference positions: where a small-strain closed form (Hertz)
                               ///< is stated; x − X is O(p/E) of the body's size (3 % of a in V1)
  Eigen::MatrixXd displacement;  ///< dim × n displacements u at the nodes (zero on a rigid side)
  Eigen::MatrixXd force;       ///< dim × n nodal force of the pair: normal_part + the friction part
  Eigen::MatrixXd normal_part; ///< dim × n nodal A_pᵀ μ_p
  Eigen::MatrixXd normals;     ///< dim × n interface normals ν_k of the pressure
  Eigen::VectorXd pressure;    ///< n, per lumped reference area of this side
  Eigen::VectorXd current_pressure;  ///< n, the same force per current lumped area a_k: p_k A_k / a_k
  Eigen::MatrixXd tangential;  ///< dim × n tangential traction
  Eigen::VectorXd gap;         ///< n (NaN: no projection)
  Eigen::MatrixXd slip;        ///< dim × n (NaN off the friction side)
  Eigen::VectorXd tangential_along;  ///< 2D: n, ±|tangential| along τ_k (empty in 3D)
  Eigen::VectorXd slip_along;        ///< 2D: n, ±|slip| along τ_k (NaN off the friction side; empty in 3D)
  Eigen::VectorXi status;      ///< n
  Eigen::VectorXd total_force;       ///< Σ_k force
  Eigen::VectorXd normal_force;      ///< Σ_k normal_part
  Eigen::VectorXd tangential_force;  ///< Σ_k of the friction part (exactly 0 without friction)
};

struct ContactPairResult {
  std::string name;
  std::vector<ContactSideResult> sides;  ///< side a, then side b (absent for an analytic obstacle)
  Eigen::VectorXd total_force;           ///< on side a (sides[0].total_force)
  Eigen::VectorXd normal_force;          ///< sides[0].normal_force
  Eigen::VectorXd tangential_force;      ///< sides[0].tangential_force
  double normal_load = 0.0;              ///< ∫ λ dΓ over the pair's rows
  double max_pressure = 0.0;
  double contact_measure = 0.0;          ///< length (2D) or area (3D)
};

/// From the contact state of the final contact solve (linearization, multipliers, friction); a
/// SolveReport is one (solvers/solve_report.hpp).
std::vector<ContactPairResult> contact_results(const ContactSet& contacts, const DofMap& dofs, const VectorXd& u,
                                               const ContactState& state);

}  // namespace symcontact
