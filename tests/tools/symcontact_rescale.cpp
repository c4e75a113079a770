// symcontact-rescale: writes a problem file and its meshes in another consistent system of units
// (tests/support/rescale_problem.hpp), to check that a result does not depend on the units.
//   symcontact-rescale CASE.toml OUT_DIR --length L [--force F]
// m–N–Pa to mm–N–MPa: --length 1e3 --force 1. With --length 1 --force 1: the reference, on the same mesh.
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "support/rescale_problem.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Rewrites a symcontact problem and its meshes into other units"};
  std::string problem, out;
  symcontact::testing::UnitChange change;
  app.add_option("problem", problem, "the problem file")->required()->check(CLI::ExistingFile);
  app.add_option("out", out, "the folder to write problem.toml and the meshes into")->required();
  app.add_option("--length", change.length, "new length unit per old one (m to mm: 1e3)")->check(CLI::PositiveNumber);
  app.add_option("--force", change.force, "new force unit per old one")->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);
  try {
    std::cout << symcontact::testing::rescale_problem(problem, change, out) << "\n";
  } catch (const std::exception& e) {
    std::cerr << "symcontact-rescale: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
