#pragma once
/// \file elastic_kernel.hpp
/// Element stiffness of isotropic linear elasticity (no assembly here; STYLE.md §3).
///
/// K_(a,i),(b,j) = Σ_q w_q det J_q [ λ G_ai G_bj + μ (δ_ij G_a·G_b + G_aj G_bi) ],
/// G_a = ∇_x N_a at quadrature point q; local DOF (a, i) sits at row D·a + i (node-major, as DofMap).
///
/// Axisymmetric (D = 2, x = r, analysis_model.hpp): the strain of N_a e_r has also ε_θθ = N_a / r =: H_a,
/// so with ε : ε and tr ε of the 3D strain (Zienkiewicz & Taylor vol. 1, §5.2, the B matrix with the
/// row N_a / r) the integrand gains
///   λ (δ_i0 H_a G_bj + δ_j0 G_ai H_b) + (λ + 2μ) δ_i0 δ_j0 H_a H_b,
/// and every weight is multiplied by 2π r_q. Quadrature points lie inside the cells, so r_q > 0 when the
/// section lies in r ≥ 0 (checked when the model is built): nodes on the axis need no special case.

#include <Eigen/Dense>

#include "symcontact/fem/element_geometry.hpp"
#include "symcontact/fem/shape_functions.hpp"
#include "symcontact/fem/analysis_model.hpp"

namespace symcontact {

/// Fills K (D·NN square). Returns the index of the first quadrature point with det J ≤ 0 (or, in an
/// axisymmetric model, r ≤ 0), or −1.
template <int D, int NN>
int linear_elastic_stiffness(const Eigen::Matrix<double, D, NN>& X, const Tabulation& tab, double lambda,
                             double mu, AnalysisModel model, Eigen::Matrix<double, D * NN, D * NN>& K) {
  K.setZero();
  Eigen::Matrix<double, NN, D> G;
  for (int q = 0; q < tab.rule.size(); ++q) {
    const double det = physical_gradients<D, NN>(X, tab.dN_at(q), G);
    if (!(det > 0)) return q;
    const Eigen::Map<const Eigen::Matrix<double, NN, 1>> N(tab.N_at(q));
    const double r = X.row(0).dot(N);
    if (model == AnalysisModel::kAxisymmetric && !(r > 0)) return q;
    const double w = tab.rule.weights[q] * det * section_measure(model, r);
    const Eigen::Matrix<double, NN, NN> GG = G * G.transpose();
    for (int b = 0; b < NN; ++b)
      for (int a = 0; a < NN; ++a)
        for (int j = 0; j < D; ++j)
          for (int i = 0; i < D; ++i) {
            double v = lambda * G(a, i) * G(b, j) + mu * G(a, j) * G(b, i);
            if (i == j) v += mu * GG(a, b);
            K(D * a + i, D * b + j) += w * v;
          }
    if (model == AnalysisModel::kAxisymmetric) {
      const Eigen::Matrix<double, NN, 1> H = N / r;
      for (int b = 0; b < NN; ++b)
        for (int a = 0; a < NN; ++a) {
          for (int j = 0; j < D; ++j) K(D * a, D * b + j) += w * lambda * H[a] * G(b, j);
          for (int i = 0; i < D; ++i) K(D * a + i, D * b) += w * lambda * G(a, i) * H[b];
          K(D * a, D * b) += w * (lambda + 2.0 * mu) * H[a] * H[b];
        }
    }
  }
  return -1;
}

}  // namespace symcontact
