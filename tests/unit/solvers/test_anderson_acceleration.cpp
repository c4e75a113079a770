// Anderson acceleration (solvers/anderson_acceleration.hpp) on affine maps G(x) = J x + c, whose fixed
// point x* = (I − J)⁻¹ c is known: with J's spectrum that of the V7 3D self-contact's geometry fixed point
// (a mode alternating at −0.63 per iteration, one growing by 1.18), where the plain iteration diverges.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <random>

#include "symcontact/solvers/anderson_acceleration.hpp"

using namespace symcontact;

namespace {

/// J = Q diag(λ) Qᵀ with a random orthogonal Q (fixed seed): λ = (1.18, −0.63, then evenly in [−0.3, 0.3]),
/// and its fixed point x* = (I − J)⁻¹ c = Q diag(1/(1 − λ)) Qᵀ c.
/// Q is a product of plane rotations of random angles, written out so that this test instantiates no
/// Eigen decomposition: under ASan an instance exported by the test executable (here PartialPivLU's)
/// preempts libgmsh's own, built without ASan, and Gmsh's setOrder() in other tests of the executable
/// then frees memory our instance allocated (a bad-free; see the sanitiser section of CMakeLists.txt).
struct AffineMap {
  Eigen::MatrixXd J;
  VectorXd xstar;
};

AffineMap affine_map(int n, const VectorXd& c) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI);
  Eigen::MatrixXd Q = Eigen::MatrixXd::Identity(n, n);
  for (int sweep = 0; sweep < 3; ++sweep)
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        const double t = angle(gen), cs = std::cos(t), sn = std::sin(t);
        const VectorXd qi = Q.col(i), qj = Q.col(j);
        Q.col(i) = cs * qi - sn * qj;
        Q.col(j) = sn * qi + cs * qj;
      }
  VectorXd lambda(n);
  lambda[0] = 1.18;
  lambda[1] = -0.63;
  for (int i = 2; i < n; ++i) lambda[i] = -0.3 + 0.6 * (i - 2) / std::max(1, n - 3);
  AffineMap m;
  m.J = Q * lambda.asDiagonal() * Q.transpose();
  m.xstar = Q * (Q.transpose() * c).cwiseQuotient((1.0 - lambda.array()).matrix());
  return m;
}

}  // namespace

TEST(AndersonAcceleration, ConvergesWhereThePlainIterationGrows) {
  const int n = 40;
  const VectorXd c = VectorXd::LinSpaced(n, 1.0, 2.0);
  const AffineMap map = affine_map(n, c);
  const Eigen::MatrixXd& J = map.J;
  const VectorXd& xstar = map.xstar;
  ASSERT_LT((xstar - (J * xstar + c)).norm(), 1e-12 * xstar.norm());  // x* is the fixed point
  // The plain iteration moves away from x* (the 1.18 mode).
  VectorXd x = VectorXd::Zero(n);
  for (int k = 0; k < 60; ++k) x = J * x + c;
  EXPECT_GT((x - xstar).norm(), 1e3 * xstar.norm());
  // Accelerated with memory 5: converges.
  AndersonAcceleration aa(5);
  x = VectorXd::Zero(n);
  int k = 0;
  double residual = 1.0;
  for (; k < 60 && residual > 1e-12 * xstar.norm(); ++k) {
    const VectorXd g = J * x + c;
    residual = (g - x).norm();
    x = aa.next(x, g);
  }
  std::printf("Anderson(5) on an affine map with eigenvalues 1.18, -0.63: residual %.1e after %d iterations\n",
              residual, k);
  EXPECT_LT(k, 60);
  EXPECT_LT((x - xstar).norm(), 1e-10 * xstar.norm());
  EXPECT_LE(aa.columns(), 5);
}

TEST(AndersonAcceleration, FirstStepAndResetArePlainSteps) {
  AndersonAcceleration aa(3);
  const VectorXd x = VectorXd::Constant(4, 1.0), g = VectorXd::LinSpaced(4, 0.0, 3.0);
  EXPECT_EQ(aa.next(x, g), g);
  EXPECT_EQ(aa.columns(), 0);
  const VectorXd x2 = g, g2 = 0.5 * g + VectorXd::Constant(4, 1.0);
  EXPECT_NE(aa.next(x2, g2), g2);  // one difference column: a mixed step
  EXPECT_EQ(aa.columns(), 1);
  aa.reset();
  EXPECT_EQ(aa.next(x, g), g);
  EXPECT_THROW(AndersonAcceleration(0), std::invalid_argument);
  EXPECT_THROW(aa.next(x, VectorXd::Zero(3)), std::invalid_argument);
}
