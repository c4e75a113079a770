#include "symcontact/io/vtu_writer.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "symcontact/mesh/mesh.hpp"
#include "support/temp_folder.hpp"

namespace symcontact {
namespace {

namespace fs = std::filesystem;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// The unit square split along its diagonal into two triangles.
Mesh two_triangles() {
  Mesh m;
  m.dim = 2;
  m.x.resize(2, 4);
  m.x << 0.0, 1.0, 1.0, 0.0,  //
      0.0, 0.0, 1.0, 0.5;
  m.set_cells(CellType::kTri3, {0, 1, 2, 0, 2, 3});
  return m;
}

TEST(VtuWriter, TwoTrianglesAscii) {
  const testing::TempFolder folder;
  const fs::path& dir = folder.path();
  const Mesh m = two_triangles();
  VtuWriter w(m);
  EXPECT_EQ(w.num_points(), 4);
  EXPECT_EQ(w.num_cells(), 2);
  Eigen::MatrixXd u = Eigen::MatrixXd::Zero(3, 4);
  u(0, 1) = 0.1;
  u(1, 2) = -2.5;
  w.add_point_data("displacement", u);
  w.add_point_data("pressure", Eigen::VectorXd::LinSpaced(4, 0.0, 3.0));
  Eigen::MatrixXd stress = Eigen::MatrixXd::Zero(6, 2);
  stress(0, 0) = 1.0 / 3.0;
  w.add_cell_data("stress", stress, {"XX", "YY", "ZZ", "XY", "YZ", "XZ"});
  w.add_cell_data("body", Eigen::VectorXd::Ones(2));
  const std::string path = (dir / "two.vtu").string();
  w.write(path);

  const std::string s = testing::read_text(path);
  EXPECT_TRUE(contains(s, "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\""));
  EXPECT_TRUE(contains(s, "<Piece NumberOfPoints=\"4\" NumberOfCells=\"2\">"));
  EXPECT_TRUE(contains(s, "<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" "
                          "format=\"ascii\">\n          0 0 0\n          0.1 0 0\n          0 -2.5 0\n"));
  EXPECT_TRUE(contains(s, "Name=\"pressure\" NumberOfComponents=\"1\" format=\"ascii\">\n          0\n          1\n"));
  EXPECT_TRUE(contains(s, "Name=\"stress\" NumberOfComponents=\"6\" ComponentName0=\"XX\" ComponentName1=\"YY\""));
  EXPECT_TRUE(contains(s, "\n          0.3333333333333333 0 0 0 0 0\n"));
  EXPECT_TRUE(contains(s, "Name=\"body\" NumberOfComponents=\"1\""));
  // Points padded to 3D.
  EXPECT_TRUE(contains(s, "Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n          0 0 0\n"
                          "          1 0 0\n          1 1 0\n          0 0.5 0\n"));
  EXPECT_TRUE(contains(s, "Name=\"connectivity\" format=\"ascii\">\n          0 1 2\n          0 2 3\n"));
  EXPECT_TRUE(contains(s, "Name=\"offsets\" format=\"ascii\">\n          3 6\n"));
  EXPECT_TRUE(contains(s, "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n          5 5\n"));
  // Point data before cell data before points before cells, as the format requires.
  EXPECT_LT(s.find("<PointData>"), s.find("<CellData>"));
  EXPECT_LT(s.find("<CellData>"), s.find("<Points>"));
  EXPECT_LT(s.find("<Points>"), s.find("<Cells>"));
  EXPECT_EQ(s.substr(s.size() - 11), "</VTKFile>\n");
  EXPECT_FALSE(contains(s, "AppendedData"));
}

// A piece holds its cells, the points they use (renumbered in their order) and the data of both; the .pvtu
// names the arrays of the pieces and the pieces themselves.
TEST(VtuWriter, PiecesOfAParallelVtu) {
  const testing::TempFolder folder;
  const fs::path& dir = folder.path();
  VtuWriter w(two_triangles());
  w.add_point_data("pressure", Eigen::VectorXd::LinSpaced(4, 0.0, 3.0));
  Eigen::MatrixXd stress = Eigen::MatrixXd::Zero(6, 2);
  stress(0, 1) = 5.0;
  w.add_cell_data("stress", stress, {"XX", "YY", "ZZ", "XY", "YZ", "XZ"});
  Eigen::MatrixXd cell_ids(1, 2);
  cell_ids << 10.0, 11.0;
  w.add_cell_data("id", cell_ids);
  std::vector<Index> used;
  const VtuWriter second = w.piece({1}, used);
  EXPECT_EQ(used, (std::vector<Index>{0, 2, 3}));
  EXPECT_EQ(second.num_points(), 3);
  EXPECT_EQ(second.num_cells(), 1);
  second.write((dir / "p1.vtu").string());
  const std::string s = testing::read_text((dir / "p1.vtu").string());
  EXPECT_TRUE(contains(s, "<Piece NumberOfPoints=\"3\" NumberOfCells=\"1\">"));
  EXPECT_TRUE(contains(s, "Name=\"pressure\" NumberOfComponents=\"1\" format=\"ascii\">\n          0\n          2\n"
                          "          3\n"));
  EXPECT_TRUE(contains(s, "Name=\"id\" NumberOfComponents=\"1\" format=\"ascii\">\n          11\n"));
  EXPECT_TRUE(contains(s, "format=\"ascii\">\n          5 0 0 0 0 0\n"));
  EXPECT_TRUE(contains(s, "Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n          0 0 0\n"
                          "          1 1 0\n          0 0.5 0\n"));
  EXPECT_TRUE(contains(s, "Name=\"connectivity\" format=\"ascii\">\n          0 1 2\n"));
  EXPECT_TRUE(contains(s, "Name=\"offsets\" format=\"ascii\">\n          3\n"));

  const VtuWriter first = w.piece({0}, used);
  EXPECT_EQ(used, (std::vector<Index>{0, 1, 2}));
  const VtuWriter none = w.piece({}, used);
  EXPECT_TRUE(used.empty());
  EXPECT_EQ(none.num_points(), 0);
  EXPECT_EQ(none.num_cells(), 0);
  EXPECT_THROW(w.piece({1, 2}, used), std::invalid_argument);
  // Cells in any order: the piece keeps it, its points in their order here.
  const VtuWriter both = w.piece({1, 0}, used);
  EXPECT_EQ(used, (std::vector<Index>{0, 1, 2, 3}));
  both.write((dir / "both.vtu").string());
  const std::string b = testing::read_text((dir / "both.vtu").string());
  EXPECT_TRUE(contains(b, "Name=\"id\" NumberOfComponents=\"1\" format=\"ascii\">\n          11\n          10\n"));
  EXPECT_TRUE(contains(b, "Name=\"offsets\" format=\"ascii\">\n          3 6\n"));
  const Eigen::MatrixXd centres = w.cell_centres();
  ASSERT_EQ(centres.cols(), 2);
  EXPECT_LT((centres.col(1) - Eigen::Vector3d(1.0 / 3.0, 0.5, 0.0)).norm(), 1e-15) << centres.col(1).transpose();

  first.write_parallel((dir / "two.pvtu").string(), {"p0.vtu", "p1.vtu"});
  const std::string p = testing::read_text((dir / "two.pvtu").string());
  EXPECT_TRUE(contains(p, "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\""));
  EXPECT_TRUE(contains(p, "<PPointData>\n      <PDataArray type=\"Float64\" Name=\"pressure\" NumberOfComponents=\"1\"/>\n"
                          "    </PPointData>\n"));
  EXPECT_TRUE(contains(p, "<PDataArray type=\"Float64\" Name=\"stress\" NumberOfComponents=\"6\" ComponentName0=\"XX\""));
  EXPECT_TRUE(contains(p, "<PPoints>\n      <PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>\n"));
  EXPECT_TRUE(contains(p, "    <Piece Source=\"p0.vtu\"/>\n    <Piece Source=\"p1.vtu\"/>\n"));
  EXPECT_LT(p.find("<PPointData>"), p.find("<PCellData>"));
  EXPECT_EQ(p.substr(p.size() - 11), "</VTKFile>\n");
}

// A mesh of two cell types: one type and one offset per cell, the cells in mesh order.
TEST(VtuWriter, MixedTrianglesAndQuadrilateralAscii) {
  const testing::TempFolder folder;
  Mesh m;
  m.dim = 2;
  m.x.resize(2, 5);
  m.x << 0.0, 1.0, 1.0, 0.0, 2.0,  //
      0.0, 0.0, 1.0, 1.0, 0.5;
  const Index quad[4] = {0, 1, 2, 3}, tri[3] = {1, 4, 2};
  m.add_cells(CellType::kQuad4, quad, 1);
  m.add_cells(CellType::kTri3, tri, 1);
  VtuWriter w(m);
  EXPECT_EQ(w.num_cells(), 2);
  w.add_cell_data("body", Eigen::VectorXd::Ones(2));
  const std::string path = (folder.path() / "mixed.vtu").string();
  w.write(path);
  const std::string s = testing::read_text(path);
  EXPECT_TRUE(contains(s, "<Piece NumberOfPoints=\"5\" NumberOfCells=\"2\">"));
  EXPECT_TRUE(contains(s, "Name=\"connectivity\" format=\"ascii\">\n          0 1 2 3\n          1 4 2\n")) << s;
  EXPECT_TRUE(contains(s, "Name=\"offsets\" format=\"ascii\">\n          4 7\n"));
  EXPECT_TRUE(contains(s, "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n          9 5\n"));
}

TEST(VtuWriter, Tet10SwapsLastEdgeNodes) {
  const testing::TempFolder folder;
  const fs::path& dir = folder.path();
  Mesh m;
  m.dim = 3;
  m.x.resize(3, 10);
  const Eigen::Vector3d v[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int k = 0; k < 4; ++k) m.x.col(k) = v[k];
  // Gmsh edge order m01 m12 m20 m30 m32 m31.
  const int edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}};
  for (int e = 0; e < 6; ++e) m.x.col(4 + e) = 0.5 * (v[edges[e][0]] + v[edges[e][1]]);
  m.set_cells(CellType::kTet10, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9});
  VtuWriter w(m);
  const std::string path = (dir / "tet10.vtu").string();
  w.write(path);
  const std::string s = testing::read_text(path);
  EXPECT_TRUE(contains(s, "<Piece NumberOfPoints=\"10\" NumberOfCells=\"1\">"));
  // VTK order m01 m12 m20 m30 m31 m32: our nodes 8 (m32) and 9 (m31) swap.
  EXPECT_TRUE(contains(s, "Name=\"connectivity\" format=\"ascii\">\n          0 1 2 3 4 5 6 7 9 8\n"));
  EXPECT_TRUE(contains(s, "Name=\"offsets\" format=\"ascii\">\n          10\n"));
  EXPECT_TRUE(contains(s, "Name=\"types\" format=\"ascii\">\n          24\n"));
}

