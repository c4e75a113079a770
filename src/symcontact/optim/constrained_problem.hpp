#pragma once
/// \file constrained_problem.hpp
/// The optimisation problem the contact solver hands to an interior-point method, with no IPOPT types
/// (STYLE.md §9):
///
///     min_x f(x)   subject to   c(x) = A x + b ≥ 0,      x ∈ R^n,
///
/// optionally with its first k rows equalities (c_i(x) = 0, num_equalities()) and simple lower bounds
/// x ≥ x_l (lower_bounds(); the dual of the condensed contact problem, dual_condensed_problem.hpp, has both),
///
/// f smooth (twice differentiable; convex for linear elasticity), A a constant sparse m × n matrix for
/// the duration of one solve (contact constraints linearised at frozen projections and normals).
/// The Hessian of the Lagrangian is ∇²f because the constraints are linear.

#include "symcontact/core/types.hpp"

namespace symcontact {

class ConstrainedProblem {
 public:
  virtual ~ConstrainedProblem() = default;
  virtual Index num_variables() const = 0;
  /// f(x). May throw EvaluationError (core/error.hpp) when f cannot be evaluated at x.
  virtual double objective(const VectorXd& x) = 0;
  /// g = ∇f(x) (g is resized by the callee).
  virtual void gradient(const VectorXd& x, VectorXd& g) = 0;
  /// The lower triangle (row ≥ column) of ∇²f(x), compressed (column-major). Its sparsity pattern
  /// must be the same at every call within one solve; explicit zeros are allowed.
  virtual void hessian_lower(const VectorXd& x, SparseMatrix& H) = 0;
  /// M += s ∇²f(x) on the lower triangle of the dense column-major n × n matrix M (the dense interior point's
  /// normal matrix). The default adds the entries of hessian_lower(); a problem whose Hessian is nearly full
  /// adds its terms directly, without a sparse copy (the condensed problem: S and the friction blocks).
  virtual void add_hessian_lower(const VectorXd& x, double s, Eigen::Ref<MatrixXd> M);
  /// out = ∇²f(x) v. The default multiplies with hessian_lower().
  virtual void hessian_product(const VectorXd& x, const VectorXd& v, VectorXd& out);
  /// True when ∇²f does not depend on x.
  virtual bool hessian_is_constant() const { return false; }
  /// True when ∇²f is (nearly) full, so that dense factorisations beat sparse ones on it (the condensed
  /// problem's Schur complement). A hint for the active-set polish; results agree to round-off either way.
  virtual bool hessian_is_dense() const { return false; }
  /// A (m × n, compressed) and b (m) of the constraints c(x) = A x + b ≥ 0.
  virtual const SparseMatrix& constraint_matrix() const = 0;
  virtual const VectorXd& constraint_offset() const = 0;
  /// k: the first k rows of A x + b are equalities (= 0), the rest inequalities (≥ 0).
  virtual Index num_equalities() const { return 0; }
  /// Lower bounds x ≥ x_l on the variables (size n), or null for none.
  virtual const VectorXd* lower_bounds() const { return nullptr; }
};

}  // namespace symcontact
