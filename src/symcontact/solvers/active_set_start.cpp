#include "symcontact/solvers/active_set_start.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <vector>

#include "symcontact/core/error.hpp"
#include "symcontact/solvers/dense_kkt.hpp"
#include "symcontact/solvers/equality_constrained_solve.hpp"
#include "symcontact/solvers/row_updated_factor.hpp"
#include "symcontact/solvers/spd_factor.hpp"

namespace symcontact {

namespace {

/// A row leaves S when its multiplier is below −kDropBelow × the largest |multiplier| of S (round-off
/// keeps closed rows at ±1e-12 of it), and joins it when its scaled value is below −kViolation × max|x|.
constexpr double kDropBelow = 1e-8, kViolation = 1e-10;
/// Newton on S has converged when its step is at most kStep × max|x|, or at most kRoundOff × max|x| and not a
/// tenth of the step before (the round-off of the augmented systems, equality_constrained_solve.cpp).
constexpr double kStep = 1e-12, kRoundOff = 1e-9;
/// Steps up to kLocal × max|x| are taken whole (Newton's local convergence: f's decrease there, of the order of
/// the step squared, is at f's round-off and a line search would stall). Larger ones go through the line
/// search, which also takes the whole step where f rises by no more than kRoundOffF of |f|. Not larger: whole
/// steps of 9e-4 × max|x| overshot and came back, a two-cycle of Newton on the regularised friction term (the
/// 2D pad on a cylinder at 2.8e4 DOFs, fourth step: 100 Newton steps, then the interior point).
constexpr double kLocal = 1e-6, kRoundOffF = 1e-14;
/// Followed data move with the iterate once Newton's step is at most kFollowBelow × max|x|.
constexpr double kFollowBelow = 1e-1;
/// Projected CG of a Newton step with the factor of an earlier one (dense_kkt.hpp): its step tolerance, the
/// larger of kCgTolerance × max|x| and kCgForcing × the Newton step before (an inexact Newton method; 1e-2
/// took 25 % less time than 1e-3 on the 3D pad on a plane at 1e4 DOFs, the same on the pads at 4e3), and the
/// iterations after which the step refactorises instead.
constexpr double kCgTolerance = 1e-13, kCgForcing = 1e-2;
constexpr int kCgMaxIterations = 50;
/// A Newton step whose projected CG took more than this many iterations makes the next step refactorise:
/// the friction blocks have moved far from the factorised ones (an iteration costs O(m²), the factorisation
/// O(m³/3): at m = 1e3–2e3 about 30–50 iterations).
constexpr int kRefactorAfter = 12;
/// The sparse path's Newton steps reuse the factor of an earlier step on the same S (a modified Newton step:
/// the iterate's gradient, the factorised step's model Hessian) once the steps are below kReuseBelow × max|x|
/// and the last one fell to at most kReuseContraction of the one before. There ∇²f moves only with the followed
/// thresholds and the slips, and the slower contraction of the old model costs less than a factorisation; a step
/// that falls less makes the next one refactorise. On the 3D pad on a plane at 1e4 DOFs, 59 factorisations in
/// 73 steps become 23 in 76 (28 in 66 with the early set updates of newton_on_set), the reactions the same to
/// 5e-10.
constexpr double kReuseBelow = 1e-2, kReuseContraction = 0.5;
/// A set that differs from the factorised one by at most kMaxUpdatedRows rows takes the factor through the
/// Sherman–Morrison–Woodbury identity (row_updated_factor.hpp) for its first step, if the step before the change
/// was at most kReuseAcrossSetsBelow × max|x| (kFollowBelow: every early change of the set qualifies): the rows of
/// a contact zone's edge that join and leave as the set settles (one to a few each round) then cost a few solves
/// with the factor instead of a factorisation each, and the later steps on the set follow the kReuseBelow rule.
constexpr std::size_t kMaxUpdatedRows = 32;
constexpr double kReuseAcrossSetsBelow = 1e-1;

/// The rows of A scaled to unit largest entry, so that multipliers and violations compare across rows.
struct ScaledRows {
  explicit ScaledRows(const ConstrainedProblem& problem) {
    const SparseMatrix& A0 = problem.constraint_matrix();
    scale = VectorXd::Zero(A0.rows());
    for (Index j = 0; j < A0.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(A0, j); it; ++it)
        scale[it.row()] = std::max(scale[it.row()], std::abs(it.value()));
    for (Index i = 0; i < scale.size(); ++i)
      if (!(scale[i] > 0.0)) scale[i] = 1.0;
    A = scale.cwiseInverse().asDiagonal() * A0;
    b = problem.constraint_offset().cwiseQuotient(scale);
  }
  VectorXd scale;  ///< max_j |A_ij|
  SparseMatrix A;  ///< rows divided by their scale
  VectorXd b;
};

/// The rows of S (a 0/1 flag per row) as A_S, b_S.
void restrict_rows(const ScaledRows& rows, const std::vector<Index>& S, SparseMatrix& AS, VectorXd& bS) {
  std::vector<Index> pos(rows.A.rows(), -1);
  for (std::size_t k = 0; k < S.size(); ++k) pos[S[k]] = static_cast<Index>(k);
  std::vector<Triplet> t;
  for (Index j = 0; j < rows.A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(rows.A, j); it; ++it)
      if (pos[it.row()] >= 0) t.emplace_back(static_cast<int>(pos[it.row()]), static_cast<int>(j), it.value());
  AS.resize(static_cast<Index>(S.size()), rows.A.cols());
  AS.setFromTriplets(t.begin(), t.end());
  bS.resize(static_cast<Index>(S.size()));
  for (std::size_t k = 0; k < S.size(); ++k) bS[k] = rows.b[S[k]];
}

/// The sparse path's model of a Newton step: ∇²f at the step that factorised it, and CHOLMOD's factor of
/// M = ∇²f + ρ A_SᵀA_S (the same pattern at every step on S: the analysis is kept).
struct SparseModel {
  /// ρ = kSparseRho × mean|H_ii| / max (A_SᵀA_S)_ii, whose multiplier iteration contracts by about 1/(1 + ρσ²)
  /// per solve (σ the rows' singular values relative to H's scale). Not larger: the iteration stops at an update
  /// of 1e-14 max|x| in M's units, so stationarity is met only to about ρ × 1e-14 (with 1e6, to 7e-12 scaled on
  /// the tests' problems, against their tolerance of 1e-12). Not smaller: each decade fewer multiplies the solves
  /// a Newton step needs to meet that update (the contraction above), for the same Newton steps.
  static constexpr double kSparseRho = 1e3;
  SparseMatrix H;
  double rho = 0.0;
  /// The factor; a new one (a new analysis: A_SᵀA_S's pattern) for each set factorised.
  std::unique_ptr<SpdFactor> chol;
  bool factorised = false;
  bool nu_warm = false;  ///< the multipliers of a step on S are there to start the next one's from
  std::vector<Index> rows;  ///< S when factorised (ascending)
  /// How the factor serves the current S: unknown until asked (serves()), its own rows, through a
  /// RowUpdatedFactor for the rows that joined or left since, or not (more than kMaxUpdatedRows changed).
  enum class Fit { kUnknown, kExact, kUpdated, kNone };
  Fit fit = Fit::kUnknown;
  std::unique_ptr<RowUpdatedFactor> update;

