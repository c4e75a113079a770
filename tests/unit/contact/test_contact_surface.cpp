#include "symcontact/contact/contact_surface.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "symcontact/contact/closest_point.hpp"
#include "symcontact/fem/quadrature.hpp"
#include "symcontact/fem/shape_functions.hpp"
#include "symcontact/mesh/gmsh_io.hpp"
#include "symcontact/mesh/structured.hpp"

using namespace symcontact;

namespace {

const std::string kGeo = std::string(SYMCONTACT_TEST_DATA) + "/geo/";

Eigen::MatrixXd facet_coords(const ContactSurface& s, const Eigen::MatrixXd& x, Index f) {
  Eigen::MatrixXd xf(s.dim, s.nodes_per_facet());
  for (int a = 0; a < s.nodes_per_facet(); ++a) xf.col(a) = x.col(s.facet(f)[a]);
  return xf;
}

}  // namespace

class ContactSurfaceTop : public ::testing::TestWithParam<int> {};

TEST_P(ContactSurfaceTop, NodesOrientationValenceAndAreas) {
  const int order = GetParam();
  const int nx = 5;
  const double x0 = -1.0, x1 = 2.0, h = (x1 - x0) / nx, ytop = 0.75;
  const Mesh m = rectangle_mesh(x0, 0.0, x1, ytop, nx, 2, order);
  const ContactSurface s = make_contact_surface(m, "top", 3, "block.top");
  EXPECT_EQ(s.name, "block.top");
  EXPECT_EQ(s.body, 3);
  EXPECT_FALSE(s.is_rigid());
  EXPECT_EQ(s.dim, 2);
  EXPECT_EQ(s.facet_type, order == 1 ? CellType::kLine2 : CellType::kLine3);
  EXPECT_EQ(s.num_facets(), nx);
  EXPECT_EQ(s.num_nodes(), order == 1 ? nx + 1 : 2 * nx + 1);
  ASSERT_EQ(s.X.cols(), s.num_nodes());
  ASSERT_EQ(static_cast<Index>(s.valence.size()), s.num_nodes());
  ASSERT_EQ(s.nodal_area.size(), s.num_nodes());

  for (Index k = 0; k < s.num_nodes(); ++k) {
    // X is the body's coordinates of the mapped node, and every node is on the top edge.
    EXPECT_EQ(s.X.col(k), m.x.col(s.nodes[k]));
    EXPECT_NEAR(s.X(1, k), ytop, 1e-15);
  }
  // Outward orientation: the normal of every facet (at any ξ) is +y with norm = dS/dξ = h.
  for (Index f = 0; f < s.num_facets(); ++f) {
    const Eigen::MatrixXd xf = facet_coords(s, s.X, f);
    for (double xi : {0.0, 0.3, 1.0}) {
      const Eigen::VectorXd n = facet_normal(s.facet_type, xf, &xi);
      ASSERT_EQ(n.size(), 2);
      EXPECT_NEAR(n.x(), 0.0, 1e-14);
      EXPECT_NEAR(n.y(), h, 1e-14);
    }
  }
  // Valence and lumped areas by position along the edge.
  double total = 0.0;
  for (Index k = 0; k < s.num_nodes(); ++k) {
    const double t = (s.X(0, k) - x0) / h;  // 0 .. nx, half-integers at P2 midnodes
    const bool end = std::abs(t) < 1e-12 || std::abs(t - nx) < 1e-12;
    const bool mid = std::abs(t - std::round(t)) > 0.25;
    total += s.nodal_area[k];
    if (mid) {
      EXPECT_EQ(order, 2);
      EXPECT_EQ(s.valence[k], 0);
      EXPECT_NEAR(s.nodal_area[k], 2.0 * h / 3.0, 1e-14);
    } else if (end) {
      EXPECT_EQ(s.valence[k], 1);
      EXPECT_NEAR(s.nodal_area[k], order == 1 ? h / 2 : h / 6, 1e-14);
    } else {
      EXPECT_EQ(s.valence[k], 2);
      EXPECT_NEAR(s.nodal_area[k], order == 1 ? h : h / 3, 1e-14);
    }
  }
  EXPECT_NEAR(total, x1 - x0, 1e-13);
  // Smoothed normals of a flat edge are exactly +y, ends included.
  const Eigen::MatrixXd n = nodal_normals(s, s.X);
  for (Index k = 0; k < s.num_nodes(); ++k) {
    EXPECT_NEAR(n(0, k), 0.0, 1e-14);
    EXPECT_NEAR(n(1, k), 1.0, 1e-14);
  }
}

