#include "symcontact/solvers/equality_constrained_solve.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <limits>
#include <memory>

#include "symcontact/solvers/dense_kkt.hpp"
#include "symcontact/solvers/spd_factor.hpp"

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

/// start.L ← the Cholesky factor of the dense H (`Hd`) on the first call, if H is definite with pivots within
/// 1e-6 of each other; whether there is one to use.
bool factor_at_start(StartFactor& start, const AlignedMatrix& Hd) {
  if (!start.tried) {
    start.tried = true;
    SpdFactor chol(true);
    if (chol.compute(SparseMatrix(), &Hd, nullptr, 0.0)) {
      const auto d = chol.dense_factor()->map().diagonal();
      if (d.minCoeff() > 1e-6 * d.maxCoeff()) start.L = chol.dense_factor();
    }
  }
  return start.L != nullptr;
}

}  // namespace

bool solve_on_set(ConstrainedProblem& problem, const SparseMatrix& AS, const VectorXd& bS, VectorXd& xs, VectorXd& nu,
                  int& iterations, bool direct, StartFactor* start) {
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
  // Takes the Newton step (Δ, λ) of a dense direct or CG solve; whether the loop has converged (the step at the
  // round-off of x).
  auto take_step = [&](const VectorXd& dx, const VectorXd& lambda) {
    xs += dx;
    nu = lambda;
    ++iterations;
    const double step = dx.lpNorm<Eigen::Infinity>();
    return step <= 1e-10 * xscale0 || at_round_off(step);
  };
  for (int newton = 0; newton < (quadratic ? 1 : 20); ++newton) {
    // The condensed problem's H is full: written straight into a dense matrix for the factorisations and the
    // products below (ConstrainedProblem::add_hessian_lower), with no sparse copy.
    const bool dense = problem.hessian_is_dense();
    SparseMatrix H;  // the sparse path's
    std::unique_ptr<AlignedMatrix> Hd;
    if (dense) {
      Hd = std::make_unique<AlignedMatrix>(xs.size(), xs.size());
      Hd->map().setZero();
      problem.add_hessian_lower(xs, 1.0, Hd->map());
    } else {
      problem.hessian_lower(xs, H);
    }
    VectorXd g;
    problem.gradient(xs, g);
    const double hdiag = dense ? Hd->map().diagonal().cwiseAbs().mean() : H.diagonal().cwiseAbs().mean();
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
        if (take_step(dx, lambda)) break;
        continue;
      }
      reference.reset();
    }
    if (newton == 0 && start && dense && direct && AS.rows() > 0 && AS.rows() <= kDirectLimit &&
        factor_at_start(*start, *Hd)) {
      // The first step from the shared start: the range-space solve on the factor of H(xs) alone, which the
      // later Newton steps take as their preconditioner (above).
      reference = std::make_unique<DenseRangeSpace>(start->L, AS, 0.0);
      VectorXd dx, lambda;
      reference->solve(g, AS * xs + bS, dx, lambda);
      if (take_step(dx, lambda)) break;
      continue;
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

}  // namespace symcontact
