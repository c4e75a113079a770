#pragma once
/// \file stress_recovery.hpp
/// Strain and stress of a linear-elastic body from its displacement, for output.
///  - cell values: the average over the cell's quadrature points (exact for P1);
///  - nodal values: at each node, the average of the cells' values evaluated at that node, weighted by
///    cell measure (a simple, local recovery; contact tractions are never taken from these).
/// Tensors are 6 components in ParaView's order XX, YY, ZZ, XY, YZ, XZ. In 2D the strain is the in-plane
/// strain (ε_zz reported as 0) and σ_zz follows the model (λ tr ε in plane strain, 0 in plane stress).

#include "symcontact/fem/dof_map.hpp"
#include "symcontact/materials/linear_elastic.hpp"
#include "symcontact/mesh/mesh.hpp"

namespace symcontact {

struct BodyFields {
  Eigen::MatrixXd displacement;   ///< 3 × num_nodes (z = 0 in 2D)
  Eigen::MatrixXd strain;         ///< 6 × num_nodes
  Eigen::MatrixXd stress;         ///< 6 × num_nodes
  Eigen::VectorXd von_mises;      ///< num_nodes
  Eigen::MatrixXd cell_stress;    ///< 6 × num_cells
  Eigen::VectorXd cell_von_mises; ///< num_cells
};

BodyFields recover_fields(const Mesh& mesh, const DofMap& dofs, int body, const LinearElastic& material,
                          const VectorXd& u);

/// Packs a symmetric 3 × 3 tensor into ParaView's 6-component order.
Eigen::Matrix<double, 6, 1> to_voigt6(const Eigen::Matrix3d& t);

}  // namespace symcontact
