/// \file fuzz_problem_reader.cpp
/// libFuzzer target: bytes → parse_problem() and check_ipopt_section() (model/problem_reader.hpp), the
/// code path of read_problem_file() without the file. The contract under test: whatever the text, the reader
/// returns a ProblemSpec or throws InputError; any other exception, a crash or a sanitiser report is
/// a bug. Mesh paths resolve against a scratch folder holding empty files with the names the seed
/// corpus uses (the reader only checks that they exist), so that inputs get past the mesh keys.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "symcontact/core/error.hpp"
#include "symcontact/model/problem_reader.hpp"

namespace {

std::string& base_dir() {
  static std::string dir;
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("symcontact_fuzz_problem_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (const char* name : {"block.geo", "block.msh", "cylinder_on_plane.geo", "two_cylinders.geo", "inclined.geo",
                           "rings.geo", "floor.msh", "mesh.msh", "upper.geo", "lower.geo"}) {
    std::ofstream(dir / name) << "// placeholder\n";
  }
  base_dir() = dir.string();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const symcontact::ProblemSpec spec = symcontact::parse_problem(text, "fuzz.toml", base_dir());
    symcontact::check_ipopt_section(spec);  // the rest of read_problem_file()'s checks
  } catch (const symcontact::InputError&) {
    // the expected outcome for bad input
  }
  return 0;
}
