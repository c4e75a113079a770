#pragma once
/// \file structured.hpp
/// Structured meshes of rectangles and boxes, for tests and benchmarks (no Gmsh needed).
///  - rectangle_mesh: nx × ny squares, each cut into two triangles along alternating diagonals;
///    facet groups "left", "right", "bottom", "top"; node groups "corner_ll" (x0, y0), "corner_lr".
///  - box_mesh: nx × ny × nz cubes, each cut into six tetrahedra (Kuhn/Freudenthal split, conforming);
///    facet groups "xmin", "xmax", "ymin", "ymax", "zmin", "zmax"; node group "origin".
/// Order 2 adds edge-midpoint nodes (elevate_to_p2()).
///  - tensor_mesh: nx × ny rectangles or nx × ny × nz boxes, one quadrilateral or hexahedron each, of any
///    of their types (Quad4/8/9, Hex8/20/27), with the groups of rectangle_mesh (2D) or box_mesh (3D).
///  - prism_mesh: nx × ny × nz boxes, each cut into two prisms (Prism6, Prism15 or Prism18) by the
///    diagonal of its square in (x, y); the groups of box_mesh, "zmin" and "zmax" of triangles, the sides
///    of quadrilaterals.
///  - pyramid_mesh: nx × ny × nz boxes, each cut into six pyramids with their apex at its centre and
///    the box's faces as their bases (Pyramid5, 13 or 14); the groups of box_mesh, of quadrilaterals.
///  - mixed_rectangle_mesh: the quadrilaterals of tensor_mesh, every other one (a checkerboard) cut into two
///    triangles along its diagonal from v0 to v2: Quad4 with Tri3, or Quad9 with Tri6 (the centre node is
///    the midpoint of the diagonal). A mesh of two cell types, for tests.

#include "symcontact/mesh/mesh.hpp"

namespace symcontact {

Mesh rectangle_mesh(double x0, double y0, double x1, double y1, int nx, int ny, int order = 1);
Mesh box_mesh(const Vec3& lo, const Vec3& hi, int nx, int ny, int nz, int order = 1);

/// `type` a quadrilateral (lo, hi in the plane, nz ignored) or hexahedron type.
Mesh tensor_mesh(CellType type, const Vec3& lo, const Vec3& hi, int nx, int ny, int nz = 1);

/// `type` Prism6, Prism15 or Prism18.
Mesh prism_mesh(CellType type, const Vec3& lo, const Vec3& hi, int nx, int ny, int nz);

/// `type` Pyramid5, Pyramid13 or Pyramid14.
Mesh pyramid_mesh(CellType type, const Vec3& lo, const Vec3& hi, int nx, int ny, int nz);

/// The mesh of the box (the rectangle in 2D, nz ignored) in cells of `type`: rectangle_mesh() or
/// box_mesh() for simplices, else tensor_mesh(), prism_mesh() or pyramid_mesh().
Mesh structured_mesh(CellType type, const Vec3& lo, const Vec3& hi, int nx, int ny, int nz = 1);

/// `type` Quad4 or Quad9; the cell (i, j) is cut when i + j is even.
Mesh mixed_rectangle_mesh(CellType type, double x0, double y0, double x1, double y1, int nx, int ny);

/// Adds a node at the midpoint of every edge and turns Tri3/Tet4 cells (and their facet groups)
/// into Tri6/Tet10 with Gmsh node ordering. Node groups keep their vertex nodes.
Mesh elevate_to_p2(const Mesh& p1);

/// Moves every node not on a facet group by a random offset of at most `amplitude` × the local
/// spacing `h` in each coordinate (deterministic for a given seed); the other nodes of each cell are then
/// reset to where the order-1 map of its vertices puts them (edge midpoints, the mean of a face's or a
/// hexahedron's vertices: node_vertices()). For patch tests on distorted meshes.
void perturb_interior_nodes(Mesh& mesh, double h, double amplitude, unsigned seed);

}  // namespace symcontact
