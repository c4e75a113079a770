// Tests of the contact table (src/symcontact/post/contact_table.hpp): its columns in 2D and 3D, one row per
// node of each side with the node numbers from 1, undefined values as NaN, and the status names: "stick"
// only on a side with friction, "contact" on a side without.

#include "symcontact/post/contact_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace symcontact {
namespace {

ContactSurface surface(const std::string& name, std::vector<Index> nodes) {
  ContactSurface s;
  s.name = name;
  s.dim = 2;
  s.nodes = std::move(nodes);
  return s;
}

/// A side of `n` nodes in 2D with the given statuses; `friction` gives it a finite slip.
ContactSideResult side(int surface_index, const std::vector<int>& status, bool friction) {
  const Index n = static_cast<Index>(status.size());
  ContactSideResult r;
  r.surface = surface_index;
  for (Eigen::MatrixXd* m : {&r.x, &r.X, &r.displacement, &r.force, &r.normal_part, &r.tangential})
    *m = Eigen::MatrixXd::Constant(2, n, 0.5);
  r.slip = Eigen::MatrixXd::Constant(2, n, friction ? 1e-3 : std::nan(""));
  r.pressure = r.current_pressure = Eigen::VectorXd::Constant(n, 2.0);
  r.gap = Eigen::VectorXd::Constant(n, std::nan(""));
  r.tangential_along = Eigen::VectorXd::Zero(n);
  r.slip_along = Eigen::VectorXd::Constant(n, friction ? 1e-3 : std::nan(""));
  r.status = Eigen::Map<const Eigen::VectorXi>(status.data(), n);
  return r;
}

TEST(ContactTable, ColumnsRowsAndStatusNamesIn2D) {
  const std::vector<ContactSurface> surfaces = {surface("upper.bottom", {4, 7}), surface("lower.top", {0, 1, 2})};
  ContactPairResult pair;
  pair.name = "interface";
  pair.sides = {side(0, {1, 2}, true), side(1, {0, 1, 1}, false)};
  const ContactTable t = contact_table(surfaces, 2, pair, {Eigen::Vector2d(3e-3, 4e-3)});

  const std::vector<std::string> names = {
      "x",    "y",    "x_ref",  "y_ref",  "gap",    "pressure", "current_pressure", "tx", "ty", "fx", "fy",
      "fn_x", "fn_y", "slip_x", "slip_y", "accumulated_slip",   "ux", "uy", "t_tangential", "slip_tangential"};
  EXPECT_EQ(t.numeric_names, names);
  EXPECT_EQ(t.pair, "interface");
  ASSERT_EQ(t.rows(), 5);
  EXPECT_EQ(t.numeric.rows(), 5);
  EXPECT_EQ(t.side, (std::vector<std::string>{"a", "a", "b", "b", "b"}));
  EXPECT_EQ(t.surface[0], "upper.bottom");
  EXPECT_EQ(t.node, (std::vector<Index>{5, 8, 1, 2, 3}));
  EXPECT_EQ(t.status, (std::vector<std::string>{"stick", "slip", "open", "contact", "contact"}));
  const Index acc = 15;
  EXPECT_EQ(t.numeric(1, acc), 4e-3);            // side a: its accumulated slip
  EXPECT_TRUE(std::isnan(t.numeric(2, acc)));    // side b: no friction, no accumulated slip
  EXPECT_TRUE(std::isnan(t.numeric(0, 4)));      // the gap of a node without projection
  EXPECT_EQ(t.numeric(0, 5), 2.0);
}

TEST(ContactTable, ThreeDimensionalColumnsHaveZAndNoSignedTangentials) {
  const ContactTable t = contact_table({}, 3, ContactPairResult{}, {});
  EXPECT_EQ(t.numeric_names.size(), 25u);
  EXPECT_EQ(t.numeric_names[2], "z");
  EXPECT_EQ(t.numeric_names.back(), "uz");
  EXPECT_EQ(t.rows(), 0);
}

}  // namespace
}  // namespace symcontact
