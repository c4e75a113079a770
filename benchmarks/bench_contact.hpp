#pragma once
/// \file bench_contact.hpp
/// The contact part of symcontact-bench (--case hertz2d | hertz2d-cylinders): the Hertz 2D cases of
/// hertz_2d.hpp at a list of fine mesh sizes h, one row per size: DOFs, free DOFs, contact constraints,
/// geometry and IPOPT iterations, time per phase, peak RSS, accuracy against the closed form, and the
/// ratio of the contact solve to one Cholesky factor-and-solve of the same stiffness.

#include <string>
#include <vector>

#include "bench_support.hpp"
#include "hertz_2d.hpp"

namespace symcontact::bench {

struct ContactBenchOptions {
  HertzCase which = HertzCase::kCylinderOnPlane;
  std::vector<double> h;       ///< fine mesh sizes, one row each (in the order given)
  int repeat = 1;              ///< floor phases: minimum over this many runs (the contact solve runs once)
  std::string examples_dir;    ///< examples/ of the source tree
  std::string csv;
  bool markdown = false;
  bool keep_work = false;      ///< keep the temporary directory with the wrapper .geo and .toml
  bool condense = true;        ///< static condensation (--no-condense: IPOPT on the whole problem)
};

/// The default ladder of h: about 1e4 to 2e5 DOFs for the cylinder on the plane.
std::vector<double> default_hertz_sizes();

/// Runs the sweep, printing the table as rows finish. Throws what solve_hertz() throws.
void run_hertz_sweep(const ContactBenchOptions& opt, const MachineInfo& machine);

}  // namespace symcontact::bench
