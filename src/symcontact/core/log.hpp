#pragma once
/// \file log.hpp
/// A small logger with verbosity levels and a progress line for long runs. The logger is an object
/// passed to whoever needs it (no global state); a default-constructed one writes to std::cerr.

#include <iosfwd>
#include <string>

namespace symcontact {

enum class Verbosity : int { kQuiet = 0, kNormal = 1, kVerbose = 2, kDebug = 3 };

class Logger {
 public:
  Logger();
  Logger(std::ostream& out, Verbosity level);
  Verbosity level() const { return level_; }
  void info(const std::string& msg) const;     ///< shown at kNormal and above
  void detail(const std::string& msg) const;   ///< shown at kVerbose and above
  void debug(const std::string& msg) const;    ///< shown at kDebug
  void warning(const std::string& msg) const;  ///< always shown
  /// A progress line "[label] done/total (pct%) extra", at kNormal and above.
  void progress(const std::string& label, long done, long total, const std::string& extra = "") const;

 private:
  std::ostream* out_;
  Verbosity level_;
};

}  // namespace symcontact
