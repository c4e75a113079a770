#include "symcontact/io/atomic_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

#ifdef _WIN32
#include <process.h>
#define SYMCONTACT_GETPID _getpid
#else
#include <signal.h>
#include <unistd.h>
#define SYMCONTACT_GETPID getpid
#endif

namespace symcontact {

namespace fs = std::filesystem;

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& writer) {
  const std::string tmp = path + ".tmp-" + std::to_string(static_cast<long>(SYMCONTACT_GETPID()));
  auto discard = [&tmp]() {
    std::error_code ignored;
    fs::remove(tmp, ignored);
  };

  std::ofstream out(tmp, std::ios::out | std::ios::binary | std::ios::trunc);
  if (!out) {
    throw std::runtime_error("cannot write '" + path + "': cannot open temporary file '" + tmp +
                             "': " + std::strerror(errno));
  }
  try {
    writer(out);
  } catch (...) {
    out.close();
    discard();
    throw;
  }
  out.flush();
  const bool ok = static_cast<bool>(out);
  out.close();
  if (!ok || out.fail()) {
    discard();
    throw std::runtime_error("cannot write '" + path + "': writing the temporary file '" + tmp +
                             "' failed (disk full?)");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    discard();
    throw std::runtime_error("cannot write '" + path + "': renaming '" + tmp + "' over it failed: " +
                             std::strerror(err));
  }
}

void ensure_directory(const std::string& dir) {
  if (dir.empty()) return;
  std::error_code ec;
  const fs::file_status st = fs::status(dir, ec);
  if (fs::exists(st)) {
    if (!fs::is_directory(st)) throw std::runtime_error("output folder '" + dir + "' exists and is not a folder");
    return;
  }
  ec.clear();
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create output folder '" + dir + "': " + ec.message());
  if (!fs::is_directory(dir, ec)) throw std::runtime_error("cannot create output folder '" + dir + "'");
}

int remove_stale_temporaries(const std::string& dir) {
  std::error_code ec;
  fs::directory_iterator it(dir.empty() ? fs::path(".") : fs::path(dir), ec);
  if (ec) return 0;
  int removed = 0;
  for (const fs::directory_entry& entry : it) {
    const std::string name = entry.path().filename().string();
    const std::size_t mark = name.rfind(".tmp-");
    if (mark == std::string::npos || mark + 5 >= name.size()) continue;
    const std::string digits = name.substr(mark + 5);
    if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) continue;
    const long pid = std::stol(digits);
#ifndef _WIN32
    if (pid == static_cast<long>(SYMCONTACT_GETPID())) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // that process still runs
#endif
    std::error_code ignored;
    if (entry.is_regular_file(ignored) && fs::remove(entry.path(), ignored)) ++removed;
  }
  return removed;
}

}  // namespace symcontact
