#include "symcontact/solvers/dense_primal_interior_point.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "symcontact/core/error.hpp"
#include "symcontact/solvers/cholesky.hpp"
#include "symcontact/solvers/dense_kkt.hpp"

extern "C" {
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
}

namespace symcontact {

namespace {

/// A line search that stalls within this factor of the tolerance ends as converged (see its use).
constexpr double kFloor = 100.0;
/// The complementarity target's floor while the iterate does not pass the stopping test, over the tolerance:
/// as IPOPT's barrier parameter, which never falls below tol/10 (Wächter & Biegler, Math. Program. 106, 2006,
/// eq. 7). Below it the complementarity is far inside its test, and Σ = Λ/S spans orders of magnitude that the
/// Newton systems no longer resolve: with thresholds that follow the iterate, r_d lags (each change of the
/// data re-opens it) while μ fell tenfold per iteration to 1e-19, and the line search stalled at r_d = 1.4e-10
/// on OpenBLAS's Haswell and Zen kernels (tolerance 1e-12; the unit test FollowingNearTheEnd…).
constexpr double kTargetFloor = 0.1;

/// The problem in the dimensionless variables of the file comment: x̃ = x/ℓ, f̃ = f/(gℓ), c̃ = Ã x̃ + b̃ with
/// Ã = R A, b̃ = R b / ℓ, R = diag(1 / max_j |A_ij|). The iterate is kept in x (the problem's units).
class ScaledProblem {
 public:
  ScaledProblem(ConstrainedProblem& problem, const ProblemScales& scales)
      : problem_(problem), g_(scales.force), l_(scales.length) {
    const SparseMatrix& A = problem.constraint_matrix();
    row_.setOnes(A.rows());
    VectorXd row_max = VectorXd::Zero(A.rows());
    for (Index j = 0; j < A.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(A, j); it; ++it)
        row_max[it.row()] = std::max(row_max[it.row()], std::abs(it.value()));
    for (Index i = 0; i < A.rows(); ++i)
      if (row_max[i] > 0.0) row_[i] = row_max[i];
    A_ = row_.cwiseInverse().asDiagonal() * A;
    b_ = problem.constraint_offset().cwiseQuotient(row_) / l_;
  }

  const SparseMatrix& A() const { return A_; }
  Index rows() const { return A_.rows(); }
  VectorXd gap(const VectorXd& x) const { return A_ * x / l_ + b_; }  ///< c̃(x)
  VectorXd gradient(const VectorXd& x) const {                         ///< ∇_x̃ f̃ = ∇f / g
    VectorXd g;
    problem_.gradient(x, g);
    return g / g_;
  }
  /// M ← ∇²_x̃ f̃ = ∇²f ℓ / g, dense lower triangle. Keeps x for hessian_times().
  void hessian(const VectorXd& x, AlignedMatrix& M) {
    auto m = M.map();
    m.setZero();
    problem_.add_hessian_lower(x, l_ / g_, m);
    x_hessian_ = x;
  }
  /// ∇²_x̃ f̃, sparse lower triangle. Keeps it and x for hessian_times().
  const SparseMatrix& hessian_sparse(const VectorXd& x) {
    problem_.hessian_lower(x, H_);
    H_ *= l_ / g_;
    x_hessian_ = x;
    sparse_hessian_ = true;
    return H_;
  }
  /// ∇²f̃ v at the point of the last hessian() call (the sparse path: with the H it returned).
  VectorXd hessian_times(const VectorXd& v) const {
    if (sparse_hessian_) return H_.selfadjointView<Eigen::Lower>() * v;
    VectorXd hv;
    problem_.hessian_product(x_hessian_, v, hv);
    return (l_ / g_) * hv;
  }
  double length() const { return l_; }
  /// λ in the problem's units from the scaled λ̃: ∇f = Aᵀλ with λ_i = g λ̃_i / R_ii⁻¹.
  VectorXd unscaled_multipliers(const VectorXd& lt) const { return g_ * lt.cwiseQuotient(row_); }
  VectorXd scaled_multipliers(const VectorXd& l) const { return l.cwiseProduct(row_) / g_; }

