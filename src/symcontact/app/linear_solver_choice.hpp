#pragma once
/// \file linear_solver_choice.hpp
/// Which path solves a run's contact steps ([contact_solver] linear_solver): the serial solver, whose sparse
/// Cholesky factors must fit in memory, or the distributed path (`symcontact-mpi`: conjugate gradients and
/// algebraic multigrid on PETSc, docs/distributed.md), which `symcontact` starts in its place.
///
/// The rule for "automatic": the serial solver, unless the model has at least kAutomaticCheckDofs DOFs, its
/// serial contact solve's predicted peak (solvers/memory_prediction.hpp, from CHOLMOD's analysis of K_ff)
/// is above kMemoryShare × MemAvailable, and the distributed path solves the problem (linear elasticity,
/// contact with rigid obstacles, frictionless or with friction on order-1 elements). Below that size the analysis is not run: such a problem fits on any machine this runs on.

#include <string>

#include "symcontact/model/model.hpp"
#include "symcontact/model/problem_spec.hpp"
#include "symcontact/solvers/memory_prediction.hpp"

namespace symcontact {

inline constexpr double kAutomaticCheckDofs = 2e5;
inline constexpr double kMemoryShare = 0.9;

/// What the distributed path does not solve yet in `spec`: the key of the first such thing and why ("" and
/// "" when it solves all of it).
struct DistributedLimit {
  std::string key, message;
  bool none() const { return key.empty(); }
};
DistributedLimit distributed_path_limit(const ProblemSpec& spec);

struct LinearSolverDecision {
  bool iterative = false;
  std::string reason;  ///< one line for the log
};

/// The machine's side of the rule: MemAvailable (−1: unknown, the serial solver), and the size from which
/// the prediction is made.
struct MemoryBudget {
  double available_bytes = available_memory_bytes();
  double min_dofs = kAutomaticCheckDofs;
};

/// The path for a built model (see the rule above).
LinearSolverDecision choose_linear_solver(const ProblemSpec& spec, const Model& model,
                                          const MemoryBudget& budget = MemoryBudget{});

}  // namespace symcontact
