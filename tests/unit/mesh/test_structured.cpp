#include "symcontact/mesh/structured.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <set>
#include <tuple>

#include "symcontact/core/error.hpp"
#include "symcontact/energy/external_load.hpp"

using namespace symcontact;

TEST(StructuredMesh, RectangleAndBoxArePositiveAndFacetsLocated) {
  for (int order = 1; order <= 2; ++order) {
    Mesh r = rectangle_mesh(0, 0, 2, 1, 4, 3, order);
    EXPECT_EQ(r.num_cells(), 24);
    EXPECT_EQ(r.num_nodes(), order == 1 ? 20 : (9 * 7));
    EXPECT_NO_THROW(r.check());
    EXPECT_EQ(r.num_facets(r.facet_groups.at("top")), 4);
    EXPECT_EQ(r.num_facets(r.facet_groups.at("left")), 3);
    Mesh b = box_mesh(Vec3(0, 0, 0), Vec3(1, 2, 3), 2, 2, 2, order);
    EXPECT_EQ(b.num_cells(), 48);
    EXPECT_NO_THROW(b.check());
    EXPECT_EQ(b.num_facets(b.facet_groups.at("zmax")), 8);
    EXPECT_EQ(b.num_nodes(), order == 1 ? 27 : 125);
  }
}

TEST(Mesh, OrientCellsFlipsClockwiseTrianglesConsistently) {
  Mesh m = rectangle_mesh(0, 0, 1, 1, 2, 2, 2);
  // Flip every other cell by hand (swap v1, v2 and the edge nodes), then reorient.
  for (Index c = 0; c < m.num_cells(); c += 2) {
    Index* n = m.cell(c);
    std::swap(n[1], n[2]);
    std::swap(n[3], n[5]);
  }
  EXPECT_EQ(m.orient_cells(), m.num_cells() / 2);
  EXPECT_NO_THROW(m.check());
  for (Index c = 0; c < m.num_cells(); ++c) {
    const Index* n = m.cell(c);
    // Edge nodes sit at the midpoints of the edges they are named for.
    EXPECT_TRUE(m.x.col(n[3]).isApprox(0.5 * (m.x.col(n[0]) + m.x.col(n[1]))));
    EXPECT_TRUE(m.x.col(n[4]).isApprox(0.5 * (m.x.col(n[1]) + m.x.col(n[2]))));
    EXPECT_TRUE(m.x.col(n[5]).isApprox(0.5 * (m.x.col(n[2]) + m.x.col(n[0]))));
  }
}

TEST(Mesh, CheckRejectsDegenerateCellNamingIt) {
  Mesh m = rectangle_mesh(0, 0, 1, 1, 1, 1, 1);
  m.x.col(m.cell(1)[2]) = 0.5 * (m.x.col(m.cell(1)[0]) + m.x.col(m.cell(1)[1]));  // collapse cell 2
  try {
    m.check();
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cell"), std::string::npos) << e.what();
  }
}

TEST(Mesh, FacetInsideTheBodyMakesANodeGroupAndOneOfNoCellIsRejected) {
  Mesh m = rectangle_mesh(0, 0, 2, 1, 2, 1, 1);
  // The interior vertical edge x = 1 is shared by two cells: no longer a boundary group, its nodes kept.
  m.facet_groups["inside"].facets = {1, 4};
  ASSERT_NO_THROW(m.locate_facets());
  EXPECT_EQ(m.facet_groups.count("inside"), 0u);
  EXPECT_EQ(m.node_groups.at("inside"), (std::vector<Index>{1, 4}));
  ASSERT_EQ(m.interior_facet_groups.count("inside"), 1u);
  EXPECT_NE(m.interior_facet_groups.at("inside").find("inside the body"), std::string::npos);
  EXPECT_EQ(m.facet_groups.count("bottom"), 1u);
  // The segment from node 0 at (0, 0) to node 5 at (2, 1) is an edge of no cell.
  m.facet_groups["diagonal"].facets = {0, 5};
  EXPECT_THROW(m.locate_facets(), InputError);
}

