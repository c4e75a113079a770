#pragma once
/// \file dual_subproblem.hpp
/// The subproblem of a condensed quadratic problem (linear elasticity, no friction term) solved through its
/// dual in the contact multipliers (dual_condensed_problem.hpp): min ½λᵀWλ − dᵀλ, λ ≥ 0, Gλ = e, then the
/// active set closed exactly in the dual's own form, and the displacements y = S⁺(Aᵀλ − ĝ) − Nβ, which
/// balance the forces for any λ. Warm-started, from the second solve of a run on, from the previous rows'
/// multipliers, the gaps at the start point as the bounds' multipliers, and the previous rigid-motion
/// multipliers β. Where the answer is to be closed (DualInteriorPoint, with WarmStart::kActiveSet), the
/// previous solution's active set is closed first (also across load steps, where no rigid motion needs the
/// previous β), as the polish would close the optimiser's, the QP's KKT conditions checked the same way: a
/// few rounds of |F|³/3 instead of the interior point's iterations of m³/3, which run where it does not
/// close.
///  - DualIpopt: IPOPT (MUMPS factorising the dense W as a sparse matrix), warm then cold.
///  - DualInteriorPoint: the dense interior point (dense_qp_interior_point.hpp, a LAPACK Cholesky of the m × m
///    matrix per iteration, stopping at IPOPT's `tol`, complementarity at 1e-6 of it), warm then cold;
///    DualIpopt's attempts where it fails. With the nearly dependent families of a symmetric pair or a
///    self-contact the optimal λ form a face (the displacements are unique) and the interior point ends at
///    a point of it, from which the closing may find a smaller set or none: the interior point's answer,
///    within its tolerance, then stands.
/// A solution with `success` false asks the caller for the primal (the reference formulation).

#include <memory>

#include "symcontact/solvers/subproblem.hpp"
#include "symcontact/solvers/subproblem_solver.hpp"

namespace symcontact {

class DualCondensedProblem;

class DualIpopt : public SubproblemMethod {
 public:
  DualIpopt();
  ~DualIpopt() override;
  SubproblemSolution solve(const Subproblem& p, const SubproblemWarmStart& warm, const Logger& log,
                           PhaseTimes& times) override;

 protected:
  /// The state of the warm start a dual attempt starts from (all null: cold).
  struct DualStart {
    const VectorXd* lambda_hat = nullptr;  ///< scaled multipliers λ̂
    const VectorXd* gaps = nullptr;        ///< scaled gaps, the bounds' multipliers
    const VectorXd* equality = nullptr;    ///< rigid-motion multipliers
  };
  /// A first optimiser tried before IPOPT; true when it solved (res then holds its solution).
  virtual bool solve_first(const DualCondensedProblem& dual, const DualStart& start, const IpoptOptions& ipopt,
                           IpoptResult& res, SubproblemSolution& s, const Logger& log);
  /// Whether the previous solution's active set may be closed before any optimiser: the rows are independent,
  /// so that a set that closes gives the QP's unique answer.
  virtual bool closes_previous_set() const { return false; }

 private:
  /// An active set closed (DualCondensedProblem::close_contact_set) from `lambda_hat` (scaled; `equality`: of
  /// the rigid modes' size, its values not read): true and `res` its answer when it closes within a few rounds.
  /// From the previous solution's multipliers, or, with rows other than the previous solution's (the first
  /// solve of a run, a search that changed the rows), from the rows the load alone violates
  /// (DualCondensedProblem::cold_start), independent rows only: a whole face pressed flat closes in one round
  /// where the interior point takes 8–18 iterations.
  enum class SetStart { kPrevious, kCold };
  bool close_set(const DualCondensedProblem& dual, VectorXd lambda_hat, VectorXd equality, SetStart from,
                 IpoptResult& res, SubproblemSolution& s, const Logger& log) const;
  VectorXd equality_prev_;  ///< the rigid-motion multipliers of the last dual solved
  int solves_ = 0;          ///< dual solves attempted
};

class DualInteriorPoint : public DualIpopt {
 public:
  /// `warm`: kActiveSet closes the previous solution's set first; kInteriorPoint does not (to compare).
  explicit DualInteriorPoint(WarmStart warm = WarmStart::kActiveSet) : warm_(warm) {}

 protected:
  bool solve_first(const DualCondensedProblem& dual, const DualStart& start, const IpoptOptions& ipopt,
                   IpoptResult& res, SubproblemSolution& s, const Logger& log) override;
  bool closes_previous_set() const override { return warm_ == WarmStart::kActiveSet; }

 private:
  WarmStart warm_;
};

}  // namespace symcontact
