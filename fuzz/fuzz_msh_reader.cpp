/// \file fuzz_msh_reader.cpp
/// libFuzzer target: bytes → a temporary `.msh` file → read_mesh_file() (mesh/gmsh_io.hpp), then
/// extract_body() for every body group and for the whole mesh, and extract_surface() for every
/// facet group, once as a 2D and once as a 3D problem. The contract under test: a
/// malformed file is an InputError naming the file; any other exception, a crash, a hang or a
/// sanitiser report (in our code or in Gmsh's parser, which the pre-validation of
/// mesh/msh_validation.hpp must keep from seeing bad structure) is a bug.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "symcontact/core/error.hpp"
#include "symcontact/mesh/gmsh_io.hpp"

namespace {

std::string& msh_path() {
  static std::string path;
  return path;
}

void extract_all(const symcontact::MeshFile& f, int dim) {
  using symcontact::InputError;
  try {
    symcontact::extract_body(f, dim, "", "body[0].group");
  } catch (const InputError&) {
  }
  for (const auto& g : f.groups) {
    try {
      if (g.dim == dim) symcontact::extract_body(f, dim, g.name, "body[0].group");
      if (g.dim == dim - 1) symcontact::extract_surface(f, dim, g.name, "contact[0].obstacle.boundary");
    } catch (const InputError&) {
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("symcontact_fuzz_msh_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  msh_path() = (dir / "fuzz.msh").string();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  {
    std::ofstream out(msh_path(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  // As a 2D and as a 3D problem would read it (the dimension selects the cells and the groups).
  for (int d : {2, 3}) {
    symcontact::MeshReadOptions opt;
    opt.dim = d;
    try {
      const symcontact::MeshFile f = symcontact::read_mesh_file(msh_path(), opt);
      extract_all(f, d);
    } catch (const symcontact::InputError&) {
      // the expected outcome for bad input
    }
  }
  return 0;
}
