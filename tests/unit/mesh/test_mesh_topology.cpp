// Tests of the whole-body mesh checks (src/symcontact/mesh/mesh_topology.hpp): coincident nodes that
// share no cell (a crack) and bodies in several pieces, on structured meshes cut or duplicated by hand.
// What a problem may declare to allow them (a self-contact on the cut's faces, pieces held by a contact
// surface or a Dirichlet boundary) is tested on the same meshes with groups added by hand.
// The same faults read from .msh files, through the command line, are in tests/unit/app/test_cli.cpp.

#include "symcontact/mesh/mesh_topology.hpp"

#include <gtest/gtest.h>

#include "symcontact/core/error.hpp"
#include "symcontact/mesh/structured.hpp"

namespace symcontact {
namespace {

/// Two meshes side by side as one (nodes and cells of `b` after those of `a`; no node shared).
Mesh side_by_side(const Mesh& a, const Mesh& b) {
  Mesh m;
  m.dim = a.dim;
  m.x.resize(a.dim, a.num_nodes() + b.num_nodes());
  m.x << a.x, b.x;
  std::vector<Index> cells = a.cells;
  for (Index v : b.cells) cells.push_back(v + a.num_nodes());
  m.set_cells(a.first_cell_type(), std::move(cells));
  return m;
}

std::string message_of(const Mesh& m, const TopologyAllowances& allow = {}) {
  try {
    check_topology(m, allow);
  } catch (const InputError& e) {
    return e.message();
  }
  return "";
}

/// Two triangles on the edge (1,0)–(0,1): the first (0,0),(1,0),(0,1) counter-clockwise; the second with its
/// free vertex at `apex`, its vertices listed (1,0), apex, (0,1) — or (1,0), (0,1), apex when `clockwise`.
Mesh two_triangles(const Eigen::Vector2d& apex, bool clockwise) {
  Mesh m;
  m.dim = 2;
  m.x.resize(2, 4);
  m.x << 0, 1, 0, apex.x(), 0, 0, 1, apex.y();
  if (clockwise)
    m.set_cells(CellType::kTri3, {0, 1, 2, 1, 2, 3});
  else
    m.set_cells(CellType::kTri3, {0, 1, 2, 1, 3, 2});
  return m;
}

TEST(MeshTopology, CellsOnOppositeSidesOfTheirEdgeAreNotFolded) {
  // Whatever the orientation each is written in (two surfaces meshed the opposite way round).
  EXPECT_NO_THROW(check_folds(two_triangles({1, 1}, false)));
  EXPECT_NO_THROW(check_folds(two_triangles({1, 1}, true)));
  for (int order : {1, 2}) {
    EXPECT_NO_THROW(check_folds(rectangle_mesh(0, 0, 2, 1, 6, 3, order)));
    EXPECT_NO_THROW(check_folds(box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), 2, 2, 2, order)));
  }
}

TEST(MeshTopology, CellFoldedOverItsNeighbourIsNamed) {
  // The second triangle's apex on the first one's side of the common edge: they overlap.
  Mesh m = two_triangles({0.2, 0.2}, false);
  m.cell_tags = {7, 8};
  try {
    check_folds(m);
    FAIL() << "no fold found";
  } catch (const InputError& e) {
    // Element 8 is negatively oriented, element 7 positively; a tie counts as a positive majority.
    EXPECT_EQ(e.key(), "element 8");
    EXPECT_NE(e.message().find("folded element"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("edge shared with element 7"), std::string::npos) << e.message();
  }
  // In a larger mesh the odd one out is named: move an interior node of a structured mesh across a
  // neighbouring vertex so that the cells around it turn over.
  Mesh r = rectangle_mesh(0, 0, 1, 1, 2, 2);
  Index centre = -1;
  for (Index v = 0; v < r.num_nodes(); ++v)
    if ((r.x.col(v) - Eigen::Vector2d(0.5, 0.5)).norm() < 1e-12) centre = v;
  ASSERT_GE(centre, 0);
  r.x.col(centre) = Eigen::Vector2d(0.5, 1.4);  // above the top edge
  try {
    check_folds(r);
    FAIL() << "no fold found";
  } catch (const InputError& e) {
    const std::string label = e.key();
    Index named = -1;
    for (Index c = 0; c < r.num_cells(); ++c)
      if (r.cell_label(c) == label) named = c;
    ASSERT_GE(named, 0) << label;
    EXPECT_LT(simplex_determinant(r, named), 0.0) << "the folded cell is the one turned over";
  }
}

TEST(MeshTopology, StructuredMeshesAreOnePieceWithoutTwins) {
  for (int order : {1, 2}) {
    const Mesh tri = rectangle_mesh(0, 0, 2, 1, 6, 3, order);
    const Mesh tet = box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), 2, 2, 2, order);
    EXPECT_EQ(cell_components(tri), 1);
    EXPECT_EQ(cell_components(tet), 1);
    EXPECT_TRUE(coincident_nodes(tri).empty());
    EXPECT_TRUE(coincident_nodes(tet).empty());
    EXPECT_NO_THROW(check_topology(tri));
    EXPECT_NO_THROW(check_topology(tet));
  }
}

