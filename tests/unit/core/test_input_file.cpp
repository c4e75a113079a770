#include "symcontact/core/input_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "support/temp_folder.hpp"

using namespace symcontact;

namespace {

namespace fs = std::filesystem;

class InputFile : public ::testing::Test {
 protected:
  const symcontact::testing::TempFolder folder_;
  const fs::path& dir_ = folder_.path();
};

TEST_F(InputFile, RegularFilesPassAlsoThroughALink) {
  std::ofstream(dir_ / "a.toml") << "x = 1\n";
  fs::create_symlink(dir_ / "a.toml", dir_ / "link.toml");
  EXPECT_EQ(input_file_problem((dir_ / "a.toml").string()), "");
  EXPECT_EQ(input_file_problem((dir_ / "link.toml").string()), "");
  EXPECT_EQ(input_file_problem((dir_ / "a.toml").string(), 6), "");  // 6 bytes: at the limit
  EXPECT_EQ(input_file_problem((dir_ / "a.toml").string(), 5),
            "is 6 bytes, more than the limit of 5 bytes (0 MiB)");
}

TEST_F(InputFile, EachKindOfNonRegularFileIsNamed) {
  ASSERT_EQ(::mkfifo((dir_ / "fifo").c_str(), 0600), 0);
  EXPECT_EQ(input_file_problem((dir_ / "fifo").string()), "is a FIFO (named pipe), expected a regular file");
  fs::create_symlink("/dev/zero", dir_ / "zero");
  EXPECT_EQ(input_file_problem((dir_ / "zero").string()),
            "is a character device (a symbolic link to '/dev/zero'), expected a regular file");
  EXPECT_EQ(input_file_problem(dir_.string()), "is a folder, expected a regular file");
  fs::create_symlink(dir_ / "loop", dir_ / "loop");
  EXPECT_EQ(input_file_problem((dir_ / "loop").string()).rfind("is a symbolic link loop", 0), 0u);
  EXPECT_EQ(input_file_problem((dir_ / "missing").string()), "does not exist");
  fs::create_symlink(dir_ / "missing", dir_ / "dangling");
  EXPECT_NE(input_file_problem((dir_ / "dangling").string()).find("the link's target is missing"), std::string::npos);
}

}  // namespace
