/// A run killed in the middle of its load steps loses nothing (issue: "Interrupted runs lose nothing"):
/// every file named by results.pvd exists and is a complete VTU, every finished step's contact CSV is
/// complete, and summary.json is a complete document. Files are written under a temporary name and
/// renamed (io/atomic_file.hpp), so a kill can only leave a stray temporary behind.

#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <thread>

extern char** environ;

namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// True when s, without trailing white space, ends with `tail`.
bool ends_with(const std::string& s, const std::string& tail) {
  const std::size_t end = s.find_last_not_of(" \n\r\t");
  if (end == std::string::npos || end + 1 < tail.size()) return false;
  return s.compare(end + 1 - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

TEST(InterruptedRun, KilledMidRunLeavesEveryFinishedStepValid) {
  const fs::path dir = fs::temp_directory_path() / ("symcontact_killed_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path out = dir / "out";
  // The V4 friction block: 11 load steps of Coulomb friction, long enough to be caught mid-run.
  const std::string example = std::string(SYMCONTACT_EXAMPLES) + "/friction_block/block.toml";
  const std::string cli = SYMCONTACT_CLI;
  const std::string out_s = out.string();
  std::vector<char*> argv = {const_cast<char*>(cli.c_str()), const_cast<char*>("run"),
                             const_cast<char*>(example.c_str()), const_cast<char*>("--out"),
                             const_cast<char*>(out_s.c_str()), const_cast<char*>("-q"), nullptr};
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, cli.c_str(), nullptr, nullptr, argv.data(), environ), 0);
  // Kill it as soon as the third step's results are there (and before the run can end).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  bool caught = false;
  while (std::chrono::steady_clock::now() < deadline) {
    if (fs::exists(out / "contact_floor_0003.csv")) {
      caught = true;
      break;
    }
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid) FAIL() << "the run ended before it could be interrupted";
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_TRUE(caught) << "no third step within the deadline";
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));

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
  fs::remove_all(dir);
}
