#include "symcontact/contact/contact_points.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <tuple>

#include "symcontact/contact/polygon_clipping.hpp"
#include "symcontact/fem/shape_functions.hpp"
#include "symcontact/mesh/structured.hpp"

using namespace symcontact;

namespace {

/// A slave face (top of a box, size 1/ns) under a master face (bottom of a box above it, size 1/nm),
/// with the master covering [mx0, mx1] × [0, 1] and a gap `gap`.
struct Faces3D {
  Mesh lower, upper;
  ContactSurface slave, master;
};

/// `cells`: Tet4 or Tet10 (box_mesh(), triangle faces), or Hex8, Hex20, Hex27 (tensor_mesh(), quadrilateral faces).
Faces3D make_faces(CellType cells, int ns, int nm, double mx0, double mx1, double gap) {
  Faces3D f;
  if (cell_shape(cells) == CellShape::kTensor) {
    f.lower = tensor_mesh(cells, Vec3(0, 0, -0.5), Vec3(1, 1, 0), ns, ns, 1);
    f.upper = tensor_mesh(cells, Vec3(mx0, 0, gap), Vec3(mx1, 1, gap + 0.5), nm, nm + 1, 1);
  } else {
    f.lower = box_mesh(Vec3(0, 0, -0.5), Vec3(1, 1, 0), ns, ns, 1, cell_order(cells));
    f.upper = box_mesh(Vec3(mx0, 0, gap), Vec3(mx1, 1, gap + 0.5), nm, nm + 1, 1, cell_order(cells));
  }
  f.slave = make_contact_surface(f.lower, "zmax", 0, "lower.top");
  f.master = make_contact_surface(f.upper, "zmin", 1, "upper.bottom");
  return f;
}

}  // namespace

class MortarCells3D : public ::testing::TestWithParam<CellType> {};

TEST_P(MortarCells3D, CellAreasSumToTheSlaveFacetAreaWhenTheMasterCoversIt) {
  const Faces3D f = make_faces(GetParam(), 3, 4, -0.1, 1.1, 0.02);
  const MasterGeometry mg = prepare_master(f.master, f.master.X);
  for (Index k = 0; k < f.slave.num_facets(); ++k) {
    double area = 0.0;
    for (const MortarCell& c : mortar_cells(f.slave, f.slave.X, k, mg, 0.1)) {
      EXPECT_GE(c.master_facet, 0);
      area += polygon_area(c.polygon);
    }
    // The whole reference triangle (1/2) or square (1).
    EXPECT_NEAR(area, cell_shape(GetParam()) == CellShape::kTensor ? 1.0 : 0.5, 1e-13) << "slave facet " << k;
  }
  // The points' weights then add up to the face area, and their gaps are the separation.
  ContactSearchOptions opt;
  opt.search_distance = 0.1;
  const std::vector<ContactPoint> pts = contact_points(f.slave, f.slave.X, mg, opt);
  double w = 0.0;
  for (const ContactPoint& p : pts) {
    w += p.weight;
    EXPECT_NEAR(p.gap, 0.02, 1e-14);  // open: θ = (x − x̄)·n̄ with n̄ = −e_z
    EXPECT_NEAR((p.normal - Eigen::Vector3d(0, 0, -1)).norm(), 0.0, 1e-14);
  }
  EXPECT_NEAR(w, 1.0, 1e-13);
}

TEST_P(MortarCells3D, PartialCoverageIntegratesOnlyTheOverlap) {
  // The master covers x ∈ [0.25, 0.8] only: the weights add up to the overlap area 0.55, and no point
  // projects past the master's border.
  const Faces3D f = make_faces(GetParam(), 4, 3, 0.25, 0.8, 0.0);
  const MasterGeometry mg = prepare_master(f.master, f.master.X);
  ContactSearchOptions opt;
  opt.search_distance = 0.1;
  double w = 0.0;
  for (const ContactPoint& p : contact_points(f.slave, f.slave.X, mg, opt)) {
    w += p.weight;
    EXPECT_GE(p.x.x(), 0.25 - 1e-14);
    EXPECT_LE(p.x.x(), 0.8 + 1e-14);
  }
  EXPECT_NEAR(w, 0.55, 1e-13);
}

