#include "symcontact/mesh/cell_type.hpp"

#include <algorithm>
#include <array>

#include "symcontact/core/error.hpp"

namespace symcontact {

namespace {
/// Index of a cell type into the tables below (CellType order).
constexpr int ix(CellType t) { return static_cast<int>(t); }

/// What the functions below return for each type, in CellType order.
struct CellFacts {
  const char* name;
  int dim, nodes, vertices, order;
};
constexpr CellFacts kFacts[] = {
    {"point", 0, 1, 1, 0}, {"line2", 1, 2, 2, 1}, {"line3", 1, 3, 2, 2},   {"tri3", 2, 3, 3, 1},
    {"tri6", 2, 6, 3, 2},  {"tet4", 3, 4, 4, 1},  {"tet10", 3, 10, 4, 2},  {"quad4", 2, 4, 4, 1},
    {"quad8", 2, 8, 4, 2}, {"quad9", 2, 9, 4, 2}, {"hex8", 3, 8, 8, 1},    {"hex20", 3, 20, 8, 2},
    {"hex27", 3, 27, 8, 2}, {"prism6", 3, 6, 6, 1}, {"prism18", 3, 18, 6, 2}, {"prism15", 3, 15, 6, 2},
    {"pyramid5", 3, 5, 5, 1}, {"pyramid13", 3, 13, 5, 2}, {"pyramid14", 3, 14, 5, 2}};
/// The last CellType.
constexpr CellType kLastType = CellType::kPyramid14;
static_assert(sizeof(kFacts) / sizeof(kFacts[0]) == ix(kLastType) + 1, "one entry per CellType");

/// 0, 1, …, n − 1.
template <int n>
constexpr std::array<int, n> identity_permutation() {
  std::array<int, n> p{};
  for (int i = 0; i < n; ++i) p[i] = i;
  return p;
}
}  // namespace

CellShape cell_shape(CellType t) {
  if (t == CellType::kPrism6 || t == CellType::kPrism18 || t == CellType::kPrism15) return CellShape::kPrism;
  if (t == CellType::kPyramid5 || t == CellType::kPyramid13 || t == CellType::kPyramid14) return CellShape::kPyramid;
  return ix(t) >= ix(CellType::kQuad4) ? CellShape::kTensor : CellShape::kSimplex;
}

int cell_dim(CellType t) { return kFacts[ix(t)].dim; }

int cell_num_nodes(CellType t) { return kFacts[ix(t)].nodes; }

int cell_num_vertices(CellType t) { return kFacts[ix(t)].vertices; }

int cell_order(CellType t) { return kFacts[ix(t)].order; }

std::string cell_name(CellType t) { return kFacts[ix(t)].name; }

CellType facet_type(CellType t) {
  switch (t) {
    case CellType::kLine2:
    case CellType::kLine3: return CellType::kPoint1;
    case CellType::kTri3:
    case CellType::kQuad4: return CellType::kLine2;
    case CellType::kTri6:
    case CellType::kQuad8:
    case CellType::kQuad9: return CellType::kLine3;
    case CellType::kTet4:
    case CellType::kPrism6:
    case CellType::kPyramid5: return CellType::kTri3;
    case CellType::kTet10:
    case CellType::kPrism15:
    case CellType::kPrism18:
    case CellType::kPyramid13:
    case CellType::kPyramid14: return CellType::kTri6;
    case CellType::kHex8: return CellType::kQuad4;
    case CellType::kHex20: return CellType::kQuad8;
    case CellType::kHex27: return CellType::kQuad9;
    default: break;
  }
  throw std::logic_error("facet_type: cell has no facet type");
}

CellType cell_facet_type(CellType t, int f) {
  const bool quad = (cell_shape(t) == CellShape::kPrism && f >= 2) || (cell_shape(t) == CellShape::kPyramid && f == 4);
  if (!quad) return facet_type(t);
  switch (t) {
    case CellType::kPrism6:
    case CellType::kPyramid5: return CellType::kQuad4;
    case CellType::kPrism15:
    case CellType::kPyramid13: return CellType::kQuad8;
    default: return CellType::kQuad9;
  }
}

CellType vertex_cell_type(CellType t) {
  switch (cell_shape(t)) {
    case CellShape::kTensor: return cell_dim(t) == 2 ? CellType::kQuad4 : CellType::kHex8;
    case CellShape::kPrism: return CellType::kPrism6;
    case CellShape::kPyramid: return CellType::kPyramid5;
    default: return cell_type_of(cell_dim(t), std::min(cell_order(t), 1));
  }
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

CellType cell_type_with_facet(CellType facet) {
  switch (facet) {
    case CellType::kQuad4: return CellType::kHex8;
    case CellType::kQuad8: return CellType::kHex20;
    case CellType::kQuad9: return CellType::kHex27;
    default: return cell_type_of(cell_dim(facet) + 1, cell_order(facet));
  }
}

int gmsh_element_type(CellType t) {
  static const int n[] = {15, 1, 8, 2, 9, 4, 11, 3, 16, 10, 5, 17, 12, 6, 13, 18, 7, 19, 14};
  static_assert(sizeof(n) / sizeof(n[0]) == ix(kLastType) + 1, "one entry per CellType");
  return n[ix(t)];
}

bool from_gmsh_element_type(int g, CellType& out) {
  for (int k = 0; k <= ix(kLastType); ++k)
    if (gmsh_element_type(static_cast<CellType>(k)) == g) {
      out = static_cast<CellType>(k);
      return true;
    }
  return false;
}

int vtk_cell_type(CellType t) {
  static const int n[] = {1, 3, 21, 5, 22, 10, 24, 9, 23, 28, 12, 25, 29, 13, 32, 26, 14, 27, 27};
  static_assert(sizeof(n) / sizeof(n[0]) == ix(kLastType) + 1, "one entry per CellType");
  return n[ix(t)];
}

int vtk_num_nodes(CellType t) { return t == CellType::kPyramid14 ? 13 : cell_num_nodes(t); }

const int* vtk_node_order(CellType t) {
  static constexpr std::array<int, 27> ident = identity_permutation<27>();
  static const int tet10[] = {0, 1, 2, 3, 4, 5, 6, 7, 9, 8};
  // VTK edges m01 m12 m23 m30 m45 m56 m67 m74 m04 m15 m26 m37 at their Gmsh positions; VTK faces
  // ξ = 0 (0 4 7 3), ξ = 1 (1 2 6 5), η = 0 (0 1 5 4), η = 1 (2 3 7 6), ζ = 0 (0 3 2 1), ζ = 1 likewise.
  static const int hex[] = {0,  1,  2,  3,  4,  5,  6,  7,  8,  11, 13, 9,  16, 18,
                            19, 17, 10, 12, 14, 15, 22, 23, 21, 24, 20, 25, 26};
  static const int wedge[] = {0, 2, 1, 3, 5, 4, 7, 9, 6, 13, 14, 12, 8, 11, 10, 16, 17, 15};
  // VTK edges (0 1) (1 2) (2 3) (3 0) (0 4) (1 4) (2 4) (3 4) at their Gmsh positions.
  static const int pyramid[] = {0, 1, 2, 3, 4, 5, 8, 10, 6, 7, 9, 11, 12};
  const int* const id = ident.data();
  static const int* const order[] = {id,  id,  id,  id,    id,    id,    tet10,   id,      id,      id,
                                     id,  hex, hex, wedge, wedge, wedge, pyramid, pyramid, pyramid};  // CellType order
  static_assert(sizeof(order) / sizeof(order[0]) == ix(kLastType) + 1, "one entry per CellType");
  return order[ix(t)];
}

int cell_num_facets(CellType t) {
  switch (t) {
    case CellType::kQuad4:
    case CellType::kQuad8:
    case CellType::kQuad9: return 4;
    case CellType::kHex8:
    case CellType::kHex20:
    case CellType::kHex27: return 6;
    default: break;
  }
  if (cell_shape(t) == CellShape::kPrism || cell_shape(t) == CellShape::kPyramid) return 5;
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
  // Quadrilaterals: edge f joins v_f and v_{f+1 mod 4}; its midpoint is node 4+f.
  static const int quad[4][3] = {{0, 1, 4}, {1, 2, 5}, {2, 3, 6}, {3, 0, 7}};
  // Tetrahedra (positively oriented: (v1-v0) x (v2-v0) . (v3-v0) > 0). Faces opposite v3, v2, v0, v1,
  // each listed so that its right-hand normal points outwards; midpoints from the Gmsh edge numbering
  // m01=4 m12=5 m20=6 m30=7 m32=8 m31=9.
  static const int tet[4][6] = {
      {0, 2, 1, 6, 5, 4},  // opposite v3
      {0, 1, 3, 4, 9, 7},  // opposite v2
      {1, 2, 3, 5, 8, 9},  // opposite v0
      {0, 3, 2, 7, 8, 6},  // opposite v1
  };
  // Hexahedra: the six faces in Gmsh's order, vertices counter-clockwise seen from outside, then the
  // four edge nodes (Gmsh numbering m01=8 m03=9 m04=10 m12=11 m15=12 m23=13 m26=14 m37=15 m45=16
  // m47=17 m56=18 m67=19) and the face centre (20..25).
  static const int hex[6][9] = {
      {0, 3, 2, 1, 9, 13, 11, 8, 20},    // ζ = 0
      {0, 1, 5, 4, 8, 12, 16, 10, 21},   // η = 0
      {0, 4, 7, 3, 10, 17, 15, 9, 22},   // ξ = 0
      {1, 2, 6, 5, 11, 14, 18, 12, 23},  // ξ = 1
      {2, 3, 7, 6, 13, 15, 19, 14, 24},  // η = 1
      {4, 5, 6, 7, 16, 18, 19, 17, 25},  // ζ = 1
  };
  // Prisms: the triangles ζ = 0 and ζ = 1, then the sides η = 0, ξ = 0 and ξ + η = 1, each
  // counter-clockwise seen from outside; then the edge nodes (Gmsh numbering m01=6 m02=7 m03=8 m12=9
  // m14=10 m25=11 m34=12 m35=13 m45=14) and the side's centre (15..17).
  static const int prism[5][9] = {{0, 2, 1, 7, 9, 6, -1, -1, -1},     {3, 4, 5, 12, 14, 13, -1, -1, -1},
                                  {0, 1, 4, 3, 6, 10, 12, 8, 15},      {0, 3, 5, 2, 8, 13, 11, 7, 16},
                                  {1, 2, 5, 4, 9, 11, 14, 10, 17}};
  // Pyramids: the sides η = 0, ξ = 0, ξ = 1 − ζ, η = 1 − ζ, then the base ζ = 0, each counter-clockwise seen
  // from outside; then the edge nodes (Gmsh numbering m01=5 m03=6 m04=7 m12=8 m14=9 m23=10 m24=11 m34=12)
  // and the base's centre (13).
  static const int pyramid[5][9] = {{0, 1, 4, 5, 9, 7, -1, -1, -1},   {0, 4, 3, 7, 12, 6, -1, -1, -1},
                                    {1, 2, 4, 8, 11, 9, -1, -1, -1},  {2, 3, 4, 10, 12, 11, -1, -1, -1},
                                    {0, 3, 2, 1, 6, 10, 8, 5, 13}};
  static const int line[2][1] = {{0}, {1}};
  if (cell_shape(t) == CellShape::kTensor) return cell_dim(t) == 2 ? quad[f] : hex[f];
  if (cell_shape(t) == CellShape::kPrism) return prism[f];
  if (cell_shape(t) == CellShape::kPyramid) return pyramid[f];
  switch (cell_dim(t)) {
    case 1: return line[f];
    case 2: return tri[f];
    case 3: return tet[f];
    default: break;
  }
  throw std::logic_error("cell_facet_nodes: cell has no facets");
}

const int* tensor_node_coordinates(CellType t, int a) {
  // Gmsh's Hex27 (gmsh.info, "Node ordering"); the first 20 are Hex20's, the first 8 Hex8's. The
  // quadrilaterals' first 4 and 8 are Quad4's and Quad8's.
  static const int hex[27][3] = {
      {-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1},
      {-1, 1, 1},   {0, -1, -1}, {-1, 0, -1}, {-1, -1, 0}, {1, 0, -1}, {1, -1, 0}, {0, 1, -1},
      {1, 1, 0},    {-1, 1, 0},  {0, -1, 1},  {-1, 0, 1},  {1, 0, 1},  {0, 1, 1},  {0, 0, -1},
      {0, -1, 0},   {-1, 0, 0},  {1, 0, 0},   {0, 1, 0},   {0, 0, 1},  {0, 0, 0}};
  static const int quad[9][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}, {0, 0}};
  if (cell_shape(t) != CellShape::kTensor) throw std::logic_error("tensor_node_coordinates: not a tensor cell");
  return cell_dim(t) == 2 ? quad[a] : hex[a];
}

std::vector<int> node_vertices(CellType t, int a) {
  const int nv = cell_num_vertices(t);
  if (a < nv) return {a};
  if (cell_shape(t) == CellShape::kTensor) {  // the corners that agree with the node where it is at ±1
    std::vector<int> v;
    const int* c = tensor_node_coordinates(t, a);
    for (int b = 0; b < nv; ++b) {
      const int* cb = tensor_node_coordinates(t, b);
      bool on = true;
      for (int i = 0; i < cell_dim(t); ++i) on = on && (c[i] == 0 || c[i] == cb[i]);
      if (on) v.push_back(b);
    }
    return v;
  }
  // The edges (and faces) of the other shapes in Gmsh's order of their nodes after the vertices.
  static const std::vector<int> tri[3] = {{0, 1}, {1, 2}, {2, 0}};
  static const std::vector<int> tet[6] = {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}};
  static const std::vector<int> prism[12] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 4}, {2, 5},
                                             {3, 4}, {3, 5}, {4, 5}, {0, 1, 4, 3}, {0, 2, 5, 3}, {1, 2, 5, 4}};
  static const std::vector<int> pyramid[9] = {{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 4},
                                              {2, 3}, {2, 4}, {3, 4}, {0, 1, 2, 3}};
  static const std::vector<int> line[1] = {{0, 1}};
  switch (cell_shape(t)) {
    case CellShape::kPrism: return prism[a - nv];
    case CellShape::kPyramid: return pyramid[a - nv];
    default: break;
  }
  return cell_dim(t) == 1 ? line[a - nv] : (cell_dim(t) == 2 ? tri[a - nv] : tet[a - nv]);
}

