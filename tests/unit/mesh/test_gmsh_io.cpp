#include "symcontact/mesh/gmsh_io.hpp"

#include <gtest/gtest.h>

#include "support/temp_folder.hpp"
#include "symcontact/core/error.hpp"
#include "symcontact/energy/external_load.hpp"

using namespace symcontact;

namespace {
const std::string kGeo = std::string(SYMCONTACT_TEST_DATA) + "/geo/";
}

TEST(GmshIo, TwoBodiesFromOneGeoGetTheirOwnNodes) {
  MeshReadOptions opt;
  opt.dim = 2;
  const MeshFile f = read_mesh_file(kGeo + "two_blocks.geo", opt);
  const Mesh lower = extract_body(f, 2, "lower", "body[0].group");
  const Mesh upper = extract_body(f, 2, "upper", "body[1].group");
  EXPECT_EQ(lower.first_cell_type(), CellType::kTri3);
  ASSERT_TRUE(lower.facet_groups.count("interface"));
  ASSERT_TRUE(upper.facet_groups.count("interface"));
  EXPECT_FALSE(upper.facet_groups.count("bottom"));
  EXPECT_TRUE(lower.node_groups.count("origin"));
  // The interface's length is 1 seen from either body, and the outward normals are opposite.
  Eigen::VectorXd nl, nu;
  EXPECT_NEAR(facet_group_measure(lower, lower.facet_groups.at("interface"), &nl), 1.0, 1e-12);
  EXPECT_NEAR(facet_group_measure(upper, upper.facet_groups.at("interface"), &nu), 1.0, 1e-12);
  EXPECT_NEAR(nl[1], 1.0, 1e-12);
  EXPECT_NEAR(nu[1], -1.0, 1e-12);
  for (Index v = 0; v < upper.num_nodes(); ++v) EXPECT_GE(upper.x(1, v), 1.0 - 1e-12);
}

TEST(GmshIo, MeshSizeRefines) {
  MeshReadOptions opt;
  opt.dim = 2;
  const Mesh coarse = extract_body(read_mesh_file(kGeo + "two_blocks.geo", opt), 2, "lower", "g");
  opt.mesh_size = 0.05;
  const Mesh fine = extract_body(read_mesh_file(kGeo + "two_blocks.geo", opt), 2, "lower", "g");
  EXPECT_GT(fine.num_cells(), 10 * coarse.num_cells());
}

TEST(GmshIo, SecondOrderNodesLieOnTheCircle) {
  MeshReadOptions opt;
  opt.dim = 2;
  opt.order = 2;
  const Mesh m = extract_body(read_mesh_file(kGeo + "disk.geo", opt), 2, "disk", "g");
  EXPECT_EQ(m.first_cell_type(), CellType::kTri6);
  const auto& rim = m.facet_groups.at("rim");
  ASSERT_GT(m.num_facets(rim), 8);
  for (Index k = 0; k < m.num_facets(rim); ++k)
    EXPECT_NEAR(m.x.col(rim.facets[3 * k + 2]).norm(), 1.0, 1e-10);  // the edge node of a Line3
  // With curved edges the rim length converges fast to 2π.
  EXPECT_NEAR(facet_group_measure(m, rim), 2 * M_PI, 1e-4);
}

TEST(GmshIo, TetrahedraFromOpenCascadeBox) {
  for (int order = 1; order <= 2; ++order) {
    MeshReadOptions opt;
    opt.dim = 3;
    opt.order = order;
    opt.mesh_size = 0.4;
    const Mesh m = extract_body(read_mesh_file(kGeo + "cube.geo", opt), 3, "cube", "g");
    EXPECT_EQ(m.first_cell_type(), order == 1 ? CellType::kTet4 : CellType::kTet10);
    for (const char* face : {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"}) {
      ASSERT_TRUE(m.facet_groups.count(face)) << face;
      EXPECT_NEAR(facet_group_measure(m, m.facet_groups.at(face)), 1.0, 1e-12) << face;
    }
  }
}

TEST(GmshIo, MissingGroupNamesTheKeyAndTheKnownGroups) {
  MeshReadOptions opt;
  const MeshFile f = read_mesh_file(kGeo + "two_blocks.geo", opt);
  try {
    extract_body(f, 2, "middle", "body[0].group");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "body[0].group");
    EXPECT_NE(e.message().find("'middle'"), std::string::npos) << e.what();
    EXPECT_NE(e.message().find("'lower'"), std::string::npos) << e.what();
  }
}

