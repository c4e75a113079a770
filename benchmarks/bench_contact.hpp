#pragma once
/// \file bench_contact.hpp
/// The contact part of symcontact-bench (--case hertz2d | hertz2d-cylinders | hertz3d | hertz3d-spheres): the
/// Hertz cases of hertz.hpp at a list of fine mesh sizes h, one row per size: DOFs, free DOFs, contact
/// constraints, condensed DOFs, geometry and IPOPT iterations, time per phase, contact search time per
/// geometry iteration against the size of the contact surfaces, peak RSS, accuracy against the closed form,
/// and the ratio of the contact solve to one Cholesky factor-and-solve of the same stiffness. The sweep ends
/// with the fitted exponent of the search time in the number of surface facets (O(n log n) expected).

#include <string>
#include <vector>

#include "bench_support.hpp"
#include "hertz.hpp"

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
  SubproblemSolver dual = SubproblemSolver::kDualInteriorPoint;  ///< --no-dual: IPOPT on the condensed DOFs; --dual-ipopt: IPOPT on the dual
  double search_distance = 0;  ///< > 0: the contact pair's search_distance (default: the example's, automatic)
  bool check_only = false;     ///< mesh each size and check that it fits (check_hertz_fits), solve none
};

/// The default ladder of h of each case:
///  - hertz2d: 0.003, 0.0015, 0.00085, 0.0006, 0.0004, 0.00027: 9.8e3, 3.5e4, 1.0e5, 2.0e5, 4.5e5, 9.7e5 DOFs;
///  - hertz2d-cylinders: the same without the last, about 2e4 … 9e5 DOFs (two bodies);
///  - hertz3d: 0.04, 0.02, 0.01, 0.007, 0.005: 1.3e3, 4.4e3, 2.3e4, 5.9e4, 1.5e5 DOFs; with `large`
///    (--large) instead 0.0045, 0.0035, 0.0028, 0.0025: 2.0e5, 4.1e5, 7.8e5, 1.1e6 DOFs (hours on two
///    cores). Each size is checked against the memory
///    available before it is solved (check_hertz_fits()) and the sweep stops at the first that does not
///    fit: on 23.5 GiB, 1.1e6 never does (18.2 GiB of factor alone), 7.8e5 only on an idle machine;
///  - hertz3d-spheres: 0.04, 0.02, 0.014 (two bodies).
std::vector<double> default_hertz_sizes(HertzCase which, bool large = false);

/// Runs the sweep, printing the table as rows finish. Throws what solve_hertz() throws.
void run_hertz_sweep(const ContactBenchOptions& opt, const MachineInfo& machine);

}  // namespace symcontact::bench
