#pragma once
/// \file stress_recovery.hpp
/// Strain, stress and volume ratio of a body from its displacement, for output.
///  - cell values: the average over the cell's quadrature points (exact for P1);
///  - nodal values: at each node, the average of the cells' values evaluated at that node, weighted by
///    cell measure (a simple, local recovery; contact tractions are never taken from these).
/// Tensors are 6 components in ParaView's order XX, YY, ZZ, XY, YZ, XZ. In 2D the strain is the in-plane
/// strain (ε_zz reported as 0) and σ_zz follows the model (λ tr ε in plane strain, 0 in plane stress).
/// Axisymmetric: XX, YY, ZZ, XY are rr, zz, θθ, rz, and H has H_θθ = u_r / R at (2, 2) (on the axis, R = 0,
/// its limit ∂u_r/∂r, u_r being 0 there by symmetry).
///
/// What is reported at a point comes from a PointLaw, evaluated on the displacement gradient H = ∇_X u
/// (3 × 3, zero third row and column in 2D):
///  - linear elasticity: ε = sym H, σ = C : ε;
///  - hyperelasticity (finite strain): the Green–Lagrange strain E = ½(FᵀF − I) and the Cauchy stress
///    σ = J⁻¹ P Fᵀ, P the first Piola–Kirchhoff stress of the law at F = I + H (F₃₃ = 1 in plane strain,
///    so σ_zz is the out-of-plane stress of the 3D law; Bonet & Wood 2008, eq. 5.43).
/// J = det F in both cases (for linear bodies a measure of how far from small strain they are).
/// Fields are on the reference mesh; the deformed shape is X + displacement (ParaView: Warp By Vector).
/// A point where the law cannot be evaluated (J ≤ 0, as in a failed iterate) reports zero stress; its
/// J ≤ 0 marks it (VTU files cannot hold NaN).
#include <functional>
#include <vector>

#include "symcontact/fem/dof_map.hpp"
#include "symcontact/materials/hyperelastic.hpp"
#include "symcontact/materials/linear_elastic.hpp"
#include "symcontact/mesh/mesh.hpp"
#include "symcontact/model/model.hpp"

namespace symcontact {

struct BodyFields {
  Eigen::MatrixXd displacement;   ///< 3 × num_nodes (z = 0 in 2D)
  Eigen::MatrixXd strain;         ///< 6 × num_nodes
  Eigen::MatrixXd stress;         ///< 6 × num_nodes
  Eigen::VectorXd von_mises;      ///< num_nodes
  Eigen::MatrixXd cell_stress;    ///< 6 × num_cells
  Eigen::VectorXd cell_von_mises; ///< num_cells
  Eigen::VectorXd volume_ratio;   ///< J = det F per node
  Eigen::VectorXd cell_volume_ratio; ///< J per cell
};

/// Strain, stress and J at a point.
struct PointState {
  Eigen::Matrix3d strain = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d stress = Eigen::Matrix3d::Zero();
  double volume_ratio = 1.0;
};
/// The material's output at a point, from H = ∇_X u (3 × 3; dim = 2: zero third row and column).
using PointLaw = std::function<PointState(const Eigen::Matrix3d& H)>;

PointLaw linear_point_law(const LinearElastic& material);
/// Plane strain is the 3D law with F₃₃ = 1, which H's zero third row and column give.
PointLaw hyperelastic_point_law(const Hyperelastic& material);

BodyFields recover_fields(const Mesh& mesh, const DofMap& dofs, int body, const PointLaw& law, const VectorXd& u);
/// A body of several materials: cell c reports laws[cell_law[c]] (`laws` non-empty; `cell_law` empty, for
/// laws[0] everywhere, or one index per cell). A node on the interface of two materials averages the
/// stresses of the cells around it, whatever their law (the nodal stress jumps there; the cell values do not
/// mix).
BodyFields recover_fields(const Mesh& mesh, const DofMap& dofs, int body, const std::vector<PointLaw>& laws,
                          const std::vector<int>& cell_law, const VectorXd& u,
                          AnalysisModel model = AnalysisModel::kPlaneStrain);
/// The linear-elastic case (ε, σ = C : ε).
BodyFields recover_fields(const Mesh& mesh, const DofMap& dofs, int body, const LinearElastic& material,
                          const VectorXd& u);

/// The fields of body `b` of a model: each cell with the law of its material (Body::cell_material), the
/// finite-strain law for a hyperelastic body, the small-strain one otherwise.
BodyFields recover_fields(const Body& body, const DofMap& dofs, int b, const VectorXd& u);

/// Packs a symmetric 3 × 3 tensor into ParaView's 6-component order.
Eigen::Matrix<double, 6, 1> to_voigt6(const Eigen::Matrix3d& t);

}  // namespace symcontact
