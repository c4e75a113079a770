#pragma once
/// \file closest_point.hpp
/// Closest-point projection of a point onto one contact facet (Line2 or Line3 in 2D).
/// The facet is x(η) = Σ_a N_a(η) x_a, η ∈ [0, 1]. The minimiser of |x(η) − p|² is found in closed form
/// for Line2 and by a safeguarded Newton iteration for Line3 (the stationarity condition
/// (x(η) − p)·x'(η) = 0, Wriggers, Computational Contact Mechanics, 2006, §4.1), and compared with the
/// ends. `unclamped` tells whether the stationary point lies inside the facet or past one of its ends.

#include <Eigen/Core>

#include "symcontact/mesh/cell_type.hpp"

namespace symcontact {

struct FacetProjection {
  double eta[2] = {0.0, 0.0};  ///< reference coordinates of the closest point (η, or (η1, η2) in 3D)
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  double distance2 = 0.0;
  /// −1 if the closest point is inside the facet (a true normal projection); otherwise the local
  /// index of the facet vertex it was clamped to.
  int clamped_vertex = -1;
};

/// `xf` is dim × npf (facet node positions), p has dim entries.
FacetProjection project_on_facet(CellType type, const Eigen::MatrixXd& xf, const Eigen::VectorXd& p);

}  // namespace symcontact
