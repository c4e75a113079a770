#include "symcontact/solvers/cholesky.hpp"

#include <Eigen/CholmodSupport>

#include "symcontact/core/error.hpp"
#include "symcontact/solvers/cholmod_long.hpp"

namespace symcontact {

struct CholeskySolver::Impl {
  using Decomposition = Eigen::CholmodDecomposition<CholmodSparseMatrix, Eigen::Lower>;  // cholmod_l_*
  Decomposition llt;
  Index n = -1;
};

CholeskySolver::CholeskySolver() : impl_(std::make_unique<Impl>()) {
  // CHOLMOD prints its warnings ("matrix not positive definite") to stdout by default; every failure is
  // reported here through info()/status instead, and callers that probe definiteness (the Newton shift,
  // the polish) expect failures.
  impl_->llt.cholmod().print = 0;
  // Where CHOLMOD picks a simplicial factor (small or very sparse matrices) it computes LDLᵀ, which
  // factorises a nonsingular indefinite matrix without complaint (see the header). LLᵀ is not forced there
  // (final_asis = 0, final_ll = 1): the equilibrium solver's Dirichlet predictor (equilibrium_solver.cpp,
  // factorize_descent(), which shifts K when it is not definite) would then take a shifted step on small
  // problems, with which a sub-step's geometry fixed point of the frictional ironing test does not converge;
  // the polish's factorisations are indifferent to it. So the predictor takes the exact tangent step on
  // small problems and a shifted one on large ones (supernodal LLᵀ throws, then K + τI): not consistent.
}
CholeskySolver::~CholeskySolver() = default;

void CholeskySolver::analyze(const SparseMatrix& lower) {
  impl_->llt.analyzePattern(to_cholmod_long(lower));
  if (impl_->llt.info() != Eigen::Success || impl_->llt.cholmod().status < CHOLMOD_OK) {
    impl_->n = -1;
    throw SolveError(
        "CHOLMOD could not analyse the stiffness matrix (status " + std::to_string(impl_->llt.cholmod().status) +
        "): the factor probably does not fit in the memory available");
  }
  impl_->n = lower.rows();
}

void CholeskySolver::factorize(const SparseMatrix& lower) {
  impl_->llt.factorize(to_cholmod_long(lower));
  if (impl_->llt.info() != Eigen::Success)
    throw SolveError(
        "the stiffness matrix is not positive definite (CHOLMOD could not factorise it): a body is "
        "probably free to move rigidly — check its Dirichlet conditions");
}

void CholeskySolver::compute(const SparseMatrix& lower) {
  if (impl_->n != lower.rows()) analyze(lower);
  factorize(lower);
}

VectorXd CholeskySolver::solve(const VectorXd& b) const { return impl_->llt.solve(b); }

MatrixXd CholeskySolver::solve(const MatrixXd& B) const { return impl_->llt.solve(B); }

double CholeskySolver::factor_nonzeros() const {
  auto& c = const_cast<Impl::Decomposition&>(impl_->llt).cholmod();
  return c.lnz;
}

double CholeskySolver::factor_flops() const {
  auto& c = const_cast<Impl::Decomposition&>(impl_->llt).cholmod();
  return c.fl;
}

}  // namespace symcontact
