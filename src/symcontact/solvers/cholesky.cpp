#include "symcontact/solvers/cholesky.hpp"

#include <Eigen/CholmodSupport>

#include "symcontact/core/error.hpp"

namespace symcontact {

struct CholeskySolver::Impl {
  Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower> llt;
  Index n = -1;
};

CholeskySolver::CholeskySolver() : impl_(std::make_unique<Impl>()) {
  // CHOLMOD prints its warnings ("matrix not positive definite") to stdout by default; every failure is
  // reported here through info()/status instead, and callers that probe definiteness (the Newton shift,
  // the polish) expect failures.
  impl_->llt.cholmod().print = 0;
}
CholeskySolver::~CholeskySolver() = default;

void CholeskySolver::analyze(const SparseMatrix& lower) {
  impl_->llt.analyzePattern(lower);
  if (impl_->llt.info() != Eigen::Success || impl_->llt.cholmod().status < CHOLMOD_OK) {
    impl_->n = -1;
    throw SolveError(
        "CHOLMOD could not analyse the stiffness matrix (status " + std::to_string(impl_->llt.cholmod().status) +
        "): the problem is probably too large for the 32-bit CHOLMOD interface or for the memory available");
  }
  impl_->n = lower.rows();
}

void CholeskySolver::factorize(const SparseMatrix& lower) {
  impl_->llt.factorize(lower);
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
  auto& c = const_cast<Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower>&>(impl_->llt).cholmod();
  return c.lnz;
}

}  // namespace symcontact
