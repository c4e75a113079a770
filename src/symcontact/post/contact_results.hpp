#pragma once
/// \file contact_results.hpp
/// Contact quantities at the surface nodes of every pair, recovered from the contact forces of the
/// final solve (both constraint families together, plus friction; surface_tractions.hpp):
///  - nodal force f_k, pressure p_k = −f_k·n_k / A_k, tangential traction t_k (force per area), with n_k
///    the interface normal at the node (contact_points.hpp, interface_normal()): minus the opposite
///    surface's smoothed normal n̄ at the node's projection (the normal of the constraints and of
///    friction) for an obstacle or a one-pass pair; for a symmetric or self-contact pair the bisector of
///    the node's own normal and −n̄; the node's own where it projects onto nothing,
///  - gap: the signed distance θ of the node to the opposite surface (closest point, smoothed normal),
///    NaN when the node projects onto nothing,
///  - slip (friction side only, NaN elsewhere): the tangential slip increment of the load step at the
///    node, the weak average Σ_q w_q N_k s_q / Σ_q w_q N_k of the friction term's point slips,
///  - status: 0 open, 1 in contact (frictionless) or sticking, 2 slipping. In contact when the normal
///    force of the multipliers alone, −(Aᵀμ)_k·n_k, exceeds 1e-4 × its maximum over the pair (exactly
///    zero off the active set after the polish; an unpolished interior point leaves multipliers of
///    order barrier/gap, far below that, on open constraints); slipping when |slip| ≥ 7α, where the
///    regularised law reaches 99 % of the threshold.
/// Pair totals: the force on side a (Σ f_k), its normal and tangential parts, the maximum pressure, and
/// the contact length (2D) or area (3D) Σ A_k over side-a nodes in contact.

#include <string>
#include <vector>

#include "symcontact/contact/contact_set.hpp"
#include "symcontact/solvers/contact_solver.hpp"

namespace symcontact {

struct ContactSideResult {
  int surface = -1;
  Eigen::MatrixXd x;           ///< dim × n current positions x = X + u
  Eigen::MatrixXd X;           ///< dim × n reference positions: where a small-strain closed form (Hertz)
                               ///< is stated; x − X is O(p/E) of the body's size (3 % of a in V1)
  Eigen::MatrixXd force;       ///< dim × n
  Eigen::VectorXd pressure;    ///< n
  Eigen::MatrixXd tangential;  ///< dim × n tangential traction
  Eigen::VectorXd gap;         ///< n (NaN: no projection)
  Eigen::MatrixXd slip;        ///< dim × n (NaN off the friction side)
  Eigen::VectorXi status;      ///< n
};

struct ContactPairResult {
  std::string name;
  std::vector<ContactSideResult> sides;  ///< side a, then side b (absent for an analytic obstacle)
  Eigen::VectorXd total_force;           ///< on side a
  Eigen::VectorXd normal_force;          ///< Σ (f_k·n_k) n_k on side a
  Eigen::VectorXd tangential_force;      ///< total − normal
  double max_pressure = 0.0;
  double contact_measure = 0.0;          ///< length (2D) or area (3D)
};

/// From the report of the final contact solve (contact_force, multiplier_force, friction).
std::vector<ContactPairResult> contact_results(const ContactSet& contacts, const DofMap& dofs, const VectorXd& u,
                                               const ContactSolveReport& report);

}  // namespace symcontact
