#pragma once
/// \file lagged_fixed_point.hpp
/// The outer loop of a load step: data that the contact solve takes as fixed (a lagged term) is updated from
/// each solve's answer until it stops changing. The loop is the same whatever is lagged; what is lagged is a
/// hook, LaggedTerm, in the manner of lagged forms in polyfem (update_lagging, then a convergence test on the
/// lagged quantity). The one lagged term of the product is the Coulomb law: the thresholds τ of the friction
/// term lag the pressure, τ = μ p (coulomb_thresholds.hpp; Algorithm 1 of the talk, METHOD.md).
///
/// With d_k the term's data for solve k and u_k that solve's answer, the term gives the residual
/// r_k = T(u_k) − d_k (one vector per part: per contact pair) and the loop sets
///     d_{k+1} = P(d_k + ω_k r_k),   c_k = max_p ‖r_{k,p}‖∞ / max_p ‖d_{k,p}‖∞,
/// P the term's projection (τ ≥ 0), until c_k < tolerance on a solve converged to the geometry tolerance.
///  - Relaxation: Aitken's Δ² rule in the vector form of Küttler & Wall, Comput. Mech. 43 (2008), eq. 44:
///      ω_k = −ω_{k−1} r_{k−1}·(r_k − r_{k−1}) / ‖r_k − r_{k−1}‖²,  ω_1 = 1, clipped to [0.1, 1]
///    (Irons & Tuck 1969). Where the map d ↦ T(u(d)) has a slope near −1 the plain iteration cycles with
///    period 2; the relaxation removes it, and the fixed point is the same.
///  - Cold start: data that do not come from an earlier step (LaggedTerm::warm() false: τ = 0, a frictionless
///    solve) are not a guess to be judged; the first residual sets them, d_1 = P(d_0 + r_0).
///  - Inexact inner solves (FrictionalOptions::inner_tolerance_factor): while d still moves, each solve's
///    geometry fixed point stops at factor × c_{k−1} (1 before any change is known); the loop ends only on a
///    solve to the full geometry tolerance, so c below tolerance on an inexact solve asks for one more
///    solve, and a full solve that moves d back above the tolerance makes every later solve of the step exact.
///  - Past the tolerance (FrictionalOptions::converge_past_tolerance): a converged change c_k that fell
///    at least tenfold from c_{k−1} is followed by one more iteration while c_k > 1e-2 × tolerance. Near a
///    fixed point contracting at a rate ρ the error of d_k is about ρ/(1 − ρ) c_k; where ρ ≤ 0.1 this costs
///    an iteration or two and takes the error well below the tolerance, so that paths that parted by
///    round-off (another unit system) meet. The loop stops at the first change below the tolerance that did
///    not fall tenfold, and never goes past max_coulomb_iterations for it.
///  - Stagnation (FixedPointMonitor: a cycle, or the noise floor of the inner solves): the inner solves are
///    tightened (IPOPT tol × 1e-2, geometry tolerance × 0.1), at most kMaxTightenings times; stagnated after
///    that, the iterate is accepted only when its last solve converged and c ≤ stagnation_acceptance, with a
///    warning and SolveReport::accepted_at_noise_floor. Otherwise, and after max_coulomb_iterations, the
///    step fails with a SolveError naming the loop, what it tried, the changes and what the user can change.
///  - A tightened solve that fails (the inner solver cannot reach the accuracy asked: an iterative Krylov
///    solve breaking down in round-off) shows the noise floor too: the loop goes back to the iterate that
///    solve started from, with its data, solves it again under the options that produced it, and accepts
///    it as above when that solve converges and its change is at most stagnation_acceptance; otherwise the
///    failed solve's SolveError stands.

#include <functional>
#include <string>
#include <vector>

#include "symcontact/core/types.hpp"
#include "symcontact/solvers/frictional_contact.hpp"

namespace symcontact {

/// What an outer loop lags: data the solve reads, and the residual of a solve's answer against them.
class LaggedTerm {
 public:
  virtual ~LaggedTerm() = default;
  /// Names the loop and its data in messages: "the <loop> fixed point", "relative change of the <data>".
  virtual std::string loop_name() const = 0;
  virtual std::string data_name() const = 0;
  /// What the user can change when the loop fails (a sentence without its final full stop).
  virtual std::string advice() const = 0;
  /// Whether anything is lagged (false: the first solve is the answer).
  virtual bool lags() const = 0;
  /// Whether the data come from an earlier step (see the file comment: cold start).
  virtual bool warm() const = 0;
  /// Drops a warm start: the data become the cold ones.
  virtual void start_cold() = 0;
  /// d_k, per part (empty for a part that lags nothing).
  virtual const std::vector<Eigen::VectorXd>& data() const = 0;
  /// r_k = T(u) − d_k at the answer u of a solve that reported `solve`, per part.
  virtual std::vector<Eigen::VectorXd> residual(const VectorXd& u, const SolveReport& solve) const = 0;
  /// d ← P(d + ω r).
  virtual void update(const std::vector<Eigen::VectorXd>& r, double omega) = 0;
  /// d ← `data`, as data() returned it earlier in the loop.
  virtual void set_data(const std::vector<Eigen::VectorXd>& data) = 0;
};

/// c = max_p ‖r_p‖∞ / max_p ‖d_p‖∞ over the parts that lag something (1 when d = 0 and r is not).
double relative_change(const std::vector<Eigen::VectorXd>& r, const std::vector<Eigen::VectorXd>& d);

/// One contact solve with the term's current data, under the options the loop chose (tightened, inexact).
using LaggedSolve = std::function<SolveReport(const ContactSolveOptions&)>;

/// Runs the loop of the file comment. `u`: the step's start, after any predictor; `u_cold`: where a cold
/// restart starts from (a warm first solve that fails: SolveError). `inexact`: whether inexact inner solves
/// are allowed (quadratic energies with a lagged term). The report sums every solve; its contact state is
/// the last one's. Throws SolveError when the loop does not converge (the file comment).
SolveReport solve_lagged(LaggedTerm& term, const LaggedSolve& solve, VectorXd& u, const VectorXd& u_cold,
                         const FrictionalOptions& options, bool inexact, const Logger& log);

}  // namespace symcontact
