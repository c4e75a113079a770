#pragma once
/// \file fixed_point_monitor.hpp
/// Progress of a fixed-point iteration x_{k+1} = G(x_k), judged from its relative changes c_k alone.
///
/// A fixed point converging at a linear rate ρ < 1 makes a new low of c_k every iteration or so; one whose
/// inner solves are inexact stops falling at their noise floor, and one caught in a cycle of period p repeats
/// its changes every p iterations. Either way it makes no new low: after `window` iterations whose smallest
/// change is not below `progress` × the smallest change before them, the iteration is called stagnated. With
/// window = 6 and progress = 0.7 a cycle of period 2 to 5 is caught, and so is any rate slower than
/// 0.7^(1/6) ≈ 0.94 per iteration; a rate of 0.9 (0.53 in six iterations) is not.
/// restart() starts a new watch (after the caller changed the iteration: a tighter inner solve, another
/// relaxation), so that the new regime is judged on its own changes.

#include <vector>

namespace symcontact {

class FixedPointMonitor {
 public:
  explicit FixedPointMonitor(int window = 6, double progress = 0.7) : window_(window), progress_(progress) {}
  void record(double change);
  /// No new low for `window` changes since the last restart (see the file comment).
  bool stagnated() const;
  void restart() { start_ = changes_.size(); }
  /// The smallest change since the last restart (+inf before any).
  double best() const;
  const std::vector<double>& changes() const { return changes_; }

 private:
  int window_;
  double progress_;
  std::vector<double> changes_;
  std::size_t start_ = 0;  ///< index of the first change since the last restart
};

}  // namespace symcontact