TEST_P(MortarCells3D, PastTheBorderOfTheMasterIsNoContact) {
  const Faces3D f = make_faces(GetParam(), 2, 2, 0.25, 0.8, 0.01);
  const MasterGeometry mg = prepare_master(f.master, f.master.X);
  ContactPoint cp;
  const Eigen::Vector3d ns(0, 0, 1);
  // Over the master: contact; past its border at x = 0.8 (the projection is clamped onto a border
  // edge) or past its corner: none, unless allowed (nodal friction).
  EXPECT_TRUE(project_to_master(mg, Eigen::Vector3d(0.5, 0.5, 0.0), ns, 0.1, cp));
  EXPECT_FALSE(project_to_master(mg, Eigen::Vector3d(0.9, 0.5, 0.0), ns, 0.1, cp));
  EXPECT_FALSE(project_to_master(mg, Eigen::Vector3d(0.9, 1.05, 0.0), ns, 0.1, cp));
  EXPECT_TRUE(project_to_master(mg, Eigen::Vector3d(0.9, 0.5, 0.0), ns, 0.2, cp, true));
  EXPECT_NEAR(cp.xbar.x(), 0.8, 1e-14);
  // A point exactly above the border edge is still in contact.
  EXPECT_TRUE(project_to_master(mg, Eigen::Vector3d(0.8, 0.5, 0.0), ns, 0.1, cp));
}

INSTANTIATE_TEST_SUITE_P(ContactPoints, MortarCells3D,
                         ::testing::Values(CellType::kTet4, CellType::kTet10, CellType::kHex8, CellType::kHex20,
                                           CellType::kHex27),
                         [](const ::testing::TestParamInfo<CellType>& p) {
                           if (p.param == CellType::kTet4) return std::string("P1");
                           if (p.param == CellType::kTet10) return std::string("P2");
                           return cell_name(p.param);
                         });

// A 2D master with a right-angled corner (the top and left sides of the square [0, 1]², group
// "top_left"): the corner node is a vertex of the polygon (ContactSurface::corner). The averaged nodal
// normal there would be the bisector (−1, 1)/√2; with the vertex treatment each side keeps its own normal
// and a slave surface resting on the corner sees the gap along its own normal.
class CornerMaster2D : public ::testing::TestWithParam<int> {
 protected:
  void SetUp() override {
    block = rectangle_mesh(0.0, 0.0, 1.0, 1.0, 4, 4, GetParam());
    auto& g = block.facet_groups["top_left"].facets;
    for (const char* side : {"left", "top"}) {
      const auto& f = block.facet_groups[side].facets;
      g.insert(g.end(), f.begin(), f.end());
    }
    block.locate_facets();
    master = make_contact_surface(block, "top_left", 0, "block.top_left");
  }
  Mesh block;
  ContactSurface master;
};

TEST_P(CornerMaster2D, OnlyTheRightAngleIsACorner) {
  int corners = 0;
  for (Index k = 0; k < master.num_nodes(); ++k) {
    const bool at = (master.X.col(k) - Eigen::Vector2d(0, 1)).norm() < 1e-14;
    EXPECT_EQ(master.corner[k] != 0, at) << "node at " << master.X.col(k).transpose();
    corners += master.corner[k];
  }
  EXPECT_EQ(corners, 1);
  // The ends of an open surface (valence 1) and the nodes along a straight side are not corners.
  const ContactSurface top = make_contact_surface(block, "top", 0, "block.top");
  for (char c : top.corner) EXPECT_EQ(c, 0);
}

