#pragma once
/// \file error_norms.hpp
/// Errors of a discrete displacement against an exact field, for convergence studies:
///   L2 error  ‖u_h − u‖ = (∫_Ω |u_h − u|²)^½,   H1 seminorm error |u_h − u|₁ = (∫_Ω |∇u_h − ∇u|²)^½,
/// integrated cell by cell with a quadrature of degree 2·order + 4 (the exact field is smooth).

#include <functional>

#include "symcontact/fem/dof_map.hpp"
#include "symcontact/mesh/mesh.hpp"

namespace symcontact {

/// u(x): writes dim components at x.
using VectorField = std::function<void(const double* x, double* u)>;
/// ∇u(x): writes dim × dim entries, grad[i * dim + j] = ∂u_i/∂x_j.
using GradientField = std::function<void(const double* x, double* grad)>;

struct ErrorNorms {
  double l2 = 0.0;
  double h1_semi = 0.0;
  double l2_exact = 0.0;  ///< ‖u‖ (for relative errors)
};

ErrorNorms compute_errors(const Mesh& mesh, const DofMap& dofs, int body, const VectorXd& u,
                          const VectorField& exact, const GradientField& exact_gradient);

}  // namespace symcontact