  /// A new set S begins: the factor's fit to it is to be found, its multipliers start from zero.
  void new_set() {
    fit = Fit::kUnknown;
    update.reset();
    nu_warm = false;
  }

  /// Factorises M at x for the set S; false when it is not definite. `factorisations` counts it.
  bool factorise(ConstrainedProblem& problem, const VectorXd& x, const SparseMatrix& AtA, double adiag,
                 const std::vector<Index>& S, int& factorisations) {
    problem.hessian_lower(x, H);
    const double hdiag = H.diagonal().cwiseAbs().mean();
    rho = AtA.rows() > 0 ? kSparseRho * hdiag / adiag : 0.0;
    update.reset();
    if (!chol || rows != S) chol = std::make_unique<SpdFactor>(false);
    rows = S;
    factorised = hdiag > 0 && chol->compute(H, nullptr, AtA.rows() > 0 ? &AtA : nullptr, rho);
    fit = factorised ? Fit::kExact : Fit::kNone;
    if (factorised) ++factorisations;
    return factorised;
  }

  /// Whether the factor (of an earlier S) can serve the set S: the same rows, or at most kMaxUpdatedRows that
  /// joined (+ρ aᵢaᵢᵀ) or left (−ρ aᵢaᵢᵀ), aᵢ the rows of `scaled`.
  bool serves(const ScaledRows& scaled, const std::vector<Index>& S) {
    if (!factorised) return false;
    if (fit != Fit::kUnknown) return fit != Fit::kNone;
    std::vector<Index> changed;
    std::vector<double> coefficient;
    std::size_t a = 0, b = 0;
    while (a < S.size() || b < rows.size()) {
      if (b == rows.size() || (a < S.size() && S[a] < rows[b])) {
        changed.push_back(S[a++]);
        coefficient.push_back(rho);
      } else if (a == S.size() || rows[b] < S[a]) {
        changed.push_back(rows[b++]);
        coefficient.push_back(-rho);
      } else {
        ++a;
        ++b;
      }
    }
    fit = changed.empty() ? Fit::kExact : Fit::kNone;
    if (changed.empty() || changed.size() > kMaxUpdatedRows) return fit == Fit::kExact;
    SparseMatrix a_changed;
    VectorXd b_changed;
    restrict_rows(scaled, changed, a_changed, b_changed);
    update = std::make_unique<RowUpdatedFactor>(*chol, SparseMatrix(a_changed.transpose()),
                                                Eigen::Map<const VectorXd>(coefficient.data(), coefficient.size()));
    if (!update->valid()) {
      update.reset();
      return false;
    }
    fit = Fit::kUpdated;
    return true;
  }

