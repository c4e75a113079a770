#pragma once
/// \file cli_fixture.hpp
/// Shared pieces of the end-to-end tests of the command-line program: each test works in its own
/// temporary folder (CTest runs them in parallel; the folder is kept when the test fails) and runs the
/// binary SYMCONTACT_CLI through the shell, capturing stdout and stderr together.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace symcontact::testing {

struct CliResult {
  int exit_code = -1;  ///< the program's exit status, or -1 when it did not exit normally
  std::string output;  ///< stdout and stderr, interleaved
};

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline std::string shell_quote(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

/// A test with its own folder `dir_` (named after the test) and `run(args)`.
class CliTest : public ::testing::Test {
 protected:
  explicit CliTest(std::string prefix) : prefix_(std::move(prefix)) {}
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           (prefix_ + std::string(info->name()) + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    if (!HasFailure()) std::filesystem::remove_all(dir_, ec);  // kept on failure, for a look
  }

  /// Runs `symcontact ARGS` in the test's folder.
  CliResult run(const std::string& args) const {
    const std::filesystem::path log = dir_ / "cli_output.txt";
    const std::string command = "cd " + shell_quote(dir_) + " && " + shell_quote(SYMCONTACT_CLI) + " " + args +
                                " > " + shell_quote(log) + " 2>&1";
    const int status = std::system(command.c_str());
    CliResult r;
    r.exit_code = (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
    r.output = read_text(log);
    return r;
  }

  std::filesystem::path dir_;

 private:
  std::string prefix_;
};

}  // namespace symcontact::testing
