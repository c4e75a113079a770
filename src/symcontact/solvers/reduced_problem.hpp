#pragma once
/// \file reduced_problem.hpp
/// An energy E(u) with Dirichlet DOFs fixed and linear constraints A u + b ≥ 0, stated on the free DOFs
/// only, as a ConstrainedProblem: u = P x + u_D (P injects the free DOFs, u_D holds the fixed values),
/// f(x) = E(P x + u_D), ∇f = Pᵀ∇E, ∇²f = Pᵀ∇²E P, and constraints (A P) x + (b + A u_D) ≥ 0.

#include <functional>
#include <vector>

#include "symcontact/energy/energy_term.hpp"
#include "symcontact/optim/constrained_problem.hpp"
#include "symcontact/solvers/fixed_dofs.hpp"

namespace symcontact {

class ReducedProblem : public ConstrainedProblem {
 public:
  ReducedProblem(const EnergyTerm& energy, const FixedDofs& fixed, Index num_dofs);

  /// Sets the constraints from their full-DOF form.
  void set_constraints(const SparseMatrix& A, const VectorXd& b);

  Index num_variables() const override { return num_free_; }
  double objective(const VectorXd& x) override;
  void gradient(const VectorXd& x, VectorXd& g) override;
  void hessian_lower(const VectorXd& x, SparseMatrix& H) override;
  bool hessian_is_constant() const override { return energy_.hessian_is_constant(); }
  const SparseMatrix& constraint_matrix() const override { return A_; }
  const VectorXd& constraint_offset() const override { return b_; }

  /// The terms of f's energy beyond a constant-Hessian part (the friction terms): value, gradient, Hessian at u.
  struct Rest {
    std::function<double(const VectorXd& u)> value;
    std::function<void(const VectorXd& u, VectorXd& g)> add_gradient;
    std::function<void(const VectorXd& u, MatrixSink& sink)> add_hessian;
  };
  /// f as `constant` (a problem on the same DOFs and Dirichlet values whose energy's Hessian is constant: the
  /// bodies' energy) plus `rest` (the friction terms). Constant's part is its quadratic form (quadratic_value()),
  /// evaluated from the cached Hessian instead of element by element; hessian_lower() assembles rest's only.
  /// The caller keeps the energy equal to constant's plus rest's.
  void split_energy(ReducedProblem& constant, Rest rest);

  /// For a problem whose energy's Hessian is constant (a quadratic energy): f(x) = f(0) + ∇f(0)ᵀx + ½ xᵀ∇²f x and
  /// its gradient, f(0) and ∇f(0) evaluated once (the first call); f itself up to the terms' round-off.
  double quadratic_value(const VectorXd& x);
  void quadratic_gradient(const VectorXd& x, VectorXd& g);

  VectorXd expand(const VectorXd& x) const;    ///< u = P x + u_D
  VectorXd restrict(const VectorXd& u) const;  ///< x = Pᵀ u
  Index num_free() const { return num_free_; }
  const std::vector<Index>& free_index() const { return free_index_; }  ///< DOF → free index or −1

 private:
  const EnergyTerm& energy_;
  VectorXd u_fixed_;              ///< u_D (zero on free DOFs)
  std::vector<Index> free_index_; ///< DOF → free index or −1
  std::vector<Index> free_dofs_;  ///< free index → DOF
  Index num_free_ = 0;
  SparseMatrix A_;
  VectorXd b_;
  SparseMatrix H_cache_;
  bool have_H_ = false;
  ReducedProblem* constant_ = nullptr;  ///< split_energy()'s
  Rest rest_;
  /// The quadratic form's f(0) and ∇f(0) (quadratic_value()), once evaluated.
  double f_at_zero_ = 0.0;
  VectorXd g_at_zero_;
};

}  // namespace symcontact
