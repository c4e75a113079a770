#pragma once
/// \file condensed_problem.hpp
/// A contact problem with a quadratic bulk energy, condensed onto the DOFs its constraints and surface
/// terms touch (static condensation; see static_condensation.hpp for the factorisation).
///
/// On the free DOFs x (ReducedProblem), let the bodies' energy be quadratic,
///     E(x) = E₀ + r₀ᵀx + ½ xᵀK x,
/// and let the constraints A x + b ≥ 0 and the extra (surface) terms Φ(x) — friction — depend on x_B
/// only, B a small set of free DOFs. For given y = x_B the interior minimiser is
///     x_I(y) = −K_II⁻¹ (r₀_I + K_IB y),
/// and the problem becomes, exactly (no approximation),
///     min_y  F(y) = f₀ + ĝᵀy + ½ yᵀS y + Φ(y)   subject to   A_B y + b ≥ 0,
///     S = K_BB − K_BI K_II⁻¹ K_IB,   w = K_II⁻¹ r₀_I,   ĝ = r₀_B − K_BI w,   f₀ = E₀ − ½ r₀_Iᵀw.
/// Its KKT points are those of the full problem with x_I = x_I(y), multipliers unchanged: the interior
/// block of the full stationarity condition is what defines x_I(y).
/// One IPOPT iteration then factorises a |B|-sized KKT system instead of an n-sized one; the interior
/// costs one Cholesky factorisation for all iterations (and all load steps, K being constant) plus one
/// triangular solve pair per expand().
///
/// Contract: the extra terms must not depend on interior DOFs (the constructor does not check it;
/// support_of() below gives the DOF support to build B with). They are evaluated at a full vector whose
/// interior holds `x_reference`'s values. That vector is built once, in the constructor; a callback only
/// writes its |B| entries, and gathers the extras' gradient from their support (the DOFs of their Hessian
/// blocks at x_reference, as support_of() returns them), so that a callback costs O(|B| + support), not
/// O(n): the extras must not touch other DOFs at other points (true of the friction term, whose points and
/// facets are frozen by the geometry step).

#include <memory>
#include <vector>

#include "symcontact/energy/energy_term.hpp"
#include "symcontact/optim/constrained_problem.hpp"
#include "symcontact/solvers/reduced_problem.hpp"
#include "symcontact/solvers/static_condensation.hpp"

namespace symcontact {

/// The load part of the condensed energy: r₀, ĝ and f₀ (above). They depend on the Dirichlet values and the
/// loads, not on the constraints: computed once per contact solve (one interior solve), shared by the
/// condensed problems of its geometry iterations.
struct CondensedLoad {
  VectorXd r0;     ///< ∇E(0) on the free DOFs
  VectorXd g_hat;  ///< ĝ (B order)
  VectorXd w;      ///< K_II⁻¹ r₀_I, zero on B (the interior's response to the loads)
  double f0 = 0.0;
};
CondensedLoad condense_load(ReducedProblem& bulk, const StaticCondensation& condensation);

/// x_B: the entries of the free DOFs x at B, in B's order (CondensedProblem::restrict()).
VectorXd boundary_values(const StaticCondensation& condensation, const VectorXd& x);
/// x with x_B = y, the other entries as they are (CondensedProblem::with_boundary()).
VectorXd with_boundary_values(const StaticCondensation& condensation, VectorXd x, const VectorXd& y);
/// The free DOFs x with x_B = y and x_I = x_I(y) = −K_II⁻¹K_IB y − w (one backward solve with the factor,
/// StaticCondensation::boundary_response()): CondensedProblem::expand(), and the completion of an interior
/// left out of date (ContactSolveOptions::lazy_interior).
VectorXd expand_condensed(const StaticCondensation& condensation, const CondensedLoad& load, const VectorXd& y);

class CondensedProblem : public ConstrainedProblem {
 public:
  /// `bulk` is the ReducedProblem of the quadratic energy alone (for r₀, E₀ and the DOF maps);
  /// `condensation` holds K_ff and its factor with B = condensation.boundary() (free numbering);
  /// `extras` are the surface terms (may be empty); A, b the constraints on the free DOFs (columns
  /// outside B must be empty). All references must outlive the object.
  /// `load` must come from condense_load(bulk, condensation).
  CondensedProblem(ReducedProblem& bulk, const StaticCondensation& condensation,
                   std::shared_ptr<const CondensedLoad> load, std::vector<std::shared_ptr<const EnergyTerm>> extras,
                   const SparseMatrix& A, const VectorXd& b, const VectorXd& x_reference);

  Index num_variables() const override { return static_cast<Index>(sc_.boundary().size()); }
  double objective(const VectorXd& y) override;
  void gradient(const VectorXd& y, VectorXd& g) override;
  void hessian_lower(const VectorXd& y, SparseMatrix& H) override;
  void add_hessian_lower(const VectorXd& y, double s, Eigen::Ref<MatrixXd> M) override;  ///< S, then the extras
  void hessian_product(const VectorXd& y, const VectorXd& v, VectorXd& out) override;
  bool hessian_is_constant() const override { return extras_.empty(); }
  bool hessian_is_dense() const override { return true; }  ///< S = K_BB − K_BI K_II⁻¹ K_IB is full
  const SparseMatrix& constraint_matrix() const override { return A_; }
  const VectorXd& constraint_offset() const override { return b_; }

  const VectorXd& linear_term() const { return load_->g_hat; }  ///< ĝ
  const StaticCondensation& condensation() const { return sc_; }
  VectorXd restrict(const VectorXd& x) const;  ///< y = x_B
  VectorXd expand(const VectorXd& y) const;    ///< x with x_B = y and x_I = x_I(y) (one interior solve)
  /// x with its B entries replaced by y, the interior left as it is (no solve).
  VectorXd with_boundary(VectorXd x, const VectorXd& y) const;
  /// The full DOF vector u with x_B = y and the interior of x_reference (no solve): right on the surfaces.
  VectorXd surface_displacement(const VectorXd& y) const;
  /// The force on the DOFs of B that the multipliers λ balance at y, A_Bᵀλ − ∇Φ(y) (at a KKT point the bodies'
  /// force ∇E = ĝ + S y there), as a full DOF vector, zero off B.
  VectorXd surface_force(const VectorXd& y, const VectorXd& multipliers);

 private:
  const VectorXd& full_dofs(const VectorXd& y);  ///< u for the extras: x_reference with x_B = y, expanded
  void add_extras_gradient(const VectorXd& y, VectorXd& g);  ///< g += ∇Φ(y) (B order)

  ReducedProblem& bulk_;
  const StaticCondensation& sc_;
  std::vector<std::shared_ptr<const EnergyTerm>> extras_;
  std::shared_ptr<const CondensedLoad> load_;
  VectorXd x_ref_;          ///< interior values for the extras' evaluation
  SparseMatrix A_;          ///< A_B
  VectorXd b_;
  std::vector<Index> dof_to_b_;  ///< global DOF → position in B or −1 (for the extras' Hessians)
  std::vector<Index> b_dof_;     ///< position in B → global DOF
  std::vector<Index> support_;   ///< global DOFs the extras touch (sorted, unique)
  VectorXd u_;                   ///< full DOFs: expanded x_reference, B entries of the last callback
  VectorXd gu_;                  ///< full-size gradient buffer of the extras, zero outside a gradient() call
};

/// The global DOFs an energy term depends on: those of its Hessian blocks at u (an element-block
/// assembler adds a block for every DOF it reads, even where the values vanish).
std::vector<Index> support_of(const EnergyTerm& term, const VectorXd& u);

}  // namespace symcontact
