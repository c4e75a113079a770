// FrictionTerm, the regularised Tresca energy j = Σ_q w_q τ_q sqrt(|s_q|² + α²) (friction_term.hpp):
// its gradient and Hessian against finite differences (the shared check_derivatives), P1 and P2, between
// two non-matching flat blocks and against a plane obstacle, at random states, at zero slip and at
// slips of order α; its value at the start of the step, its convexity, the regularised law at one
// point (tangential force −τ w s / sqrt(s² + α²)), new thresholds on the same points, and the primal-dual
// Newton model of its Hessian.
//
// Choice of the finite-difference step. η_α(s) = sqrt(s² + α²) bends on the length α: η'' = α²/r³ and
// η''' = −3 α² s / r⁵, so |η'''| ~ 1/α² near s ~ α. A central difference of the gradient with step h
// errs by h² η''''/6 ~ h²/α³ against a Hessian of size 1/α: relative error (h/α)². With h ≥ α the
// check compares the Hessian with a secant over the whole bend and fails for a correct term; with
// h = 1e-3 α the truncation error is ~1e-6 relative, and the round-off (ε ‖g‖ / h ~ 1e-16 / 1e-3 α)
// stays far below it for the α used here. So every check below uses h = 1e-3 α.
#include "symcontact/contact/friction_term.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "support/finite_difference.hpp"
#include "symcontact/contact/contact_points.hpp"
#include "symcontact/mesh/structured.hpp"
#include "symcontact/solvers/condensed_problem.hpp"

using namespace symcontact;
using namespace symcontact::testing;

