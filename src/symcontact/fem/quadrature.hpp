#pragma once
/// \file quadrature.hpp
/// Quadrature rules on the reference simplices and cubes:
///  - line  [0, 1],
///  - triangle {ξ, η ≥ 0, ξ + η ≤ 1} (area 1/2),
///  - tetrahedron {ξ, η, ζ ≥ 0, ξ + η + ζ ≤ 1} (volume 1/6),
///  - square [0, 1]² and cube [0, 1]³ (measure 1): Gauss–Legendre tensor products.
/// Weights sum to the reference measure. Low degrees use the classical symmetric rules (1-point,
/// 3-point edge-interior, 4-point Keast); higher degrees use collapsed (Duffy) Gauss–Legendre
/// products, which have positive weights and are exact for any requested total degree
/// (Stroud, "Approximate calculation of multiple integrals", 1971, §2.4).

#include <vector>

#include "symcontact/fem/analysis_model.hpp"
#include "symcontact/mesh/cell_type.hpp"

namespace symcontact {

struct QuadratureRule {
  int dim = 0;                 ///< reference dimension (0 point, 1 line, 2 triangle, 3 tetrahedron)
  std::vector<double> points;  ///< num_points × dim reference coordinates, point after point
  std::vector<double> weights;
  int size() const { return static_cast<int>(weights.size()); }
  const double* point(int q) const { return points.data() + q * dim; }
};

/// A rule on the reference simplex of dimension `dim` exact for polynomials of total degree ≤ `degree`.
QuadratureRule simplex_quadrature(int dim, int degree);

/// A Gauss–Legendre tensor-product rule on [0, 1]^dim exact for polynomials of degree ≤ `degree` in
/// each variable separately (degree / 2 + 1 points per direction).
QuadratureRule tensor_quadrature(int dim, int degree);

/// The rule on the unit triangle times [0, 1]: simplex_quadrature(2, degree) times degree / 2 + 1 Gauss
/// points in ζ (exact for degree ≤ `degree` in (ξ, η) and in ζ separately).
QuadratureRule prism_quadrature(int degree);

/// The collapsed rule on the pyramid {0 ≤ ζ ≤ 1, 0 ≤ ξ, η ≤ 1 − ζ} (volume 1/3): (ξ, η, ζ) =
/// (a (1 − c), b (1 − c), c) over the cube of (a, b, c), with degree / 2 + 1 Gauss points in a and b,
/// degree / 2 + 2 in c and the Jacobian (1 − c)² in the weights. Exact for polynomials of total degree
/// ≤ `degree`, and for the pyramids' rational functions of that degree in (a, b) and in c (Stroud, 1971,
/// §2.4; Bergot et al. 2010, §3).
QuadratureRule pyramid_quadrature(int degree);

/// The rule on the reference cell of `t`: simplex_quadrature() for a simplex, tensor_quadrature() for a
/// quadrilateral or hexahedron (whose Q_p shape functions have degree p in each variable),
/// prism_quadrature() for a prism, pyramid_quadrature() for a pyramid.
QuadratureRule cell_quadrature(CellType t, int degree);

/// The degree of the rule that integrates stiffness and elastic energy over a cell of type t: 2(p − 1) for
/// straight simplices, exact for their polynomial integrand; 3 for P2, whose cells may be curved; 2p per
/// variable for quadrilaterals, hexahedra, prisms and pyramids (p + 1 Gauss points per direction, full
/// integration, exact for parallelogram and parallelepiped cells and affine pyramids; Hughes, "The finite
/// element method", 2000, §3.8).
/// Axisymmetric models (analysis_model.hpp) use 2 more: the integrand gains the factor r and the hoop
/// terms N_a N_b / r, and a one-point rule on a linear triangle would leave a zero-energy rotation of each
/// cell (its hoop strain vanishing at the centroid only; Zienkiewicz & Taylor vol. 1, §5.3).
int stiffness_quadrature_degree(CellType t, AnalysisModel model = AnalysisModel::kPlaneStrain);

/// n-point Gauss–Legendre nodes and weights on [0, 1] (exact to degree 2n − 1).
void gauss_legendre_01(int n, std::vector<double>& x, std::vector<double>& w);

}  // namespace symcontact
