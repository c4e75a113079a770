#include "symcontact/core/progress_clock.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "symcontact/core/timer.hpp"

namespace symcontact {

ProgressClock::ProgressClock(double quiet_seconds) : start_(wall_seconds()), quiet_(quiet_seconds) {}

double ProgressClock::elapsed() const { return wall_seconds() - start_; }

std::string ProgressClock::suffix(long done, long total) const {
  const double t = elapsed();
  if (t < quiet_ || done <= 0) return "";
  std::string s = ", elapsed " + format_duration(t);
  if (done < total) s += ", about " + format_duration(t / static_cast<double>(done) * (total - done)) + " left";
  return s;
}

void log_iteration(const Logger& log, const ProgressClock& clock, const std::string& line, double after_seconds) {
  const double t = clock.elapsed();
  if (t > after_seconds)
    log.info(line + " (elapsed " + format_duration(t) + ")");
  else
    log.detail(line);
}

std::string format_duration(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char buf[32];
  if (s < 60) {
    std::snprintf(buf, sizeof buf, "%ld s", s);
  } else if (s < 3600) {
    std::snprintf(buf, sizeof buf, "%ld min %02ld s", s / 60, s % 60);
  } else {
    std::snprintf(buf, sizeof buf, "%ld h %02ld min", s / 3600, (s % 3600) / 60);
  }
  return buf;
}

}  // namespace symcontact
