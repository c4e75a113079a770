#pragma once
/// \file energy_sum.hpp
/// E(u) = Σ_k E_k(u): the total energy the solvers minimise. Owns its terms.

#include <memory>
#include <vector>

#include "symcontact/energy/energy_term.hpp"

namespace symcontact {

class EnergySum : public EnergyTerm {
 public:
  /// Adds a term and returns a non-owning pointer to it (to set load factors later).
  template <class T>
  T* add(std::unique_ptr<T> term) {
    T* p = term.get();
    terms_.push_back(std::move(term));
    return p;
  }
  std::string name() const override { return "total"; }
  double value(const VectorXd& u) const override;
  void add_gradient(const VectorXd& u, VectorXd& g) const override;
  void add_hessian(const VectorXd& u, MatrixSink& sink) const override;
  bool hessian_is_constant() const override;
  const std::vector<std::unique_ptr<EnergyTerm>>& terms() const { return terms_; }

 private:
  std::vector<std::unique_ptr<EnergyTerm>> terms_;
};

}  // namespace symcontact
