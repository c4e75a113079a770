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

/// The one-pass patch (independent rows), and a GeometrySubproblem of it built at the undeformed state.
class GeometrySubproblemTest : public ::testing::Test {
 protected:
  void SetUp() override {
    symcontact::testing::ContactPatchCase c;
    c.mode = "one-pass";
    patch_ = symcontact::testing::contact_patch_model(c, folder_.path(), fixed_);
    u0_ = VectorXd::Zero(model().dofs().num_dofs());
    fixed_.impose(u0_);
  }
  const Model& model() const { return *patch_->model; }
  /// A subproblem under `o`, built at u0_.
  std::unique_ptr<GeometrySubproblem> built(const ContactSolveOptions& o) {
    const Model& m = model();
    auto sub = std::make_unique<GeometrySubproblem>(m.energy(), fixed_, m.contacts(), m.dofs(), o, workspace_, log_,
                                                    nullptr);
    sub->build(m.contacts().linearize(m.dofs(), u0_), u0_, sub->reduced().restrict(u0_), rep_.times);
    return sub;
  }

  symcontact::testing::TempFolder folder_{"geometry_subproblem"};
  std::unique_ptr<symcontact::testing::ModelCase> patch_;
  FixedDofs fixed_;
  VectorXd u0_;
  ContactWorkspace workspace_;
  SolveReport rep_;
  std::ostringstream sink_;
  Logger log_{sink_, Verbosity::kQuiet};
};

struct Step {
  bool condensed = false;
  bool dual = false;
  VectorXd u;  ///< the subproblem's solution, every DOF
  VectorXd multipliers;
};

Step solve_once(GeometrySubproblem& sub, const VectorXd& u0, const IpoptOptions& ipopt, SolveReport& rep) {
  const VectorXd x = sub.reduced().restrict(u0);
  Step s;
  s.condensed = sub.condensed() != nullptr;
  GeometrySubproblem::Outcome out = sub.solve(x, 1, SubproblemWarmStart{}, ipopt, true, rep);
  EXPECT_TRUE(out.solution.result.success) << out.solution.result.status_text;
  s.dual = out.dual;
  const VectorXd xs = s.condensed ? sub.condensed()->expand(out.solution.result.x) : out.solution.result.x;
  s.u = sub.reduced().expand(xs);
  s.multipliers = out.solution.result.multipliers;
  return s;
}

ContactSolveOptions options(bool condense) {
  ContactSolveOptions o;
  o.static_condensation = condense;
  o.ipopt.tolerance = 1e-11;
  return o;
}

}  // namespace

TEST_F(GeometrySubproblemTest, CondensedByTheDualAndWholeByThePrimalGiveTheSameSolution) {
  const Step condensed = solve_once(*built(options(true)), u0_, options(true).ipopt, rep_);
  const Step whole = solve_once(*built(options(false)), u0_, options(false).ipopt, rep_);
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

TEST_F(GeometrySubproblemTest, TheSameLinearisationIsUnchangedAndAMovedOneIsNot) {
  // In the current geometry the rows are the slave nodes' projections on the master facets, which move with
  // the displacement.
  const Model& m = model();
  const auto sub = built(ContactSolveOptions());
  const ContactLinearization lin = m.contacts().linearize(m.dofs(), u0_);
  EXPECT_TRUE(sub->unchanged(lin, u0_, 0.0));
  // A tangential shift of one block moves every projection on the other: other coefficients in A.
  ASSERT_GE(m.dofs().num_bodies(), 2);
  VectorXd shifted = u0_;
  for (Index d = m.dofs().offset(0); d < m.dofs().offset(1); d += m.dofs().dim()) shifted[d] += 1e-3;
  EXPECT_FALSE(sub->unchanged(m.contacts().linearize(m.dofs(), shifted), shifted, 1.0));
  // The same rows with gaps moved by 1e-9: unchanged to 1e-8, not to 1e-10.
  ContactLinearization moved = lin;
  moved.b.array() += 1e-9;
  EXPECT_TRUE(sub->unchanged(moved, u0_, 1e-8));
  EXPECT_FALSE(sub->unchanged(moved, u0_, 1e-10));
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

TEST_F(GeometrySubproblemTest, MultipliersCarriedToChangedRowsStartTheActiveSetNewton) {
  // The primal's condensed subproblem: without a start the dense interior point solves it; with the multipliers
  // of rows that changed since (SubproblemWarmStart::carried, here the solution's own) Newton on their active
  // set does, in one factorisation, to the same answer; the interior point and IPOPT never see them.
  ContactSolveOptions o = options(true);
  o.subproblem_solver = SubproblemSolver::kPrimalInteriorPoint;
  auto sub = built(o);
  const VectorXd x = sub->reduced().restrict(u0_);
  const IpoptResult cold = sub->solve(x, 1, SubproblemWarmStart{}, o.ipopt, true, rep_).solution.result;
  ASSERT_TRUE(cold.success) << cold.status_text;
  EXPECT_EQ(cold.status_text.find("primal interior point: converged ("), std::string::npos) << cold.status_text;
  const SubproblemWarmStart carried{nullptr, &cold.multipliers};
  const IpoptResult warm = sub->solve(x, 2, carried, o.ipopt, true, rep_).solution.result;
  ASSERT_TRUE(warm.success) << warm.status_text;
  EXPECT_EQ(warm.status_text, "primal interior point: converged (active set: 1 factorisation)");
  EXPECT_LT((warm.x - cold.x).lpNorm<Eigen::Infinity>(), 1e-9 * cold.x.lpNorm<Eigen::Infinity>());
  EXPECT_LT((warm.multipliers - cold.multipliers).lpNorm<Eigen::Infinity>(),
            1e-8 * cold.multipliers.lpNorm<Eigen::Infinity>());
}
