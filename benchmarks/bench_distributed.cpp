/// symcontact-bench-distributed — the distributed path on the model problems of
/// src/symcontact/distributed/model_problems.hpp, one row per size:
/// - `--problem elasticity`: the clamped block by CG + GAMG (gamg_elasticity.hpp): DOFs, CG iterations,
///   multigrid levels, times of assembly (each rank its own cells), setup and solve, rank 0's peak RSS;
/// - `--problem contact`: the block pressed onto a rigid ball by the interior point with Krylov Newton solves
///   (contact_interior_point.hpp): contact nodes and those in contact, interior-point iterations, CG
///   iterations per Newton system (smallest, largest, all), times, the largest contact force and peak RSS.
/// - `--problem sliding`: the block pressed by 0.01 on a rigid plane and dragged by 0.05 (its whole bottom face
///   sliding) with Coulomb friction `--mu` (α = 10⁻³ h) as a fixed point of Tresca solves: the Tresca solves,
///   the interior point's columns summed over them, and R_x / R_n of the top against μ;
/// - `--problem hertz`: VALIDATION.md's V2 (examples/hertz_3d/sphere_on_plane.*) at the sizes `--h`, by the
///   same interior point: its columns, then Gmsh's meshing time and p0 and a against the closed form.
///   symcontact-bench-distributed --dim 3 --divisions 20 32 48 70
///   symcontact-bench-distributed --problem contact --dim 3 --divisions 16 24 32 [--preconditioner gamg]
///   symcontact-bench-distributed --problem hertz --h 0.02 0.01 0.005
///   symcontact-bench-distributed --problem sliding --dim 3 --divisions 16 24 --mu 0.2
///   mpiexec -n 2 symcontact-bench-distributed --dim 3 --divisions 70
/// A program of its own: the distributed path never shares a process with IPOPT's sequential MUMPS
/// (src/CMakeLists.txt), so the Cholesky floor of the same block comes from `symcontact-bench --case
/// elasticity`, which builds the same mesh (docs/performance.md).

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <string>
#include <vector>

#include "symcontact/distributed/model_problems.hpp"
#include "symcontact/distributed/petsc_support.hpp"
#include "symcontact/distributed/contact_interior_point.hpp"
#include "symcontact/distributed/gamg_elasticity.hpp"

