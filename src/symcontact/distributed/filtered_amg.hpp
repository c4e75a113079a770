#pragma once
/// \file filtered_amg.hpp
/// Algebraic multigrid with filtering: a preconditioner for the Newton systems of contact interior points,
///
///     N = K + Aᵀ Σ A,   Σ = diag(λ_j / s_j),
///
/// whose contact entries grow without bound on the active rows as the barrier parameter falls (λ_j → the
/// contact force, s_j → 0). Smoothed-aggregation AMG alone (GAMG) does not see that the contact DOFs are
/// stiffened far beyond their neighbours, and its conjugate-gradient iteration count grows with Σ. The
/// filter adds an exact solve on a small subspace that holds those DOFs: with P the injection of the contact
/// nodes' DOFs and B one AMG cycle on N, the iteration matrix is the symmetric product
///
///     I − M N = (I − B N) (I − P (Pᵀ N P)⁻¹ Pᵀ N) (I − B N),
///
/// symmetric positive definite for an SPD N, so conjugate gradients apply (Petrides, Hartland, Kolev et al.,
/// "AMG with filtering", 2025; a two-level symmetric multiplicative Schwarz method, Xu, SIAM Review 34 (1992)).
/// Pᵀ N P is the stiffness block of the contact surface's nodes plus Σ: sparse, with the surface's graph,
/// factorised directly (gathered on every rank, PETSc's own LU with a nested-dissection ordering).
///
/// Here: PETSc's PCCOMPOSITE, symmetric multiplicative, of PCGAMG and a shell PC that applies
/// P (Pᵀ N P)⁻¹ Pᵀ.

#include <petscksp.h>

#include <vector>

#include "symcontact/core/types.hpp"
#include "symcontact/distributed/petsc_support.hpp"

namespace symcontact {

/// y = P (Pᵀ N P)⁻¹ Pᵀ x, refactorised whenever N's values change (the PC's set-up).
class SubspaceCorrection {
 public:
  /// dofs: this rank's own rows of the subspace (every rank passes its part; collective).
  explicit SubspaceCorrection(const std::vector<PetscInt>& dofs);
  SubspaceCorrection(const SubspaceCorrection&) = delete;
  SubspaceCorrection& operator=(const SubspaceCorrection&) = delete;

  /// Makes pc the shell that applies the correction; *this must outlive pc's use.
  void attach(PC pc);

 private:
  static PetscErrorCode setup(PC pc);
  static PetscErrorCode apply(PC pc, Vec x, Vec y);
  void factorise(Mat N);
  void correct(Vec x, Vec y);

  petsc::Owned<IS, ISDestroy> dofs_;
  petsc::Owned<Mat, MatDestroy> block_;  ///< Pᵀ N P
  petsc::Owned<KSP, KSPDestroy> direct_;
  petsc::Owned<Vec, VecDestroy> rhs_, sol_;
};

enum class NewtonPreconditioner {
  kGamg,          ///< smoothed-aggregation AMG on N alone
  kFilteredGamg,  ///< the same, with the exact correction on the contact nodes' DOFs
};

/// Sets pc to the chosen preconditioner for N (PCGAMG, or PCCOMPOSITE of PCGAMG and `correction`); GAMG's
/// hierarchy is rebuilt for every new N. Keeping the prolongators of the first N (PETSc's default,
/// PCGAMGSetReuseInterpolation) with the smoothers' eigenvalue bounds of that N makes the preconditioner
/// indefinite as Σ grows; with fresh bounds it needs about twice the iterations. N must carry its near null space (the rigid-body modes).
void configure_newton_preconditioner(PC pc, NewtonPreconditioner kind, SubspaceCorrection* correction);

/// Builds the preconditioner for pc's current operator now, the composite's parts included (PETSc would
/// otherwise build them at the first application, inside the Krylov solve).
void set_up_newton_preconditioner(PC pc);

}  // namespace symcontact