TEST_P(ContactSurfaceTop, BottomGroupPointsDown) {
  const Mesh m = rectangle_mesh(0.0, 0.0, 1.0, 1.0, 3, 3, GetParam());
  const ContactSurface s = make_contact_surface(m, "bottom", 0, "b");
  const Eigen::MatrixXd n = nodal_normals(s, s.X);
  for (Index k = 0; k < s.num_nodes(); ++k) EXPECT_NEAR(n(1, k), -1.0, 1e-14);
  const ContactSurface r = make_contact_surface(m, "right", 0, "r");
  const Eigen::MatrixXd nr = nodal_normals(r, r.X);
  for (Index k = 0; k < r.num_nodes(); ++k) EXPECT_NEAR(nr(0, k), 1.0, 1e-14);
}

TEST_P(ContactSurfaceTop, CurrentPositionsAddTheDisplacement) {
  const Mesh m = rectangle_mesh(0.0, 0.0, 1.0, 0.5, 4, 2, GetParam());
  const Mesh other = rectangle_mesh(0.0, 1.0, 1.0, 1.5, 3, 2, GetParam());
  DofMap dofs(2);
  dofs.add_body(other.num_nodes());
  const int body = dofs.add_body(m.num_nodes());
  const ContactSurface s = make_contact_surface(m, "top", body, "m.top");
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  VectorXd u(dofs.num_dofs());
  for (Index i = 0; i < u.size(); ++i) u[i] = U(rng);
  const Eigen::MatrixXd x = current_positions(s, dofs, u);
  ASSERT_EQ(x.rows(), 2);
  ASSERT_EQ(x.cols(), s.num_nodes());
  for (Index k = 0; k < s.num_nodes(); ++k)
    for (int i = 0; i < 2; ++i)
      EXPECT_EQ(x(i, k), s.X(i, k) + u[dofs.offset(body) + 2 * s.nodes[k] + i]);
  // A rigid surface ignores u.
  const ContactSurface rigid = make_contact_surface(m, "top", -1, "rigid");
  EXPECT_TRUE(rigid.is_rigid());
  EXPECT_EQ(current_positions(rigid, dofs, u), rigid.X);
}

INSTANTIATE_TEST_SUITE_P(ContactSurface, ContactSurfaceTop, ::testing::Values(1, 2),
                         [](const ::testing::TestParamInfo<int>& param_info) { return "P" + std::to_string(param_info.param); });

TEST(ContactSurface, MissingGroupThrowsOutOfRange) {
  const Mesh m = rectangle_mesh(0.0, 0.0, 1.0, 1.0, 2, 2);
  EXPECT_THROW(make_contact_surface(m, "nope", 0, "x"), std::out_of_range);
}

TEST(ContactSurface, DiskRimNormalsAreRadial) {
  double worst[3] = {0, 0, 0};
  for (int order = 1; order <= 2; ++order) {
    MeshReadOptions opt;
    opt.dim = 2;
    opt.order = order;
    const Mesh m = extract_body(read_mesh_file(kGeo + "disk.geo", opt), 2, "disk", "g");
    const ContactSurface s = make_contact_surface(m, "rim", 0, "disk.rim");
    ASSERT_GT(s.num_facets(), 8);
    // A closed curve: every vertex has valence 2, midnodes 0.
    for (Index k = 0; k < s.num_nodes(); ++k) {
      const bool vertex = s.valence[k] > 0;
      EXPECT_EQ(s.valence[k], vertex ? 2 : 0);
    }
    // Facets are oriented outward: the facet normal at the middle points away from the centre.
    for (Index f = 0; f < s.num_facets(); ++f) {
      const Eigen::MatrixXd xf = facet_coords(s, s.X, f);
      const double half = 0.5;
      const Eigen::VectorXd n = facet_normal(s.facet_type, xf, &half);
      EXPECT_GT(n.dot(0.5 * (xf.col(0) + xf.col(1))), 0.0) << "facet " << f;
    }
    const Eigen::MatrixXd n = nodal_normals(s, s.X);
    for (Index k = 0; k < s.num_nodes(); ++k) {
      EXPECT_NEAR(n.col(k).norm(), 1.0, 1e-14);
      const Eigen::Vector2d radial = s.X.col(k).normalized();
      const double err = (n.col(k) - radial).norm();
      worst[order] = std::max(worst[order], err);
    }
    EXPECT_LT(worst[order], 1e-2) << "order " << order;
    EXPECT_NEAR(s.nodal_area.sum(), 2 * M_PI, order == 1 ? 0.05 : 1e-3);
  }
  EXPECT_LT(worst[2], worst[1]);
}

