#pragma once
/// \file equality_constrained_solve.hpp
/// The solve of the active-set polish (active_set_polish.hpp) on a fixed set S of rows:
///     min f(x)  subject to  A_S x + b_S = 0,
/// by Newton steps on f (one for a quadratic f), each solved with M = H + ρ A_Sᵀ A_S factorised
/// (spd_factor.hpp; H alone when S is empty) either
///  - directly, by the range space of the KKT system (Nocedal & Wright, Numerical Optimization, 2006, §16.2):
///        M Δ − A_Sᵀ λ = −ĝ,  A_S Δ = −c_S,  ĝ = g + ρ A_Sᵀ c_S
///        ⇒ (A_S M⁻¹ A_Sᵀ) λ = A_S M⁻¹ ĝ − c_S,
///    in the least-squares, minimum-norm sense because dependent rows make it singular; later Newton steps of
///    a dense problem by projected CG preconditioned with the last factorised system (dense_kkt.hpp); or
///  - by the method of multipliers (Hestenes 1969; Nocedal & Wright §17.3):
///        M Δx = −(∇f(x) − A_Sᵀ ν) − ρ A_Sᵀ c_S(x),   x ← x + Δx,   ν ← ν − ρ c_S(x),
///    which converges whatever the rank of A_S (dependent rows get some split of the multiplier; A_Sᵀ ν, the
///    contact force, is unique).

#include <functional>
#include <memory>
#include <vector>

#include "symcontact/optim/constrained_problem.hpp"
#include "symcontact/solvers/dense_kkt.hpp"
#include "symcontact/solvers/spd_factor.hpp"

namespace symcontact {

/// The Cholesky factor of a dense H(x) alone (ρ = 0) at a start point that several solves on different sets
/// share: the polish's rounds all restart from the optimiser's x and differ only in S, so the first solve
/// factorises H(x) and the others reuse it (with ρ = 0 the factor does not depend on S; the range-space step
/// is the same solution). Kept only where H is numerically definite with its Cholesky pivots within 1e-6 of
/// each other (condition below about 1e12); a body held by contact alone leaves H singular, and every solve
/// then factorises H + ρ A_SᵀA_S of its own set.
/// The range-space solve on that factor is shared too: the rounds' sets mostly shrink, and the range space of a
/// subset of the rows is the first one's restricted to them (DenseRangeSpace's subset constructor).
struct StartFactor {
  bool tried = false;                      ///< H(x) factorised (or found not definite) by an earlier solve
  std::shared_ptr<const AlignedMatrix> L;  ///< null: H(x) not definite enough
  /// The rows (the caller's numbering, increasing) of the next solve's A_S; the caller sets them. Empty: not
  /// known, no range space is shared.
  std::vector<Index> rows;
  std::shared_ptr<const DenseRangeSpace> range;  ///< L's range space on the rows `range_rows`
  std::vector<Index> range_rows;
};

/// xs: the start on entry, the solution on exit; nu: the multipliers of the rows of AS (ν ≥ 0 for a pull of
/// the constraint), their start on entry; `iterations` counts the steps taken. `direct`: the range-space solve
/// where S has at most a few thousand rows (else, or when M needs a large ρ to be definite, the method of
/// multipliers). `start` (optional, direct solves of a dense H): the factor of H at this xs shared with the other
/// solves from the same xs (StartFactor). A non-quadratic f gets at most 20 Newton steps: xs is then their last
/// iterate, not necessarily converged, which the caller judges (active_set_polish.cpp keeps it only where the
/// stationarity error fell). Returns false when M cannot be factorised.
bool solve_on_set(ConstrainedProblem& problem, const SparseMatrix& AS, const VectorXd& bS, VectorXd& xs, VectorXd& nu,
                  int& iterations, bool direct, StartFactor* start = nullptr);

/// M⁻¹ b: a factor of M = H + ρ A_SᵀA_S, or one updated for rows that joined or left S (row_updated_factor.hpp).
using SpdSolve = std::function<VectorXd(const VectorXd&)>;

/// The method of multipliers on the set S with M = H + ρ A_Sᵀ A_S factorised (`solve`), from xs with the gradient
/// g = ∇f(xs) and the multipliers nu: xs += M⁻¹(−(g − A_Sᵀ ν) − ρ A_Sᵀ c_S), ν −= ρ c_S(xs), g kept as the
/// gradient of f's quadratic model by g += H Δ (`hessian_times` adds H Δ to its second argument); for a
/// quadratic f the solution of the file comment's problem, else one Newton step of it. One step when S is
/// empty. Converged when c_S and the update are at most 1e-14 × max(xscale0, max|xs|) (max-norm: from xs = 0, the
/// scale is the answer's). Returns false when the
/// violation stops falling (40 iterations without a 1 % gain: the rows are inconsistent, the set must change
/// instead). `iterations` counts the solves.
bool multiplier_method(const SpdSolve& solve, const std::function<void(const VectorXd&, VectorXd&)>& hessian_times,
                       const SparseMatrix& AS, const VectorXd& bS, double rho, double xscale0, VectorXd& g,
                       VectorXd& xs, VectorXd& nu, int& iterations);

}  // namespace symcontact
