/// \file problem_reader_ipopt.cpp
/// The part of problem_reader.hpp that asks IPOPT (the [ipopt] section's check), apart from the rest so that
/// a program that must not load IPOPT (the distributed run, src/CMakeLists.txt) links the reader without it.

#include "symcontact/core/error.hpp"
#include "symcontact/model/problem_reader.hpp"
#include "symcontact/optim/ipopt_solver.hpp"

namespace symcontact {

void check_ipopt_section(const ProblemSpec& spec) {
  try {
    check_ipopt_options(spec.contact_solver.friction.contact.ipopt);
  } catch (const IpoptOptionError& e) {
    throw InputError(spec.file, "ipopt." + e.name(), e.what());
  }
}

ProblemSpec read_problem_file(const std::string& path) {
  ProblemSpec spec = parse_problem(read_problem_text(path), path, problem_folder(path));
  check_ipopt_section(spec);
  return spec;
}

}  // namespace symcontact
