#include "symcontact/solvers/equality_constrained_solve.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "symcontact/solvers/dense_kkt.hpp"
#include "symcontact/solvers/spd_factor.hpp"

namespace symcontact {

namespace {

/// Up to this many active constraints the KKT system on S is solved directly (dense Schur complement);
/// above it, by the method of multipliers.
constexpr Index kDirectLimit = 3000;
/// The same limit where M is sparse (CHOLMOD): there the range-space solve costs one pair of triangular solves
/// per active row (range_space_step), each about 4 nnz(L) flops, and the method of multipliers a few pairs in
/// all; a 3D pad on a rigid plane (8.3e3 free DOFs, 677 rows) took 2.4 s per polish the direct way.
constexpr Index kSparseDirectLimit = 200;

/// Projected CG of a later Newton step (dense_kkt.hpp) stops once its update is below kCgTolerance × max |x|
/// (1e-3 of the Newton loop's own stopping step, 1e-10 × max |x|: the steps it takes are those of the direct
/// solve to far below what ends the loop); after kCgMaxIterations the step refactorises instead. On the
/// inclined interface with Coulomb friction (2e4 DOFs, |B| = 382, |S| = 191) it takes 1–2 iterations per
/// step, each O(|B|²) against a factorisation's O(|B|³).
constexpr double kCgTolerance = 1e-13;
constexpr int kCgMaxIterations = 50;
/// Newton steps of the polish below this (relative to max|x|) that no longer fall tenfold are round-off.
constexpr double kRoundOffStep = 1e-9;
/// A step of at most this fraction of the one before has left an error far below itself (at_round_off()).
constexpr double kContracted = 1e-2;

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

}  // namespace

bool multiplier_method(const SpdSolve& solve, const std::function<void(const VectorXd&, VectorXd&)>& hessian_times,
                       const SparseMatrix& AS, const VectorXd& bS, double rho, double xscale0, VectorXd& g,
                       VectorXd& xs, VectorXd& nu, int& iterations) {
  double best = std::numeric_limits<double>::infinity();
  int since_progress = 0;
  for (int it = 0; it < (AS.rows() > 0 ? 400 : 1); ++it) {
    const VectorXd cS = AS * xs + bS;
    const VectorXd dx = solve(VectorXd(-(g - AS.transpose() * nu) - rho * (AS.transpose() * cS)));
    xs += dx;
    hessian_times(dx, g);
    ++iterations;
    if (AS.rows() == 0) break;
    const VectorXd cS1 = AS * xs + bS;
    nu -= rho * cS1;
    const double viol = cS1.lpNorm<Eigen::Infinity>();
    const double xscale = std::max(xscale0, xs.lpNorm<Eigen::Infinity>());
    if (viol <= 1e-14 * xscale && dx.lpNorm<Eigen::Infinity>() <= 1e-14 * xscale) break;
    if (viol < 0.99 * best) {
      best = viol;
      since_progress = 0;
    } else if (++since_progress >= 40) {
      return false;
    }
  }
  return true;
}

namespace {

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

/// What a Newton step on the set ends with: taken (Newton goes on), converged, stalled (the set cannot be closed:
/// the loop ends and the caller's rounds decide what to drop), or failed (M cannot be factorised).
enum class StepEnd { kTaken, kConverged, kStalled, kFailed };

/// H(x) and ∇f(x) at one Newton step: the condensed problem's H is full and is written straight into a dense
/// matrix for the factorisations and products (ConstrainedProblem::add_hessian_lower), with no sparse copy.
struct HessianAt {
  SparseMatrix H;                    // the sparse path's
  const AlignedMatrix* Hd = nullptr;  // the dense path's (NewtonOnSet's buffer)
  VectorXd g;
  double diag = 0.0;  // mean |H_ii|
};

/// Newton's loop on one set S (see solve_on_set): the state it keeps between steps.
class NewtonOnSet {
 public:
  NewtonOnSet(ConstrainedProblem& problem, const SparseMatrix& AS, const VectorXd& bS, VectorXd& xs, VectorXd& nu,
              int& iterations, bool direct, StartFactor* start)
      : problem_(problem), AS_(AS), bS_(bS), xs_(xs), nu_(nu), iterations_(iterations), direct_(direct),
        start_(start), xscale0_(std::max(xs.lpNorm<Eigen::Infinity>(), 1e-300)) {}

  /// One Newton step (`first`: the first of the loop).
  StepEnd step(bool first) {
    HessianAt h = hessian();
    if (!(h.diag > 0)) return StepEnd::kFailed;
    if (reference_) {
      if (const std::optional<StepEnd> end = cg_step(h)) return *end;
    }
    const bool dense = h.Hd != nullptr;
    if (first && start_ && dense && direct_ && AS_.rows() > 0 && AS_.rows() <= kDirectLimit &&
        factor_at_start(*start_, *h.Hd)) {
      // The first step from the shared start: the range-space solve on the factor of H(xs) alone, which the
      // later Newton steps take as their preconditioner (cg_step).
      reference_ = range_space_at_start();
      VectorXd dx, lambda;
      reference_->solve(h.g, AS_ * xs_ + bS_, dx, lambda);
      return take_step(dx, lambda) ? StepEnd::kConverged : StepEnd::kTaken;
    }
    return factorised_step(h);
  }

