#pragma once
/// \file mesh.hpp
/// The mesh of one body: nodes, volume cells of one or more Lagrange types, and named groups of cells, of
/// boundary facets and of nodes (from Gmsh physical groups).
///
/// Layout: `x` is dim × num_nodes (column j = node j). `cells` holds the node indices of the cells, cell
/// after cell, in Gmsh node ordering (cell_type.hpp); cell c's are cells[cell_offsets[c]] up to
/// cells[cell_offsets[c + 1]]. `cell_blocks` cuts the cells into runs of one type, so that kernels
/// dispatch on the type once a block (a uniform mesh has one block). The types of a mesh share one order
/// and one facet type of each shape (triangles with quadrilaterals in 2D; in 3D tetrahedra, hexahedra,
/// prisms and pyramids, but not Hex20 with Hex27: compatible_cell_types()). Facet groups hold facets of one type each the same way
/// (FacetGroup::type). Every cell is positively oriented (det J > 0 at its vertices); mesh builders
/// reorient cells read with the other orientation.
/// A facet is keyed by its sorted vertex indices (std::array<Index, 4>, −1 for the entries a segment or
/// triangle lacks).

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "symcontact/core/types.hpp"
#include "symcontact/mesh/cell_type.hpp"

namespace symcontact {

/// A named set of boundary facets (a Gmsh physical curve in 2D, surface in 3D).
/// Sorted vertex indices of a facet, −1 after the last (two for a segment, three for a triangle, four for
/// a quadrilateral).
using FacetKey = std::array<Index, 4>;
/// Hash of a FacetKey, for unordered maps keyed by facets.
struct FacetKeyHash {
  std::size_t operator()(const FacetKey& k) const;
};
/// The key of the facet whose `num_vertices` vertices are v[0], v[1], ...
FacetKey facet_key(const Index* v, int num_vertices);

struct FacetGroup {
  std::vector<Index> facets;  ///< num_facets × nodes-per-facet node indices
  /// The facets' type; unset: the mesh's facet_cell_type() (any group of a mesh whose cells have one facet
  /// type). Set where the cells have facets of two types (prisms: triangles and quadrilaterals).
  std::optional<CellType> type;
  std::vector<Index> tags;    ///< element tag of each facet in its mesh file (empty: built in code)
  /// The cell each facet bounds and its local facet number (filled by Mesh::locate_facets()).
  std::vector<Index> cell;
  std::vector<int> local_facet;
};

/// Cells [begin, end) of a mesh, all of one type.
struct CellBlock {
  CellType type = CellType::kTri3;
  Index begin = 0, end = 0;
};

struct Mesh {
  int dim = 2;
  Eigen::MatrixXd x;                ///< dim × num_nodes reference coordinates
  std::vector<Index> cells;         ///< node indices, cell after cell
  std::vector<Index> cell_offsets{0};  ///< cell c's nodes start at cells[cell_offsets[c]]; num_cells + 1 entries
  /// Runs of cells of one type, in cell order, covering every cell. A mesh with no cells keeps one empty block
  /// for its type (a rigid surface: facets alone, of type facet_cell_type()).
  std::vector<CellBlock> cell_blocks{CellBlock{}};
  std::vector<Index> cell_tags;  ///< element tag of each cell in its mesh file (empty: built in code)
  std::vector<Index> node_tags;  ///< node tag of each node in its mesh file (empty: built in code)
  std::map<std::string, FacetGroup> facet_groups;
  std::map<std::string, std::vector<Index>> node_groups;  ///< physical points (and any node set)
  /// The dimension of the physical group each node group of a mesh file comes from (0: physical points;
  /// 1: physical curves in 3D); no entry for a node group built in code.
  std::map<std::string, int> node_group_dims;
  /// Physical groups of cells (of dimension `dim`) restricted to this mesh: cell indices, increasing.
  std::map<std::string, std::vector<Index>> cell_groups;
  /// Groups of facets (dimension dim − 1) that cannot be boundary groups, kept as node groups: those with a
  /// facet inside the body (shared by two cells; locate_facets()) and those holding facets of two types
  /// (extract_body()). Why, for the message of a contact surface or a load that names one. A Dirichlet
  /// condition may still hold its nodes.
  std::map<std::string, std::string> interior_facet_groups;
  /// Groups of facets (dimension dim − 1) with facets left out because they lie partly on duplicate nodes
  /// outside the body's cells (extract_body()), and why: a contact surface, a load or a Dirichlet condition
  /// that names one would miss part of it, so naming one is an input error. Unused, they are harmless.
  std::map<std::string, std::string> incomplete_groups;

