#include "symcontact/mesh/cell_type.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "symcontact/fem/shape_functions.hpp"

using namespace symcontact;

namespace {
const CellType kTensor[] = {CellType::kQuad4, CellType::kQuad8, CellType::kQuad9,
                            CellType::kHex8,  CellType::kHex20, CellType::kHex27};

Eigen::VectorXd ref_point(CellType t, int a) {
  const std::vector<double> r = reference_nodes(t);
  const int d = cell_dim(t);
  return Eigen::Map<const Eigen::VectorXd>(r.data() + a * d, d);
}
}  // namespace

TEST(CellType, GmshNumbersRoundTrip) {
  for (int k = 0; k <= static_cast<int>(CellType::kPyramid14); ++k) {
    const auto t = static_cast<CellType>(k);
    CellType back;
    ASSERT_TRUE(from_gmsh_element_type(gmsh_element_type(t), back));
    EXPECT_EQ(back, t);
  }
  CellType none;
  EXPECT_FALSE(from_gmsh_element_type(21, none));  // 10-node triangle (order 3)
  EXPECT_FALSE(from_gmsh_element_type(29, none));  // 20-node tetrahedron (order 3)
}

// The reflection maps each node to the node at the mirrored reference point (ξ ↔ η swapped).
TEST(CellType, ReflectionSwapsTheFirstTwoReferenceAxes) {
  for (CellType t : kTensor) {
    const int* p = cell_reflection(t);
    for (int a = 0; a < cell_num_nodes(t); ++a) {
      Eigen::VectorXd x = ref_point(t, a);
      std::swap(x[0], x[1]);
      EXPECT_LT((ref_point(t, p[a]) - x).norm(), 1e-15) << cell_name(t) << " node " << a;
    }
  }
}

// Facet f's nodes lie on one face of the reference cell, in the facet type's own order (vertices, edge
// midpoints, centre), and the facet's right-hand normal points out of the cell.
TEST(CellType, FacetsAreOrderedAndOutward) {
  for (CellType t : kTensor) {
    const CellType ft = facet_type(t);
    const int d = cell_dim(t);
    Eigen::VectorXd centre = Eigen::VectorXd::Constant(d, 0.5);
    for (int f = 0; f < cell_num_facets(t); ++f) {
      const int* loc = cell_facet_nodes(t, f);
      const int nfv = cell_num_vertices(ft);
      // Node k of the facet is at the facet-reference point of node k, mapped by the facet's vertices.
      const std::vector<double> fr = reference_nodes(ft);
      std::vector<double> N(cell_num_nodes(ft));
      for (int k = 0; k < cell_num_nodes(ft); ++k) {
        const CellType linear = d == 2 ? CellType::kLine2 : CellType::kQuad4;
        shape_functions(linear, fr.data() + k * (d - 1), N.data(), nullptr);
        Eigen::VectorXd x = Eigen::VectorXd::Zero(d);
        for (int v = 0; v < nfv; ++v) x += N[v] * ref_point(t, loc[v]);
        EXPECT_LT((ref_point(t, loc[k]) - x).norm(), 1e-15) << cell_name(t) << " facet " << f << " node " << k;
      }
      Eigen::VectorXd normal(d);
      if (d == 2) {
        const Eigen::VectorXd e = ref_point(t, loc[1]) - ref_point(t, loc[0]);
        normal << e[1], -e[0];
      } else {
        const Eigen::Vector3d a = ref_point(t, loc[1]) - ref_point(t, loc[0]);
        const Eigen::Vector3d b = ref_point(t, loc[3]) - ref_point(t, loc[0]);
        normal = a.cross(b);
      }
      EXPECT_GT(normal.dot(ref_point(t, loc[0]) - centre), 0.0) << cell_name(t) << " facet " << f;
    }
  }
}

