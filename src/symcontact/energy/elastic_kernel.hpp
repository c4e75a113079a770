#pragma once
/// \file elastic_kernel.hpp
/// Element stiffness of isotropic linear elasticity (no assembly here; STYLE.md §3).
///
/// K_(a,i),(b,j) = Σ_q w_q det J_q [ λ G_ai G_bj + μ (δ_ij G_a·G_b + G_aj G_bi) ],
/// G_a = ∇_x N_a at quadrature point q; local DOF (a, i) sits at row D·a + i (node-major, as DofMap).

#include <Eigen/Dense>

#include "symcontact/fem/element_geometry.hpp"
#include "symcontact/fem/shape_functions.hpp"

namespace symcontact {

/// Fills K (D·NN square). Returns the index of the first quadrature point with det J ≤ 0, or −1.
template <int D, int NN>
int linear_elastic_stiffness(const Eigen::Matrix<double, D, NN>& X, const Tabulation& tab, double lambda,
                             double mu, Eigen::Matrix<double, D * NN, D * NN>& K) {
  K.setZero();
  Eigen::Matrix<double, NN, D> G;
  for (int q = 0; q < tab.rule.size(); ++q) {
    const double det = physical_gradients<D, NN>(X, tab.dN_at(q), G);
    if (!(det > 0)) return q;
    const double w = tab.rule.weights[q] * det;
    const Eigen::Matrix<double, NN, NN> GG = G * G.transpose();
    for (int b = 0; b < NN; ++b)
      for (int a = 0; a < NN; ++a)
        for (int j = 0; j < D; ++j)
          for (int i = 0; i < D; ++i) {
            double v = lambda * G(a, i) * G(b, j) + mu * G(a, j) * G(b, i);
            if (i == j) v += mu * GG(a, b);
            K(D * a + i, D * b + j) += w * v;
          }
  }
  return -1;
}

}  // namespace symcontact
