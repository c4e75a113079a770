// Anderson acceleration (solvers/anderson_acceleration.hpp) on affine maps G(x) = J x + c, whose fixed
// point x* = (I − J)⁻¹ c is known: with J's spectrum that of the V7 3D self-contact's geometry fixed point
// (a mode alternating at −0.63 per iteration, one growing by 1.18), where the plain iteration diverges.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <random>

#include "symcontact/solvers/anderson_acceleration.hpp"

using namespace symcontact;

namespace {

/// J = Q diag(λ) Qᵀ with a random orthogonal Q (fixed seed): λ = (1.18, −0.63, then evenly in [−0.3, 0.3]).
Eigen::MatrixXd iteration_matrix(int n) {
  std::mt19937 gen(7);
  std::normal_distribution<double> N(0.0, 1.0);
  Eigen::MatrixXd R(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) R(i, j) = N(gen);
  const Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(R).householderQ();
  Eigen::VectorXd lambda(n);
  lambda[0] = 1.18;
  lambda[1] = -0.63;
  for (int i = 2; i < n; ++i) lambda[i] = -0.3 + 0.6 * (i - 2) / std::max(1, n - 3);
  return Q * lambda.asDiagonal() * Q.transpose();
}

}  // namespace

TEST(AndersonAcceleration, ConvergesWhereThePlainIterationGrows) {
  const int n = 40;
  const Eigen::MatrixXd J = iteration_matrix(n);
  const VectorXd c = VectorXd::LinSpaced(n, 1.0, 2.0);
  const VectorXd xstar = (Eigen::MatrixXd::Identity(n, n) - J).partialPivLu().solve(c);
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
