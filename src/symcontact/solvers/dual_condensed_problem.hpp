#pragma once
/// \file dual_condensed_problem.hpp
/// The Lagrangian dual of a frictionless condensed contact problem: a problem in the contact multipliers
/// alone, whose size is the number of constraint rows m instead of the condensed DOFs |B| (about 2m for a
/// symmetric pair), with simple bounds instead of general inequalities, and whose Hessian is formed once per
/// geometry iteration instead of being factorised by IPOPT at every one of its iterations.
///
/// Primal (condensed_problem.hpp, no friction term): S = K_BB − K_BI K_II⁻¹ K_IB positive SEMIdefinite —
/// its null space N (n × k, semidefinite_factor.hpp) holds the rigid motions of the bodies that only the
/// contact holds (the upper cylinder of the Hertz pair slides vertically without it):
///     min_y  ½ yᵀS y + ĝᵀy   subject to   A y + b ≥ 0.
/// Its Lagrangian ½yᵀSy + ĝᵀy − λᵀ(Ay + b) is bounded below in y only if Nᵀ(Aᵀλ − ĝ) = 0 (the contact forces
/// balance the loads along every rigid motion); then y = S⁺(Aᵀλ − ĝ) + N α and the dual is (Dorn 1960; the
/// FETI form with a rigid-body equality: Dostál, Optimal Quadratic Programming Algorithms, 2009, §8.3)
///     min_λ  ½ λᵀW λ − dᵀλ   subject to   λ ≥ 0,   G λ = e,
///     W = A S⁺ Aᵀ,   d = A S⁺ ĝ − b,   G = (A N)ᵀ,   e = Nᵀ ĝ.
/// Its KKT conditions are W λ − d − Gᵀβ = z ≥ 0, z ⊥ λ; with α = −β the primal gaps are
///     A y + b = W λ − d + Gᵀ α = z,
/// so the bound multipliers z are the gaps, complementary to the contact multipliers λ, and the primal is
/// recovered exactly: y = S⁺(Aᵀλ − ĝ) − N β balances the forces for ANY λ (no optimiser error in it).
/// IPOPT's stationarity ∇f + Gᵀλ_ip − z = 0 gives β = −λ_ip, so α = λ_ip = −μ_eq in the μ = −λ_ip
/// convention of ipopt_solver.hpp (the unit tests check it against the primal solved by IPOPT).
///
/// Scaling: the rows of A are scaled to force units, λ_i = D_i λ̂_i with D_i = f_ref / max_j |A_ij|
/// (f_ref = ‖ĝ‖∞, or max|S|·max|b_i / max_j A_ij| without load), so that λ̂ is O(1) where the contact
/// carries the load and IPOPT's absolute bound pushes (1e-2) mean what they mean on a unit problem.
/// The problem's variables are λ̂; multipliers() and primal() convert.

#include <memory>
#include <string>
#include <vector>

#include "symcontact/optim/constrained_problem.hpp"
#include "symcontact/solvers/dense_kkt.hpp"
#include "symcontact/solvers/dense_qp_interior_point.hpp"
#include "symcontact/solvers/semidefinite_factor.hpp"

namespace symcontact {

class DualCondensedProblem : public ConstrainedProblem {
 public:
  /// `factor`: of S (must outlive the object); A (m × n), b: the condensed constraints; g_hat: ĝ (size n).
  /// Forms W, d, G, e: O(nnz(A) (n + m)) with the factor's explicit generalised inverse.
  DualCondensedProblem(const SemidefiniteFactor& factor, const SparseMatrix& A, const VectorXd& b,
                       const VectorXd& g_hat);

  Index num_variables() const override { return m_; }
  double objective(const VectorXd& lambda_hat) override;
  void gradient(const VectorXd& lambda_hat, VectorXd& g) override;
  void hessian_lower(const VectorXd& lambda_hat, SparseMatrix& H) override;
  bool hessian_is_constant() const override { return true; }
  bool hessian_is_dense() const override { return true; }
  const SparseMatrix& constraint_matrix() const override { return G_; }
  const VectorXd& constraint_offset() const override { return minus_e_; }
  Index num_equalities() const override { return G_.rows(); }
  const VectorXd* lower_bounds() const override { return &zero_; }

  /// The contact multipliers of the primal rows, λ = D λ̂ (negative entries, round-off of the bound,
  /// are set to zero).
  VectorXd multipliers(const VectorXd& lambda_hat) const;
  /// y = S⁺(Aᵀλ − ĝ) + N α with α = −μ_eq (`equality_multipliers`, IPOPT's result in the μ convention).
  VectorXd primal(const VectorXd& lambda_hat, const VectorXd& equality_multipliers) const;
  /// λ̂ = λ / D: multipliers of the primal rows in the problem's variables (a warm start).
  VectorXd scaled_multipliers(const VectorXd& lambda) const { return lambda.cwiseQuotient(D_); }
  /// The scaled primal gaps D (A y + b) for that y (what the bound multipliers should equal).
  VectorXd scaled_gaps(const VectorXd& y) const;

