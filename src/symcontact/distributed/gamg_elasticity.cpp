#include "symcontact/distributed/gamg_elasticity.hpp"

#include <petscksp.h>

#include <stdexcept>

#include "symcontact/distributed/petsc_support.hpp"

namespace symcontact {

using petsc::check;
using petsc::Owned;

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

bool PetscSession::all_ranks(bool ok) const {
  int mine = ok ? 1 : 0, all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_LAND, PETSC_COMM_WORLD);
  return all != 0;
}

namespace {

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

}  // namespace

GamgResult solve_elasticity_gamg(const SparseMatrix& K_share, const VectorXd& f, const std::vector<Index>& fixed,
                                 const VectorXd& fixed_values, const Eigen::MatrixXd& x, const GamgOptions& options) {
  const int dim = static_cast<int>(x.rows());
  const Index n = dim * x.cols();
  if (K_share.rows() != n || K_share.cols() != n || f.size() != n ||
      fixed_values.size() != static_cast<Index>(fixed.size()))
    throw std::invalid_argument("solve_elasticity_gamg: K, f, the fixed values and the coordinates do not match");
  const petsc::RowRange mine = petsc::my_rows(dim, x.cols());
  const auto t_setup = std::chrono::steady_clock::now();
  Owned<Mat, MatDestroy> A;
  check(MatCreate(PETSC_COMM_WORLD, &A.object), "MatCreate");
  petsc::assemble_symmetric(K_share, mine, A.object);
  Owned<Vec, VecDestroy> b, u;
  check(MatCreateVecs(A.object, &u.object, &b.object), "MatCreateVecs");
  petsc::impose_fixed(f, fixed, fixed_values, mine, A.object, u.object, b.object);
  petsc::set_rigid_body_modes(x, mine, A.object);
  Owned<KSP, KSPDestroy> ksp;
  check(KSPCreate(PETSC_COMM_WORLD, &ksp.object), "KSPCreate");
  configure_solver(ksp.object, A.object, options);
  check(KSPSetUp(ksp.object), "KSPSetUp");
  GamgResult result;
  result.setup_seconds = petsc::seconds_since(t_setup);
  PC pc = nullptr;
  PetscInt levels = 0;
  if (KSPGetPC(ksp.object, &pc) == 0 && PCMGGetLevels(pc, &levels) == 0) result.levels = static_cast<int>(levels);

  const auto t_solve = std::chrono::steady_clock::now();
  check(KSPSolve(ksp.object, b.object, u.object), "KSPSolve");
  result.solve_seconds = petsc::seconds_since(t_solve);
  PetscInt its = 0;
  KSPConvergedReason reason;
  check(KSPGetIterationNumber(ksp.object, &its), "KSPGetIterationNumber");
  check(KSPGetConvergedReason(ksp.object, &reason), "KSPGetConvergedReason");
  result.iterations = static_cast<int>(its);
  result.converged = reason > 0;
  result.reason = KSPConvergedReasons[reason];
  result.relative_residual = petsc::relative_residual(A.object, u.object, b.object);
  result.u = petsc::gather_to_all(u.object);
  // The identity rows keep ū up to the preconditioner's round-off (1e-14); the fixed DOFs take it exactly.
  for (std::size_t k = 0; k < fixed.size(); ++k) result.u[fixed[k]] = fixed_values[static_cast<Index>(k)];
  return result;
}

}  // namespace symcontact
