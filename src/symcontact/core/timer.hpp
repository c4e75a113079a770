#pragma once
/// \file timer.hpp
/// Wall-clock timing per named phase (meshing, assembly, factorisation, ...). Phases keep the order in
/// which they were first seen so that reports read in execution order.

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace symcontact {

class PhaseTimes {
 public:
  void add(const std::string& phase, double seconds);
  double get(const std::string& phase) const;  ///< 0 when the phase never ran
  double total() const;
  const std::vector<std::pair<std::string, double>>& entries() const { return entries_; }
  void merge(const PhaseTimes& other);

 private:
  std::vector<std::pair<std::string, double>> entries_;
};

/// Adds the time between construction and destruction (or stop()) to `times[phase]`.
class ScopedPhase {
 public:
  ScopedPhase(PhaseTimes& times, std::string phase);
  ~ScopedPhase();
  double stop();  ///< stops early and returns the elapsed seconds; idempotent
  ScopedPhase(const ScopedPhase&) = delete;
  ScopedPhase& operator=(const ScopedPhase&) = delete;

 private:
  PhaseTimes& times_;
  std::string phase_;
  std::chrono::steady_clock::time_point start_;
  bool running_ = true;
};

/// Seconds since an arbitrary epoch (steady clock).
double wall_seconds();

}  // namespace symcontact
