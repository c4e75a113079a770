// Pointwise hyperelastic laws (materials/hyperelastic.hpp): P against finite differences of ψ, ∂P/∂F
// against finite differences of P, for Neo-Hookean and Mooney–Rivlin in 2D plane strain and 3D, at random
// F (J in [0.5, 2]), near J = 1 (F = I + 1e-6·R) and at large stretch; ψ(I) = 0, P(I) = 0; frame
// invariance; the small-strain limit (∂P/∂F at I = the linear elastic tensor); J ≤ 0 throws.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "symcontact/core/error.hpp"
#include "symcontact/materials/hyperelastic.hpp"

using namespace symcontact;

namespace {

template <int D>
using Mat = Eigen::Matrix<double, D, D>;
template <int D>
using Tangent = Eigen::Matrix<double, D * D, D * D>;

struct Law {
  std::string name;
  Hyperelastic material;
};

std::vector<Law> laws() {
  return {{"neo_hookean(E,nu)", Hyperelastic::from_young_poisson(HyperelasticLaw::kNeoHookean, 3.0, 0.3)},
          {"neo_hookean(mu,lambda)", Hyperelastic::neo_hookean(1.3, 4.1)},
          {"mooney_rivlin(E,nu)", Hyperelastic::from_young_poisson(HyperelasticLaw::kMooneyRivlin, 3.0, 0.3)},
          {"mooney_rivlin(c1,c2,kappa)", Hyperelastic::mooney_rivlin(0.7, 0.2, 5.0)},
          {"mooney_rivlin(c2=0)", Hyperelastic::mooney_rivlin(0.5, 0.0, 2.0)}};
}

template <int D>
Mat<D> random_matrix(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  Mat<D> R;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) R(i, j) = scale * U(rng);
  return R;
}

/// A random F with det F uniform in [0.5, 2] (plane strain: det of the 2 × 2 block, F₃₃ = 1).
template <int D>
Mat<D> random_F(std::mt19937& rng, double spread) {
  std::uniform_real_distribution<double> Jd(0.5, 2.0);
  for (;;) {
    const Mat<D> F0 = Mat<D>::Identity() + random_matrix<D>(rng, spread);
    const double det = F0.determinant();
    if (det < 0.2) continue;
    return std::pow(Jd(rng) / det, 1.0 / D) * F0;
  }
}

template <int D>
Mat<D> rotation(std::mt19937& rng) {
  // The Q factor of a random matrix, with det Q = +1.
  const Eigen::HouseholderQR<Mat<D>> qr(random_matrix<D>(rng, 1.0));
  Mat<D> Q = qr.householderQ();
  if (Q.determinant() < 0) Q.col(0) *= -1.0;
  return Q;
}

/// max |P − FD(ψ)| / max|P| with central differences of step h.
template <int D>
double stress_fd_error(const Hyperelastic& m, const Mat<D>& F, double h) {
  const Mat<D> P = m.stress<D>(F);
  Mat<D> fd;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) {
      Mat<D> Fp = F, Fm = F;
      Fp(i, j) += h;
      Fm(i, j) -= h;
      fd(i, j) = (m.energy<D>(Fp) - m.energy<D>(Fm)) / (2 * h);
    }
  return (fd - P).cwiseAbs().maxCoeff() / P.cwiseAbs().maxCoeff();
}

/// max |A − FD(P)| / max|A|; A(D·i + J, D·k + L) = ∂P_iJ/∂F_kL.
template <int D>
double tangent_fd_error(const Hyperelastic& m, const Mat<D>& F, double h) {
  const Tangent<D> A = m.tangent<D>(F);
  Tangent<D> fd;
  for (int k = 0; k < D; ++k)
    for (int L = 0; L < D; ++L) {
      Mat<D> Fp = F, Fm = F;
      Fp(k, L) += h;
      Fm(k, L) -= h;
      const Mat<D> dP = (m.stress<D>(Fp) - m.stress<D>(Fm)) / (2 * h);
      for (int i = 0; i < D; ++i)
        for (int J = 0; J < D; ++J) fd(D * i + J, D * k + L) = dP(i, J);
    }
  return (fd - A).cwiseAbs().maxCoeff() / A.cwiseAbs().maxCoeff();
}

template <int D>
void check_derivatives_at(const Hyperelastic& m, const Mat<D>& F, double h, double tol, const std::string& what) {
  EXPECT_LT(stress_fd_error<D>(m, F, h), tol) << what << "\nF =\n" << F;
  EXPECT_LT(tangent_fd_error<D>(m, F, h), tol) << what << "\nF =\n" << F;
  const Tangent<D> A = m.tangent<D>(F);
  EXPECT_LT((A - A.transpose()).cwiseAbs().maxCoeff(), 1e-12 * A.cwiseAbs().maxCoeff()) << what;
}

