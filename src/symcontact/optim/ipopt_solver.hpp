#pragma once
/// \file ipopt_solver.hpp
/// Solves a ConstrainedProblem
///
///     min_x f(x)   subject to   c(x) = A x + b ≥ 0
///
/// with the interior point method IPOPT (Wächter & Biegler 2006). The adapter is thin (STYLE.md §9):
/// a private Ipopt::TNLP in the .cpp translates sizes, bounds, sparsity structures and values, and
/// nothing else; no IPOPT type appears in this header.
///
/// Conventions
/// - IPOPT sees g(x) = A x + b with bounds 0 ≤ g ≤ +∞ and free variables. Its Lagrangian is
///   f + λᵀg, so at a KKT point λ ≤ 0. We report μ = −λ ≥ 0, the contact-pressure sign:
///       ∇f(x) = Aᵀ μ,   μ ≥ 0,   c(x) ≥ 0,   μ_i c_i(x) = 0.
///   Warm-start multipliers are given in the same (μ ≥ 0) convention. Equality rows
///   (ConstrainedProblem::num_equalities()) get bounds 0 ≤ g ≤ 0 and multipliers of either sign in the
///   same convention (∇f = Aᵀμ still holds). Lower bounds on x (ConstrainedProblem::lower_bounds()) are
///   IPOPT's own variable bounds; their multipliers z ≥ 0 are reported (∇f = Aᵀμ + z).
/// - Hessian of the Lagrangian = obj_factor · ∇²f (the constraints are linear); its sparsity is the
///   pattern of hessian_lower() at x0, fixed for the whole solve.
///
/// Scaling (IPOPT "user-scaling"). IPOPT's tolerances are absolute numbers on the scaled problem, so the
/// scaled problem is made dimensionless: then `tolerance` means the same in any consistent system of units
/// (m–N–Pa or mm–N–MPa give the same iterates to round-off), and neither a 1e-8 nor a 1e+11 gradient
/// (SI units) is declared converged at x0 or kept from converging. From the problem at x0:
/// - a force scale g_ref = max(‖∇f(x0)‖∞, h ‖x0‖∞), h = max|∇²f(x0)| (a stiffness): for the usual cold start
///   x0 = 0 the load, for a warm start near a minimiser (∇f(x0) ≈ 0) the internal force of x0;
/// - a length scale ℓ = g_ref / h: the displacement that load causes (cold start), ‖x0‖∞ (warm start);
///   (g_ref = ℓ = 1 when g_ref is 0 or not finite; ℓ = 1 when h is);
/// - variables x̃ = x / ℓ; objective f̃ = f / (g_ref ℓ), so that ∇_x̃ f̃ = ∇f / g_ref and ∇²_x̃ f̃ = ∇²f / h;
///   constraint row i divided by ℓ max_j |A_ij| (1/ℓ for an empty row), so that scaled gaps are in units
///   of ℓ whatever the units of A (weak, area-weighted gaps).
/// `tolerance` is therefore relative to g_ref for the stationarity and to ℓ (times g_ref) for the gaps and
/// the complementarity. IPOPT's extra absolute checks on the unscaled problem (dual_inf_tol,
/// compl_inf_tol, constr_viol_tol and their "acceptable" variants) are set to IPOPT's defaults times the
/// same scales, so that they mean on our problem what they mean on a dimensionless one.
/// The IPOPT option "obj_scaling_factor" given by the user multiplies 1 / (g_ref ℓ) (IPOPT's rule).
///
/// Errors
/// - f, ∇f or ∇²f throwing EvaluationError makes the callback return false: IPOPT then shortens the
///   step (line search) or, at the starting point, stops with a failed status. Any other exception
///   propagates out of solve_with_ipopt.
/// - An unknown IPOPT option, a value of the wrong type or out of range: IpoptOptionError (an
///   std::invalid_argument) naming the option; check_ipopt_options() finds these before any solve. Inconsistent sizes (x0, A, b, multipliers0): std::invalid_argument.
/// - A failed solve does NOT throw: success == false and status/status_text say why; the caller
///   decides (typically by throwing SolveError with its own context).

#include <map>
#include <stdexcept>
#include <string>

#include "symcontact/core/types.hpp"
#include "symcontact/optim/constrained_problem.hpp"

