#include "symcontact/solvers/active_set_polish.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "symcontact/core/error.hpp"
#include "symcontact/solvers/equality_constrained_solve.hpp"

namespace symcontact {

namespace {

/// A constraint is violated when its scaled value is below −kViolationTolerance × max |x|.
constexpr double kViolationTolerance = 1e-10;
/// A constraint is open when its scaled value is above kOpenGap × max |x|: far above the barrier offsets an
/// interior point leaves at closed rows (up to about 1e-5 of max |x| on the nearly dependent families of a
/// symmetric pair).
constexpr double kOpenGap = 1e-3;

/// Removes from the set the rows of S whose multiplier ν pulls (below −1e-8 of the largest |ν|): they were not
/// active. Whether any was removed.
bool drop_pulling_rows(const std::vector<Index>& S, const VectorXd& nu, std::vector<char>& in_set) {
  const double numax = nu.size() ? nu.cwiseAbs().maxCoeff() : 0.0;
  bool changed = false;
  for (std::size_t k = 0; k < S.size(); ++k)
    if (nu[k] < -1e-8 * numax) {
      in_set[S[k]] = 0;
      changed = true;
    }
  return changed;
}

/// Whether x closes every row of A_S x + b_S = 0 (rows scaled to a unit largest entry) to within
/// kViolationTolerance × max |x|.
bool closes_rows(const SparseMatrix& AS, const VectorXd& bS, const VectorXd& x) {
  if (AS.rows() == 0) return true;
  const double xscale = std::max(x.lpNorm<Eigen::Infinity>(), 1e-300);
  return (AS * x + bS).lpNorm<Eigen::Infinity>() <= kViolationTolerance * xscale;
}

/// The largest |A_ij| of each row: the constraint values in the units of x (as IPOPT saw them).
VectorXd row_scales(const SparseMatrix& A) {
  VectorXd row_scale = VectorXd::Zero(A.rows());
  for (int j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it)
      row_scale[it.row()] = std::max(row_scale[it.row()], std::abs(it.value()));
  return row_scale;
}

/// The rows the polish starts from: μ_i > 1e-6 max μ. Holding values with no gap closed at all (a surface
/// approaching its opposite side: every row the optimiser left open by more than kOpenGap of the
/// displacements), the multipliers are the barrier's μ_b / c_i alone, however they compare with each other: none
/// is active. (Where some gap is closed, the set is left as it is: the frictional ironing test's hardest step is
/// sensitive to dropping the open rows beside a closed one.)
std::vector<char> starting_set(const VectorXd& x, const VectorXd& mu, const VectorXd& c0, const VectorXd& row_scale,
                               bool hold_values) {
  const Index m = mu.size();
  const double mu_max = m > 0 ? mu.maxCoeff() : 0.0;
  std::vector<char> in_set(m, 0);
  for (Index i = 0; i < m; ++i) in_set[i] = mu_max > 0 && mu[i] > 1e-6 * mu_max && row_scale[i] > 0;
  if (hold_values) {
    const double open_gap = kOpenGap * std::max(x.lpNorm<Eigen::Infinity>(), 1e-300);
    bool any_closed = false;
    for (Index i = 0; i < m; ++i) any_closed = any_closed || (in_set[i] && c0[i] / row_scale[i] <= open_gap);
    if (!any_closed) std::fill(in_set.begin(), in_set.end(), 0);
  }
  return in_set;
}

/// The equality problem of one set S: A_S with rows scaled to a unit largest entry, its offsets b_S (holding
/// values: less the values c0 the optimiser left), and the start of the scaled multipliers ν = μ · scale.
struct SetSystem {
  std::vector<Index> S;
  SparseMatrix AS;
  VectorXd bS, nu;
};

SetSystem set_system(const ConstrainedProblem& problem, const VectorXd& c0, const VectorXd& mu, const VectorXd& row_scale,
                     const std::vector<char>& in_set, bool hold_values) {
  const SparseMatrix& A = problem.constraint_matrix();
  const VectorXd& b = problem.constraint_offset();
  SetSystem sys;
  std::vector<Index> pos(A.rows(), -1);
  for (Index i = 0; i < A.rows(); ++i)
    if (in_set[i]) {
      pos[i] = static_cast<Index>(sys.S.size());
      sys.S.push_back(i);
    }
  const auto& S = sys.S;
  std::vector<Triplet> t;
  for (int j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it)
      if (pos[it.row()] >= 0) t.emplace_back(static_cast<int>(pos[it.row()]), j, it.value() / row_scale[it.row()]);
  sys.AS.resize(static_cast<Index>(S.size()), A.cols());
  sys.AS.setFromTriplets(t.begin(), t.end());
  sys.bS.resize(S.size());
  sys.nu.resize(S.size());
  for (std::size_t k = 0; k < S.size(); ++k) {
    sys.bS[k] = b[S[k]] / row_scale[S[k]];
    if (hold_values) sys.bS[k] -= c0[S[k]] / row_scale[S[k]];  // target: the constraint values IPOPT left
    sys.nu[k] = mu[S[k]] * row_scale[S[k]];
  }
  return sys;
}

/// xs, sys.nu ← the solution on the set from x, and the rows of S that pull removed from in_set (`changed`:
/// whether any was). Holding the values is always consistent: solved directly. Closing may not be (curved
/// symmetric pairs): solved directly too, and where that leaves a row of S open or violated (the least-squares
/// answer of inconsistent rows) and pulls on none, again from x by the method of multipliers, which degrades
/// gracefully there. A set with rows that pull (negative multipliers: the least-squares multipliers tell them
/// as well) is not solved further: those rows leave it for the next round. Directly, a set costs a few
/// factorisations, the first of them (H(x), where definite: `start`) shared by every round; the method of
/// multipliers converges along nearly dependent rows at the rate 1/(1 + ρσ²), σ their smallest singular value
/// (thousands of dense solves on the first set of the 3D plates of docs/performance.md). False when
/// M = H + ρ A_SᵀA_S cannot be factorised.
bool solve_set(ConstrainedProblem& problem, const VectorXd& x, bool hold_values, SetSystem& sys, VectorXd& xs,
               int& iterations, std::vector<char>& in_set, bool& changed, StartFactor& start) {
  const VectorXd nu_start = sys.nu;
  xs = x;
  start.rows = sys.S;
  bool solved = solve_on_set(problem, sys.AS, sys.bS, xs, sys.nu, iterations, true, &start) && xs.allFinite() &&
                sys.nu.allFinite();
  changed = solved && drop_pulling_rows(sys.S, sys.nu, in_set);
  if (solved && !changed && !hold_values && !closes_rows(sys.AS, sys.bS, xs)) {
    xs = x;
    sys.nu = nu_start;
    solved = solve_on_set(problem, sys.AS, sys.bS, xs, sys.nu, iterations, false) && xs.allFinite() &&
             sys.nu.allFinite();
    changed = solved && drop_pulling_rows(sys.S, sys.nu, in_set);
  }
  return solved;
}

/// The other half of the active-set update (the primal-dual active set strategy: Hintermüller, Ito & Kunisch,
/// SIAM J. Optim. 13, 2003, eq. 2.4): constraints outside S that the solve on S violates (at xs) were active
/// too, and join S. A constraint that became active between two geometry iterations is left by a warm-started
/// IPOPT solve (often a single iteration) with the tiny multiplier of the warm start, below the starting set's
/// threshold; without this step the closing polish is rejected and the whole solve falls back to balancing
/// forces only, which keeps the barrier offsets (on the V7 3D hairpin: pressures off the half model's by 3.6e-5
/// of the maximum). For a quadratic f only (the caller), where the solve on S is exact and this is the strategy
/// of the reference (for a finite-strain energy it makes the geometry fixed point of the crushed ring's last
/// step cycle). Whether any row joined.
bool add_violated_rows(const ConstrainedProblem& problem, const VectorXd& row_scale, const VectorXd& xs,
                       std::vector<char>& in_set) {
  const double xscale = std::max(xs.lpNorm<Eigen::Infinity>(), 1e-300);
  const VectorXd c = problem.constraint_matrix() * xs + problem.constraint_offset();
  bool changed = false;
  for (Index i = 0; i < c.size(); ++i)
    if (!in_set[i] && row_scale[i] > 0 && -c[i] / row_scale[i] > kViolationTolerance * xscale) {
      in_set[i] = 1;
      changed = true;
    }
  return changed;
}

/// Why the polished point (xs, μ_new) is not kept in place of the optimiser's (x, μ), or empty: a constraint
/// violated (a KKT point of the inequality problem only), or — for a non-quadratic f (friction), where Newton
/// on a strongly curved term can land anywhere — a stationarity error ‖∇f − Aᵀμ‖∞ that did not fall.
std::string rejection(ConstrainedProblem& problem, const VectorXd& x, const VectorXd& mu, const VectorXd& xs,
                      const VectorXd& mu_new, const VectorXd& row_scale, double& max_violation) {
  const SparseMatrix& A = problem.constraint_matrix();
  const double xscale = std::max(xs.lpNorm<Eigen::Infinity>(), 1e-300);
  const VectorXd c = A * xs + problem.constraint_offset();
  for (Index i = 0; i < A.rows(); ++i)
    if (row_scale[i] > 0) max_violation = std::max(max_violation, -c[i] / row_scale[i]);
  if (max_violation > kViolationTolerance * xscale) return "a constraint outside the active set became violated";
  if (problem.hessian_is_constant()) return "";
  auto stationarity = [&](const VectorXd& xx, const VectorXd& m) {
    VectorXd g;
    problem.gradient(xx, g);
    return (g - A.transpose() * m).lpNorm<Eigen::Infinity>();
  };
  // Scale: the larger of the constraint force and the gradient at the IPOPT point. A polish that only closes
  // the constraints keeps stationarity at round-off level; a Newton overshoot raises it by orders of magnitude.
  VectorXd g0;
  problem.gradient(x, g0);
  const double scale = std::max((A.transpose() * mu).lpNorm<Eigen::Infinity>(), g0.lpNorm<Eigen::Infinity>());
  if (!(stationarity(xs, mu_new) <= 10.0 * stationarity(x, mu) + 1e-6 * scale))
    return "the Newton steps did not reduce the stationarity error";
  return "";
}

PolishResult polish_on_active_set(ConstrainedProblem& problem, VectorXd& x, VectorXd& mu, PolishMode mode) {
  const bool hold_values = mode == PolishMode::kBalanceForces;
  PolishResult r;
  const SparseMatrix& A = problem.constraint_matrix();
  if (mu.size() != A.rows()) {
    r.reason = "multipliers and constraints differ in size";
    return r;
  }
  const VectorXd row_scale = row_scales(A);
  const VectorXd c0 = A * x + problem.constraint_offset();
  std::vector<char> in_set = starting_set(x, mu, c0, row_scale, hold_values);
  // Rounds: constraints that the equality solve wants to pull (negative multiplier) were not really
  // active; drop them and solve again. After a warm-started IPOPT solve the multipliers of inactive
  // constraints can stay above the threshold, so the first set may hold ten times the active ones and
  // need several rounds to shrink. Constraints the solve violates join the set (quadratic f).
  constexpr int kMaxRounds = 30;
  VectorXd xs;
  SetSystem sys;
  StartFactor start;  // every round's solve starts from x: H(x) factorised once
  for (int round = 0; round < kMaxRounds; ++round) {
    sys = set_system(problem, c0, mu, row_scale, in_set, hold_values);
    r.active = static_cast<int>(sys.S.size());
    bool changed = false;
    if (!solve_set(problem, x, hold_values, sys, xs, r.iterations, in_set, changed, start)) {
      r.reason = "the Hessian (+ ρ AᵀA) is not positive definite";
      return r;
    }
    if (!changed && problem.hessian_is_constant()) changed = add_violated_rows(problem, row_scale, xs, in_set);
    if (!changed) break;
    if (round == kMaxRounds - 1) {
      r.reason = "the active set did not settle (negative multipliers or violated constraints remain)";
      return r;
    }
  }
  VectorXd mu_new = VectorXd::Zero(A.rows());
  for (std::size_t k = 0; k < sys.S.size(); ++k) mu_new[sys.S[k]] = std::max(0.0, sys.nu[k]) / row_scale[sys.S[k]];
  r.reason = rejection(problem, x, mu, xs, mu_new, row_scale, r.max_violation);
  if (!r.reason.empty()) return r;
  x = xs;
  mu = mu_new;
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