 private:
  ConstrainedProblem& problem_;
  double g_, l_;
  VectorXd row_;
  SparseMatrix A_;
  VectorXd b_;
  VectorXd x_hessian_;  ///< x at the last hessian() call
  SparseMatrix H_;      ///< ∇²f̃ there, on the sparse path
  bool sparse_hessian_ = false;
};

/// The state of one iteration and its residuals (scaled).
struct Iterate {
  VectorXd x, s, l;  ///< x in the problem's units; s̃, λ̃ scaled
  VectorXd rd, rp;   ///< r_d = ∇f̃ − Ãᵀλ̃, r_p = c̃(x) − s̃
  double mu() const { return s.size() ? s.dot(l) / static_cast<double>(s.size()) : 0.0; }
  /// ‖(r_d, r_p, s ∘ λ − target)‖₂
  double norm(double target) const {
    return std::sqrt(rd.squaredNorm() + rp.squaredNorm() + (s.cwiseProduct(l).array() - target).matrix().squaredNorm());
  }
  double error() const {
    const double c = s.size() ? s.cwiseProduct(l).maxCoeff() : 0.0;
    return std::max({rd.lpNorm<Eigen::Infinity>(), rp.size() ? rp.lpNorm<Eigen::Infinity>() : 0.0, c});
  }
};

void residuals(const ScaledProblem& sp, Iterate& it) {
  it.rd = sp.gradient(it.x);
  it.rd.noalias() -= sp.A().transpose() * it.l;
  it.rp = sp.gap(it.x) - it.s;
}

/// The factor of the normal matrix N = ∇²f̃(x) + ÃᵀDÃ (+ a diagonal shift), D = diag(λ̃ / s̃): dense by LAPACK
/// (dpotrf on its lower triangle) where ∇²f is nearly full (ConstrainedProblem::hessian_is_dense(): the
/// condensed problem), sparse by CHOLMOD otherwise, its ordering and symbolic analysis kept from one iteration
/// to the next while the pattern of N stays (∇²f's pattern is fixed within a solve, and D > 0 keeps ÃᵀDÃ's).
class NormalFactor {
 public:
  NormalFactor(bool dense, Index n) : dense_(dense ? std::make_unique<AlignedMatrix>(n, n) : nullptr) {}
  /// False when N is not numerically definite (dpotrf or CHOLMOD's supernodal factor breaks down).
  bool factorize(ScaledProblem& sp, const Iterate& it, double relative_shift) {
    const SparseMatrix DA = it.l.cwiseQuotient(it.s).asDiagonal() * sp.A();
    const SparseMatrix ADA = sp.A().transpose() * DA;
    return dense_ ? factorize_dense(sp, it, ADA, relative_shift) : factorize_sparse(sp, it, ADA, relative_shift);
  }
  /// v ← N⁻¹ v.
  void solve(VectorXd& v) const {
    if (!dense_) {
      v = sparse_.solve(v);
      return;
    }
    AlignedMatrix b(v.size(), 1);
    b.map() = v;
    lower_solve(*dense_, false, b);
    lower_solve(*dense_, true, b);
    v = b.map();
  }