// Quadrilateral and hexahedral meshes: the cells tile the box (measures add up), pass Mesh::check(), have
// outward boundary groups of the right measure, and orient_cells() turns a reflected cell back.
TEST(StructuredMesh, TensorMeshesOfEveryType) {
  for (CellType t : {CellType::kQuad4, CellType::kQuad8, CellType::kQuad9, CellType::kHex8, CellType::kHex20,
                     CellType::kHex27}) {
    const int D = cell_dim(t);
    Mesh m = tensor_mesh(t, Vec3(0, 0, 0), Vec3(2, 1, 3), 3, 2, 2);
    EXPECT_NO_THROW(m.check()) << cell_name(t);
    EXPECT_EQ(m.num_cells(), D == 2 ? 6 : 12);
    const double volume = D == 2 ? 2.0 : 6.0;
    DofMap dofs(D);
    dofs.add_body(m.num_nodes());
    const VectorXd f = body_force_vector(m, dofs, 0, [&](const double*, double* b) { b[0] = 1, b[1] = 0, b[2] = 0; });
    double total = 0;
    for (Index v = 0; v < m.num_nodes(); ++v) total += f[dofs.dof(0, v, 0)];
    EXPECT_NEAR(total, volume, 1e-12) << cell_name(t);
    const char* side = D == 2 ? "right" : "xmax";
    Eigen::VectorXd n;
    EXPECT_NEAR(facet_group_measure(m, m.facet_groups.at(side), &n), D == 2 ? 1.0 : 3.0, 1e-12) << cell_name(t);
    EXPECT_NEAR(n[0], D == 2 ? 1.0 : 3.0, 1e-12) << cell_name(t);
    // Reflect cell 0: it is now negative and is turned back.
    const int* p = cell_reflection(t);
    std::vector<Index> c0(m.cell(0), m.cell(0) + m.nodes_per_cell(0));
    for (int a = 0; a < m.nodes_per_cell(0); ++a) m.cells[a] = c0[p[a]];
    EXPECT_LT(simplex_determinant(m, 0), 0.0) << cell_name(t);
    EXPECT_EQ(m.orient_cells(), 1);
    EXPECT_NO_THROW(m.check()) << cell_name(t);
    perturb_interior_nodes(m, 0.5, 0.2, 7);
    EXPECT_NO_THROW(m.check()) << cell_name(t);
  }
}

// Quad4 + Tri3 and Quad9 + Tri6 in a checkerboard: blocks of one type each, every cell positive, the
// boundary groups located on cells of both types (the cut cells' triangles share the quadrilaterals' edges).
TEST(Mesh, MixedRectangleMeshHasBlocksOfBothTypes) {
  for (CellType q : {CellType::kQuad4, CellType::kQuad9}) {
    const Mesh m = mixed_rectangle_mesh(q, 0, 0, 2, 1, 4, 3);
    const CellType t = q == CellType::kQuad4 ? CellType::kTri3 : CellType::kTri6;
    ASSERT_TRUE(m.mixed());
    const auto counts = m.cell_type_counts();
    ASSERT_EQ(counts.size(), 2u);
    EXPECT_EQ(counts[0].first, t);  // cell (0, 0) is cut
    EXPECT_EQ(counts[0].second, 2 * 6);
    EXPECT_EQ(counts[1].first, q);
    EXPECT_EQ(counts[1].second, 6);
    EXPECT_EQ(m.num_cells(), 18);
    EXPECT_EQ(m.order(), cell_order(q));
    EXPECT_NO_THROW(m.check());
    EXPECT_EQ(m.cell_offsets.back(), static_cast<Index>(m.cells.size()));
    std::set<CellType> bottom_types;
    const FacetGroup& bottom = m.facet_groups.at("bottom");
    for (Index c : bottom.cell) bottom_types.insert(m.cell_type(c));
    EXPECT_EQ(bottom_types.size(), 2u) << cell_name(q);
    Eigen::VectorXd n;
    EXPECT_NEAR(facet_group_measure(m, bottom, &n), 2.0, 1e-12);
  }
}

