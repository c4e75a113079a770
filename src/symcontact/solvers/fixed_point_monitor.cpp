#include "symcontact/solvers/fixed_point_monitor.hpp"

#include <algorithm>
#include <limits>

namespace symcontact {

void FixedPointMonitor::record(double change) { changes_.push_back(change); }

double FixedPointMonitor::best() const {
  double b = std::numeric_limits<double>::infinity();
  for (std::size_t k = start_; k < changes_.size(); ++k) b = std::min(b, changes_[k]);
  return b;
}

bool FixedPointMonitor::stagnated() const {
  const std::size_t n = changes_.size() - start_, w = static_cast<std::size_t>(window_);
  if (n <= w) return false;
  const auto first = changes_.begin() + static_cast<std::ptrdiff_t>(start_);
  const auto split = changes_.end() - static_cast<std::ptrdiff_t>(w);
  const double before = *std::min_element(first, split);
  const double recent = *std::min_element(split, changes_.end());
  return !(recent < progress_ * before);
}

}  // namespace symcontact
