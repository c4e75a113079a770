#pragma once
/// \file hyperelastic.hpp
/// Isotropic compressible hyperelastic laws, pointwise (STYLE.md §4): the strain-energy density ψ(F)
/// per unit reference volume, the first Piola–Kirchhoff stress P = ∂ψ/∂F and the tangent ∂P/∂F. Nothing
/// here knows about elements.
///
/// Laws (F the deformation gradient, J = det F, C = FᵀF, I₁ = tr C, I₂ = ½(I₁² − C:C),
/// Ī₁ = J^{-2/3} I₁, Ī₂ = J^{-4/3} I₂ the isochoric invariants):
///  - Neo-Hookean (Bonet & Wood, Nonlinear Continuum Mechanics for Finite Element Analysis, 2nd ed. 2008,
///    §6.4.3, eq. 6.28):  ψ = μ/2 (I₁ − 3) − μ ln J + λ/2 (ln J)².
///    P = μ (F − F^{-T}) + λ ln J F^{-T}.
///  - Mooney–Rivlin, decoupled compressible form (Holzapfel, Nonlinear Solid Mechanics, 2000, §6.5,
///    eq. 6.148 for the isochoric part, with the volumetric function U(J) = κ/2 (J − 1)²; Bonet & Wood
///    §6.5):  ψ = C₁ (Ī₁ − 3) + C₂ (Ī₂ − 3) + κ/2 (J − 1)².
/// Small-strain limit: both reduce to isotropic linear elasticity with shear modulus μ and Lamé λ —
/// Neo-Hookean directly; Mooney–Rivlin with μ = 2 (C₁ + C₂) and bulk modulus κ = λ + 2μ/3. Given
/// (E, ν), μ = E/(2(1+ν)), λ = Eν/((1+ν)(1−2ν)); for Mooney–Rivlin the shear modulus is split evenly,
/// C₁ = C₂ = μ/4 (give c1, c2 in the problem file for another split).
///
/// Plane strain (D = 2): F is the in-plane 2 × 2 block of a 3 × 3 gradient with F₃₃ = 1 (and F_{i3} =
/// F_{3i} = 0); ψ is the 3D density, P and ∂P/∂F are the in-plane blocks of the 3D ones. Plane stress is
/// not supported.
///
/// Tangent layout: A(D·i + J, D·k + L) = ∂P_iJ/∂F_kL (row-major flattening of each index pair), a
/// D² × D² matrix; it is symmetric (A = ∂²ψ/∂F∂F).
///
/// Numerics near J = 1 (F = I + H, |H| ≪ 1): ψ and P are formed from H, J − 1 = tr H + i₂(H) + det H,
/// ln J = log1p(J − 1), and the O(|H|²) combinations j − log1p(j), eˣ − 1 − x, so that they keep full
/// relative accuracy down to |H| ~ 1e-8 instead of cancelling O(1) terms (I₁ − 3, F − F^{-T}).
///
/// Errors: J ≤ 0 (or a non-finite F) throws EvaluationError — the state is outside the domain of ψ.

#include <Eigen/Core>

namespace symcontact {

enum class HyperelasticLaw { kNeoHookean, kMooneyRivlin };

struct Hyperelastic {
  HyperelasticLaw law = HyperelasticLaw::kNeoHookean;
  double mu = 0.0, lambda = 0.0;          ///< Neo-Hookean constants [stress]
  double c1 = 0.0, c2 = 0.0, kappa = 0.0; ///< Mooney–Rivlin constants [stress]

  /// Requires μ > 0 and λ + 2μ/3 > 0 (asserted; the problem reader checks user input).
  static Hyperelastic neo_hookean(double mu, double lambda);
  /// Requires C₁ ≥ 0, C₂ ≥ 0, C₁ + C₂ > 0 and κ > 0 (asserted).
  static Hyperelastic mooney_rivlin(double c1, double c2, double kappa);
  /// The law with the small-strain moduli of (E, ν): requires E > 0, −1 < ν < 0.5 (asserted).
  static Hyperelastic from_young_poisson(HyperelasticLaw law, double young, double poisson);

  /// Small-strain shear modulus μ and Lamé λ (3D) of the law.
  double shear_modulus() const;
  double lame_lambda() const;

  /// ψ(F); and, when the pointers are non-null, P(F) and A = ∂P/∂F (layout above). D = 2 (plane strain)
  /// or 3. Throws EvaluationError when det F ≤ 0 or F is not finite.
  template <int D>
  double evaluate(const Eigen::Matrix<double, D, D>& F, Eigen::Matrix<double, D, D>* P,
                  Eigen::Matrix<double, D * D, D * D>* A) const;

  /// The same from the displacement gradient H = ∇_X u = F − I, which keeps the full relative accuracy of
  /// small H (forming F = I + H first rounds H to absolute 1e-16); element kernels use this one.
  template <int D>
  double evaluate_displacement_gradient(const Eigen::Matrix<double, D, D>& H, Eigen::Matrix<double, D, D>* P,
                                        Eigen::Matrix<double, D * D, D * D>* A) const;

  template <int D>
  double energy(const Eigen::Matrix<double, D, D>& F) const {
    return evaluate<D>(F, nullptr, nullptr);
  }
  template <int D>
  Eigen::Matrix<double, D, D> stress(const Eigen::Matrix<double, D, D>& F) const {
    Eigen::Matrix<double, D, D> P;
    evaluate<D>(F, &P, nullptr);
    return P;
  }
  template <int D>
  Eigen::Matrix<double, D * D, D * D> tangent(const Eigen::Matrix<double, D, D>& F) const {
    Eigen::Matrix<double, D * D, D * D> A;
    evaluate<D>(F, nullptr, &A);
    return A;
  }
};

extern template double Hyperelastic::evaluate_displacement_gradient<2>(const Eigen::Matrix<double, 2, 2>&,
                                                                       Eigen::Matrix<double, 2, 2>*,
                                                                       Eigen::Matrix<double, 4, 4>*) const;
extern template double Hyperelastic::evaluate_displacement_gradient<3>(const Eigen::Matrix<double, 3, 3>&,
                                                                       Eigen::Matrix<double, 3, 3>*,
                                                                       Eigen::Matrix<double, 9, 9>*) const;
extern template double Hyperelastic::evaluate<2>(const Eigen::Matrix<double, 2, 2>&, Eigen::Matrix<double, 2, 2>*,
                                                 Eigen::Matrix<double, 4, 4>*) const;
extern template double Hyperelastic::evaluate<3>(const Eigen::Matrix<double, 3, 3>&, Eigen::Matrix<double, 3, 3>*,
                                                 Eigen::Matrix<double, 9, 9>*) const;

}  // namespace symcontact