namespace symcontact {

/// The problem's own scales at x0 (see the file comment).
struct ProblemScales {
  double force = 1.0;   ///< g_ref
  double length = 1.0;  ///< ℓ
  double objective_scaling() const { return 1.0 / (force * length); }
};

/// g_ref = max(‖∇f(x0)‖∞, h·‖x0‖∞) and ℓ = g_ref / h, h = max|∇²f(x0)| (the largest entry of the Hessian's
/// lower triangle H0): the scales of the file comment, which every interior point of the contact solver uses.
ProblemScales problem_scales(const VectorXd& x0, const VectorXd& g0, const SparseMatrix& H0);

struct IpoptOptions {
  double tolerance = 1e-10;  ///< IPOPT "tol" on the scaled problem (relative to g_ref, see above)
  int max_iterations = 1000;  ///< IPOPT "max_iter"
  int print_level = 0;        ///< IPOPT "print_level" on stdout; 0 = nothing at all on stdout
  /// IPOPT log written to this file when not empty, at file_print_level = max(5, print_level).
  std::string output_file;
  /// Start from x0 and multipliers0 (IPOPT warm_start_init_point with small bound pushes). Without
  /// multipliers0 only x0 is used, as in a cold start.
  bool warm_start = false;
  /// User-set IPOPT options (e.g. from the problem file), applied after the defaults so they override
  /// them (e.g. {"mu_strategy", "monotone"}).
  std::map<std::string, std::string> string_options;
  std::map<std::string, double> numeric_options;
  std::map<std::string, int> integer_options;
};

/// A user IPOPT option that IPOPT does not know, or a value of the wrong type or out of range.
class IpoptOptionError : public std::invalid_argument {
 public:
  IpoptOptionError(std::string name, const std::string& message)
      : std::invalid_argument(message), name_(std::move(name)) {}
  const std::string& name() const { return name_; }  ///< the option's name

 private:
  std::string name_;
};

/// Sets the user options of `options` (string_options, numeric_options, integer_options) on a fresh
/// IPOPT application exactly as solve_with_ipopt() does, without solving: throws IpoptOptionError for
/// the first one IPOPT rejects. Writes nothing to the console.
void check_ipopt_options(const IpoptOptions& options);

struct IpoptResult {
  bool success = false;       ///< Solve_Succeeded or Solved_To_Acceptable_Level
  int status = 0;             ///< Ipopt::ApplicationReturnStatus as int
  std::string status_text;    ///< e.g. "Solve_Succeeded", "Infeasible_Problem_Detected"
  int iterations = 0;
  double objective = 0.0;     ///< f(x) (unscaled)
  /// Final iterate; also on failure (the last iterate, for inspection). When IPOPT stopped before
  /// producing any iterate (invalid problem, evaluation failure at x0) it is x0.
  VectorXd x;
  VectorXd multipliers;        ///< μ ≥ 0 with ∇f(x) = Aᵀμ at a KKT point (= −IPOPT's λ)
  VectorXd constraint_values;  ///< c(x) = A x + b
  /// z ≥ 0 of the lower bounds x ≥ x_l (ConstrainedProblem::lower_bounds()): ∇f(x) = Aᵀμ + z at a KKT
  /// point; zero when the problem has no bounds.
  VectorXd bound_multipliers;
  double seconds = 0.0;               ///< wall time inside IPOPT (including callbacks)
  double seconds_in_callbacks = 0.0;  ///< wall time spent evaluating f, ∇f, ∇²f, c
  ProblemScales scales;               ///< the scaling used (see the file comment)
};

/// Solves min f(x) s.t. A x + b ≥ 0 from x0 (size problem.num_variables()). `multipliers0` (size m,
/// μ ≥ 0 convention) and `bound_multipliers0` (size n, z ≥ 0 of the lower bounds) are only used when
/// options.warm_start is true. The problem is evaluated at x0 before IPOPT starts (gradient and
/// Hessian, for the scaling and the Hessian pattern).
IpoptResult solve_with_ipopt(ConstrainedProblem& problem, const VectorXd& x0, const IpoptOptions& options,
                             const VectorXd* multipliers0 = nullptr, const VectorXd* bound_multipliers0 = nullptr);

}  // namespace symcontact
