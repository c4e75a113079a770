#pragma once
// A random convex problem shaped like the condensed frictional subproblem, for the tests of the dense primal
// interior point (solvers/dense_primal_interior_point.hpp) and of the active-set start
// (solvers/active_set_start.hpp): a dense positive definite quadratic plus regularised |x_k| terms (the friction
// term's sqrt(|v|² + α²)), and sparse rows.
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include <Eigen/Dense>

#include "symcontact/optim/constrained_problem.hpp"
#include "symcontact/optim/ipopt_solver.hpp"

namespace symcontact::testing {

/// f(x) = ½ xᵀQx − qᵀx + w Σ_k sqrt(x_k² + α²) for k in the first half of x; A x + b ≥ 0.
/// Lengths are in units of `length` and forces in units of `force` (a change of units multiplies x by
/// `length`, Q by force/length, q by force, w by force·length / length = force, α by length).
class FrictionLikeProblem : public ConstrainedProblem {
 public:
  FrictionLikeProblem(Index n, Index m, unsigned seed, double length = 1.0, double force = 1.0) : alpha_(1e-3 * length) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    MatrixXd B(n, n);
    for (Index i = 0; i < n; ++i)
      for (Index j = 0; j < n; ++j) B(i, j) = u(rng);
    Q_ = (B.transpose() * B + 0.1 * MatrixXd::Identity(n, n)) * (force / length);
    q_.resize(n);
    for (Index i = 0; i < n; ++i) q_[i] = 3.0 * u(rng) * force;
    w_ = 0.3 * force;
    std::vector<Eigen::Triplet<double>> t;
    for (Index i = 0; i < m; ++i) {
      // a gap row: one DOF against a combination of two others, as a node against a facet
      const Index a = i % n, b = (i + 1 + i / n) % n, c = (i + 3) % n;
      t.emplace_back(i, a, 1.0);
      t.emplace_back(i, b, -0.5 + 0.2 * u(rng));
      if (c != a && c != b) t.emplace_back(i, c, -0.3);
    }
    A_.resize(m, n);
    A_.setFromTriplets(t.begin(), t.end());
    b_.resize(m);
    for (Index i = 0; i < m; ++i) b_[i] = 0.2 * (u(rng) + 0.5) * length;
  }
  Index num_variables() const override { return Q_.rows(); }
  double objective(const VectorXd& x) override {
    double f = 0.5 * x.dot(Q_ * x) - q_.dot(x);
    for (Index k = 0; k < x.size() / 2; ++k) f += w(k) * std::sqrt(x[k] * x[k] + alpha_ * alpha_);
    return f;
  }
  void gradient(const VectorXd& x, VectorXd& g) override {
    g = Q_ * x - q_;
    for (Index k = 0; k < x.size() / 2; ++k) g[k] += w(k) * x[k] / std::sqrt(x[k] * x[k] + alpha_ * alpha_);
  }
  void hessian_lower(const VectorXd& x, SparseMatrix& H) override {
    MatrixXd D = Q_;
    for (Index k = 0; k < x.size() / 2; ++k) D(k, k) += w(k) * alpha_ * alpha_ / std::pow(x[k] * x[k] + alpha_ * alpha_, 1.5);
    H = D.triangularView<Eigen::Lower>().toDenseMatrix().sparseView();
    // the same pattern at every call: the full lower triangle
    for (Index j = 0; j < D.cols(); ++j)
      for (Index i = j; i < D.rows(); ++i)
        if (H.coeff(i, j) == 0.0) H.coeffRef(i, j) = 0.0;
    H.makeCompressed();
  }
  /// Dense by default (the condensed problem's Hessian); set_dense(false) makes the methods take their sparse
  /// path (CHOLMOD on the same full lower triangle).
  bool hessian_is_dense() const override { return dense_; }
  void set_dense(bool dense) { dense_ = dense; }
  double weight() const { return w_; }
  void shift_offset(double fraction) { b_.array() += fraction * b_.cwiseAbs().maxCoeff(); }
  void set_weight(double w) { w_ = w; }
  /// Weights of each |x_k| term instead of the one w (empty: w for every term).
  const VectorXd& weights() const { return wk_; }
  void set_weights(const VectorXd& w) { wk_ = w; }
  const SparseMatrix& constraint_matrix() const override { return A_; }
  const VectorXd& constraint_offset() const override { return b_; }

 private:
  MatrixXd Q_;
  VectorXd q_;
  double w(Index k) const { return wk_.size() ? wk_[k] : w_; }
  double w_, alpha_;
  VectorXd wk_;
  bool dense_ = true;
  SparseMatrix A_;
  VectorXd b_;
};

/// The rule of the tests whose data follow the iterate: w_k = 0.2 (1 + λ_k) for the |x_k| terms (the first half
/// of x's n entries), each term's weight following one row's multiplier, as τ = μ p follows the pressure.
inline VectorXd followed_weights(const VectorXd& multipliers, Index n) {
  return VectorXd(0.2 * (1.0 + multipliers.head(n / 2).array()));
}

/// A hook of FollowIterate's form (solvers/dense_primal_interior_point.hpp) that sets q's weights by
/// followed_weights() until they change by at most 1e-12 of their largest; `changes` (if given) counts the
/// changes.
inline std::function<bool(const VectorXd&, const VectorXd&)> weights_follower(FrictionLikeProblem& q,
                                                                              int* changes = nullptr) {
  return [&q, changes](const VectorXd&, const VectorXd& multipliers) {
    const VectorXd w = followed_weights(multipliers, q.num_variables());
    if ((w - q.weights()).lpNorm<Eigen::Infinity>() <= 1e-12 * w.lpNorm<Eigen::Infinity>()) return false;
    q.set_weights(w);
    if (changes) ++*changes;
    return true;
  };
}

/// The largest KKT violation, relative to the problem's force scale ‖q‖∞ and length scale.
inline double kkt_violation(FrictionLikeProblem& p, const IpoptResult& r, double force, double length) {
  VectorXd g;
  p.gradient(r.x, g);
  const VectorXd rd = g - p.constraint_matrix().transpose() * r.multipliers;
  const VectorXd c = p.constraint_matrix() * r.x + p.constraint_offset();
  double v = rd.lpNorm<Eigen::Infinity>() / force;
  v = std::max(v, -c.minCoeff() / length);
  v = std::max(v, -r.multipliers.minCoeff() / force);
  v = std::max(v, c.cwiseProduct(r.multipliers).cwiseAbs().maxCoeff() / (force * length));
  return v;
}

}  // namespace symcontact::testing
