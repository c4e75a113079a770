#pragma once
/// \file quadratic_energy.hpp
/// Stand-ins for an elastic energy in the solver tests: E(u) = ½ uᵀK u − fᵀu over all DOFs, with K given by
/// its lower triangle, and the 5-point Laplacian of a grid to serve as K.

#include <string>

#include "symcontact/energy/energy_term.hpp"

namespace symcontact::testing {

/// The 5-point Laplacian of an m × m grid (Neumann: singular, constants in its kernel) plus shift·I, lower
/// triangle.
SparseMatrix grid_laplacian(int m, double shift);

/// E(u) = ½ uᵀK u − fᵀu (a stand-in for linear elasticity); its Hessian goes to the sink as 1 × 1 diagonal
/// blocks and 2 × 2 blocks holding one off-diagonal entry each.
class QuadraticEnergy : public EnergyTerm {
 public:
  QuadraticEnergy(SparseMatrix lower, VectorXd f) : k_(std::move(lower)), f_(std::move(f)) {}
  std::string name() const override { return "quadratic"; }
  double value(const VectorXd& u) const override;
  void add_gradient(const VectorXd& u, VectorXd& g) const override;
  void add_hessian(const VectorXd& u, MatrixSink& sink) const override;
  bool hessian_is_constant() const override { return true; }

 private:
  SparseMatrix k_;
  VectorXd f_;
};

}  // namespace symcontact::testing
