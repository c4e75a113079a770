#include "symcontact/solvers/active_set_polish.hpp"

#include <cmath>
#include <vector>

#include "symcontact/core/error.hpp"
#include "symcontact/solvers/cholesky.hpp"

namespace symcontact {

PolishResult polish_active_set(ConstrainedProblem& problem, VectorXd& x, VectorXd& mu) {
  PolishResult r;
  const SparseMatrix& A = problem.constraint_matrix();
  const VectorXd& b = problem.constraint_offset();
  if (!problem.hessian_is_constant()) {
    r.reason = "the objective is not quadratic";
    return r;
  }
  if (A.rows() == 0 || mu.size() != A.rows() || mu.maxCoeff() <= 0) {
    r.reason = "no active constraint";
    return r;
  }
  // Row scales: constraint values in the units of x (as IPOPT saw them).
  VectorXd row_scale = VectorXd::Zero(A.rows());
  for (int j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it)
      row_scale[it.row()] = std::max(row_scale[it.row()], std::abs(it.value()));
  const double mu_max = mu.maxCoeff();
  std::vector<Index> S;
  std::vector<Index> pos(A.rows(), -1);
  for (Index i = 0; i < A.rows(); ++i)
    if (mu[i] > 1e-6 * mu_max && row_scale[i] > 0) {
      pos[i] = static_cast<Index>(S.size());
      S.push_back(i);
    }
  r.active = static_cast<int>(S.size());
  // A_S with rows scaled to unit max entry (scaled multipliers ν = μ · scale).
  std::vector<Triplet> t;
  for (int j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it)
      if (pos[it.row()] >= 0)
        t.emplace_back(static_cast<int>(pos[it.row()]), j, it.value() / row_scale[it.row()]);
  SparseMatrix AS(static_cast<Index>(S.size()), A.cols());
  AS.setFromTriplets(t.begin(), t.end());
  VectorXd bS(S.size()), nu(S.size());
  for (std::size_t k = 0; k < S.size(); ++k) {
    bS[k] = b[S[k]] / row_scale[S[k]];
    nu[k] = mu[S[k]] * row_scale[S[k]];
  }
  SparseMatrix H;
  problem.hessian_lower(x, H);
  const SparseMatrix AtA = SparseMatrix(AS.transpose() * AS).triangularView<Eigen::Lower>();
  const double hdiag = H.diagonal().cwiseAbs().mean();
  const double adiag = AtA.diagonal().cwiseAbs().maxCoeff();
  if (!(hdiag > 0) || !(adiag > 0)) {
    r.reason = "degenerate Hessian or constraints";
    return r;
  }
  // Large ρ: the nearly dependent rows of the two families give A_S tiny singular values, along which
  // the method of multipliers converges at the rate 1/(1 + ρ σ²).
  const double rho = 1e6 * hdiag / adiag;
  const SparseMatrix M = H + rho * AtA;
  CholeskySolver chol;
  try {
    chol.compute(M);
  } catch (const SolveError&) {
    r.reason = "H + ρ AᵀA is not positive definite";
    return r;
  }
  auto full_hessian_times = [&](const VectorXd& v) -> VectorXd {
    return H.selfadjointView<Eigen::Lower>() * v;
  };
  VectorXd xs = x, g;
  problem.gradient(xs, g);
  const double xscale = std::max(xs.lpNorm<Eigen::Infinity>(), 1e-300);
  for (int it = 0; it < 50; ++it) {
    const VectorXd cS = AS * xs + bS;
    const VectorXd rhs = -(g - AS.transpose() * nu) - rho * (AS.transpose() * cS);
    const VectorXd dx = chol.solve(rhs);
    xs += dx;
    g += full_hessian_times(dx);
    const VectorXd cS1 = AS * xs + bS;
    nu -= rho * cS1;
    r.iterations = it + 1;
    if (cS1.lpNorm<Eigen::Infinity>() <= 1e-14 * xscale && dx.lpNorm<Eigen::Infinity>() <= 1e-14 * xscale) break;
  }
  // Accept only a KKT point of the inequality problem.
  if (nu.minCoeff() < -1e-8 * nu.cwiseAbs().maxCoeff()) {
    r.reason = "a multiplier of the active set became negative";
    return r;
  }
  const VectorXd c = A * xs + b;
  for (Index i = 0; i < A.rows(); ++i)
    if (row_scale[i] > 0) r.max_violation = std::max(r.max_violation, -c[i] / row_scale[i]);
  if (r.max_violation > 1e-10 * xscale) {
    r.reason = "a constraint outside the active set became violated";
    return r;
  }
  x = xs;
  mu.setZero();
  for (std::size_t k = 0; k < S.size(); ++k) mu[S[k]] = std::max(0.0, nu[k]) / row_scale[S[k]];
  r.applied = true;
  return r;
}

}  // namespace symcontact
