#include "symcontact/distributed/filtered_amg.hpp"

#include <exception>

namespace symcontact {

using petsc::check;

SubspaceCorrection::SubspaceCorrection(const std::vector<PetscInt>& dofs) {
  check(ISCreateGeneral(PETSC_COMM_WORLD, static_cast<PetscInt>(dofs.size()), dofs.data(), PETSC_COPY_VALUES,
                        &dofs_.object),
        "ISCreateGeneral");
  check(KSPCreate(PETSC_COMM_WORLD, &direct_.object), "KSPCreate");
  check(KSPSetType(direct_.object, KSPPREONLY), "KSPSetType");
  check(KSPSetOptionsPrefix(direct_.object, "filter_"), "KSPSetOptionsPrefix");
  PC pc = nullptr;
  check(KSPGetPC(direct_.object, &pc), "KSPGetPC");
  check(PCSetType(pc, PCREDUNDANT), "PCSetType");  // the block gathered whole on every rank
}

void SubspaceCorrection::attach(PC pc) {
  check(PCSetType(pc, PCSHELL), "PCSetType");
  check(PCShellSetContext(pc, this), "PCShellSetContext");
  check(PCShellSetSetUp(pc, &SubspaceCorrection::setup), "PCShellSetSetUp");
  check(PCShellSetApply(pc, &SubspaceCorrection::apply), "PCShellSetApply");
  check(PCShellSetName(pc, "contact-subspace correction"), "PCShellSetName");
}

void SubspaceCorrection::factorise(Mat N) {
  check(MatCreateSubMatrix(N, dofs_.object, dofs_.object, block_.object ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX,
                           &block_.object),
        "MatCreateSubMatrix");
  check(KSPSetOperators(direct_.object, block_.object, block_.object), "KSPSetOperators");
  PC redundant = nullptr, inner = nullptr;
  KSP inner_ksp = nullptr;
  check(KSPGetPC(direct_.object, &redundant), "KSPGetPC");
  check(PCRedundantGetKSP(redundant, &inner_ksp), "PCRedundantGetKSP");
  check(KSPGetPC(inner_ksp, &inner), "KSPGetPC");
  check(PCSetType(inner, PCLU), "PCSetType");
  check(PCFactorSetMatOrderingType(inner, MATORDERINGND), "PCFactorSetMatOrderingType");
  check(KSPSetFromOptions(direct_.object), "KSPSetFromOptions");
  check(KSPSetUp(direct_.object), "KSPSetUp");
  if (!rhs_.object) check(MatCreateVecs(block_.object, &sol_.object, &rhs_.object), "MatCreateVecs");
}

void SubspaceCorrection::correct(Vec x, Vec y) {
  check(VecISCopy(x, dofs_.object, SCATTER_REVERSE, rhs_.object), "VecISCopy");
  check(KSPSolve(direct_.object, rhs_.object, sol_.object), "KSPSolve");
  check(VecSet(y, 0.0), "VecSet");
  check(VecISCopy(y, dofs_.object, SCATTER_FORWARD, sol_.object), "VecISCopy");
}

PetscErrorCode SubspaceCorrection::setup(PC pc) {
  try {
    SubspaceCorrection* self = nullptr;
    check(PCShellGetContext(pc, &self), "PCShellGetContext");
    Mat N = nullptr;
    check(PCGetOperators(pc, nullptr, &N), "PCGetOperators");
    self->factorise(N);
    return 0;
  } catch (const std::exception&) {
    return PETSC_ERR_LIB;  // PETSc's caller reports the failure; no exception crosses its C frames
  }
}

PetscErrorCode SubspaceCorrection::apply(PC pc, Vec x, Vec y) {
  try {
    SubspaceCorrection* self = nullptr;
    check(PCShellGetContext(pc, &self), "PCShellGetContext");
    self->correct(x, y);
    return 0;
  } catch (const std::exception&) {
    return PETSC_ERR_LIB;
  }
}

namespace {

/// GAMG rebuilt from scratch for every new matrix (PETSc keeps the first prolongators by default).
void configure_gamg(PC pc) {
  check(PCSetType(pc, PCGAMG), "PCSetType");
  check(PCGAMGSetReuseInterpolation(pc, PETSC_FALSE), "PCGAMGSetReuseInterpolation");
}

}  // namespace

void configure_newton_preconditioner(PC pc, NewtonPreconditioner kind, SubspaceCorrection* correction) {
  if (kind == NewtonPreconditioner::kGamg) {
    configure_gamg(pc);
    return;
  }
  check(PCSetType(pc, PCCOMPOSITE), "PCSetType");
  check(PCCompositeSetType(pc, PC_COMPOSITE_SYMMETRIC_MULTIPLICATIVE), "PCCompositeSetType");
  check(PCCompositeAddPCType(pc, PCGAMG), "PCCompositeAddPCType");
  check(PCCompositeAddPCType(pc, PCSHELL), "PCCompositeAddPCType");
  PC amg = nullptr, filter = nullptr;
  check(PCCompositeGetPC(pc, 0, &amg), "PCCompositeGetPC");
  check(PCCompositeGetPC(pc, 1, &filter), "PCCompositeGetPC");
  configure_gamg(amg);
  correction->attach(filter);
}

void set_up_newton_preconditioner(PC pc) {
  check(PCSetUp(pc), "PCSetUp");
  PetscBool composite = PETSC_FALSE;
  check(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(pc), PCCOMPOSITE, &composite), "PetscObjectTypeCompare");
  if (!composite) return;
  for (PetscInt k = 0; k < 2; ++k) {
    PC part = nullptr;
    check(PCCompositeGetPC(pc, k, &part), "PCCompositeGetPC");
    check(PCSetUp(part), "PCSetUp");
  }
}

}  // namespace symcontact
