#pragma once
/// \file cell_type.hpp
/// The Lagrange cell types symcontact knows, with their node counts and orderings.
///
/// Node ordering follows Gmsh (https://gmsh.info/doc/texinfo/gmsh.html#Node-ordering):
///  - Line3:  v0 v1 m01
///  - Tri6:   v0 v1 v2 m01 m12 m20
///  - Tet10:  v0 v1 v2 v3 m01 m12 m20 m30 m32 m31
/// VTK orders Tet10 edges as m01 m12 m20 m30 m31 m32, so the last two nodes swap on output
/// (see vtk_node_order()).

#include <array>
#include <string>

namespace symcontact {

enum class CellType : int { kPoint1, kLine2, kLine3, kTri3, kTri6, kTet4, kTet10 };

int cell_dim(CellType t);          ///< topological dimension (0..3)
int cell_num_nodes(CellType t);    ///< number of nodes
int cell_num_vertices(CellType t); ///< number of corner nodes
int cell_order(CellType t);        ///< polynomial order (1 or 2; 0 for a point)
std::string cell_name(CellType t);
/// The facet type of a cell (Tri3 -> Line2, Tet10 -> Tri6, ...).
CellType facet_type(CellType t);
/// The Lagrange cell of topological dimension `dim` and polynomial `order`.
CellType cell_type_of(int dim, int order);
/// Gmsh element type number (1 line2, 2 tri3, 4 tet4, 8 line3, 9 tri6, 11 tet10, 15 point); -1 if none.
int gmsh_element_type(CellType t);
/// Inverse of gmsh_element_type(); returns false for types symcontact does not support.
bool from_gmsh_element_type(int gmsh_type, CellType& out);
/// VTK cell type id (3, 21, 5, 22, 10, 24, 1).
int vtk_cell_type(CellType t);
/// vtk_node_order(t)[k] is the index, in our ordering, of VTK's k-th node.
const int* vtk_node_order(CellType t);

/// Local node indices of facet f of a cell of type t (cell_num_nodes(facet_type(t)) entries),
/// ordered so that the facet normal computed from its first vertices points out of the cell
/// for a positively oriented cell.
const int* cell_facet_nodes(CellType t, int f);
int cell_num_facets(CellType t);

}  // namespace symcontact
