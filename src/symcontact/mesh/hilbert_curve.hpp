#pragma once
/// \file hilbert_curve.hpp
/// Points ordered along a Hilbert curve: consecutive runs of the order are compact regions, which is what a
/// split of nodes or cells into contiguous ranges (the ranks of the distributed path, the pieces of a parallel
/// VTU) needs.
///
/// Hilbert index: the coordinates quantised on a 2^b grid over the bounding box's largest side (b = 31 in 2D,
/// 21 in 3D: 62 and 63 bits), mapped to the curve by Skilling's transpose algorithm ("Programming the Hilbert
/// curve", AIP Conf. Proc. 707, 381, 2004: the inverse undo of the axes' excess work, then Gray encoding, then
/// the bits interleaved); ties (coincident points) in their given order. The order depends on the
/// coordinates only.

#include <cstdint>
#include <vector>

#include "symcontact/core/types.hpp"

namespace symcontact {

/// The Hilbert index of grid point `cell` (one value per dimension, each below 2^bits) on the curve of `bits`
/// levels; throws std::invalid_argument beyond 64 bits in all.
std::uint64_t hilbert_index(std::vector<std::uint64_t> cell, int bits);

/// The columns of `points` (2 or 3 × n) in their order along the curve: order[k] is the k-th point.
std::vector<Index> hilbert_order(const Eigen::MatrixXd& points);

}  // namespace symcontact