TEST(MeshTopology, TwoSeparateBlocksAreTwoComponents) {
  const Mesh m = side_by_side(rectangle_mesh(0, 0, 1, 1, 2, 2), rectangle_mesh(2, 0, 3, 1, 3, 1));
  std::vector<Index> component;
  EXPECT_EQ(cell_components(m, &component), 2);
  ASSERT_EQ(static_cast<Index>(component.size()), m.num_cells());
  EXPECT_EQ(component.front(), 0);
  EXPECT_EQ(component.back(), 1);
  const std::string msg = message_of(m);
  EXPECT_NE(msg.find("the body is disconnected: its elements form 2 separate pieces"), std::string::npos) << msg;
  EXPECT_NE(msg.find("8 elements from cell 1, 6 elements from cell 9"), std::string::npos) << msg;
}

TEST(MeshTopology, TouchingBlocksWithTheirOwnNodesAreACrack) {
  // Two unit squares meeting along x = 1, each with its own nodes there: 3 pairs of twins (ny = 2),
  // named by the file's node tags when the mesh has them.
  Mesh m = side_by_side(rectangle_mesh(0, 0, 1, 1, 1, 2), rectangle_mesh(1, 0, 2, 1, 1, 2));
  const auto twins = coincident_nodes(m);
  ASSERT_EQ(twins.size(), 3u);
  for (const auto& [a, b] : twins) EXPECT_EQ((m.x.col(a) - m.x.col(b)).norm(), 0.0);
  m.node_tags.resize(m.num_nodes());
  for (Index v = 0; v < m.num_nodes(); ++v) m.node_tags[v] = 100 + v;
  const std::string msg = message_of(m);
  EXPECT_NE(msg.find("3 pairs of nodes are at the same position without sharing any element"), std::string::npos)
      << msg;
  EXPECT_NE(msg.find("node " + std::to_string(100 + twins[0].first) + " and node " +
                     std::to_string(100 + twins[0].second) + " at (1, "),
            std::string::npos)
      << msg;
}

/// Two unit squares meeting along x = 1, each with its own nodes there (ny = 2: 3 pairs of twins), with the
/// node groups "left_face" (the first square's nodes on x = 1), "right_face" (the second's), "interface" (both),
/// "left_bottom" and "right_bottom" (each square's nodes on y = 0).
Mesh touching_squares() {
  Mesh m = side_by_side(rectangle_mesh(0, 0, 1, 1, 1, 2), rectangle_mesh(1, 0, 2, 1, 1, 2));
  const Index first = rectangle_mesh(0, 0, 1, 1, 1, 2).num_nodes();
  for (Index v = 0; v < m.num_nodes(); ++v) {
    const std::string side = v < first ? "left" : "right";
    if (m.x(0, v) == 1.0) {
      m.node_groups[side + "_face"].push_back(v);
      m.node_groups["interface"].push_back(v);
    }
    if (m.x(1, v) == 0.0) m.node_groups[side + "_bottom"].push_back(v);
  }
  return m;
}

TEST(MeshTopology, CutWhoseFacesAreInSelfContactIsAllowed) {
  const Mesh m = touching_squares();
  TopologyAllowances allow;
  allow.body = "blocks";
  allow.self_contacts = {{"interface", "interface"}};
  allow.contact_surfaces = {"interface"};
  EXPECT_NO_THROW(check_topology(m, allow));
  // The two faces as two groups of one pair, in either order.
  allow.self_contacts = {{"right_face", "left_face"}};
  allow.contact_surfaces = {"right_face", "left_face"};
  EXPECT_NO_THROW(check_topology(m, allow));
}

TEST(MeshTopology, CutWithOneFaceOutsideTheSelfContactIsRefused) {
  const Mesh m = touching_squares();
  TopologyAllowances allow;
  allow.body = "blocks";
  allow.contact_surfaces = {"left_face"};
  allow.self_contacts = {{"left_face", "left_face"}};  // the right square's twins are on no side of it
  std::string msg = message_of(m, allow);
  EXPECT_NE(msg.find("3 pairs of nodes are at the same position without sharing any element"), std::string::npos)
      << msg;
  EXPECT_NE(msg.find("a [[contact]] a = b = \"blocks.G\" (self-contact surfaces of this body: 'left_face')"),
            std::string::npos)
      << msg;
  // A contact between a face and the other square's bottom covers none of the twins either.
  allow.self_contacts = {{"left_face", "right_bottom"}};
  msg = message_of(m, allow);
  EXPECT_NE(msg.find("self-contact surfaces of this body: 'left_face' with 'right_bottom'"), std::string::npos) << msg;
  // Without any self-contact, the message says what would allow the cut.
  msg = message_of(m, TopologyAllowances{});
  EXPECT_NE(msg.find("declare the parts as separate bodies"), std::string::npos) << msg;
  EXPECT_NE(msg.find("\"<body>.G\" (self-contact surfaces of this body: none)"), std::string::npos) << msg;
}

