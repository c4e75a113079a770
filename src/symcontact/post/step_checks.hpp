#pragma once
/// \file step_checks.hpp
/// The checks a load step's answer must pass before the run writes it as converged (app/run.cpp). They look
/// at the answer itself, not at what the solver reported, so that a solve that "succeeded" on a wrong
/// problem (bodies pushed through each other, a body left free) is not reported as a result:
///
/// 1. **Finite values**: every displacement, the gradient ∇E(u) and the contact multipliers are finite.
/// 2. **Penetration** (contact/penetration.hpp): no contact node lies deeper than
///    kPenetrationRelativeTolerance × h (25 % of the local element size) inside the other body of its pair,
///    behind the other surface after starting in front of it, or behind an analytic obstacle. Global: not
///    limited to the contact search's distance or active set. A pair in small sliding (geometry =
///    "reference") is held instead to the gaps its solve enforces, linearised at the reference configuration
///    (find_linearized_penetrations()); its depth in the deformed configuration beyond the tolerance is a
///    warning (StepCheckFigures::warnings), for it then measures the model's assumption, not the solve.
/// 3. **Equilibrium of each body**: on the free DOFs of body b, r = ∇E(u) + ∇j(u) − Aᵀμ (E the bodies'
///    energy: elastic minus the loads' work; j the regularised friction terms of the last solve; A, μ the
///    gap constraints of the last geometry iteration and their multipliers), and
///    ‖r_b‖₂ ≤ kEquilibriumRelativeTolerance × F with F the force scale of the step:
///    max(‖f_ext‖₂, ‖∇E(u) on the fixed DOFs‖₂ (the reactions), ‖Aᵀμ‖₂, F_b), where the floor
///    F_b = kRoundOffStrain × (λ + 2μ) × L_b^(dim−1) (the small-strain moduli of the body's stiffest
///    material, L_b the diagonal of its bounding box) is the force a strain of kRoundOffStrain makes
///    across the body. Without it a
///    step whose forces are all round-off (a rigid motion imposed on a hyperelastic body, which is
///    stress-free) would be measured against round-off; the elastic forces' own round-off,
///    about 1e-16 (λ + 2μ) L_b^(dim−1), stays well below 1e-6 F_b.
///
/// 4. **Nodes held into the other side**: a contact row whose every DOF is prescribed (a node held by
///    Dirichlet conditions along its contact normal) has the gap the prescribed displacements give it, which
///    contact cannot change; deeper than kHeldDepthTolerance × h it is an error naming the node. A node held
///    along its contact normal and in contact shares its force with the support in a split the problem leaves
///    open (an overconstraint): a warning.
///
/// A failed check throws SolveError naming the step, the body or pair, the node and the measured figure;
/// the run turns it into exit 3 with the finished steps kept.

#include <string>
#include <vector>

#include "symcontact/contact/contact_state.hpp"
#include "symcontact/model/model.hpp"

namespace symcontact {

/// ‖r_b‖₂ / F above which a body is not in equilibrium (see the file comment). The solvers balance forces to
/// round-off on the condensed and dual paths and to the optimiser's tolerance otherwise.
constexpr double kEquilibriumRelativeTolerance = 1e-6;
/// The depth, over the local element size, beyond which a node held by its Dirichlet conditions counts as held
/// inside the other side (check 4): its gap is exact, so only round-off is tolerated.
constexpr double kHeldDepthTolerance = 1e-8;
/// The strain whose force across a body is the floor of its force scale (see the file comment).
constexpr double kRoundOffStrain = 1e-8;

/// What the checks measured (for summary.json): the largest ‖r_b‖₂ / F over the bodies, and the largest
/// depth / h over the contact nodes (0 without contact or penetration).
struct StepCheckFigures {
  double equilibrium = 0.0;
  double penetration = 0.0;
  /// What holds but should be known: a small-sliding pair whose bodies overlap in the deformed configuration.
  std::vector<std::string> warnings;
};

/// Runs the checks on a load step's solution u, with the Dirichlet conditions `fixed` of the step
/// and, with contact, the contact state of its last contact solve (null without contact; a SolveReport is
/// one: solvers/solve_report.hpp). Throws SolveError when one fails (the run prefixes the step); returns
/// the figures otherwise.
StepCheckFigures check_step(const Model& model, const VectorXd& u, const FixedDofs& fixed,
                            const ContactState* contact);

}  // namespace symcontact
