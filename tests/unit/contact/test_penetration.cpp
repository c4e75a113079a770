/// Tests of the global penetration test (contact/penetration.hpp) on two structured unit squares, "lower"
/// [0,1]² and "upper" [0,1]×[1,2], one symmetric pair between lower.top and upper.bottom: the reference
/// configuration and a small press measure nothing beyond the tolerance; a node pushed inside the other
/// body, and the upper square pushed right through the lower one, are found with their depth.

#include "symcontact/contact/penetration.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "symcontact/contact/contact_surface.hpp"
#include "symcontact/mesh/structured.hpp"

namespace symcontact {
namespace {

/// One symmetric pair "interface" between surfaces a and b, search distance 0.1.
ContactSet one_pair(ContactSurface a, ContactSurface b) {
  ContactSet contacts;
  contacts.surfaces.push_back(std::move(a));
  contacts.surfaces.push_back(std::move(b));
  ContactPair pair;
  pair.name = "interface";
  pair.surface_a = 0;
  pair.surface_b = 1;
  pair.search_distance = 0.1;
  contacts.pairs.push_back(pair);
  contacts.finalize();
  return contacts;
}

struct TwoSquares {
  Mesh lower = rectangle_mesh(0, 0, 1, 1, 4, 4);
  Mesh upper = rectangle_mesh(0, 1, 1, 2, 4, 4);
  DofMap dofs{2};
  ContactSet contacts =
      one_pair(make_contact_surface(lower, "top", 0, "lower.top"), make_contact_surface(upper, "bottom", 1, "upper.bottom"));
  TwoSquares() {
    dofs.add_body(lower.num_nodes());
    dofs.add_body(upper.num_nodes());
  }
  std::vector<const Mesh*> meshes() const { return {&lower, &upper}; }
  /// u with the upper square translated by (0, dy).
  VectorXd upper_moved(double dy) const {
    VectorXd u = VectorXd::Zero(dofs.num_dofs());
    for (Index v = 0; v < upper.num_nodes(); ++v) u[dofs.dof(1, v, 1)] = dy;
    return u;
  }
};

double worst_ratio(const std::vector<Penetration>& found) {
  double r = 0.0;
  for (const auto& p : found) r = std::max(r, p.ratio());
  return r;
}

TEST(Penetration, TouchingSquaresAndASmallOverlapAreWithinTheTolerance) {
  const TwoSquares s;
  const auto at_rest = find_penetrations(s.contacts, s.meshes(), s.dofs, s.upper_moved(0.0));
  EXPECT_LT(worst_ratio(at_rest), 1e-9);
  // 5 % of h = 0.25 into the lower square: measured, not beyond 25 %.
  const auto small = find_penetrations(s.contacts, s.meshes(), s.dofs, s.upper_moved(-0.0125));
  ASSERT_FALSE(small.empty());
  EXPECT_NEAR(worst_ratio(small), 0.05, 1e-9);
  for (const auto& p : small) EXPECT_FALSE(p.exceeds());
}

TEST(Penetration, OverlapBeyondTheToleranceIsFoundWithItsDepth) {
  const TwoSquares s;
  const auto found = find_penetrations(s.contacts, s.meshes(), s.dofs, s.upper_moved(-0.3));
  ASSERT_EQ(found.size(), 2u);  // both sides of the symmetric pair
  int inside = 0;
  for (const auto& p : found) {
    EXPECT_TRUE(p.exceeds());
    EXPECT_NEAR(p.depth, 0.3, 1e-12);
    EXPECT_NEAR(p.size, 0.25, 1e-12);
    inside += !p.passed_through;
  }
  // The upper surface's end nodes lie on the lower square's sides (its boundary, not inside it) and count
  // as behind its top; the lower surface's nodes lie inside the upper square, on edges between its cells.
  EXPECT_GE(inside, 1);
}

// The same in 3D on two cubes of 6-node prisms (prism_mesh(), 4 × 4 × 4 boxes each), the upper one's bottom
// pushed up to 0.3 into the lower one through their triangular faces: found inside the other body's prisms;
// and on two cubes of pyramids (pyramid_mesh()) through their bases.
class PenetrationInto : public ::testing::TestWithParam<CellType> {};

TEST_P(PenetrationInto, OverlapIsFoundWithItsDepth) {
  const Mesh lower = structured_mesh(GetParam(), Vec3(0, 0, 0), Vec3(1, 1, 1), 4, 4, 4);
  const Mesh upper = structured_mesh(GetParam(), Vec3(0, 0, 1), Vec3(1, 1, 2), 4, 4, 4);
  DofMap dofs{3};
  dofs.add_body(lower.num_nodes());
  dofs.add_body(upper.num_nodes());
  const ContactSet contacts = one_pair(make_contact_surface(lower, "zmax", 0, "lower.zmax", AnalysisModel::kThreeD),
                                      make_contact_surface(upper, "zmin", 1, "upper.zmin", AnalysisModel::kThreeD));
  VectorXd u = VectorXd::Zero(dofs.num_dofs());
  EXPECT_LT(worst_ratio(find_penetrations(contacts, {&lower, &upper}, dofs, u)), 1e-9);
  // A bump pressed down: u_z = −0.3 at the centre of the upper cube's bottom, falling to 0 at its sides, so
  // that the deepest node, (0.5, 0.5, 0.7), is inside the lower cube (on the side faces a node would be on
  // its boundary, not in it).
  for (Index v = 0; v < upper.num_nodes(); ++v)
    u[dofs.dof(1, v, 2)] = -0.3 * (1 - 2 * std::abs(upper.x(0, v) - 0.5)) * (1 - 2 * std::abs(upper.x(1, v) - 0.5));
  const auto found = find_penetrations(contacts, {&lower, &upper}, dofs, u);
  ASSERT_EQ(found.size(), 2u);
  bool upper_found = false;
  for (const auto& p : found) {
    EXPECT_TRUE(p.exceeds());
    if (p.depth > 0.3 - 1e-12) {  // the upper surface's centre node, 0.3 into the lower cube's prisms
      upper_found = true;
      EXPECT_NEAR(p.depth, 0.3, 1e-12);
      EXPECT_FALSE(p.passed_through);
    }
  }
  EXPECT_TRUE(upper_found);
}

INSTANTIATE_TEST_SUITE_P(PrismsAndPyramids, PenetrationInto, ::testing::Values(CellType::kPrism6, CellType::kPyramid5),
                         [](const auto& p) { return cell_name(p.param); });

TEST(Penetration, BodyPushedRightThroughTheOtherIsFound) {
  // The upper square ends at [0,1]×[−4,−3]: no node lies inside the other square, but each surface's
  // nodes started in front of the other surface and now lie 5 behind it.
  const TwoSquares s;
  const auto found = find_penetrations(s.contacts, s.meshes(), s.dofs, s.upper_moved(-5.0));
  ASSERT_EQ(found.size(), 2u);
  for (const auto& p : found) {
    EXPECT_TRUE(p.exceeds());
    EXPECT_TRUE(p.passed_through);
    EXPECT_NEAR(p.depth, 5.0, 1e-12);
  }
}

// Small sliding: the gaps the solve enforces, linearised at the reference configuration. Pressing the upper
// square 0.1 down is a linearised gap of −0.1 at every node, both sides (40 % of h); sliding it sideways by
// half its width changes no linearised gap. A pair in the current geometry is not measured this way.
TEST(Penetration, SmallSlidingPairIsMeasuredOnItsLinearisedGaps) {
  TwoSquares s;
  s.contacts.pairs[0].geometry = ContactGeometry::kReference;
  const ContactLinearization lin = s.contacts.linearize(s.dofs, VectorXd::Zero(s.dofs.num_dofs()));
  const auto pressed = find_linearized_penetrations(s.contacts, lin, s.upper_moved(-0.1));
  ASSERT_EQ(pressed.size(), 2u);
  for (const auto& p : pressed) {
    EXPECT_NEAR(p.depth, 0.1, 1e-12);
    EXPECT_NEAR(p.size, 0.25, 1e-12);
    EXPECT_TRUE(p.exceeds());
  }
  VectorXd slid = s.upper_moved(0.0);
  for (Index v = 0; v < s.upper.num_nodes(); ++v) slid[s.dofs.dof(1, v, 0)] = 0.5;
  EXPECT_LT(worst_ratio(find_linearized_penetrations(s.contacts, lin, slid)), 1e-12);
  s.contacts.pairs[0].geometry = ContactGeometry::kCurrent;
  EXPECT_TRUE(find_linearized_penetrations(s.contacts, lin, s.upper_moved(-0.1)).empty());
}

TEST(Penetration, AnalyticObstacleDepthIsTheSignedDistance) {
  TwoSquares s;
  ContactSet plane;
  plane.surfaces.push_back(make_contact_surface(s.lower, "bottom", 0, "lower.bottom"));
  Obstacle ob;
  ob.point = Eigen::Vector3d(0, 0.1, 0);  // the floor y = 0.1, above the square's bottom y = 0
  ob.normal = Eigen::Vector3d::UnitY();
  plane.obstacles.push_back(ob);
  ContactPair pair;
  pair.name = "floor";
  pair.surface_a = 0;
  pair.obstacle = 0;
  plane.pairs.push_back(pair);
  plane.finalize();
  const auto found = find_penetrations(plane, s.meshes(), s.dofs, VectorXd::Zero(s.dofs.num_dofs()));
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NEAR(found[0].depth, 0.1, 1e-12);
  EXPECT_EQ(found[0].master, -1);
  EXPECT_TRUE(found[0].exceeds());  // 0.1 / 0.25 = 40 %
}

}  // namespace
}  // namespace symcontact
