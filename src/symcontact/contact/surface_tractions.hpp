#pragma once
/// \file surface_tractions.hpp
/// Nodal contact tractions of a surface from a nodal force vector F (force the other side exerts on
/// the body): with n_k the smoothed outward normal and A_k = ∫ N_k dS the lumped reference area,
///   pressure p_k = −F_k·n_k / A_k,   tangential traction t_k = (F_k − (F_k·n_k) n_k) / A_k.
/// On Tri6 surfaces F is first turned into the test basis (test_basis_forces(), contact_surface.hpp),
/// whose lumped areas are all positive (the vertex shape functions of a Tri6 integrate to zero); a
/// uniform traction is recovered exactly either way.

#include <vector>

#include "symcontact/contact/contact_points.hpp"
#include "symcontact/contact/contact_surface.hpp"

namespace symcontact {

struct SurfaceTractions {
  Eigen::MatrixXd x;           ///< dim × n current positions
  Eigen::MatrixXd normals;     ///< dim × n smoothed outward normals
  Eigen::MatrixXd force;       ///< dim × n
  Eigen::VectorXd pressure;    ///< n
  Eigen::MatrixXd tangential;  ///< dim × n
};

/// `normals` (dim × n), when given, replaces the surface's own smoothed normals for the decomposition
/// (the Coulomb threshold uses the opposite surface's normal at each node's projection, the normal of the
/// constraints and of the friction term).
SurfaceTractions surface_tractions(const ContactSurface& s, const DofMap& dofs, const VectorXd& u,
                                   const VectorXd& force, const Eigen::MatrixXd* normals = nullptr);

/// Interpolates nodal values of surface `s` to the slave points of a family on it.
std::vector<double> interpolate_at_points(const ContactSurface& s, const std::vector<ContactPoint>& points,
                                          const Eigen::VectorXd& nodal);

}  // namespace symcontact
