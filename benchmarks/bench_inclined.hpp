#pragma once
/// \file bench_inclined.hpp
/// The frictional part of symcontact-bench (--case inclined): the inclined interface with Coulomb
/// friction μ = 0.2 (inclined_2d.hpp) at a list of element sizes h, one row per size: DOFs, load steps,
/// Coulomb, geometry and IPOPT iterations (summed over the steps), time per phase, peak RSS, the reaction
/// ratio against its exact gross-slip value, and the ratio of the whole load path to one Cholesky
/// factor-and-solve of the same stiffness.

#include <string>
#include <vector>

#include "bench_support.hpp"

namespace symcontact::bench {

struct InclinedBenchOptions {
  std::vector<double> h;       ///< element sizes of the lower body, one row each (in the order given)
  int repeat = 1;              ///< floor phases: minimum over this many runs (the contact solves run once)
  std::string examples_dir;    ///< examples/ of the source tree
  std::string csv;
  bool markdown = false;
  bool keep_work = false;      ///< keep the temporary directory with the wrapper .geo and .toml
};

/// The default ladder of h: about 5.6e3, 2.2e4, 8.4e4 and 3.3e5 DOFs.
std::vector<double> default_inclined_sizes();

/// Runs the sweep, printing the table as rows finish. Throws what solve_inclined() throws.
void run_inclined_sweep(const InclinedBenchOptions& opt, const MachineInfo& machine);

}  // namespace symcontact::bench
