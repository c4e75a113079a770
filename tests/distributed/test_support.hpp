#pragma once
// Shared by the distributed path's tests: the process's PetscSession (main.cpp) and the reference solve.

#include <vector>

#include "symcontact/core/types.hpp"
#include "symcontact/distributed/gamg_elasticity.hpp"

namespace symcontact {

extern const PetscSession* g_petsc;  ///< main()'s

/// K u = f on the free DOFs, u = the fixed values on the fixed ones, by a sparse Cholesky factorisation of
/// K_ff (Eigen's simplicial LLᵀ) on this process alone: the reference of the distributed solves.
VectorXd cholesky_solution(const SparseMatrix& K_lower, const VectorXd& f, const std::vector<Index>& fixed,
                           const VectorXd& fixed_values);

}  // namespace symcontact
