#include "symcontact/distributed/gamg_elasticity.hpp"

#include <petscksp.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace symcontact {

namespace {

void check(PetscErrorCode e, const char* call) {
  if (e != 0) throw std::runtime_error(std::string("PETSc: ") + call + " failed (error " + std::to_string(e) + ")");
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// The full symmetric matrix, row-major, from its lower triangle (or as given).
Eigen::SparseMatrix<double, Eigen::RowMajor, Index> full_rows(const SparseMatrix& K, bool lower) {
  Eigen::SparseMatrix<double, Eigen::RowMajor, Index> R;
  if (!lower) {
    R = K;
  } else {
    SparseMatrix strict = K.triangularView<Eigen::StrictlyLower>();
    SparseMatrix full = SparseMatrix(K.transpose()) + strict;  // lower + its strictly-lower transpose
    R = full;
  }
  R.makeCompressed();
  return R;
}

/// Destroys a PETSc object when it leaves scope.
template <class T, PetscErrorCode (*Destroy)(T*)>
struct Owned {
  T object = nullptr;
  ~Owned() {
    if (object) Destroy(&object);
  }
};

}  // namespace

PetscSession::PetscSession(int* argc, char*** argv) {
  check(PetscInitialize(argc, argv, nullptr, nullptr), "PetscInitialize");
}

PetscSession::~PetscSession() { PetscFinalize(); }

int PetscSession::rank() const {
  PetscMPIInt r = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &r);
  return r;
}

int PetscSession::size() const {
  PetscMPIInt s = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &s);
  return s;
}

