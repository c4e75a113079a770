#pragma once
/// \file contact_surface.hpp
/// A candidate contact surface Γ_C: the facets of one named boundary group of a body (or of a rigid
/// meshed obstacle, which has no DOFs), with its own compact node numbering.
///
/// Layout: surface node k is node `nodes[k]` of its body; `facets` holds num_facets × npf surface-node
/// indices, each facet oriented so that its normal points out of the body (Mesh::locate_facets()).
/// 2D facets are Line2/Line3, 3D facets Tri3/Tri6 or Quad4/Quad8/Quad9 (the faces of Hex8/Hex20/Hex27 cells).

#include <string>
#include <vector>

#include "symcontact/core/types.hpp"
#include "symcontact/fem/analysis_model.hpp"
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
  /// 2D only (empty in 3D): 1 for the vertex nodes where the surface has a corner: two facets meet there
  /// whose outward unit normals at the node, in the reference configuration, differ by more than
  /// kCornerAngleDegrees (the 90° corner of a block; not a faceted curve, whose facets turn by a few
  /// degrees per node). At a corner the averaged nodal normal (nodal_normals()) is wrong for both facets
  /// (45° off for a right angle), so the master side of the contact search treats the node as a vertex
  /// instead: each facet keeps its own normal up to the corner, and a point whose closest point is the
  /// corner itself takes the normal of the normal cone nearest to the opposite surface's (contact_points.hpp).
  std::vector<char> corner;
  /// 3D only (empty in 2D): num_facets × facet_num_edges() flags, 1 when edge e of facet f (closest_point.hpp
  /// numbering)
  /// belongs to no other facet of the surface. Such edges form the border of the surface, the 3D
  /// analogue of the 2D ends: a projection clamped onto a border edge, or onto a vertex of one, is past
  /// the end of the surface and finds no contact (boundary_vertex).
  std::vector<char> boundary_edge;
  /// 3D only (empty in 2D): 1 for the surface nodes that are vertices of a border edge.
  std::vector<char> boundary_vertex;
  /// kAxisymmetric: the surface is the (r, z) trace of a surface of revolution, and every integral over it
  /// has dS = 2π r ds (surface_measure(); analysis_model.hpp). Any other model: dS as the facets give it.
  AnalysisModel model = AnalysisModel::kPlaneStrain;
  /// ∫_Γ φ_k dS in the reference configuration (lumped area), φ_k the test functions of the gap
  /// constraints (test_functions(): the shape functions, except on Tri6 and Quad8 facets).
  Eigen::VectorXd nodal_area;
  /// Mean facet_size() of the facets that contain each surface node (reference configuration).
  Eigen::VectorXd nodal_size;

  int nodes_per_facet() const { return cell_num_nodes(facet_type); }
  Index num_facets() const { return static_cast<Index>(facets.size()) / nodes_per_facet(); }
  Index num_nodes() const { return static_cast<Index>(nodes.size()); }
  const Index* facet(Index f) const { return facets.data() + f * nodes_per_facet(); }
  bool is_rigid() const { return body < 0; }
};

/// Facet-normal angle above which a 2D surface node is a corner (ContactSurface::corner). 45°: a right
/// angle (90°) is a corner; a circle meshed with at least 8 facets (≤ 45° per node) is not.
constexpr double kCornerAngleDegrees = 45.0;

/// The surface of facet group `group` of `mesh`, owned by `body` (−1: rigid). Throws
/// std::out_of_range if the group does not exist (the caller turns it into an InputError with its key).
ContactSurface make_contact_surface(const Mesh& mesh, const std::string& group, int body, const std::string& name,
                                    AnalysisModel model = AnalysisModel::kPlaneStrain);

/// Size of facet f of s: the largest distance between two of its vertices (reference configuration).
double facet_size(const ContactSurface& s, Index f);

/// Current positions x = X + u of the surface nodes (dim × num_nodes); X for a rigid surface.
Eigen::MatrixXd current_positions(const ContactSurface& s, const DofMap& dofs, const VectorXd& u);

/// Lumped areas ∫_Γ φ_k dS (num_nodes) of the surface with node positions `x` (dim × num_nodes), φ_k the test
/// functions (test_functions()): ContactSurface::nodal_area for x = X, the current ones for x = X + u.
Eigen::VectorXd lumped_areas(const ContactSurface& s, const Eigen::MatrixXd& x);

/// Smoothed nodal normals (dim × num_nodes, unit): at every node the outward normals of the facets
/// around it, evaluated at the node and weighted by the local surface Jacobian, summed and normalised
/// (the averaged-normal field of Yang, Laursen and Meng 2005, §2.2, interpolated by the shape functions).
Eigen::MatrixXd nodal_normals(const ContactSurface& s, const Eigen::MatrixXd& x);