  /// M⁻¹ b for the set the factor serves.
  VectorXd solve(const VectorXd& b) const { return update ? update->solve(b) : chol->solve(b); }
};

/// Newton directions of  min f  subject to  A_S x + b_S = 0:  ∇²f Δ − A_Sᵀν = −∇f,  A_S Δ = −c_S. With a dense
/// ∇²f (the condensed problem) each is the range-space solve of that KKT system (dense_kkt.hpp) with a new
/// factorisation of ∇²f + ρ A_SᵀA_S, or projected CG preconditioned with the last one where only f's friction
/// blocks changed since; the CG stops at an update of `cg_tolerance` (inexact Newton: the caller sets it from
/// the step before). With a sparse one, CHOLMOD's factor of ∇²f + ρ A_SᵀA_S with a large ρ and the method of
/// multipliers (equality_constrained_solve.hpp): a few solves with the factor where the range space would
/// take one per row.
class NewtonOnSet {
 public:
  /// `factorisations` counts the factorisations made.
  /// `sparse`: the sparse path's model, kept from set to set; `scaled`, `S`: the scaled rows and the set.
  NewtonOnSet(ConstrainedProblem& problem, const SparseMatrix& AS, const VectorXd& bS, int& factorisations,
              SparseModel& sparse, const ScaledRows& scaled, const std::vector<Index>& S)
      : problem_(problem), AS_(AS), bS_(bS), sparse_(sparse), scaled_(scaled), S_(S),
        H_(problem.hessian_is_dense() ? std::make_unique<AlignedMatrix>(problem.num_variables(),
                                                                        problem.num_variables())
                                      : nullptr),
        factorisations_(factorisations) {
    sparse_.new_set();
    if (AS.rows() > 0) {
      AtA_ = SparseMatrix(AS.transpose() * AS).triangularView<Eigen::Lower>();
      adiag_ = AtA_.diagonal().cwiseAbs().maxCoeff();
    }
  }

  /// Whether the last direction came from the sparse path's model of an earlier step (`reuse`).
  bool stale() const { return stale_; }

  /// The direction dx at x, the rows' multipliers nu at x + dx, and the slope ∇f(x)ᵀdx. False when
  /// ∇²f + ρ A_SᵀA_S cannot be factorised. `reuse`: the sparse path may keep its last factor (kReuseBelow).
  bool direction(const VectorXd& x, double cg_tolerance, bool reuse, VectorXd& dx, VectorXd& nu, double& slope) {
    if (!H_) return sparse_direction(x, reuse, dx, nu, slope);
    AlignedMatrix& H = *H_;
    H.map().setZero();
    problem_.add_hessian_lower(x, 1.0, H.map());
    VectorXd g;
    problem_.gradient(x, g);
    const VectorXd cS = AS_ * x + bS_;
    if (reference_ && cg_iterations_ <= kRefactorAfter) {
      const auto multiply = [&](const VectorXd& v, VectorXd& out) {
        out = VectorXd::Zero(v.size());
        symmetric_multiply_add(H, v, out);
      };
      const ProjectedCgResult cg = projected_cg(*reference_, multiply, g, cS, dx, nu, cg_tolerance, kCgMaxIterations);
      cg_iterations_ = cg.iterations;
      if (cg.converged) {
        slope = g.dot(dx);
        return true;
      }
    }
    const double hdiag = H.map().diagonal().cwiseAbs().mean();
    const double rho = AS_.rows() > 0 ? hdiag / adiag_ : 0.0;
    SpdFactor chol(true);
    if (!(hdiag > 0) || !chol.compute(SparseMatrix(), &H, AS_.rows() > 0 ? &AtA_ : nullptr, rho)) return false;
    ++factorisations_;
    cg_iterations_ = 0;
    if (AS_.rows() == 0) {
      dx = chol.solve(VectorXd(-g));
      nu.resize(0);
    } else {
      reference_ = std::make_unique<DenseRangeSpace>(chol.dense_factor(), AS_, rho);
      reference_->solve(g, cS, dx, nu);
    }
    slope = g.dot(dx);
    return true;
  }

