#pragma once
/// \file input_file.hpp
/// What a path names, found before anything opens it: only regular files are read as input. Opening a
/// FIFO blocks until some other process writes to it, a character device such as /dev/zero never ends,
/// and a symbolic link loop fails with ELOOP (which a plain "cannot open" would report as a missing
/// file). The check follows symbolic links, as opening would, and says what the final target is.

#include <cstdint>
#include <limits>
#include <string>

namespace symcontact {

/// The size limit of a problem file (64 MiB): a TOML file describing a few bodies is a few kB.
constexpr std::uintmax_t kMaxProblemFileBytes = std::uintmax_t{64} << 20;

/// Returns "" when `path` (following symbolic links) is a regular file of at most `max_bytes` bytes;
/// otherwise what it is instead, as a clause to append to the file name: "does not exist", "is a
/// symbolic link loop", "is a FIFO (named pipe)", "is a character device", "is a block device", "is a
/// socket", "is a folder", "is 70000000 bytes, more than the limit of 67108864 bytes (64 MiB)",
/// "cannot be examined: <reason>". When `path` itself is a symbolic link the clause says where it
/// leads ("is a character device (a symbolic link to '/dev/zero')").
std::string input_file_problem(const std::string& path,
                               std::uintmax_t max_bytes = std::numeric_limits<std::uintmax_t>::max());

}  // namespace symcontact
