#include "symcontact/mesh/cell_type.hpp"

#include "symcontact/core/error.hpp"

namespace symcontact {

int cell_dim(CellType t) {
  switch (t) {
    case CellType::kPoint1: return 0;
    case CellType::kLine2:
    case CellType::kLine3: return 1;
    case CellType::kTri3:
    case CellType::kTri6: return 2;
    case CellType::kTet4:
    case CellType::kTet10: return 3;
  }
  return -1;
}

int cell_num_nodes(CellType t) {
  static const int n[] = {1, 2, 3, 3, 6, 4, 10};
  return n[static_cast<int>(t)];
}

int cell_num_vertices(CellType t) {
  static const int n[] = {1, 2, 2, 3, 3, 4, 4};
  return n[static_cast<int>(t)];
}

int cell_order(CellType t) {
  static const int n[] = {0, 1, 2, 1, 2, 1, 2};
  return n[static_cast<int>(t)];
}

std::string cell_name(CellType t) {
  static const char* n[] = {"point", "line2", "line3", "tri3", "tri6", "tet4", "tet10"};
  return n[static_cast<int>(t)];
}

CellType facet_type(CellType t) {
  switch (t) {
    case CellType::kLine2:
    case CellType::kLine3: return CellType::kPoint1;
    case CellType::kTri3: return CellType::kLine2;
    case CellType::kTri6: return CellType::kLine3;
    case CellType::kTet4: return CellType::kTri3;
    case CellType::kTet10: return CellType::kTri6;
    default: break;
  }
  throw std::logic_error("facet_type: cell has no facet type");
}

CellType cell_type_of(int dim, int order) {
  if (order == 1 && dim == 1) return CellType::kLine2;
  if (order == 2 && dim == 1) return CellType::kLine3;
  if (order == 1 && dim == 2) return CellType::kTri3;
  if (order == 2 && dim == 2) return CellType::kTri6;
  if (order == 1 && dim == 3) return CellType::kTet4;
  if (order == 2 && dim == 3) return CellType::kTet10;
  if (dim == 0) return CellType::kPoint1;
  throw std::logic_error("cell_type_of: unsupported dimension/order");
}

int gmsh_element_type(CellType t) {
  static const int n[] = {15, 1, 8, 2, 9, 4, 11};
  return n[static_cast<int>(t)];
}

bool from_gmsh_element_type(int g, CellType& out) {
  switch (g) {
    case 15: out = CellType::kPoint1; return true;
    case 1: out = CellType::kLine2; return true;
    case 8: out = CellType::kLine3; return true;
    case 2: out = CellType::kTri3; return true;
    case 9: out = CellType::kTri6; return true;
    case 4: out = CellType::kTet4; return true;
    case 11: out = CellType::kTet10; return true;
    default: return false;
  }
}

int vtk_cell_type(CellType t) {
  static const int n[] = {1, 3, 21, 5, 22, 10, 24};
  return n[static_cast<int>(t)];
}

const int* vtk_node_order(CellType t) {
  static const int ident[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  static const int tet10[] = {0, 1, 2, 3, 4, 5, 6, 7, 9, 8};
  return t == CellType::kTet10 ? tet10 : ident;
}

int cell_num_facets(CellType t) {
  switch (cell_dim(t)) {
    case 1: return 2;
    case 2: return 3;
    case 3: return 4;
    default: return 0;
  }
}

const int* cell_facet_nodes(CellType t, int f) {
  // Triangles: edge f joins v_f and v_{f+1}; its midpoint is node 3+f (m01, m12, m20).
  static const int tri[3][3] = {{0, 1, 3}, {1, 2, 4}, {2, 0, 5}};
  // Tetrahedra (positively oriented: (v1-v0) x (v2-v0) . (v3-v0) > 0). Faces opposite v3, v2, v0, v1,
  // each listed so that its right-hand normal points outwards; midpoints from the Gmsh edge numbering
  // m01=4 m12=5 m20=6 m30=7 m32=8 m31=9.
  static const int tet[4][6] = {
      {0, 2, 1, 6, 5, 4},  // opposite v3
      {0, 1, 3, 4, 9, 7},  // opposite v2
      {1, 2, 3, 5, 8, 9},  // opposite v0
      {0, 3, 2, 7, 8, 6},  // opposite v1
  };
  static const int line[2][1] = {{0}, {1}};
  switch (cell_dim(t)) {
    case 1: return line[f];
    case 2: return tri[f];
    case 3: return tet[f];
    default: break;
  }
  throw std::logic_error("cell_facet_nodes: cell has no facets");
}

}  // namespace symcontact