 private:
  /// The sparse path of direction(): the method of multipliers on the model (SparseModel) from x's gradient,
  /// the model refactorised at x unless `reuse`.
  bool sparse_direction(const VectorXd& x, bool reuse, VectorXd& dx, VectorXd& nu, double& slope) {
    VectorXd g;
    problem_.gradient(x, g);
    slope = 0.0;
    stale_ = reuse && sparse_.serves(scaled_, S_);
    if (!stale_ && !sparse_.factorise(problem_, x, AtA_, adiag_, S_, factorisations_)) return false;
    const SparseMatrix& H = sparse_.H;
    const double rho = sparse_.rho;
    const auto hessian_times = [&H](const VectorXd& v, VectorXd& out) { out += H.selfadjointView<Eigen::Lower>() * v; };
    VectorXd xs = x, gs = g;
    // From the last step's multipliers on S (the answer's, to the model's change), else from 0.
    if (!sparse_.nu_warm || nu.size() != AS_.rows()) nu = VectorXd::Zero(AS_.rows());
    int solves = 0;
    const double xscale = std::max(x.lpNorm<Eigen::Infinity>(), 1e-300);
    const SparseModel& model = sparse_;
    const SpdSolve solve = [&model](const VectorXd& b) { return model.solve(b); };
    if (!multiplier_method(solve, hessian_times, AS_, bS_, rho, xscale, gs, xs, nu, solves))
      return false;
    sparse_.nu_warm = true;
    dx = xs - x;
    slope = g.dot(dx);
    return true;
  }