// VTK has no 14-node pyramid: Pyramid14 is written as VTK's 13-node quadratic pyramid (type 27), its
// edges in VTK's order (0 1) (1 2) (2 3) (3 0) (0 4) (1 4) (2 4) (3 4), the base's centre left out.
TEST(VtuWriter, Pyramid14IsWrittenAsAQuadraticPyramid) {
  const testing::TempFolder folder;
  Mesh m;
  m.dim = 3;
  m.x = Eigen::MatrixXd::Random(3, 14);
  std::vector<Index> cell(14);
  for (int a = 0; a < 14; ++a) cell[a] = a;
  m.set_cells(CellType::kPyramid14, cell);
  VtuWriter w(m);
  const std::string path = (folder.path() / "pyramid14.vtu").string();
  w.write(path);
  const std::string s = testing::read_text(path);
  EXPECT_TRUE(contains(s, "<Piece NumberOfPoints=\"14\" NumberOfCells=\"1\">"));
  // Gmsh's m01 m03 m04 m12 m14 m23 m24 m34 are nodes 5..12.
  EXPECT_TRUE(contains(s, "Name=\"connectivity\" format=\"ascii\">\n          0 1 2 3 4 5 8 10 6 7 9 11 12\n")) << s;
  EXPECT_TRUE(contains(s, "Name=\"offsets\" format=\"ascii\">\n          13\n"));
  EXPECT_TRUE(contains(s, "Name=\"types\" format=\"ascii\">\n          27\n"));
}

