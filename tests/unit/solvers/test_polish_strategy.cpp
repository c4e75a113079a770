// The polish decisions of a contact solve (solvers/polish_strategy.hpp): when closing is given up, when the
// force balance is deferred to the end of the fixed point, and that the polish it runs does remove the
// optimiser's offset.
#include <sstream>

#include <gtest/gtest.h>

#include "symcontact/core/log.hpp"
#include "symcontact/optim/ipopt_solver.hpp"
#include "symcontact/solvers/condensation_cache.hpp"
#include "symcontact/solvers/polish_strategy.hpp"

using namespace symcontact;

namespace {

/// min ½|x − t|² s.t. x₀ ≥ 0, with t = (−1, 2): the constraint is active at the solution (0, 2), μ = 1.
/// `quadratic` false declares the Hessian non-constant (as a problem with friction terms is).
class Projection : public ConstrainedProblem {
 public:
  explicit Projection(bool quadratic) : quadratic_(quadratic) {
    A_.resize(1, 2);
    A_.insert(0, 0) = 1.0;
    A_.makeCompressed();
    b_ = VectorXd::Zero(1);
    t_.resize(2);
    t_ << -1.0, 2.0;
  }
  Index num_variables() const override { return 2; }
  double objective(const VectorXd& x) override { return 0.5 * (x - t_).squaredNorm(); }
  void gradient(const VectorXd& x, VectorXd& g) override { g = x - t_; }
  void hessian_lower(const VectorXd&, SparseMatrix& H) override {
    H.resize(2, 2);
    H.setIdentity();
  }
  bool hessian_is_constant() const override { return quadratic_; }
  const SparseMatrix& constraint_matrix() const override { return A_; }
  const VectorXd& constraint_offset() const override { return b_; }

 private:
  bool quadratic_;
  SparseMatrix A_;
  VectorXd b_, t_;
};

/// The point an interior point leaves: the active constraint open by a barrier offset.
IpoptResult interior_point_answer() {
  IpoptResult r;
  r.success = true;
  r.x.resize(2);
  r.x << 1e-6, 2.0;
  r.multipliers = VectorXd::Constant(1, 1.0 - 1e-6);
  return r;
}

const Logger& quiet() {
  static std::ostringstream sink;
  static const Logger log(sink, Verbosity::kQuiet);
  return log;
}

}  // namespace

TEST(PolishStrategy, ClosingRemovesTheBarrierOffset) {
  ContactWorkspace ws;
  PolishStrategy polish(true, ws, 0);
  Projection p(true);
  IpoptResult r = interior_point_answer();
  PhaseTimes times;
  EXPECT_TRUE(polish.closes());
  EXPECT_TRUE(polish.polish_primal(p, r, quiet(), times));
  EXPECT_FALSE(polish.balance_deferred());
  EXPECT_NEAR(r.x[0], 0.0, 1e-14);
  EXPECT_NEAR(r.multipliers[0], 1.0, 1e-12);
}

// With friction terms on linear-elastic bodies a closed iteration is closed now and force-balanced once more
// at the end of the fixed point (the closing's method of multipliers leaves a stationarity error where friction
// sticks); with finite-strain bodies it is not.
TEST(PolishStrategy, AFrictionalClosingOnLinearElasticBodiesIsForceBalancedAtTheEnd) {
  for (const BodiesEnergy bodies : {BodiesEnergy::kQuadratic, BodiesEnergy::kNonQuadratic}) {
    ContactWorkspace ws;
    PolishStrategy polish(true, ws, 0, bodies);
    Projection frictional(false);
    IpoptResult r = interior_point_answer();
    PhaseTimes times;
    EXPECT_TRUE(polish.polish_primal(frictional, r, quiet(), times));
    EXPECT_NEAR(r.x[0], 0.0, 1e-14) << "closed now";
    EXPECT_EQ(polish.balance_deferred(), bodies == BodiesEnergy::kQuadratic);
    EXPECT_TRUE(polish.closes()) << "closing goes on";
    EXPECT_FALSE(ws.closing_polish_rejected);
  }
}

