#include "symcontact/contact/contact_surface.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

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