TEST(VtuWriter, RawFacetsAndEmptySurface) {
  const testing::TempFolder folder;
  const fs::path& dir = folder.path();
  Eigen::MatrixXd p(3, 3);
  p << 0, 1, 2,  //
      0, 0, 0,   //
      0, 0, 1;
  VtuWriter w(p, CellType::kLine2, {0, 1, 1, 2});
  w.add_cell_data("normal_stress", Eigen::VectorXd::Constant(2, -4.0));
  const std::string path = (dir / "surface.vtu").string();
  w.write(path);
  const std::string s = testing::read_text(path);
  EXPECT_TRUE(contains(s, "Name=\"connectivity\" format=\"ascii\">\n          0 1\n          1 2\n"));
  EXPECT_TRUE(contains(s, "Name=\"types\" format=\"ascii\">\n          3 3\n"));
  EXPECT_TRUE(contains(s, "          2 0 1\n"));

  VtuWriter empty(p, CellType::kTri3, {});
  EXPECT_EQ(empty.num_cells(), 0);
  empty.write((dir / "empty.vtu").string());
  EXPECT_TRUE(contains(testing::read_text(dir / "empty.vtu"), "NumberOfCells=\"0\""));
}

TEST(VtuWriter, ManyCellsWrapOffsetLines) {
  const testing::TempFolder folder;
  const fs::path& dir = folder.path();
  Eigen::MatrixXd p = Eigen::MatrixXd::Zero(1, 12);
  std::vector<Index> conn;
  for (Index c = 0; c < 11; ++c) conn.insert(conn.end(), {c, c + 1});
  VtuWriter w(p, CellType::kLine2, conn);
  w.write((dir / "line.vtu").string());
  EXPECT_TRUE(contains(testing::read_text(dir / "line.vtu"),
                       "Name=\"offsets\" format=\"ascii\">\n          2 4 6 8 10 12 14 16 18 20\n          22\n"));
}

