#pragma once
/// \file progress_clock.hpp
/// Times for progress lines: how long a loop has run and about how long it has left.

#include <string>

#include "symcontact/core/log.hpp"

namespace symcontact {

/// The time a loop of `total` items has run and an estimate of the time left: suffix(done, total) is
/// ", elapsed 1 min 12 s, about 40 s left" (the time left from the mean time per item so far), or empty
/// while the loop has run less than `quiet_seconds`, so that short runs print the same lines every time.
class ProgressClock {
 public:
  explicit ProgressClock(double quiet_seconds = 5.0);
  std::string suffix(long done, long total) const;
  double elapsed() const;  ///< seconds since construction

 private:
  double start_;
  double quiet_;
};

/// An iteration's line of a loop timed by `clock`: at the default verbosity, with the elapsed time, once the
/// loop has run `after_seconds` (a long loop shows it is alive), else at -v only.
void log_iteration(const Logger& log, const ProgressClock& clock, const std::string& line, double after_seconds = 5.0);

/// "45 s", "3 min 20 s", "2 h 05 min": a duration in seconds, rounded to what a reader needs.
std::string format_duration(double seconds);

}  // namespace symcontact
