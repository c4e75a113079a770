// The PETSc numbering of the distributed path (src/symcontact/distributed/node_ordering.hpp): the ordering the
// Hilbert curve gives nodes cuts a body into compact halves where the mesh generator's order does not; vectors
// and constraints carried over and back unchanged.

#include "symcontact/distributed/node_ordering.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <random>
#include <set>

#include "test_support.hpp"

namespace symcontact {
namespace {

/// An n³ grid of nodes in a shuffled order (as a mesh generator's), its edges between grid neighbours.
struct ShuffledGrid {
  Eigen::MatrixXd x;
  std::vector<std::pair<Index, Index>> edges;
};

ShuffledGrid shuffled_grid(int n) {
  const Index count = static_cast<Index>(n) * n * n;
  std::vector<Index> label(static_cast<std::size_t>(count));
  std::iota(label.begin(), label.end(), Index{0});
  std::shuffle(label.begin(), label.end(), std::mt19937(5));
  ShuffledGrid g{Eigen::MatrixXd(3, count), {}};
  auto at = [&](int i, int j, int k) { return label[static_cast<std::size_t>((k * n + j) * n + i)]; };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        g.x.col(at(i, j, k)) << i, j, k;
        if (i + 1 < n) g.edges.emplace_back(at(i, j, k), at(i + 1, j, k));
        if (j + 1 < n) g.edges.emplace_back(at(i, j, k), at(i, j + 1, k));
        if (k + 1 < n) g.edges.emplace_back(at(i, j, k), at(i, j, k + 1));
      }
  return g;
}

/// The fraction of edges between the first and the second half of the nodes in the numbering `number`.
template <class Number>
double cut_fraction(const ShuffledGrid& g, Number number) {
  const Index half = g.x.cols() / 2;
  std::size_t cut = 0;
  for (const auto& [a, b] : g.edges) cut += (number(a) < half) != (number(b) < half);
  return static_cast<double>(cut) / static_cast<double>(g.edges.size());
}

// Two ranks' halves of a 16³ grid: the shuffled order cuts about half the edges, the Hilbert order no more than
// twice a plane through the middle (256 of 11,520 edges: 2.2 %).
TEST(NodeOrdering, HalvesOfTheHilbertOrderAreCompact) {
  const ShuffledGrid g = shuffled_grid(16);
  const NodeOrdering ordering(g.x);
  const double shuffled = cut_fraction(g, [](Index k) { return k; });
  const double hilbert = cut_fraction(g, [&](Index k) { return ordering.node(k); });
  if (g_petsc->rank() == 0)
    std::printf("edges cut between the halves: shuffled order %.1f %%, Hilbert order %.1f %%\n", 100 * shuffled,
                100 * hilbert);
  EXPECT_GT(shuffled, 0.4);
  EXPECT_LE(hilbert, 2.0 * 256.0 / static_cast<double>(g.edges.size()));
}

TEST(NodeOrdering, CarriesVectorsAndConstraintsOverAndBack) {
  const ShuffledGrid g = shuffled_grid(5);
  const NodeOrdering ordering(g.x);
  const Index nodes = g.x.cols(), n = 3 * nodes;
  std::set<Index> seen;
  for (Index k = 0; k < nodes; ++k) seen.insert(ordering.node(k));
  EXPECT_EQ(static_cast<Index>(seen.size()), nodes);
  EXPECT_EQ(*seen.rbegin(), nodes - 1);
  const VectorXd u = VectorXd::LinSpaced(n, -1.0, 2.0);
  EXPECT_EQ(ordering.to_model(ordering.to_petsc(u)), u);
  const Eigen::MatrixXd x = ordering.nodes_to_petsc(g.x);
  for (Index k = 0; k < nodes; ++k) EXPECT_EQ(x.col(ordering.node(k)), g.x.col(k));
  // Two rows (nodes 3 and 7) reading several nodes, with a slip map: the same values in either numbering.
  NodalConstraints c;
  c.node = {3, 7};
  c.normal = Eigen::MatrixXd::Zero(3, 2);
  c.lower = VectorXd::Zero(2);
  std::vector<Eigen::Triplet<double>> t{{0, 9, 1.0}, {0, 22, -0.5}, {1, 23, 2.0}, {1, 40, 0.25}};
  c.rows.resize(2, n);
  c.rows.setFromTriplets(t.begin(), t.end());
  c.slip_map.resize(6, n);
  c.slip_map.setFromTriplets(t.begin(), t.end());
  const NodalConstraints p = ordering.to_petsc(c);
  EXPECT_EQ(p.node, (std::vector<Index>{ordering.node(3), ordering.node(7)}));
  EXPECT_EQ(p.rows * ordering.to_petsc(u), c.rows * u);
  EXPECT_EQ(p.slip_map * ordering.to_petsc(u), c.slip_map * u);
  EXPECT_EQ(ordering.dofs_to_petsc({1, 22}), (std::vector<Index>{ordering.dof(1), ordering.dof(22)}));
  EXPECT_EQ(ordering.dof(22), 3 * ordering.node(7) + 1);
}

}  // namespace
}  // namespace symcontact