template <int D>
void random_states() {
  std::mt19937 rng(42 + D);
  for (const Law& law : laws())
    for (int trial = 0; trial < 20; ++trial) {
      const Mat<D> F = random_F<D>(rng, 0.4);
      check_derivatives_at<D>(law.material, F, 1e-6, 1e-7, law.name + " D=" + std::to_string(D));
    }
}

template <int D>
void near_identity() {
  // F = I + 1e-6 R: P = O(1e-6), ψ = O(1e-12). Steps of 1e-9 ≪ |H| see the O(|H|²) energy only if ψ
  // keeps its relative accuracy there (the careful log1p / J − 1 forms); I₁ − 3 − 2 ln J would not.
  std::mt19937 rng(7 + D);
  for (const Law& law : laws())
    for (int trial = 0; trial < 10; ++trial) {
      const Mat<D> F = Mat<D>::Identity() + random_matrix<D>(rng, 1e-6);
      check_derivatives_at<D>(law.material, F, 1e-9, 1e-6, law.name + " near J = 1, D=" + std::to_string(D));
    }
}

template <int D>
void large_stretch() {
  std::mt19937 rng(11 + D);
  for (const Law& law : laws()) {
    std::vector<Mat<D>> states;
    Mat<D> S = Mat<D>::Identity();
    S(0, 0) = 3.0;
    S(1, 1) = 0.45;
    if (D == 3) S(D - 1, D - 1) = 1.6;
    states.push_back(S);
    states.push_back(rotation<D>(rng) * S * rotation<D>(rng));
    Mat<D> shear = Mat<D>::Identity();
    shear(0, 1) = 2.5;
    states.push_back(shear);
    Mat<D> compress = 0.35 * Mat<D>::Identity();
    states.push_back(compress);
    for (const auto& F : states)
      check_derivatives_at<D>(law.material, F, 1e-6, 1e-7, law.name + " large stretch, D=" + std::to_string(D));
  }
}

template <int D>
void identity_is_stress_free() {
  for (const Law& law : laws()) {
    EXPECT_EQ(law.material.energy<D>(Mat<D>::Identity()), 0.0) << law.name;
    EXPECT_EQ(law.material.stress<D>(Mat<D>::Identity()).cwiseAbs().maxCoeff(), 0.0) << law.name;
  }
}

template <int D>
void frame_invariance() {
  std::mt19937 rng(3 + D);
  for (const Law& law : laws())
    for (int trial = 0; trial < 10; ++trial) {
      const Mat<D> F = random_F<D>(rng, 0.5), Q = rotation<D>(rng);
      const double psi = law.material.energy<D>(F);
      EXPECT_NEAR(law.material.energy<D>(Q * F), psi, 1e-12 * std::abs(psi)) << law.name;
      const Mat<D> P = law.material.stress<D>(F);
      EXPECT_LT((law.material.stress<D>(Q * F) - Q * P).cwiseAbs().maxCoeff(), 1e-12 * P.cwiseAbs().maxCoeff())
          << law.name;
    }
}

/// ∂P/∂F at F = I equals C_iJkL = λ δ_iJ δ_kL + μ (δ_ik δ_JL + δ_iL δ_Jk) (plane strain: its in-plane block).
template <int D>
void small_strain_limit() {
  const double E = 7.0;
  for (double nu : {-0.3, 0.0, 0.3, 0.49}) {
    const double mu = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    Tangent<D> C;
    for (int i = 0; i < D; ++i)
      for (int J = 0; J < D; ++J)
        for (int k = 0; k < D; ++k)
          for (int L = 0; L < D; ++L)
            C(D * i + J, D * k + L) = lambda * (i == J) * (k == L) + mu * ((i == k) * (J == L) + (i == L) * (J == k));
    for (HyperelasticLaw law : {HyperelasticLaw::kNeoHookean, HyperelasticLaw::kMooneyRivlin}) {
      const Hyperelastic m = Hyperelastic::from_young_poisson(law, E, nu);
      EXPECT_NEAR(m.shear_modulus(), mu, 1e-14 * mu);
      EXPECT_NEAR(m.lame_lambda(), lambda, 1e-13 * (mu + std::abs(lambda)));
      const Tangent<D> A = m.tangent<D>(Mat<D>::Identity());
      EXPECT_LT((A - C).cwiseAbs().maxCoeff(), 1e-13 * C.cwiseAbs().maxCoeff()) << "nu = " << nu;
      // And the linear stress for a small displacement gradient: P(I + εG) ≈ ε C:G to O(ε²).
      std::mt19937 rng(5);
      const Mat<D> G = random_matrix<D>(rng, 1.0);
      const double eps = 1e-7;
      const Mat<D> P = m.stress<D>(Mat<D>::Identity() + eps * G);
      const Mat<D> sym = 0.5 * (G + G.transpose());
      const Mat<D> sigma = lambda * sym.trace() * Mat<D>::Identity() + 2 * mu * sym;
      EXPECT_LT((P / eps - sigma).cwiseAbs().maxCoeff(), 1e-5 * sigma.cwiseAbs().maxCoeff()) << "nu = " << nu;
    }
  }
  // Own constants: Mooney–Rivlin μ = 2(C₁ + C₂), λ = κ − 2μ/3.
  const Hyperelastic mr = Hyperelastic::mooney_rivlin(0.7, 0.2, 5.0);
  EXPECT_DOUBLE_EQ(mr.shear_modulus(), 1.8);
  EXPECT_DOUBLE_EQ(mr.lame_lambda(), 5.0 - 1.2);
}

