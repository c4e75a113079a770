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
#include <initializer_list>
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

inline void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  ASSERT_TRUE(out.good()) << "cannot write " << path;
}

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

  /// Writes `text` as `name` in the test's folder and returns its path.
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const std::filesystem::path p = dir_ / name;
    write_text(p, text);
    return p;
  }

  /// Runs `run CASE --out out EXTRA`, expects an input error (exit 2) whose message holds every string
  /// in `expected`, and no output folder.
  void expect_input_error(const std::filesystem::path& case_file, std::initializer_list<std::string> expected,
                          const std::string& extra = "") const {
    const std::filesystem::path out = dir_ / "out";
    const CliResult r = run("run " + shell_quote(case_file) + " --out " + shell_quote(out) + " " + extra);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("input error"), std::string::npos) << r.output;
    for (const std::string& s : expected) {
      EXPECT_NE(r.output.find(s), std::string::npos) << "'" << s << "' not in: " << r.output;
    }
    EXPECT_FALSE(std::filesystem::exists(out)) << "an input error must not create the output folder";
  }

  std::filesystem::path dir_;

 private:
  std::string prefix_;
};

}  // namespace symcontact::testing
