#pragma once
/// \file shape_functions.hpp
/// Lagrange shape functions on the reference simplices (quadrature.hpp gives the domains), P1 and P2,
/// with nodes in Gmsh order (cell_type.hpp). Written through the barycentric coordinates
/// L0 = 1 − Σξ_i, L_i = ξ_i: vertices N_a = L_a (P1) or L_a (2 L_a − 1) (P2), edge (a, b) nodes 4 L_a L_b.

#include <vector>

#include "symcontact/fem/quadrature.hpp"
#include "symcontact/mesh/cell_type.hpp"

namespace symcontact {

/// Values N[a] and reference gradients dN[a * d + i] = ∂N_a/∂ξ_i at the reference point xi
/// (d = cell_dim(t)). Either output may be null.
void shape_functions(CellType t, const double* xi, double* N, double* dN);

/// Reference coordinates of the nodes of a cell type (num_nodes × dim).
std::vector<double> reference_nodes(CellType t);

/// Shape functions tabulated at the points of a quadrature rule.
struct Tabulation {
  CellType type{};
  int num_nodes = 0;
  int dim = 0;
  QuadratureRule rule;
  std::vector<double> N;   ///< num_points × num_nodes
  std::vector<double> dN;  ///< num_points × num_nodes × dim
  const double* N_at(int q) const { return N.data() + q * num_nodes; }
  const double* dN_at(int q) const { return dN.data() + q * num_nodes * dim; }
};

Tabulation tabulate(CellType t, const QuadratureRule& rule);

}  // namespace symcontact