// Prisms: triangles at z = 0 and 1, quadrilaterals on the sides, each group of one type and located
// on the cells with outward normals; every cell positive, reflected ones turned back.
TEST(Mesh, PrismMeshHasGroupsOfBothFacetTypes) {
  Mesh m = prism_mesh(CellType::kPrism6, Vec3(0, 0, 0), Vec3(1, 2, 3), 2, 3, 4);
  EXPECT_EQ(m.num_cells(), 2 * 2 * 3 * 4);
  EXPECT_NO_THROW(m.check());
  for (const auto& [name, area, type] : {std::tuple{"zmin", 2.0, CellType::kTri3}, std::tuple{"zmax", 2.0, CellType::kTri3},
                                         std::tuple{"xmin", 6.0, CellType::kQuad4}, std::tuple{"ymax", 3.0, CellType::kQuad4}}) {
    const FacetGroup& g = m.facet_groups.at(name);
    EXPECT_EQ(m.facet_type_of(g), type) << name;
    Eigen::VectorXd n;
    EXPECT_NEAR(facet_group_measure(m, g, &n), area, 1e-12) << name;
    EXPECT_NEAR(n.norm(), area, 1e-12) << name;  // a flat face: Σ n dA = its area times its outward normal
    const int axis = name[0] - 'x';
    EXPECT_NEAR(n[axis], name[1] == 'm' && name[2] == 'i' ? -area : area, 1e-12) << name;
  }
  const int* p = cell_reflection(CellType::kPrism6);
  std::vector<Index> c0(m.cell(0), m.cell(0) + 6);
  for (int a = 0; a < 6; ++a) m.cells[a] = c0[p[a]];
  EXPECT_LT(simplex_determinant(m, 0), 0.0);
  EXPECT_EQ(m.orient_cells(), 1);
  EXPECT_NO_THROW(m.check());
}

