#include "symcontact/solvers/reduced_problem.hpp"

#include <stdexcept>

namespace symcontact {

ReducedProblem::ReducedProblem(const EnergyTerm& energy, const FixedDofs& fixed, Index num_dofs) : energy_(energy) {
  num_free_ = fixed.free_numbering(num_dofs, free_index_);
  free_dofs_.resize(num_free_);
  for (Index d = 0; d < num_dofs; ++d)
    if (free_index_[d] >= 0) free_dofs_[free_index_[d]] = d;
  u_fixed_ = VectorXd::Zero(num_dofs);
  fixed.impose(u_fixed_);
  A_.resize(0, num_free_);
}

void ReducedProblem::set_constraints(const SparseMatrix& A, const VectorXd& b) {
  b_ = b;
  std::vector<Triplet> t;
  t.reserve(A.nonZeros());
  for (int j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) {
      const Index f = free_index_[j];
      if (f >= 0)
        t.emplace_back(static_cast<int>(it.row()), static_cast<int>(f), it.value());
      else
        b_[it.row()] += it.value() * u_fixed_[j];
    }
  A_.resize(A.rows(), num_free_);
  A_.setFromTriplets(t.begin(), t.end());
}

VectorXd ReducedProblem::expand(const VectorXd& x) const {
  VectorXd u = u_fixed_;
  for (Index k = 0; k < num_free_; ++k) u[free_dofs_[k]] = x[k];
  return u;
}

VectorXd ReducedProblem::restrict(const VectorXd& u) const {
  VectorXd x(num_free_);
  for (Index k = 0; k < num_free_; ++k) x[k] = u[free_dofs_[k]];
  return x;
}

double ReducedProblem::objective(const VectorXd& x) {
  if (constant_) return constant_->quadratic_value(x) + rest_.value(expand(x));
  return energy_.value(expand(x));
}

void ReducedProblem::gradient(const VectorXd& x, VectorXd& g) {
  VectorXd gu = VectorXd::Zero(u_fixed_.size());
  if (!constant_) {
    energy_.add_gradient(expand(x), gu);
    g = restrict(gu);
    return;
  }
  constant_->quadratic_gradient(x, g);
  rest_.add_gradient(expand(x), gu);
  for (Index k = 0; k < num_free_; ++k) g[k] += gu[free_dofs_[k]];
}

void ReducedProblem::split_energy(ReducedProblem& constant, Rest rest) {
  constant_ = &constant;
  rest_ = std::move(rest);
}

double ReducedProblem::quadratic_value(const VectorXd& x) {
  VectorXd g;
  quadratic_gradient(x, g);  // ∇f(0) + H x
  // f(0) + ∇f(0)ᵀx + ½ xᵀH x = f(0) + ½ (∇f(0) + ∇f(x))ᵀx
  return f_at_zero_ + 0.5 * (g_at_zero_ + g).dot(x);
}

void ReducedProblem::quadratic_gradient(const VectorXd& x, VectorXd& g) {
  if (!energy_.hessian_is_constant())
    throw std::logic_error("ReducedProblem::quadratic_gradient: the energy " + energy_.name() + " is not quadratic");
  if (g_at_zero_.size() != num_free_) {
    const VectorXd zero = VectorXd::Zero(num_free_);
    f_at_zero_ = energy_.value(expand(zero));
    VectorXd gu = VectorXd::Zero(u_fixed_.size());
    energy_.add_gradient(expand(zero), gu);
    g_at_zero_ = restrict(gu);
  }
  SparseMatrix H;
  if (!have_H_) hessian_lower(x, H);
  g = g_at_zero_;
  g.noalias() += H_cache_.selfadjointView<Eigen::Lower>() * x;
}

void ReducedProblem::hessian_lower(const VectorXd& x, SparseMatrix& H) {
  if (have_H_ && energy_.hessian_is_constant()) {
    H = H_cache_;
    return;
  }
  if (constant_) {
    constant_->hessian_lower(x, H);
    ReducedTripletSink sink(free_index_);
    rest_.add_hessian(expand(x), sink);
    if (!sink.triplets().empty()) H += sink.to_lower_matrix(num_free_);
    return;
  }
  ReducedTripletSink sink(free_index_);
  energy_.add_hessian(expand(x), sink);
  H = sink.to_lower_matrix(num_free_);
  if (energy_.hessian_is_constant()) {
    H_cache_ = H;
    have_H_ = true;
  }
}

}  // namespace symcontact
