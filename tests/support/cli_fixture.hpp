#pragma once
/// \file cli_fixture.hpp
/// Shared pieces of the end-to-end tests of the command-line program: each test works in its own
/// temporary folder (support/temp_folder.hpp) and runs the
/// binary SYMCONTACT_CLI through the shell, capturing stdout and stderr together.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <string>

#include "support/temp_folder.hpp"

namespace symcontact::testing {

struct CliResult {
  int exit_code = -1;  ///< the program's exit status, or -1 when it did not exit normally
  std::string output;  ///< stdout and stderr, interleaved
};

inline std::string shell_quote(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

/// Expects every string of `expected` in `output` (each failure names the missing string).
inline void expect_all_in(const std::string& output, std::initializer_list<std::string> expected) {
  for (const std::string& s : expected) {
    EXPECT_NE(output.find(s), std::string::npos) << "'" << s << "' not in: " << output;
  }
}

/// A test with its own folder `dir_` (named after the test), `run(args)` and `run_case(file)`.
class CliTest : public ::testing::Test {
 protected:
  explicit CliTest(const std::string& prefix) : folder_(prefix), dir_(folder_.path()) {}

  /// Runs `symcontact ARGS` in the test's folder.
  CliResult run(const std::string& args) const { return run_with_env("", args); }
  /// Runs `ENV symcontact ARGS` in the test's folder: `env` holds NAME=VALUE assignments for the shell.
  CliResult run_with_env(const std::string& env, const std::string& args) const {
    const std::filesystem::path log = dir_ / "cli_output.txt";
    const std::string command = "cd " + shell_quote(dir_) + " && " + env + (env.empty() ? "" : " ") +
                                shell_quote(SYMCONTACT_CLI) + " " + args + " > " + shell_quote(log) + " 2>&1";
    const int status = std::system(command.c_str());
    CliResult r;
    r.exit_code = (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
    r.output = read_text(log);
    return r;
  }

  /// Runs `symcontact run CASE --out <folder>/out EXTRA`: the results land in out_.
  CliResult run_case(const std::filesystem::path& case_file, const std::string& extra = "") const {
    return run("run " + shell_quote(case_file) + " --out " + shell_quote(out_) + " " + extra);
  }

  /// Writes `text` as `name` in the test's folder and returns its path.
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    return folder_.write(name, text);
  }

  /// Runs `run CASE --out out EXTRA`, expects an input error (exit 2) whose message holds every string
  /// in `expected`, and no output folder.
  void expect_input_error(const std::filesystem::path& case_file, std::initializer_list<std::string> expected,
                          const std::string& extra = "") const {
    const CliResult r = run_case(case_file, extra);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("input error"), std::string::npos) << r.output;
    expect_all_in(r.output, expected);
    EXPECT_FALSE(std::filesystem::exists(out_)) << "an input error must not create the output folder";
  }

  /// Runs `check CASE` and `run CASE --out out`: each must exit 2 with every string of `expected` in its
  /// output; no output folder afterwards.
  void expect_refused_by_check_and_run(const std::string& case_file, std::initializer_list<std::string> expected) const {
    for (const std::string& cmd : {"check " + case_file, "run " + case_file + " --out out"}) {
      const CliResult r = run(cmd);
      EXPECT_EQ(r.exit_code, 2) << cmd << "\n" << r.output;
      expect_all_in(r.output, expected);
    }
    EXPECT_FALSE(std::filesystem::exists(out_));
  }

  TempFolder folder_;
  const std::filesystem::path& dir_;
  const std::filesystem::path out_ = dir_ / "out";  ///< run_case()'s output folder
};

}  // namespace symcontact::testing
