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

/// The full symmetric matrix, row-major, from its lower triangle.
Eigen::SparseMatrix<double, Eigen::RowMajor, Index> full_rows(const SparseMatrix& K_lower) {
  const SparseMatrix strict = K_lower.triangularView<Eigen::StrictlyLower>();
  Eigen::SparseMatrix<double, Eigen::RowMajor, Index> R = SparseMatrix(K_lower) + SparseMatrix(strict.transpose());
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

namespace {

/// This rank's rows: those of the nodes [first, last), i.e. dim·[first, last).
struct RowRange {
  int dim;
  Index first, last;
  Index row0() const { return dim * first; }
  Index row1() const { return dim * last; }
  Index local() const { return row1() - row0(); }
  bool owns(Index row) const { return row >= row0() && row < row1(); }
};

RowRange my_rows(int dim, Index num_nodes) {
  PetscMPIInt rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  return {dim, num_nodes * rank / size, num_nodes * (rank + 1) / size};
}

/// Adds every entry of this rank's share R (full rows) to A, in any row: PETSc sends the entries of other
/// ranks' rows to them at the assembly.
void add_share(const Eigen::SparseMatrix<double, Eigen::RowMajor, Index>& R, Mat A) {
  std::vector<PetscInt> cols;
  for (Index i = 0; i < R.rows(); ++i) {
    const Index begin = R.outerIndexPtr()[i], count = R.outerIndexPtr()[i + 1] - begin;
    if (count == 0) continue;
    cols.assign(R.innerIndexPtr() + begin, R.innerIndexPtr() + begin + count);
    const PetscInt row = static_cast<PetscInt>(i);
    check(MatSetValues(A, 1, &row, static_cast<PetscInt>(count), cols.data(), R.valuePtr() + begin, ADD_VALUES),
          "MatSetValues");
  }
  check(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
}

/// The distributed matrix of block size dim, the sum of the ranks' shares of K: their entries first added to
/// PETSc's preallocator (which learns every owned row's pattern, off-rank entries included), then to A.
void assemble_matrix(const SparseMatrix& K_share, const RowRange& mine, Mat A) {
  const auto R = full_rows(K_share);
  const PetscInt n = static_cast<PetscInt>(K_share.rows());
  Owned<Mat, MatDestroy> pattern;
  check(MatCreate(PETSC_COMM_WORLD, &pattern.object), "MatCreate");
  for (Mat M : {pattern.object, A}) {
    check(MatSetSizes(M, mine.local(), mine.local(), n, n), "MatSetSizes");
    check(MatSetBlockSize(M, mine.dim), "MatSetBlockSize");
  }
  check(MatSetType(pattern.object, MATPREALLOCATOR), "MatSetType");
  check(MatSetUp(pattern.object), "MatSetUp");
  add_share(R, pattern.object);
  check(MatSetType(A, MATAIJ), "MatSetType");
  check(MatPreallocatorPreallocate(pattern.object, PETSC_TRUE, A), "MatPreallocatorPreallocate");
  add_share(R, A);
}

/// b = f and u = ū on the fixed rows, then the fixed rows and columns of A made identity rows, ū moved into b.
void impose_fixed(const VectorXd& f, const std::vector<Index>& fixed, const VectorXd& fixed_values,
                  const RowRange& mine, Mat A, Vec u, Vec b) {
  for (Index i = mine.row0(); i < mine.row1(); ++i) check(VecSetValue(b, i, f[i], INSERT_VALUES), "VecSetValue");
  check(VecSet(u, 0.0), "VecSet");
  std::vector<PetscInt> rows;
  for (std::size_t k = 0; k < fixed.size(); ++k)
    if (mine.owns(fixed[k])) {
      rows.push_back(static_cast<PetscInt>(fixed[k]));
      check(VecSetValue(u, fixed[k], fixed_values[static_cast<Index>(k)], INSERT_VALUES), "VecSetValue");
    }
  for (Vec v : {b, u}) {
    check(VecAssemblyBegin(v), "VecAssemblyBegin");
    check(VecAssemblyEnd(v), "VecAssemblyEnd");
  }
  check(MatZeroRowsColumns(A, static_cast<PetscInt>(rows.size()), rows.data(), 1.0, u, b), "MatZeroRowsColumns");
}

/// The rigid motions of the node coordinates x, set as A's near null space (GAMG reads it).
void set_rigid_body_modes(const Eigen::MatrixXd& x, const RowRange& mine, Mat A) {
  Owned<Vec, VecDestroy> coords;
  check(VecCreate(PETSC_COMM_WORLD, &coords.object), "VecCreate");
  check(VecSetSizes(coords.object, mine.local(), mine.dim * x.cols()), "VecSetSizes");
  check(VecSetBlockSize(coords.object, mine.dim), "VecSetBlockSize");
  check(VecSetFromOptions(coords.object), "VecSetFromOptions");
  for (Index v = mine.first; v < mine.last; ++v)
    for (int c = 0; c < mine.dim; ++c)
      check(VecSetValue(coords.object, mine.dim * v + c, x(c, v), INSERT_VALUES), "VecSetValue");
  check(VecAssemblyBegin(coords.object), "VecAssemblyBegin");
  check(VecAssemblyEnd(coords.object), "VecAssemblyEnd");
  Owned<MatNullSpace, MatNullSpaceDestroy> rigid;
  check(MatNullSpaceCreateRigidBody(coords.object, &rigid.object), "MatNullSpaceCreateRigidBody");
  check(MatSetNearNullSpace(A, rigid.object), "MatSetNearNullSpace");
}

/// CG on the unpreconditioned residual, GAMG, the options' tolerance; PETSC_OPTIONS may still change them.
void configure_solver(KSP ksp, Mat A, const GamgOptions& options) {
  check(KSPSetOperators(ksp, A, A), "KSPSetOperators");
  check(KSPSetType(ksp, KSPCG), "KSPSetType");
  check(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  check(KSPSetTolerances(ksp, options.relative_tolerance, 0.0, PETSC_DEFAULT, options.max_iterations),
        "KSPSetTolerances");
  check(KSPSetInitialGuessNonzero(ksp, PETSC_TRUE), "KSPSetInitialGuessNonzero");  // u holds ū
  PC pc = nullptr;
  check(KSPGetPC(ksp, &pc), "KSPGetPC");
  check(PCSetType(pc, PCGAMG), "PCSetType");
  check(KSPSetFromOptions(ksp), "KSPSetFromOptions");
}

/// ‖b − A u‖₂ / ‖b‖₂.
double relative_residual(Mat A, Vec u, Vec b) {
  Owned<Vec, VecDestroy> r;
  check(VecDuplicate(b, &r.object), "VecDuplicate");
  check(MatMult(A, u, r.object), "MatMult");
  check(VecAYPX(r.object, -1.0, b), "VecAYPX");
  PetscReal rn = 0.0, bn = 0.0;
  check(VecNorm(r.object, NORM_2, &rn), "VecNorm");
  check(VecNorm(b, NORM_2, &bn), "VecNorm");
  return bn > 0.0 ? rn / bn : rn;
}

/// The whole of the distributed vector u, on every rank.
VectorXd gather_to_all(Vec u) {
  Owned<VecScatter, VecScatterDestroy> gather;
  Owned<Vec, VecDestroy> all;
  check(VecScatterCreateToAll(u, &gather.object, &all.object), "VecScatterCreateToAll");
  check(VecScatterBegin(gather.object, u, all.object, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  check(VecScatterEnd(gather.object, u, all.object, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  PetscInt n = 0;
  check(VecGetSize(all.object, &n), "VecGetSize");
  const PetscScalar* data = nullptr;
  check(VecGetArrayRead(all.object, &data), "VecGetArrayRead");
  VectorXd out = Eigen::Map<const VectorXd>(data, n);
  check(VecRestoreArrayRead(all.object, &data), "VecRestoreArrayRead");
  return out;
}

}  // namespace

GamgResult solve_elasticity_gamg(const SparseMatrix& K_share, const VectorXd& f, const std::vector<Index>& fixed,
                                 const VectorXd& fixed_values, const Eigen::MatrixXd& x, const GamgOptions& options) {
  const int dim = static_cast<int>(x.rows());
  const Index n = dim * x.cols();
  if (K_share.rows() != n || K_share.cols() != n || f.size() != n ||
      fixed_values.size() != static_cast<Index>(fixed.size()))
    throw std::invalid_argument("solve_elasticity_gamg: K, f, the fixed values and the coordinates do not match");
  const RowRange mine = my_rows(dim, x.cols());
  const auto t_setup = std::chrono::steady_clock::now();
  Owned<Mat, MatDestroy> A;
  check(MatCreate(PETSC_COMM_WORLD, &A.object), "MatCreate");
  assemble_matrix(K_share, mine, A.object);
  Owned<Vec, VecDestroy> b, u;
  check(MatCreateVecs(A.object, &u.object, &b.object), "MatCreateVecs");
  impose_fixed(f, fixed, fixed_values, mine, A.object, u.object, b.object);
  set_rigid_body_modes(x, mine, A.object);
  Owned<KSP, KSPDestroy> ksp;
  check(KSPCreate(PETSC_COMM_WORLD, &ksp.object), "KSPCreate");
  configure_solver(ksp.object, A.object, options);
  check(KSPSetUp(ksp.object), "KSPSetUp");
  GamgResult result;
  result.setup_seconds = seconds_since(t_setup);
  PC pc = nullptr;
  PetscInt levels = 0;
  if (KSPGetPC(ksp.object, &pc) == 0 && PCMGGetLevels(pc, &levels) == 0) result.levels = static_cast<int>(levels);

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
  result.relative_residual = relative_residual(A.object, u.object, b.object);
  result.u = gather_to_all(u.object);
  // The identity rows keep ū up to the preconditioner's round-off (1e-14); the fixed DOFs take it exactly.
  for (std::size_t k = 0; k < fixed.size(); ++k) result.u[fixed[k]] = fixed_values[static_cast<Index>(k)];
  return result;
}

}  // namespace symcontact