TEST(MeshTopology, CutPartlyInSelfContactNamesTheOtherPairs) {
  Mesh m = touching_squares();
  // "top_pair": the twins at (1, 1) only, as a two-node group on both squares.
  for (Index v : m.node_groups["interface"])
    if (m.x(1, v) == 1.0) m.node_groups["top_pair"].push_back(v);
  TopologyAllowances allow;
  allow.self_contacts = {{"top_pair", "top_pair"}};
  const std::string msg = message_of(m, allow);
  EXPECT_NE(msg.find("2 pairs of nodes are at the same position"), std::string::npos) << msg;
  EXPECT_NE(msg.find("and on no self-contact of the body (1 other pair is on one, allowed)"), std::string::npos) << msg;
  EXPECT_EQ(msg.find("at (1, 1)"), std::string::npos) << "the covered pair is not listed: " << msg;
}

TEST(MeshTopology, PiecesEachHeldAreAllowed) {
  // Two separate squares: held by a contact surface on one and a Dirichlet boundary on the other.
  Mesh m = side_by_side(rectangle_mesh(0, 0, 1, 1, 2, 2), rectangle_mesh(2, 0, 3, 1, 3, 1));
  for (Index v = 0; v < m.num_nodes(); ++v) {
    if (m.x(0, v) == 1.0) m.node_groups["a_right"].push_back(v);
    if (m.x(0, v) == 3.0 && m.x(1, v) == 0.0) m.node_groups["b_corner"].push_back(v);
  }
  TopologyAllowances allow;
  allow.contact_surfaces = {"a_right"};
  allow.dirichlet_boundaries = {"b_corner"};
  EXPECT_NO_THROW(check_topology(m, allow));
  // The second square held by nothing: refused, naming it and the groups that hold pieces.
  allow.dirichlet_boundaries = {"absent_group"};  // a group the mesh lacks holds nothing
  std::string msg = message_of(m, allow);
  EXPECT_NE(msg.find("the body is disconnected: its elements form 2 separate pieces"), std::string::npos) << msg;
  EXPECT_NE(msg.find("and 1 of them (6 elements from cell 9) has no node on a contact surface or a Dirichlet "
                     "boundary of the body (contact surfaces: 'a_right'; Dirichlet boundaries: 'absent_group')"),
            std::string::npos)
      << msg;
  EXPECT_NE(msg.find("or hold every piece"), std::string::npos) << msg;
  // Neither held.
  msg = message_of(m, TopologyAllowances{});
  EXPECT_NE(msg.find("and none of them has a node on a contact surface"), std::string::npos) << msg;
}

TEST(MeshTopology, TouchingSquaresInSelfContactWithOneClampedAreAllowed) {
  // The V3 patch test as one body: twins covered by the self-contact, both pieces held.
  const Mesh m = touching_squares();
  TopologyAllowances allow;
  allow.self_contacts = {{"interface", "interface"}};
  allow.contact_surfaces = {"interface"};
  allow.dirichlet_boundaries = {"left_bottom"};
  EXPECT_NO_THROW(check_topology(m, allow));
  allow.self_contacts.clear();  // the pieces are held, but the twins are not covered
  EXPECT_NE(message_of(m, allow).find("3 pairs of nodes"), std::string::npos);
}

TEST(MeshTopology, NearlyCoincidentNodesWithinTheTolerance) {
  Mesh m = side_by_side(rectangle_mesh(0, 0, 1, 1, 1, 1), rectangle_mesh(1, 0, 2, 1, 1, 1));
  m.x(0, 4) += 1e-13;  // a node of the second square, moved by far less than 1e-10 × the diagonal
  EXPECT_EQ(coincident_nodes(m).size(), 2u);
  m.x(0, 4) += 1e-6;  // now well apart
  EXPECT_EQ(coincident_nodes(m).size(), 1u);
}

TEST(MeshTopology, LargeStructuredMeshHasNoTwins) {
  // 40,401 nodes on a lattice whose columns share their x: the hash grid keeps this linear (a sweep
  // along x would compare every pair of a column).
  const Mesh m = rectangle_mesh(0, 0, 1, 1, 200, 200);
  EXPECT_TRUE(coincident_nodes(m).empty());
  EXPECT_EQ(cell_components(m), 1);
}

}  // namespace
}  // namespace symcontact
