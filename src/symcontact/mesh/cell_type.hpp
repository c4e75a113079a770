#pragma once
/// \file cell_type.hpp
/// The Lagrange cell types symcontact knows, with their node counts and orderings.
///
/// Node ordering follows Gmsh (https://gmsh.info/doc/texinfo/gmsh.html#Node-ordering):
///  - Line3:  v0 v1 m01
///  - Tri6:   v0 v1 v2 m01 m12 m20
///  - Tet10:  v0 v1 v2 v3 m01 m12 m20 m30 m32 m31
///  - Quad4:  v0 v1 v2 v3 (counter-clockwise); Quad8 adds m01 m12 m23 m30; Quad9 adds the centre c
///  - Hex8:   v0..v3 the face ζ = 0 (counter-clockwise seen from ζ > 0), v4..v7 above them;
///            Hex20 adds the edge nodes m01 m03 m04 m12 m15 m23 m26 m37 m45 m47 m56 m67;
///            Hex27 adds the face centres of (0 3 2 1) (0 1 5 4) (0 4 7 3) (1 2 6 5) (2 3 7 6) (4 5 6 7)
///            and the cell centre.
/// VTK orders Tet10 edges as m01 m12 m20 m30 m31 m32, Hex20 edges as m01 m12 m23 m30 m45 m56 m67 m74
/// m04 m15 m26 m37 and Hex27 faces as ξ = 0, ξ = 1, η = 0, η = 1, ζ = 0, ζ = 1: vtk_node_order()
/// permutes them on output. Quadrilaterals have the same order in both.
///
///  - Prism6: v0 v1 v2 the triangle ζ = 0 (counter-clockwise seen from ζ > 0), v3 v4 v5 above them;
///    Prism18 adds the edge nodes m01 m02 m03 m12 m14 m25 m34 m35 m45 and the centres of the sides
///    (0 1 4 3) (0 2 5 3) (1 2 5 4); Prism15 is Prism18 without the sides' centres.
///  - Pyramid5: v0..v3 the square base (counter-clockwise seen from the apex), v4 the apex; Pyramid13 adds
///    the edge nodes m01 m03 m04 m12 m14 m23 m24 m34, Pyramid14 also the centre of the base.
/// VTK lists a wedge's first triangle clockwise seen from the second (its normal pointing away from it):
/// vtk_node_order() swaps v1, v2 and v4, v5, and orders Prism18's edges (0 1) (1 2) (2 0) (3 4) (4 5)
/// (5 3) (0 3) (1 4) (2 5) and sides (0 1 4 3) (1 2 5 4) (2 0 3 5) in its own numbering. VTK's quadratic
/// pyramid orders its edges (0 1) (1 2) (2 3) (3 0) (0 4) (1 4) (2 4) (3 4) and has no base centre:
/// Pyramid14 is written as a 13-node pyramid (vtk_num_nodes()).
///
/// Quadrilaterals and hexahedra map from the unit square or cube [0, 1]^d (v0 at the origin, v1 on
/// the ξ axis, v3 on the η axis, v4 on the ζ axis); simplices from the unit simplex; prisms from the unit
/// triangle (ξ, η) times [0, 1] (ζ); pyramids from {0 ≤ ζ ≤ 1, 0 ≤ ξ, η ≤ 1 − ζ}: the base [0, 1]² with
/// v0 at the origin, v1 on the ξ axis, v3 on the η axis, and the apex v4 at (0, 0, 1).

#include <array>
#include <string>
#include <vector>