TEST_P(CornerMaster2D, EachSideKeepsItsNormalAndTheCornerTakesTheSlaveNormal) {
  const MasterGeometry mg = prepare_master(master, master.X);
  ContactPoint cp;
  const Eigen::Vector3d down(0, -1, 0);
  // On the top facet next to the corner: n̄ = (0, 1) exactly (interpolating the bisector would tilt it).
  ASSERT_TRUE(project_to_master(mg, Eigen::Vector2d(0.1, 1.05), down, 0.2, cp));
  EXPECT_NEAR((cp.normal - Eigen::Vector3d(0, 1, 0)).norm(), 0.0, 1e-14);
  EXPECT_NEAR(cp.gap, 0.05, 1e-14);
  // On the left side next to the corner: n̄ = (−1, 0).
  ASSERT_TRUE(project_to_master(mg, Eigen::Vector2d(-0.04, 0.9), Eigen::Vector3d(1, 0, 0), 0.2, cp));
  EXPECT_NEAR((cp.normal - Eigen::Vector3d(-1, 0, 0)).norm(), 0.0, 1e-14);
  EXPECT_NEAR(cp.gap, 0.04, 1e-14);
  // Above and left of the corner (its closest point is the corner): a horizontal slave surface resting
  // on the corner measures the gap vertically, 0.04 (the bisector would give 0.07/√2 = 0.0495).
  ASSERT_TRUE(project_to_master(mg, Eigen::Vector2d(-0.03, 1.04), down, 0.2, cp));
  EXPECT_NEAR((cp.xbar - Eigen::Vector3d(0, 1, 0)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((cp.normal - Eigen::Vector3d(0, 1, 0)).norm(), 0.0, 1e-14);
  EXPECT_NEAR(cp.gap, 0.04, 1e-14);
  // A slave surface inclined by 30° (normal (sin 30°, −cos 30°)): −n_s is inside the cone, n̄ = −n_s.
  const Eigen::Vector3d tilted(0.5, -std::sqrt(0.75), 0);
  ASSERT_TRUE(project_to_master(mg, Eigen::Vector2d(-0.03, 1.04), tilted, 0.2, cp));
  EXPECT_NEAR((cp.normal + tilted).norm(), 0.0, 1e-14);
  // A slave normal outside the cone (pointing right and slightly up): the nearer side's normal, (−1, 0).
  ASSERT_TRUE(project_to_master(mg, Eigen::Vector2d(-0.03, 1.04), Eigen::Vector3d(1, 0.2, 0), 0.2, cp));
  EXPECT_NEAR((cp.normal - Eigen::Vector3d(-1, 0, 0)).norm(), 0.0, 1e-14);
  EXPECT_NEAR(cp.gap, 0.03, 1e-14);
}

TEST_P(CornerMaster2D, FlatSlaveOverTheCornerSeesAUniformGap) {
  // A flat slave face at y = 1.02, x ∈ [−0.3, 0.3], facing down: half of it overhangs the corner. Every
  // point's gap is 0.02 along (0, 1), and every point contributes (weights add up to the length 0.6).
  const Mesh upper = rectangle_mesh(-0.3, 1.02, 0.3, 1.5, 3, 1, GetParam());
  const ContactSurface slave = make_contact_surface(upper, "bottom", 1, "upper.bottom");
  const MasterGeometry mg = prepare_master(master, master.X);
  ContactSearchOptions opt;
  opt.search_distance = 0.5;  // beyond the overhang: no point is left out for its distance
  double w = 0.0;
  for (const ContactPoint& p : contact_points(slave, slave.X, mg, opt)) {
    w += p.weight;
    EXPECT_NEAR(p.gap, 0.02, 1e-14) << "at x = " << p.x.x();
    EXPECT_NEAR((p.normal - Eigen::Vector3d(0, 1, 0)).norm(), 0.0, 1e-14) << "at x = " << p.x.x();
  }
  EXPECT_NEAR(w, 0.6, 1e-13);
}

INSTANTIATE_TEST_SUITE_P(ContactPoints, CornerMaster2D, ::testing::Values(1, 2),
                         [](const ::testing::TestParamInfo<int>& p) { return "P" + std::to_string(p.param); });

// The interface normal of a node whose own normal is tilted by t from −e_y, facing its mirror image (the
// opposite side's normal n̄ the reflection of the own one through y = 0), as at the edge of the contact
// zone in V7: one-sided, −n̄ (tilted by t the other way); two-sided, the bisector, which is the symmetry
// plane's normal −e_y exactly, so that a nodal force along e_y (the mirror-symmetric nodal force) gives
// its full magnitude as the pressure, where −n̄ gives cos t of it.
TEST(InterfaceNormal, TwoSidedIsTheBisectorOfBothSidesNormalsOneSidedTheOpposite) {
  const double t = 0.022;
  for (int dim : {2, 3}) {
    Eigen::VectorXd own = Eigen::VectorXd::Zero(dim), nbar = Eigen::VectorXd::Zero(dim);
    own[0] = std::sin(t) * (dim == 3 ? 0.6 : 1.0);  // a unit vector tilted by t from −e_y
    own[1] = -std::cos(t);
    if (dim == 3) own[2] = std::sin(t) * 0.8;
    nbar = own;
    nbar[1] = -own[1];  // the mirror image's outward normal
    const Eigen::VectorXd one = interface_normal(own, nbar, false), two = interface_normal(own, nbar, true);
    EXPECT_NEAR((one + nbar).norm(), 0.0, 1e-15);
    EXPECT_NEAR(std::abs(two[1] + 1.0), 0.0, 1e-15) << "dim " << dim;
    EXPECT_NEAR(two.norm(), 1.0, 1e-15);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(dim);
    f[1] = 1.0;
    EXPECT_NEAR(-f.dot(two), 1.0, 1e-15);
    EXPECT_NEAR(-f.dot(one), std::cos(t), 1e-15);
  }
}

// The bisector-ray projection (project_to_master() with `ray_normal`; self-contact pairs) on a curved
// master z = −f (3D; y = −f in 2D, f = 0.01 + 0.3 |x − c|², slopes up to 0.3): a slave point p that is the
// mirror image of a master point q, with the mirror image of the master's smoothed normal at q as its
// own, must project onto q itself, along the symmetry plane's normal, with gap 2 f(q) — for every q on a
// grid of every facet (the ray leaves the facet of p's closest point near facet edges, so the search
// must go on to the neighbour: counted). The closest point instead measures the distance to the tilted
// facet, 2 f cos t (n_f·n̄), short of 2 f by up to 5 % here.
namespace {

/// The point at η of master facet f and the smoothed master normal there (unit), both padded to 3D.
void master_point(const MasterGeometry& mg, Index f, const double* eta, Eigen::Vector3d& q, Eigen::Vector3d& n) {
  const ContactSurface& s = *mg.surface;
  double M[10];
  shape_functions(s.facet_type, eta, M, nullptr);
  q.setZero();
  n.setZero();
  for (int b = 0; b < s.nodes_per_facet(); ++b) {
    q.head(s.dim) += M[b] * mg.x.col(s.facet(f)[b]);
    n.head(s.dim) += M[b] * mg.normals.col(s.facet(f)[b]);
  }
  n.normalize();
}

}  // namespace

class BisectorRay : public ::testing::TestWithParam<std::tuple<int, int>> {};

TEST_P(BisectorRay, TheMirrorImageOfAMasterPointProjectsOntoItWithTwiceItsDistanceToThePlane) {
  const auto [dim, order] = GetParam();
  const Mesh lower = dim == 2 ? rectangle_mesh(0.0, -0.5, 1.0, 0.0, 4, 1, order)
                              : box_mesh(Vec3(0, 0, -0.5), Vec3(1, 1, 0), 4, 4, 1, order);
  const ContactSurface master = make_contact_surface(lower, dim == 2 ? "top" : "zmax", 0, "lower.top");
  const int up = dim - 1;  // the axis normal to the plane of symmetry
  auto f = [&](const Eigen::VectorXd& X) {
    double r2 = 0.0;
    for (int i = 0; i < up; ++i) r2 += (X[i] - 0.5) * (X[i] - 0.5);
    return 0.01 + 0.3 * r2;
  };
  Eigen::MatrixXd x = master.X;
  for (Index k = 0; k < master.num_nodes(); ++k) x(up, k) = -f(master.X.col(k));
  const MasterGeometry mg = prepare_master(master, x);
  int crossed = 0, points = 0;
  double worst_closest = 0.0;
  const int n = 6;
  for (Index fm = 0; fm < master.num_facets(); ++fm)
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= (dim == 3 ? n - i : 0); ++j) {
        // In 2D from 0.003 to 0.997 of the facet: the ends are where the ray leaves the closest point's facet.
        const double eta[2] = {dim == 2 ? 0.003 + 0.994 * i / n : (i + 0.25) / (n + 1), (j + 0.25) / (n + 1)};
        Eigen::Vector3d q, nq;
        master_point(mg, fm, eta, q, nq);
        Eigen::Vector3d p = q, ns = nq;
        p[up] = -q[up];
        ns[up] = -nq[up];
        // The slave point's facet normal: any vector facing the master (it only decides facing).
        Eigen::Vector3d facing = Eigen::Vector3d::Zero();
        facing[up] = -1.0;
        ContactPoint closest, ray;
        ASSERT_TRUE(project_to_master(mg, p.head(dim), facing, 1.0, closest));
        ASSERT_TRUE(project_to_master(mg, p.head(dim), facing, 1.0, ray, false, &ns));
        ++points;
        if (ray.master_facet != closest.master_facet) ++crossed;
        EXPECT_NEAR((ray.xbar - q).norm(), 0.0, 1e-12) << "facet " << fm << " η " << eta[0] << " " << eta[1];
        EXPECT_NEAR(ray.gap, 2.0 * std::abs(q[up]), 1e-12);
        EXPECT_NEAR(std::abs(ray.normal[up]), 1.0, 1e-12);
        worst_closest = std::max(worst_closest, std::abs(closest.gap / (2.0 * std::abs(q[up])) - 1.0));
      }
  EXPECT_GT(crossed, 0) << "no ray left its closest point's facet: the neighbour search is untested";
  EXPECT_GT(worst_closest, 1e-3) << "the closest point should fall short of 2 f on the tilted facets";
  std::printf("bisector ray %dD P%d: %d points, %d on another facet than the closest point's; closest-point gap "
              "off by up to %.2e relative\n", dim, order, points, crossed, worst_closest);
}

INSTANTIATE_TEST_SUITE_P(ContactPoints, BisectorRay,
                         ::testing::Combine(::testing::Values(2, 3), ::testing::Values(1, 2)),
                         [](const ::testing::TestParamInfo<std::tuple<int, int>>& p) {
                           return std::to_string(std::get<0>(p.param)) + "D_P" + std::to_string(std::get<1>(p.param));
                         });

// The linearisation of the bisector-ray gap (ContactPoint::gap_direction): at a point where the gap is
// zero, moving the slave point by δp and the master's nodes by δx_b changes θ by d·(δp − Σ N_b(η) δx_b)
// to first order, d = n_f/(n_f·m) — checked by central differences of re-projected gaps (m, n̄ and the
// foot recomputed) on the curved master of the test above, where d differs from m by up to the facets'
// tilt against m (m alone misses the gap's change under a slide along a tilted facet).
TEST_P(BisectorRay, TheGapDirectionIsTheDerivativeOfTheRayGapByFiniteDifferences) {
  const auto [dim, order] = GetParam();
  const Mesh lower = dim == 2 ? rectangle_mesh(0.0, -0.5, 1.0, 0.0, 4, 1, order)
                              : box_mesh(Vec3(0, 0, -0.5), Vec3(1, 1, 0), 4, 4, 1, order);
  const ContactSurface master = make_contact_surface(lower, dim == 2 ? "top" : "zmax", 0, "lower.top");
  const int up = dim - 1;
  Eigen::MatrixXd x = master.X;
  for (Index k = 0; k < master.num_nodes(); ++k) {
    double r2 = 0.0;
    for (int i = 0; i < up; ++i) r2 += (master.X(i, k) - 0.3) * (master.X(i, k) - 0.3);
    x(up, k) = -0.3 * r2;
  }
  const MasterGeometry mg = prepare_master(master, x);
  const int npf = master.nodes_per_facet();
  Eigen::Vector3d facing = Eigen::Vector3d::Zero();
  facing[up] = -1.0;
  double worst = 0.0, largest_tilt = 0.0;
  std::srand(7);  // Eigen's Random draws from std::rand: the same directions in every run
  for (Index fm = 0; fm < master.num_facets(); fm += 3) {
    const double eta[2] = {dim == 2 ? 0.37 : 0.29, 0.23};
    Eigen::Vector3d q, nq;
    master_point(mg, fm, eta, q, nq);
    Eigen::Vector3d ns = nq;  // the mirror image's normal: the slave surface touches the master at q
    ns[up] = -nq[up];
    ContactPoint cp;
    ASSERT_TRUE(project_to_master(mg, q.head(dim), facing, 1.0, cp, false, &ns));
    ASSERT_NEAR(cp.gap, 0.0, 1e-14);
    ASSERT_GT(cp.gap_direction.norm(), 0.0);
    largest_tilt = std::max(largest_tilt, (cp.gap_direction - cp.normal).norm());
    // A random direction of the slave point and of the master facet's nodes.
    const Eigen::Vector3d dp = Eigen::Vector3d::Random();
    Eigen::MatrixXd dx = Eigen::MatrixXd::Zero(dim, master.num_nodes());
    for (int b = 0; b < npf; ++b) dx.col(master.facet(cp.master_facet)[b]) = Eigen::VectorXd::Random(dim);
    double Mh[10];
    shape_functions(master.facet_type, cp.eta, Mh, nullptr);
    Eigen::Vector3d dxbar = Eigen::Vector3d::Zero();
    for (int b = 0; b < npf; ++b) dxbar.head(dim) += Mh[b] * dx.col(master.facet(cp.master_facet)[b]);
    const double predicted = cp.gap_direction.dot(dp - dxbar);  // in 2D the third components are unused (0 in d)
    const double eps = 1e-6;
    double g[2];
    for (int s = 0; s < 2; ++s) {
      const double e = s == 0 ? eps : -eps;
      const MasterGeometry mge = prepare_master(master, x + e * dx);
      const Eigen::VectorXd pe = (q + e * dp).head(dim);
      ContactPoint ce;
      ASSERT_TRUE(project_to_master(mge, pe, facing, 1.0, ce, false, &ns));
      g[s] = ce.gap;
    }
    const double fd = (g[0] - g[1]) / (2 * eps);
    worst = std::max(worst, std::abs(fd - predicted));
  }
  std::printf("bisector ray %dD P%d: |FD − d·δ| up to %.2e; |d − m| up to %.2e\n", dim, order, worst, largest_tilt);
  EXPECT_LT(worst, 1e-7);
  EXPECT_GT(largest_tilt, 1e-2) << "the master should be tilted against m somewhere";
}
