#pragma once
/// \file cholesky.hpp
/// Sparse Cholesky factorisation A = L Lᵀ of a symmetric positive definite matrix by CHOLMOD
/// (supernodal LLᵀ or simplicial LDLᵀ, CHOLMOD's choice by size and sparsity),
/// through Eigen's CholmodSupport and CHOLMOD's 64-bit interface at every size (cholmod_long.hpp: no 2³¹
/// limit on the factor's entries). Only the lower triangle of A is read (copied once per call to 64-bit
/// indices). The symbolic analysis can be reused across factorisations of matrices with the same
/// pattern. This is also the "physical floor" that contact solves are measured against.

#include <memory>

#include "symcontact/core/types.hpp"

namespace symcontact {

class CholeskySolver {
 public:
  CholeskySolver();
  ~CholeskySolver();
  CholeskySolver(const CholeskySolver&) = delete;
  CholeskySolver& operator=(const CholeskySolver&) = delete;

  /// Fill-reducing ordering and symbolic factorisation (pattern of `lower` only).
  void analyze(const SparseMatrix& lower);
  /// Numeric factorisation. Throws SolveError when A is not positive definite (for an elastic
  /// stiffness: a body free to move rigidly, i.e. too few Dirichlet conditions) — with a supernodal
  /// factor. With a simplicial one (CHOLMOD's choice for small or very sparse matrices, e.g. a
  /// 3D grid Laplacian of 6³ unknowns) the factor is LDLᵀ, and a nonsingular indefinite A is factorised
  /// and solved exactly instead; only a zero pivot throws. LLᵀ is not forced there: with it the
  /// Dirichlet predictor (equilibrium_solver.cpp, factorize_descent()) takes a shifted step instead of
  /// the exact tangent one, and a sub-step's geometry fixed point in the frictional ironing test does not
  /// converge (see the .cpp). Callers that need definiteness on small problems must not infer it from
  /// success.
  void factorize(const SparseMatrix& lower);
  /// analyze() when needed (first call or new size), then factorize().
  void compute(const SparseMatrix& lower);
  VectorXd solve(const VectorXd& b) const;
  /// Several right-hand sides at once (columns of B).
  MatrixXd solve(const MatrixXd& B) const;
  /// Number of nonzeros in the factor L: predicted by analyze(), exact after factorize().
  double factor_nonzeros() const;
  /// Floating-point operations of the numeric factorisation, as analyze() predicts them (CHOLMOD's count).
  double factor_flops() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace symcontact
