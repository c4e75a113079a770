#pragma once
/// \file shape_functions.hpp
/// Shape functions on the reference cells (quadrature.hpp gives the domains), with nodes in Gmsh order
/// (cell_type.hpp).
///  - Simplices, P1 and P2, written through the barycentric coordinates L0 = 1 − Σξ_i, L_i = ξ_i:
///    vertices N_a = L_a (P1) or L_a (2 L_a − 1) (P2), edge (a, b) nodes 4 L_a L_b.
///  - Quad4, Quad9, Hex8, Hex27: tensor products N_a(ξ) = Π_i ℓ_{a_i}(ξ_i) of the 1D Lagrange
///    polynomials through the node's coordinates (0, 1, or 0 ½ 1).
///  - Quad8, Hex20 (serendipity), in s_i = 2ξ_i − 1 ∈ [−1, 1] and node coordinates c_i ∈ {−1, 0, 1}:
///    corners N = 2^{−d} Π(1 + s_i c_i) (Σ s_i c_i − d + 1), edge nodes (c_j = 0)
///    N = 2^{1−d} (1 − s_j²) Π_{i≠j}(1 + s_i c_i) (Zienkiewicz & Taylor, "The finite element method",
///    vol. 1, §8.7).
///  - Prisms: the triangle's functions times the 1D ones in ζ; Prism15 the serendipity wedge.
///  - Pyramids: the rational nodal bases of Bergot, Cohen & Duruflé (2010), which hold P_p and conform to
///    tetrahedra on their triangles and to hexahedra on their base (shape_functions.cpp).

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