namespace symcontact {

enum class CellType : int {
  kPoint1, kLine2, kLine3, kTri3, kTri6, kTet4, kTet10,
  kQuad4, kQuad8, kQuad9, kHex8, kHex20, kHex27, kPrism6, kPrism18, kPrism15, kPyramid5, kPyramid13, kPyramid14
};

/// The reference shape of a cell type: a simplex (point, segment, triangle, tetrahedron), a
/// tensor-product cell (quadrilateral, hexahedron) whose quadrature and shape functions are products, a
/// prism (a triangle times a segment) or a pyramid (a square collapsed to a point).
enum class CellShape { kSimplex, kTensor, kPrism, kPyramid };
CellShape cell_shape(CellType t);

int cell_dim(CellType t);          ///< topological dimension (0..3)
int cell_num_nodes(CellType t);    ///< number of nodes
int cell_num_vertices(CellType t); ///< number of corner nodes
int cell_order(CellType t);        ///< polynomial order (1 or 2; 0 for a point); 2 for Quad8/Hex20/...
std::string cell_name(CellType t);
/// The facet type of a cell (Tri3 -> Line2, Tet10 -> Tri6, Quad9 -> Line3, Hex20 -> Quad8, ...); for a prism,
/// or pyramid, whose facets are of two types, that of its triangles (cell_facet_type() gives each facet's).
CellType facet_type(CellType t);
/// The type of facet f of a cell of type t (cell_facet_nodes()): facet_type(t), except for a prism's
/// quadrilateral sides.
CellType cell_facet_type(CellType t, int f);
/// The order-1 cell of the same shape, whose nodes are t's vertices (Tet10 -> Tet4, Hex27 -> Hex8,
/// Pyramid13 -> Pyramid5, ...).
CellType vertex_cell_type(CellType t);
/// The simplex Lagrange cell of topological dimension `dim` and polynomial `order`.
CellType cell_type_of(int dim, int order);
/// The cell type whose facets are of type `facet` (Line2 -> Tri3, Quad8 -> Hex20, ...), for a rigid
/// surface made of facets alone.
CellType cell_type_with_facet(CellType facet);
/// Gmsh element type number (1 line2, 2 tri3, 3 quad4, 4 tet4, 5 hex8, 6 prism6, 8 line3, 9 tri6, 10 quad9,
/// 11 tet10, 12 hex27, 13 prism18, 15 point, 16 quad8, 17 hex20, 18 prism15, 7 pyramid5, 19 pyramid13,
/// 14 pyramid14).
int gmsh_element_type(CellType t);
/// Inverse of gmsh_element_type(); returns false for types symcontact does not support.
bool from_gmsh_element_type(int gmsh_type, CellType& out);
/// VTK cell type id (1, 3, 21, 5, 22, 10, 24, 9, 23, 28, 12, 25, 29, 13, 32, 26, 14, 27, 27).
int vtk_cell_type(CellType t);
/// The number of nodes VTK's cell of vtk_cell_type(t) has: cell_num_nodes(t), 13 for Pyramid14.
int vtk_num_nodes(CellType t);
/// vtk_node_order(t)[k] is the index, in our ordering, of VTK's k-th node (vtk_num_nodes(t) entries).
const int* vtk_node_order(CellType t);

/// Local node indices of facet f of a cell of type t (cell_num_nodes(cell_facet_type(t, f)) entries),
/// ordered so that the facet normal computed from its first vertices points out of the cell
/// for a positively oriented cell (a quadrilateral facet: its first, second and last vertices).
const int* cell_facet_nodes(CellType t, int f);
int cell_num_facets(CellType t);
/// Reference coordinates of node a of a quadrilateral or hexahedron in {−1, 0, 1}^d (Gmsh's, on
/// [−1, 1]^d; the point of [0, 1]^d is (c + 1) / 2): cell_dim(t) entries.
const int* tensor_node_coordinates(CellType t, int a);

/// The vertices whose mean is node a of a cell of type t, where the order-1 map of the vertices puts it:
/// {a} for a vertex, the two ends of an edge, the four corners of a quadrilateral face, the eight of a
/// hexahedron.
std::vector<int> node_vertices(CellType t, int a);

/// A permutation of the nodes of a cell that reverses its orientation: the cell with nodes
/// n[p[0]], n[p[1]], ... is the mirror image of the cell n[0], n[1], ... (swaps v1 and v2 of a
/// simplex, or the ξ and η axes of a quadrilateral or hexahedron).
const int* cell_reflection(CellType t);

}  // namespace symcontact
