#include "symcontact/solvers/dense_qp_interior_point.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <Eigen/Dense>

extern "C" {
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
}

namespace symcontact {

namespace {

/// The factorised Newton system of one iteration: H = W + X⁻¹Z = L Lᵀ and the range-space pieces for G.
class NewtonSystem {
 public:
  NewtonSystem(Index m, const MatrixXd& G) : L_(m, m), G_(G), Y_(m, G.rows()) {}

  /// Factorises W + diag(h) (lower triangle); false when dpotrf breaks down even with the shift.
  bool factorize(const AlignedMatrix& W, const VectorXd& h, double shift) {
    const Index m = W.rows();
    auto l = L_.map();
    const auto w = W.map();
    for (Index j = 0; j < m; ++j) {
      l.col(j).tail(m - j) = w.col(j).tail(m - j);
      l(j, j) += h[j] + shift;
    }
    const int mi = static_cast<int>(m);
    int info = 0;
    dpotrf_("L", &mi, L_.data(), &mi, &info);
    if (info != 0) return false;
    if (G_.rows() > 0) {
      Y_.map() = G_.transpose();
      lower_solve(L_, false, Y_);
      M_.compute(Y_.map().transpose() * Y_.map());
    }
    return true;
  }

  /// Solves H Δx − Gᵀ Δβ = f, G Δx = g.
  void solve(const VectorXd& f, const VectorXd& g, VectorXd& dx, VectorXd& dbeta) const {
    const Index m = f.size();
    AlignedMatrix v(m, 1);
    v.map() = f;
    lower_solve(L_, false, v);
    if (G_.rows() > 0) {
      dbeta = M_.solve(g - Y_.map().transpose() * v.map());
      v.map() += Y_.map() * dbeta;
    } else {
      dbeta.resize(0);
    }
    lower_solve(L_, true, v);
    dx = v.map();
  }

