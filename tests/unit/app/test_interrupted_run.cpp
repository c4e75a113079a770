/// A run killed in the middle of its load steps loses nothing (issue: "Interrupted runs lose nothing"):
/// every file named by results.pvd exists and is a complete VTU, every finished step's contact CSV is
/// complete, and summary.json is a complete document. Files are written under a temporary name and
/// renamed (io/atomic_file.hpp), so a kill can only leave a stray temporary behind, which the next run
/// into the folder removes. SIGINT and SIGTERM are handled (core/interrupt.hpp): the run stops after the
/// file it is writing, marks summary.json "interrupted" and exits 130 / 143 with no temporary left.

#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "support/temp_folder.hpp"

extern char** environ;

namespace {

namespace fs = std::filesystem;

using symcontact::testing::read_text;
using symcontact::testing::TempFolder;

/// True when s, without trailing white space, ends with `tail`.
bool ends_with(const std::string& s, const std::string& tail) {
  const std::size_t end = s.find_last_not_of(" \n\r\t");
  if (end == std::string::npos || end + 1 < tail.size()) return false;
  return s.compare(end + 1 - tail.size(), tail.size(), tail) == 0;
}

/// Starts `symcontact run` on the V4 friction block (11 load steps of Coulomb friction, long enough to
/// be caught mid-run) into `out`, and waits until the third step's contact CSV is there. Returns the
/// process id, or 0 (after a test failure) when the run ended first or took too long.
pid_t start_friction_block_until_step_3(const fs::path& out) {
  const std::string example = std::string(SYMCONTACT_EXAMPLES) + "/friction_block/block.toml";
  const std::string cli = SYMCONTACT_CLI;
  const std::string out_s = out.string();
  std::vector<char*> argv = {const_cast<char*>(cli.c_str()), const_cast<char*>("run"),
                             const_cast<char*>(example.c_str()), const_cast<char*>("--out"),
                             const_cast<char*>(out_s.c_str()), const_cast<char*>("-q"), nullptr};
  pid_t pid = 0;
  EXPECT_EQ(posix_spawn(&pid, cli.c_str(), nullptr, nullptr, argv.data(), environ), 0);
  if (pid == 0) return 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (std::chrono::steady_clock::now() < deadline) {
    if (fs::exists(out / "contact_floor_0003.csv")) return pid;
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid) {
      ADD_FAILURE() << "the run ended before it could be interrupted";
      return 0;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ADD_FAILURE() << "no third step within the deadline";
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  return 0;
}

/// Starts the friction block into `out` (start_friction_block_until_step_3()), sends it `signal` and waits
/// for it: its wait status, or nothing (after a test failure) when it could not be started or signalled.
std::optional<int> interrupted_status(const fs::path& out, int signal) {
  const pid_t pid = start_friction_block_until_step_3(out);
  if (pid == 0) return std::nullopt;
  if (kill(pid, signal) != 0) {
    ADD_FAILURE() << "cannot send signal " << signal;
    return std::nullopt;
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

/// The names of the files in `dir` holding ".tmp-" (temporaries of io/atomic_file.hpp).
std::vector<std::string> temporaries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().find(".tmp-") != std::string::npos) names.push_back(e.path().filename().string());
  return names;
}

/// Interrupts the friction block with `signal` after its third step: the run must exit 128 + signal,
/// mark summary.json "interrupted" with its finished steps, name complete files only, and leave no
/// temporary file.
void expect_clean_stop(int signal, const std::string& signal_name) {
  const TempFolder folder("symcontact_signal_");
  const fs::path& dir = folder.path();
  const fs::path out = dir / "out";
  const std::optional<int> stopped = interrupted_status(out, signal);
  ASSERT_TRUE(stopped.has_value());
  const int status = *stopped;
  ASSERT_TRUE(WIFEXITED(status)) << "the signal was not handled";
  EXPECT_EQ(WEXITSTATUS(status), 128 + signal);
  const std::string summary = read_text(out / "summary.json");
  EXPECT_TRUE(ends_with(summary, "}")) << summary;
  EXPECT_NE(summary.find("\"status\": \"interrupted\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("interrupted by " + signal_name), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"step\": 3"), std::string::npos) << summary;
  EXPECT_TRUE(ends_with(read_text(out / "results.pvd"), "</VTKFile>"));
  EXPECT_TRUE(temporaries(out).empty()) << temporaries(out).front();
}

}  // namespace

TEST(InterruptedRun, SigtermStopsCleanlyWithExit143) { expect_clean_stop(SIGTERM, "SIGTERM"); }

TEST(InterruptedRun, SigintStopsCleanlyWithExit130) { expect_clean_stop(SIGINT, "SIGINT"); }

TEST(InterruptedRun, TemporariesOfAKilledRunAreRemovedByTheNextRun) {
  const TempFolder folder("symcontact_stale_");
  const fs::path& dir = folder.path();
  const fs::path out = dir / "out";
  fs::create_directories(out);
  // A process that has ended: its id names the temporaries of a "killed" run.
  pid_t dead = 0;
  char* true_argv[] = {const_cast<char*>("/bin/true"), nullptr};
  ASSERT_EQ(posix_spawn(&dead, "/bin/true", nullptr, nullptr, true_argv, environ), 0);
  waitpid(dead, nullptr, 0);
  const std::string stale = "summary.json.tmp-" + std::to_string(dead);
  std::ofstream(out / stale) << "{ \"status\": ";
  std::ofstream(out / "notes.tmp-draft") << "not ours";  // not a process id: kept
  const std::string example = std::string(SYMCONTACT_EXAMPLES) + "/block_2d/block.toml";
  const std::string command = "'" + std::string(SYMCONTACT_CLI) + "' run '" + example + "' --out '" + out.string() +
                              "' -q";
  ASSERT_EQ(std::system(command.c_str()), 0);
  EXPECT_FALSE(fs::exists(out / stale));
  EXPECT_TRUE(fs::exists(out / "notes.tmp-draft"));
  EXPECT_TRUE(fs::is_regular_file(out / "summary.json"));
}

TEST(InterruptedRun, KilledMidRunLeavesEveryFinishedStepValid) {
  const TempFolder folder("symcontact_killed_");
  const fs::path& dir = folder.path();
  const fs::path out = dir / "out";
  const std::optional<int> killed = interrupted_status(out, SIGKILL);
  ASSERT_TRUE(killed.has_value());
  ASSERT_TRUE(WIFSIGNALED(*killed));

  // The collection names only complete files.
  const std::string pvd = read_text(out / "results.pvd");
  ASSERT_TRUE(ends_with(pvd, "</VTKFile>")) << pvd;
  const std::regex file_attr("file=\"([^\"]+)\"");
  int listed = 0;
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), file_attr); it != std::sregex_iterator(); ++it) {
    const fs::path vtu = out / (*it)[1].str();
    ASSERT_TRUE(fs::exists(vtu)) << vtu;
    EXPECT_TRUE(ends_with(read_text(vtu), "</VTKFile>")) << vtu;
    ++listed;
  }
  EXPECT_GE(listed, 2);
  // Each contact CSV present has one row per surface node after its header (33 nodes, see block.geo).
  for (const auto& e : fs::directory_iterator(out)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("contact_floor_", 0) != 0 || e.path().extension() != ".csv") continue;
    const std::string csv = read_text(e.path());
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 33) << name;
  }
  // The summary is a complete document, still marked running, with the finished steps.
  const std::string summary = read_text(out / "summary.json");
  EXPECT_TRUE(ends_with(summary, "}")) << summary;
  EXPECT_NE(summary.find("\"status\": \"running\""), std::string::npos);
  EXPECT_NE(summary.find("\"step\": 2"), std::string::npos);
}