 private:
  bool factorize_dense(ScaledProblem& sp, const Iterate& it, const SparseMatrix& ADA, double relative_shift) {
    AlignedMatrix& M = *dense_;
    sp.hessian(it.x, M);
    auto m = M.map();
    for (Index j = 0; j < ADA.outerSize(); ++j)
      for (SparseMatrix::InnerIterator e(ADA, j); e; ++e)
        if (e.row() >= j) m(e.row(), j) += e.value();
    if (relative_shift > 0.0) m.diagonal().array() += relative_shift * std::max(m.diagonal().maxCoeff(), 1.0);
    const int ni = static_cast<int>(M.rows());
    int info = 0;
    dpotrf_("L", &ni, M.data(), &ni, &info);
    return info == 0;
  }
  bool factorize_sparse(ScaledProblem& sp, const Iterate& it, const SparseMatrix& ADA, double relative_shift) {
    SparseMatrix N = sp.hessian_sparse(it.x) + SparseMatrix(ADA.triangularView<Eigen::Lower>());
    N.makeCompressed();
    if (relative_shift > 0.0) {
      const double shift = relative_shift * std::max(N.diagonal().maxCoeff(), 1.0);
      for (Index j = 0; j < N.outerSize(); ++j) N.coeffRef(j, j) += shift;
    }
    const bool same_pattern = static_cast<Index>(pattern_.size()) == N.nonZeros() + N.outerSize() + 1 &&
                              std::equal(N.outerIndexPtr(), N.outerIndexPtr() + N.outerSize() + 1, pattern_.begin()) &&
                              std::equal(N.innerIndexPtr(), N.innerIndexPtr() + N.nonZeros(),
                                         pattern_.begin() + N.outerSize() + 1);
    if (!same_pattern) {
      pattern_.assign(N.outerIndexPtr(), N.outerIndexPtr() + N.outerSize() + 1);
      pattern_.insert(pattern_.end(), N.innerIndexPtr(), N.innerIndexPtr() + N.nonZeros());
      sparse_.analyze(N);
    }
    try {
      sparse_.factorize(N);
    } catch (const SolveError&) {
      return false;
    }
    return true;
  }

