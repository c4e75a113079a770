// One geometry iteration's subproblem (solvers/geometry_subproblem.hpp) on the 2D contact patch of V3 with
// independent rows (one-pass pair), linearised at the undeformed state: with linear elasticity it is condensed
// onto the contact DOFs and solved by the dual; without condensation it is the whole problem, solved by the
// primal; both give the same displacements and multipliers. Linearised again at its solution the subproblem is
// unchanged, and a moved one is not; on a rigid plane the geometry fixed point ends on that without a second solve.
#include <gtest/gtest.h>

#include <memory>
#include <sstream>

#include "support/contact_patch_case.hpp"
#include "support/model_case.hpp"
#include "support/solve_case.hpp"
#include "support/temp_folder.hpp"
#include "symcontact/solvers/geometry_subproblem.hpp"

using namespace symcontact;

namespace {

struct Step {
  bool condensed = false;
  bool dual = false;
  VectorXd u;           ///< the subproblem's solution, every DOF
  VectorXd multipliers;
};

Step solve_once(const Model& m, const FixedDofs& fixed, bool condense) {
  ContactSolveOptions o;
  o.static_condensation = condense;
  o.ipopt.tolerance = 1e-11;
  ContactWorkspace workspace;
  std::ostringstream sink;
  const Logger log(sink, Verbosity::kQuiet);
  GeometrySubproblem sub(m.energy(), fixed, m.contacts(), m.dofs(), o, workspace, log, nullptr);
  VectorXd u = VectorXd::Zero(m.dofs().num_dofs());
  fixed.impose(u);
  const VectorXd x = sub.reduced().restrict(u);
  const ContactLinearization lin = m.contacts().linearize(m.dofs(), u);
  SolveReport rep;
  sub.build(lin, u, x, rep.times);
  Step s;
  s.condensed = sub.condensed() != nullptr;
  GeometrySubproblem::Outcome out = sub.solve(x, 1, nullptr, o.ipopt, true, rep);
  EXPECT_TRUE(out.solution.result.success) << out.solution.result.status_text;
  s.dual = out.dual;
  const VectorXd xs = s.condensed ? sub.condensed()->expand(out.solution.result.x) : out.solution.result.x;
  s.u = sub.reduced().expand(xs);
  s.multipliers = out.solution.result.multipliers;
  return s;
}

}  // namespace

TEST(GeometrySubproblem, CondensedByTheDualAndWholeByThePrimalGiveTheSameSolution) {
  symcontact::testing::TempFolder folder{"geometry_subproblem"};
  symcontact::testing::ContactPatchCase c;
  c.mode = "one-pass";
  FixedDofs fixed;
  const auto patch = symcontact::testing::contact_patch_model(c, folder.path(), fixed);
  const Model& m = *patch->model;
  const Step condensed = solve_once(m, fixed, true), whole = solve_once(m, fixed, false);
  EXPECT_TRUE(condensed.condensed);
  EXPECT_TRUE(condensed.dual);
  EXPECT_FALSE(whole.condensed);
  EXPECT_FALSE(whole.dual);
  ASSERT_EQ(condensed.multipliers.size(), whole.multipliers.size());
  ASSERT_GT(whole.multipliers.size(), 0);
  EXPECT_GT(whole.multipliers.maxCoeff(), 0.0) << "the blocks are pressed together";
  EXPECT_LT((condensed.u - whole.u).lpNorm<Eigen::Infinity>(), 1e-7 * whole.u.lpNorm<Eigen::Infinity>());
  EXPECT_LT((condensed.multipliers - whole.multipliers).lpNorm<Eigen::Infinity>(),
            1e-6 * whole.multipliers.lpNorm<Eigen::Infinity>());
}

TEST(GeometrySubproblem, TheSameLinearisationIsUnchangedAndAMovedOneIsNot) {
  // The one-pass patch in the current geometry: its rows are the slave nodes' projections on the master
  // facets, which move with the displacement.
  symcontact::testing::TempFolder folder{"geometry_subproblem_unchanged"};
  symcontact::testing::ContactPatchCase c;
  c.mode = "one-pass";
  FixedDofs fixed;
  const auto patch = symcontact::testing::contact_patch_model(c, folder.path(), fixed);
  const Model& m = *patch->model;
  ContactSolveOptions o;
  ContactWorkspace workspace;
  std::ostringstream sink;
  const Logger log(sink, Verbosity::kQuiet);
  GeometrySubproblem sub(m.energy(), fixed, m.contacts(), m.dofs(), o, workspace, log, nullptr);
  VectorXd u = VectorXd::Zero(m.dofs().num_dofs());
  fixed.impose(u);
  const ContactLinearization lin = m.contacts().linearize(m.dofs(), u);
  SolveReport rep;
  sub.build(lin, u, sub.reduced().restrict(u), rep.times);
  EXPECT_TRUE(sub.unchanged(m.contacts().linearize(m.dofs(), u), u, 0.0));
  // A tangential shift of one block moves every projection on the other: other coefficients in A.
  ASSERT_GE(m.dofs().num_bodies(), 2);
  VectorXd shifted = u;
  for (Index d = m.dofs().offset(0); d < m.dofs().offset(1); d += m.dofs().dim()) shifted[d] += 1e-3;
  EXPECT_FALSE(sub.unchanged(m.contacts().linearize(m.dofs(), shifted), shifted, 1.0));
  // The same rows with gaps moved by 1e-9: unchanged to 1e-8, not to 1e-10.
  ContactLinearization moved = lin;
  moved.b.array() += 1e-9;
  EXPECT_TRUE(sub.unchanged(moved, u, 1e-8));
  EXPECT_FALSE(sub.unchanged(moved, u, 1e-10));
}

TEST(GeometrySubproblem, OnARigidPlaneTheSecondIterationNeedsNoSolve) {
  // examples/hertz_2d/cylinder_on_plane.toml: the plane's rows are its normal at every iterate, so the
  // linearisation at the first solution is the first subproblem again.
  const std::string dir = std::string(SYMCONTACT_EXAMPLES) + "/hertz_2d";
  const auto solved =
      symcontact::testing::solve_case(symcontact::testing::read_text(dir + "/cylinder_on_plane.toml"), dir);
  const SolveReport& r = solved->report;
  EXPECT_TRUE(r.converged);
  ASSERT_EQ(r.ipopt_per_iteration.size(), 2u);
  EXPECT_GT(r.ipopt_per_iteration[0], 0);
  EXPECT_EQ(r.ipopt_per_iteration[1], 0);
  ASSERT_EQ(r.change_history.size(), 2u);
  EXPECT_EQ(r.change_history[1], 0.0);
}
