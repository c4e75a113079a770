#pragma once
/// \file condensation_cache.hpp
/// The static condensation of the contact solve and what it keeps between solves of one run.
///
/// With a quadratic bulk energy E(x) = ½ xᵀK x + r₀ᵀx (linear elasticity), the free DOFs split into the set
/// B the contact rows and friction terms touch and the interior I, and the interior is eliminated exactly:
/// x_I(y) = −K_II⁻¹(r₀_I + K_IB y), leaving the condensed problem in y = x_B with the Schur complement
/// S = K_BB − K_BI K_II⁻¹ K_IB (condensed_problem.hpp, static_condensation.hpp). One sparse Cholesky factor
/// of K_II serves every geometry iteration, Coulomb iteration and load step while B holds the DOFs touched;
/// B grows (never shrinks within a run) by a margin of facet rings when the contact zone leaves it.

#include <memory>
#include <vector>

#include "symcontact/contact/contact_set.hpp"
#include "symcontact/contact/friction_term.hpp"
#include "symcontact/core/log.hpp"
#include "symcontact/energy/energy_term.hpp"
#include "symcontact/solvers/fixed_dofs.hpp"

namespace symcontact {

class StaticCondensation;
class SemidefiniteFactor;
class CondensedProblem;
class ReducedProblem;
struct CondensedLoad;

/// What solve_contact keeps between calls: the static condensation of a quadratic bulk energy (its
/// Cholesky factor and Schur complement), reused while the energy object, the set of free DOFs and the
/// condensed DOFs still fit; the warm start of the next solve. One per run (all load steps and Coulomb
/// iterations of one model); it is rebuilt, never misused, when given another energy or Dirichlet set.
struct ContactWorkspace {
  ContactWorkspace();
  ~ContactWorkspace();
  const EnergyTerm* energy = nullptr;   ///< the energy the condensation belongs to
  std::vector<Index> free_index;        ///< its DOF → free numbering
  std::unique_ptr<StaticCondensation> condensation;
  int factorisations = 0;               ///< condensations computed (for reports and tests)
  /// The null space and generalised inverse of the condensation's Schur complement for the dual solve, and
  /// the value of `factorisations` it belongs to.
  std::unique_ptr<SemidefiniteFactor> schur_factor;
  int schur_factor_of = -1;
  /// The load part of the condensed problem (condensed_problem.hpp) of the last solve and the value of
  /// `factorisations` it belongs to: reused while ∇E(0) (loads, Dirichlet values) is the same.
  std::shared_ptr<const CondensedLoad> load;
  int load_of = -1;
  /// The last converged solve's multipliers and the identity of its rows (family, node): the warm start of
  /// the next solve's first optimiser call when its rows are the same.
  VectorXd multipliers;
  std::vector<int> row_family;
  std::vector<Index> row_node;
  /// The closing polish was rejected in the previous solve with a non-quadratic energy (friction): the
  /// next such solve balances forces only and skips that attempt (polish_strategy.hpp).
  bool closing_polish_rejected = false;
  /// The last solve left u's interior out of date (ContactSolveOptions::lazy_interior): complete_interior().
  bool interior_pending = false;
  /// The cost rule's verdict for the condensation's B where the optimiser alone may take the uncondensed
  /// problem (SparseAlternative::kOptimiser): the uncondensed problem is the cheaper one to optimise on.
  bool optimise_uncondensed = false;
  /// CHOLMOD's predicted flops of factorising K_ff, for the energy and numbering they belong to (the cost rule
  /// of condense_problem), and the |B| the rule's choice was last logged for.
  double sparse_flops = 0.0;
  const EnergyTerm* sparse_flops_energy = nullptr;
  std::vector<Index> sparse_flops_free_index;
  Index sparse_logged_for = -1;
};

/// The primal path's cost rule (condense_problem): the subproblems with friction terms are not condensed when
/// a dense factorisation on B, |B|³/3 flops, is more than kDenseOverSparse times CHOLMOD's flops of factorising
/// K_ff and more than kSparseAboveFlops. Dense flops run about four times faster than sparse ones here (LAPACK
/// on one block against CHOLMOD's supernodes, plus the sparse path's assembly and solves per iteration). Below
/// 1e9 flops (|B| ≲ 1,400) the two cost about the same, and the condensed path stays. Measured on the 3D pads of
/// docs/performance.md ("Whole faces in contact"), CPU time sparse / condensed: on a plane 1.03, 0.92, 1.16 at
/// flop ratios 9.3, 7.5, 6.9 (2.7e7–3.5e8 flops), then 0.92, 0.65, 0.60 at 4.1, 6.5, 5.5 (1.0e4, 1.8e4, 3.3e4
/// DOFs, 2.8e9–3.7e10 flops); on a ball 1.05, 1.03 at 7.1e3 and 1.0e4 DOFs; peak memory 0.28–0.35 times.
inline constexpr double kDenseOverSparse = 4.0;
inline constexpr double kSparseAboveFlops = 1e9;
/// The floor where IPOPT optimises (SparseAlternative::kOptimiser): MUMPS factorises the condensed problem's
/// dense KKT block more slowly per flop than LAPACK does the interior point's, so that the uncondensed KKT
/// system pays from lower. Measured on the 3D clamped plates with Coulomb friction (docs/performance.md), contact
/// CPU time with the uncondensed / the condensed optimisation: 1.04 at 3.4e8 flops (2.9e3 DOFs), 0.87 at 8.5e8
/// (4.4e3), 0.74 at 3.4e9 (8.1e3), 0.54 at 1.0e4 DOFs; flop ratios 16–24.
inline constexpr double kOptimiserSparseAboveFlops = 5e8;
/// The rule above: the uncondensed problem is cheaper, from the flops of the dense factorisation on B
/// (|B|³/3) and of K_ff's sparse one, above the floor `above`. condense_problem decides by it, and the run-level
/// choice (app/linear_solver_choice.hpp) predicts that decision by it.
inline bool uncondensed_is_cheaper(double dense_flops, double sparse_flops, double above = kSparseAboveFlops) {
  return dense_flops > above && dense_flops > kDenseOverSparse * sparse_flops;
}

/// Who may take the uncondensed problem where the cost rule (uncondensed_is_cheaper) prefers it; linear-elastic
/// bodies only.
enum class SparseAlternative {
  kNone,
  /// The primal interior point, for the whole subproblem (independent rows): with friction terms and the rule
  /// against the dense factorisation, condense_problem condenses nothing.
  kWholeSolve,
  /// IPOPT (symmetric pairs): it optimises the uncondensed problem, whose sparse KKT system MUMPS factorises,
  /// and its answer is restricted to B for the condensed problem's polish, a dense range-space solve on B. The
  /// sparse polish would take one solve per active row, or the method of multipliers, which stalls on the
  /// nearly dependent rows of the two families. condense_problem condenses, and sets
  /// ContactWorkspace::optimise_uncondensed to the rule's verdict.
  kOptimiser,
  /// The same whatever the cost (IpoptProblem::kUncondensed): ContactWorkspace::optimise_uncondensed is set.
  kOptimiserAlways,
};

/// When and how far to condense (ContactSolveOptions::max_condensed_dofs, ::same_loads).
struct CondensationLimits {
  Index max_condensed_dofs = 12000;
  bool same_loads = false;
  SparseAlternative sparse_alternative = SparseAlternative::kNone;
};

/// The condensed form of the current geometry iterate's problem, or null when condensing does not apply
/// or pay: B empty, |B| above `limits.max_condensed_dofs` or above half the free DOFs, with friction terms and
/// `limits.sparse_alternative` kWholeSolve a dense factorisation on B dearer than a sparse one of K_ff
/// (kDenseOverSparse), or a factorisation that fails. Reuses the workspace's factorisation when its B holds every DOF the constraints of `problem`
/// and the `friction` terms (evaluated at the full vector u) touch; otherwise refactorises with the union
/// of the old B, the new DOFs and a margin. `load` (null on the first call of a solve) caches the load part
/// for this solve's Dirichlet values and loads.
std::unique_ptr<CondensedProblem> condense_problem(ReducedProblem& bulk, const ReducedProblem& problem,
                                                   const ContactSet& contacts, const DofMap& dofs,
                                                   const std::vector<std::shared_ptr<const FrictionTerm>>& friction,
                                                   const VectorXd& u, const VectorXd& x, const EnergyTerm& energy,
                                                   ContactWorkspace& ws, const CondensationLimits& limits,
                                                   const Logger& log, std::shared_ptr<const CondensedLoad>& load);

/// Whether the condensed set holds every free DOF of the contact surfaces (rigid ones have none): then the
/// search, the friction points and the surface pressures read nothing outside B.
bool surfaces_condensed(const ContactSet& contacts, const DofMap& dofs, const std::vector<Index>& free_index,
                        const std::vector<Index>& b_position);

/// The pivoted factor of the workspace's Schur complement for the dual (computed once per condensation), or
/// null when the dual cannot be used: a null space that is not clean (max |S N| above 1e-8 of max |S|: a
/// pivot between round-off and stiffness, no clear rank) is left to the primal.
const SemidefiniteFactor* dual_schur_factor(ContactWorkspace& ws, const Logger& log);

/// Makes u whole after solves with ContactSolveOptions::lazy_interior: the interior DOFs from u's condensed
/// entries and the workspace's factor and load part (those of the last solve), x_I = −K_II⁻¹(r₀_I + K_IB x_B).
/// Does nothing when the workspace has nothing pending. `energy` and `fixed` must be those of the last solve.
void complete_interior(const EnergyTerm& energy, const FixedDofs& fixed, VectorXd& u, ContactWorkspace& workspace);

}  // namespace symcontact
