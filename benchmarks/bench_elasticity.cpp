/// \file bench_elasticity.cpp
/// symcontact-bench: how long the elastic building blocks take as the mesh grows.
///
/// Solves a clamped linear-elastic unit square (plane strain) and unit cube under a pressure on the
/// top face (elastic_block.hpp) on structured simplex meshes of about 1e4, 3e4, 1e5, 3e5, 1e6 DOFs,
/// and prints one row per mesh: DOFs, free DOFs, nnz(K_ff), the time of one energy gradient, of the
/// stiffness assembly (element kernels into a ReducedTripletSink, then the sparse matrix), of the
/// CHOLMOD analysis, factorisation and solve, nnz(L), the peak RSS and the relative residual
/// ‖K_ff u − f‖/‖f‖ (≈ 1e-15 expected). The machine and BLAS are printed first. Results and their
/// reading are in docs/performance.md.
///
///   OPENBLAS_NUM_THREADS=1 symcontact-bench --dim all --order 1 --repeat 1 --csv results.csv
///
/// Options: --dim 2|3|all (all), --order 1|2 (1), --min-dofs N (1e4), --max-dofs N (1.1e6 in 2D,
/// 3.1e5 in 3D), --dofs N... (explicit sizes instead of the ladder), --repeat R (1; each time is the minimum over R runs), --csv FILE, --markdown.
///
/// --case selects the benchmark: `elasticity` (the default, above), or the contact benchmarks
/// `hertz2d` (cylinder on a rigid plane), `hertz2d-cylinders` (two elastic cylinders), `hertz3d` (quarter
/// sphere on a rigid plane, P1 Tet4) and `hertz3d-spheres` (two elastic quarter spheres), which solve the
/// Hertz examples (examples/hertz_2d, examples/hertz_3d) at the fine mesh sizes --h (defaults: hertz2d
/// 0.003 0.0015 0.00085 0.0006 0.0004 0.00027, about 1e4 to 1e6 DOFs; hertz2d-cylinders the same without
/// the last; hertz3d 0.04 0.02 0.01 0.007 0.005, about 1e3 to 1.5e5 DOFs; hertz3d-spheres 0.04 0.02
/// 0.014) and compare the contact solve with one Cholesky factor-and-solve of the same stiffness; they
/// also time the contact search against the size of the contact surfaces and print its fitted exponent
/// (bench_contact.hpp):
///
///   OPENBLAS_NUM_THREADS=1 symcontact-bench --case hertz2d --h 0.004 0.002 --csv hertz.csv
///   OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 symcontact-bench --case hertz3d --h 0.04 0.02 0.01 --csv h3d.csv
///
/// `inclined` solves the inclined interface with Coulomb friction mu = 0.2 (examples/inclined_2d,
/// docs/validation-friction.md V5; ten load steps, each a Coulomb fixed point) at the element sizes --h (default
/// 0.025 0.0125 0.00625 0.003125 0.0015625: 5.6e3 to 1.3e6 DOFs) against the same floor (bench_inclined.hpp):
///
///   OPENBLAS_NUM_THREADS=1 symcontact-bench --case inclined --h 0.05 0.025
///
/// `pad-flat`, `pad-ball`, `clamped-plates` and their 2D analogues `pad-flat-2d`, `pad-ball-2d`,
/// `clamped-plates-2d` have a contact zone that is a whole face: a pad pressed onto a rigid plane, resp. a
/// rigid sphere, and dragged; two plates with a hole pressed together by their washers and sheared; all
/// with Coulomb friction μ = 0.3 over 4 to 6 load steps (large_contact.hpp; --frictionless: without), at the
/// element sizes --h (default: sizes that each take a couple of minutes at most, 1e4 to 3e5 DOFs in 2D, 1e3
/// to 8e3 in 3D; --large the larger sizes), against the same floor:
///
///   OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 symcontact-bench --case pad-flat --csv pad-flat.csv
///
/// `hertz2d-freefem` solves the peers' Hertz quarter model (../shared/peers, hertz_quarter.geo) on the same
/// .msh with symcontact and with FreeFEM + ff-Ipopt, side by side, at the sizes --h (default 0.005
/// 0.0025 0.00125), against the same floor (freefem_peer.hpp); without FreeFEM the FreeFEM columns are skipped:
///
///   OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 symcontact-bench --case hertz2d-freefem --csv ff.csv
///
/// `problem` solves any problem files --problem FILE... as `symcontact run` does, one row each, with
/// the per-step figures in --steps-csv FILE (bench_problem.hpp); e.g. the 110-step ironing:
///
///   symcontact-bench --case problem --problem examples/ironing_2d/ironing.toml --steps-csv steps.csv
///
/// `suite` runs, in ONE run, every contact case at its default sizes, one after the other: hertz2d,
/// hertz2d-cylinders, inclined, hertz3d, hertz2d-freefem (which skips FreeFEM with a message when it is
/// absent), pad-flat-2d, pad-ball-2d, clamped-plates-2d, pad-flat, pad-ball and clamped-plates, printing
/// each table as it goes; --csv PREFIX writes one file PREFIX<case>.csv per case
/// (e.g. results/suite-hertz3d.csv for --csv results/suite-). A case that fails is reported and the suite
/// goes on (the exit code says so); --h is refused. At the default sizes it goes to about 1e6 DOFs in 2D,
/// so the largest sizes dominate its run time:
///
///   OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 symcontact-bench --case suite --csv results/suite-
///
/// `--case hertz3d --large` is the large 3D sweep instead of the default ladder: h = 0.0045 0.0035 0.0028
/// 0.0025, 2.0e5, 4.1e5, 7.8e5 and 1.1e6 DOFs (hours on 2 cores; memory: docs/performance.md and
/// check_hertz_fits()). Before each size is
/// solved, CHOLMOD's analysis predicts its factor, and the sweep stops at the first size that would not fit
/// in the memory available (check_hertz_fits(), hertz.hpp); --check-only does only that (meshing and
/// CHOLMOD's analysis, minutes), for every size, and solves none:
///
///   OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 symcontact-bench --case hertz3d --large --csv h3d-large.csv
///   symcontact-bench --case hertz3d --large --check-only
///
/// Contact options: --h H... , --examples DIR (the source tree's examples/), --keep-work, --no-condense
/// (Hertz cases: IPOPT on the whole problem instead of the condensed one), --search-distance D (Hertz
/// cases: the pair's search distance instead of the automatic one), and --repeat,
/// --csv, --markdown as above (--repeat applies to the floor only; the contact solve runs once).

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <ctime>
#include <exception>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_contact.hpp"
#include "bench_inclined.hpp"
#include "bench_problem.hpp"
#include "bench_support.hpp"
#include "elastic_block.hpp"
#include "freefem_peer.hpp"
#include "large_contact.hpp"
#include "symcontact/core/blas_kernels.hpp"
#include "symcontact/core/blas_threads.hpp"
#include "symcontact/core/error.hpp"
#include "symcontact/mesh/cell_type.hpp"

