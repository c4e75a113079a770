#include "symcontact/io/output_folder.hpp"

#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace symcontact {

namespace {

namespace fs = std::filesystem;

#ifndef PATH_MAX
constexpr std::size_t kPathMax = 4096;
#else
constexpr std::size_t kPathMax = PATH_MAX;
#endif
#ifndef NAME_MAX
constexpr std::size_t kNameMax = 255;
#else
constexpr std::size_t kNameMax = NAME_MAX;
#endif

/// Why entries cannot be created in the existing folder `folder`, or "".
std::string not_writable(const fs::path& folder) {
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    return "is not writable: '" + folder.string() + "': " + std::strerror(errno);
  const fs::path probe = folder / (".symcontact-probe-" + std::to_string(static_cast<long>(::getpid())));
  if (::mkdir(probe.c_str(), 0700) != 0)
    return "is not writable: cannot create entries in '" + folder.string() + "': " + std::strerror(errno);
  ::rmdir(probe.c_str());
  return "";
}

}  // namespace

std::string output_folder_problem(const std::string& dir) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(dir.empty() ? fs::path(".") : fs::path(dir), ec).lexically_normal();
  if (ec) return "cannot be resolved: " + ec.message();
  for (const fs::path& part : absolute) {
    if (part.string().size() > kNameMax)
      return "has a part of " + std::to_string(part.string().size()) + " characters, more than the limit of " +
             std::to_string(kNameMax);
  }
  const std::size_t room = kPathMax - kNameMax - 1;
  if (absolute.string().size() > room)
    return "is too long (" + std::to_string(absolute.string().size()) + " characters as an absolute path, at most " +
           std::to_string(room) + " so that the file names written in it fit in " + std::to_string(kPathMax) + ")";
  // Walk down from the root: the first part that does not exist is where creation would start.
  fs::path prefix;
  fs::path deepest_existing = absolute.root_path();
  for (const fs::path& part : absolute) {
    prefix /= part;
    struct stat st {};
    if (::stat(prefix.c_str(), &st) != 0) {
      if (errno == ENOENT) break;
      return "cannot be examined: '" + prefix.string() + "': " + std::strerror(errno);
    }
    if (!S_ISDIR(st.st_mode)) {
      if (prefix == absolute) return "is a file, not a folder";
      return "is under '" + prefix.string() + "', which is a file, not a folder";
    }
    deepest_existing = prefix;
  }
  return not_writable(deepest_existing);
}

}  // namespace symcontact