 private:
  /// The range space of the start's factor on A_S: the shared one restricted where S is a subset of its rows,
  /// else formed (and shared when the caller named the rows).
  std::shared_ptr<const DenseRangeSpace> range_space_at_start() {
    StartFactor& s = *start_;
    if (s.range && !s.rows.empty()) {
      std::vector<Index> keep;
      keep.reserve(s.rows.size());
      std::size_t k = 0;
      for (const Index row : s.rows) {
        while (k < s.range_rows.size() && s.range_rows[k] < row) ++k;
        if (k == s.range_rows.size() || s.range_rows[k] != row) break;
        keep.push_back(static_cast<Index>(k));
      }
      if (keep.size() == s.rows.size()) return std::make_shared<const DenseRangeSpace>(*s.range, keep, AS_);
    }
    auto range = std::make_shared<const DenseRangeSpace>(s.L, AS_, 0.0);
    if (!s.rows.empty()) {
      s.range = range;
      s.range_rows = s.rows;
    }
    return range;
  }

  /// H and g at xs; a dense H goes into one buffer that every Newton step of the loop rewrites (|B|² doubles:
  /// not allocated, and its pages not touched anew, at each step).
  HessianAt hessian() {
    HessianAt h;
    if (problem_.hessian_is_dense()) {
      if (!Hd_) Hd_ = std::make_unique<AlignedMatrix>(xs_.size(), xs_.size());
      Hd_->map().setZero();
      problem_.add_hessian_lower(xs_, 1.0, Hd_->map());
      h.Hd = Hd_.get();
      h.diag = Hd_->map().diagonal().cwiseAbs().mean();
    } else {
      problem_.hessian_lower(xs_, h.H);
      h.diag = h.H.diagonal().cwiseAbs().mean();
    }
    problem_.gradient(xs_, h.g);
    return h;
  }

  /// A later Newton step of the dense direct solve: between two steps only the friction Hessian changed (one
  /// small block per contact node), so the KKT system is solved by projected CG preconditioned with the last
  /// factorised one (dense_kkt.hpp) instead of a new O(|B|³) factorisation. nullopt when CG does not converge
  /// fast: the step then refactorises.
  std::optional<StepEnd> cg_step(const HessianAt& h) {
    const VectorXd cS = AS_ * xs_ + bS_;
    auto multiply = [&](const VectorXd& v, VectorXd& out) {
      out = VectorXd::Zero(v.size());
      symmetric_multiply_add(*h.Hd, v, out);
    };
    VectorXd dx, lambda;
    const ProjectedCgResult cg =
        projected_cg(*reference_, multiply, h.g, cS, dx, lambda, kCgTolerance * xscale0_, kCgMaxIterations);
    if (!cg.converged) {
      reference_.reset();
      return std::nullopt;
    }
    return take_step(dx, lambda) ? StepEnd::kConverged : StepEnd::kTaken;
  }

  /// Factorises M = H + ρ A_Sᵀ A_S into `chol`; ρ on return. With the direct solve ρ only has to make M
  /// definite (bodies held by contact alone): a balanced ρ keeps M well conditioned. The method of
  /// multipliers wants a large ρ: the nearly dependent rows of the two families give A_S tiny singular
  /// values, along which it converges at the rate 1/(1 + ρ σ²). If the balanced ρ does not make M definite,
  /// the large one is used (and the method of multipliers). False when neither makes M definite.
  bool factorise(const HessianAt& h, SpdFactor& chol, double& rho) {
    if (AS_.rows() > 0 && AtA_.rows() == 0) {  // A_S is the same for every Newton step: formed once
      AtA_ = SparseMatrix(AS_.transpose() * AS_).triangularView<Eigen::Lower>();
      adiag_ = AtA_.diagonal().cwiseAbs().maxCoeff();
    }
    if (AS_.rows() > 0 && !(adiag_ > 0)) return false;
    // The balanced ρ where the range-space solve will take the step (on the sparse path only up to its limit).
    const bool balanced = direct_ && (h.Hd != nullptr || AS_.rows() <= kSparseDirectLimit);
    for (const double factor : {balanced ? 1.0 : 1e6, 1e6}) {
      rho = AS_.rows() > 0 ? factor * h.diag / adiag_ : 0.0;
      if (chol.compute(h.H, h.Hd, AS_.rows() > 0 ? &AtA_ : nullptr, rho)) {
        if (factor != 1.0) direct_ = false;
        return true;
      }
      if (AS_.rows() == 0) break;
    }
    return false;
  }