const int* cell_reflection(CellType t) {
  static const int ident[] = {0, 1, 2};
  static const int line3[] = {1, 0, 2};
  static const int tri[] = {0, 2, 1, 5, 4, 3};
  static const int tet[] = {0, 2, 1, 3, 6, 5, 4, 7, 9, 8};
  static const int quad[] = {0, 3, 2, 1, 7, 6, 5, 4, 8};
  // Hexahedra: ξ and η swapped, so v1 <-> v3, v5 <-> v7, with their edges and faces.
  static const int hex[] = {0,  3,  2,  1,  4,  7,  6,  5,  9,  8,  10, 13, 15, 11,
                            14, 12, 17, 16, 19, 18, 20, 22, 21, 24, 23, 25, 26};
  // Prisms: ξ and η swapped, so v1 <-> v2 and v4 <-> v5, with their edges and sides.
  static const int prism[] = {0, 2, 1, 3, 5, 4, 7, 6, 8, 9, 11, 10, 13, 12, 14, 16, 15, 17};
  // Pyramids: ξ and η swapped, so v1 <-> v3, with their edges.
  static const int pyramid[] = {0, 3, 2, 1, 4, 6, 5, 7, 10, 12, 8, 11, 9, 13};
  static const int* const reflection[] = {ident, line3, line3, tri,   tri,   tet,   tet,     quad,    quad,   quad,
                                          hex,   hex,   hex,   prism, prism, prism, pyramid, pyramid, pyramid};  // in CellType order
  static_assert(sizeof(reflection) / sizeof(reflection[0]) == ix(kLastType) + 1, "one entry per CellType");
  return reflection[ix(t)];
}

}  // namespace symcontact
