#pragma once
/// \file obstacle.hpp
/// Analytic rigid obstacles (Signorini's one-sided problem): a plane, or a circle (2D) / sphere (3D)
/// with the body outside it or inside it. project() gives the closest point x̄ on the obstacle and the
/// unit normal n̄ pointing to the admissible side, so that the gap is θ = (x − x̄)·n̄ ≥ 0.

#include <Eigen/Core>
#include <string>

namespace symcontact {

struct Obstacle {
  enum class Kind { kPlane, kSphere };
  std::string name;
  Kind kind = Kind::kPlane;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   ///< a point of the plane, or the centre
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();  ///< plane: unit normal towards the body
  double radius = 0.0;                                ///< sphere / circle
  bool inside = false;                                ///< sphere: the body is inside (a rigid hole)

  /// x has 3 components (z = 0 in 2D).
  void project(const Eigen::Vector3d& x, Eigen::Vector3d& xbar, Eigen::Vector3d& n) const;
};

}  // namespace symcontact