  Index num_nodes() const { return x.cols(); }
  Index num_cells() const { return static_cast<Index>(cell_offsets.size()) - 1; }
  /// The type of cell c (a search among the blocks: loops over cells go block by block instead).
  CellType cell_type(Index c) const;
  int nodes_per_cell(Index c) const { return static_cast<int>(cell_offsets[c + 1] - cell_offsets[c]); }
  const Index* cell(Index c) const { return cells.data() + cell_offsets[c]; }
  Index* cell(Index c) { return cells.data() + cell_offsets[c]; }
  /// Whether the cells are of more than one type.
  bool mixed() const { return cell_blocks.size() > 1; }
  /// The type of the first block: the type of every cell of a mesh that is not mixed().
  CellType first_cell_type() const { return cell_blocks.front().type; }
  /// The number of cells of each type, in the order the types first appear.
  std::vector<std::pair<CellType, Index>> cell_type_counts() const;
  /// The cells' types for messages and summaries: "Tri3", or "Tri3 (12) + Quad4 (30)" for a mixed mesh.
  std::string cell_types_label() const;
  /// The largest number of nodes of a cell.
  int max_nodes_per_cell() const;
  /// The polynomial order shared by the cells.
  int order() const { return cell_order(first_cell_type()); }
  /// The facet type of the first block's cells (of a prism: its triangles).
  CellType facet_cell_type() const { return facet_type(first_cell_type()); }
  /// The type of the facets of group g.
  CellType facet_type_of(const FacetGroup& g) const { return g.type ? *g.type : facet_cell_type(); }
  Index num_facets(const FacetGroup& g) const {
    return static_cast<Index>(g.facets.size()) / cell_num_nodes(facet_type_of(g));
  }

  /// Replaces the cells by `connectivity`, cells of type t one after the other.
  void set_cells(CellType t, std::vector<Index> connectivity);
  /// Appends `count` cells of type t (connectivity: their node indices, cell after cell), in a block of their own
  /// unless the last block is of type t. Throws std::invalid_argument when t's order or facet type differs from
  /// the cells' already there (compatible_cell_types()).
  void add_cells(CellType t, const Index* connectivity, Index count);
  /// How messages name cell c: "element <tag>" (the mesh file's tag) or "cell <c + 1>".
  std::string cell_label(Index c) const;
  /// How messages name node v: "node <tag>" (the mesh file's tag) or "node <v + 1>".
  std::string node_label(Index v) const;

  /// Nodes of a facet group, or of a node group, sorted and unique. Throws std::out_of_range if absent.
  std::vector<Index> group_nodes(const std::string& name) const;
  bool has_group(const std::string& name) const;
  /// All group names, facet groups first.
  std::vector<std::string> group_names() const;

  /// Finds, for every facet of every group, the cell it bounds and its local facet number, and
  /// reorders its nodes to the outward orientation of that cell. A group with a facet shared by two cells
  /// (inside the body) becomes a node group and is listed in interior_facet_groups, with a reason naming
  /// that facet (by its element tag, FacetGroup::tags) and both cells. Throws InputError(file="", key=group)
  /// when a facet is a facet of no cell.
  void locate_facets();

  /// Checks the mesh: finite coordinates, node indices in range, no cell with a non-positive
  /// Jacobian determinant at any node (inverted or degenerate). Throws InputError naming the node or
  /// the cell (node_label(), cell_label()).
  void check() const;

  /// Reorients cells whose Jacobian at the first vertex is negative (swaps two vertices and the
  /// matching edge nodes). Returns the number of cells flipped.
  Index orient_cells();
};

/// Whether cells of types a and b can be in one mesh: the same dimension and order, and the same facet
/// type wherever both have facets of one shape (a triangle and a quadrilateral of the same order in 2D; in
/// 3D tetrahedra, hexahedra, prisms and pyramids of one order, a hexahedron meeting a tetrahedron through
/// pyramids; not an 8-node with a 9-node quadrilateral face, as Hex20 with Hex27 or Prism18).
bool compatible_cell_types(CellType a, CellType b);

/// Signed measure-like determinant of the vertex simplex of cell c (2× area, 6× volume); for a
/// quadrilateral, hexahedron, prism or pyramid, that of the simplex at its vertex 0 (corner_determinant(m, c, 0)).
double simplex_determinant(const Mesh& m, Index c);

/// Determinant of the edges leaving vertex `corner` of cell c along the reference axes, signed so that
/// it is positive for a positively oriented cell: the sign of det J at that vertex for a quadrilateral,
/// hexahedron or prism (corner < cell_num_vertices()); for a pyramid, det J of its vertex map at a base
/// vertex, and at the apex seen from the base's centre. For a simplex, simplex_determinant() at any corner.
double corner_determinant(const Mesh& m, Index c, int corner);

}  // namespace symcontact
