#pragma once
/// \file linear_elastic.hpp
/// Isotropic linear elasticity, pointwise: σ = λ tr(ε) I + 2μ ε.
/// λ = Eν/((1+ν)(1−2ν)), μ = E/(2(1+ν)). Plane stress uses λ* = 2λμ/(λ+2μ) = Eν/(1−ν²) in the in-plane
/// law and σ_zz = 0; plane strain keeps λ and has σ_zz = λ (ε_xx + ε_yy).

#include <Eigen/Core>

#include "symcontact/fem/analysis_model.hpp"

namespace symcontact {

struct LinearElastic {
  double lambda = 0.0;  ///< in-plane Lamé λ (λ* under plane stress)
  double mu = 0.0;
  double lambda_3d = 0.0;  ///< the true 3D λ (for σ_zz in plane strain)
  AnalysisModel model = AnalysisModel::kPlaneStrain;

  /// Requires E > 0 and −1 < ν < 0.5 (checked by the problem reader; asserted here).
  static LinearElastic from_young_poisson(double young, double poisson, AnalysisModel model);

  /// Full 3 × 3 stress from the in-plane (2D) or full (3D) small strain, including σ_zz in 2D. Axisymmetric:
  /// the strain holds ε_θθ at (2, 2), and the stress σ_θθ there.
  Eigen::Matrix3d stress(const Eigen::Matrix3d& strain) const;
};

/// Von Mises equivalent stress sqrt(3/2 s:s), s the deviator of σ.
double von_mises(const Eigen::Matrix3d& sigma);

}  // namespace symcontact
