// Points along a Hilbert curve (src/symcontact/mesh/hilbert_curve.hpp): the index walks through every cell of
// the grid by face neighbours, and the order of points follows it.

#include "symcontact/mesh/hilbert_curve.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace symcontact {
namespace {

/// Every cell of the 2^bits grid in `dim` dimensions, its Hilbert index: a bijection onto [0, 2^(dim·bits)) whose
/// consecutive indices are face neighbours.
void expect_hilbert_walk(int dim, int bits) {
  const std::uint64_t side = std::uint64_t{1} << bits, cells = std::uint64_t{1} << (dim * bits);
  std::vector<std::vector<std::uint64_t>> at(cells);
  for (std::uint64_t c = 0; c < cells; ++c) {
    std::vector<std::uint64_t> cell(static_cast<std::size_t>(dim));
    for (int i = 0; i < dim; ++i) cell[static_cast<std::size_t>(i)] = (c >> (bits * i)) % side;
    const std::uint64_t h = hilbert_index(cell, bits);
    ASSERT_LT(h, cells);
    ASSERT_TRUE(at[h].empty()) << "index " << h << " twice";
    at[h] = cell;
  }
  for (std::uint64_t h = 1; h < cells; ++h) {
    std::uint64_t distance = 0;
    for (int i = 0; i < dim; ++i) {
      const auto a = at[h - 1][static_cast<std::size_t>(i)], b = at[h][static_cast<std::size_t>(i)];
      distance += a > b ? a - b : b - a;
    }
    EXPECT_EQ(distance, 1u) << "dim " << dim << ", indices " << h - 1 << " and " << h;
  }
}

TEST(HilbertCurve, TheIndexWalksThroughEveryCellByFaceNeighbours) {
  expect_hilbert_walk(2, 4);
  expect_hilbert_walk(3, 3);
  EXPECT_THROW(hilbert_index({1, 2, 3}, 22), std::invalid_argument);
}

TEST(HilbertCurve, OrdersPointsAlongTheCurve) {
  // The 4 × 4 grid's cell centres, listed row by row: the order is the walk of the index, from a corner.
  Eigen::MatrixXd points(2, 16);
  for (int k = 0; k < 16; ++k) points.col(k) << k % 4 + 0.5, k / 4 + 0.5;
  const std::vector<Index> order = hilbert_order(points);
  ASSERT_EQ(order.size(), 16u);
  for (std::size_t k = 1; k < order.size(); ++k)
    EXPECT_DOUBLE_EQ((points.col(order[k]) - points.col(order[k - 1])).lpNorm<1>(), 1.0) << "step " << k;
  EXPECT_EQ(order.front(), 0);
  // Coincident points keep their given order.
  const std::vector<Index> same = hilbert_order(Eigen::MatrixXd::Ones(3, 4));
  EXPECT_EQ(same, (std::vector<Index>{0, 1, 2, 3}));
}

}  // namespace
}  // namespace symcontact
