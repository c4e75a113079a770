#include "symcontact/contact/contact_set.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "symcontact/mesh/structured.hpp"

using namespace symcontact;

namespace {

struct Blocks {
  Mesh lower, upper;
  DofMap dofs{2};
  ContactSet set;
};

/// Lower block [0, 1] × [−0.5, 0] (5 facets on top), upper block [0.13, 0.83] × [0.05, 0.45] (7 facets).
/// surfaces[0] = lower.top, surfaces[1] = upper.bottom.
Blocks make_blocks(int order) {
  Blocks b;
  b.lower = rectangle_mesh(0.0, -0.5, 1.0, 0.0, 5, 2, order);
  b.upper = rectangle_mesh(0.13, 0.05, 0.83, 0.45, 7, 2, order);
  b.dofs.add_body(b.lower.num_nodes());
  b.dofs.add_body(b.upper.num_nodes());
  b.set.surfaces.push_back(make_contact_surface(b.lower, "top", 0, "lower.top"));
  b.set.surfaces.push_back(make_contact_surface(b.upper, "bottom", 1, "upper.bottom"));
  return b;
}

ContactPair pair_of(int a, int b, ContactMode mode, bool slave_is_b = false) {
  ContactPair p;
  p.name = "p";
  p.surface_a = a;
  p.surface_b = b;
  p.mode = mode;
  p.slave_is_b = slave_is_b;
  p.search_distance = 0.5;
  return p;
}

}  // namespace

TEST(ContactSet, AutomaticSearchDistanceFormula) {
  for (int order = 1; order <= 2; ++order) {
    Blocks b = make_blocks(order);
    const ContactSurface& lo = b.set.surfaces[0];
    const ContactSurface& up = b.set.surfaces[1];
    // One surface: box [0, 1] × {0}, diagonal 1; largest facet 0.2 (vertex to vertex, also for P2).
    EXPECT_NEAR(ContactSet::automatic_search_distance(lo, nullptr), 0.1 * 1.0 + 2 * 0.2, 1e-14) << "P" << order;
    EXPECT_NEAR(ContactSet::automatic_search_distance(up, nullptr), 0.1 * 0.7 + 2 * 0.1, 1e-14) << "P" << order;
    // Two: box [0, 1] × [0, 0.05], largest facet 0.2; symmetric in its arguments.
    const double want = 0.1 * std::hypot(1.0, 0.05) + 2 * 0.2;
    EXPECT_NEAR(ContactSet::automatic_search_distance(lo, &up), want, 1e-14) << "P" << order;
    EXPECT_NEAR(ContactSet::automatic_search_distance(up, &lo), want, 1e-14) << "P" << order;
  }
}

TEST(ContactSet, FamiliesPerMode) {
  Blocks b = make_blocks(1);
  ContactSet& set = b.set;
  set.obstacles.push_back(Obstacle{});
  set.pairs = {pair_of(0, 1, ContactMode::kSymmetric)};
  set.finalize();
  ASSERT_EQ(set.families().size(), 2u);
  EXPECT_EQ(set.families()[0].pair, 0);
  EXPECT_EQ(set.families()[0].slave, 0);
  EXPECT_EQ(set.families()[0].master, 1);
  EXPECT_EQ(set.families()[1].slave, 1);
  EXPECT_EQ(set.families()[1].master, 0);
  // finalize() again does not duplicate.
  set.finalize();
  EXPECT_EQ(set.families().size(), 2u);

  set.pairs = {pair_of(0, 1, ContactMode::kOnePass, true)};
  set.finalize();
  ASSERT_EQ(set.families().size(), 1u);
  EXPECT_EQ(set.families()[0].slave, 1);
  EXPECT_EQ(set.families()[0].master, 0);

  set.pairs = {pair_of(0, 1, ContactMode::kOnePass, false)};
  set.finalize();
  ASSERT_EQ(set.families().size(), 1u);
  EXPECT_EQ(set.families()[0].slave, 0);
  EXPECT_EQ(set.families()[0].master, 1);

  ContactPair obstacle_pair = pair_of(1, -1, ContactMode::kSymmetric);  // mode is ignored with an obstacle
  obstacle_pair.obstacle = 0;
  set.pairs = {obstacle_pair};
  set.finalize();
  ASSERT_EQ(set.families().size(), 1u);
  EXPECT_EQ(set.families()[0].slave, 1);
  EXPECT_EQ(set.families()[0].master, -1);

  // Several pairs: families in pair order, tagged with their pair.
  set.pairs = {pair_of(0, 1, ContactMode::kSymmetric), obstacle_pair, pair_of(0, 1, ContactMode::kOnePass, true)};
  set.finalize();
  ASSERT_EQ(set.families().size(), 4u);
  const int want_pair[4] = {0, 0, 1, 2};
  for (int f = 0; f < 4; ++f) EXPECT_EQ(set.families()[f].pair, want_pair[f]);
  EXPECT_FALSE(set.empty());
}

