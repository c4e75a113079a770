#pragma once
/// \file hyperelastic_energy.hpp
/// Total-Lagrangian strain energy of one hyperelastic body (talk eq. 6, METHOD.md "Bodies and energies"):
///   E(u) = Σ_cells ∫_{Ω_c} ψ(F) dX,  F = I + ∇_X u,
/// with ψ a pointwise law (materials/hyperelastic.hpp). Element kernel (per cell, quadrature point q,
/// G_a = ∇_X N_a, w_q = quadrature weight × det of the reference map):
///   E_e = Σ_q w_q ψ(F_q),  F_q = I + Σ_a u_a ⊗ G_a,
///   f_(a,i) = Σ_q w_q P_iJ G_aJ,
///   K_(a,i),(b,k) = Σ_q w_q A_iJkL G_aJ G_bL,  A = ∂P/∂F,
/// local DOF (a, i) at row D·a + i (node-major, as DofMap). Summed over J, L.
///
/// Axisymmetric (D = 2, x = r; analysis_model.hpp): F is the 3 × 3 gradient with the (r, z) block I + ∇_X u
/// and F_θθ = 1 + u_r / R (R the reference radius; Bonet & Wood 2008, §9.3 on axisymmetric kinematics),
/// ψ the 3D law, and every weight is multiplied by 2π R. With B the 9 × 2NN matrix of ∂F/∂u (column
/// (b, k): G_b in row k of the (r, z) block, and N_b / R at θθ for k = r):
///   f = Σ_q w_q Bᵀ vec P,  K = Σ_q w_q Bᵀ A B.
///
/// Quadrature: the same rule as LinearElasticEnergy — degree 0 (one point) for P1, where F is constant
/// on a cell so every integrand is exact; degree 3 = 2(p−1) + 1 for P2: ψ(F) is not a polynomial, but its
/// small-strain limit (the linear stiffness integrand, degree 2(p−1) = 2 on straight cells) is then
/// integrated exactly, one degree is left for the nonlinearity and curved cells, and the linearisation at
/// u = 0 is exactly the linear-elastic stiffness of the same mesh.
///
/// Errors: a reference element with det(∂X/∂ξ) ≤ 0 → InputError at construction (as the linear term);
/// a deformed state with det F ≤ 0 at a quadrature point → EvaluationError naming the body and the cell
/// (Mesh::cell_label), so that a solver can back away.

#include <string>
#include <vector>

#include "symcontact/energy/cell_materials.hpp"
#include "symcontact/energy/energy_term.hpp"
#include "symcontact/fem/dof_map.hpp"
#include "symcontact/fem/shape_functions.hpp"
#include "symcontact/fem/analysis_model.hpp"
#include "symcontact/materials/hyperelastic.hpp"
#include "symcontact/mesh/mesh.hpp"

namespace symcontact {

class HyperelasticEnergy : public EnergyTerm {
 public:
  /// `label` names the body in messages. The mesh must be 2D (plane strain, or axisymmetric when `model`
  /// says so) or 3D and outlive the term.
  HyperelasticEnergy(const Mesh& mesh, const DofMap& dofs, int body, const Hyperelastic& material,
                     std::string label, AnalysisModel model = AnalysisModel::kPlaneStrain);
  /// A body of several materials: cell c has the law materials[cell_material[c]] (`materials` non-empty;
  /// `cell_material` empty, for one law everywhere, or one index per cell).
  HyperelasticEnergy(const Mesh& mesh, const DofMap& dofs, int body, std::vector<Hyperelastic> materials,
                     std::vector<int> cell_material, std::string label,
                     AnalysisModel model = AnalysisModel::kPlaneStrain);
  std::string name() const override { return "hyperelastic(" + label_ + ")"; }
  double value(const VectorXd& u) const override;
  void add_gradient(const VectorXd& u, VectorXd& g) const override;
  void add_hessian(const VectorXd& u, MatrixSink& sink) const override;
  bool hessian_is_constant() const override { return false; }

 private:
  /// Runs the element kernel on every cell at state u, with what = 0 (value), 1 (+ gradient) or
  /// 2 (+ Hessian), and calls f(dofs, e, g_e, K_e) with the local results.
  template <int What, class F>
  void for_each_cell(const VectorXd& u, F&& f) const;

  const Mesh& mesh_;
  Index offset_;
  CellMaterials<Hyperelastic> materials_;
  std::string label_;
  AnalysisModel model_;
  std::vector<Tabulation> tabs_;  ///< one per cell block of the mesh
};

}  // namespace symcontact
