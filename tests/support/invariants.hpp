#pragma once
/// \file invariants.hpp
/// Test helper: the checks a contact solution must pass that need no reference solution.
///  - equilibrium of every body: r = ∇E(u) + Σ_p ∇j_p(u) − Aᵀμ on its free DOFs (E the bodies' energy, j_p
///    the friction terms of the last solve, A and μ its last linearisation and multipliers: the KKT
///    condition of the contact solve), relative to the largest force of the problem (max |∇E(u)|, which
///    holds the reactions, and max |Aᵀμ|);
///  - penetration: the smallest nodal gap of every contact surface, relative to its smallest facet size h;
///  - the Coulomb law: the largest excess max(0, |t_k| − μ p_k) of the tangential traction over the threshold
///    at the nodes of each Coulomb pair's friction side (where its slips are defined), relative to μ max p.

#include "support/solve_case.hpp"

namespace symcontact::testing {

struct Invariants {
  double equilibrium = 0.0;     ///< max over bodies of ‖r‖∞ / force scale
  double penetration = 0.0;     ///< max over surfaces of max(0, −min gap) / h
  double friction_excess = 0.0; ///< max over Coulomb pairs of max_k (|t_k| − μ p_k)⁺ / (μ max p)
};

Invariants measure_invariants(const SolvedCase& c);

}  // namespace symcontact::testing
