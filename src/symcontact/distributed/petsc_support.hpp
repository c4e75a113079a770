#pragma once
/// \file petsc_support.hpp
/// The pieces every solver of the distributed path shares: PETSc errors as exceptions, PETSc objects owned
/// by scope, the rows a rank owns, the distributed stiffness assembled from the ranks' shares, its fixed
/// DOFs and rigid-body modes, and the gather of a distributed vector.
///
/// DOF layout as in DofMap: node-major, dof = dim·node + comp. Each rank owns the rows of a contiguous range
/// of nodes (my_rows), so a node's dim DOFs never straddle two ranks and the matrices keep block size dim.

#include <petscmat.h>

#include <chrono>
#include <vector>

#include "symcontact/core/types.hpp"

namespace symcontact::petsc {

/// Throws std::runtime_error naming `call` when e is not 0.
void check(PetscErrorCode e, const char* call);

double seconds_since(std::chrono::steady_clock::time_point t0);

/// Destroys a PETSc object when it leaves scope.
template <class T, PetscErrorCode (*Destroy)(T*)>
struct Owned {
  T object = nullptr;
  Owned() = default;
  Owned(const Owned&) = delete;
  Owned& operator=(const Owned&) = delete;
  ~Owned() {
    if (object) Destroy(&object);
  }
};

/// This rank's rows: those of the nodes [first, last), i.e. dim·[first, last).
struct RowRange {
  int dim;
  Index first, last;
  Index row0() const { return dim * first; }
  Index row1() const { return dim * last; }
  Index local() const { return row1() - row0(); }
  bool owns(Index row) const { return row >= row0() && row < row1(); }
  bool owns_node(Index node) const { return node >= first && node < last; }
};

/// num_nodes split into contiguous, nearly equal ranges, one per rank of PETSC_COMM_WORLD.
RowRange my_rows(int dim, Index num_nodes);

/// A distributed n × n matrix of block size dim, the sum of the ranks' shares (each the lower triangle of
/// its share of a symmetric matrix, n × n on every rank); preallocated exactly, off-rank entries included.
void assemble_symmetric(const SparseMatrix& share_lower, const RowRange& mine, Mat A);

/// b = f on this rank's rows and u = ū on the fixed ones; then A's fixed rows and columns become identity
/// rows and columns, the products with ū moved into b (MatZeroRowsColumns). Every rank passes the same f,
/// fixed DOFs and values.
void impose_fixed(const VectorXd& f, const std::vector<Index>& fixed, const VectorXd& fixed_values,
                  const RowRange& mine, Mat A, Vec u, Vec b);

/// The rigid motions of the node coordinates x (dim × num_nodes) set as A's near null space (GAMG reads it).
void set_rigid_body_modes(const Eigen::MatrixXd& x, const RowRange& mine, Mat A);

/// The whole of the distributed vector u, on every rank.
VectorXd gather_to_all(Vec u);

/// ‖b − A u‖₂ / ‖b‖₂ (‖b − A u‖₂ when b = 0).
double relative_residual(Mat A, Vec u, Vec b);

}  // namespace symcontact::petsc
