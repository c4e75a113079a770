#pragma once
/// \file geometry_subproblem.hpp
/// The subproblem of one geometry iteration (Algorithm 2 of METHOD.md), built and solved:
///     U_{n+1} = argmin E(U) + Σ_pairs j_τ(U)  subject to  A_n U + b_n ≥ 0,
/// with A_n, b_n the contact constraints linearised at U_n (contact_set.hpp) and j_τ the friction terms of the
/// thresholds τ at U_n (friction_state.hpp; none without friction). When the bodies' energy is quadratic the
/// problem is condensed onto the contact DOFs B (condensed_problem.hpp, one factor of K for the whole run in
/// the ContactWorkspace). It is then solved by the dual where it applies (condensed, no friction term,
/// constraints present: dual_subproblem.hpp) and otherwise, or when the dual fails, by the primal, the
/// reference formulation (primal_subproblem.hpp); which method of each is SubproblemSolver's choice. Where IPOPT
/// solves the primal of a condensed problem whose dense KKT block would cost more than a sparse factorisation of
/// K_ff (IpoptProblem), it optimises the uncondensed problem, and the answer is restricted to B for the condensed
/// problem's polish.

#include <memory>
#include <vector>

#include "symcontact/solvers/composite_energy.hpp"
#include "symcontact/solvers/condensation_cache.hpp"
#include "symcontact/solvers/condensed_problem.hpp"
#include "symcontact/solvers/contact_solver.hpp"
#include "symcontact/solvers/dual_subproblem.hpp"
#include "symcontact/solvers/primal_subproblem.hpp"
#include "symcontact/solvers/reduced_problem.hpp"

namespace symcontact {

class GeometrySubproblem {
 public:
  GeometrySubproblem(const EnergyTerm& energy, const FixedDofs& fixed, const ContactSet& contacts, const DofMap& dofs,
                     const ContactSolveOptions& options, ContactWorkspace& workspace, const Logger& log,
                     const FrictionState* friction);
  GeometrySubproblem(const GeometrySubproblem&) = delete;  // problem_ calls back into this object
  GeometrySubproblem& operator=(const GeometrySubproblem&) = delete;

  /// The bodies' energy with the friction terms on the free DOFs: restrict() and expand() between u and x.
  const ReducedProblem& reduced() const { return problem_; }

  /// Sets the rows of `lin` and the friction terms of the iterate u_it, and condenses when the energy is
  /// quadratic (x: u_it's free DOFs). Returns the problem the optimiser sees, condensed() or the whole one.
  ConstrainedProblem& build(const ContactLinearization& lin, const VectorXd& u_it, const VectorXd& x,
                            PhaseTimes& times);
  /// Whether the subproblem linearised at u_it (rows `lin`) is that of the last build(): the same rows with the
  /// same A bit for bit, b within `b_tolerance` (in b's units, a length), and the same friction points in every
  /// field a FrictionTerm reads. Then the last build's solution solves it too, to b_tolerance. So it is for a
  /// pair in ContactGeometry::kReference, and for a rigid plane while no point enters or leaves the search
  /// distance (its rows are the plane's normal; b only moves by round-off).
  bool unchanged(const ContactLinearization& lin, const VectorXd& u_it, double b_tolerance) const;
  /// The problem of the last build(), as the optimiser sees it: condensed() or the whole one.
  ConstrainedProblem& target();
  /// The condensed problem of the last build(); null when it was not condensed.
  const CondensedProblem* condensed() const { return condensed_.get(); }
  /// The friction term of each pair at the last build() (null for a frictionless pair), for the reported slips.
  std::vector<std::shared_ptr<const FrictionTerm>> friction_terms() const {
    return {friction_terms_.begin(), friction_terms_.end()};
  }

  /// What solve() returns: the method's solution and whether the dual gave it.
  struct Outcome {
    SubproblemSolution solution;
    bool dual = false;
  };
  /// The subproblem of the last build() from the iterate x (free DOFs), its multipliers warm-started from
  /// `warm` (subproblem.hpp). The dual's attempts and the iterations of a failed one are added to rep.
  Outcome solve(const VectorXd& x, int geometry_iteration, const SubproblemWarmStart& warm, const IpoptOptions& ipopt,
                bool close_active_set, SolveReport& rep);

 private:
  const EnergyTerm& energy_;
  const FixedDofs& fixed_;
  const ContactSet& contacts_;
  const DofMap& dofs_;
  const ContactSolveOptions& options_;
  ContactWorkspace& workspace_;
  const Logger& log_;
  const FrictionState* friction_;
  CompositeEnergy total_;
  ReducedProblem problem_;  ///< the bodies' energy with the friction terms
  ReducedProblem bulk_;     ///< the bodies' energy alone (static condensation)
  const bool condense_;
  std::shared_ptr<const CondensedLoad> condensed_load_;  ///< of this solve's Dirichlet values and loads
  std::unique_ptr<DualIpopt> dual_;                       ///< null: the dual is not used
  std::unique_ptr<PrimalIpopt> primal_;
  std::unique_ptr<CondensedProblem> condensed_;
  std::vector<std::shared_ptr<FrictionTerm>> friction_terms_;
  ContactLinearization last_;  ///< the rows of the last build()
  /// The thresholds follow the optimiser's iterates (FrictionState::follower, given only where the primal
  /// interior point solves the subproblems): every friction term is kept, zero thresholds too.
  bool follows_ = false;
  /// Who may take the uncondensed problem by the cost rule (CondensationLimits::sparse_alternative).
  SparseAlternative sparse_alternative_ = SparseAlternative::kNone;
  /// The friction terms' second derivative: the primal-dual model where the primal interior point and its
  /// active-set Newton solve the subproblems (their line searches halved step after step where slips turn
  /// under the exact one; IPOPT where they fail takes the model too, positive semidefinite like the exact
  /// one), the exact one where IPOPT solves them.
  FrictionHessian friction_hessian_ = FrictionHessian::kExact;

  /// The optimiser's hook (Subproblem::follow) on `condensed`, or on the whole reduced problem where it is null:
  /// the follower sets the nodal thresholds, and the friction terms take them at their points.
  std::function<bool(const VectorXd&, const VectorXd&)> follow_hook(CondensedProblem* condensed);
  /// The bodies' force on the surfaces at the reduced problem's x (see the .cpp).
  VectorXd surface_force(const VectorXd& x, const VectorXd& multipliers);
  /// Sets the fixed DOFs of `force` (full-DOF) to the multipliers' force Aᵀλ there, as the solve's contact
  /// force has it (contact_forces.hpp), so that a pressure read at a node with a fixed DOF is the same number.
  void add_fixed_dof_force(const VectorXd& multipliers, VectorXd& force) const;
  /// The free DOFs of the start of the load step, moved as at its first solve: the primal's retry with friction.
  VectorXd step_start() const;
  /// The primal method on the whole reduced problem for the condensed one `p` (SparseAlternative::kOptimiser):
  /// its answer restricted to B, in p.target's variables.
  SubproblemSolution solve_uncondensed(const Subproblem& p, const CondensedProblem& condensed, const VectorXd& x,
                                       const SubproblemWarmStart& warm, PhaseTimes& times);
};

}  // namespace symcontact
