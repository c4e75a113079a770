#include "symcontact/materials/linear_elastic.hpp"

#include "symcontact/core/error.hpp"

#include <cmath>

namespace symcontact {

LinearElastic LinearElastic::from_young_poisson(double E, double nu, AnalysisModel model) {
  SYMCONTACT_ASSERT(E > 0 && nu > -1 && nu < 0.5);
  LinearElastic m;
  m.model = model;
  m.mu = E / (2.0 * (1.0 + nu));
  m.lambda_3d = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  m.lambda = model == AnalysisModel::kPlaneStress ? 2.0 * m.lambda_3d * m.mu / (m.lambda_3d + 2.0 * m.mu)
                                                  : m.lambda_3d;
  return m;
}

Eigen::Matrix3d LinearElastic::stress(const Eigen::Matrix3d& eps) const {
  Eigen::Matrix3d s;
  switch (model) {
    case AnalysisModel::kThreeD:
    case AnalysisModel::kAxisymmetric:  // strain(2, 2) = ε_θθ; the (r, z) block and σ_θθ as in 3D
      s = lambda * eps.trace() * Eigen::Matrix3d::Identity() + 2.0 * mu * eps;
      break;
    case AnalysisModel::kPlaneStrain: {
      const double tr = eps(0, 0) + eps(1, 1);
      s.setZero();
      s.topLeftCorner<2, 2>() = lambda * tr * Eigen::Matrix2d::Identity() + 2.0 * mu * eps.topLeftCorner<2, 2>();
      s(2, 2) = lambda * tr;
      break;
    }
    case AnalysisModel::kPlaneStress: {
      const double tr = eps(0, 0) + eps(1, 1);
      s.setZero();
      s.topLeftCorner<2, 2>() = lambda * tr * Eigen::Matrix2d::Identity() + 2.0 * mu * eps.topLeftCorner<2, 2>();
      break;
    }
  }
  return s;
}

double von_mises(const Eigen::Matrix3d& s) {
  const Eigen::Matrix3d dev = s - s.trace() / 3.0 * Eigen::Matrix3d::Identity();
  return std::sqrt(1.5 * dev.cwiseProduct(dev).sum());
}

}  // namespace symcontact
