#pragma once
/// \file energy_term.hpp
/// The one interface every energy term implements (STYLE.md §2). The solver minimises
/// E(u) = Σ_k E_k(u) (possibly under contact constraints) and never special-cases physics:
/// elastic strain energy, external loads, and later friction and hyperelasticity look alike.
///
/// Contract: u is the global DOF vector (DofMap layout). add_gradient() adds ∂E/∂u into g (same size
/// as u); add_hessian() adds ∂²E/∂u² as dense element blocks into a MatrixSink. All three are
/// evaluated at the same u and are consistent (checked by finite differences in the tests).
/// An evaluation that is impossible at u (an inverted element) throws EvaluationError (core/error.hpp).

#include <string>

#include "symcontact/core/error.hpp"
#include "symcontact/core/types.hpp"
#include "symcontact/fem/matrix_sink.hpp"

namespace symcontact {

class EnergyTerm {
 public:
  virtual ~EnergyTerm() = default;
  virtual std::string name() const = 0;
  virtual double value(const VectorXd& u) const = 0;
  virtual void add_gradient(const VectorXd& u, VectorXd& g) const = 0;
  virtual void add_hessian(const VectorXd& u, MatrixSink& sink) const = 0;
  /// True when the Hessian does not depend on u (E is at most quadratic).
  virtual bool hessian_is_constant() const { return false; }
};

}  // namespace symcontact
