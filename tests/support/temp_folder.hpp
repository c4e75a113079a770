#pragma once
/// \file temp_folder.hpp
/// A test's own temporary folder and whole-file reads and writes. The folder lies under
/// ::testing::TempDir(), is named after the running test and the process (CTest runs tests in parallel
/// processes), starts empty, and is removed when the test passed — kept when it failed, for a look.

#include <filesystem>
#include <string>

namespace symcontact::testing {

/// The whole content of `path` (bytes as they are); empty when it cannot be read.
std::string read_text(const std::filesystem::path& path);
/// Writes `text` to `path` (creating its folder); a test failure when it cannot.
void write_text(const std::filesystem::path& path, const std::string& text);

class TempFolder {
 public:
  /// Creates <TempDir>/<prefix><suite>_<test>_<pid>, empty. Construct it inside a test (or its fixture).
  explicit TempFolder(const std::string& prefix = "symcontact_");
  ~TempFolder();
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  /// Writes `text` as `name` (relative to the folder) and returns its path.
  std::filesystem::path write(const std::string& name, const std::string& text) const;

 private:
  std::filesystem::path path_;
};

}  // namespace symcontact::testing