TEST(GmshIo, MalformedFilesAreInputErrors) {
  const symcontact::testing::TempFolder folder;
  folder.write("bad.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 2 1 2\ngarbage\n");
  folder.write("bad.geo", "Point(1) = {0, 0, 0};\nLine(1) = {1, 2};\n");
  folder.write("mesh.stl", "solid\n");
  MeshReadOptions opt;
  for (const std::string name : {"bad.msh", "bad.geo", "mesh.stl", "absent.msh"}) {
    const std::string path = (folder / name).string();
    try {
      read_mesh_file(path, opt);
      FAIL() << name;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), path);
      EXPECT_FALSE(e.message().empty());
    }
  }
}

namespace {
std::size_t cell_count(const MeshFile& f) {
  std::size_t n = 0;
  for (const auto& b : f.all_cells) n += b.tags.size();
  return n;
}
}  // namespace

TEST(GmshIo, PredictedCellCountIsALowerEstimateOfTheActualCount) {
  // The unit square and the unit cube fill their bounding boxes: the actual count is above the
  // estimate (2·A/h², 6·V/h³), near the full-box count of equilateral triangles (2.3·A/h²); Gmsh's
  // tetrahedra are smaller than regular ones of edge h (1125 at h = 0.25, 2.9 times the estimate).
  const double unit[3] = {1.0, 1.0, 0.0}, cube[3] = {1.0, 1.0, 1.0};
  EXPECT_DOUBLE_EQ(predicted_cell_count(2, unit, 0.1), 200.0);
  EXPECT_DOUBLE_EQ(predicted_cell_count(3, cube, 0.5), 48.0);
  const double xz[3] = {2.0, 0.0, 1.0};  // a 2D geometry in the xz plane
  EXPECT_DOUBLE_EQ(predicted_cell_count(2, xz, 1.0), 4.0);
  MeshReadOptions opt;
  opt.dim = 2;
  opt.mesh_size = 0.05;
  const double tri = static_cast<double>(cell_count(read_mesh_file(kGeo + "square.geo", opt)));
  EXPECT_GE(tri, predicted_cell_count(2, unit, 0.05));
  EXPECT_LE(tri, 1.5 * predicted_cell_count(2, unit, 0.05));
  opt.dim = 3;
  opt.mesh_size = 0.25;
  const double tet = static_cast<double>(cell_count(read_mesh_file(kGeo + "cube.geo", opt)));
  EXPECT_GE(tet, predicted_cell_count(3, cube, 0.25));
  EXPECT_LE(tet, 4.0 * predicted_cell_count(3, cube, 0.25));
}

TEST(GmshIo, MeshSizeAboveTheCellLimitIsRefusedNamingItsKey) {
  MeshReadOptions opt;
  opt.dim = 2;
  opt.mesh_size = 0.05;  // predicted 800 triangles
  opt.mesh_size_key = "problem.mesh_size";
  opt.max_predicted_cells = 500;
  try {
    read_mesh_file(kGeo + "square.geo", opt);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("problem.mesh_size = 0.05 would make about 800 triangles"), std::string::npos)
        << e.what();
    EXPECT_NE(e.message().find("limit of 500 cells"), std::string::npos) << e.what();
  }
  opt.max_predicted_cells = 0;  // no limit (--allow-large-mesh)
  EXPECT_NO_THROW(read_mesh_file(kGeo + "square.geo", opt));
}

