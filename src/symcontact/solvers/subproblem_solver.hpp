#pragma once
/// \file subproblem_solver.hpp
/// The choice of the method that solves each geometry iteration's subproblem (subproblem.hpp), and its names
/// in the problem file ([contact_solver] subproblem_solver, docs/input.md).

#include <memory>
#include <optional>
#include <string>

namespace symcontact {

class ContactSet;
class DualIpopt;
class PrimalIpopt;

/// How the subproblem of each geometry iteration is solved (subproblem.hpp). Every choice gives the same
/// solution to the optimiser's tolerance; only the cost changes. The dual applies to a condensed problem
/// without friction terms; any other subproblem is solved by the primal whatever the choice: with the
/// "interior_point" choices a condensed one with independent rows (no symmetric pair, no self-contact; in 2D
/// any rows: pairs_on_dense_primal()) by the dense primal interior point of dense_primal_interior_point.hpp
/// (one LAPACK Cholesky of the |B| × |B| normal matrix per iteration; IpoptOptions::tolerance, or [ipopt] tol,
/// is its tolerance), by IPOPT where that fails, where the problem is not condensed and where the rows are
/// not independent in 3D; with the "ipopt" choices by IPOPT.
enum class SubproblemSolver {
  /// IPOPT on the condensed (or whole) displacements, with m inequalities and a dense |B| × |B| KKT
  /// factorisation at each of its iterations (primal_subproblem.hpp), or where that costs more, with friction,
  /// on the uncondensed problem's sparse one (IpoptProblem).
  kPrimalIpopt,
  /// The dual in the m contact multipliers with bounds, its Hessian formed once per geometry iteration, by
  /// IPOPT (MUMPS factorising the dense matrix as a sparse one: about 3 times the time of the interior point
  /// and 10 m² doubles of workspace); the displacements follow exactly from the multipliers, forces balanced
  /// with no optimiser error (dual_subproblem.hpp). Falls back to the primal when IPOPT fails.
  kDualIpopt,
  /// The dual by the dense interior point of dense_qp_interior_point.hpp (one LAPACK Cholesky of the m × m
  /// matrix per iteration; IpoptOptions::tolerance, or [ipopt] tol, is its tolerance too), on every contact
  /// kind: the dual is a convex QP whatever the rows, and on a symmetric pair or a self-contact, whose nearly
  /// dependent rows leave λ not unique, the barrier keeps its Newton matrix definite and the interior point
  /// ends at a point of the optimal face (the displacements are unique); by IPOPT where it fails.
  /// Subproblems with friction terms: the dense primal interior point (above).
  kDualInteriorPoint,
  /// Every subproblem on the primal, by the dense primal interior point where it applies (above).
  kPrimalInteriorPoint,
};

/// The problem file's name of a choice: "primal_ipopt", "dual_ipopt", "dual_interior_point",
/// "primal_interior_point".
inline const char* subproblem_solver_name(SubproblemSolver s) {
  switch (s) {
    case SubproblemSolver::kPrimalIpopt:
      return "primal_ipopt";
    case SubproblemSolver::kDualIpopt:
      return "dual_ipopt";
    case SubproblemSolver::kDualInteriorPoint:
      return "dual_interior_point";
    case SubproblemSolver::kPrimalInteriorPoint:
      return "primal_interior_point";
  }
  return "";
}

/// The choice named `name` in the problem file; nullopt for any other string. (Inline, as the name above:
/// the problem reader calls them without linking the solver.)
inline std::optional<SubproblemSolver> parse_subproblem_solver(const std::string& name) {
  for (const SubproblemSolver s : {SubproblemSolver::kPrimalIpopt, SubproblemSolver::kDualIpopt,
                                   SubproblemSolver::kDualInteriorPoint, SubproblemSolver::kPrimalInteriorPoint})
    if (name == subproblem_solver_name(s)) return s;
  return std::nullopt;
}

/// How the dense interior points' subproblems start where the previous solution's multipliers are at hand (a
/// later geometry iteration, Coulomb iteration or load step on the same rows).
enum class WarmStart {
  /// First the primal-dual active set strategy from the previous solution's active set (the primal:
  /// active_set_start.hpp; the dual: its closing, dual_subproblem.hpp), the interior point where it fails:
  /// between load steps the set changes little, and Newton on it costs one or a few factorisations where the
  /// interior point takes 10–25.
  kActiveSet,
  /// The interior point from the previous solution and its multipliers (to compare).
  kInteriorPoint,
};

/// The problem file's name of a warm start: "active_set", "interior_point".
inline const char* warm_start_name(WarmStart w) { return w == WarmStart::kActiveSet ? "active_set" : "interior_point"; }

/// The warm start named `name` in the problem file; nullopt for any other string.
inline std::optional<WarmStart> parse_warm_start(const std::string& name) {
  for (const WarmStart w : {WarmStart::kActiveSet, WarmStart::kInteriorPoint})
    if (name == warm_start_name(w)) return w;
  return std::nullopt;
}

/// Which form of a condensed subproblem IPOPT optimises where it solves the primal (symmetric pairs and
/// self-contact, or subproblem_solver = "primal_ipopt", with friction terms on linear-elastic bodies). The polish
/// closes the condensed problem either way (a dense range-space solve on B).
enum class IpoptProblem {
  /// By the cost rule (condensation_cache.hpp, kOptimiserSparseAboveFlops): the uncondensed one, with a sparse
  /// KKT system, once the dense factorisation on B costs more than kDenseOverSparse sparse ones of K_ff.
  kAutomatic,
  /// The condensed one, a dense |B| × |B| KKT block at each iteration.
  kCondensed,
  /// The uncondensed one, whatever the cost (to compare).
  kUncondensed,
};

/// The problem file's name of an IpoptProblem: "automatic", "condensed", "uncondensed".
inline const char* ipopt_problem_name(IpoptProblem p) {
  return p == IpoptProblem::kAutomatic ? "automatic" : p == IpoptProblem::kCondensed ? "condensed" : "uncondensed";
}

/// The IpoptProblem named `name` in the problem file; nullopt for any other string.
inline std::optional<IpoptProblem> parse_ipopt_problem(const std::string& name) {
  for (const IpoptProblem p : {IpoptProblem::kAutomatic, IpoptProblem::kCondensed, IpoptProblem::kUncondensed})
    if (name == ipopt_problem_name(p)) return p;
  return std::nullopt;
}

/// Whether the constraint rows of `contacts` are independent (obstacles and one-pass pairs: no symmetric pair,
/// no self-contact), so that the multipliers are unique.
bool independent_rows(const ContactSet& contacts);

/// The dual method of a solve under `choice` (dual_subproblem.hpp): the dense interior point for
/// "dual_interior_point", IPOPT on the dual for "dual_ipopt"; null for the primal choices. `warm`: whether the
/// dense interior point's subproblems first close the previous solution's active set.
std::unique_ptr<DualIpopt> dual_method(SubproblemSolver choice, WarmStart warm);

/// Whether the primal subproblems of a solve under `choice` go to the dense primal interior point first (the
/// "interior_point" choices, rows independent); primal_method() gives it then.
bool dense_primal_first(const ContactSet& contacts, SubproblemSolver choice);

/// Whether, under `choice`, the condensed primal subproblems of the symmetric pairs and self-contact of a
/// `dim`-dimensional problem go to the dense primal interior point (PrimalForms::kCondensedOnly), the Coulomb
/// thresholds following its iterates: in 2D, where the contact curves keep B small and every subproblem
/// condensed (the 2D clamped plates: 4 solves for the 4 steps where IPOPT, thresholds updated between solves,
/// took 14–21; docs/performance.md). In 3D the cost rule gives the clamped plates' subproblems to IPOPT on the
/// uncondensed problem from 4e3 DOFs, where thresholds that follow would cost IPOPT its inexact solves (1.5
/// times the time at 1e4 DOFs): they stay with IPOPT.
bool pairs_on_dense_primal(const ContactSet& contacts, int dim, SubproblemSolver choice);

/// Whether primal_method() gives the dense primal interior point for some subproblems of a run: dense_primal_first()
/// or pairs_on_dense_primal(). Where it does, its Newton steps take the primal-dual friction curvature and the
/// Coulomb thresholds may follow its iterates.
bool primal_interior_point_first(const ContactSet& contacts, int dim, SubproblemSolver choice);

/// The primal method of a solve under `choice` (primal_subproblem.hpp): with the "interior_point" choices the
/// dense interior point first where the rows are independent, on the condensed problem only where
/// pairs_on_dense_primal(), IPOPT where it fails; IPOPT otherwise (the active-set Newton on the uncondensed
/// problem cannot close the nearly dependent rows of a symmetric pair: PrimalForms).
/// `warm`: how the dense interior point starts where it has the previous solution's multipliers.
std::unique_ptr<PrimalIpopt> primal_method(const ContactSet& contacts, int dim, SubproblemSolver choice,
                                           WarmStart warm);

}  // namespace symcontact