namespace {

const double kAlpha = 1e-4;
const double kFdStep = 1e-3 * kAlpha;  // well below α: see the file comment
const double kTol = 1e-6;

/// Two flat blocks in one DofMap: the lower [0, 1] × [−0.5, 0] (body 0, 5 × 2) is the master through
/// its "top"; the upper [0.13, 0.83] × [0, 0.4] (body 1, 7 × 2, non-matching) is the slave through its
/// "bottom". Without `with_master` only the upper block exists, over a plane obstacle.
struct Interface {
  Mesh lower, upper;
  DofMap dofs{2};
  ContactSurface master, slave;
  bool with_master = true;
  int slave_body = 0;
  std::vector<ContactPoint> points;
  Eigen::Vector2d tangent = Eigen::Vector2d::UnitX();  ///< tangent of the frozen normal (all points alike)
};

/// Rigid rotation by `angle` about the origin of every node of `body`, added to u.
void add_rotation(const Interface& s, const Mesh& m, int body, double angle, VectorXd& u) {
  const Eigen::Matrix2d R = Eigen::Rotation2Dd(angle).toRotationMatrix() - Eigen::Matrix2d::Identity();
  for (Index k = 0; k < m.num_nodes(); ++k) {
    const Eigen::Vector2d d = R * Eigen::Vector2d(m.x.col(k).head<2>());
    for (int i = 0; i < 2; ++i) u[s.dofs.dof(body, k, i)] += d[i];
  }
}

/// The body–body interface, its contact points computed at the configuration rotated by `tilt`
/// (both blocks together), so that the frozen normals are n = (−sin tilt, cos tilt).
Interface body_body(int order, double tilt) {
  Interface s;
  s.lower = rectangle_mesh(0.0, -0.5, 1.0, 0.0, 5, 2, order);
  s.upper = rectangle_mesh(0.13, 0.0, 0.83, 0.4, 7, 2, order);
  const int b0 = s.dofs.add_body(s.lower.num_nodes());
  s.slave_body = s.dofs.add_body(s.upper.num_nodes());
  s.master = make_contact_surface(s.lower, "top", b0, "lower.top");
  s.slave = make_contact_surface(s.upper, "bottom", s.slave_body, "upper.bottom");
  VectorXd u = VectorXd::Zero(s.dofs.num_dofs());
  add_rotation(s, s.lower, b0, tilt, u);
  add_rotation(s, s.upper, s.slave_body, tilt, u);
  const MasterGeometry mg = prepare_master(s.master, current_positions(s.master, s.dofs, u));
  ContactSearchOptions opt;
  opt.search_distance = 0.5;
  s.points = contact_points(s.slave, current_positions(s.slave, s.dofs, u), mg, opt);
  s.tangent = Eigen::Vector2d(std::cos(tilt), std::sin(tilt));
  return s;
}

/// The upper block alone over the plane through (0, −0.02) with normal (−sin tilt, cos tilt).
Interface against_plane(int order, double tilt) {
  Interface s;
  s.with_master = false;
  s.upper = rectangle_mesh(0.13, 0.0, 0.83, 0.4, 7, 2, order);
  s.slave_body = s.dofs.add_body(s.upper.num_nodes());
  s.slave = make_contact_surface(s.upper, "bottom", s.slave_body, "upper.bottom");
  Obstacle plane;
  plane.point = Eigen::Vector3d(0.0, -0.02, 0.0);
  plane.normal = Eigen::Vector3d(-std::sin(tilt), std::cos(tilt), 0.0);
  ContactSearchOptions opt;
  opt.search_distance = 0.5;
  s.points = contact_points(s.slave, current_positions(s.slave, s.dofs, VectorXd::Zero(s.dofs.num_dofs())), plane, opt);
  s.tangent = Eigen::Vector2d(std::cos(tilt), std::sin(tilt));
  return s;
}

std::vector<double> random_tau(std::size_t n, unsigned seed) {
  // τ of order 10 so that the gradients are of order 1 and the FD check's scale max(1, ‖g‖∞) is theirs.
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(5.0, 20.0);
  std::vector<double> tau(n);
  for (double& t : tau) t = U(rng);
  return tau;
}

VectorXd random_vector(Index n, double amplitude, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  VectorXd v(n);
  for (Index i = 0; i < n; ++i) v[i] = amplitude * U(rng);
  return v;
}

/// Translation of the slave body by c along the tangent: every point slips by exactly c.
VectorXd slave_slide(const Interface& s, double c) {
  VectorXd v = VectorXd::Zero(s.dofs.num_dofs());
  for (Index k = 0; k < s.upper.num_nodes(); ++k)
    for (int i = 0; i < 2; ++i) v[s.dofs.dof(s.slave_body, k, i)] = c * s.tangent[i];
  return v;
}

FrictionTerm make_term(const Interface& s, const std::vector<double>& tau, const VectorXd& u_start) {
  return FrictionTerm("friction", s.slave, s.with_master ? &s.master : nullptr, s.points, tau,
                      std::vector<double>(s.points.size(), kAlpha), s.dofs, u_start);
}

Eigen::MatrixXd dense_hessian(const FrictionTerm& term, const VectorXd& u) {
  TripletSink sink;
  term.add_hessian(u, sink);
  return Eigen::MatrixXd(sink.to_matrix(u.size()));
}

struct Case {
  int order;
  bool with_master;
  double tilt;
};

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  return std::string(info.param.with_master ? "BodyBody" : "Plane") + "P" + std::to_string(info.param.order) +
         (info.param.tilt != 0.0 ? "Tilted" : "Flat");
}

class FrictionTermCase : public ::testing::TestWithParam<Case> {
 protected:
  Interface interface() const {
    const Case c = GetParam();
    return c.with_master ? body_body(c.order, c.tilt) : against_plane(c.order, c.tilt);
  }
};

}  // namespace

TEST_P(FrictionTermCase, HasContactPointsWithTheFrozenNormal) {
  const Interface s = interface();
  ASSERT_GE(s.points.size(), 7u * 3u);  // at least 3 points per slave facet
  const Eigen::Vector2d n(-s.tangent[1], s.tangent[0]);
  for (const ContactPoint& p : s.points) EXPECT_NEAR((p.normal.head<2>() - n).norm(), 0.0, 1e-12);
}