TEST(VtuWriter, ValidatesSizesNamingTheArray) {
  const Mesh m = two_triangles();
  VtuWriter w(m);
  auto expect_message = [](auto&& f, const std::string& part) {
    try {
      f();
      FAIL() << "expected std::invalid_argument mentioning " << part;
    } catch (const std::invalid_argument& e) {
      EXPECT_TRUE(contains(e.what(), part)) << e.what();
    }
  };
  expect_message([&] { w.add_point_data("u", Eigen::MatrixXd::Zero(3, 5)); }, "'u'");
  expect_message([&] { w.add_point_data("p", Eigen::VectorXd::Zero(2)); }, "'p'");
  expect_message([&] { w.add_cell_data("s", Eigen::MatrixXd::Zero(6, 4)); }, "'s'");
  expect_message([&] { w.add_cell_data("e", Eigen::MatrixXd::Zero(0, 2)); }, "'e'");
  expect_message([&] { w.add_cell_data("c", Eigen::MatrixXd::Zero(2, 2), {"only one"}); }, "'c'");
  expect_message([&] { w.add_point_data("", Eigen::VectorXd::Zero(4)); }, "empty name");
  w.add_point_data("u", Eigen::MatrixXd::Zero(3, 4));
  expect_message([&] { w.add_point_data("u", Eigen::MatrixXd::Zero(3, 4)); }, "'u' added twice");
  w.add_cell_data("u", Eigen::VectorXd::Zero(2));  // same name in cell data is fine

  Eigen::MatrixXd p = Eigen::MatrixXd::Zero(3, 3);
  EXPECT_THROW(VtuWriter(p, CellType::kTri3, {0, 1}), std::invalid_argument);
  EXPECT_THROW(VtuWriter(p, CellType::kTri3, {0, 1, 3}), std::invalid_argument);
  EXPECT_THROW(VtuWriter(p, CellType::kTri3, {0, 1, -1}), std::invalid_argument);
  EXPECT_THROW(VtuWriter(Eigen::MatrixXd::Zero(4, 3), CellType::kTri3, {0, 1, 2}), std::invalid_argument);
}