 private:
  AlignedMatrix L_;
  const MatrixXd& G_;
  AlignedMatrix Y_;
  Eigen::CompleteOrthogonalDecomposition<MatrixXd> M_;
};

}  // namespace

DenseQpResult solve_dense_qp(const AlignedMatrix& W, const VectorXd& d, const MatrixXd& G, const VectorXd& e,
                             const DenseQpOptions& options, const VectorXd* x0, const VectorXd* z0,
                             const VectorXd* beta0) {
  const Index m = W.rows(), k = G.rows();
  if (W.cols() != m || d.size() != m || (k > 0 && G.cols() != m) || e.size() != k)
    throw std::invalid_argument("solve_dense_qp: sizes of W, d, G and e differ");
  if ((x0 && x0->size() != m) || (z0 && z0->size() != m) || (beta0 && beta0->size() != k) || (!x0 != !z0))
    throw std::invalid_argument("solve_dense_qp: the starting point's sizes differ from the problem's");
  DenseQpResult r;
  if (m == 0) {
    r.success = k == 0 || e.lpNorm<Eigen::Infinity>() == 0.0;
    r.status = r.success ? "converged" : "equality rows without variables";
    r.beta = VectorXd::Zero(k);
    return r;
  }
  // Scales of the residuals: relative, not floored at 1 (a small load gives a small d, and a floor of 1 would
  // loosen the test by the load's size: 1e-3 on the inclined interface, where the geometry fixed point
  // then stalls at a change of 2e-6).
  const double w_max = W.map().diagonal().cwiseAbs().maxCoeff();
  const double d_max = d.lpNorm<Eigen::Infinity>(), e_max = k > 0 ? e.lpNorm<Eigen::Infinity>() : 0.0;
  const double s_d = d_max > 0 ? d_max : (w_max > 0 ? w_max : 1.0);
  const double s_p = e_max > 0 ? e_max : 1.0;
  auto residual_d = [&](const VectorXd& x, const VectorXd& z, const VectorXd& beta) {
    VectorXd rd = -d - z;
    symmetric_multiply_add(W, x, rd);
    if (k > 0) rd.noalias() -= G.transpose() * beta;
    return rd;
  };

  VectorXd x, z, beta = beta0 ? *beta0 : VectorXd::Zero(k);
  if (x0) {
    // A warm start: the previous solution, lifted off the bounds (an interior point method cannot start on them).
    const double x_max = x0->lpNorm<Eigen::Infinity>(), z_max = z0->lpNorm<Eigen::Infinity>();
    const double lift_x = 1e-2 * (x_max > 0 ? x_max : 1.0);
    const double lift_z = 1e-2 * (z_max > 0 ? z_max : s_d);
    x = x0->cwiseMax(lift_x);
    z = z0->cwiseMax(lift_z);
  } else {
    x = VectorXd::Ones(m);
    VectorXd w1 = -d;
    symmetric_multiply_add(W, x, w1);
    // z on the scale of the problem (the method is invariant under a scaling of W, d and z together, provided
    // z starts on that scale: with z = 1 on a problem whose d is 2e-9, as on the inclined interface, it
    // spends its iterations bringing z down and meets x = 0 in round-off).
    const double z_scale = w1.lpNorm<Eigen::Infinity>();
    z = VectorXd::Constant(m, z_scale > 0 ? z_scale : s_d);
  }

  NewtonSystem newton(m, G);
  const double mu0 = x.dot(z) / static_cast<double>(m);
  VectorXd dx_aff, dz_aff, db_aff, dx, dz, db;
  for (int it = 0;; ++it) {
    const VectorXd rd = residual_d(x, z, beta);
    const VectorXd rp = k > 0 ? VectorXd(G * x - e) : VectorXd();
    const double mu = x.dot(z) / static_cast<double>(m);
    const double rd_norm = rd.lpNorm<Eigen::Infinity>(), rp_norm = k > 0 ? rp.lpNorm<Eigen::Infinity>() : 0.0;
    r.iterations = it;
    if (!std::isfinite(rd_norm) || !std::isfinite(rp_norm) || !std::isfinite(mu)) {
      r.status = "non-finite iterate";
      break;
    }
    if (rd_norm <= options.tolerance * s_d && rp_norm <= options.tolerance * s_p &&
        mu <= options.complementarity_tolerance * s_d * std::max(1.0, x.lpNorm<Eigen::Infinity>())) {
      r.success = true;
      r.status = "converged";
      break;
    }
    if (it >= options.max_iterations) {
      std::ostringstream s;
      s << "no convergence in " << options.max_iterations << " iterations (dual residual " << rd_norm / s_d
        << ", primal residual " << rp_norm / s_p << ", complementarity " << mu / s_d << ")";
      r.status = s.str();
      break;
    }
    const VectorXd h = z.cwiseQuotient(x);
    if (!newton.factorize(W, h, 0.0) && !newton.factorize(W, h, 1e-14 * std::max(w_max, 1.0))) {
      r.status = "the Newton matrix W + X⁻¹Z is not numerically definite";
      break;
    }
    const VectorXd g = k > 0 ? VectorXd(-rp) : VectorXd();
    // Predictor (affine scaling): r_c = x ∘ z.
    VectorXd rc = x.cwiseProduct(z);
    newton.solve(-rd - rc.cwiseQuotient(x), g, dx_aff, db_aff);
    dz_aff = -(rc + z.cwiseProduct(dx_aff)).cwiseQuotient(x);
    const double a_aff = std::min(step_to_boundary(x, dx_aff, 1.0), step_to_boundary(z, dz_aff, 1.0));
    const double mu_aff = (x + a_aff * dx_aff).dot(z + a_aff * dz_aff) / static_cast<double>(m);
    const double sigma = std::pow(std::clamp(mu_aff / mu, 0.0, 1.0), 3);
    // Corrector: r_c = x ∘ z + Δx_aff ∘ Δz_aff − σμ.
    rc += dx_aff.cwiseProduct(dz_aff);
    rc.array() -= sigma * mu;
    newton.solve(-rd - rc.cwiseQuotient(x), g, dx, db);
    dz = -(rc + z.cwiseProduct(dx)).cwiseQuotient(x);
    // τ → 1 as μ falls (superlinear steps), but below 1 in floating point: a step that lands on x_i = 0 exactly
    // would divide by it in X⁻¹Z.
    const double tau = std::clamp(1.0 - mu / std::max(mu0, std::numeric_limits<double>::min()), 0.99, 1.0 - 1e-10);
    const double alpha = std::min(step_to_boundary(x, dx, tau), step_to_boundary(z, dz, tau));
    x += alpha * dx;
    z += alpha * dz;
    if (k > 0) beta += alpha * db;
  }
  r.x = std::move(x);
  r.z = std::move(z);
  r.beta = std::move(beta);
  return r;
}

}  // namespace symcontact
