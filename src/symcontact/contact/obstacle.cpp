#include "symcontact/contact/obstacle.hpp"

namespace symcontact {

void Obstacle::project(const Eigen::Vector3d& x, Eigen::Vector3d& xbar, Eigen::Vector3d& n) const {
  if (kind == Kind::kPlane) {
    n = normal;
    xbar = x - (x - point).dot(n) * n;
    return;
  }
  Eigen::Vector3d e = x - point;
  const double r = e.norm();
  e = r > 0 ? Eigen::Vector3d(e / r) : Eigen::Vector3d::UnitY();  // the centre itself: any direction
  xbar = point + radius * e;
  n = inside ? Eigen::Vector3d(-e) : e;
}

}  // namespace symcontact