/// Weights of the weak gap constraints on one facet (φ_a in gap_constraints.hpp), at reference point ξ.
/// They are the trace shape functions N_a, except on Tri6 facets, whose vertex functions integrate to
/// zero over a flat facet (so weak gaps tested with them carry no information, and their lumped areas
/// vanish). There a modified quadratic basis is used, of the kind introduced for quadratic mortar
/// contact by Puso, Laursen & Solberg (CMAME 197, 2008, "A segment-to-segment mortar contact method for
/// quadratic elements and large deformations") and used by Popp, Gee & Wall (SIAM J. Sci. Comput. 34,
/// 2012, "Dual quadratic mortar finite element methods for 3D finite deformation contact"):
///   φ_v = N_v + c (N_e + N_e'),  e, e' the two edges at vertex v;   φ_e = (1 − 2c) N_e,   c = 1/5.
/// For any c it still sums to one and is still quadratic; on a flat facet of area A it integrates to
/// ∫ φ_v = 2cA/3 = 2A/15 and ∫ φ_e = (1 − 2c)A/3 = A/5, all positive for 0 < c < 1/2 (checked in
/// tests/unit/contact/test_contact_surface.cpp). Geometry and displacements keep the standard N.
/// Quad8 (serendipity) facets have the same defect, worse: their vertex functions integrate to −A/12 on a
/// flat facet; the same modification with the same c, each vertex between its two edges, gives
/// ∫ φ_v = −A/12 + 2cA/3 = A/20 and ∫ φ_e = (1 − 2c)A/3 = A/5.
///
/// Axisymmetric Line3 facets have the defect too, where the surface meets the axis: a vertex at r = 0
/// has ∫ N_v 2πr ds = 2πh² ∫₀¹ (1 − ξ)(1 − 2ξ) ξ dξ = 0, so its lumped area and its gap row vanish (the
/// row's coefficients sum to zero: it would constrain a curvature of the gap, not the gap). The same
/// modification, the segment being one edge, gives it ∫ φ_v 2πr ds = 2πc h²/3 > 0; an axisymmetric
/// surface of Line3 facets uses it on every facet (test_functions(const ContactSurface&, …)).
void test_functions(CellType type, const double* xi, double* phi);
/// The test functions of surface s: those of its facet type, and the modified basis on the Line3 facets of
/// an axisymmetric surface.
void test_functions(const ContactSurface& s, const double* xi, double* phi);

/// Whether test_functions() modifies the shape functions of facets of type t (Tri6, Quad8).
bool has_modified_test_basis(CellType t);
/// Whether the test functions of surface s are modified: its facets are Tri6 or Quad8, or it is an
/// axisymmetric surface of Line3 facets.
bool has_modified_test_basis(const ContactSurface& s);

/// The edges of a facet type that carry an edge node in the modified test basis: a Line3 segment is one
/// edge, a Tri6 or Quad8 facet has facet_num_edges(); edge e has the local vertices basis_edge(t, e) and
/// the edge node cell_num_vertices(t) + e.
int basis_num_edges(CellType t);
const int* basis_edge(CellType t, int e);

/// The coefficient c of the modified Tri6 and Quad8 test basis (test_functions()).
constexpr double kModifiedTri6Coefficient = 0.2;

/// Nodal forces F (dim × n, F_k = ∫ t N_k dS for a traction t) turned into the test basis:
/// (T F)_i = ∫ t φ_i dS, with φ_i = Σ_k T_ik N_k (test_functions()). The identity except where
/// has_modified_test_basis(s) (Tri6 and Quad8 surfaces, axisymmetric Line3 ones),
/// where (T F)_v = F_v + c Σ_{edge nodes e next to v} F_e and (T F)_e = (1 − 2c) F_e. Dividing by the lumped
/// area nodal_area[i] = ∫ φ_i dS then gives back a uniform traction exactly.
Eigen::MatrixXd test_basis_forces(const ContactSurface& s, const Eigen::MatrixXd& F);

/// Unnormalised outward normal of facet geometry `xf` (dim × npf) at reference point ξ; its norm is the
/// surface Jacobian dS/dξ. In 2D, for a facet traversed with the body on its left, n = (t_y, −t_x).
Eigen::VectorXd facet_normal(CellType type, const Eigen::MatrixXd& xf, const double* xi);

/// The surface element of s at reference point xi of a facet with nodes xf (dim × npf): |facet_normal()|,
/// times 2π r(xi) when s.model is axisymmetric (dS = 2π r ds).
double surface_measure(const ContactSurface& s, const Eigen::MatrixXd& xf, const double* xi);

/// 2D: the outward unit normals of the two facets at each vertex node for node positions `x` (dim × n),
/// 4 × num_nodes: rows 0–1 of the facet that ends at the node (its local node 1), rows 2–3 of the one that
/// starts there (local node 0); zero where there is no such facet. Used for corners (ContactSurface::corner)
/// in the reference configuration and by the contact search in the current one.
Eigen::MatrixXd facet_end_normals(const ContactSurface& s, const Eigen::MatrixXd& x);

}  // namespace symcontact
