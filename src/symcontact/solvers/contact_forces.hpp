#pragma once
/// \file contact_forces.hpp
/// The contact forces of a converged contact solve, per DOF.
///
/// At a KKT point of min E(u) + j(u) s.t. A u + b ≥ 0, the bodies' residual balances the interface:
/// ∇E(u) = Aᵀμ − ∇j(u) on the free DOFs. Aᵀμ carries the optimiser's tolerance; the residual ∇E(u) does not
/// (it balances the applied loads to round-off) and holds the whole interface force, normal and frictional.
/// So the contact force is ∇E(u) on the free DOFs of the contact surfaces, and Aᵀμ on fixed DOFs, where the
/// residual also holds the support reaction (friction forces on fixed DOFs are not recovered).
/// Condensed, the residual on B is ĝ + S y, exactly ∇E there (x_I = x_I(y)); a surface DOF outside B is
/// touched by no constraint or friction term, its residual is zero but for round-off, and Aᵀμ = 0 is kept.

#include <memory>
#include <vector>

#include "symcontact/contact/contact_set.hpp"
#include "symcontact/contact/friction_term.hpp"
#include "symcontact/energy/energy_term.hpp"
#include "symcontact/solvers/fixed_dofs.hpp"

namespace symcontact {

struct ContactForces {
  VectorXd contact_force;     ///< F_c: ∇E(u) on free surface DOFs, Aᵀμ elsewhere (full DOF vector)
  VectorXd multiplier_force;  ///< Aᵀμ alone (zero exactly where no constraint is active)
  /// ∇E(u) − (Aᵀμ − ∇j) on the free DOFs of the contact surfaces where contact_force is the residual, 0
  /// elsewhere: the optimiser's error in the multipliers' balance (round-off where the polish or the dual
  /// closed the solve).
  VectorXd force_defect;
};

/// The bodies' residual on the condensed set B of the last geometry iteration (ĝ + S y, one entry per
/// position of B) and the DOF positions in B (free numbering → position, −1 outside); absent when the last
/// iteration was not condensed.
struct CondensedResidual {
  const VectorXd* residual = nullptr;
  const std::vector<Index>* b_position = nullptr;
};

/// A: the constraint rows of the last linearisation, mu their multipliers, friction the friction terms of
/// the last geometry iterate (null entries: none), u the solution.
ContactForces recover_contact_forces(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts,
                                     const DofMap& dofs, const VectorXd& u, const SparseMatrix& A, const VectorXd& mu,
                                     const std::vector<std::shared_ptr<const FrictionTerm>>& friction,
                                     const CondensedResidual& condensed);

}  // namespace symcontact
