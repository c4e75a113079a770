#include "symcontact/core/timer.hpp"

namespace symcontact {

void PhaseTimes::add(const std::string& phase, double seconds) {
  for (auto& e : entries_)
    if (e.first == phase) {
      e.second += seconds;
      return;
    }
  entries_.emplace_back(phase, seconds);
}

double PhaseTimes::get(const std::string& phase) const {
  for (const auto& e : entries_)
    if (e.first == phase) return e.second;
  return 0.0;
}

double PhaseTimes::total() const {
  double t = 0;
  for (const auto& e : entries_) t += e.second;
  return t;
}

void PhaseTimes::merge(const PhaseTimes& other) {
  for (const auto& e : other.entries_) add(e.first, e.second);
}

ScopedPhase::ScopedPhase(PhaseTimes& times, std::string phase)
    : times_(times), phase_(std::move(phase)), start_(std::chrono::steady_clock::now()) {}

ScopedPhase::~ScopedPhase() { stop(); }

double ScopedPhase::stop() {
  if (!running_) return 0.0;
  running_ = false;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  times_.add(phase_, s);
  return s;
}

double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace symcontact