// A .geo that subdivides or recombines its mesh is counted in the cells it asks for: three quadrilaterals per
// triangle, one per two, four hexahedra per tetrahedron.
TEST(GmshIo, MeshSizeLimitCountsTheCellsTheGeoAsksFor) {
  const symcontact::testing::TempFolder dir("symcontact_cell_limit_");
  struct Case {
    const char* option;
    int dim;
    const char* geo;
    double mesh_size;
    const char* expected;
  };
  const Case cases[] = {
      {"Mesh.SubdivisionAlgorithm = 1;", 2, "square.geo", 0.05, "about 2.4e+03 quadrilaterals (three per"},
      {"Mesh.RecombineAll = 1;", 2, "square.geo", 0.05, "about 400 quadrilaterals (one per two"},
      {"Mesh.SubdivisionAlgorithm = 2;", 3, "cube.geo", 0.25, "about 1.54e+03 hexahedra (four per"}};
  int n = 0;
  for (const Case& c : cases) {
    const std::string text = std::string(c.option) + "\nInclude \"" + kGeo + c.geo + "\";\n";
    const std::string path = dir.write(std::to_string(++n) + ".geo", text).string();
    MeshReadOptions opt;
    opt.dim = c.dim;
    opt.mesh_size = c.mesh_size;
    opt.max_predicted_cells = 100;
    try {
      read_mesh_file(path, opt);
      ADD_FAILURE() << c.option << ": no error";
    } catch (const InputError& e) {
      EXPECT_NE(e.message().find(c.expected), std::string::npos) << e.what();
    }
  }
}

// A recombined .geo gives quadrilaterals: Quad4 at order 1; at order 2 Gmsh makes Quad9 (complete), or Quad8
// when the file sets Mesh.SecondOrderIncomplete = 1. Edge nodes of the rim lie on the circle.
TEST(GmshIo, RecombinedSurfaceGivesQuadrilaterals) {
  MeshReadOptions opt;
  opt.dim = 2;
  const Mesh q4 = extract_body(read_mesh_file(kGeo + "disk_quads.geo", opt), 2, "disk", "g");
  EXPECT_EQ(q4.first_cell_type(), CellType::kQuad4);
  EXPECT_NEAR(facet_group_measure(q4, q4.facet_groups.at("rim")), 2 * M_PI, 0.1);
  opt.order = 2;
  const Mesh q9 = extract_body(read_mesh_file(kGeo + "disk_quads.geo", opt), 2, "disk", "g");
  EXPECT_EQ(q9.first_cell_type(), CellType::kQuad9);
  EXPECT_NEAR(facet_group_measure(q9, q9.facet_groups.at("rim")), 2 * M_PI, 1e-3);
  const auto& rim = q9.facet_groups.at("rim");
  for (Index k = 0; k < q9.num_facets(rim); ++k) EXPECT_NEAR(q9.x.col(rim.facets[3 * k + 2]).norm(), 1.0, 1e-10);
  const symcontact::testing::TempFolder tmp;
  const std::string incomplete =
      tmp.write("disk_quad8.geo", symcontact::testing::read_text(kGeo + "disk_quads.geo") +
                                      "\nMesh.SecondOrderIncomplete = 1;\n").string();
  const Mesh q8 = extract_body(read_mesh_file(incomplete, opt), 2, "disk", "g");
  EXPECT_EQ(q8.first_cell_type(), CellType::kQuad8);
  EXPECT_EQ(q8.num_cells(), q9.num_cells());
}

