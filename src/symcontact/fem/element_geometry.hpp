#pragma once
/// \file element_geometry.hpp
/// Isoparametric map of one cell at one reference point: x(ξ) = Σ_a X_a N_a(ξ),
/// J = ∂x/∂ξ = Σ_a X_a ⊗ ∇_ξ N_a, and physical gradients ∇_x N_a = J^{-T} ∇_ξ N_a.

#include <Eigen/Dense>

namespace symcontact {

/// Gathers the coordinates of a cell's nodes into a D × NN matrix.
template <int D, int NN, class Nodes>
Eigen::Matrix<double, D, NN> gather_coordinates(const Eigen::MatrixXd& x, const Nodes* nodes) {
  Eigen::Matrix<double, D, NN> X;
  for (int a = 0; a < NN; ++a) X.col(a) = x.col(nodes[a]).template head<D>();
  return X;
}

/// Physical shape-function gradients G (NN × D, row a = ∇_x N_a) and det J at one point.
/// `dN` is the reference gradient table, NN × D row-major (Tabulation::dN_at()).
/// Returns det J; G is left unset when det J ≤ 0 (an inverted map — the caller reports it).
template <int D, int NN>
double physical_gradients(const Eigen::Matrix<double, D, NN>& X, const double* dN,
                          Eigen::Matrix<double, NN, D>& G) {
  const Eigen::Map<const Eigen::Matrix<double, NN, D, (D == 1 ? Eigen::ColMajor : Eigen::RowMajor)>> dNr(dN);
  const Eigen::Matrix<double, D, D> J = X * dNr;
  const double det = J.determinant();
  if (det > 0) G.noalias() = dNr * J.inverse();
  return det;
}

}  // namespace symcontact
