#pragma once
/// \file contact_results.hpp
/// Contact quantities at the surface nodes, recovered from the contact forces F_c = Aᵀ μ of the final
/// solve (the multipliers of BOTH constraint families together):
///  - nodal force f_k (force the other body exerts on this node),
///  - pressure p_k = −f_k·n_k / A_k, with n_k the smoothed outward normal and A_k = ∫ N_k dS the lumped
///    reference area — one interface pressure, seen from each side,
///  - gap: the signed distance θ of the node to the opposite surface (closest point, smoothed normal),
///    NaN when the node projects onto nothing,
///  - status: 1 (contact) when p_k > 1e-4 · max p over the pair, else 0 (an interior point leaves
///    multipliers of order barrier/gap, far below that, on open constraints).
/// Pair totals: the force on side a (Σ f_k), the maximum pressure, and the contact length (2D) or area (3D)
/// Σ A_k over side-a nodes in contact.

#include <string>
#include <vector>

#include "symcontact/contact/contact_set.hpp"

namespace symcontact {

struct ContactSideResult {
  int surface = -1;
  Eigen::MatrixXd x;          ///< dim × n current positions
  Eigen::MatrixXd force;      ///< dim × n
  Eigen::VectorXd pressure;   ///< n
  Eigen::VectorXd gap;        ///< n (NaN: no projection)
  Eigen::VectorXi status;     ///< n
};

struct ContactPairResult {
  std::string name;
  std::vector<ContactSideResult> sides;  ///< side a, then side b (absent for an obstacle)
  Eigen::VectorXd total_force;           ///< on side a
  double max_pressure = 0.0;
  double contact_measure = 0.0;          ///< length (2D) or area (3D)
};

std::vector<ContactPairResult> contact_results(const ContactSet& contacts, const DofMap& dofs, const VectorXd& u,
                                               const VectorXd& contact_force);

}  // namespace symcontact
