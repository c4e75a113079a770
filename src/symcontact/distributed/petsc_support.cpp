#include "symcontact/distributed/petsc_support.hpp"

#include <stdexcept>
#include <string>

namespace symcontact::petsc {

void check(PetscErrorCode e, const char* call) {
  if (e != 0) throw std::runtime_error(std::string("PETSc: ") + call + " failed (error " + std::to_string(e) + ")");
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

RowRange my_rows(int dim, Index num_nodes) {
  PetscMPIInt rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  return {dim, num_nodes * rank / size, num_nodes * (rank + 1) / size};
}

namespace {

/// The full symmetric matrix, row-major, from its lower triangle.
Eigen::SparseMatrix<double, Eigen::RowMajor, Index> full_rows(const SparseMatrix& lower) {
  const SparseMatrix strict = lower.triangularView<Eigen::StrictlyLower>();
  Eigen::SparseMatrix<double, Eigen::RowMajor, Index> R = SparseMatrix(lower) + SparseMatrix(strict.transpose());
  R.makeCompressed();
  return R;
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

void assemble_vector(Vec v) {
  check(VecAssemblyBegin(v), "VecAssemblyBegin");
  check(VecAssemblyEnd(v), "VecAssemblyEnd");
}

}  // namespace

void assemble_symmetric(const SparseMatrix& share_lower, const RowRange& mine, Mat A) {
  const auto R = full_rows(share_lower);
  const PetscInt n = static_cast<PetscInt>(share_lower.rows());
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
  assemble_vector(b);
  assemble_vector(u);
  check(MatZeroRowsColumns(A, static_cast<PetscInt>(rows.size()), rows.data(), 1.0, u, b), "MatZeroRowsColumns");
}

void set_rigid_body_modes(const Eigen::MatrixXd& x, const RowRange& mine, Mat A) {
  Owned<Vec, VecDestroy> coords;
  check(VecCreate(PETSC_COMM_WORLD, &coords.object), "VecCreate");
  check(VecSetSizes(coords.object, mine.local(), mine.dim * x.cols()), "VecSetSizes");
  check(VecSetBlockSize(coords.object, mine.dim), "VecSetBlockSize");
  check(VecSetFromOptions(coords.object), "VecSetFromOptions");
  for (Index v = mine.first; v < mine.last; ++v)
    for (int c = 0; c < mine.dim; ++c)
      check(VecSetValue(coords.object, mine.dim * v + c, x(c, v), INSERT_VALUES), "VecSetValue");
  assemble_vector(coords.object);
  Owned<MatNullSpace, MatNullSpaceDestroy> rigid;
  check(MatNullSpaceCreateRigidBody(coords.object, &rigid.object), "MatNullSpaceCreateRigidBody");
  check(MatSetNearNullSpace(A, rigid.object), "MatSetNearNullSpace");
}

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

}  // namespace symcontact::petsc
