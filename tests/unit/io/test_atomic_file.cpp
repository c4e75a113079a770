#include "symcontact/io/atomic_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "support/temp_folder.hpp"

namespace symcontact {
namespace {

namespace fs = std::filesystem;

std::size_t count_entries(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicFile, WritesContentAndLeavesNoTemporary) {
  const testing::TempFolder folder;
  const fs::path& dir = folder.path();
  const std::string path = (dir / "out.txt").string();
  write_file_atomically(path, [](std::ostream& os) { os << "hello\n" << 42 << '\n'; });
  EXPECT_EQ(testing::read_text(path), "hello\n42\n");
  EXPECT_EQ(count_entries(dir), 1u);

  write_file_atomically(path, [](std::ostream& os) { os << "second"; });  // replaces
  EXPECT_EQ(testing::read_text(path), "second");
  EXPECT_EQ(count_entries(dir), 1u);
}

TEST(AtomicFile, ThrowingWriterKeepsPreviousFile) {
  const testing::TempFolder folder;
  const fs::path& dir = folder.path();
  const std::string path = (dir / "out.txt").string();
  write_file_atomically(path, [](std::ostream& os) { os << "good"; });
  EXPECT_THROW(write_file_atomically(path,
                                     [](std::ostream& os) {
                                       os << "half written";
                                       throw std::logic_error("writer failed");
                                     }),
               std::logic_error);
  EXPECT_EQ(testing::read_text(path), "good");
  EXPECT_EQ(count_entries(dir), 1u);
}

TEST(AtomicFile, BadStreamThrowsNamingPath) {
  const testing::TempFolder folder;
  const fs::path& dir = folder.path();
  const std::string path = (dir / "out.txt").string();
  try {
    write_file_atomically(path, [](std::ostream& os) { os.setstate(std::ios::badbit); });
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_EQ(count_entries(dir), 0u);
}

TEST(AtomicFile, MissingFolderThrowsNamingPath) {
  const testing::TempFolder folder;
  const fs::path& dir = folder.path();
  const std::string path = (dir / "no_such_folder" / "out.txt").string();
  try {
    write_file_atomically(path, [](std::ostream& os) { os << "x"; });
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

TEST(AtomicFile, EnsureDirectory) {
  const testing::TempFolder folder;
  const fs::path& dir = folder.path();
  const std::string nested = (dir / "a" / "b" / "c").string();
  ensure_directory(nested);
  EXPECT_TRUE(fs::is_directory(nested));
  ensure_directory(nested);  // already there: fine
  ensure_directory("");      // the current folder: nothing to do

  const std::string file = (dir / "a_file").string();
  write_file_atomically(file, [](std::ostream& os) { os << "x"; });
  for (const std::string& bad : {file, (fs::path(file) / "sub").string()}) {
    try {
      ensure_directory(bad);
      FAIL() << "expected std::runtime_error for " << bad;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace symcontact