// Cells of another order or of another quadrilateral face cannot join a mesh; the others can.
TEST(Mesh, AddCellsRefusesTypesOfAnotherOrder) {
  Mesh m;
  const Index tri[3] = {0, 1, 2};
  m.add_cells(CellType::kTri3, tri, 1);
  const Index quad9[9] = {0, 1, 2, 3, 4, 5, 6, 7, 8};
  EXPECT_THROW(m.add_cells(CellType::kQuad9, quad9, 1), std::invalid_argument);
  EXPECT_THROW(m.add_cells(CellType::kTet4, tri, 0), std::invalid_argument);
  m.add_cells(CellType::kQuad4, quad9, 1);
  m.add_cells(CellType::kQuad4, quad9, 1);
  m.add_cells(CellType::kTri3, tri, 1);
  ASSERT_EQ(m.cell_blocks.size(), 3u);  // Tri3, Quad4 (two cells), Tri3
  EXPECT_EQ(m.cell_type(0), CellType::kTri3);
  EXPECT_EQ(m.cell_type(1), CellType::kQuad4);
  EXPECT_EQ(m.cell_type(2), CellType::kQuad4);
  EXPECT_EQ(m.cell_type(3), CellType::kTri3);
  EXPECT_EQ(m.nodes_per_cell(2), 4);
  EXPECT_EQ(m.cell(3) - m.cells.data(), 11);
  EXPECT_EQ(m.max_nodes_per_cell(), 4);
  EXPECT_EQ(m.cell_types_label(), "tri3 (2) + quad4 (2)");
  // 3D: tetrahedra, hexahedra, prisms and pyramids of one order join (pyramids between tetrahedra and
  // hexahedra); an 8-node quadrilateral face cannot meet a 9-node one.
  Mesh solid;
  solid.dim = 3;
  const Index tet[4] = {0, 1, 2, 3}, prism[6] = {0, 1, 2, 3, 4, 5}, hex[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  solid.add_cells(CellType::kTet4, tet, 1);
  solid.add_cells(CellType::kPrism6, prism, 1);
  solid.add_cells(CellType::kHex8, hex, 1);
  solid.add_cells(CellType::kPyramid5, hex, 1);
  EXPECT_EQ(solid.cell_types_label(), "tet4 (1) + prism6 (1) + hex8 (1) + pyramid5 (1)");
  EXPECT_THROW(solid.add_cells(CellType::kTet10, hex, 0), std::invalid_argument);
  EXPECT_TRUE(compatible_cell_types(CellType::kTet10, CellType::kHex27));
  EXPECT_TRUE(compatible_cell_types(CellType::kPyramid13, CellType::kHex20));
  EXPECT_TRUE(compatible_cell_types(CellType::kPrism15, CellType::kPyramid13));
  EXPECT_FALSE(compatible_cell_types(CellType::kHex20, CellType::kHex27));
  EXPECT_FALSE(compatible_cell_types(CellType::kPyramid14, CellType::kPrism15));
  EXPECT_FALSE(compatible_cell_types(CellType::kTet10, CellType::kPrism6));
}

// Pyramids: six per box, the box's faces their bases; the groups are quadrilaterals of the pyramids'
// bases with outward normals; the cells fill the box; a reflected pyramid is found and turned back, and one
// whose apex went through its base is refused by the mesh checks.
TEST(Mesh, PyramidMeshFillsTheBoxAndItsChecksSeeInvertedPyramids) {
  for (CellType t : {CellType::kPyramid5, CellType::kPyramid13, CellType::kPyramid14}) {
    Mesh m = pyramid_mesh(t, Vec3(0, 0, 0), Vec3(1, 2, 3), 2, 3, 4);
    EXPECT_EQ(m.num_cells(), 6 * 2 * 3 * 4);
    EXPECT_NO_THROW(m.check());
    for (const auto& [name, area] : {std::pair{"zmin", 2.0}, std::pair{"xmax", 6.0}, std::pair{"ymin", 3.0}}) {
      const FacetGroup& g = m.facet_groups.at(name);
      EXPECT_EQ(m.facet_type_of(g), cell_facet_type(t, 4)) << name;
      Eigen::VectorXd n;
      EXPECT_NEAR(facet_group_measure(m, g, &n), area, 1e-12) << name;
      EXPECT_NEAR(n.norm(), area, 1e-12) << name;
    }
    double volume = 0.0;
    for (Index c = 0; c < m.num_cells(); ++c) {
      const Index* v = m.cell(c);  // a straight pyramid: a third of its base times its height
      const Vec3 a = m.x.col(v[1]) - m.x.col(v[0]), b = m.x.col(v[3]) - m.x.col(v[0]), h = m.x.col(v[4]) - m.x.col(v[0]);
      volume += a.cross(b).dot(h) / 3.0;
    }
    EXPECT_NEAR(volume, 6.0, 1e-12) << cell_name(t);
  }
  Mesh m = pyramid_mesh(CellType::kPyramid5, Vec3(0, 0, 0), Vec3(1, 1, 1), 1, 1, 1);
  const int* p = cell_reflection(CellType::kPyramid5);
  std::vector<Index> c0(m.cell(0), m.cell(0) + 5);
  for (int a = 0; a < 5; ++a) m.cells[a] = c0[p[a]];
  EXPECT_LT(simplex_determinant(m, 0), 0.0);
  EXPECT_EQ(m.orient_cells(), 1);
  EXPECT_NO_THROW(m.check());
  m.x.col(m.cell(0)[4]) = 0.5 * (m.x.col(m.cell(0)[0]) + m.x.col(m.cell(0)[2])) - 0.1 * Vec3(0, 0, 1);
  // The apex of cell 0 (the box's centre) pushed through the base z = 0: every cell around it is inverted.
  EXPECT_THROW(m.check(), InputError);
}