// The 6-node prism: its reflection swaps ξ and η; each facet (triangles ζ = 0, 1, then the three
// quadrilateral sides) has its vertices on one face of the reference prism, and its right-hand normal from
// its first, second and last vertices points out of the prism; VTK's wedge lists the first triangle the
// other way round (its normal into the prism).
TEST(CellType, PrismFacetsAreOutwardAndItsReflectionSwapsXiAndEta) {
  const CellType t = CellType::kPrism6;
  const int* p = cell_reflection(t);
  for (int a = 0; a < 6; ++a) {
    Eigen::VectorXd x = ref_point(t, a);
    std::swap(x[0], x[1]);
    EXPECT_LT((ref_point(t, p[a]) - x).norm(), 1e-15) << "node " << a;
  }
  const Eigen::Vector3d centre(1.0 / 3, 1.0 / 3, 0.5);
  for (int f = 0; f < cell_num_facets(t); ++f) {
    const int* loc = cell_facet_nodes(t, f);
    const int nfv = cell_num_vertices(cell_facet_type(t, f));
    EXPECT_EQ(nfv, f < 2 ? 3 : 4);
    const Eigen::Vector3d a = ref_point(t, loc[1]) - ref_point(t, loc[0]);
    const Eigen::Vector3d b = ref_point(t, loc[nfv - 1]) - ref_point(t, loc[0]);
    const Eigen::Vector3d normal = a.cross(b);
    EXPECT_GT(normal.dot(ref_point(t, loc[0]) - centre), 0.0) << "facet " << f;
    for (int v = 0; v < nfv; ++v)  // every vertex on the facet's plane
      EXPECT_NEAR(normal.dot(ref_point(t, loc[v]) - ref_point(t, loc[0])), 0.0, 1e-15) << "facet " << f;
  }
  const int* vtk = vtk_node_order(t);
  const Eigen::Vector3d v0 = ref_point(t, vtk[0]), v1 = ref_point(t, vtk[1]), v2 = ref_point(t, vtk[2]);
  EXPECT_LT((v1 - v0).cross(v2 - v0).dot(ref_point(t, vtk[3]) - v0), 0.0);
  EXPECT_EQ(vtk_cell_type(t), 13);
}

