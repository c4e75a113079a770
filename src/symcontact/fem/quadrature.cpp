#include "symcontact/fem/quadrature.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace symcontact {

void gauss_legendre_01(int n, std::vector<double>& x, std::vector<double>& w) {
  // Newton iteration on P_n from the Chebyshev-like initial guesses; nodes mapped from [-1, 1].
  x.assign(n, 0.0);
  w.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    double t = std::cos(M_PI * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = t;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * t * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (t * p1 - p0) / (t * t - 1.0);
      const double dt = p1 / dp;
      t -= dt;
      if (std::abs(dt) < 1e-16) break;
    }
    x[i] = 0.5 * (1.0 - t);
    w[i] = 1.0 / ((1.0 - t * t) * dp * dp);  // (2/((1-t²)P'²)) × ½ for the map to [0,1]
  }
}

namespace {

// Collapsed product: ξ = s, η = t (1 − s) on the triangle; Jacobian (1 − s).
QuadratureRule duffy_triangle(int n) {
  std::vector<double> x, w;
  gauss_legendre_01(n + 1, x, w);  // one extra point for the (1 − s) Jacobian
  QuadratureRule r;
  r.dim = 2;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = 0; j < x.size(); ++j) {
      const double s = x[i], t = x[j];
      r.points.push_back(s);
      r.points.push_back(t * (1.0 - s));
      r.weights.push_back(w[i] * w[j] * (1.0 - s));
    }
  return r;
}

QuadratureRule duffy_tet(int n) {
  std::vector<double> x, w;
  gauss_legendre_01(n + 1, x, w);
  QuadratureRule r;
  r.dim = 3;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = 0; j < x.size(); ++j)
      for (std::size_t k = 0; k < x.size(); ++k) {
        const double s = x[i], t = x[j], v = x[k];
        r.points.push_back(s);
        r.points.push_back(t * (1.0 - s));
        r.points.push_back(v * (1.0 - s) * (1.0 - t));
        r.weights.push_back(w[i] * w[j] * w[k] * (1.0 - s) * (1.0 - s) * (1.0 - t));
      }
  return r;
}

}  // namespace

QuadratureRule simplex_quadrature(int dim, int degree) {
  if (degree < 0) degree = 0;
  QuadratureRule r;
  r.dim = dim;
  switch (dim) {
    case 0:
      r.weights = {1.0};
      return r;
    case 1: {
      std::vector<double> x, w;
      gauss_legendre_01(degree / 2 + 1, x, w);
      r.points = x;
      r.weights = w;
      return r;
    }
    case 2:
      if (degree <= 1) {
        r.points = {1.0 / 3.0, 1.0 / 3.0};
        r.weights = {0.5};
        return r;
      }
      if (degree == 2) {
        r.points = {1.0 / 6.0, 1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0, 1.0 / 6.0, 2.0 / 3.0};
        r.weights = {1.0 / 6.0, 1.0 / 6.0, 1.0 / 6.0};
        return r;
      }
      return duffy_triangle(degree / 2 + 1);
    case 3:
      if (degree <= 1) {
        r.points = {0.25, 0.25, 0.25};
        r.weights = {1.0 / 6.0};
        return r;
      }
      if (degree == 2) {
        const double a = 0.5854101966249685, b = 0.1381966011250105;  // (5 ± 3√5)/20
        r.points = {b, b, b, a, b, b, b, a, b, b, b, a};
        r.weights.assign(4, 1.0 / 24.0);
        return r;
      }
      return duffy_tet(degree / 2 + 1);
    default:
      throw std::invalid_argument("simplex_quadrature: dimension must be 0..3");
  }
}

QuadratureRule tensor_quadrature(int dim, int degree) {
  std::vector<double> x, w;
  gauss_legendre_01(std::max(degree, 0) / 2 + 1, x, w);
  const int n = static_cast<int>(x.size());
  int total = 1;
  for (int i = 0; i < dim; ++i) total *= n;
  QuadratureRule r;
  r.dim = dim;
  for (int q = 0; q < total; ++q) {
    double weight = 1.0;
    for (int i = 0, rest = q; i < dim; ++i, rest /= n) {  // ξ_0 fastest
      r.points.push_back(x[rest % n]);
      weight *= w[rest % n];
    }
    r.weights.push_back(weight);
  }
  return r;
}

QuadratureRule prism_quadrature(int degree) {
  const QuadratureRule tri = simplex_quadrature(2, degree);
  std::vector<double> z, wz;
  gauss_legendre_01(std::max(degree, 0) / 2 + 1, z, wz);
  QuadratureRule r;
  r.dim = 3;
  for (std::size_t k = 0; k < z.size(); ++k)
    for (int q = 0; q < tri.size(); ++q) {
      r.points.insert(r.points.end(), {tri.point(q)[0], tri.point(q)[1], z[k]});
      r.weights.push_back(tri.weights[q] * wz[k]);
    }
  return r;
}

QuadratureRule pyramid_quadrature(int degree) {
  std::vector<double> x, w, z, wz;
  gauss_legendre_01(std::max(degree, 0) / 2 + 1, x, w);
  gauss_legendre_01(std::max(degree, 0) / 2 + 2, z, wz);  // the Jacobian (1 − ζ)² adds 2 to the degree in ζ
  QuadratureRule r;
  r.dim = 3;
  for (std::size_t k = 0; k < z.size(); ++k)
    for (std::size_t j = 0; j < x.size(); ++j)
      for (std::size_t i = 0; i < x.size(); ++i) {
        const double s = 1.0 - z[k];
        r.points.insert(r.points.end(), {x[i] * s, x[j] * s, z[k]});
        r.weights.push_back(w[i] * w[j] * wz[k] * s * s);
      }
  return r;
}

QuadratureRule cell_quadrature(CellType t, int degree) {
  switch (cell_shape(t)) {
    case CellShape::kTensor: return tensor_quadrature(cell_dim(t), degree);
    case CellShape::kPrism: return prism_quadrature(degree);
    case CellShape::kPyramid: return pyramid_quadrature(degree);
    default: return simplex_quadrature(cell_dim(t), degree);
  }
}

int stiffness_quadrature_degree(CellType t, AnalysisModel model) {
  const int extra = model == AnalysisModel::kAxisymmetric ? 2 : 0;
  if (cell_shape(t) != CellShape::kSimplex) return 2 * cell_order(t) + extra;
  return (cell_order(t) == 1 ? 0 : 3) + extra;
}

}  // namespace symcontact
