#include "symcontact/core/log.hpp"

#include <iostream>
#include <sstream>

namespace symcontact {

Logger::Logger() : out_(&std::cerr), level_(Verbosity::kNormal) {}
Logger::Logger(std::ostream& out, Verbosity level) : out_(&out), level_(level) {}

void Logger::info(const std::string& msg) const {
  if (level_ >= Verbosity::kNormal) *out_ << msg << '\n';
}
void Logger::detail(const std::string& msg) const {
  if (level_ >= Verbosity::kVerbose) *out_ << msg << '\n';
}
void Logger::debug(const std::string& msg) const {
  if (level_ >= Verbosity::kDebug) *out_ << msg << '\n';
}
void Logger::warning(const std::string& msg) const { *out_ << "warning: " << msg << '\n'; }

void Logger::progress(const std::string& label, long done, long total, const std::string& extra) const {
  if (level_ < Verbosity::kNormal) return;
  std::ostringstream s;
  s << '[' << label << "] " << done << '/' << total;
  if (total > 0) s << " (" << (100 * done) / total << "%)";
  if (!extra.empty()) s << ' ' << extra;
  *out_ << s.str() << std::endl;
}

}  // namespace symcontact
