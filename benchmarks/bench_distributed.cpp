/// symcontact-bench-distributed — the distributed path on the model problems of
/// src/symcontact/distributed/model_problems.hpp, one row per size:
/// - `--problem elasticity`: the clamped block by CG + GAMG (gamg_elasticity.hpp): DOFs, CG iterations,
///   multigrid levels, times of assembly (each rank its own cells), setup and solve, rank 0's peak RSS;
/// - `--problem contact`: the block pressed onto a rigid ball by the interior point with Krylov Newton solves
///   (contact_interior_point.hpp): contact nodes and those in contact, interior-point iterations, CG
///   iterations per Newton system (smallest, largest, all), times, the largest contact force and peak RSS.
///   symcontact-bench-distributed --dim 3 --divisions 20 32 48 70
///   symcontact-bench-distributed --problem contact --dim 3 --divisions 16 24 32 [--preconditioner gamg]
///   mpiexec -n 2 symcontact-bench-distributed --dim 3 --divisions 70
/// A program of its own: the distributed path never shares a process with IPOPT's sequential MUMPS
/// (src/CMakeLists.txt), so the Cholesky floor of the same block comes from `symcontact-bench --case
/// elasticity`, which builds the same mesh (docs/performance.md).

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <string>
#include <vector>

#include "symcontact/distributed/model_problems.hpp"
#include "symcontact/distributed/contact_interior_point.hpp"
#include "symcontact/distributed/gamg_elasticity.hpp"

namespace {

using symcontact::PetscSession;

/// VmHWM of /proc/self/status in MiB (−1 when absent).
double peak_rss_mib() {
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return -1.0;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Settings {
  int dim = 3;
  std::vector<int> divisions{20, 32};
  double rtol = 1e-10;
  double radius = 1.0, depth = 0.02;
  symcontact::NewtonPreconditioner preconditioner = symcontact::NewtonPreconditioner::kFilteredGamg;
};

void elasticity_rows(const PetscSession& petsc, const Settings& s) {
  const bool root = petsc.rank() == 0;
  if (root)
    std::printf("# ranks %d; CG + GAMG, rtol %g\n%9s %10s %6s %6s %12s %10s %10s %12s\n", petsc.size(), s.rtol,
                "divisions", "DOFs", "CG it", "levels", "assembly [s]", "setup [s]", "solve [s]", "peak RSS [MiB]");
  for (const int n : s.divisions) {
    const auto t0 = std::chrono::steady_clock::now();
    const symcontact::BlockSystem b = symcontact::clamped_block_system(s.dim, n, petsc.rank(), petsc.size());
    const double assembly = seconds_since(t0);
    symcontact::GamgOptions options;
    options.relative_tolerance = s.rtol;
    const symcontact::GamgResult r =
        symcontact::solve_elasticity_gamg(b.K_lower, b.f, b.fixed, b.fixed_values, b.mesh.x, options);
    if (root)
      std::printf("%9d %10lld %6d %6d %12.2f %10.2f %10.2f %12.0f%s\n", n, static_cast<long long>(b.f.size()),
                  r.iterations, r.levels, assembly, r.setup_seconds, r.solve_seconds, peak_rss_mib(),
                  r.converged ? "" : ("  not converged: " + r.reason).c_str());
  }
}

void contact_rows(const PetscSession& petsc, const Settings& s) {
  const bool root = petsc.rank() == 0;
  const bool filtered = s.preconditioner == symcontact::NewtonPreconditioner::kFilteredGamg;
  if (root)
    std::printf("# ranks %d; block on a rigid ball (R %g, depth %g), interior point, CG + %s, tolerance %g\n"
                "%9s %10s %8s %8s %6s %11s %8s %10s %10s %10s %14s %12s\n",
                petsc.size(), s.radius, s.depth, filtered ? "GAMG with filtering" : "GAMG", s.rtol, "divisions",
                "DOFs", "contact", "active", "IP it", "CG min–max", "CG all", "setup [s]", "Krylov [s]", "total [s]",
                "max force", "peak RSS [MiB]");
  for (const int n : s.divisions) {
    const symcontact::ObstacleSystem o =
        symcontact::block_on_ball_system(s.dim, n, s.radius, s.depth, petsc.rank(), petsc.size());
    symcontact::ContactInteriorPointOptions options;
    options.tolerance = s.rtol;
    options.preconditioner = s.preconditioner;
    const symcontact::BlockSystem& b = o.block;
    const auto r = symcontact::solve_contact_interior_point(b.K_lower, b.f, b.fixed, b.fixed_values, b.mesh.x,
                                                            o.contact, options);
    const auto& its = r.krylov_iterations;
    const long active = std::count_if(r.lambda.begin(), r.lambda.end(),
                                      [&](double l) { return l > std::sqrt(s.rtol) * r.force_scale; });
    if (root)
      std::printf("%9d %10lld %8lld %8ld %6d %5d–%-5d %8d %10.2f %10.2f %10.2f %14.6e %12.0f%s\n", n,
                  static_cast<long long>(b.f.size()), static_cast<long long>(o.contact.size()), active, r.iterations,
                  its.empty() ? 0 : *std::min_element(its.begin(), its.end()),
                  its.empty() ? 0 : *std::max_element(its.begin(), its.end()),
                  std::accumulate(its.begin(), its.end(), 0), r.setup_seconds, r.krylov_seconds, r.total_seconds,
                  r.lambda.maxCoeff(), peak_rss_mib(), r.converged ? "" : ("  not converged: " + r.reason).c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  PetscSession petsc(&argc, &argv);
  CLI::App app{"symcontact-bench-distributed — the distributed path on PETSc", "symcontact-bench-distributed"};
  Settings s;
  std::string problem = "elasticity", preconditioner = "filtered";
  app.add_option("--problem", problem, "elasticity or contact")->check(CLI::IsMember({"elasticity", "contact"}));
  app.add_option("--dim", s.dim, "2 or 3")->check(CLI::IsMember({2, 3}));
  app.add_option("--divisions", s.divisions, "divisions per side, one row each");
  app.add_option("--rtol", s.rtol, "relative residual of the solve (elasticity), tolerance (contact)");
  app.add_option("--radius", s.radius, "contact: the ball's radius");
  app.add_option("--depth", s.depth, "contact: how far the block's top is moved down");
  app.add_option("--preconditioner", preconditioner, "contact: filtered (GAMG with filtering) or gamg")
      ->check(CLI::IsMember({"filtered", "gamg"}));
  app.allow_extras();  // PETSc's own options (-ksp_monitor, ...) pass through
  CLI11_PARSE(app, argc, argv);
  if (problem == "contact" && !app.count("--rtol")) s.rtol = 1e-9;
  if (preconditioner == "gamg") s.preconditioner = symcontact::NewtonPreconditioner::kGamg;
  if (problem == "elasticity")
    elasticity_rows(petsc, s);
  else
    contact_rows(petsc, s);
  return 0;
}