  std::unique_ptr<AlignedMatrix> dense_;  ///< the dense path's L (null on the sparse path)
  CholeskySolver sparse_;
  std::vector<SparseMatrix::StorageIndex> pattern_;  ///< outer then inner indices of the analysed N
};

/// The Newton direction for the target σμ, with `extra` added to s ∘ λ (the corrector's Δs_aff ∘ Δλ_aff).
/// L is the factor of ∇²f̃ + ÃᵀDÃ.
void reduced_solve(const ScaledProblem& sp, const NormalFactor& L, const Iterate& it, const VectorXd& rd,
                   const VectorXd& rp, const VectorXd& rc, VectorXd& dxt, VectorXd& ds, VectorXd& dl) {
  const VectorXd w = (rc + it.l.cwiseProduct(rp)).cwiseQuotient(it.s);
  dxt = -rd - sp.A().transpose() * w;
  L.solve(dxt);
  ds = sp.A() * dxt + rp;
  dl = -(rc + it.l.cwiseProduct(ds)).cwiseQuotient(it.s);
}

/// The Newton direction for the target in `rc` (s ∘ λ − σμ, plus the corrector's Δs_aff ∘ Δλ_aff), L the
/// factor of ∇²f̃ + ÃᵀDÃ: the normal equations of the file comment, then two steps of iterative refinement
/// on the whole linearised system (∇²f̃ Δx − ÃᵀΔλ = −r_d, ÃΔx − Δs = −r_p, Λ Δs + S Δλ = −r_c). Near the
/// solution D = Λ/S spans many orders of magnitude and the normal equations alone lose the digits that the
/// last iterations need (a line search then stalls at a residual of 1e-10 or so, where the refined direction
/// goes on to round-off). dx in the problem's units.
void direction(const ScaledProblem& sp, const NormalFactor& L, const Iterate& it, const VectorXd& rc, VectorXd& dx,
               VectorXd& ds, VectorXd& dl) {
  VectorXd dxt, ex, es, el;
  reduced_solve(sp, L, it, it.rd, it.rp, rc, dxt, ds, dl);
  for (int refinement = 0; refinement < 2; ++refinement) {
    // The residuals of the linearised system at (dxt, ds, dl), as the right-hand sides of a correction.
    const VectorXd ed = it.rd + sp.hessian_times(dxt) - sp.A().transpose() * dl;
    const VectorXd ep = it.rp + sp.A() * dxt - ds;
    const VectorXd ec = rc + it.l.cwiseProduct(ds) + it.s.cwiseProduct(dl);
    reduced_solve(sp, L, it, ed, ep, ec, ex, es, el);
    dxt += ex;
    ds += es;
    dl += el;
  }
  dx = sp.length() * dxt;
}

/// Backtracking from the largest step to the fraction τ of the boundary along (dx, ds, dl): halved until the
/// residual at the target σμ falls by 1e-4 α of itself. True with `trial` the accepted point.
bool line_search(const ScaledProblem& sp, const Iterate& it, const VectorXd& dx, const VectorXd& ds,
                 const VectorXd& dl, double target, Iterate& trial) {
  const double tau = std::max(0.99, 1.0 - it.mu());
  double alpha = std::min(step_to_boundary(it.s, ds, tau), step_to_boundary(it.l, dl, tau));
  const double f0 = it.norm(target);
  for (int half = 0; half < 40; ++half, alpha *= 0.5) {
    trial.x = it.x + alpha * dx;
    trial.s = it.s + alpha * ds;
    trial.l = it.l + alpha * dl;
    try {
      residuals(sp, trial);
    } catch (const EvaluationError&) {
      continue;
    }
    if (trial.norm(target) <= (1.0 - 1e-4 * alpha) * f0) return true;
  }
  return false;
}

/// One iteration from `it` with the factor L: Mehrotra's predictor-corrector direction, or where the line
/// search rejects it (the corrector's second-order term is not a Newton direction of the residual) the plain
/// Newton direction to the same target σμ, which is a descent direction of its norm. The target is not below
/// `floor` while μ is above it (kTargetFloor).
bool newton_step(const ScaledProblem& sp, const NormalFactor& L, const Iterate& it, Iterate& trial, double floor) {
  const Index p = it.s.size();
  const double mu = it.mu();
  VectorXd dx_aff, ds_aff, dl_aff, dx, ds, dl;
  VectorXd rc = it.s.cwiseProduct(it.l);  // predictor: target 0
  direction(sp, L, it, rc, dx_aff, ds_aff, dl_aff);
  const double a_aff = std::min(step_to_boundary(it.s, ds_aff, 1.0), step_to_boundary(it.l, dl_aff, 1.0));
  const double mu_aff = p ? (it.s + a_aff * ds_aff).dot(it.l + a_aff * dl_aff) / static_cast<double>(p) : 0.0;
  // Mehrotra's σμ, but not below a tenth of μ while the stationarity and feasibility are behind it: with a
  // non-quadratic f, complementarity run ahead of them pins the slacks to their bounds before r_d is met.
  const double behind = std::max(it.rd.lpNorm<Eigen::Infinity>(), p ? it.rp.lpNorm<Eigen::Infinity>() : 0.0);
  const double sigma = mu > 0 ? std::pow(std::clamp(mu_aff / mu, 0.0, 1.0), 3) : 0.0;
  const double target = std::max({sigma * mu, 0.1 * std::min(mu, behind), std::min(mu, floor)});
  rc.array() -= target;
  direction(sp, L, it, rc + ds_aff.cwiseProduct(dl_aff), dx, ds, dl);  // corrector
  if (line_search(sp, it, dx, ds, dl, target, trial)) return true;
  direction(sp, L, it, rc, dx, ds, dl);
  return line_search(sp, it, dx, ds, dl, target, trial);
}

}  // namespace

ProblemScales dense_primal_scales(ConstrainedProblem& problem, const VectorXd& x0) {
  VectorXd g0;
  problem.gradient(x0, g0);
  SparseMatrix H0;
  problem.hessian_lower(x0, H0);
  return problem_scales(x0, g0, H0);
}

double dense_primal_error(ConstrainedProblem& problem, const ProblemScales& scales, const VectorXd& x,
                          const VectorXd& multipliers) {
  const ScaledProblem sp(problem, scales);
  Iterate it;
  it.x = x;
  it.l = sp.scaled_multipliers(multipliers);
  it.s = sp.gap(x).cwiseMax(0.0);
  residuals(sp, it);
  return it.error();
}

IpoptResult solve_dense_primal(ConstrainedProblem& problem, const VectorXd& x0, const DensePrimalOptions& options,
                               const VectorXd* multipliers0, const FollowIterate* follow) {
  if (problem.num_equalities() > 0 || problem.lower_bounds())
    throw std::invalid_argument("solve_dense_primal: equality rows and bounds are not supported");
  const Index n = problem.num_variables();
  IpoptResult r;
  r.x = x0;
  Iterate it;
  it.x = x0;
  try {
    r.scales = dense_primal_scales(problem, x0);
  } catch (const EvaluationError& e) {
    r.status_text = std::string("f cannot be evaluated at the start: ") + e.what();
    return r;
  }
  ScaledProblem sp(problem, r.scales);
  const Index p = sp.rows();
  // Start: the gaps, lifted off 0 (scaled), and the multipliers: 1 cold; warm, the previous solve's lifted
  // by kWarmLift only, so that a start near the solution stays near it (a lift of 1e-2 took twice the
  // iterations of 1e-6 on the 3D pads of docs/performance.md: the active set is mostly the previous one).
  constexpr double kColdLift = 1e-2, kWarmLift = 1e-6;
  const bool warm = multipliers0 && multipliers0->size() == p;
  it.s = sp.gap(x0).cwiseMax(warm ? kWarmLift : kColdLift);
  it.l = warm ? VectorXd(sp.scaled_multipliers(*multipliers0).cwiseMax(kWarmLift)) : VectorXd(VectorXd::Ones(p));
  NormalFactor M(problem.hessian_is_dense(), n);
  try {
    residuals(sp, it);
    for (int k = 0;; ++k) {
      r.iterations = k;
      // Followed data set at x: a point that then passes the stopping test solves the problem of its own data.
      if (follow && it.error() <= options.follow_below && (*follow)(it.x, sp.unscaled_multipliers(it.l)))
        residuals(sp, it);
      const double error = it.error();
      if (!std::isfinite(error)) {
        r.status_text = "non-finite iterate";
        break;
      }
      if (error <= options.tolerance) {
        // Further steps while they lower the error tenfold, to 1e-4 of the tolerance at most: the answer then
        // sits far inside the tolerance, so that two runs whose round-off ends them on either side of it (the
        // same problem in other units) still agree far below it.
        double e = error;
        for (int extra = 0; extra < 4 && e > 1e-4 * options.tolerance; ++extra) {
          Iterate trial;
          if (!(M.factorize(sp, it, 0.0) || M.factorize(sp, it, 1e-12)) || !newton_step(sp, M, it, trial, 0.0) ||
              !(trial.error() < e))
            break;
          const double e_next = trial.error();
          it = std::move(trial);
          r.iterations = k + extra + 1;
          if (e_next > 0.1 * e) break;
          e = e_next;
        }
        r.success = true;
        r.status_text = "converged";
        break;
      }
      if (k >= options.max_iterations) {
        std::ostringstream s;
        s << "no convergence in " << options.max_iterations << " iterations (scaled error " << error << ")";
        r.status_text = s.str();
        break;
      }
      if (!M.factorize(sp, it, 0.0) && !M.factorize(sp, it, 1e-12)) {
        r.status_text = "the Newton matrix is not numerically definite";
        break;
      }
      Iterate trial;
      if (!newton_step(sp, M, it, trial, kTargetFloor * options.tolerance)) {
        // Within kFloor × tolerance this is the round-off floor of the Newton systems (D = Λ/S spanning some
        // twenty orders of magnitude at a tolerance of 1e-12): the point is as converged as it gets.
        r.success = error <= kFloor * options.tolerance;
        std::ostringstream s;
        s << (r.success ? "converged to the round-off floor" : "the line search cannot reduce the residual")
          << " (scaled error " << error << ")";
        r.status_text = s.str();
        break;
      }
      it = std::move(trial);
    }
    r.objective = problem.objective(it.x);
  } catch (const EvaluationError& e) {
    r.success = false;
    r.status_text = std::string("f cannot be evaluated: ") + e.what();
  }
  r.x = it.x;
  r.multipliers = sp.unscaled_multipliers(it.l);
  r.constraint_values = problem.constraint_matrix() * it.x + problem.constraint_offset();
  r.bound_multipliers = VectorXd::Zero(n);
  return r;
}

}  // namespace symcontact