  Index num_rigid_modes() const { return G_.rows(); }

  /// The same problem solved by the dense interior point of dense_qp_interior_point.hpp instead of IPOPT
  /// (the default backend: dense Cholesky instead of MUMPS on a dense matrix). `lambda_hat0`, `gaps0` (both or
  /// neither) and `equality_multipliers0` start it (a warm start). The result's `beta` is in the convention of
  /// `equality_multipliers` (IPOPT's μ_eq: primal() and close_contact_set() take it), `z` the scaled gaps.
  DenseQpResult solve_interior_point(const DenseQpOptions& options, const VectorXd* lambda_hat0 = nullptr,
                                     const VectorXd* gaps0 = nullptr,
                                     const VectorXd* equality_multipliers0 = nullptr) const;

  /// The dual form of the active-set polish (active_set_polish.hpp does it on the primal): IPOPT leaves each
  /// closed contact open by its barrier offset μ_b/λ_i; with F the rows whose λ̂ > 1e-6 max λ̂, the
  /// equality problem λ_i = 0 off F, gap_i = 0 on F, G λ = e, i.e.
  ///     [W_FF  G_Fᵀ] [λ_F]   [d_F]
  ///     [G_F    0  ] [ α ] = [ e ],
  /// is solved in the least-squares minimum-norm sense (complete orthogonal decomposition: the two nearly
  /// dependent families of a symmetric pair make W_FF singular), rows with λ_i < 0 leave F and rows whose gap
  /// went negative join it, until F settles (Hintermüller, Ito & Kunisch, SIAM J. Optim. 13, 2003). Each round
  /// costs O(|F|³) on the m × m W, against a dense |B| × |B| factorisation and method-of-multipliers solves
  /// in the primal. Applied only when F settles, its gaps vanish (the set closes consistently: not so for the
  /// two families of a curved symmetric pair) to 1e-10 · max(f_ref ‖y‖∞, ‖d_F‖∞), λ ≥ 0 and no gap is negative
  /// beyond 1e-10 · f_ref ‖y‖∞; then `lambda_hat` and `equality_multipliers` are replaced. A set met before ends
  /// the rounds (they are a function of F alone: it would cycle).
  struct Closing {
    bool applied = false;
    int rounds = 0;
    Index active = 0;
    std::string reason;  ///< why it was not applied
  };
  /// `max_rounds` bounds the rounds (a start far from the answer gives up early instead of cycling).
  /// `rows`: kIndependent gives up on a set whose rows are nearly dependent (W_FF not definite), where the
  /// minimum-norm answer would pick one of many splits of the force between them.
  enum class Rows { kAny, kIndependent };
  Closing close_contact_set(VectorXd& lambda_hat, VectorXd& equality_multipliers, int max_rounds = 30,
                            Rows rows = Rows::kAny) const;
  /// A start of the closing without a previous solution: the rows the load alone would violate, by how much
  /// (λ̂ = max(d, 0): the scaled penetrations at λ = 0).
  VectorXd cold_start() const { return d_.cwiseMax(0.0); }
  /// Whether row i starts in the closing's set F: λ̂_i > 1e-6 max λ̂.
  static std::vector<char> closing_start_set(const VectorXd& lambda_hat);

 private:
  /// λ (size m, zero off F) and α solving the closing's system on the closed rows F (ascending),
  /// W_FF λ_F + G_Fᵀ α = d_F, G_F λ_F = e; `df_max` = ‖d_F‖∞. False where `rows` is kIndependent and W_FF is
  /// not definite.
  bool solve_closed_rows(const std::vector<Index>& F, Rows rows, VectorXd& lam, VectorXd& alpha,
                         double& df_max) const;

  const SemidefiniteFactor& factor_;
  Index m_ = 0;
  VectorXd D_;                       ///< row scales
  SparseMatrix A_scaled_;            ///< D A
  VectorXd b_scaled_;                ///< D b
  VectorXd s_g_;                     ///< S⁺ ĝ
  std::unique_ptr<AlignedMatrix> W_;  ///< Ã S⁺ Ãᵀ, lower triangle
  SparseMatrix W_lower_;             ///< the same as a (full) sparse lower triangle, for IPOPT (formed on first use)
  VectorXd d_;
  SparseMatrix G_;
  MatrixXd G_dense_;                 ///< G, k × m (k: the rigid modes, a few)
  VectorXd minus_e_;
  VectorXd zero_;
  double f_ref_ = 1.0;
};

}  // namespace symcontact
