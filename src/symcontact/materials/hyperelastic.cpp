#include "symcontact/materials/hyperelastic.hpp"

#include <cmath>
#include <sstream>

#include <Eigen/Dense>

#include "symcontact/core/error.hpp"

namespace symcontact {

namespace {

using M3 = Eigen::Matrix3d;
using T3 = Eigen::Matrix<double, 9, 9>;

/// x − log1p(x) (≥ 0, O(x²)), without the cancellation of the two O(x) terms for small |x|.
double x_minus_log1p(double x) {
  if (std::abs(x) < 1e-2) {
    // Σ_{n≥2} (−1)ⁿ xⁿ / n; 12 terms reach |x|¹³/13 < 1e-26 relative to x²/2.
    double s = 0.0, p = x * x;
    for (int n = 2; n <= 13; ++n) {
      s += ((n % 2 == 0) ? p : -p) / n;
      p *= x;
    }
    return s;
  }
  return x - std::log1p(x);
}

/// eˣ − 1 − x (O(x²)), accurate for small |x|.
double expm1_minus_x(double x) {
  if (std::abs(x) < 1e-2) {
    double s = 0.0, p = x * x, f = 2.0;
    for (int n = 2; n <= 10; ++n) {
      s += p / f;
      p *= x;
      f *= n + 1;
    }
    return s;
  }
  return std::expm1(x) - x;
}

/// Levi-Civita symbol ε_ijk.
double levi_civita(int i, int j, int k) { return 0.5 * (i - j) * (j - k) * (k - i); }

/// Kinematic quantities of F = I + H, formed so that the O(|H|) and O(|H|²) ones keep relative accuracy.
struct Kinematics {
  M3 F, H, Finv_T;
  double J = 1.0;        ///< det F
  double j = 0.0;        ///< J − 1 = tr H + i₂(H) + det H
  double ell = 0.0;      ///< ln J = log1p(j)
  double trH = 0.0;
  double HH = 0.0;       ///< H:H
  double trH_minus_ell = 0.0;  ///< tr H − ln J = −i₂(H) − det H + (j − log1p j), O(|H|²)
  int dim = 3;  ///< the dimension of the problem: plane strain (2) needs the tangent's in-plane block only
};

/// From the displacement gradient H (F = I + H is formed here, for the O(1) quantities only).
Kinematics kinematics(const M3& H) {
  Kinematics k;
  k.H = H;
  k.F = M3::Identity() + H;
  const M3& F = k.F;
  if (!H.allFinite()) throw EvaluationError("hyperelastic material: non-finite deformation gradient");
  k.trH = k.H.trace();
  k.HH = k.H.squaredNorm();
  const double i2 = 0.5 * (k.trH * k.trH - (k.H * k.H).trace());
  const double i3 = k.H.determinant();
  k.j = k.trH + i2 + i3;
  k.J = 1.0 + k.j;
  if (!(k.j > -1.0)) {
    std::ostringstream s;
    s << "hyperelastic material: det F = " << F.determinant() << " <= 0 (inverted material)";
    throw EvaluationError(s.str());
  }
  k.ell = std::log1p(k.j);
  k.trH_minus_ell = -i2 - i3 + x_minus_log1p(k.j);
  k.Finv_T = F.inverse().transpose();
  return k;
}

/// Second derivatives of ψ(I₁, I₂, J) and first derivatives, for the tangent.
struct InvariantDerivatives {
  double W1 = 0, W2 = 0, WJ = 0;
  double W11 = 0, W12 = 0, W22 = 0, W1J = 0, W2J = 0, WJJ = 0;
};

/// A_iJkL = Σ_a W_a ∂²I_a/∂F_iJ∂F_kL + Σ_ab W_ab (∂I_a/∂F_iJ)(∂I_b/∂F_kL), I_a ∈ {I₁, I₂, J}, with
///   ∂I₁/∂F = 2F,  ∂I₂/∂F = 2(I₁F − FC),  ∂J/∂F = cof F,
///   ∂²I₁ = 2 δ_ik δ_JL,
///   ∂²I₂ = 2 [2 F_iJ F_kL + I₁ δ_ik δ_JL − δ_ik C_LJ − F_iL F_kJ − b_ik δ_JL]  (b = FFᵀ),
///   ∂²J  = ε_ikm ε_JLN F_mN  (no inverse needed): zero unless i ≠ k and J ≠ L, and then the one term with
///          m = 3 − i − k, N = 3 − J − L.
/// Only the entries with i, J, k, L < `dim` are formed (plane strain reads the in-plane block, dim = 2); the
/// others are zero.
T3 invariant_tangent(const M3& F, const InvariantDerivatives& d, int dim) {
  const M3 C = F.transpose() * F, b = F * F.transpose();
  const double I1 = C.trace();
  const M3 g1 = 2.0 * F;
  const M3 g2 = 2.0 * (I1 * F - F * C);
  M3 gJ;  // cofactor
  gJ.col(0) = F.col(1).cross(F.col(2));
  gJ.col(1) = F.col(2).cross(F.col(0));
  gJ.col(2) = F.col(0).cross(F.col(1));
  T3 A = T3::Zero();
  for (int i = 0; i < dim; ++i)
    for (int J = 0; J < dim; ++J)
      for (int k = 0; k < dim; ++k)
        for (int L = 0; L < dim; ++L) {
          const double dik = i == k ? 1.0 : 0.0, dJL = J == L ? 1.0 : 0.0;
          double d2J = 0.0;
          if (i != k && J != L) {
            const int m = 3 - i - k, N = 3 - J - L;
            d2J += levi_civita(i, k, m) * levi_civita(J, L, N) * F(m, N);
          }
          const double d2I2 =
              2.0 * (2.0 * F(i, J) * F(k, L) + I1 * dik * dJL - dik * C(L, J) - F(i, L) * F(k, J) - b(i, k) * dJL);
          const double a1 = g1(i, J), a2 = g2(i, J), aJ = gJ(i, J);
          const double c1 = g1(k, L), c2 = g2(k, L), cJ = gJ(k, L);
          A(3 * i + J, 3 * k + L) = 2.0 * d.W1 * dik * dJL + d.W2 * d2I2 + d.WJ * d2J +  //
                                    d.W11 * a1 * c1 + d.W22 * a2 * c2 + d.WJJ * aJ * cJ +
                                    d.W12 * (a1 * c2 + a2 * c1) + d.W1J * (a1 * cJ + aJ * c1) +
                                    d.W2J * (a2 * cJ + aJ * c2);
        }
  return A;
}

/// Neo-Hookean: ψ = μ/2 H:H + μ (tr H − ln J) + λ/2 (ln J)²  (= μ/2 (I₁ − 3) − μ ln J + λ/2 (ln J)²,
/// since I₁ − 3 = 2 tr H + H:H);  P = μ (H + Hᵀ F^{-T}) + λ ln J F^{-T}  (F − F^{-T} = H + Hᵀ F^{-T}).
double neo_hookean_law(const Hyperelastic& m, const Kinematics& k, M3* P, T3* A) {
  const double mu = m.mu, lambda = m.lambda;
  if (P) *P = mu * (k.H + k.H.transpose() * k.Finv_T) + lambda * k.ell * k.Finv_T;
  if (A) {
    InvariantDerivatives d;
    d.W1 = 0.5 * mu;
    d.WJ = (lambda * k.ell - mu) / k.J;
    d.WJJ = (mu + lambda - lambda * k.ell) / (k.J * k.J);
    *A = invariant_tangent(k.F, d, k.dim);
  }
  return 0.5 * mu * k.HH + mu * k.trH_minus_ell + 0.5 * lambda * k.ell * k.ell;
}

/// Mooney–Rivlin: ψ = C₁ (Ī₁ − 3) + C₂ (Ī₂ − 3) + κ/2 (J − 1)². With E = ½(C − I) = ½(H + Hᵀ + HᵀH),
/// I₁ = 3 + a, a = 2 tr E; I₂ = 3 + b, b = 4 tr E + 2 (tr E)² − 2 E:E; J^{-2/3} = 1 + m, J^{-4/3} = 1 + n:
///   Ī₁ − 3 = 3φ(x) + 2(tr H − ln J) + H:H + m a,                       x = −⅔ ln J, φ(x) = eˣ − 1 − x,
///   Ī₂ − 3 = 3φ(y) + 4(tr H − ln J) + 2 H:H + 2 (tr E)² − 2 E:E + n b,  y = −⁴⁄₃ ln J,
/// every term O(|H|²). Stress P = F S, S = 2 ∂ψ/∂C, written with F C^{-1} = F^{-T}:
///   P = F^{-T} [4C₁ J^{-2/3} dev E + 2C₂ J^{-4/3} ((2 tr E − ⅔ b) I + 2E + 4 tr E E − 4E²) + κ (J − 1) J I],
/// from ∂Ī₁/∂C = J^{-2/3}(I − I₁/3 C^{-1}) = 2 J^{-2/3} C^{-1} dev E and
/// ∂Ī₂/∂C = J^{-4/3}(I₁ I − C − ⅔ I₂ C^{-1}) = J^{-4/3} C^{-1}(I₁ C − C² − ⅔ I₂ I) (Holzapfel §6.5).
double mooney_rivlin_law(const Hyperelastic& m, const Kinematics& k, M3* P, T3* A) {
  const double c1 = m.c1, c2 = m.c2, kappa = m.kappa;
  const M3 E = 0.5 * (k.H + k.H.transpose() + k.H.transpose() * k.H);
  const double trE = E.trace(), EE = E.squaredNorm();
  const double a = 2.0 * trE;
  const double b = 4.0 * trE + 2.0 * trE * trE - 2.0 * EE;
  const double x = -2.0 / 3.0 * k.ell, y = -4.0 / 3.0 * k.ell;
  const double mm = std::expm1(x), nn = std::expm1(y);
  const double I1bar_minus_3 = 3.0 * expm1_minus_x(x) + 2.0 * k.trH_minus_ell + k.HH + mm * a;
  const double I2bar_minus_3 =
      3.0 * expm1_minus_x(y) + 4.0 * k.trH_minus_ell + 2.0 * k.HH + 2.0 * trE * trE - 2.0 * EE + nn * b;
  const double Jm23 = 1.0 + mm, Jm43 = 1.0 + nn;
  if (P) {
    const M3 I = M3::Identity();
    const M3 devE = E - trE / 3.0 * I;
    const M3 S2 = (2.0 * trE - 2.0 / 3.0 * b) * I + 2.0 * E + 4.0 * trE * E - 4.0 * E * E;
    *P = k.Finv_T * (4.0 * c1 * Jm23 * devE + 2.0 * c2 * Jm43 * S2 + kappa * k.j * k.J * I);
  }
  if (A) {
    const double J = k.J, I1 = 3.0 + a, I2 = 3.0 + b;
    InvariantDerivatives d;
    d.W1 = c1 * Jm23;
    d.W2 = c2 * Jm43;
    d.WJ = -2.0 / 3.0 * c1 * Jm23 * I1 / J - 4.0 / 3.0 * c2 * Jm43 * I2 / J + kappa * k.j;
    d.W1J = -2.0 / 3.0 * c1 * Jm23 / J;
    d.W2J = -4.0 / 3.0 * c2 * Jm43 / J;
    d.WJJ = 10.0 / 9.0 * c1 * Jm23 * I1 / (J * J) + 28.0 / 9.0 * c2 * Jm43 * I2 / (J * J) + kappa;
    *A = invariant_tangent(k.F, d, k.dim);
  }
  return c1 * I1bar_minus_3 + c2 * I2bar_minus_3 + 0.5 * kappa * k.j * k.j;
}

}  // namespace

Hyperelastic Hyperelastic::neo_hookean(double mu, double lambda) {
  SYMCONTACT_ASSERT(mu > 0 && lambda + 2.0 * mu / 3.0 > 0);
  Hyperelastic m;
  m.law = HyperelasticLaw::kNeoHookean;
  m.mu = mu;
  m.lambda = lambda;
  return m;
}

Hyperelastic Hyperelastic::mooney_rivlin(double c1, double c2, double kappa) {
  SYMCONTACT_ASSERT(c1 >= 0 && c2 >= 0 && c1 + c2 > 0 && kappa > 0);
  Hyperelastic m;
  m.law = HyperelasticLaw::kMooneyRivlin;
  m.c1 = c1;
  m.c2 = c2;
  m.kappa = kappa;
  return m;
}

Hyperelastic Hyperelastic::from_young_poisson(HyperelasticLaw law, double E, double nu) {
  SYMCONTACT_ASSERT(E > 0 && nu > -1 && nu < 0.5);
  const double mu = E / (2.0 * (1.0 + nu));
  const double lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  if (law == HyperelasticLaw::kNeoHookean) return neo_hookean(mu, lambda);
  return mooney_rivlin(0.25 * mu, 0.25 * mu, E / (3.0 * (1.0 - 2.0 * nu)));
}

double Hyperelastic::shear_modulus() const { return law == HyperelasticLaw::kNeoHookean ? mu : 2.0 * (c1 + c2); }

double Hyperelastic::lame_lambda() const {
  return law == HyperelasticLaw::kNeoHookean ? lambda : kappa - 2.0 / 3.0 * shear_modulus();
}

template <int D>
double Hyperelastic::evaluate(const Eigen::Matrix<double, D, D>& F, Eigen::Matrix<double, D, D>* P,
                              Eigen::Matrix<double, D * D, D * D>* A) const {
  return evaluate_displacement_gradient<D>(F - Eigen::Matrix<double, D, D>::Identity(), P, A);
}

template <int D>
double Hyperelastic::evaluate_displacement_gradient(const Eigen::Matrix<double, D, D>& H,
                                                    Eigen::Matrix<double, D, D>* P,
                                                    Eigen::Matrix<double, D * D, D * D>* A) const {
  M3 H3 = M3::Zero();  // plane strain: H_{i3} = H_{3i} = 0, F₃₃ = 1
  H3.template topLeftCorner<D, D>() = H;
  Kinematics k = kinematics(H3);
  k.dim = D;
  M3 P3;
  T3 A3;
  const double psi = law == HyperelasticLaw::kNeoHookean ? neo_hookean_law(*this, k, P ? &P3 : nullptr, A ? &A3 : nullptr)
                                                         : mooney_rivlin_law(*this, k, P ? &P3 : nullptr, A ? &A3 : nullptr);
  if (P) *P = P3.template topLeftCorner<D, D>();
  if (A) {
    for (int i = 0; i < D; ++i)
      for (int J = 0; J < D; ++J)
        for (int kk = 0; kk < D; ++kk)
          for (int L = 0; L < D; ++L) (*A)(D * i + J, D * kk + L) = A3(3 * i + J, 3 * kk + L);
  }
  return psi;
}

template double Hyperelastic::evaluate_displacement_gradient<2>(const Eigen::Matrix<double, 2, 2>&,
                                                                Eigen::Matrix<double, 2, 2>*,
                                                                Eigen::Matrix<double, 4, 4>*) const;
template double Hyperelastic::evaluate_displacement_gradient<3>(const Eigen::Matrix<double, 3, 3>&,
                                                                Eigen::Matrix<double, 3, 3>*,
                                                                Eigen::Matrix<double, 9, 9>*) const;
template double Hyperelastic::evaluate<2>(const Eigen::Matrix<double, 2, 2>&, Eigen::Matrix<double, 2, 2>*,
                                          Eigen::Matrix<double, 4, 4>*) const;
template double Hyperelastic::evaluate<3>(const Eigen::Matrix<double, 3, 3>&, Eigen::Matrix<double, 3, 3>*,
                                          Eigen::Matrix<double, 9, 9>*) const;

}  // namespace symcontact
