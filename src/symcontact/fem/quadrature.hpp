#pragma once
/// \file quadrature.hpp
/// Quadrature rules on the reference simplices:
///  - line  [0, 1],
///  - triangle {ξ, η ≥ 0, ξ + η ≤ 1} (area 1/2),
///  - tetrahedron {ξ, η, ζ ≥ 0, ξ + η + ζ ≤ 1} (volume 1/6).
/// Weights sum to the reference measure. Low degrees use the classical symmetric rules (1-point,
/// 3-point edge-interior, 4-point Keast); higher degrees use collapsed (Duffy) Gauss–Legendre
/// products, which have positive weights and are exact for any requested total degree
/// (Stroud, "Approximate calculation of multiple integrals", 1971, §2.4).

#include <vector>

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

/// n-point Gauss–Legendre nodes and weights on [0, 1] (exact to degree 2n − 1).
void gauss_legendre_01(int n, std::vector<double>& x, std::vector<double>& w);

}  // namespace symcontact
