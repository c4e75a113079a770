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

}  // namespace symcontact
