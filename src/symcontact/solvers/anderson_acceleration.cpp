#include "symcontact/solvers/anderson_acceleration.hpp"

#include <Eigen/Dense>

#include "symcontact/core/error.hpp"

namespace symcontact {

AndersonAcceleration::AndersonAcceleration(int memory) : memory_(memory) {
  if (memory < 1) throw std::invalid_argument("AndersonAcceleration: memory must be at least 1");
}

void AndersonAcceleration::reset() {
  has_previous_ = false;
  dF_.clear();
  dG_.clear();
}

VectorXd AndersonAcceleration::next(const VectorXd& x, const VectorXd& g) {
  if (x.size() != g.size()) throw std::invalid_argument("AndersonAcceleration::next: x and G(x) differ in size");
  const VectorXd f = g - x;
  if (has_previous_ && f_prev_.size() != f.size()) reset();
  if (has_previous_) {
    dF_.push_back(f - f_prev_);
    dG_.push_back(g - g_prev_);
    if (static_cast<int>(dF_.size()) > memory_) {
      dF_.pop_front();
      dG_.pop_front();
    }
  }
  f_prev_ = f;
  g_prev_ = g;
  has_previous_ = true;
  const int k = columns();
  if (k == 0) return g;
  Eigen::MatrixXd F(f.size(), k);
  for (int j = 0; j < k; ++j) F.col(j) = dF_[j];
  // Least squares by a rank-revealing QR: nearly parallel columns (a mode already converged) get no
  // weight instead of an ill-conditioned one.
  const Eigen::VectorXd gamma = F.colPivHouseholderQr().solve(f);
  VectorXd out = g;
  for (int j = 0; j < k; ++j) out -= gamma[j] * dG_[j];
  return out;
}

}  // namespace symcontact
