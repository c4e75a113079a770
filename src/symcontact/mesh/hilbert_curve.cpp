#include "symcontact/mesh/hilbert_curve.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace symcontact {

std::uint64_t hilbert_index(std::vector<std::uint64_t> cell, int bits) {
  const std::size_t n = cell.size();
  if (n == 0 || bits < 1 || static_cast<std::size_t>(bits) * n > 64)
    throw std::invalid_argument("hilbert_index: 1 to 64 bits in all");
  // Skilling (2004): from the finest level's excess work back to the coarsest, each coordinate's bit either
  // reflects the lower bits of the first coordinate or swaps them with its own; then Gray encoding.
  for (std::uint64_t level = std::uint64_t{1} << (bits - 1); level > 1; level >>= 1) {
    const std::uint64_t lower = level - 1;
    for (std::size_t i = 0; i < n; ++i) {
      if (cell[i] & level) {
        cell[0] ^= lower;
      } else {
        const std::uint64_t swap = (cell[0] ^ cell[i]) & lower;
        cell[0] ^= swap;
        cell[i] ^= swap;
      }
    }
  }
  for (std::size_t i = 1; i < n; ++i) cell[i] ^= cell[i - 1];
  std::uint64_t flip = 0;
  for (std::uint64_t level = std::uint64_t{1} << (bits - 1); level > 1; level >>= 1)
    if (cell[n - 1] & level) flip ^= level - 1;
  for (std::uint64_t& c : cell) c ^= flip;
  // The transposed index: bit k of coordinate i is bit (k·n + n − 1 − i) of the index.
  std::uint64_t index = 0;
  for (int k = bits - 1; k >= 0; --k)
    for (std::size_t i = 0; i < n; ++i) index = (index << 1) | ((cell[i] >> k) & 1u);
  return index;
}

std::vector<Index> hilbert_order(const Eigen::MatrixXd& points) {
  const Index n = points.cols();
  const int dim = static_cast<int>(points.rows());
  const int bits = dim == 2 ? 31 : 21;
  const double top = static_cast<double>((std::uint64_t{1} << bits) - 1);
  std::vector<std::uint64_t> key(static_cast<std::size_t>(n), 0);
  if (n > 0) {
    const Eigen::VectorXd lo = points.rowwise().minCoeff();
    const double side = (points.rowwise().maxCoeff() - lo).maxCoeff();
    std::vector<std::uint64_t> cell(static_cast<std::size_t>(dim));
    for (Index k = 0; k < n; ++k) {
      for (int i = 0; i < dim; ++i)
        cell[static_cast<std::size_t>(i)] =
            side > 0.0 ? static_cast<std::uint64_t>(std::clamp((points(i, k) - lo[i]) / side, 0.0, 1.0) * top) : 0;
      key[static_cast<std::size_t>(k)] = hilbert_index(cell, bits);
    }
  }
  std::vector<Index> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), Index{0});
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) {
    return key[static_cast<std::size_t>(a)] < key[static_cast<std::size_t>(b)];
  });
  return order;
}

}  // namespace symcontact
