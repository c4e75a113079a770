#include "symcontact/solvers/active_set_polish.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <new>
#include <limits>
#include <vector>

#include "symcontact/core/error.hpp"
#include "symcontact/solvers/cholesky.hpp"
#include "symcontact/solvers/dense_kkt.hpp"

// BLAS and LAPACK (Fortran interfaces; column-major, every argument by address).
extern "C" {
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
void dtrsv_(const char* uplo, const char* trans, const char* diag, const int* n, const double* a, const int* lda,
            double* x, const int* incx);
}

namespace symcontact {

namespace {

/// Up to this many active constraints the KKT system on S is solved directly (dense Schur complement);
/// above it, by the method of multipliers.
constexpr Index kDirectLimit = 3000;

/// Projected CG of a later Newton step (dense_kkt.hpp) stops once its update is below kCgTolerance × max |x|
/// (1e-3 of the Newton loop's own stopping step, 1e-10 × max |x|: the steps it takes are those of the direct
/// solve to far below what ends the loop); after kCgMaxIterations the step refactorises instead. On the
/// inclined interface with Coulomb friction (2e4 DOFs, |B| = 382, |S| = 191) it takes 1–2 iterations per
/// step, each O(|B|²) against a factorisation's O(|B|³).
constexpr double kCgTolerance = 1e-13;
constexpr int kCgMaxIterations = 50;
/// Newton steps of the polish below this (relative to max|x|) that no longer fall tenfold are round-off.
constexpr double kRoundOffStep = 1e-9;

/// A constraint is violated when its scaled value is below −kViolationTolerance × max |x|.
constexpr double kViolationTolerance = 1e-10;
/// A constraint is open when its scaled value is above kOpenGap × max |x|: far above the barrier offsets an
/// interior point leaves at closed rows (up to about 1e-5 of max |x| on the nearly dependent families of a
/// symmetric pair).
constexpr double kOpenGap = 1e-3;

/// M = L Lᵀ for the polish. A sparse M goes to CHOLMOD. A dense one — the condensed problem, whose Schur
/// complement fills its |B| × |B| Hessian (ConstrainedProblem::hessian_is_dense()) — goes to LAPACK's dpotrf
/// (OpenBLAS here), which also leaves the triangular factor for the multi-column (BLAS-3) range-space solve
/// below; CHOLMOD's supernodal factor of a full matrix is the same algorithm, but its solves come one column
/// at a time.
class SpdFactor {
 public:
  explicit SpdFactor(bool dense) : dense_(dense) {}
  /// Factorises M = H + ρ AtA from their lower triangles (`dense_h`: H as a dense matrix, the dense path;
  /// `h`: H sparse, the sparse one); false when M is not (numerically) positive definite.
  bool compute(const SparseMatrix& h, const AlignedMatrix* dense_h, const SparseMatrix* AtA, double rho) {
    if (!dense_) {
      try {
        sparse_.compute(AtA ? SparseMatrix(h + rho * *AtA) : h);
        return true;
      } catch (const SolveError&) {
        return false;
      }
    }
    n_ = static_cast<int>(h.rows());
    factor_ = std::make_shared<AlignedMatrix>(n_, n_);
    auto m = factor_->map();
    m = dense_h->map();
    if (AtA)
      for (int j = 0; j < AtA->outerSize(); ++j)
        for (SparseMatrix::InnerIterator it(*AtA, j); it; ++it) m(it.row(), j) += rho * it.value();
    int info = 0;
    dpotrf_("L", &n_, factor_->data(), &n_, &info);
    return info == 0;
  }
  VectorXd solve(const VectorXd& b) const {
    if (!dense_) return sparse_.solve(b);
    AlignedMatrix x(n_, 1);
    x.map() = b;
    const int inc = 1;
    dtrsv_("L", "N", "N", &n_, factor_->data(), &n_, x.data(), &inc);
    dtrsv_("L", "T", "N", &n_, factor_->data(), &n_, x.data(), &inc);
    return x.map();
  }
  bool dense() const { return dense_; }
  int size() const { return n_; }
  /// L of M = L Lᵀ in its lower triangle (only when dense()).
  std::shared_ptr<const AlignedMatrix> dense_factor() const { return factor_; }