TEST(VtuWriter, AsciiRejectsNonFinite) {
  const testing::TempFolder folder;
  const fs::path& dir = folder.path();
  VtuWriter w(two_triangles());
  Eigen::VectorXd p = Eigen::VectorXd::Zero(4);
  p(2) = std::numeric_limits<double>::quiet_NaN();
  w.add_point_data("pressure", p);
  const std::string path = (dir / "nan.vtu").string();
  try {
    w.write(path);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_TRUE(contains(e.what(), "'pressure'")) << e.what();
  }
  EXPECT_FALSE(fs::exists(path));
  w.set_encoding(VtuEncoding::kBinaryAppended);
  w.write(path);  // binary keeps NaN
  EXPECT_TRUE(fs::exists(path));
}

/// The raw block at `offset` of the appended section of a binary .vtu: its UInt64 size header and bytes.
std::string appended_block(const std::string& s, std::uint64_t offset) {
  const std::size_t start = s.find('_', s.find("<AppendedData encoding=\"raw\">")) + 1;
  std::uint64_t bytes = 0;
  std::memcpy(&bytes, s.data() + start + offset, sizeof(bytes));
  return s.substr(start + offset + sizeof(bytes), bytes);
}

TEST(VtuWriter, BinaryAppendedRoundTrips) {
  const testing::TempFolder folder;
  const fs::path& dir = folder.path();
  VtuWriter w(two_triangles());
  w.set_encoding(VtuEncoding::kBinaryAppended);
  Eigen::MatrixXd u = Eigen::MatrixXd::Random(3, 4);
  u(1, 3) = std::numeric_limits<double>::infinity();
  w.add_point_data("displacement", u);
  w.add_cell_data("id", Eigen::Vector2d(7.0, 8.0));
  const std::string path = (dir / "bin.vtu").string();
  w.write(path);
  const std::string s = testing::read_text(path);
  EXPECT_TRUE(contains(s, "header_type=\"UInt64\""));
  // Offsets: each block is an 8-byte header then the data.
  const std::uint64_t off_u = 0, off_id = off_u + 8 + 12 * 8, off_pts = off_id + 8 + 2 * 8;
  const std::uint64_t off_conn = off_pts + 8 + 12 * 8, off_offsets = off_conn + 8 + 6 * 8;
  const std::uint64_t off_types = off_offsets + 8 + 2 * 8;
  EXPECT_TRUE(contains(s, "Name=\"displacement\" NumberOfComponents=\"3\" format=\"appended\" offset=\"0\"/>"));
  EXPECT_TRUE(contains(s, "Name=\"id\" NumberOfComponents=\"1\" format=\"appended\" offset=\"" +
                              std::to_string(off_id) + "\"/>"));
  EXPECT_TRUE(contains(s, "Name=\"types\" format=\"appended\" offset=\"" + std::to_string(off_types) + "\"/>"));

  const std::string ub = appended_block(s, off_u);
  ASSERT_EQ(ub.size(), 12 * sizeof(double));
  Eigen::MatrixXd u_back(3, 4);
  std::memcpy(u_back.data(), ub.data(), ub.size());
  EXPECT_TRUE((u_back.array() == u.array()).all());

  const std::string cb = appended_block(s, off_conn);
  ASSERT_EQ(cb.size(), 6 * sizeof(std::int64_t));
  std::int64_t conn[6];
  std::memcpy(conn, cb.data(), cb.size());
  EXPECT_EQ(std::vector<std::int64_t>(conn, conn + 6), (std::vector<std::int64_t>{0, 1, 2, 0, 2, 3}));

  EXPECT_EQ(appended_block(s, off_types), std::string("\x05\x05"));
  EXPECT_EQ(s.substr(s.size() - 30), "\n  </AppendedData>\n</VTKFile>\n");
}

}  // namespace
}  // namespace symcontact