TEST(ContactSet, SymmetricRowsAreTheTwoOnePassFamiliesStacked) {
  // The same constraints through two paths: a symmetric pair equals one-pass a→b then one-pass b→a.
  for (int order = 1; order <= 2; ++order) {
    Blocks b = make_blocks(order);
    VectorXd u = VectorXd::Zero(b.dofs.num_dofs());
    for (Index i = 0; i < u.size(); ++i) u[i] = 1e-3 * std::sin(1.7 * static_cast<double>(i));
    ContactSet sym = b.set, ab = b.set, ba = b.set;
    sym.pairs = {pair_of(0, 1, ContactMode::kSymmetric)};
    ab.pairs = {pair_of(0, 1, ContactMode::kOnePass, false)};
    ba.pairs = {pair_of(0, 1, ContactMode::kOnePass, true)};
    sym.finalize();
    ab.finalize();
    ba.finalize();
    const ContactLinearization ls = sym.linearize(b.dofs, u), la = ab.linearize(b.dofs, u), lb = ba.linearize(b.dofs, u);
    ASSERT_GT(la.A.rows(), 0);
    ASSERT_GT(lb.A.rows(), 0);
    ASSERT_EQ(ls.A.rows(), la.A.rows() + lb.A.rows());
    ASSERT_EQ(ls.A.cols(), b.dofs.num_dofs());
    const Eigen::MatrixXd S(ls.A), A1(la.A), A2(lb.A);
    EXPECT_EQ(S.topRows(la.A.rows()), A1);
    EXPECT_EQ(S.bottomRows(lb.A.rows()), A2);
    EXPECT_EQ(ls.b.head(la.b.size()), la.b);
    EXPECT_EQ(ls.b.tail(lb.b.size()), lb.b);
    for (Index r = 0; r < ls.A.rows(); ++r) EXPECT_EQ(ls.row_family[r], r < la.A.rows() ? 0 : 1);
    ASSERT_EQ(ls.points.size(), 2u);
    EXPECT_EQ(ls.points[0].size(), la.points[0].size());
    EXPECT_EQ(ls.points[1].size(), lb.points[0].size());
    EXPECT_EQ(static_cast<Index>(ls.row_node.size()), ls.A.rows());
    EXPECT_EQ(static_cast<Index>(ls.row_support.size()), ls.A.rows());
  }
}

TEST(ContactSet, ReferenceGeometryRowsAreThoseOfXAtEveryDisplacement) {
  // A pair in ContactGeometry::kReference linearises at u = 0 whatever u: its rows are the current pair's
  // at u = 0 (g = g(X) + A u). Here next to a current pair on the same surfaces (each configuration has its
  // own positions and master geometry), whose rows do move with u.
  for (int order = 1; order <= 2; ++order) {
    Blocks b = make_blocks(order);
    VectorXd u = VectorXd::Zero(b.dofs.num_dofs());
    for (Index i = 0; i < u.size(); ++i) u[i] = 2e-2 * std::sin(1.7 * static_cast<double>(i));
    ContactSet mixed = b.set, current = b.set;
    ContactPair reference = pair_of(0, 1, ContactMode::kOnePass, true);
    reference.geometry = ContactGeometry::kReference;
    mixed.pairs = {reference, pair_of(0, 1, ContactMode::kOnePass, true)};
    current.pairs = {pair_of(0, 1, ContactMode::kOnePass, true)};
    mixed.finalize();
    current.finalize();
    const ContactLinearization lm = mixed.linearize(b.dofs, u);
    const ContactLinearization l0 = current.linearize(b.dofs, VectorXd::Zero(u.size()));
    const ContactLinearization lu = current.linearize(b.dofs, u);
    ASSERT_GT(l0.A.rows(), 0);
    ASSERT_EQ(lm.A.rows(), l0.A.rows() + lu.A.rows());
    const Eigen::MatrixXd M(lm.A), A0(l0.A), Au(lu.A);
    EXPECT_EQ(M.topRows(l0.A.rows()), A0) << "P" << order;
    EXPECT_EQ(lm.b.head(l0.b.size()), l0.b) << "P" << order;
    EXPECT_EQ(M.bottomRows(lu.A.rows()), Au) << "P" << order;
    EXPECT_EQ(lm.b.tail(lu.b.size()), lu.b) << "P" << order;
    // And the displacement does change the current rows (the test above could not tell otherwise).
    EXPECT_GT((A0.rows() == Au.rows() ? (A0 - Au).cwiseAbs().maxCoeff() : 1.0), 1e-6) << "P" << order;
    EXPECT_EQ(mixed.geometry_displacement(0, u), VectorXd::Zero(u.size()));
    EXPECT_EQ(mixed.geometry_displacement(1, u), u);
  }
}

TEST(ContactSet, EmptySetLinearizesToNoRows) {
  Blocks b = make_blocks(1);
  b.set.finalize();
  EXPECT_TRUE(b.set.empty());
  const ContactLinearization lin = b.set.linearize(b.dofs, VectorXd::Zero(b.dofs.num_dofs()));
  EXPECT_EQ(lin.A.rows(), 0);
  EXPECT_EQ(lin.A.cols(), b.dofs.num_dofs());
  EXPECT_EQ(lin.b.size(), 0);
}

TEST(ContactSet, ValuesFollowTheirRowsByFamilyAndNode) {
  // Earlier rows (family, node) (0, 1), (0, 2), (1, 1) with values 1, 2, 3; the new rows (0, 2), (1, 1), (0, 5):
  // the values of the rows they keep, in their order, and 0 on the row new to them.
  ContactLinearization to;
  to.A.resize(3, 4);
  to.row_family = {0, 1, 0};
  to.row_node = {2, 1, 5};
  const VectorXd carried = values_on_rows({0, 0, 1}, {1, 2, 1}, (VectorXd(3) << 1.0, 2.0, 3.0).finished(), to);
  ASSERT_EQ(carried.size(), 3);
  EXPECT_EQ(carried[0], 2.0);
  EXPECT_EQ(carried[1], 3.0);
  EXPECT_EQ(carried[2], 0.0);
}
