#pragma once
/// \file composite_energy.hpp
/// The energy a geometry iteration minimises: the bodies' energy E (elastic + loads) plus the friction terms
/// j_τ of the current iterate, one per contact pair (friction_term.hpp):
///     E(U) + Σ_pairs j_τ(U).
/// A null term adds nothing (a frictionless pair, or a zero threshold), so the sum stays quadratic where E is.

#include <memory>
#include <vector>

#include "symcontact/contact/friction_term.hpp"
#include "symcontact/energy/energy_term.hpp"

namespace symcontact {

class CompositeEnergy : public EnergyTerm {
 public:
  explicit CompositeEnergy(const EnergyTerm& base) : base_(base) {}
  /// One entry per pair; null entries are skipped.
  std::vector<std::shared_ptr<const FrictionTerm>> extra;
  std::string name() const override { return "energy+friction"; }
  double value(const VectorXd& u) const override;
  void add_gradient(const VectorXd& u, VectorXd& g) const override;
  void add_hessian(const VectorXd& u, MatrixSink& sink) const override;
  /// The friction terms' part of value() alone.
  double extra_value(const VectorXd& u) const;
  /// The friction terms' part of add_gradient() alone.
  void add_extra_gradient(const VectorXd& u, VectorXd& g) const;
  /// The friction terms' part of add_hessian() alone.
  void add_extra_hessian(const VectorXd& u, MatrixSink& sink) const;
  /// E's, as long as no friction term is present.
  bool hessian_is_constant() const override;

 private:
  const EnergyTerm& base_;
};

}  // namespace symcontact