// The 18-node prism: its reflection maps each node to the mirrored reference point; VTK's node k
// (VTK_BIQUADRATIC_QUADRATIC_WEDGE, vtkBiQuadraticQuadraticWedge.h) is the midpoint of VTK's edges
// (0 1) (1 2) (2 0) (3 4) (4 5) (5 3) (0 3) (1 4) (2 5), then the centre of its sides (0 1 4 3) (1 2 5 4)
// (2 0 3 5), all in VTK's numbering.
TEST(CellType, Prism18ReflectionAndVtkOrder) {
  const CellType t = CellType::kPrism18;
  const int* p = cell_reflection(t);
  for (int a = 0; a < 18; ++a) {
    Eigen::VectorXd x = ref_point(t, a);
    std::swap(x[0], x[1]);
    EXPECT_LT((ref_point(t, p[a]) - x).norm(), 1e-15) << "node " << a;
  }
  const int* vtk = vtk_node_order(t);
  const auto at = [&](int k) { return ref_point(t, vtk[k]); };
  const int edges[9][2] = {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {0, 3}, {1, 4}, {2, 5}};
  for (int e = 0; e < 9; ++e)
    EXPECT_LT((at(6 + e) - 0.5 * (at(edges[e][0]) + at(edges[e][1]))).norm(), 1e-15) << "VTK edge node " << 6 + e;
  const int sides[3][4] = {{0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
  for (int s = 0; s < 3; ++s) {
    Eigen::VectorXd c = Eigen::VectorXd::Zero(3);
    for (int v : sides[s]) c += 0.25 * at(v);
    EXPECT_LT((at(15 + s) - c).norm(), 1e-15) << "VTK side node " << 15 + s;
  }
  // Each facet's nodes, past its vertices, at the midpoints of its edges (and its side's centre).
  for (int f = 0; f < 5; ++f) {
    const int* loc = cell_facet_nodes(t, f);
    const int nv = f < 2 ? 3 : 4;
    for (int e = 0; e < nv; ++e) {
      const Eigen::VectorXd m = 0.5 * (ref_point(t, loc[e]) + ref_point(t, loc[(e + 1) % nv]));
      EXPECT_LT((ref_point(t, loc[nv + e]) - m).norm(), 1e-15) << "facet " << f << " edge " << e;
    }
  }
  EXPECT_EQ(vtk_cell_type(t), 32);
}

// VTK's node k of a Hex27 (VTK_TRIQUADRATIC_HEXAHEDRON, vtkTriQuadraticHexahedron.h) is the centroid of
// the VTK vertices listed here; vtk_node_order() must pick the Gmsh node at that point.
TEST(CellType, VtkOrderOfHexahedraMatchesVtkDefinition) {
  const std::vector<std::vector<int>> vtk27 = {
      {0}, {1}, {2}, {3}, {4}, {5}, {6}, {7}, {0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4},
      {0, 4}, {1, 5}, {2, 6}, {3, 7}, {0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 2, 6, 7}, {0, 1, 2, 3},
      {4, 5, 6, 7}, {0, 1, 2, 3, 4, 5, 6, 7}};
  for (CellType t : {CellType::kHex20, CellType::kHex27, CellType::kQuad8, CellType::kQuad9}) {
    const int* order = vtk_node_order(t);
    for (int k = 0; k < cell_num_nodes(t); ++k) {
      // Quadrilaterals: VTK_QUADRATIC_QUAD and VTK_BIQUADRATIC_QUAD list vertices, edges m01 m12 m23 m30, centre.
      const std::vector<int> quad_def[9] = {{0}, {1}, {2}, {3}, {0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 1, 2, 3}};
      const std::vector<int>& def = cell_dim(t) == 3 ? vtk27[k] : quad_def[k];
      Eigen::VectorXd x = Eigen::VectorXd::Zero(cell_dim(t));
      for (int v : def) x += ref_point(t, v) / static_cast<double>(def.size());
      EXPECT_LT((ref_point(t, order[k]) - x).norm(), 1e-15) << cell_name(t) << " VTK node " << k;
    }
  }
  EXPECT_EQ(vtk_cell_type(CellType::kQuad4), 9);
  EXPECT_EQ(vtk_cell_type(CellType::kQuad8), 23);
  EXPECT_EQ(vtk_cell_type(CellType::kQuad9), 28);
  EXPECT_EQ(vtk_cell_type(CellType::kHex8), 12);
  EXPECT_EQ(vtk_cell_type(CellType::kHex20), 25);
  EXPECT_EQ(vtk_cell_type(CellType::kHex27), 29);
}

// Every node is the mean of its node_vertices() in the reference cell (whose order-1 map is affine on
// each edge and face), for every type.
TEST(CellType, NodesAreTheMeansOfTheirVertices) {
  for (int k = 1; k <= static_cast<int>(CellType::kPyramid14); ++k) {
    const auto t = static_cast<CellType>(k);
    for (int a = 0; a < cell_num_nodes(t); ++a) {
      const std::vector<int> from = node_vertices(t, a);
      Eigen::VectorXd x = Eigen::VectorXd::Zero(cell_dim(t));
      for (int v : from) {
        EXPECT_LT(v, cell_num_vertices(t));
        x += ref_point(t, v) / static_cast<double>(from.size());
      }
      EXPECT_LT((ref_point(t, a) - x).norm(), 1e-15) << cell_name(t) << " node " << a;
    }
  }
}

// The pyramids: the reflection mirrors ξ and η; each facet (the four triangles, then the base) has its
// vertices on one face of the reference pyramid, its right-hand normal out of it and its other nodes at
// the midpoints of its edges (and the base's centre); VTK's quadratic pyramid (vtkQuadraticPyramid.h)
// lists the midpoints of (0 1) (1 2) (2 3) (3 0) (0 4) (1 4) (2 4) (3 4).
TEST(CellType, PyramidFacetsReflectionAndVtkOrder) {
  for (CellType t : {CellType::kPyramid5, CellType::kPyramid13, CellType::kPyramid14}) {
    const int* p = cell_reflection(t);
    for (int a = 0; a < cell_num_nodes(t); ++a) {
      Eigen::VectorXd x = ref_point(t, a);
      std::swap(x[0], x[1]);
      EXPECT_LT((ref_point(t, p[a]) - x).norm(), 1e-15) << cell_name(t) << " node " << a;
    }
    const Eigen::Vector3d centre(0.4, 0.4, 0.2);
    for (int f = 0; f < cell_num_facets(t); ++f) {
      const CellType ft = cell_facet_type(t, f);
      const int* loc = cell_facet_nodes(t, f);
      const int nfv = cell_num_vertices(ft);
      EXPECT_EQ(nfv, f < 4 ? 3 : 4);
      const Eigen::Vector3d a = ref_point(t, loc[1]) - ref_point(t, loc[0]);
      const Eigen::Vector3d b = ref_point(t, loc[nfv - 1]) - ref_point(t, loc[0]);
      const Eigen::Vector3d normal = a.cross(b);
      EXPECT_GT(normal.dot(ref_point(t, loc[0]) - centre), 0.0) << cell_name(t) << " facet " << f;
      for (int k = 0; k < cell_num_nodes(ft); ++k) {
        EXPECT_NEAR(normal.dot(ref_point(t, loc[k]) - ref_point(t, loc[0])), 0.0, 1e-15) << "facet " << f;
        if (k < nfv || k >= 2 * nfv) continue;
        const Eigen::Vector3d m = 0.5 * (ref_point(t, loc[k - nfv]) + ref_point(t, loc[(k - nfv + 1) % nfv]));
        EXPECT_LT((ref_point(t, loc[k]) - m).norm(), 1e-15) << cell_name(t) << " facet " << f << " node " << k;
      }
    }
    const int* vtk = vtk_node_order(t);
    const int edges[8][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 4}, {2, 4}, {3, 4}};
    for (int k = 0; k < vtk_num_nodes(t); ++k) {
      const Eigen::Vector3d x = k < 5 ? ref_point(t, k) : 0.5 * (ref_point(t, edges[k - 5][0]) + ref_point(t, edges[k - 5][1]));
      EXPECT_LT((ref_point(t, vtk[k]) - x).norm(), 1e-15) << cell_name(t) << " VTK node " << k;
    }
    EXPECT_EQ(vtk_cell_type(t), cell_order(t) == 1 ? 14 : 27);
  }
  EXPECT_EQ(vtk_num_nodes(CellType::kPyramid14), 13);
}

// The 15-node prism is the 18-node one without the sides' centres, in its nodes, facets, reflection and
// VTK order (VTK_QUADRATIC_WEDGE, the first 15 of the biquadratic wedge's).
TEST(CellType, Prism15IsPrism18WithoutTheSidesCentres) {
  const CellType t = CellType::kPrism15, u = CellType::kPrism18;
  for (int a = 0; a < 15; ++a) {
    EXPECT_LT((ref_point(t, a) - ref_point(u, a)).norm(), 1e-15);
    EXPECT_EQ(cell_reflection(t)[a], cell_reflection(u)[a]);
    EXPECT_EQ(vtk_node_order(t)[a], vtk_node_order(u)[a]);
  }
  for (int f = 0; f < 5; ++f) {
    EXPECT_EQ(cell_facet_type(t, f), f < 2 ? CellType::kTri6 : CellType::kQuad8);
    for (int k = 0; k < cell_num_nodes(cell_facet_type(t, f)); ++k)
      EXPECT_EQ(cell_facet_nodes(t, f)[k], cell_facet_nodes(u, f)[k]);
  }
  EXPECT_EQ(vtk_cell_type(t), 26);
}
