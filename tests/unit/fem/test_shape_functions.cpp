#include "symcontact/fem/shape_functions.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace symcontact;

namespace {
const CellType kAll[] = {CellType::kLine2,    CellType::kLine3,     CellType::kTri3,     CellType::kTri6,
                         CellType::kTet4,     CellType::kTet10,     CellType::kQuad4,    CellType::kQuad8,
                         CellType::kQuad9,    CellType::kHex8,      CellType::kHex20,    CellType::kHex27,
                         CellType::kPrism6,   CellType::kPrism15,   CellType::kPrism18,  CellType::kPyramid5,
                         CellType::kPyramid13, CellType::kPyramid14};

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

// Order-2 cells reproduce every quadratic ξ_i ξ_j (complete P2: Σ_a N_a ξ_{a,i} ξ_{a,j} = ξ_i ξ_j); Quad9 and
// Hex27 also reproduce the full tensor product Π ξ_i², which Quad8 and Hex20 (serendipity) do not.
TEST(ShapeFunctions, QuadraticCompletenessAndTensorProducts) {
  std::mt19937 rng(5);
  const CellType order2[] = {CellType::kTri6,    CellType::kTet10,     CellType::kQuad8,    CellType::kQuad9,
                             CellType::kHex20,   CellType::kHex27,     CellType::kPrism15,  CellType::kPrism18,
                             CellType::kPyramid13, CellType::kPyramid14};
  for (CellType t : order2) {
    const int n = cell_num_nodes(t), d = cell_dim(t);
    const auto nodes = reference_nodes(t);
    std::vector<double> N(n);
    const auto x = random_point(d, rng);
    shape_functions(t, x.data(), N.data(), nullptr);
    for (int i = 0; i < d; ++i)
      for (int j = i; j < d; ++j) {
        double v = 0;
        for (int a = 0; a < n; ++a) v += N[a] * nodes[a * d + i] * nodes[a * d + j];
        EXPECT_NEAR(v, x[i] * x[j], 1e-14) << cell_name(t);
      }
    if (cell_shape(t) != CellShape::kTensor) continue;
    double v = 0, exact = 1;
    for (int a = 0; a < n; ++a) {
      double m = N[a];
      for (int i = 0; i < d; ++i) m *= nodes[a * d + i] * nodes[a * d + i];
      v += m;
    }
    for (int i = 0; i < d; ++i) exact *= x[i] * x[i];
    if (t == CellType::kQuad9 || t == CellType::kHex27)
      EXPECT_NEAR(v, exact, 1e-14) << cell_name(t);
    else
      EXPECT_GT(std::abs(v - exact), 1e-6) << cell_name(t);
  }
}

// Conformity: on each facet of a 3D cell, the functions of the nodes off the facet vanish and those of its
// nodes are the facet type's own (at the facet's point s, mapped into the cell by the facet's vertices), so
// that a tetrahedron, hexahedron, prism or pyramid sharing that facet agrees with the cell along it.
TEST(ShapeFunctions, TracesOnFacetsAreTheFacetsFunctions) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (CellType t : kAll) {
    if (cell_dim(t) != 3) continue;
    const int n = cell_num_nodes(t);
    const auto nodes = reference_nodes(t);
    for (int f = 0; f < cell_num_facets(t); ++f) {
      const CellType ft = cell_facet_type(t, f);
      const int fn = cell_num_nodes(ft), fv = cell_num_vertices(ft);
      const CellType flin = fv == 3 ? CellType::kTri3 : CellType::kQuad4;
      const int* loc = cell_facet_nodes(t, f);
      for (int trial = 0; trial < 5; ++trial) {
        double s[2] = {U(rng), U(rng)};
        if (fv == 3 && s[0] + s[1] > 1) s[0] = 1 - s[0], s[1] = 1 - s[1];
        double Nl[4], Nf[9], N[27], x[3] = {0, 0, 0};
        shape_functions(flin, s, Nl, nullptr);
        shape_functions(ft, s, Nf, nullptr);
        for (int v = 0; v < fv; ++v)
          for (int i = 0; i < 3; ++i) x[i] += Nl[v] * nodes[3 * loc[v] + i];
        shape_functions(t, x, N, nullptr);
        std::vector<double> expected(n, 0.0);
        for (int k = 0; k < fn; ++k) expected[loc[k]] = Nf[k];
        for (int a = 0; a < n; ++a)
          EXPECT_NEAR(N[a], expected[a], 1e-13) << cell_name(t) << " facet " << f << " node " << a;
      }
    }
  }
}

// The pyramids' gradients at the apex are their limits along the axis from the base's centre.
TEST(ShapeFunctions, PyramidGradientsAtTheApexAreTheLimitsAlongTheAxis) {
  for (CellType t : {CellType::kPyramid5, CellType::kPyramid13, CellType::kPyramid14}) {
    const int n = cell_num_nodes(t);
    std::vector<double> N(n), dN(3 * n), Nn(n), dNn(3 * n);
    const double apex[3] = {0, 0, 1}, near[3] = {0.5e-9, 0.5e-9, 1 - 1e-9};
    shape_functions(t, apex, N.data(), dN.data());
    shape_functions(t, near, Nn.data(), dNn.data());
    for (int a = 0; a < n; ++a) {
      EXPECT_EQ(N[a], a == 4 ? 1.0 : 0.0) << cell_name(t);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(dN[3 * a + i], dNn[3 * a + i], 1e-7) << cell_name(t) << " node " << a;
    }
  }
}