 private:
  bool dense_;
  int n_ = 0;
  CholeskySolver sparse_;
  std::shared_ptr<AlignedMatrix> factor_;
};

/// The lower triangle of a compressed lower-triangular matrix as a dense matrix (zero above).
std::unique_ptr<AlignedMatrix> dense_lower(const SparseMatrix& lower) {
  auto d = std::make_unique<AlignedMatrix>(lower.rows(), lower.cols());
  auto m = d->map();
  m.setZero();
  for (int j = 0; j < lower.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(lower, j); it; ++it)
      if (it.row() >= j) m(it.row(), j) += it.value();
  return d;
}

/// The range-space step on the sparse path, Δ = M⁻¹ (A_Sᵀ λ − ĝ) with (A_S M⁻¹ A_Sᵀ) λ = A_S M⁻¹ ĝ − c_S (see
/// solve_on_set), λ in the least-squares, minimum-norm sense. Column by column: a multi-column solve goes
/// through BLAS-3 kernels whose rounding depends on buffer alignment, and the same input must give the same
/// digits.
void range_space_step(const SpdFactor& chol, const SparseMatrix& AS, const VectorXd& cS, const VectorXd& ghat,
                      VectorXd& dx, VectorXd& lambda) {
  const MatrixXd At = MatrixXd(AS.transpose());
  MatrixXd MinvAt(At.rows(), At.cols());
  for (Index j = 0; j < At.cols(); ++j) MinvAt.col(j) = chol.solve(VectorXd(At.col(j)));
  const MatrixXd S = AS * MinvAt;
  const VectorXd Minv_g = chol.solve(VectorXd(ghat));
  const VectorXd rhs = AS * Minv_g - cS;
  // The threshold before compute(): the rank it fixes decides how many Householder reflections of Z
  // are formed, and solve() must use that same rank (set afterwards, solve() read coefficients
  // compute() never wrote: uninitialised memory, found by the ASan build of the V5 tests).
  Eigen::CompleteOrthogonalDecomposition<MatrixXd> cod;
  cod.setThreshold(1e-12);
  cod.compute(S);
  lambda = cod.solve(rhs);
  dx = MinvAt * lambda - Minv_g;
}

/// The method of multipliers on the set S with M = H + ρ A_Sᵀ A_S factorised (`chol`): x += M⁻¹(−(g − A_Sᵀ ν) −
/// ρ A_Sᵀ c_S), ν −= ρ c_S(x), g kept as the gradient by g += H Δ (`hessian_times` adds H Δ). One step when S
/// is empty. Returns false when the violation stops falling (40 iterations without a 1 % gain: the rows are
/// inconsistent, the set must change instead).
template <class HessianTimes>
bool multiplier_method(const SpdFactor& chol, const HessianTimes& hessian_times, const SparseMatrix& AS,
                       const VectorXd& bS, double rho, double xscale0, VectorXd& g, VectorXd& xs, VectorXd& nu,
                       int& iterations) {
  double best = std::numeric_limits<double>::infinity();
  int since_progress = 0;
  for (int it = 0; it < (AS.rows() > 0 ? 400 : 1); ++it) {
    const VectorXd cS = AS * xs + bS;
    const VectorXd dx = chol.solve(VectorXd(-(g - AS.transpose() * nu) - rho * (AS.transpose() * cS)));
    xs += dx;
    hessian_times(dx, g);
    ++iterations;
    if (AS.rows() == 0) break;
    const VectorXd cS1 = AS * xs + bS;
    nu -= rho * cS1;
    const double viol = cS1.lpNorm<Eigen::Infinity>();
    if (viol <= 1e-14 * xscale0 && dx.lpNorm<Eigen::Infinity>() <= 1e-14 * xscale0) break;
    if (viol < 0.99 * best) {
      best = viol;
      since_progress = 0;
    } else if (++since_progress >= 40) {
      return false;
    }
  }
  return true;
}

/// The equality-constrained solve on a fixed set S: Newton steps on f (one for a quadratic f), each
/// solved directly (range space, `direct`) or by the method of multipliers, with M = H + ρ A_Sᵀ A_S
/// (H alone when S is empty).
/// Returns false when M cannot be factorised.
bool solve_on_set(ConstrainedProblem& problem, const SparseMatrix& AS, const VectorXd& bS, VectorXd& xs, VectorXd& nu,
                  int& iterations, bool direct) {
  const bool quadratic = problem.hessian_is_constant();
  const double xscale0 = std::max(xs.lpNorm<Eigen::Infinity>(), 1e-300);
  // The factorised KKT system of the last dense direct step, which preconditions the next ones.
  std::unique_ptr<DenseRangeSpace> reference;
  SparseMatrix AtA;  // lower triangle of A_Sᵀ A_S
  double adiag = 0.0;
  // Newton's steps fall quadratically until they reach the round-off of these augmented systems (1e-10 to
  // 3e-10 of max|x| on the inclined interface, where IPOPT's point is already there: without this test its
  // force-balancing polish takes 12–20 steps of noise). A step at that level that is not a tenth of the
  // one before is taken as round-off, and ends the loop.
  double previous_step = std::numeric_limits<double>::infinity();
  auto at_round_off = [&](double step) {
    const bool stop = step <= kRoundOffStep * xscale0 && step > 0.1 * previous_step;
    previous_step = step;
    return stop;
  };
  for (int newton = 0; newton < (quadratic ? 1 : 20); ++newton) {
    SparseMatrix H;
    problem.hessian_lower(xs, H);
    VectorXd g;
    problem.gradient(xs, g);
    const double hdiag = H.diagonal().cwiseAbs().mean();
    // The condensed problem's H is full: kept dense for the factorisations and the products below.
    const bool dense = problem.hessian_is_dense();
    const std::unique_ptr<AlignedMatrix> Hd = dense ? dense_lower(H) : nullptr;
    if (!(hdiag > 0)) return false;
    if (reference) {
      // A later Newton step of the dense direct solve: between two steps only the friction Hessian
      // changed (one small block per contact node), so the KKT system is solved by projected CG
      // preconditioned with the last factorised one (dense_kkt.hpp) instead of a new O(|B|³)
      // factorisation; if it does not converge fast, the step refactorises as before.
      const VectorXd cS = AS * xs + bS;
      auto multiply = [&](const VectorXd& v, VectorXd& out) {
        out = VectorXd::Zero(v.size());
        symmetric_multiply_add(*Hd, v, out);
      };
      VectorXd dx, lambda;
      const ProjectedCgResult cg =
          projected_cg(*reference, multiply, g, cS, dx, lambda, kCgTolerance * xscale0, kCgMaxIterations);
      if (cg.converged) {
        xs += dx;
        nu = lambda;
        ++iterations;
        const double step = dx.lpNorm<Eigen::Infinity>();
        if (step <= 1e-10 * xscale0 || at_round_off(step)) break;
        continue;
      }
      reference.reset();
    }
    if (AS.rows() > 0 && AtA.rows() == 0) {  // A_S is the same for every Newton step: formed once
      AtA = SparseMatrix(AS.transpose() * AS).triangularView<Eigen::Lower>();
      adiag = AtA.diagonal().cwiseAbs().maxCoeff();
    }
    if (AS.rows() > 0 && !(adiag > 0)) return false;
    // With the direct solve ρ only has to make M definite (bodies held by contact alone): a balanced ρ
    // keeps M well conditioned. The method of multipliers wants a large ρ: the nearly dependent rows of
    // the two families give A_S tiny singular values, along which it converges at the rate 1/(1 + ρ σ²).
    // If the balanced ρ does not make M definite, the large one is used (and the method of multipliers).
    double rho = 0.0;
    SpdFactor chol(dense);
    bool factorised = false;
    for (const double factor : {direct ? 1.0 : 1e6, 1e6}) {
      rho = AS.rows() > 0 ? factor * hdiag / adiag : 0.0;
      if (chol.compute(H, Hd.get(), AS.rows() > 0 ? &AtA : nullptr, rho)) {
        factorised = true;
        if (factor != 1.0) direct = false;
        break;
      }
      if (AS.rows() == 0) break;
    }
    if (!factorised) return false;
    const VectorXd x_start = xs;
    bool stalled = false;
    if (direct && AS.rows() > 0 && AS.rows() <= kDirectLimit) {
      // Range-space solve of the KKT system on S, exact in one step (Nocedal & Wright §16.2):
      //   M Δ − A_Sᵀ λ = −ĝ,  A_S Δ = −c_S,  ĝ = g + ρ A_Sᵀ c_S  (the ρ term vanishes on A_S Δ = −c_S)
      //   ⇒ (A_S M⁻¹ A_Sᵀ) λ = A_S M⁻¹ ĝ − c_S, solved in the least-squares, minimum-norm sense
      //   (complete orthogonal decomposition) because dependent rows make it singular.
      const VectorXd cS = AS * xs + bS;
      const VectorXd ghat = g + rho * (AS.transpose() * cS);
      if (chol.dense()) {
        // With M = L Lᵀ dense: DenseRangeSpace, one multi-column triangular solve for W = L⁻¹ A_Sᵀ instead
        // of |S| + 2 pairs of single-column solves (BLAS-3 work instead of BLAS-2). It is kept to
        // precondition the next Newton steps (above).
        reference = std::make_unique<DenseRangeSpace>(chol.dense_factor(), AS, rho);
        VectorXd dx, lambda;
        reference->solve(g, cS, dx, lambda);
        xs += dx;
        nu = lambda;
        ++iterations;
      } else {
        VectorXd dx, lambda;
        range_space_step(chol, AS, cS, ghat, dx, lambda);
        xs += dx;
        nu = lambda;
        ++iterations;
      }
    } else {
      const auto hessian_times = [&](const VectorXd& dx, VectorXd& out) {
        if (dense)
          symmetric_multiply_add(*Hd, dx, out);
        else
          out += H.selfadjointView<Eigen::Lower>() * dx;
      };
      stalled = !multiplier_method(chol, hessian_times, AS, bS, rho, xscale0, g, xs, nu, iterations);
    }
    // A stalled method of multipliers means the set cannot be closed (inconsistent rows): further Newton
    // steps on f cannot change that, and the caller's rounds decide what to drop.
    if (stalled) break;
    // Newton has converged when its step is at the level of round-off in x (1e-10 relative: the
    // augmented systems lose a few digits).
    const double step = (xs - x_start).lpNorm<Eigen::Infinity>();
    if (step <= 1e-10 * xscale0 || at_round_off(step)) break;
  }
  return true;
}

PolishResult polish_on_active_set(ConstrainedProblem& problem, VectorXd& x, VectorXd& mu, PolishMode mode) {
  const bool hold_values = mode == PolishMode::kBalanceForces;
  PolishResult r;
  const SparseMatrix& A = problem.constraint_matrix();
  const VectorXd& b = problem.constraint_offset();
  if (mu.size() != A.rows()) {
    r.reason = "multipliers and constraints differ in size";
    return r;
  }
  // Row scales: constraint values in the units of x (as IPOPT saw them).
  VectorXd row_scale = VectorXd::Zero(A.rows());
  for (int j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it)
      row_scale[it.row()] = std::max(row_scale[it.row()], std::abs(it.value()));
  const double mu_max = A.rows() > 0 ? mu.maxCoeff() : 0.0;
  const VectorXd c0 = A * x + b;
  std::vector<char> in_set(A.rows(), 0);
  for (Index i = 0; i < A.rows(); ++i) in_set[i] = mu_max > 0 && mu[i] > 1e-6 * mu_max && row_scale[i] > 0;
  // Holding values with no gap closed at all (a surface approaching its opposite side: every row the optimiser
  // left open by more than kOpenGap of the displacements), the multipliers are the barrier's μ_b / c_i alone,
  // however they compare with each other: none is active. (Where some gap is closed, the set is left as it is:
  // the frictional ironing test's hardest step is sensitive to dropping the open rows beside a closed one.)
  if (hold_values) {
    const double open_gap = kOpenGap * std::max(x.lpNorm<Eigen::Infinity>(), 1e-300);
    bool any_closed = false;
    for (Index i = 0; i < A.rows(); ++i) any_closed = any_closed || (in_set[i] && c0[i] / row_scale[i] <= open_gap);
    if (!any_closed) std::fill(in_set.begin(), in_set.end(), 0);
  }
  // Rounds: constraints that the equality solve wants to pull (negative multiplier) were not really
  // active; drop them and solve again. After a warm-started IPOPT solve the multipliers of inactive
  // constraints can stay above the threshold, so the first set may hold ten times the active ones and
  // need several rounds to shrink. Constraints the solve violates join the set (below).
  constexpr int kMaxRounds = 30;
  VectorXd xs, nu;
  std::vector<Index> S;
  for (int round = 0; round < kMaxRounds; ++round) {
    S.clear();
    std::vector<Index> pos(A.rows(), -1);
    for (Index i = 0; i < A.rows(); ++i)
      if (in_set[i]) {
        pos[i] = static_cast<Index>(S.size());
        S.push_back(i);
      }
    r.active = static_cast<int>(S.size());
    // A_S with rows scaled to unit max entry (scaled multipliers ν = μ · scale).
    std::vector<Triplet> t;
    for (int j = 0; j < A.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(A, j); it; ++it)
        if (pos[it.row()] >= 0) t.emplace_back(static_cast<int>(pos[it.row()]), j, it.value() / row_scale[it.row()]);
    SparseMatrix AS(static_cast<Index>(S.size()), A.cols());
    AS.setFromTriplets(t.begin(), t.end());
    VectorXd bS(S.size());
    nu.resize(S.size());
    for (std::size_t k = 0; k < S.size(); ++k) {
      bS[k] = b[S[k]] / row_scale[S[k]];
      if (hold_values) bS[k] -= c0[S[k]] / row_scale[S[k]];  // target: the constraint values IPOPT left
      nu[k] = mu[S[k]] * row_scale[S[k]];
    }
    xs = x;
    // Holding the values is always consistent: solved directly. Closing may not be (curved symmetric
    // pairs): the method of multipliers, which degrades gracefully there.
    if (!solve_on_set(problem, AS, bS, xs, nu, r.iterations, hold_values) || !xs.allFinite() || !nu.allFinite()) {
      r.reason = "the Hessian (+ ρ AᵀA) is not positive definite";
      return r;
    }
    const double numax = nu.size() ? nu.cwiseAbs().maxCoeff() : 0.0;
    bool changed = false;
    for (std::size_t k = 0; k < S.size(); ++k)
      if (nu[k] < -1e-8 * numax) {
        in_set[S[k]] = 0;
        changed = true;
      }
    if (!changed && problem.hessian_is_constant()) {
      // The other half of the active-set update (the primal-dual active set strategy: Hintermüller, Ito &
      // Kunisch, SIAM J. Optim. 13, 2003, eq. 2.4): constraints outside S that the solve on S violates were
      // active too, and join S. A constraint that became active between two geometry iterations is left
      // by a warm-started IPOPT solve (often a single iteration) with the tiny multiplier of the warm
      // start, below the threshold above; without this step the closing polish is rejected and the
      // whole solve falls back to balancing forces only, which keeps the barrier offsets (on the V7 3D
      // hairpin: pressures off the half model's by 3.6e-5 of the maximum). For a quadratic f only,
      // where the solve on S is exact and this is the strategy of the reference (for a finite-strain
      // energy it makes the geometry fixed point of the crushed ring's last step cycle).
      const double xscale = std::max(xs.lpNorm<Eigen::Infinity>(), 1e-300);
      const VectorXd c = A * xs + b;
      for (Index i = 0; i < A.rows(); ++i)
        if (!in_set[i] && row_scale[i] > 0 && -c[i] / row_scale[i] > kViolationTolerance * xscale) {
          in_set[i] = 1;
          changed = true;
        }
    }
    if (!changed) break;
    if (round == kMaxRounds - 1) {
      r.reason = "the active set did not settle (negative multipliers or violated constraints remain)";
      return r;
    }
  }
  // Accept only a KKT point of the inequality problem: no constraint violated.
  const double xscale = std::max(xs.lpNorm<Eigen::Infinity>(), 1e-300);
  const VectorXd c = A * xs + b;
  for (Index i = 0; i < A.rows(); ++i)
    if (row_scale[i] > 0) r.max_violation = std::max(r.max_violation, -c[i] / row_scale[i]);
  if (r.max_violation > kViolationTolerance * xscale) {
    r.reason = "a constraint outside the active set became violated";
    return r;
  }
  // For a non-quadratic f (friction), Newton on a strongly curved term can land anywhere: keep the polished
  // point only if the stationarity error ‖∇f − Aᵀμ‖∞ actually fell.
  if (!problem.hessian_is_constant()) {
    auto stationarity = [&](const VectorXd& xx, const VectorXd& m) {
      VectorXd g;
      problem.gradient(xx, g);
      return (g - A.transpose() * m).lpNorm<Eigen::Infinity>();
    };
    VectorXd mu_new = VectorXd::Zero(A.rows());
    for (std::size_t k = 0; k < S.size(); ++k) mu_new[S[k]] = std::max(0.0, nu[k]) / row_scale[S[k]];
    // Scale: the larger of the constraint force and the gradient at the IPOPT point. A polish that only
    // closes the constraints keeps stationarity at round-off level; a Newton overshoot raises it by
    // orders of magnitude.
    VectorXd g0;
    problem.gradient(x, g0);
    const double scale = std::max((A.transpose() * mu).lpNorm<Eigen::Infinity>(), g0.lpNorm<Eigen::Infinity>());
    if (!(stationarity(xs, mu_new) <= 10.0 * stationarity(x, mu) + 1e-6 * scale)) {
      r.reason = "the Newton steps did not reduce the stationarity error";
      return r;
    }
  }
  x = xs;
  mu.setZero();
  for (std::size_t k = 0; k < S.size(); ++k) mu[S[k]] = std::max(0.0, nu[k]) / row_scale[S[k]];
  r.applied = true;
  return r;
}

}  // namespace

PolishResult polish_active_set(ConstrainedProblem& problem, VectorXd& x, VectorXd& mu, PolishMode mode) {
  // x and mu change only when the polish is applied; a full Newton step of a finite-strain energy may
  // reach a state it cannot be evaluated at (an inverted cell): then the IPOPT point is kept.
  try {
    return polish_on_active_set(problem, x, mu, mode);
  } catch (const EvaluationError& e) {
    PolishResult r;
    r.reason = std::string("a Newton step reached a state the energy cannot be evaluated at (") + e.what() + ")";
    return r;
  }
}

}  // namespace symcontact