namespace {

using symcontact::PetscSession;
using symcontact::VectorXd;

/// VmHWM of /proc/self/status in MiB (−1 when absent).
double peak_rss_mib() {
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return -1.0;
}

struct Settings {
  int dim = 3;
  std::vector<int> divisions{20, 32};
  std::vector<double> h{0.02, 0.01};
  double rtol = 1e-10;
  double radius = 1.0, depth = 0.02, mu = 0.2;
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
    const double assembly = symcontact::petsc::seconds_since(t0);
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

const char* const kIpHeader = "%6s %11s %8s %10s %10s %10s";

/// The interior point's columns: iterations, CG iterations per Newton system (smallest–largest) and in all,
/// setup, Krylov and total times.
void print_ip_columns(const symcontact::ContactInteriorPointResult& r) {
  const auto& its = r.krylov_iterations;
  std::printf(" %6d %5d–%-5d %8d %10.2f %10.2f %10.2f", r.iterations,
              its.empty() ? 0 : *std::min_element(its.begin(), its.end()),
              its.empty() ? 0 : *std::max_element(its.begin(), its.end()), std::accumulate(its.begin(), its.end(), 0),
              r.setup_seconds, r.krylov_seconds, r.total_seconds);
}

void print_ip_header() {
  std::printf(kIpHeader, "IP it", "CG min–max", "CG all", "setup [s]", "Krylov [s]", "total [s]");
}

void print_end(const symcontact::ContactInteriorPointResult& r) {
  std::printf(" %12.0f%s\n", peak_rss_mib(), r.converged ? "" : ("  not converged: " + r.reason).c_str());
}

symcontact::ContactInteriorPointResult solve(const symcontact::ObstacleSystem& o, const Settings& s) {
  symcontact::ContactInteriorPointOptions options;
  options.tolerance = s.rtol;
  options.preconditioner = s.preconditioner;
  const symcontact::BlockSystem& b = o.block;
  return symcontact::solve_contact_interior_point(b.K_lower, b.f, b.fixed, b.fixed_values, b.mesh.x, o.contact,
                                                  options);
}

const char* preconditioner_name(const Settings& s) {
  return s.preconditioner == symcontact::NewtonPreconditioner::kFilteredGamg ? "GAMG with filtering" : "GAMG";
}

void contact_rows(const PetscSession& petsc, const Settings& s) {
  const bool root = petsc.rank() == 0;
  if (root) {
    std::printf("# ranks %d; block on a rigid ball (R %g, depth %g), interior point, CG + %s, tolerance %g\n"
                "%9s %10s %8s %8s", petsc.size(), s.radius, s.depth, preconditioner_name(s), s.rtol, "divisions",
                "DOFs", "contact", "active");
    print_ip_header();
    std::printf(" %14s %12s\n", "max force", "peak RSS [MiB]");
  }
  for (const int n : s.divisions) {
    const auto o = symcontact::block_on_ball_system(s.dim, n, s.radius, s.depth, petsc.rank(), petsc.size());
    const auto r = solve(o, s);
    const long active = std::count_if(r.lambda.begin(), r.lambda.end(),
                                      [&](double l) { return l > std::sqrt(s.rtol) * r.force_scale; });
    if (!root) continue;
    std::printf("%9d %10lld %8lld %8ld", n, static_cast<long long>(o.block.f.size()),
                static_cast<long long>(o.contact.size()), active);
    print_ip_columns(r);
    std::printf(" %14.6e", r.lambda.maxCoeff());
    print_end(r);
  }
}

/// p0 and a of V2 (largest nodal pressure; largest distance to the axis of a node above 1e-3 p0) against the
/// closed form at the applied load P_h, in per cent.
std::pair<double, double> hertz_errors(const symcontact::ObstacleSystem& o, const VectorXd& lambda) {
  const double load = 4 * symcontact::vertical_load(o.block), estar = 1.0 / (1 - 0.3 * 0.3);
  const double a_ref = std::cbrt(3 * load / (4 * estar)), p0_ref = 3 * load / (2 * M_PI * a_ref * a_ref);
  const VectorXd p = symcontact::nodal_pressures(o.block.mesh, "contact", o.contact, lambda);
  double a = 0.0;
  for (Eigen::Index j = 0; j < o.contact.size(); ++j)
    if (p[j] > 1e-3 * p.maxCoeff())
      a = std::max(a, std::hypot(o.block.mesh.x(0, o.contact.node[j]), o.block.mesh.x(1, o.contact.node[j])));
  return {100 * (p.maxCoeff() / p0_ref - 1), 100 * (a / a_ref - 1)};
}

/// R_x / R_n of the block's top (its reactions: K u − f on its nodes).
double reaction_ratio(const symcontact::BlockSystem& whole, const VectorXd& u, int dim) {
  const VectorXd residual = symcontact::SparseMatrix(whole.K_lower.selfadjointView<Eigen::Lower>()) * u - whole.f;
  double tangential = 0.0, normal = 0.0;
  for (const auto v : whole.mesh.group_nodes(dim == 2 ? "top" : "zmax")) {
    tangential += residual[dim * v];
    normal -= residual[dim * v + dim - 1];
  }
  return tangential / normal;
}

void sliding_rows(const PetscSession& petsc, const Settings& s) {
  const bool root = petsc.rank() == 0;
  if (root) {
    std::printf("# ranks %d; block sliding on a rigid plane, Coulomb mu %g, interior point, CG + %s, tolerance %g\n"
                "%9s %10s %8s %7s", petsc.size(), s.mu, preconditioner_name(s), s.rtol, "divisions", "DOFs",
                "contact", "solves");
    print_ip_header();
    std::printf(" %12s %12s\n", "R_x/R_n", "peak RSS [MiB]");
  }
  for (const int n : s.divisions) {
    const double alpha = 1e-3 / n;
    const auto o = symcontact::block_on_plane_system(s.dim, n, 0.01, 0.05, 0.0, alpha, petsc.rank(), petsc.size());
    symcontact::ContactInteriorPointOptions options;
    options.tolerance = s.rtol;
    options.preconditioner = s.preconditioner;
    const symcontact::BlockSystem& b = o.block;
    const auto c = symcontact::solve_coulomb_interior_point(b.K_lower, b.f, b.fixed, b.fixed_values, b.mesh.x,
                                                            o.contact, s.mu, 1e-6, 30, options);
    if (!root) continue;
    const double ratio = reaction_ratio(symcontact::block_on_plane_system(s.dim, n, 0.01, 0.05, 0.0, alpha).block,
                                        c.last.u, s.dim);
    std::printf("%9d %10lld %8lld %7d", n, static_cast<long long>(b.f.size()), static_cast<long long>(o.contact.size()),
                c.coulomb_iterations + 1);
    print_ip_columns(c.all);
    std::printf(" %12.9f", ratio);
    print_end(c.last);
  }
}

void hertz_rows(const PetscSession& petsc, const Settings& s) {
  const bool root = petsc.rank() == 0;
  if (root) {
    std::printf("# ranks %d; V2 Hertz sphere on a rigid plane (quarter model), interior point, CG + %s, "
                "tolerance %g\n%9s %10s %8s", petsc.size(), preconditioner_name(s), s.rtol, "h", "DOFs", "contact");
    print_ip_header();
    std::printf(" %10s %8s %8s %12s\n", "mesh [s]", "p0 [%]", "a [%]", "peak RSS [MiB]");
  }
  const auto dir = std::filesystem::temp_directory_path() / ("symcontact_bench_hertz_" + std::to_string(petsc.rank()));
  std::filesystem::create_directories(dir);
  for (const double h : s.h) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto o = symcontact::hertz_sphere_system(std::string(SYMCONTACT_BENCH_EXAMPLES) + "/hertz_3d/sphere_on_plane.geo",
                                                   h, dir.string(), petsc.rank(), petsc.size());
    const double meshing = symcontact::petsc::seconds_since(t0);
    const auto r = solve(o, s);
    if (!root) continue;
    const auto [p0_error, a_error] = hertz_errors(o, r.lambda);
    std::printf("%9.4f %10lld %8lld", h, static_cast<long long>(o.block.f.size()), static_cast<long long>(o.contact.size()));
    print_ip_columns(r);
    std::printf(" %10.1f %+8.2f %+8.2f", meshing, p0_error, a_error);
    print_end(r);
  }
}

}  // namespace