namespace {

using symcontact::Index;
using symcontact::SubproblemSolver;
using namespace symcontact::bench;
using Kind = ResultTable::Kind;

constexpr double kDefaultMaxDofs2d = 1.1e6;
/// The factor of the 3D P1 stiffness grows faster than the DOFs (docs/performance.md: about 4 GiB at 3e5 DOFs,
/// 16 GiB at 1e6 through CHOLMOD's 64-bit interface, cholmod_long.hpp), so the ladder stops at 3e5 by
/// default (--dofs for more; a size whose factor does not fit is refused).
constexpr double kDefaultMaxDofs3d = 3.1e5;

std::vector<ResultTable::Column> columns() {
  return {
      {"dim", "", Kind::kInteger, 0},
      {"order", "", Kind::kInteger, 0},
      {"cell_type", "", Kind::kText, 0},
      {"divisions", "n", Kind::kInteger, 0},
      {"cells", "", Kind::kInteger, 0},
      {"dofs", "DOFs", Kind::kInteger, 0},
      {"free_dofs", "free", Kind::kInteger, 0},
      {"nnz_kff", "nnz(K_ff)", Kind::kInteger, 0},
      {"nnz_kff_lower", "", Kind::kInteger, 0},
      {"triplets", "", Kind::kInteger, 0},
      {"mesh_s", "", Kind::kFixed, 3},
      {"setup_s", "", Kind::kFixed, 3},
      {"gradient_s", "grad [s]", Kind::kFixed, 3},
      {"assembly_s", "assembly [s]", Kind::kFixed, 3},
      {"analyze_s", "analyze [s]", Kind::kFixed, 3},
      {"factorize_s", "factor [s]", Kind::kFixed, 3},
      {"solve_s", "solve [s]", Kind::kFixed, 3},
      {"nnz_l", "nnz(L)", Kind::kInteger, 0},
      {"fill", "fill", Kind::kFixed, 1},
      {"peak_rss_mib", "peak RSS [MiB]", Kind::kInteger, 0},
      {"rss_after_mib", "", Kind::kInteger, 0},
      {"relative_residual", "rel. residual", Kind::kScientific, 1},
      {"max_displacement", "", Kind::kScientific, 3},
      {"repeat", "", Kind::kInteger, 0},
      {"openblas_threads", "", Kind::kInteger, 0},
  };
}

struct Options {
  std::string bench_case = "elasticity";
  std::vector<double> h;           ///< contact: fine mesh sizes (the case's default ladder when empty)
  std::string examples = SYMCONTACT_BENCH_EXAMPLES;
  bool keep_work = false;
  bool no_condense = false;
  bool no_dual = false;
  bool dual_ipopt = false;
  bool large = false;            ///< hertz3d and the large-contact cases: the large sweep
  bool check_only = false;       ///< Hertz cases: mesh and check the memory of each size, solve none
  bool frictionless = false;     ///< large-contact cases: no friction, to compare
  std::string subproblem_solver; ///< large-contact cases: [contact_solver] subproblem_solver; empty: the default
  std::string coulomb_update;    ///< large-contact cases: [contact_solver] coulomb_update; empty: the default
  std::string warm_start;        ///< large-contact cases: [contact_solver] warm_start; empty: the default
  double search_distance = 0.0;  ///< Hertz cases: > 0 overrides the example's (automatic) search distance
  std::vector<std::string> problems;  ///< --case problem
  std::string steps_csv;
  std::string dim = "all";
  int order = 1;
  double min_dofs = 1e4;
  double max_dofs = 0.0;  ///< 0: the default of the dimension
  std::vector<double> dofs;  ///< explicit sizes (replace the ladder)
  int repeat = 1;
  std::string csv;
  bool markdown = false;
  std::string freefem = "FreeFem++";  ///< --case hertz2d-freefem
  double freefem_tol = 1e-12;
  bool skip_freefem = false;
};

/// Runs the size ladder for one dimension; returns the wall time of the sweep.
double sweep(int dim, const Options& opt, const MachineInfo& machine, bool append_csv) {
  const double max_dofs = opt.max_dofs > 0 ? opt.max_dofs : (dim == 2 ? kDefaultMaxDofs2d : kDefaultMaxDofs3d);
  const auto cell = symcontact::cell_type_of(dim, opt.order);
  std::cout << "\n## " << dim << "D P" << opt.order << " (" << symcontact::cell_name(cell) << "), "
            << (dim == 2 ? "unit square, plane strain" : "unit cube")
            << ", bottom clamped, pressure on top; ";
  if (opt.dofs.empty())
    std::cout << "DOFs in [" << opt.min_dofs << ", " << max_dofs << "]";
  else
    std::cout << "explicit sizes";
  std::cout << ", min of " << opt.repeat << " run(s)\n\n";
  ResultTable table(columns(), std::cout, opt.markdown);
  if (!opt.csv.empty()) table.write_csv(opt.csv, append_csv);

  const auto t_sweep = std::chrono::steady_clock::now();
  bool rss_reset_ok = true;
  const std::vector<double> sizes = opt.dofs.empty() ? size_ladder(opt.min_dofs, max_dofs) : opt.dofs;
  for (const double target : sizes) {
    rss_reset_ok = reset_peak_rss() && rss_reset_ok;
    const int n = block_divisions(dim, opt.order, target);
    ElasticBlock block(dim, opt.order, n);
    CholeskyFloor r;
    try {
      r = measure_cholesky_floor(block, opt.repeat);
    } catch (const FactorTooLarge& e) {
      std::cout << "# stopped at " << block.dofs.num_dofs() << " DOFs: " << e.what() << "\n";
      break;
    }
    const double peak = peak_rss_mib();
    table.add_row({static_cast<double>(dim), static_cast<double>(opt.order), symcontact::cell_name(cell),
                   static_cast<double>(n), static_cast<double>(block.mesh.num_cells()),
                   static_cast<double>(block.dofs.num_dofs()), static_cast<double>(block.num_free),
                   static_cast<double>(r.nnz_full), static_cast<double>(r.nnz_lower),
                   static_cast<double>(r.num_triplets), block.mesh_seconds, block.setup_seconds, r.gradient,
                   r.assembly, r.analyze, r.factorize, r.solve, r.nnz_factor,
                   r.nnz_factor / static_cast<double>(r.nnz_lower), peak, current_rss_mib(),
                   r.relative_residual, r.max_displacement, static_cast<double>(opt.repeat),
                   static_cast<double>(machine.openblas_threads)});
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_sweep).count();
  std::cout << "\n# " << dim << "D sweep: " << std::fixed << std::setprecision(1) << wall
            << std::defaultfloat << " s wall (meshing and setup included)\n";
  if (!rss_reset_ok)
    std::cout << "# note: /proc/self/clear_refs refused the peak-RSS reset: peak RSS is monotone over the run\n";
  else
    std::cout << "# peak RSS is per size (VmHWM reset through /proc/self/clear_refs before each size)\n";
  return wall;
}

/// The contact cases --case suite runs, in this order.
const std::vector<std::string> kSuiteCases = {"hertz2d",        "hertz2d-cylinders", "inclined",     "hertz3d",
                                              "hertz2d-freefem", "pad-flat-2d",       "pad-ball-2d",  "clamped-plates-2d",
                                              "pad-flat",        "pad-ball",          "clamped-plates"};

/// One contact benchmark (every --case but elasticity, problem and suite) at the sizes `h` (its default
/// ladder when empty), its table printed as rows finish and written to `csv` when not empty.
void run_contact_case(const std::string& name, const Options& opt, const std::vector<double>& h,
                      const std::string& csv, const MachineInfo& machine) {
  // The options every contact sweep has.
  auto common = [&](auto& c, const std::vector<double>& default_h) {
    c.h = h.empty() ? default_h : h;
    c.repeat = opt.repeat;
    c.csv = csv;
    c.markdown = opt.markdown;
    c.keep_work = opt.keep_work;
  };
  if (name == "hertz2d-freefem") {
    FreefemPeerOptions c;
    common(c, default_freefem_sizes());
    c.freefem = opt.freefem;
    c.freefem_tol = opt.freefem_tol;
    c.skip_freefem = opt.skip_freefem;
    run_freefem_sweep(c, machine);
    return;
  }
  if (const std::optional<LargeContactCase> which = large_contact_case(name)) {
    LargeContactBenchOptions c;
    common(c, default_large_contact_sizes(*which, opt.large));
    c.which = *which;
    c.friction = opt.frictionless ? LargeContactFriction::kNone : LargeContactFriction::kCoulomb;
    c.subproblem_solver = opt.subproblem_solver;
    c.coulomb_update = opt.coulomb_update;
    c.warm_start = opt.warm_start;
    c.condense = !opt.no_condense;
    run_large_contact_sweep(c, machine);
    return;
  }
  if (name == "inclined") {
    InclinedBenchOptions c;
    common(c, default_inclined_sizes());
    c.examples_dir = opt.examples;
    run_inclined_sweep(c, machine);
    return;
  }
  ContactBenchOptions c;
  if (name == "hertz2d")
    c.which = HertzCase::kCylinderOnPlane;
  else if (name == "hertz2d-cylinders")
    c.which = HertzCase::kTwoCylinders;
  else if (name == "hertz3d")
    c.which = HertzCase::kSphereOnPlane;
  else if (name == "hertz3d-spheres")
    c.which = HertzCase::kTwoSpheres;
  else
    throw std::logic_error("run_contact_case: unknown case " + name);
  common(c, default_hertz_sizes(c.which, opt.large));
  c.examples_dir = opt.examples;
  c.condense = !opt.no_condense;
  c.dual = opt.no_dual ? SubproblemSolver::kPrimalIpopt : opt.dual_ipopt ? SubproblemSolver::kDualIpopt : SubproblemSolver::kDualInteriorPoint;
  c.search_distance = opt.search_distance;
  c.check_only = opt.check_only;
  run_hertz_sweep(c, machine);
}

/// --case suite: every case of kSuiteCases at its default ladder, one after the other; with --csv PREFIX,
/// one file PREFIX<case>.csv each. A case that fails is reported and the suite goes on; the exit code is
/// that of the first failure (kExitOk when none).
int run_suite(const Options& opt, const MachineInfo& machine) {
  if (!opt.h.empty()) throw std::runtime_error("--case suite runs every case at its default sizes: --h is not allowed");
  if (opt.large) throw std::runtime_error("--case suite runs every case at its default sizes: --large is not allowed");
  if (!opt.csv.empty()) {  // --csv results/suite-: make results/
    const std::filesystem::path parent = std::filesystem::path(opt.csv).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
  }
  const auto t0 = std::chrono::steady_clock::now();
  int status = symcontact::kExitOk;
  std::vector<std::string> failed;
  for (const std::string& name : kSuiteCases) {
    std::cout << "\n# suite: " << name << "\n" << std::flush;
    const std::string csv = opt.csv.empty() ? std::string() : opt.csv + name + ".csv";
    try {
      run_contact_case(name, opt, {}, csv, machine);
    } catch (const symcontact::SolveError& e) {
      std::cout << "# suite: " << name << " FAILED (solve): " << e.what() << "\n";
      if (status == symcontact::kExitOk) status = symcontact::kExitSolveError;
      failed.push_back(name);
    } catch (const std::exception& e) {
      std::cout << "# suite: " << name << " FAILED: " << e.what() << "\n";
      if (status == symcontact::kExitOk) status = symcontact::kExitInternalError;
      failed.push_back(name);
    }
    std::cout << std::flush;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "\n# suite: " << kSuiteCases.size() - failed.size() << " of " << kSuiteCases.size()
            << " cases done in " << std::fixed << std::setprecision(1) << wall << std::defaultfloat << " s wall";
  for (const auto& f : failed) std::cout << (f == failed.front() ? "; failed: " : ", ") << f;
  std::cout << "\n";
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  symcontact::restart_with_better_blas_kernels(argv);  // as `symcontact` does: the kernels users get
  symcontact::apply_thread_setting(0);                  // as `symcontact run` without --threads
  Options opt;
  CLI::App app{"symcontact-bench — assembly and sparse Cholesky times of linear elasticity, 2D and 3D, and "
               "contact solves (Hertz 2D and 3D, inclined interface with friction) against that Cholesky floor",
               "symcontact-bench"};
  app.add_option("--case", opt.bench_case,
                 "elasticity (default), hertz2d, hertz2d-cylinders, hertz2d-freefem, hertz3d, hertz3d-spheres, "
                 "inclined, pad-flat, pad-ball, clamped-plates, pad-flat-2d, pad-ball-2d, clamped-plates-2d, problem, "
                 "or suite (every contact case at its default sizes: hertz2d, hertz2d-cylinders, inclined, hertz3d, "
                 "hertz2d-freefem, pad-flat-2d, pad-ball-2d, clamped-plates-2d, pad-flat, pad-ball, clamped-plates)")
      ->check(CLI::IsMember({"elasticity", "hertz2d", "hertz2d-cylinders", "hertz2d-freefem", "hertz3d",
                             "hertz3d-spheres", "inclined", "pad-flat", "pad-ball", "clamped-plates", "pad-flat-2d",
                             "pad-ball-2d", "clamped-plates-2d", "problem", "suite"}));
  app.add_option("--h", opt.h,
                 "Hertz cases: fine mesh sizes near the contact point (default hertz2d 0.003 0.0015 0.00085 0.0006 "
                 "0.0004 0.00027, hertz2d-cylinders the same without the last, hertz3d 0.04 0.02 0.01 0.007 0.005, "
                 "hertz3d-spheres 0.04 0.02 0.014); inclined: element sizes (default 0.025 0.0125 0.00625 0.003125 0.0015625); "
                 "hertz2d-freefem: sizes of the peers' mesh (default 0.005 0.0025 0.00125); pad-flat, pad-ball, "
                 "clamped-plates and their -2d analogues: element sizes (problem.mesh_size; defaults in "
                 "docs/performance.md)")
      ->check(CLI::PositiveNumber);
  app.add_option("--examples", opt.examples,
                 "contact: the examples/ folder holding hertz_2d/, hertz_3d/ and inclined_2d/")
      ->check(CLI::ExistingDirectory);
  app.add_option("--problem", opt.problems, "problem: the problem files to solve, one row each");
  app.add_option("--steps-csv", opt.steps_csv, "problem: write every step's time and iterations to this CSV file");
  app.add_flag("--keep-work", opt.keep_work, "contact: keep the temporary wrapper .geo and .toml");
  app.add_flag("--large", opt.large,
               "hertz3d: the large sweep h = 0.0045 0.0035 0.0028 0.0025 (2.0e5, 4.1e5, 7.8e5, 1.1e6 DOFs) instead of "
               "the default ladder: hours; a size that does not fit in memory stops the sweep (on 24 GiB, 1.1e6 "
               "does not: the floor's own factor is 22 GiB); pad-flat, pad-ball, clamped-plates and their -2d "
               "analogues: the sizes beyond the default ladder (docs/performance.md)");
  app.add_option("--subproblem-solver", opt.subproblem_solver,
                 "pad-flat, pad-ball, clamped-plates and their -2d analogues: [contact_solver] subproblem_solver of "
                 "the problems, to compare (default: the problem file's default)")
      ->check(CLI::IsMember({"dual_interior_point", "dual_ipopt", "primal_ipopt", "primal_interior_point"}));
  app.add_option("--coulomb-update", opt.coulomb_update,
                 "pad-flat, pad-ball, clamped-plates and their -2d analogues: [contact_solver] coulomb_update of the "
                 "problems, to compare (default: the problem file's default)")
      ->check(CLI::IsMember({"inside_optimizer", "between_solves"}));
  app.add_option("--warm-start", opt.warm_start,
                 "pad-flat, pad-ball, clamped-plates and their -2d analogues: [contact_solver] warm_start of the "
                 "problems, to compare (default: the problem file's default)")
      ->check(CLI::IsMember({"active_set", "interior_point"}));
  app.add_flag("--frictionless", opt.frictionless,
               "pad-flat, pad-ball, clamped-plates and their -2d analogues: the same problems without friction");
  app.add_flag("--check-only", opt.check_only,
               "Hertz cases: mesh each size and print its DOFs, predicted factor and whether it fits in memory; "
               "solve none");
  app.add_flag("--no-condense", opt.no_condense,
               "Hertz cases: no static condensation (IPOPT on the whole problem), to compare; pad-flat, pad-ball, "
               "clamped-plates and their -2d analogues: [contact_solver] static_condensation = false");
  app.add_flag("--no-dual", opt.no_dual,
               "Hertz cases: no dual solve (IPOPT on the condensed displacements, with the primal polish), to compare");
  app.add_flag("--dual-ipopt", opt.dual_ipopt,
               "Hertz cases: IPOPT on the dual instead of the dense interior point, to compare");
  app.add_option("--search-distance", opt.search_distance,
                 "Hertz cases: the contact pair's search_distance (default: the example's, i.e. automatic)")
      ->check(CLI::PositiveNumber);
  app.add_option("--dim", opt.dim, "2, 3 or all")->check(CLI::IsMember({"2", "3", "all"}));
  app.add_option("--order", opt.order, "polynomial order of the elements")->check(CLI::IsMember({1, 2}));
  app.add_option("--min-dofs", opt.min_dofs, "smallest size of the ladder 1e4, 3e4, 1e5, ... [DOFs]")
      ->check(CLI::PositiveNumber);
  app.add_option("--max-dofs", opt.max_dofs,
                 "largest size [DOFs] (default 1.1e6 in 2D, 3.1e5 in 3D)")
      ->check(CLI::PositiveNumber);
  app.add_option("--dofs", opt.dofs, "explicit sizes [DOFs] instead of the ladder (e.g. --dofs 6e5)")
      ->check(CLI::PositiveNumber);
  app.add_option("--repeat", opt.repeat, "runs per size; every time reported is the minimum")
      ->check(CLI::Range(1, 1000));
  app.add_option("--csv", opt.csv,
                 "also write the results (full precision, more columns) to this CSV file; suite: the prefix of "
                 "one file per case, PREFIX<case>.csv");
  app.add_flag("--markdown", opt.markdown, "print Markdown tables (for docs/performance.md)");
  app.add_option("--freefem", opt.freefem, "hertz2d-freefem: the FreeFEM executable (default FreeFem++ on PATH)");
  app.add_option("--freefem-tol", opt.freefem_tol, "hertz2d-freefem: IPOPT tol of the FreeFEM runs (default 1e-12)")
      ->check(CLI::PositiveNumber);
  app.add_flag("--skip-freefem", opt.skip_freefem, "hertz2d-freefem: symcontact and the floor only");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }

  std::cout << "# symcontact-bench (symcontact " << SYMCONTACT_VERSION << "):";
  for (int k = 0; k < argc; ++k) std::cout << " " << argv[k];
  const std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof(date), "%Y-%m-%d %H:%M:%S %Z", std::localtime(&now));
  std::cout << "\n# date: " << date << "\n";
  const MachineInfo machine = machine_info();
  print_machine_info(std::cout, machine);

  try {
    if (opt.bench_case == "problem") {
      ProblemBenchOptions c;
      c.files = opt.problems;
      c.repeat = opt.repeat;
      c.csv = opt.csv;
      c.steps_csv = opt.steps_csv;
      c.markdown = opt.markdown;
      if (c.files.empty()) throw std::runtime_error("--case problem needs --problem FILE...");
      run_problem_files(c, machine);
      return symcontact::kExitOk;
    }
    if (opt.bench_case == "suite") return run_suite(opt, machine);
    if (opt.bench_case != "elasticity") {
      run_contact_case(opt.bench_case, opt, opt.h, opt.csv, machine);
      return symcontact::kExitOk;
    }
    bool append = false;
    for (const int dim : {2, 3}) {
      if (opt.dim != "all" && opt.dim != std::to_string(dim)) continue;
      sweep(dim, opt, machine, append);
      append = true;
    }
  } catch (const symcontact::SolveError& e) {
    std::cerr << "symcontact-bench: solve failed: " << e.what() << "\n";
    return symcontact::kExitSolveError;
  } catch (const std::exception& e) {
    std::cerr << "symcontact-bench: " << e.what() << "\n";
    return symcontact::kExitInternalError;
  }
  return symcontact::kExitOk;
}