  /// A step on a new factorisation of M: the range-space solve or the method of multipliers.
  StepEnd factorised_step(const HessianAt& h) {
    const bool dense = h.Hd != nullptr;
    SpdFactor chol(dense);
    double rho = 0.0;
    if (!factorise(h, chol, rho)) return StepEnd::kFailed;
    const VectorXd x_start = xs_;
    if (direct_ && AS_.rows() > 0 && AS_.rows() <= (dense ? kDirectLimit : kSparseDirectLimit)) {
      // Range-space solve of the KKT system on S, exact in one step (Nocedal & Wright §16.2):
      //   M Δ − A_Sᵀ λ = −ĝ,  A_S Δ = −c_S,  ĝ = g + ρ A_Sᵀ c_S  (the ρ term vanishes on A_S Δ = −c_S)
      //   ⇒ (A_S M⁻¹ A_Sᵀ) λ = A_S M⁻¹ ĝ − c_S, solved in the least-squares, minimum-norm sense
      //   (complete orthogonal decomposition) because dependent rows make it singular.
      const VectorXd cS = AS_ * xs_ + bS_;
      VectorXd dx, lambda;
      if (chol.dense()) {
        // With M = L Lᵀ dense: DenseRangeSpace, one multi-column triangular solve for W = L⁻¹ A_Sᵀ instead
        // of |S| + 2 pairs of single-column solves (BLAS-3 work instead of BLAS-2). It is kept to
        // precondition the next Newton steps (cg_step).
        reference_ = std::make_unique<DenseRangeSpace>(chol.dense_factor(), AS_, rho);
        reference_->solve(h.g, cS, dx, lambda);
      } else {
        range_space_step(chol, AS_, cS, VectorXd(h.g + rho * (AS_.transpose() * cS)), dx, lambda);
      }
      xs_ += dx;
      nu_ = lambda;
      ++iterations_;
    } else {
      VectorXd g = h.g;
      const auto hessian_times = [&](const VectorXd& dx, VectorXd& out) {
        if (dense)
          symmetric_multiply_add(*h.Hd, dx, out);
        else
          out += h.H.selfadjointView<Eigen::Lower>() * dx;
      };
      // A stalled method of multipliers means the set cannot be closed (inconsistent rows): further Newton
      // steps on f cannot change that, and the caller's rounds decide what to drop.
      const SpdSolve solve = [&chol](const VectorXd& b) { return chol.solve(b); };
      if (!multiplier_method(solve, hessian_times, AS_, bS_, rho, xscale0_, g, xs_, nu_, iterations_))
        return StepEnd::kStalled;
    }
    // Newton has converged when its step is at the level of round-off in x (1e-10 relative: the augmented
    // systems lose a few digits).
    const double step = (xs_ - x_start).lpNorm<Eigen::Infinity>();
    return step <= 1e-10 * xscale0_ || at_round_off(step) ? StepEnd::kConverged : StepEnd::kTaken;
  }

  /// Takes the Newton step (Δ, λ) of a dense direct or CG solve; whether the loop has converged (the step at
  /// the round-off of x).
  bool take_step(const VectorXd& dx, const VectorXd& lambda) {
    xs_ += dx;
    nu_ = lambda;
    ++iterations_;
    const double step = dx.lpNorm<Eigen::Infinity>();
    return step <= 1e-10 * xscale0_ || at_round_off(step);
  }

  /// Newton's steps fall quadratically until they reach the round-off of these augmented systems (1e-10 to
  /// 3e-10 of max|x| on the inclined interface, where IPOPT's point is already there: without this test its
  /// force-balancing polish takes 12–20 steps of noise). A step at that level ends the loop when it is not a
  /// tenth of the one before (round-off), or when it is at most kContracted of it: converging q-linearly or
  /// faster, the error it leaves is about that ratio times the step, below 1e-11 of max|x|, and a further step
  /// would only measure round-off.
  bool at_round_off(double step) {
    const bool contracted = std::isfinite(previous_step_) && step <= kContracted * previous_step_;
    const bool stop = step <= kRoundOffStep * xscale0_ && (step > 0.1 * previous_step_ || contracted);
    previous_step_ = step;
    return stop;
  }

  ConstrainedProblem& problem_;
  const SparseMatrix& AS_;
  const VectorXd& bS_;
  VectorXd& xs_;
  VectorXd& nu_;
  int& iterations_;
  bool direct_;
  StartFactor* start_;
  const double xscale0_;
  std::shared_ptr<const DenseRangeSpace> reference_;  // the last dense direct step's factorised KKT system
  std::unique_ptr<AlignedMatrix> Hd_;                 // the dense H of the current step (hessian())
  SparseMatrix AtA_;                                  // lower triangle of A_Sᵀ A_S
  double adiag_ = 0.0;
  double previous_step_ = std::numeric_limits<double>::infinity();
};

}  // namespace

bool solve_on_set(ConstrainedProblem& problem, const SparseMatrix& AS, const VectorXd& bS, VectorXd& xs, VectorXd& nu,
                  int& iterations, bool direct, StartFactor* start) {
  NewtonOnSet newton(problem, AS, bS, xs, nu, iterations, direct, start);
  for (int k = 0; k < (problem.hessian_is_constant() ? 1 : 20); ++k) {
    const StepEnd end = newton.step(k == 0);
    if (end == StepEnd::kFailed) return false;
    if (end == StepEnd::kConverged || end == StepEnd::kStalled) break;
  }
  return true;
}

}  // namespace symcontact