  ConstrainedProblem& problem_;
  const SparseMatrix& AS_;
  const VectorXd& bS_;
  std::unique_ptr<AlignedMatrix> H_;  ///< the dense path's ∇²f (null on the sparse path)
  SparseModel& sparse_;               ///< the sparse path's
  const ScaledRows& scaled_;
  const std::vector<Index>& S_;
  SparseMatrix AtA_;
  double adiag_ = 0.0;
  std::unique_ptr<DenseRangeSpace> reference_;
  int& factorisations_;
  int cg_iterations_ = 0;  ///< of the last projected CG
  bool stale_ = false;
};

/// The step length along dx from x: 1 where x is off the rows of S (the step lands on them: they are linear);
/// on them, halved from 1 until f falls by 1e-4 of the slope (Armijo; f convex and dx a descent direction on
/// the rows' null space: ∇fᵀdx = −dxᵀ∇²f dx), the whole step also where f rises within its round-off
/// (kRoundOffF). 0 when no length in 30 halvings does.
double step_length(ConstrainedProblem& problem, const VectorXd& x, const VectorXd& dx, double slope, bool on_rows) {
  if (!on_rows) return 1.0;
  const double f0 = problem.objective(x);
  double alpha = 1.0;
  for (int half = 0; half < 30; ++half, alpha *= 0.5) {
    try {
      const double f = problem.objective(x + alpha * dx);
      if (f <= f0 + 1e-4 * alpha * slope) return alpha;
      if (alpha == 1.0 && f - f0 <= kRoundOffF * std::max(std::abs(f0), std::abs(f))) return alpha;
    } catch (const EvaluationError&) {
    }
  }
  return 0.0;
}

/// S predicted from the warm start: the rows with a multiplier above 1e-6 of the largest (the polish's set,
/// active_set_polish.hpp) and the rows violated at x0.
std::vector<Index> predicted_set(const ScaledRows& rows, const VectorXd& x0, const VectorXd& multipliers0) {
  const double top = multipliers0.size() ? multipliers0.maxCoeff() : 0.0;
  const VectorXd c = rows.A * x0 + rows.b;
  std::vector<Index> S;
  for (Index i = 0; i < c.size(); ++i)
    if ((top > 0.0 && multipliers0[i] > 1e-6 * top) || c[i] < 0.0) S.push_back(i);
  return S;
}

/// The primal-dual active set update (Hintermüller, Ito & Kunisch 2003, eq. 2.4): rows of S with a negative
/// multiplier leave it, rows outside S that x violates join it. Returns whether S changed.
bool update_set(const ScaledRows& rows, const VectorXd& x, const VectorXd& nu, std::vector<Index>& S) {
  const double numax = nu.size() ? nu.cwiseAbs().maxCoeff() : 0.0;
  const double xscale = std::max(x.lpNorm<Eigen::Infinity>(), 1e-300);
  const VectorXd c = rows.A * x + rows.b;
  std::vector<char> in(rows.A.rows(), 0);
  for (const Index i : S) in[i] = 1;
  bool changed = false;
  for (std::size_t k = 0; k < S.size(); ++k)
    if (nu[static_cast<Index>(k)] < -kDropBelow * numax) {
      in[S[k]] = 0;
      changed = true;
    }
  for (Index i = 0; i < c.size(); ++i)
    if (!in[i] && -c[i] > kViolation * xscale) {
      in[i] = 1;
      changed = true;
    }
  if (!changed) return false;
  S.clear();
  for (Index i = 0; i < c.size(); ++i)
    if (in[i]) S.push_back(i);
  return true;
}

IpoptResult fail(IpoptResult r, const std::string& why) {
  r.success = false;
  r.status_text = why;
  return r;
}

/// The iterate of the attempt: x, the multipliers ν of the rows of S (scaled rows), and what it has cost.
struct SetIterate {
  VectorXd x, nu;
  std::vector<Index> S;
  int newton_steps = 0, factorisations = 0, follows = 0;
  SparseModel sparse;  ///< the sparse path's model, from set to set
  double last_step = std::numeric_limits<double>::infinity();  ///< the last Newton step taken (max-norm)
  /// μ ≥ 0 per row, in the problem's units.
  VectorXd multipliers(const ScaledRows& rows) const {
    VectorXd mu = VectorXd::Zero(rows.A.rows());
    for (std::size_t k = 0; k < S.size(); ++k)
      mu[S[k]] = std::max(0.0, nu[static_cast<Index>(k)]) / rows.scale[S[k]];
    return mu;
  }
};

/// Whether the primal-dual update would change S at it.x with the multipliers it.nu (S itself unchanged).
bool set_changes(const ScaledRows& rows, const SetIterate& it) {
  std::vector<Index> S = it.S;
  return update_set(rows, it.x, it.nu, S);
}

/// Newton on S (the file comment's steps 2 and 3) from it.x until its step is at round-off and the followed
/// data no longer change, or until, near that, the set would change. Returns why it failed; empty otherwise.
std::string newton_on_set(ConstrainedProblem& problem, const ScaledRows& rows, const ActiveSetStartOptions& options,
                          const FollowIterate* follow, SetIterate& it) {
  SparseMatrix AS;
  VectorXd bS;
  restrict_rows(rows, it.S, AS, bS);
  NewtonOnSet newton(problem, AS, bS, it.factorisations, it.sparse, rows, it.S);
  double previous = std::numeric_limits<double>::infinity();
  // The last two steps, followed data or not: whether the model may be kept (kReuseBelow), the CG's forcing.
  double last = std::numeric_limits<double>::infinity(), before_last = last;
  bool refactorise = false;  ///< the next step takes a new model (the round-off test below)
  for (int k = 0;; ++k) {
    if (k >= options.max_newton_steps) return "Newton on the active set did not converge";
    VectorXd dx;
    double slope = 0.0;
    const double xscale = std::max(it.x.lpNorm<Eigen::Infinity>(), 1e-300);
    const bool on_rows = (AS * it.x + bS).lpNorm<Eigen::Infinity>() <= kRoundOff * xscale;
    // Inexact Newton (Dembo, Eisenstat & Steihaug, SIAM J. Numer. Anal. 19, 1982): the CG's accuracy a
    // fraction of the step last taken, down to round-off. Not reset when the followed data change: a CG that
    // then stops at 1e-2 × max|x| gives directions far coarser than the steps, and the followed thresholds
    // stall (the 2D pad on a plane at 9.4e4 DOFs: 58 steps and one more Coulomb iteration, against 33).
    const double cg_tolerance = std::max(kCgTolerance * xscale, kCgForcing * std::min(last, xscale));
    // A new set's first step keeps the factor of the set before, updated for the rows that changed
    // (kMaxUpdatedRows), when the step before the change was below kReuseAcrossSetsBelow.
    const bool reuse = k == 0 ? it.last_step <= kReuseAcrossSetsBelow * xscale
                              : !refactorise && last <= kReuseBelow * xscale &&
                                    last <= kReuseContraction * before_last;
    if (!newton.direction(it.x, cg_tolerance, reuse, dx, it.nu, slope) || !dx.allFinite() || !it.nu.allFinite())
      return "the Newton matrix on the active set is not definite";
    ++it.newton_steps;
    const double step = dx.lpNorm<Eigen::Infinity>();
    bool converged = step <= kStep * xscale || (step <= kRoundOff * xscale && step > 0.1 * previous);
    // Steps that stop falling tenfold are round-off only with the model of this iterate: with an earlier one
    // they fall linearly, at the rate of that model's error, which is no sign of round-off. The next step
    // refactorises, and its successor decides.
    refactorise = converged && step > kStep * xscale && newton.stale();
    converged = converged && !refactorise;
    previous = step;
    before_last = last;
    last = step;
    it.last_step = step;
    const double alpha = step <= kLocal * xscale ? 1.0 : step_length(problem, it.x, dx, slope, on_rows);
    if (alpha == 0.0) return "no step on the active set lowers f";
    it.x += alpha * dx;
    // Near S's solution, a set that the update would change ends Newton on S: the set is updated at this
    // iterate (as the semismooth Newton method updates it at every step) instead of after converging on a set
    // that is about to change, followed data and all.
    if (alpha == 1.0 && step <= kFollowBelow * xscale && set_changes(rows, it)) return "";
    // Followed data move with the iterate once Newton is near its solution: their fixed point and Newton's
    // converge together (the interior point's follow_below).
    if (step <= kFollowBelow * xscale && follow && it.follows < options.max_follows &&
        (*follow)(it.x, it.multipliers(rows))) {
      ++it.follows;
      previous = std::numeric_limits<double>::infinity();
      continue;
    }
    if (converged) return "";
  }
}

}  // namespace

IpoptResult solve_from_active_set(ConstrainedProblem& problem, const VectorXd& x0, const VectorXd& multipliers0,
                                  const ActiveSetStartOptions& options, const FollowIterate* follow) {
  IpoptResult r;
  r.x = x0;
  if (problem.num_equalities() > 0 || problem.lower_bounds() || multipliers0.size() != problem.constraint_matrix().rows())
    return fail(std::move(r), "not a problem with inequality rows only and their multipliers");
  const ScaledRows rows(problem);
  SetIterate it;
  it.x = x0;
  it.S = predicted_set(rows, x0, multipliers0);
  try {
    r.scales = dense_primal_scales(problem, x0);
    for (int set_round = 0;; ++set_round) {
      if (set_round >= options.max_set_rounds) return fail(std::move(r), "the active set did not settle");
      const std::string failure = newton_on_set(problem, rows, options, follow, it);
      r.iterations = it.newton_steps;
      if (!failure.empty()) return fail(std::move(r), failure);
      if (!update_set(rows, it.x, it.nu, it.S)) break;
    }
    r.x = it.x;
    r.multipliers = it.multipliers(rows);
    const double error = dense_primal_error(problem, r.scales, r.x, r.multipliers);
    if (!(error <= options.tolerance)) {
      std::ostringstream s;
      s << "the solution on the active set does not pass the stopping test (scaled error " << error << ")";
      return fail(std::move(r), s.str());
    }
    r.objective = problem.objective(r.x);
  } catch (const EvaluationError& e) {
    return fail(std::move(r), std::string("f cannot be evaluated: ") + e.what());
  }
  r.success = true;
  r.status_text = "converged (active set: " + std::to_string(it.factorisations) +
                  (it.factorisations == 1 ? " factorisation)" : " factorisations)");
  r.constraint_values = problem.constraint_matrix() * r.x + problem.constraint_offset();
  r.bound_multipliers = VectorXd::Zero(problem.num_variables());
  return r;
}

}  // namespace symcontact
