#include "symcontact/io/atomic_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace symcontact {
namespace {

namespace fs = std::filesystem;

/// A fresh empty folder under the GoogleTest temporary folder, named after the running test.
fs::path fresh_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(::testing::TempDir()) / (std::string("symcontact_") + info->test_suite_name() +
                                                          "_" + info->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::size_t count_entries(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicFile, WritesContentAndLeavesNoTemporary) {
  const fs::path dir = fresh_dir();
  const std::string path = (dir / "out.txt").string();
  write_file_atomically(path, [](std::ostream& os) { os << "hello\n" << 42 << '\n'; });
  EXPECT_EQ(read_all(path), "hello\n42\n");
  EXPECT_EQ(count_entries(dir), 1u);

  write_file_atomically(path, [](std::ostream& os) { os << "second"; });  // replaces
  EXPECT_EQ(read_all(path), "second");
  EXPECT_EQ(count_entries(dir), 1u);
}

TEST(AtomicFile, ThrowingWriterKeepsPreviousFile) {
  const fs::path dir = fresh_dir();
  const std::string path = (dir / "out.txt").string();
  write_file_atomically(path, [](std::ostream& os) { os << "good"; });
  EXPECT_THROW(write_file_atomically(path,
                                     [](std::ostream& os) {
                                       os << "half written";
                                       throw std::logic_error("writer failed");
                                     }),
               std::logic_error);
  EXPECT_EQ(read_all(path), "good");
  EXPECT_EQ(count_entries(dir), 1u);
}

TEST(AtomicFile, BadStreamThrowsNamingPath) {
  const fs::path dir = fresh_dir();
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
  const fs::path dir = fresh_dir();
  const std::string path = (dir / "no_such_folder" / "out.txt").string();
  try {
    write_file_atomically(path, [](std::ostream& os) { os << "x"; });
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

TEST(AtomicFile, EnsureDirectory) {
  const fs::path dir = fresh_dir();
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