TEST_P(FrictionTermCase, DerivativesAtRandomStates) {
  const Interface s = interface();
  const Index n = s.dofs.num_dofs();
  const std::vector<double> tau = random_tau(s.points.size(), 3);
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const VectorXd u0 = random_vector(n, 0.01, 10 + seed);
    const FrictionTerm term = make_term(s, tau, u0);
    // Increments of 10 α per DOF: slips from ~0 to ~30 α, in every direction of the tangent.
    const VectorXd u = u0 + random_vector(n, 10 * kAlpha, 20 + seed);
    const FdResult r = check_derivatives(term, u, kFdStep, 6, 400, seed);
    EXPECT_LT(r.gradient_error, kTol) << "seed " << seed;
    EXPECT_LT(r.hessian_error, kTol) << "seed " << seed;
  }
}

TEST_P(FrictionTermCase, DerivativesAtZeroSlip) {
  const Interface s = interface();
  const VectorXd u0 = random_vector(s.dofs.num_dofs(), 0.01, 7);
  const FrictionTerm term = make_term(s, random_tau(s.points.size(), 4), u0);
  for (const Eigen::Vector3d& sq : term.slips(u0)) EXPECT_EQ(sq.norm(), 0.0);  // u = u_start: exactly 0
  // At s = 0 the gradient vanishes and the Hessian is w τ PBᵀPB / α, its largest value.
  VectorXd g = VectorXd::Zero(u0.size());
  term.add_gradient(u0, g);
  EXPECT_EQ(g.cwiseAbs().maxCoeff(), 0.0);
  const FdResult r = check_derivatives(term, u0, kFdStep, 6);
  EXPECT_LT(r.gradient_error, kTol);
  EXPECT_LT(r.hessian_error, kTol);
}

TEST_P(FrictionTermCase, DerivativesAtSlipsOfOrderAlpha) {
  const Interface s = interface();
  const Index n = s.dofs.num_dofs();
  const VectorXd u0 = random_vector(n, 0.01, 8);
  const FrictionTerm term = make_term(s, random_tau(s.points.size(), 5), u0);
  for (double factor : {1e-3, 1.0, 10.0}) {
    const double c = factor * kAlpha;
    // A uniform slide by c, spread by ±10 % so that the points differ.
    const VectorXd u = u0 + slave_slide(s, c) + random_vector(n, 0.1 * c, 30);
    double smin = 1e300, smax = 0.0;
    for (const Eigen::Vector3d& sq : term.slips(u)) {
      smin = std::min(smin, sq.norm());
      smax = std::max(smax, sq.norm());
    }
    EXPECT_GT(smin, 0.5 * c);
    EXPECT_LT(smax, 1.5 * c);
    const FdResult r = check_derivatives(term, u, kFdStep, 6);
    std::printf("  slip %g alpha: FD gradient error %.2e, Hessian error %.2e\n", factor, r.gradient_error,
                r.hessian_error);
    EXPECT_LT(r.gradient_error, kTol) << "slip " << factor << " alpha";
    EXPECT_LT(r.hessian_error, kTol) << "slip " << factor << " alpha";
  }
}

// slip_map: the maps B_q give the term's slips, s_q = P_q B_q (u − u⁰), and its gradient,
// Σ_q B_qᵀ w τ s_q / r_q (r_q = √(|s_q|² + α²)): what the distributed interior point builds its friction from.
TEST_P(FrictionTermCase, SlipMapGivesTheSlipsAndTheGradient) {
  const Interface s = interface();
  const Index n = s.dofs.num_dofs();
  const std::vector<double> tau = random_tau(s.points.size(), 14);
  const VectorXd u0 = random_vector(n, 0.01, 15);
  const VectorXd u = u0 + random_vector(n, 10 * kAlpha, 16);
  const FrictionTerm term = make_term(s, tau, u0);
  const SparseMatrix B = term.slip_map(n);
  ASSERT_EQ(B.rows(), 2 * static_cast<Index>(s.points.size()));
  const VectorXd v = B * (u - u0);
  const std::vector<Eigen::Vector3d> slips = term.slips(u);
  const std::vector<double> bounds = term.bounds();
  VectorXd gradient = VectorXd::Zero(n), expected = VectorXd::Zero(n);
  term.add_gradient(u, gradient);
  double scale = 0.0;
  for (std::size_t q = 0; q < s.points.size(); ++q) {
    const Eigen::Vector2d normal = s.points[q].normal.head<2>();
    const Eigen::Vector2d vq = v.segment<2>(2 * static_cast<Index>(q));
    const Eigen::Vector2d sq = vq - normal * normal.dot(vq);
    // to round-off in the displacements (the term subtracts P B u⁰ after the product)
    EXPECT_NEAR((sq - slips[q].head<2>()).norm(), 0.0, 1e-13 * u.lpNorm<Eigen::Infinity>()) << "point " << q;
    const double r = std::sqrt(sq.squaredNorm() + kAlpha * kAlpha);
    VectorXd per_point = VectorXd::Zero(2 * static_cast<Index>(s.points.size()));
    per_point.segment<2>(2 * static_cast<Index>(q)) = bounds[q] / r * sq;
    expected += B.transpose() * per_point;
    scale = std::max(scale, bounds[q]);
  }
  EXPECT_LT((gradient - expected).lpNorm<Eigen::Infinity>(), 1e-13 * scale);
  EXPECT_GT(gradient.lpNorm<Eigen::Infinity>(), 0.0);
}

