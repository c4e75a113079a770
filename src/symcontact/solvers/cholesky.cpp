#include "symcontact/solvers/cholesky.hpp"

#include <Eigen/CholmodSupport>

#include "symcontact/core/error.hpp"

namespace symcontact {

struct CholeskySolver::Impl {
  Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower> llt;
  Index n = -1;
};

CholeskySolver::CholeskySolver() : impl_(std::make_unique<Impl>()) {}
CholeskySolver::~CholeskySolver() = default;

void CholeskySolver::analyze(const SparseMatrix& lower) {
  impl_->llt.analyzePattern(lower);
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

double CholeskySolver::factor_nonzeros() const {
  auto& c = const_cast<Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower>&>(impl_->llt).cholmod();
  return c.lnz;
}

}  // namespace symcontact
