#include "symcontact/energy/energy_sum.hpp"

namespace symcontact {

double EnergySum::value(const VectorXd& u) const {
  double e = 0.0;
  for (const auto& t : terms_) e += t->value(u);
  return e;
}

void EnergySum::add_gradient(const VectorXd& u, VectorXd& g) const {
  for (const auto& t : terms_) t->add_gradient(u, g);
}

void EnergySum::add_hessian(const VectorXd& u, MatrixSink& sink) const {
  for (const auto& t : terms_) t->add_hessian(u, sink);
}

bool EnergySum::hessian_is_constant() const {
  for (const auto& t : terms_)
    if (!t->hessian_is_constant()) return false;
  return true;
}

}  // namespace symcontact