TEST_P(FrictionTermCase, ValueAtTheStartIsSumOfWeightTauAlpha) {
  const Interface s = interface();
  const std::vector<double> tau = random_tau(s.points.size(), 6);
  const VectorXd u0 = random_vector(s.dofs.num_dofs(), 0.01, 9);
  const FrictionTerm term = make_term(s, tau, u0);
  double expected = 0.0;
  for (std::size_t q = 0; q < s.points.size(); ++q) expected += s.points[q].weight * tau[q] * kAlpha;
  EXPECT_NEAR(term.value(u0), expected, 1e-14 * expected);
  // A uniform slide by c: every point adds w τ (sqrt(c² + α²) − α).
  const double c = 3 * kAlpha;
  EXPECT_NEAR(term.value(u0 + slave_slide(s, c)), expected * std::sqrt(c * c + kAlpha * kAlpha) / kAlpha,
              1e-12 * expected);
}

// set_thresholds: the term with new thresholds is the term built with them (value, gradient, Hessian), and
// with the zero blocks kept its DOF support does not depend on them: a point with τ = 0 keeps its (zero)
// Hessian block.
TEST_P(FrictionTermCase, NewThresholdsGiveTheTermBuiltWithThemOnTheSameSupport) {
  const Interface s = interface();
  const Index n = s.dofs.num_dofs();
  const VectorXd u0 = random_vector(n, 0.01, 11);
  const VectorXd u = u0 + random_vector(n, 10 * kAlpha, 12);
  std::vector<double> tau = random_tau(s.points.size(), 13);
  for (std::size_t q = 0; q < tau.size(); q += 3) tau[q] = 0.0;
  FrictionTerm term = make_term(s, std::vector<double>(s.points.size(), 0.0), u0);
  EXPECT_TRUE(support_of(term, u).empty()) << "no blocks of zero thresholds by default";
  term.keep_zero_blocks(true);
  const std::vector<Index> support = support_of(term, u);
  EXPECT_FALSE(support.empty());
  term.set_thresholds(tau);
  const FrictionTerm built = make_term(s, tau, u0);
  EXPECT_EQ(term.value(u), built.value(u));
  VectorXd g = VectorXd::Zero(n), gb = VectorXd::Zero(n);
  term.add_gradient(u, g);
  built.add_gradient(u, gb);
  EXPECT_EQ((g - gb).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((dense_hessian(term, u) - dense_hessian(built, u)).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(support_of(term, u), support);
  EXPECT_GT(g.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_THROW(term.set_thresholds(std::vector<double>(tau.size() + 1, 1.0)), std::invalid_argument);
}

TEST_P(FrictionTermCase, HessianIsPositiveSemidefinite) {
  const Interface s = interface();
  const Index n = s.dofs.num_dofs();
  const VectorXd u0 = random_vector(n, 0.01, 11);
  const FrictionTerm term = make_term(s, random_tau(s.points.size(), 7), u0);
  for (double amplitude : {0.0, kAlpha, 10 * kAlpha}) {
    const VectorXd u = u0 + random_vector(n, amplitude, 12);
    const Eigen::MatrixXd H = dense_hessian(term, u);
    const double scale = H.cwiseAbs().maxCoeff();
    ASSERT_GT(scale, 0.0);
    EXPECT_LT((H - H.transpose()).cwiseAbs().maxCoeff(), 1e-14 * scale);
    for (unsigned seed = 0; seed < 20; ++seed) {
      const VectorXd x = random_vector(n, 1.0, 100 + seed);
      EXPECT_GE(x.dot(H * x), -1e-12 * scale * x.squaredNorm()) << "amplitude " << amplitude;
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(H, Eigen::EigenvaluesOnly);
    EXPECT_GE(eig.eigenvalues().minCoeff(), -1e-12 * scale) << "amplitude " << amplitude;
    // Along a line the energy is convex: midpoint below the chord.
    const VectorXd a = u0 + random_vector(n, 10 * kAlpha, 13), b = u0 + random_vector(n, 10 * kAlpha, 14);
    EXPECT_LE(term.value(0.5 * (a + b)), 0.5 * (term.value(a) + term.value(b)) + 1e-15);
  }
}

TEST_P(FrictionTermCase, RegularisedLawAtOnePoint) {
  const Interface s = interface();
  // One point in the middle of the slave, alone in its term.
  const std::size_t q = s.points.size() / 2;
  Interface one = s;
  one.points = {s.points[q]};
  const double tau = 2.5, w = s.points[q].weight;
  const VectorXd u0 = random_vector(s.dofs.num_dofs(), 0.01, 15);
  const FrictionTerm term = make_term(one, {tau}, u0);
  for (double c : {0.0, 1e-3 * kAlpha, -0.5 * kAlpha, kAlpha, 3 * kAlpha, -10 * kAlpha, 1e3 * kAlpha}) {
    const VectorXd u = u0 + slave_slide(one, c);
    ASSERT_NEAR(term.slips(u)[0].head<2>().dot(one.tangent), c, 1e-15);
    // The force on the slave is −∇j over its DOFs; its tangential resultant is the law's.
    VectorXd g = VectorXd::Zero(u.size());
    term.add_gradient(u, g);
    Eigen::Vector2d f_slave = Eigen::Vector2d::Zero(), f_master = Eigen::Vector2d::Zero();
    for (Index k = 0; k < one.upper.num_nodes(); ++k)
      for (int i = 0; i < 2; ++i) f_slave[i] -= g[one.dofs.dof(one.slave_body, k, i)];
    if (one.with_master)
      for (Index k = 0; k < one.lower.num_nodes(); ++k)
        for (int i = 0; i < 2; ++i) f_master[i] -= g[one.dofs.dof(0, k, i)];
    const double law = -tau * w * c / std::sqrt(c * c + kAlpha * kAlpha);
    EXPECT_NEAR(f_slave.dot(one.tangent), law, 1e-12 * tau * w) << "slip " << c;
    EXPECT_NEAR(f_slave.dot(Eigen::Vector2d(-one.tangent[1], one.tangent[0])), 0.0, 1e-12 * tau * w);  // purely tangential
    if (one.with_master) {
      EXPECT_NEAR((f_slave + f_master).norm(), 0.0, 1e-12 * tau * w);  // action = reaction
    }
  }
}

// The primal-dual model (FrictionHessian::kPrimalDual) at one point slipping back, then forward: its first
// evaluation is ∇²j (z = s/r); the second carries z by the linearisation of z r = s, so that the curvature
// along the slip is w τ (1 − z s/r)/r, about 2 w τ/r where the slip turned, against ∇²j's w τ α²/r³.
TEST_P(FrictionTermCase, PrimalDualModelCarriesTheTractionDirection) {
  const Interface s = interface();
  Interface one = s;
  one.points = {s.points[s.points.size() / 2]};
  const double tau = 2.5, wt = tau * one.points[0].weight;
  const VectorXd u0 = random_vector(s.dofs.num_dofs(), 0.01, 16);
  const FrictionTerm exact = make_term(one, {tau}, u0);
  FrictionTerm model = make_term(one, {tau}, u0);
  model.set_hessian_model(FrictionHessian::kPrimalDual);
  const double c1 = -10 * kAlpha, c2 = 10 * kAlpha;
  const VectorXd u1 = u0 + slave_slide(one, c1), u2 = u0 + slave_slide(one, c2), v = slave_slide(one, 1.0);
  const Eigen::MatrixXd H1 = dense_hessian(model, u1);
  EXPECT_LT((H1 - dense_hessian(exact, u1)).cwiseAbs().maxCoeff(), 1e-13 * H1.cwiseAbs().maxCoeff());
  const double r1 = std::hypot(c1, kAlpha), r2 = std::hypot(c2, kAlpha);
  const double z1 = c1 / r1, z2 = std::clamp(z1 + (1 - z1 * z1) * (c2 - c1) / r1, -1.0, 1.0);
  const Eigen::MatrixXd H2 = dense_hessian(model, u2);
  const double along = v.dot(H2 * v), along_exact = v.dot(dense_hessian(exact, u2) * v);
  EXPECT_NEAR(along, wt * (1 - z2 * c2 / r2) / r2, 1e-10 * wt / r2);
  EXPECT_NEAR(along_exact, wt * kAlpha * kAlpha / (r2 * r2 * r2), 1e-10 * wt / r2);
  EXPECT_GT(along, 100 * along_exact);
  // The same point again: z is kept, the model unchanged; the gradient is the exact one.
  EXPECT_EQ((dense_hessian(model, u2) - H2).cwiseAbs().maxCoeff(), 0.0);
  VectorXd g = VectorXd::Zero(u2.size()), g_exact = VectorXd::Zero(u2.size());
  model.add_gradient(u2, g);
  exact.add_gradient(u2, g_exact);
  EXPECT_EQ((g - g_exact).cwiseAbs().maxCoeff(), 0.0);
}

// Along any sequence of states the model stays symmetric and positive semidefinite (|z| ≤ 1).
TEST_P(FrictionTermCase, PrimalDualModelIsPositiveSemidefinite) {
  const Interface s = interface();
  const Index n = s.dofs.num_dofs();
  const VectorXd u0 = random_vector(n, 0.01, 17);
  FrictionTerm model = make_term(s, random_tau(s.points.size(), 8), u0);
  model.set_hessian_model(FrictionHessian::kPrimalDual);
  for (unsigned k = 0; k < 6; ++k) {
    const VectorXd u = u0 + random_vector(n, 10 * kAlpha, 40 + k);
    const Eigen::MatrixXd H = dense_hessian(model, u);
    const double scale = H.cwiseAbs().maxCoeff();
    ASSERT_GT(scale, 0.0);
    EXPECT_LT((H - H.transpose()).cwiseAbs().maxCoeff(), 1e-14 * scale);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(H, Eigen::EigenvaluesOnly);
    EXPECT_GE(eig.eigenvalues().minCoeff(), -1e-12 * scale) << "state " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(FrictionTerm, FrictionTermCase,
                         ::testing::Values(Case{1, true, 0.0}, Case{2, true, 0.0}, Case{1, true, 0.3},
                                           Case{2, true, 0.3}, Case{1, false, 0.0}, Case{2, false, 0.0},
                                           Case{1, false, 0.3}, Case{2, false, 0.3}),
                         case_name);

// ---------------------------------------------------------------------------------------------------
// 3D: two-component slips in the tangent plane, between two non-matching boxes (Tri3 / Tri6 facets), with
// the nodal points the solver uses (nodal_contact_points) and with the segment-based mortar points.

/// Two non-matching boxes in one DofMap: the lower [0, 1]² × [−0.5, 0] (body 0) is the master through its
/// "zmax"; the upper [0.13, 0.83] × [0.1, 0.9] × [0, 0.4] (body 1) the slave through its "zmin".
struct Boxes {
  Mesh lower, upper;
  DofMap dofs{3};
  ContactSurface master, slave;
  int slave_body = 1;
};

Boxes boxes(int order) {
  Boxes b;
  b.lower = box_mesh(Vec3(0, 0, -0.5), Vec3(1, 1, 0), 3, 3, 1, order);
  b.upper = box_mesh(Vec3(0.13, 0.1, 0), Vec3(0.83, 0.9, 0.4), 4, 3, 1, order);
  const int b0 = b.dofs.add_body(b.lower.num_nodes());
  b.slave_body = b.dofs.add_body(b.upper.num_nodes());
  b.master = make_contact_surface(b.lower, "zmax", b0, "lower.top");
  b.slave = make_contact_surface(b.upper, "zmin", b.slave_body, "upper.bottom");
  return b;
}

/// The slave's nodal points (one per surface node, nodal_contact_points()) on the undeformed master.
std::vector<ContactPoint> nodal_points(const Boxes& b) {
  const MasterGeometry mg = prepare_master(b.master, b.master.X);
  return nodal_contact_points(b.slave, b.slave.X, &mg, nullptr, 0.5);
}

/// Translation of the slave body by d: every point slips by exactly d (d tangential).
VectorXd slave_translation(const Boxes& b, const Eigen::Vector3d& d) {
  VectorXd v = VectorXd::Zero(b.dofs.num_dofs());
  for (Index k = 0; k < b.upper.num_nodes(); ++k)
    for (int i = 0; i < 3; ++i) v[b.dofs.dof(b.slave_body, k, i)] = d[i];
  return v;
}

/// The slave's tangential traction recovered from the term's force as the post-processing and the Coulomb
/// threshold recover it (surface_tractions.hpp): t_i = (T F)_i / A_i, F = −∇j on the slave's nodes.
Eigen::MatrixXd recovered_traction(const Boxes& b, const FrictionTerm& term, const VectorXd& u) {
  VectorXd g = VectorXd::Zero(u.size());
  term.add_gradient(u, g);
  Eigen::MatrixXd F(3, b.slave.num_nodes());
  for (Index k = 0; k < b.slave.num_nodes(); ++k)
    for (int i = 0; i < 3; ++i) F(i, k) = -g[b.dofs.dof(b.slave_body, b.slave.nodes[k], i)];
  Eigen::MatrixXd t = test_basis_forces(b.slave, F);
  for (Index k = 0; k < b.slave.num_nodes(); ++k) t.col(k) /= b.slave.nodal_area[k];
  return t;
}

/// Whether nodal point p sits at an edge node of its facet (Tri6 local nodes 3–5).
bool at_edge_node(const ContactSurface& s, const ContactPoint& p) {
  const Index* f = s.facet(p.slave_facet);
  return std::find(f, f + s.nodes_per_facet(), p.slave_node) - f >= 3;
}

class FrictionTerm3D : public ::testing::TestWithParam<int> {};

TEST_P(FrictionTerm3D, DerivativesAtRandomStatesAndAtZeroSlip) {
  const Boxes b = boxes(GetParam());
  const MasterGeometry mg = prepare_master(b.master, b.master.X);
  ContactSearchOptions opt;
  opt.search_distance = 0.5;
  std::vector<std::vector<ContactPoint>> point_sets = {contact_points(b.slave, b.slave.X, mg, opt), nodal_points(b)};
  // The nodal points less a few vertices (on Tri6: edge nodes whose vertex projects onto nothing).
  std::vector<ContactPoint> without_some_vertices;
  for (const ContactPoint& p : point_sets[1])
    if (at_edge_node(b.slave, p) || p.slave_node % 3 != 0) without_some_vertices.push_back(p);
  ASSERT_LT(without_some_vertices.size(), point_sets[1].size());
  point_sets.push_back(without_some_vertices);
  for (const auto& points : point_sets) {
    ASSERT_GT(points.size(), 10u);
    for (const ContactPoint& p : points) ASSERT_NEAR((p.normal - Eigen::Vector3d(0, 0, 1)).norm(), 0.0, 1e-14);  // the master's n̄
    const std::vector<double> tau = random_tau(points.size(), 6);
    const Index n = b.dofs.num_dofs();
    const VectorXd u0 = random_vector(n, 0.01, 41);
    std::vector<double> alpha(points.size());  // a regularisation length of its own at every point
    for (std::size_t q = 0; q < points.size(); ++q) alpha[q] = kAlpha * (0.5 + 0.1 * static_cast<double>(q % 10));
    const FrictionTerm term("friction", b.slave, &b.master, points, tau, alpha, b.dofs, u0);
    // Slips have both tangential components, none along the normal.
    const VectorXd u = u0 + random_vector(n, 10 * kAlpha, 42);
    double sx = 0, sy = 0;
    for (const Eigen::Vector3d& s : term.slips(u)) {
      EXPECT_EQ(s.z(), 0.0);
      sx = std::max(sx, std::abs(s.x()));
      sy = std::max(sy, std::abs(s.y()));
    }
    EXPECT_GT(sx, kAlpha);
    EXPECT_GT(sy, kAlpha);
    for (const VectorXd& state : {u, u0}) {
      const FdResult r = check_derivatives(term, state, kFdStep, 6, 400, 3);
      EXPECT_LT(r.gradient_error, kTol);
      EXPECT_LT(r.hessian_error, kTol);
    }
    // A uniform slide is a uniform slip in any basis: every point slips by d, also on Tri6 edge nodes.
    const Eigen::Vector3d d(3 * kAlpha, -2 * kAlpha, 0.0);
    for (const Eigen::Vector3d& s : term.slips(u0 + slave_translation(b, d))) EXPECT_LT((s - d).norm(), 1e-12 * d.norm());
  }
}

// The nodal friction law in the basis the thresholds live in: with the solver's nodal points, the tangential
// traction recovered from the term's force (in the test basis, as the pressure and τ = μ p are) satisfies
// |t_i| ≤ τ_i at every node, for a slip that varies from node to node and a threshold that does too. On Tri6
// facets this holds because the term measures the slip in the test basis (friction_term.hpp); with the
// standard nodal slips a vertex's traction also carries c times its edge neighbours' friction forces.
TEST_P(FrictionTerm3D, RecoveredTractionSatisfiesTheNodalLaw) {
  const Boxes b = boxes(GetParam());
  std::vector<ContactPoint> all = nodal_points(b), some;
  ASSERT_EQ(static_cast<Index>(all.size()), b.slave.num_nodes());
  for (const ContactPoint& p : all)
    if (p.slave_node % 5 != 0) some.push_back(p);
  for (const std::vector<ContactPoint>* points : {&all, &some}) {
    const std::vector<double> point_tau = random_tau(points->size(), 17);
    Eigen::VectorXd tau = Eigen::VectorXd::Zero(b.slave.num_nodes());  // 0 at nodes without a point
    for (std::size_t q = 0; q < points->size(); ++q) tau[(*points)[q].slave_node] = point_tau[q];
    const Index n = b.dofs.num_dofs();
    const VectorXd u0 = random_vector(n, 0.01, 51);
    const FrictionTerm term("friction", b.slave, &b.master, *points, point_tau,
                            std::vector<double>(points->size(), kAlpha), b.dofs, u0);
    // Slips of 10 to 1000 α, in every direction: from the regularised zone to full slip at every node.
    for (double amplitude : {10 * kAlpha, 1e3 * kAlpha}) {
      const VectorXd u = u0 + random_vector(n, amplitude, 52);
      const Eigen::MatrixXd t = recovered_traction(b, term, u);
      double worst = -1e300;
      for (Index k = 0; k < b.slave.num_nodes(); ++k) {
        worst = std::max(worst, (t.col(k).norm() - tau[k]) / tau.maxCoeff());
        EXPECT_LE(t.col(k).norm(), tau[k] * (1 + 1e-12) + 1e-12 * tau.maxCoeff()) << "node " << k;
        EXPECT_NEAR(t(2, k), 0.0, 1e-12 * tau.maxCoeff()) << "node " << k;  // tangential to n̄ = e_z
      }
      std::printf("  P%d, %zu points, slips ~%g alpha: max (|t| - tau) / max tau = %.2e\n", GetParam(),
                  points->size(), amplitude / kAlpha, worst);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(FrictionTerm, FrictionTerm3D, ::testing::Values(1, 2),
                         [](const ::testing::TestParamInfo<int>& p) { return "P" + std::to_string(p.param); });
