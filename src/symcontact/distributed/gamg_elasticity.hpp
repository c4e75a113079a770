#pragma once
/// \file gamg_elasticity.hpp
/// The stiffness system of linear elasticity solved on PETSc across MPI ranks, by conjugate gradients
/// preconditioned with smoothed-aggregation algebraic multigrid (PETSc's GAMG) that knows the rigid-body
/// modes: the building block of the iterative path for problems whose Cholesky factor does not fit
/// (issue: distributed contact solves).
///
///     K u = f,   u_i = ū_i on the fixed DOFs,
///
/// K the assembled stiffness over every DOF (DofMap layout: node-major, dof = dim·node + comp), symmetric
/// positive definite once the fixed DOFs are removed. The fixed rows and columns are replaced by the
/// identity and their values moved to the right-hand side (PETSc MatZeroRowsColumns), so every node keeps
/// its dim DOFs and the matrix its block size dim, which GAMG aggregates by. The near null space is the
/// rigid motions of the node coordinates (3 in 2D, 6 in 3D: PETSc MatNullSpaceCreateRigidBody): smoothed
/// aggregation interpolates them exactly on every level (Vaněk, Mandel & Brezina, Computing 56 (1996)),
/// which keeps the iteration count bounded as the mesh is refined.
///
/// Distribution: each rank owns a contiguous range of nodes (rows dim·[first, last)) and passes its share of
/// K, the shares summing to K (the stiffness of the cells it assembles: clamped_block_system() gives each
/// rank a contiguous range of cells); PETSc adds the entries that fall in other ranks' rows where they
/// belong. The answer is gathered on every rank. Stopping: ‖r‖₂ ≤ relative_tolerance · ‖b‖₂, b the right-hand side after the fixed values moved
/// into it: a test relative to the problem's own load, the same in any units.

#include <string>
#include <vector>

#include "symcontact/core/types.hpp"

namespace symcontact {

/// PETSc (and MPI) initialised for the lifetime of the object; one per process, before any solve.
class PetscSession {
 public:
  PetscSession(int* argc, char*** argv);
  PetscSession(const PetscSession&) = delete;
  PetscSession& operator=(const PetscSession&) = delete;
  ~PetscSession();
  int rank() const;
  int size() const;
  /// Whether `ok` holds on every rank (collective over PETSC_COMM_WORLD).
  bool all_ranks(bool ok) const;
};

struct GamgOptions {
  double relative_tolerance = 1e-10;
  int max_iterations = 500;
};

struct GamgResult {
  VectorXd u;                     ///< every DOF, on every rank
  bool converged = false;
  std::string reason;             ///< PETSc's KSPConvergedReason, as text
  int iterations = 0;             ///< conjugate-gradient iterations
  double relative_residual = 0.0; ///< ‖b − K u‖₂ / ‖b‖₂ on the free DOFs, recomputed after the solve
  double setup_seconds = 0.0;     ///< matrix, near null space and the multigrid hierarchy (KSPSetUp)
  double solve_seconds = 0.0;     ///< the iterations
  int levels = 0;                 ///< multigrid levels GAMG built
};

/// K_share: this rank's share of the lower triangle of the stiffness, n × n with n = dim · num_nodes (on one
/// rank, the whole of it); f: the load on every DOF; fixed / fixed_values: the Dirichlet DOFs and their
/// values; x: dim × num_nodes node coordinates. Collective over PETSC_COMM_WORLD; every rank passes the same
/// f, fixed DOFs and coordinates.
GamgResult solve_elasticity_gamg(const SparseMatrix& K_share, const VectorXd& f,
                                 const std::vector<Index>& fixed, const VectorXd& fixed_values,
                                 const Eigen::MatrixXd& x, const GamgOptions& options = {});

}  // namespace symcontact
