#include "symcontact/core/input_file.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace symcontact {

namespace {

/// What the stat() of a non-regular file says it is.
const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "is a folder";
  if (S_ISFIFO(mode)) return "is a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "is a character device";
  if (S_ISBLK(mode)) return "is a block device";
  if (S_ISSOCK(mode)) return "is a socket";
  return "is not a regular file";
}

/// " (a symbolic link to 'target')" when `path` is itself a link, else "".
std::string link_note(const std::string& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return "";
  std::error_code ec;
  const std::filesystem::path target = std::filesystem::read_symlink(path, ec);
  return ec ? " (a symbolic link)" : " (a symbolic link to '" + target.string() + "')";
}

}  // namespace

std::string input_file_problem(const std::string& path, std::uintmax_t max_bytes) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    const int err = errno;
    if (err == ELOOP) return "is a symbolic link loop (following its links never reaches a file)";
    if (err == ENOENT) {
      // A link whose target is missing is not the same mistake as a missing name.
      const std::string note = link_note(path);
      return note.empty() ? "does not exist" : "does not exist" + note + ", the link's target is missing";
    }
    if (err == ENOTDIR) return "does not exist (a part of its path is not a folder)";
    if (err == ENAMETOOLONG) return "cannot be examined: the path is too long";
    return std::string("cannot be examined: ") + std::strerror(err);
  }
  if (!S_ISREG(st.st_mode)) return std::string(kind_of(st.st_mode)) + link_note(path) + ", expected a regular file";
  const auto size = static_cast<std::uintmax_t>(st.st_size);
  if (size > max_bytes) {
    return "is " + std::to_string(size) + " bytes, more than the limit of " + std::to_string(max_bytes) + " bytes (" +
           std::to_string(max_bytes >> 20) + " MiB)";
  }
  return "";
}

}  // namespace symcontact
