#pragma once
/// \file mesh_topology.hpp
/// Whole-body checks of a mesh's connectivity, run on every body read from a file (extract_body() in
/// gmsh_io.hpp) after Mesh::check():
///
/// - **Coincident nodes**: two nodes at the same position that share no cell cut the body there (a
///   crack: the cells on either side do not hold together), typically two surfaces meshed separately
///   and not merged. Positions count as equal within `relative_tolerance` × the diagonal of the
///   body's bounding box. Such a pair is allowed when the problem declares the cut's faces in contact:
///   a self-contact of the body (TopologyAllowances::self_contacts) with one node on each side of it.
/// - **Connected components**: cells are connected when they share a node. A body in several pieces
///   is allowed when every piece is held: it has a node on one of the body's contact surfaces or
///   Dirichlet boundaries (TopologyAllowances). Whether that holds the piece against every rigid
///   motion is not checked here (a piece touching the rest only through a frictionless contact can
///   still slide along it); the solve then fails and says so.
///
/// Both use the node labels of Mesh::node_label() (the mesh file's node tags) in messages.

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "symcontact/mesh/mesh.hpp"

namespace symcontact {

/// What a body's problem declares that lets check_topology() accept a mesh that is cut or in pieces. A
/// group named here that the mesh lacks is ignored (its absence is reported where the group is used).
struct TopologyAllowances {
  std::string body;  ///< the body's name, for messages
  /// Pairs of the body's boundary groups declared in contact with each other (a [[contact]] whose a and b
  /// both name this body; (g, g) for a surface in contact with itself).
  std::vector<std::pair<std::string, std::string>> self_contacts;
  std::vector<std::string> contact_surfaces;      ///< the body's boundary groups in any [[contact]]
  std::vector<std::string> dirichlet_boundaries;  ///< the groups of the body's [[body.dirichlet]]
};

/// Number of connected components of the cells (two cells are connected when they share a node). If
/// `component` is given it gets, for each cell, the index of its component, components numbered in
/// the order of their first cell. O(cells × nodes per cell) (union-find).
Index cell_components(const Mesh& m, std::vector<Index>* component = nullptr);

/// The nodes of a mesh in a hash grid of cells of size relative_tolerance × the bounding-box diagonal: the
/// nodes within that distance of a point lie in its cell or the neighbouring ones. O(1) expected per query,
/// whatever the layout (a sweep along one axis would be quadratic on structured meshes).
class NodeGrid {
 public:
  explicit NodeGrid(const Mesh& m, double relative_tolerance = 1e-10);
  /// Appends to `out` (not cleared) the nodes within the tolerance of y (m.dim entries).
  void near(const Eigen::VectorXd& y, std::vector<Index>& out) const;
  /// A node within the tolerance of y, or −1.
  Index at(const Eigen::VectorXd& y) const;

 private:
  using Key = std::array<std::int64_t, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const;
  };
  Key key_of(const Eigen::VectorXd& y) const;
  const Mesh& m_;
  double tol_, cell_;
  Eigen::VectorXd lo_;
  std::unordered_map<Key, std::vector<Index>, KeyHash> grid_;
};

/// Pairs (a, b), a < b, of nodes at the same position (distance ≤ relative_tolerance × bounding-box
/// diagonal) that belong to no common cell, sorted. A hash grid of that cell size: O(n) expected.
std::vector<std::pair<Index, Index>> coincident_nodes(const Mesh& m, double relative_tolerance = 1e-10);

/// Throws InputError(file = "", key = "", message) when the body has coincident nodes sharing no cell that
/// no self-contact of `allow` covers (a pair is covered by a pair of groups (g, h) when one node lies on g
/// and the other on h; the message names up to three refused pairs by their node labels, with the
/// position, the number of such pairs, and the body's self-contact surfaces), or more than one connected
/// component with one of them held by no group of `allow` (the message gives the count and, for each
/// component, its number of cells and one of its elements, then the pieces held by nothing). Each message
/// says what would make the mesh allowed.
void check_topology(const Mesh& m, const TopologyAllowances& allow = {});

/// Throws InputError(file = "", key = cell_label(), message) when two cells that share a facet (an edge in 2D,
/// a face in 3D) lie on the same side of it (the centroids of their vertices off the facet on the same side
/// of the line or plane through its first sorted vertices): the mesh folds over itself there, whatever the orientation convention of the file. Run on the
/// cells as read, before Mesh::orient_cells(), so that the message can name the cell whose orientation
/// (sign of simplex_determinant()) differs from the majority of the body's cells — the folded one; a mesh
/// with every cell of one sign, or a region of the other sign bounded by no fold (another surface meshed
/// the other way round), passes. Vertices only (edge and face nodes of quadratic cells are not examined).
/// O(cells) expected (hash of facets).
void check_folds(const Mesh& m);

}  // namespace symcontact