int main(int argc, char** argv) {
  PetscSession petsc(&argc, &argv);
  CLI::App app{"symcontact-bench-distributed — the distributed path on PETSc", "symcontact-bench-distributed"};
  Settings s;
  std::string problem = "elasticity", preconditioner = "filtered";
  app.add_option("--problem", problem, "elasticity, contact, sliding or hertz")
      ->check(CLI::IsMember({"elasticity", "contact", "sliding", "hertz"}));
  app.add_option("--mu", s.mu, "sliding: the friction coefficient");
  app.add_option("--dim", s.dim, "2 or 3")->check(CLI::IsMember({2, 3}));
  app.add_option("--divisions", s.divisions, "divisions per side, one row each");
  app.add_option("--rtol", s.rtol, "relative residual of the solve (elasticity), tolerance (contact)");
  app.add_option("--h", s.h, "hertz: mesh sizes near the contact point, one row each");
  app.add_option("--radius", s.radius, "contact: the ball's radius");
  app.add_option("--depth", s.depth, "contact: how far the block's top is moved down");
  app.add_option("--preconditioner", preconditioner, "contact: filtered (GAMG with filtering) or gamg")
      ->check(CLI::IsMember({"filtered", "gamg"}));
  app.allow_extras();  // PETSc's own options (-ksp_monitor, ...) pass through
  CLI11_PARSE(app, argc, argv);
  if (problem != "elasticity" && !app.count("--rtol")) s.rtol = 1e-9;
  if (preconditioner == "gamg") s.preconditioner = symcontact::NewtonPreconditioner::kGamg;
  if (problem == "elasticity")
    elasticity_rows(petsc, s);
  else if (problem == "contact")
    contact_rows(petsc, s);
  else if (problem == "sliding")
    sliding_rows(petsc, s);
  else
    hertz_rows(petsc, s);
  return 0;
}
