#include "symcontact/solvers/composite_energy.hpp"

namespace symcontact {

double CompositeEnergy::value(const VectorXd& u) const { return base_.value(u) + extra_value(u); }

double CompositeEnergy::extra_value(const VectorXd& u) const {
  double v = 0.0;
  for (const auto& t : extra)
    if (t) v += t->value(u);
  return v;
}

void CompositeEnergy::add_gradient(const VectorXd& u, VectorXd& g) const {
  base_.add_gradient(u, g);
  add_extra_gradient(u, g);
}

void CompositeEnergy::add_extra_gradient(const VectorXd& u, VectorXd& g) const {
  for (const auto& t : extra)
    if (t) t->add_gradient(u, g);
}

void CompositeEnergy::add_hessian(const VectorXd& u, MatrixSink& sink) const {
  base_.add_hessian(u, sink);
  add_extra_hessian(u, sink);
}

void CompositeEnergy::add_extra_hessian(const VectorXd& u, MatrixSink& sink) const {
  for (const auto& t : extra)
    if (t) t->add_hessian(u, sink);
}

bool CompositeEnergy::hessian_is_constant() const {
  for (const auto& t : extra)
    if (t) return false;
  return base_.hessian_is_constant();
}

}  // namespace symcontact