GamgResult solve_elasticity_gamg(const SparseMatrix& K, bool lower, const VectorXd& f, const std::vector<Index>& fixed,
                                 const VectorXd& fixed_values, const Eigen::MatrixXd& x, const GamgOptions& options) {
  const int dim = static_cast<int>(x.rows());
  const Index num_nodes = x.cols(), n = dim * num_nodes;
  if (K.rows() != n || K.cols() != n || f.size() != n || fixed_values.size() != static_cast<Index>(fixed.size()))
    throw std::invalid_argument("solve_elasticity_gamg: K, f, the fixed values and the coordinates do not match");
  PetscMPIInt rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  // Rows dim·[first, last) of the nodes [first, last) are this rank's.
  const Index first = num_nodes * rank / size, last = num_nodes * (rank + 1) / size;
  const Index row0 = dim * first, row1 = dim * last, local = row1 - row0;
  const auto t_setup = std::chrono::steady_clock::now();

  const auto R = full_rows(K, lower);
  std::vector<PetscInt> d_nnz(local, 0), o_nnz(local, 0);
  for (Index i = row0; i < row1; ++i)
    for (auto it = decltype(R)::InnerIterator(R, i); it; ++it)
      ++((it.col() >= row0 && it.col() < row1) ? d_nnz : o_nnz)[i - row0];
  Owned<Mat, MatDestroy> A;
  check(MatCreate(PETSC_COMM_WORLD, &A.object), "MatCreate");
  check(MatSetSizes(A.object, local, local, n, n), "MatSetSizes");
  check(MatSetType(A.object, MATAIJ), "MatSetType");
  check(MatSetBlockSize(A.object, dim), "MatSetBlockSize");
  check(MatSeqAIJSetPreallocation(A.object, 0, d_nnz.data()), "MatSeqAIJSetPreallocation");
  check(MatMPIAIJSetPreallocation(A.object, 0, d_nnz.data(), 0, o_nnz.data()), "MatMPIAIJSetPreallocation");
  std::vector<PetscInt> cols;
  std::vector<PetscScalar> vals;
  for (Index i = row0; i < row1; ++i) {
    cols.clear();
    vals.clear();
    for (auto it = decltype(R)::InnerIterator(R, i); it; ++it) {
      cols.push_back(static_cast<PetscInt>(it.col()));
      vals.push_back(it.value());
    }
    const PetscInt row = static_cast<PetscInt>(i);
    check(MatSetValues(A.object, 1, &row, static_cast<PetscInt>(cols.size()), cols.data(), vals.data(), INSERT_VALUES),
          "MatSetValues");
  }
  check(MatAssemblyBegin(A.object, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(A.object, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");

  // b = f; u holds the fixed values at the fixed rows; then the fixed rows and columns become identity rows.
  Owned<Vec, VecDestroy> b, u, coords;
  check(MatCreateVecs(A.object, &u.object, &b.object), "MatCreateVecs");
  for (Index i = row0; i < row1; ++i) check(VecSetValue(b.object, i, f[i], INSERT_VALUES), "VecSetValue");
  check(VecSet(u.object, 0.0), "VecSet");
  std::vector<PetscInt> fixed_rows;
  for (std::size_t k = 0; k < fixed.size(); ++k)
    if (fixed[k] >= row0 && fixed[k] < row1) {
      fixed_rows.push_back(static_cast<PetscInt>(fixed[k]));
      check(VecSetValue(u.object, fixed[k], fixed_values[static_cast<Index>(k)], INSERT_VALUES), "VecSetValue");
    }
  for (Vec v : {b.object, u.object}) {
    check(VecAssemblyBegin(v), "VecAssemblyBegin");
    check(VecAssemblyEnd(v), "VecAssemblyEnd");
  }
  check(MatZeroRowsColumns(A.object, static_cast<PetscInt>(fixed_rows.size()), fixed_rows.data(), 1.0, u.object,
                           b.object),
        "MatZeroRowsColumns");

  // The rigid motions of the nodes: GAMG's near null space.
  check(VecCreate(PETSC_COMM_WORLD, &coords.object), "VecCreate");
  check(VecSetSizes(coords.object, local, n), "VecSetSizes");
  check(VecSetBlockSize(coords.object, dim), "VecSetBlockSize");
  check(VecSetFromOptions(coords.object), "VecSetFromOptions");
  for (Index v = first; v < last; ++v)
    for (int c = 0; c < dim; ++c) check(VecSetValue(coords.object, dim * v + c, x(c, v), INSERT_VALUES), "VecSetValue");
  check(VecAssemblyBegin(coords.object), "VecAssemblyBegin");
  check(VecAssemblyEnd(coords.object), "VecAssemblyEnd");
  Owned<MatNullSpace, MatNullSpaceDestroy> rigid;
  check(MatNullSpaceCreateRigidBody(coords.object, &rigid.object), "MatNullSpaceCreateRigidBody");
  check(MatSetNearNullSpace(A.object, rigid.object), "MatSetNearNullSpace");

  Owned<KSP, KSPDestroy> ksp;
  check(KSPCreate(PETSC_COMM_WORLD, &ksp.object), "KSPCreate");
  check(KSPSetOperators(ksp.object, A.object, A.object), "KSPSetOperators");
  check(KSPSetType(ksp.object, KSPCG), "KSPSetType");
  check(KSPSetNormType(ksp.object, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  check(KSPSetTolerances(ksp.object, options.relative_tolerance, 0.0, PETSC_DEFAULT, options.max_iterations),
        "KSPSetTolerances");
  check(KSPSetInitialGuessNonzero(ksp.object, PETSC_TRUE), "KSPSetInitialGuessNonzero");  // u: the fixed values
  PC pc = nullptr;
  check(KSPGetPC(ksp.object, &pc), "KSPGetPC");
  check(PCSetType(pc, PCGAMG), "PCSetType");
  check(KSPSetFromOptions(ksp.object), "KSPSetFromOptions");  // PETSC_OPTIONS may add monitors or change it
  check(KSPSetUp(ksp.object), "KSPSetUp");
  GamgResult result;
  result.setup_seconds = seconds_since(t_setup);
  PetscInt levels = 0;
  if (PCMGGetLevels(pc, &levels) == 0) result.levels = static_cast<int>(levels);

  const auto t_solve = std::chrono::steady_clock::now();
  check(KSPSolve(ksp.object, b.object, u.object), "KSPSolve");
  result.solve_seconds = seconds_since(t_solve);
  PetscInt its = 0;
  KSPConvergedReason reason;
  check(KSPGetIterationNumber(ksp.object, &its), "KSPGetIterationNumber");
  check(KSPGetConvergedReason(ksp.object, &reason), "KSPGetConvergedReason");
  result.iterations = static_cast<int>(its);
  result.converged = reason > 0;
  result.reason = KSPConvergedReasons[reason];

  // ‖b − A u‖ / ‖b‖ of the system solved (its fixed rows hold u = ū exactly).
  Owned<Vec, VecDestroy> r;
  check(VecDuplicate(b.object, &r.object), "VecDuplicate");
  check(MatMult(A.object, u.object, r.object), "MatMult");
  check(VecAYPX(r.object, -1.0, b.object), "VecAYPX");
  PetscReal rn = 0.0, bn = 0.0;
  check(VecNorm(r.object, NORM_2, &rn), "VecNorm");
  check(VecNorm(b.object, NORM_2, &bn), "VecNorm");
  result.relative_residual = bn > 0.0 ? rn / bn : rn;

  // Every rank gets the whole answer.
  Owned<VecScatter, VecScatterDestroy> gather;
  Owned<Vec, VecDestroy> all;
  check(VecScatterCreateToAll(u.object, &gather.object, &all.object), "VecScatterCreateToAll");
  check(VecScatterBegin(gather.object, u.object, all.object, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  check(VecScatterEnd(gather.object, u.object, all.object, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  const PetscScalar* data = nullptr;
  check(VecGetArrayRead(all.object, &data), "VecGetArrayRead");
  result.u = Eigen::Map<const VectorXd>(data, n);
  check(VecRestoreArrayRead(all.object, &data), "VecRestoreArrayRead");
  // The identity rows keep ū up to the preconditioner's round-off (1e-14); the fixed DOFs take it exactly.
  for (std::size_t k = 0; k < fixed.size(); ++k) result.u[fixed[k]] = fixed_values[static_cast<Index>(k)];
  return result;
}

}  // namespace symcontact
