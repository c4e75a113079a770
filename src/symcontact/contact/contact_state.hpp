#pragma once
/// \file contact_state.hpp
/// The contact state a solve ends with, as the post-processing reads it (post/contact_results.hpp,
/// post/step_checks.hpp): the linearised gap constraints A u + b ≥ 0 of the last geometry iterate, their
/// multipliers μ ≥ 0 (one per row of A), the forces they exert and the friction terms j of that iterate.
/// At the KKT point Aᵀμ − Σ_p ∇j_p = ∇E(u) on the free DOFs, to the optimiser's tolerance.

#include <memory>
#include <vector>

#include "symcontact/contact/contact_set.hpp"
#include "symcontact/contact/friction_term.hpp"
#include "symcontact/core/types.hpp"

namespace symcontact {

struct ContactState {
  ContactLinearization linearization;       ///< at the last geometry iterate
  VectorXd multipliers;                     ///< μ of the last solve (one per row)
  VectorXd contact_force;                   ///< F_c = Aᵀ μ (∇E(u) on free DOFs, see the solver), full DOF vector
  VectorXd multiplier_force;                ///< Aᵀ μ alone (zero exactly where no constraint is active)
  /// ∇E(u) − (Aᵀμ − ∇j) on the free DOFs of the contact surfaces where contact_force is the residual, 0
  /// elsewhere: the optimiser's error in the multipliers' balance (round-off where the polish or the dual
  /// closed the solve). j: the friction terms below.
  VectorXd force_defect;
  /// The friction terms of the last geometry iterate, per pair (null without friction).
  std::vector<std::shared_ptr<const FrictionTerm>> friction;
};

}  // namespace symcontact
