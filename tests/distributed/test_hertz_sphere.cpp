// VALIDATION.md, V2 (Hertz 3D, a sphere on a rigid plane) through the distributed interior point with
// Krylov Newton solves (src/symcontact/distributed/contact_interior_point.hpp), on one rank and, registered a
// second time under mpirun, on two: the quarter sphere of examples/hertz_3d/sphere_on_plane.* at h = 0.04
// and 0.02, with V2's tolerances at the load actually applied, as tests/validation/test_hertz_3d.cpp
// checks the serial solver: a within max(2 %, one element), p0 within 5 %, the contact force equal to the
// load.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "symcontact/distributed/contact_interior_point.hpp"
#include "symcontact/distributed/model_problems.hpp"
#include "test_support.hpp"

namespace symcontact {
namespace {

const double kEstar = 1.0 / (1 - 0.3 * 0.3);
double a_of(double P) { return std::cbrt(3 * P / (4 * kEstar)); }
double p0_of(double P) { return 3 * P / (2 * M_PI * a_of(P) * a_of(P)); }

TEST(HertzSphere, MeetsV2ThroughTheDistributedInteriorPoint) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("symcontact_distributed_hertz_" + std::to_string(g_petsc->rank()));
  std::filesystem::create_directories(dir);
  double previous_a_error = 1.0;
  for (const double h : {0.04, 0.02}) {
    const ObstacleSystem o = hertz_sphere_system(std::string(SYMCONTACT_EXAMPLES) + "/hertz_3d/sphere_on_plane.geo",
                                                 h, dir.string(), g_petsc->rank(), g_petsc->size());
    const BlockSystem& b = o.block;
    const ContactInteriorPointResult r =
        solve_contact_interior_point(b.K_lower, b.f, b.fixed, b.fixed_values, b.mesh.x, o.contact);
    ASSERT_TRUE(r.converged) << r.reason;
    const double load = 4 * vertical_load(b), force = 4 * r.lambda.sum();
    const VectorXd p = nodal_pressures(b.mesh, "contact", o.contact, r.lambda);
    const double p0 = p.maxCoeff();
    double a = 0.0;
    for (Index j = 0; j < o.contact.size(); ++j)
      if (p[j] > 1e-3 * p0) a = std::max(a, std::hypot(b.mesh.x(0, o.contact.node[j]), b.mesh.x(1, o.contact.node[j])));
    const double a_ref = a_of(load), p0_ref = p0_of(load);
    if (g_petsc->rank() == 0)
      std::printf("h = %.3f, %lld DOFs: %d iterations, CG per Newton system up to %d; P_h = %.6f, p0 = %.6f "
                  "(%+.2f %%), a = %.5f (%+.2f %%, %.2f elements), force / P_h − 1 = %.1e\n",
                  h, static_cast<long long>(r.u.size()), r.iterations,
                  *std::max_element(r.krylov_iterations.begin(), r.krylov_iterations.end()), load, p0,
                  100 * (p0 / p0_ref - 1), a, 100 * (a / a_ref - 1), std::abs(a - a_ref) / h, force / load - 1);
    EXPECT_NEAR(p0, p0_ref, 0.05 * p0_ref) << "h = " << h;
    EXPECT_NEAR(a, a_ref, std::max(0.02 * a_ref, h)) << "h = " << h;
    EXPECT_NEAR(force, load, 1e-8 * load) << "h = " << h;
    EXPECT_LT(std::abs(a - a_ref), previous_a_error) << "the contact radius converges";
    previous_a_error = std::abs(a - a_ref);
  }
}

}  // namespace
}  // namespace symcontact
