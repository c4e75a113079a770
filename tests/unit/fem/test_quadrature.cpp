#include "symcontact/fem/quadrature.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace symcontact;

namespace {
double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

/// ∫ over the reference simplex of Π x_i^{a_i} = Π a_i! / (d + Σ a_i)!  (Dirichlet integral).
double exact_monomial(const std::vector<int>& a) {
  int s = 0;
  double num = 1.0;
  for (int ai : a) {
    s += ai;
    num *= factorial(ai);
  }
  return num / factorial(static_cast<int>(a.size()) + s);
}
}  // namespace

TEST(Quadrature, ExactForAllMonomialsUpToItsDegree) {
  for (int dim = 1; dim <= 3; ++dim)
    for (int degree = 0; degree <= 8; ++degree) {
      const QuadratureRule r = simplex_quadrature(dim, degree);
      std::vector<int> a(dim, 0);
      // Enumerate all exponent tuples with total degree <= `degree`.
      std::function<void(int, int)> rec = [&](int k, int left) {
        if (k == dim) {
          double q = 0.0;
          for (int p = 0; p < r.size(); ++p) {
            double v = r.weights[p];
            for (int i = 0; i < dim; ++i) v *= std::pow(r.point(p)[i], a[i]);
            q += v;
          }
          EXPECT_NEAR(q, exact_monomial(a), 1e-14) << "dim " << dim << " degree " << degree;
          return;
        }
        for (int e = 0; e <= left; ++e) {
          a[k] = e;
          rec(k + 1, left - e);
        }
        a[k] = 0;
      };
      rec(0, degree);
    }
}

TEST(Quadrature, PointsInsideAndWeightsPositive) {
  for (int dim = 1; dim <= 3; ++dim)
    for (int degree = 0; degree <= 8; ++degree) {
      const QuadratureRule r = simplex_quadrature(dim, degree);
      for (int p = 0; p < r.size(); ++p) {
        EXPECT_GT(r.weights[p], 0.0);
        double s = 0.0;
        for (int i = 0; i < dim; ++i) {
          EXPECT_GE(r.point(p)[i], 0.0);
          s += r.point(p)[i];
        }
        EXPECT_LE(s, 1.0 + 1e-15);
      }
    }
}

// Tensor rules on [0, 1]^dim: exact for Π x_i^{a_i} with every a_i ≤ degree, ∫ = Π 1 / (a_i + 1); the
// next degree in one variable is not integrated exactly (so the point count is the smallest).
TEST(Quadrature, TensorRulesExactPerVariable) {
  for (int dim = 2; dim <= 3; ++dim)
    for (int degree = 0; degree <= 6; ++degree) {
      const QuadratureRule r = tensor_quadrature(dim, degree);
      const auto integral = [&](const int* a) {
        double q = 0.0;
        for (int p = 0; p < r.size(); ++p) {
          double v = r.weights[p];
          for (int i = 0; i < dim; ++i) v *= std::pow(r.point(p)[i], a[i]);
          q += v;
        }
        return q;
      };
      const int top = degree | 1;  // an odd degree 2n − 1 is the rule's true exactness
      for (int e = 0; e < (dim == 3 ? (top + 1) * (top + 1) * (top + 1) : (top + 1) * (top + 1)); ++e) {
        const int a[3] = {e % (top + 1), (e / (top + 1)) % (top + 1), e / ((top + 1) * (top + 1))};
        double exact = 1.0;
        for (int i = 0; i < dim; ++i) exact /= a[i] + 1;
        EXPECT_NEAR(integral(a), exact, 1e-14) << dim << "D degree " << degree;
      }
      const int over[3] = {top + 1, 0, 0};
      EXPECT_GT(std::abs(integral(over) - 1.0 / (top + 2)), 1e-8) << dim << "D degree " << degree;
    }
  EXPECT_EQ(cell_quadrature(CellType::kQuad4, stiffness_quadrature_degree(CellType::kQuad4)).size(), 4);
  EXPECT_EQ(cell_quadrature(CellType::kHex27, stiffness_quadrature_degree(CellType::kHex27)).size(), 27);
  EXPECT_EQ(cell_quadrature(CellType::kTri6, 3).size(), simplex_quadrature(2, 3).size());
}