TEST(PolishStrategy, DisabledPolishLeavesTheOptimiserPoint) {
  ContactWorkspace ws;
  PolishStrategy polish(false, ws, 0);
  Projection p(true);
  IpoptResult r = interior_point_answer();
  PhaseTimes times;
  EXPECT_FALSE(polish.closes());
  EXPECT_FALSE(polish.polish_primal(p, r, quiet(), times));
  EXPECT_EQ(r.x[0], 1e-6);
}

TEST(PolishStrategy, AClosingRejectedInThePreviousFrictionalSolveDefersTheForceBalance) {
  ContactWorkspace ws;
  ws.closing_polish_rejected = true;
  Projection frictional(false);
  IpoptResult r = interior_point_answer();
  PhaseTimes times;
  PolishStrategy polish(true, ws, 0);
  EXPECT_FALSE(polish.polish_primal(frictional, r, quiet(), times));
  EXPECT_TRUE(polish.balance_deferred());
  EXPECT_FALSE(polish.closes());
  EXPECT_EQ(r.x[0], 1e-6) << "a deferred balance leaves the point to the end of the fixed point";
  // The balance at the end removes the stationarity error only: the constraint keeps its value.
  VectorXd x = r.x, mu = r.multipliers;
  polish.balance(frictional, x, mu, quiet(), times);
  EXPECT_NEAR(x[0], 1e-6, 1e-15);
  EXPECT_NEAR(mu[0], 1.0 + 1e-6, 1e-12) << "∇f = Aᵀμ at x: μ = x₀ − t₀";
  // A quadratic problem is not concerned: the same workspace flag, closing still tried.
  PolishStrategy quadratic(true, ws, 0);
  Projection p(true);
  IpoptResult rq = interior_point_answer();
  EXPECT_TRUE(quadratic.polish_primal(p, rq, quiet(), times));
}

TEST(PolishStrategy, ARejectedDualClosingIsGivenUpForTheSolve) {
  ContactWorkspace ws;
  PolishStrategy polish(true, ws, 0);
  polish.closing_rejected("the set cycles", quiet());
  EXPECT_FALSE(polish.closes());
  polish.closed_by_method();
  EXPECT_FALSE(polish.balance_deferred());
}

TEST(PolishStrategy, WithoutAccelerationClosingStopsOnceTheChangeGrewTwiceInARow) {
  ContactWorkspace ws;
  PolishStrategy polish(true, ws, 0);
  std::vector<double> history;
  for (double change : {1e-2, 1e-4, 2e-4}) {
    polish.record_change(change, true, history, quiet());
    history.push_back(change);
    EXPECT_TRUE(polish.closes()) << "after " << change;
  }
  polish.record_change(3e-4, false, history, quiet());
  EXPECT_TRUE(polish.closes()) << "an iteration not closed exactly does not count";
  polish.record_change(3e-4, true, history, quiet());
  EXPECT_FALSE(polish.closes()) << "grew twice in a row with the set closed";
}

TEST(PolishStrategy, WithAccelerationClosingStopsAfterMemoryPlusTwoClosedIterationsWithoutANewLow) {
  ContactWorkspace ws;
  const int memory = 3;
  PolishStrategy polish(true, ws, memory);
  std::vector<double> history;
  polish.record_change(1e-5, true, history, quiet());
  history.push_back(1e-5);
  for (int k = 1; k <= memory + 2; ++k) {
    polish.record_change(k % 2 ? 4e-5 : 2e-5, true, history, quiet());  // not monotone, no new low
    history.push_back(2e-5);
    EXPECT_TRUE(polish.closes()) << "after " << k << " iterations without a new low";
  }
  polish.record_change(3e-5, true, history, quiet());
  EXPECT_FALSE(polish.closes());
}