template <int D>
void inversion_throws() {
  for (const Law& law : laws()) {
    Mat<D> F = Mat<D>::Identity();
    F(0, 0) = -1.0;
    EXPECT_THROW(law.material.energy<D>(F), EvaluationError) << law.name;
    EXPECT_THROW(law.material.stress<D>(F), EvaluationError) << law.name;
    EXPECT_THROW(law.material.tangent<D>(F), EvaluationError) << law.name;
    F(0, 0) = 0.0;  // J = 0
    EXPECT_THROW(law.material.energy<D>(F), EvaluationError) << law.name;
    F(0, 0) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(law.material.energy<D>(F), EvaluationError) << law.name;
    // Just inside: finite values.
    F(0, 0) = 1e-8;
    EXPECT_TRUE(std::isfinite(law.material.energy<D>(F))) << law.name;
  }
}

}  // namespace

TEST(Hyperelastic, StressAndTangentMatchFiniteDifferencesAtRandomStates2D) { random_states<2>(); }
TEST(Hyperelastic, StressAndTangentMatchFiniteDifferencesAtRandomStates3D) { random_states<3>(); }
TEST(Hyperelastic, StressAndTangentMatchFiniteDifferencesNearIdentity2D) { near_identity<2>(); }
TEST(Hyperelastic, StressAndTangentMatchFiniteDifferencesNearIdentity3D) { near_identity<3>(); }
TEST(Hyperelastic, StressAndTangentMatchFiniteDifferencesAtLargeStretch2D) { large_stretch<2>(); }
TEST(Hyperelastic, StressAndTangentMatchFiniteDifferencesAtLargeStretch3D) { large_stretch<3>(); }
TEST(Hyperelastic, IdentityIsStressFree2D) { identity_is_stress_free<2>(); }
TEST(Hyperelastic, IdentityIsStressFree3D) { identity_is_stress_free<3>(); }
TEST(Hyperelastic, FrameInvariance2D) { frame_invariance<2>(); }
TEST(Hyperelastic, FrameInvariance3D) { frame_invariance<3>(); }
TEST(Hyperelastic, SmallStrainLimitIsLinearElasticity2D) { small_strain_limit<2>(); }
TEST(Hyperelastic, SmallStrainLimitIsLinearElasticity3D) { small_strain_limit<3>(); }
TEST(Hyperelastic, NonPositiveJacobianThrows2D) { inversion_throws<2>(); }
TEST(Hyperelastic, NonPositiveJacobianThrows3D) { inversion_throws<3>(); }

TEST(Hyperelastic, EnergyNearIdentityKeepsRelativeAccuracy) {
  // Pure shear-free dilation F = (1 + ε) I, 3D: ψ_NH = 3μ/2 ((1+ε)² − 1) − 3μ ln(1+ε) + 9λ/2 ln²(1+ε)
  // = (3μ + 9λ/2) ε² + O(ε³); the careful forms give it to ~1e-15 relative even at ε = 1e-9.
  const Hyperelastic nh = Hyperelastic::neo_hookean(1.0, 2.0);
  const Hyperelastic mr = Hyperelastic::mooney_rivlin(0.3, 0.2, 4.0);
  for (double eps_wanted : {1e-9, 1e-7, 1e-5}) {
    const Mat<3> F = (1 + eps_wanted) * Mat<3>::Identity();
    const double eps = F(0, 0) - 1.0;  // the ε actually stored (exact difference)
    const double l = std::log1p(eps);
    // μ = 1, λ = 2: ψ = 3ε + 1.5ε² − 3 ln(1+ε) + 9 ln²(1+ε), with ε − ln(1+ε) by its series.
    const double e2 = eps * eps;
    const double eps_minus_l = e2 / 2 - e2 * eps / 3 + e2 * e2 / 4 - e2 * e2 * eps / 5;
    const double psi_nh = 1.5 * e2 + 3.0 * eps_minus_l + 9.0 * l * l;
    EXPECT_NEAR(nh.energy<3>(F), psi_nh, 1e-13 * psi_nh) << eps;
    // Mooney–Rivlin: a dilation has Ī₁ = Ī₂ = 3, so ψ = κ/2 (J − 1)², J − 1 = 3ε + 3ε² + ε³.
    const double j = 3 * eps + 3 * eps * eps + eps * eps * eps;
    EXPECT_NEAR(mr.energy<3>(F), 2.0 * j * j, 1e-13 * 2.0 * j * j) << eps;
  }
}
