#include "support/temp_folder.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iterator>

namespace symcontact::testing {

namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write_text(const fs::path& path, const std::string& text) {
  if (path.has_parent_path()) fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
  EXPECT_TRUE(out.good()) << "cannot write " << path;
}

TempFolder::TempFolder(const std::string& prefix) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = prefix;
  if (info != nullptr) name += std::string(info->test_suite_name()) + "_" + info->name() + "_";
  name += std::to_string(::getpid());
  std::replace(name.begin(), name.end(), '/', '_');  // parameterised tests: "Suite/Test.Case/3"
  path_ = fs::path(::testing::TempDir()) / name;
  fs::remove_all(path_);
  fs::create_directories(path_);
}

TempFolder::~TempFolder() {
  std::error_code ec;
  if (!::testing::Test::HasFailure()) fs::remove_all(path_, ec);
}

fs::path TempFolder::write(const std::string& name, const std::string& text) const {
  const fs::path p = path_ / name;
  write_text(p, text);
  return p;
}

}  // namespace symcontact::testing
