/// symcontact-bench-distributed — the clamped elastic block (src/symcontact/distributed/block_system.hpp)
/// solved by CG + GAMG on PETSc (gamg_elasticity.hpp), one row per size: DOFs, CG iterations, multigrid
/// levels, times of assembly (each rank its own cells), setup (matrix, near null space, hierarchy) and
/// solve, and rank 0's peak RSS.
///   symcontact-bench-distributed --dim 3 --divisions 20 32 48 70
///   mpiexec -n 2 symcontact-bench-distributed --dim 3 --divisions 70
/// A program of its own: the distributed path never shares a process with IPOPT's sequential MUMPS
/// (src/CMakeLists.txt), so the Cholesky floor of the same block comes from `symcontact-bench --case
/// elasticity`, which builds the same mesh (docs/performance.md).

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "symcontact/distributed/block_system.hpp"
#include "symcontact/distributed/gamg_elasticity.hpp"

namespace {

/// VmHWM of /proc/self/status in MiB (−1 when absent).
double peak_rss_mib() {
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return -1.0;
}

}  // namespace

int main(int argc, char** argv) {
  symcontact::PetscSession petsc(&argc, &argv);
  CLI::App app{"symcontact-bench-distributed — the elastic block by CG + GAMG on PETSc", "symcontact-bench-distributed"};
  int dim = 3;
  std::vector<int> divisions{20, 32};
  double rtol = 1e-10;
  app.add_option("--dim", dim, "2 or 3")->check(CLI::IsMember({2, 3}));
  app.add_option("--divisions", divisions, "divisions per side, one row each");
  app.add_option("--rtol", rtol, "relative residual of the solve");
  app.allow_extras();  // PETSc's own options (-ksp_monitor, ...) pass through
  CLI11_PARSE(app, argc, argv);
  const bool root = petsc.rank() == 0;
  if (root)
    std::printf("# ranks %d; CG + GAMG, rtol %g\n%9s %10s %6s %6s %12s %10s %10s %12s\n", petsc.size(), rtol, "divisions",
                "DOFs", "CG it", "levels", "assembly [s]", "setup [s]", "solve [s]", "peak RSS [MiB]");
  for (const int n : divisions) {
    const auto t0 = std::chrono::steady_clock::now();
    const symcontact::BlockSystem s = symcontact::clamped_block_system(dim, n, petsc.rank(), petsc.size());
    const double assembly = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    symcontact::GamgOptions options;
    options.relative_tolerance = rtol;
    const symcontact::GamgResult r =
        symcontact::solve_elasticity_gamg(s.K_lower, s.f, s.fixed, s.fixed_values, s.mesh.x, options);
    if (root)
      std::printf("%9d %10lld %6d %6d %12.2f %10.2f %10.2f %12.0f%s\n", n, static_cast<long long>(s.f.size()),
                  r.iterations, r.levels, assembly, r.setup_seconds, r.solve_seconds, peak_rss_mib(),
                  r.converged ? "" : ("  not converged: " + r.reason).c_str());
  }
  return 0;
}
