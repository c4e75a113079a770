#pragma once
/// \file contact_surface.hpp
/// A candidate contact surface Γ_C: the facets of one named boundary group of a body (or of a rigid
/// meshed obstacle, which has no DOFs), with its own compact node numbering.
///
/// Layout: surface node k is node `nodes[k]` of its body; `facets` holds num_facets × npf surface-node
/// indices, each facet oriented so that its normal points out of the body (Mesh::locate_facets()).
/// 2D facets are Line2/Line3, 3D facets Tri3/Tri6.

#include <string>
#include <vector>

#include "symcontact/core/types.hpp"
#include "symcontact/fem/dof_map.hpp"
#include "symcontact/mesh/mesh.hpp"

namespace symcontact {

struct ContactSurface {
  std::string name;             ///< "<body>.<group>", used in messages and output
  int body = -1;                ///< DOF owner in the DofMap; −1 for a rigid surface (no DOFs)
  int dim = 2;
  CellType facet_type = CellType::kLine2;
  std::vector<Index> nodes;     ///< surface node → body node
  std::vector<Index> facets;    ///< num_facets × npf surface-node indices
  Eigen::MatrixXd X;            ///< dim × num_nodes reference coordinates
  /// Number of facets that share each surface node as a vertex (0 for edge-midpoint nodes). In 2D a
  /// vertex of valence 1 is an end of the surface: projections past it find no contact.
  std::vector<int> valence;
  Eigen::VectorXd nodal_area;   ///< ∫_Γ N_k dS in the reference configuration (lumped area)

  int nodes_per_facet() const { return cell_num_nodes(facet_type); }
  Index num_facets() const { return static_cast<Index>(facets.size()) / nodes_per_facet(); }
  Index num_nodes() const { return static_cast<Index>(nodes.size()); }
  const Index* facet(Index f) const { return facets.data() + f * nodes_per_facet(); }
  bool is_rigid() const { return body < 0; }
};

/// The surface of facet group `group` of `mesh`, owned by `body` (−1: rigid). Throws
/// std::out_of_range if the group does not exist (the caller turns it into an InputError with its key).
ContactSurface make_contact_surface(const Mesh& mesh, const std::string& group, int body, const std::string& name);

/// Current positions x = X + u of the surface nodes (dim × num_nodes); X for a rigid surface.
Eigen::MatrixXd current_positions(const ContactSurface& s, const DofMap& dofs, const VectorXd& u);

/// Smoothed nodal normals (dim × num_nodes, unit): at every node the outward normals of the facets
/// around it, evaluated at the node and weighted by the local surface Jacobian, summed and normalised
/// (the averaged-normal field of Yang, Laursen and Meng 2005, §2.2, interpolated by the shape functions).
Eigen::MatrixXd nodal_normals(const ContactSurface& s, const Eigen::MatrixXd& x);

/// Unnormalised outward normal of facet geometry `xf` (dim × npf) at reference point ξ; its norm is the
/// surface Jacobian dS/dξ. In 2D, for a facet traversed with the body on its left, n = (t_y, −t_x).
Eigen::VectorXd facet_normal(CellType type, const Eigen::MatrixXd& xf, const double* xi);

}  // namespace symcontact