TEST(GmshIo, RecombinedVolumeGivesHexahedra) {
  const CellType expected[3] = {CellType::kHex8, CellType::kHex27, CellType::kHex20};
  const symcontact::testing::TempFolder tmp;
  for (int k = 0; k < 3; ++k) {
    MeshReadOptions opt;
    opt.dim = 3;
    opt.order = k == 0 ? 1 : 2;
    std::string path = kGeo + "cube_hexes.geo";
    if (k == 2)  // Hex20: the incomplete (serendipity) second order
      path = tmp.write("cube_hex20.geo", symcontact::testing::read_text(path) + "\nMesh.SecondOrderIncomplete = 1;\n")
                 .string();
    const Mesh m = extract_body(read_mesh_file(path, opt), 3, "cube", "g");
    EXPECT_EQ(m.first_cell_type(), expected[k]);
    EXPECT_EQ(m.num_cells(), 27);
    EXPECT_EQ(m.facet_cell_type(), facet_type(expected[k]));
    for (const char* face : {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"}) {
      ASSERT_TRUE(m.facet_groups.count(face)) << face;
      Eigen::VectorXd n;
      EXPECT_NEAR(facet_group_measure(m, m.facet_groups.at(face), &n), 1.0, 1e-12) << face;
      EXPECT_NEAR(n.norm(), 1.0, 1e-12) << face;
    }
    EXPECT_NEAR(facet_group_measure(m, m.facet_groups.at("xmax"), nullptr), 1.0, 1e-12);
  }
}

// A body half recombined: quadrilaterals on the left square, triangles on the right, in one mesh of two cell
// blocks sharing the nodes of x = 1; at order 2 the quadrilaterals are Quad9 and the triangles Tri6.
TEST(GmshIo, BodyMixingTrianglesAndQuadrilateralsKeepsBothTypes) {
  for (int order : {1, 2}) {
    MeshReadOptions opt;
    opt.dim = 2;
    opt.order = order;
    const MeshFile f = read_mesh_file(kGeo + "square_mixed.geo", opt);
    const Mesh m = extract_body(f, 2, "block", "body[0].group");
    ASSERT_TRUE(m.mixed()) << order;
    const CellType quad = order == 1 ? CellType::kQuad4 : CellType::kQuad9;
    const CellType tri = order == 1 ? CellType::kTri3 : CellType::kTri6;
    Index quads = 0, tris = 0;
    for (const auto& [t, n] : m.cell_type_counts()) {
      EXPECT_TRUE(t == quad || t == tri) << cell_name(t);
      (t == quad ? quads : tris) += n;
    }
    EXPECT_GT(quads, 0);
    EXPECT_GT(tris, 0);
    EXPECT_EQ(quads + tris, m.num_cells());
    // Every cell is of the type of its block, with that type's node count and a positive Jacobian.
    for (const CellBlock& b : m.cell_blocks)
      for (Index c = b.begin; c < b.end; ++c) {
        EXPECT_EQ(m.cell_type(c), b.type);
        EXPECT_EQ(m.nodes_per_cell(c), cell_num_nodes(b.type));
        EXPECT_GT(simplex_determinant(m, c), 0.0);
        // The quadrilaterals are in the left square, the triangles in the right one.
        double xc = 0.0;
        for (int a = 0; a < cell_num_vertices(b.type); ++a) xc += m.x(0, m.cell(c)[a]) / cell_num_vertices(b.type);
        EXPECT_EQ(xc < 1.0, b.type == quad) << m.cell_label(c);
      }
    // The bottom spans both squares: facets of quadrilaterals and of triangles alike.
    EXPECT_NEAR(facet_group_measure(m, m.facet_groups.at("bottom")), 2.0, 1e-12);
    EXPECT_EQ(m.cell_types_label().find(cell_name(quad)) != std::string::npos, true) << m.cell_types_label();
    EXPECT_EQ(m.cell_types_label().find(cell_name(tri)) != std::string::npos, true) << m.cell_types_label();
  }
}

// A hex-dominant body: hexahedra, tetrahedra and the pyramids Gmsh builds between them, in one mesh. Gmsh
// 4.8 cannot build pyramids again in a process once it was finalised and initialised anew (it aborts): the
// same .geo read again with the same options is the mesh remembered from the first read, and another .geo
// with quadrilateral faces is refused with the way out (a .msh). ctest runs each test in a process of its own; run alone,
// this test must be the process's first to mesh pyramids.
TEST(GmshIo, HexDominantGeoGivesPyramidsAndASecondMeshingIsRefused) {
  MeshReadOptions opt;
  opt.dim = 3;
  const MeshFile file = read_mesh_file(kGeo + "hex_tet.geo", opt);
  const Mesh m = extract_body(file, 3, "block", "g");
  EXPECT_EQ(m.cell_types_label(), "hex8 (18) + tet4 (240) + pyramid5 (9)");
  EXPECT_NO_THROW(m.check());
  const Mesh again = extract_body(read_mesh_file(kGeo + "hex_tet.geo", opt), 3, "block", "g");
  EXPECT_EQ(again.cells, m.cells);
  EXPECT_EQ(again.x, m.x);
  try {
    read_mesh_file(kGeo + "cube_hexes.geo", opt);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot build pyramids twice in one process"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("gmsh -3 -order 1"), std::string::npos) << e.what();
  }
  // Tetrahedra alone are meshed as before.
  EXPECT_NO_THROW(read_mesh_file(kGeo + "cube.geo", opt));
}