// ---------------------------------------------------------------------------------------------------
// 3D surfaces (Tri3, Tri6) and the modified Tri6 test basis.

/// The cells of the box: Tet4, Tet10 (box_mesh()) or Hex8, Hex20, Hex27 (tensor_mesh(), quadrilateral faces;
/// Hex20's Quad8 faces with the modified test basis, whose lumped areas are positive too).
class ContactSurfaceBox : public ::testing::TestWithParam<CellType> {};

TEST_P(ContactSurfaceBox, OutwardNormalsBorderAndAreas) {
  const CellType cells = GetParam();
  const bool hex = cell_shape(cells) == CellShape::kTensor;
  const Mesh m = hex ? tensor_mesh(cells, Vec3(0, 0, 0), Vec3(2, 1, 0.5), 4, 3, 2)
                     : box_mesh(Vec3(0, 0, 0), Vec3(2, 1, 0.5), 4, 3, 2, cell_order(cells));
  for (const char* name : {"zmax", "zmin", "xmax", "ymin"}) {
    const ContactSurface s = make_contact_surface(m, name, 0, name);
    EXPECT_EQ(s.dim, 3);
    EXPECT_EQ(s.facet_type, facet_type(cells));
    const std::string g = name;
    const int axis = g[0] - 'x';
    const double sign = g.substr(1) == "max" ? 1.0 : -1.0;
    // Smoothed normals: exactly ±e_axis, at every node.
    const Eigen::MatrixXd n = nodal_normals(s, s.X);
    for (Index k = 0; k < s.num_nodes(); ++k)
      EXPECT_NEAR((n.col(k) - sign * Eigen::Vector3d::Unit(axis)).norm(), 0.0, 1e-14) << name;
    // Facet normals are outward with norm dS/dξ = 2 × facet area (a triangle), the facet area (a rectangle).
    double area = 0.0;
    for (Index f = 0; f < s.num_facets(); ++f) {
      const double xi[2] = {0.2, 0.3};
      const Eigen::VectorXd nf = facet_normal(s.facet_type, facet_coords(s, s.X, f), xi);
      EXPECT_GT(sign * nf[axis], 0.0);
      area += (hex ? 1.0 : 0.5) * nf.norm();
    }
    // Lumped areas: all positive (P2 too, with the modified test basis), summing to the face area.
    const double face = (axis == 0 ? 1 * 0.5 : axis == 1 ? 2 * 0.5 : 2 * 1);
    EXPECT_NEAR(area, face, 1e-13);
    EXPECT_NEAR(s.nodal_area.sum(), face, 1e-13);
    EXPECT_GT(s.nodal_area.minCoeff(), 0.0);
    // Border: the edges on the face's perimeter, and their vertices.
    const int ne = facet_num_edges(s.facet_type);
    ASSERT_EQ(s.boundary_edge.size(), ne * static_cast<std::size_t>(s.num_facets()));
    double border = 0.0;
    for (Index f = 0; f < s.num_facets(); ++f)
      for (int e = 0; e < ne; ++e)
        if (s.boundary_edge[ne * f + e])
          border += (s.X.col(s.facet(f)[facet_edge(s.facet_type, e)[0]]) -
                     s.X.col(s.facet(f)[facet_edge(s.facet_type, e)[1]]))
                        .norm();
    const double perimeter = axis == 0 ? 3.0 : axis == 1 ? 5.0 : 6.0;
    EXPECT_NEAR(border, perimeter, 1e-13) << name;
    const Eigen::VectorXd lo = s.X.rowwise().minCoeff(), hi = s.X.rowwise().maxCoeff();
    for (Index k = 0; k < s.num_nodes(); ++k) {
      bool on_perimeter = false;
      for (int i = 0; i < 3; ++i)
        if (i != axis && (std::abs(s.X(i, k) - lo[i]) < 1e-12 || std::abs(s.X(i, k) - hi[i]) < 1e-12)) on_perimeter = true;
      if (s.valence[k] > 0) {
        EXPECT_EQ(s.boundary_vertex[k] != 0, on_perimeter) << name << " node " << k;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(ContactSurface, ContactSurfaceBox,
                         ::testing::Values(CellType::kTet4, CellType::kTet10, CellType::kHex8, CellType::kHex20,
                                           CellType::kHex27),
                         [](const ::testing::TestParamInfo<CellType>& p) {
                           if (p.param == CellType::kTet4) return std::string("P1");
                           if (p.param == CellType::kTet10) return std::string("P2");
                           return cell_name(p.param);
                         });

TEST(ContactSurfaceTestBasis, ModifiedTri6BasisIsAPartitionOfUnityWithPositiveIntegrals) {
  // A curved Tri6 (edge nodes lifted) and a flat one: Σ φ_a = 1 everywhere, ∫ φ_a > 0 for every a, and on
  // the flat one ∫ φ_v = 2A/15, ∫ φ_e = A/5 — while the standard vertex functions integrate to 0.
  const QuadratureRule rule = simplex_quadrature(2, 8);
  Eigen::MatrixXd flat(3, 6), curved(3, 6);
  flat << 0, 2, 0, 1, 1, 0,  //
      0, 0, 1, 0, 0.5, 0.5,  //
      0, 0, 0, 0, 0, 0;
  curved = flat;
  curved.row(2) << 0, 0, 0, 0.3, 0.2, 0.25;
  for (const Eigen::MatrixXd* xf : {&flat, &curved}) {
    double phi_int[6] = {}, N_int[6] = {}, A = 0.0;
    for (int q = 0; q < rule.size(); ++q) {
      double phi[6], N[6];
      test_functions(CellType::kTri6, rule.point(q), phi);
      shape_functions(CellType::kTri6, rule.point(q), N, nullptr);
      double sum = 0.0;
      for (double v : phi) sum += v;
      EXPECT_NEAR(sum, 1.0, 1e-14);
      const double J = facet_normal(CellType::kTri6, *xf, rule.point(q)).norm();
      A += rule.weights[q] * J;
      for (int a = 0; a < 6; ++a) {
        phi_int[a] += rule.weights[q] * J * phi[a];
        N_int[a] += rule.weights[q] * J * N[a];
      }
    }
    for (int a = 0; a < 6; ++a) EXPECT_GT(phi_int[a], 0.05 * A) << "node " << a;
    if (xf == &flat) {
      for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(N_int[a], 0.0, 1e-14);
        EXPECT_NEAR(phi_int[a], 2.0 * A / 15.0, 1e-14);
        EXPECT_NEAR(phi_int[3 + a], A / 5.0, 1e-14);
      }
    }
  }
  // Other facet types keep the shape functions.
  const double xi[2] = {0.2, 0.3};
  double phi[3], N[3];
  test_functions(CellType::kTri3, xi, phi);
  shape_functions(CellType::kTri3, xi, N, nullptr);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(phi[a], N[a]);
}

TEST(ContactSurfaceTestBasis, UniformTractionIsRecoveredAtEveryTri6Node) {
  // Consistent nodal forces of a uniform traction t on a P2 face, F_k = ∫ t N_k dS (zero at the vertices),
  // turned into the test basis and divided by the lumped areas: t at every node.
  const Mesh m = box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), 3, 2, 2, 2);
  const ContactSurface s = make_contact_surface(m, "zmax", 0, "top");
  const Eigen::Vector3d t(0.1, -0.2, -1.0);
  Eigen::MatrixXd F = Eigen::MatrixXd::Zero(3, s.num_nodes());
  const QuadratureRule rule = simplex_quadrature(2, 4);
  for (Index f = 0; f < s.num_facets(); ++f)
    for (int q = 0; q < rule.size(); ++q) {
      double N[6];
      shape_functions(CellType::kTri6, rule.point(q), N, nullptr);
      const double J = facet_normal(CellType::kTri6, facet_coords(s, s.X, f), rule.point(q)).norm();
      for (int a = 0; a < 6; ++a) F.col(s.facet(f)[a]) += rule.weights[q] * J * N[a] * t;
    }
  const Eigen::MatrixXd T = test_basis_forces(s, F);
  for (Index k = 0; k < s.num_nodes(); ++k) EXPECT_NEAR((T.col(k) / s.nodal_area[k] - t).norm(), 0.0, 1e-13);
}
