#pragma once
/// \file linear_solver_choice.hpp
/// Which path solves a run's contact steps ([contact_solver] linear_solver): the serial solver, whose sparse
/// Cholesky factors must fit in memory, or the distributed path (`symcontact-mpi`: conjugate gradients and
/// algebraic multigrid on PETSc, docs/distributed.md), which `symcontact` starts in its place.
///
/// The rule for "automatic", where the distributed path solves the problem (linear elasticity; contact with
/// rigid obstacles, between elastic bodies and self-contact, frictionless or with friction on order-1
/// elements): the distributed path when
///  - the serial solver's work per interior-point iteration is predicted to cost more than the iterative
///    solve's: W > kIterativeFlopsPerDof × free DOFs, with W = |B|³/3 and B the DOFs the serial solver
///    condenses onto (predicted_condensed_dofs) — its interior point factorises a dense |B| × |B| matrix at every
///    iteration — or, with friction where the condensation's cost rule (kDenseOverSparse,
///    solvers/condensation_cache.hpp) takes the uncondensed problem, W = kSparseFlopInDenseFlops × the flops of
///    K_ff's sparse factorisation; the iterative path's Newton solves cost a multiple of the DOFs. For contact with
///    rigid planes only: against a curved obstacle the iterative path took twice the serial solver's
///    iterations (docs/distributed.md);
///  - or the model has at least kAutomaticCheckDofs DOFs and its serial contact solve's predicted peak
///    (solvers/memory_prediction.hpp, from CHOLMOD's analysis of K_ff) is above kMemoryShare × MemAvailable.
///    Below that size the analysis is not run: such a problem fits on any machine this runs on.
/// The serial solver otherwise. kIterativeFlopsPerDof is measured (docs/distributed.md, "Choosing the
/// path"): one process, a 3D pad dragged with Coulomb friction on a rigid plane, the ratio of the two paths'
/// times giving the same break-even constant (1.57e6) at 2.9e4 DOFs (|B| = 4,320, the condensed serial solver
/// 1.4 times faster) and at 6.5e4 (|B| = 7,653, 1.7 times slower).

#include <string>

#include "symcontact/model/model.hpp"
#include "symcontact/model/problem_spec.hpp"
#include "symcontact/solvers/memory_prediction.hpp"

namespace symcontact {

inline constexpr double kAutomaticCheckDofs = 2e5;
inline constexpr double kMemoryShare = 0.9;
/// The iterative path's cost per free DOF and interior-point iteration, in flops of a dense factorisation.
inline constexpr double kIterativeFlopsPerDof = 1.5e6;
/// The uncondensed serial solver's cost per flop of K_ff's sparse factorisation, in flops of a dense one, at
/// the sizes where the iterative path competes: the 3D pad dragged on a rigid plane, one process, took 37 s
/// and 151 s of CPU (81 and 85 iterations) at 2.9e4 and 6.5e4 DOFs against the iterative path's 132 s and
/// 272 s (docs/distributed.md, "Choosing the path"), which this rate and kIterativeFlopsPerDof order alike
/// (the condensation's own rate, kDenseOverSparse = 4, is the break-even at 1e4 DOFs, where CHOLMOD's
/// supernodes are smaller).
inline constexpr double kSparseFlopInDenseFlops = 2.0;

/// What the distributed path does not solve yet in `spec`: the key of the first such thing and why ("" and
/// "" when it solves all of it).
struct DistributedLimit {
  std::string key, message;
  bool none() const { return key.empty(); }
};
DistributedLimit distributed_path_limit(const ProblemSpec& spec);

/// What settled a LinearSolverDecision.
enum class DecisionBasis {
  kProblemFile,  ///< linear_solver = "direct" or "iterative"
  kDefault,      ///< automatic, and no part of the rule moves the problem off the serial solver
  kDenseWork,    ///< automatic: the serial solver's dense work costs more
  kMemory,       ///< automatic: the serial solver is predicted not to fit (iterative, or direct where the
                 ///< distributed path does not solve the problem)
};

struct LinearSolverDecision {
  bool iterative = false;
  DecisionBasis basis = DecisionBasis::kDefault;
  std::string reason;   ///< one line for the log
  std::string figures;  ///< the figures behind kDenseWork or kMemory, as in `reason`
};

/// The machine's side of the rule: MemAvailable (−1: unknown, the serial solver), the size from which the
/// memory is predicted, and the iterative path's cost against the dense factorisation's.
struct MemoryBudget {
  double available_bytes = available_memory_bytes();
  double min_dofs = kAutomaticCheckDofs;
  double iterative_flops_per_dof = kIterativeFlopsPerDof;
};

/// |B| of the rule above, at the initial configuration: the free DOFs that the contact rows read (ContactSet::
/// linearize at u = 0, within the pairs' search distances) and, where any pair has friction, every DOF of
/// those DOFs' nodes (the friction terms' support). The condensation's margin around the zone is left out.
Index predicted_condensed_dofs(const ProblemSpec& spec, const Model& model);

/// The path for a built model (see the rule above).
LinearSolverDecision choose_linear_solver(const ProblemSpec& spec, const Model& model,
                                          const MemoryBudget& budget = MemoryBudget{});

/// Why `d` moved off the direct solver (basis kDenseWork or kMemory), with its figures, for a message.
std::string off_direct_reason(const LinearSolverDecision& d);

/// The rule for a program that runs the serial solver only (the Python module): the serial solver, its reason
/// saying so where `symcontact run` would take the distributed path for its cost (basis kDenseWork); an
/// InputError on contact_solver.linear_solver where the file asks for the distributed path or the serial
/// solver is predicted not to fit in memory (the run would be ended by the system, not by an error of ours).
LinearSolverDecision serial_only_choice(const ProblemSpec& spec, const Model& model,
                                        const MemoryBudget& budget = MemoryBudget{});

}  // namespace symcontact
