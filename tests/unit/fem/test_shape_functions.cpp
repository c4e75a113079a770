#include "symcontact/fem/shape_functions.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace symcontact;

namespace {
const CellType kAll[] = {CellType::kLine2, CellType::kLine3, CellType::kTri3,
                         CellType::kTri6,  CellType::kTet4,  CellType::kTet10};

std::vector<double> random_point(int d, std::mt19937& rng) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> x(d);
  double s;
  do {
    s = 0;
    for (auto& v : x) s += (v = U(rng));
  } while (s > 1.0);
  return x;
}
}  // namespace

TEST(ShapeFunctions, KroneckerAtNodes) {
  for (CellType t : kAll) {
    const int n = cell_num_nodes(t), d = cell_dim(t);
    const auto nodes = reference_nodes(t);
    std::vector<double> N(n);
    for (int a = 0; a < n; ++a) {
      shape_functions(t, nodes.data() + a * d, N.data(), nullptr);
      for (int b = 0; b < n; ++b) EXPECT_NEAR(N[b], a == b ? 1.0 : 0.0, 1e-14) << cell_name(t);
    }
  }
}

TEST(ShapeFunctions, ReproduceLinearFieldsAndGradientsMatchFiniteDifferences) {
  std::mt19937 rng(3);
  for (CellType t : kAll) {
    const int n = cell_num_nodes(t), d = cell_dim(t);
    const auto nodes = reference_nodes(t);
    std::vector<double> N(n), dN(n * d), Np(n), Nm(n);
    for (int trial = 0; trial < 10; ++trial) {
      auto x = random_point(d, rng);
      shape_functions(t, x.data(), N.data(), dN.data());
      // Partition of unity and linear completeness: Σ N_a = 1, Σ N_a ξ_a = ξ.
      double s = 0;
      for (int a = 0; a < n; ++a) s += N[a];
      EXPECT_NEAR(s, 1.0, 1e-14);
      for (int i = 0; i < d; ++i) {
        double xi = 0;
        for (int a = 0; a < n; ++a) xi += N[a] * nodes[a * d + i];
        EXPECT_NEAR(xi, x[i], 1e-14);
      }
      const double h = 1e-6;
      for (int i = 0; i < d; ++i) {
        auto xp = x, xm = x;
        xp[i] += h;
        xm[i] -= h;
        shape_functions(t, xp.data(), Np.data(), nullptr);
        shape_functions(t, xm.data(), Nm.data(), nullptr);
        for (int a = 0; a < n; ++a) EXPECT_NEAR(dN[a * d + i], (Np[a] - Nm[a]) / (2 * h), 1e-8) << cell_name(t);
      }
    }
  }
}
