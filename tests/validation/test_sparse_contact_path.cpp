// The two forms of a frictional subproblem on a rigid obstacle (solvers/condensation_cache.hpp, kDenseOverSparse):
// a pad [−0.6, 0.6]² × [0, t] pressed onto the rigid plane z = 0 and dragged along x with Coulomb friction
// μ = 0.3, its whole bottom face in contact. Thick and coarse (t = 0.4, h = 0.1: |B| = 594) its contact DOFs are
// few and the subproblems are condensed; thin and finer (t = 0.15, h = 0.05: |B| = 2,184) a dense factorisation
// on them costs about 30 times a sparse one of K_ff, and the primal interior point takes the uncondensed problem.
// Either way the bottom slides as a whole in the last step, so that the top's reaction has |R_x / R_z| = μ up to
// the friction regularisation (slips of 0.04 against α of a few 1e-4).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "support/solve_case.hpp"

using namespace symcontact;
using namespace symcontact::testing;

namespace {

std::string pad_geo(double t) {
  return R"(Point(1) = {-0.6, -0.6, 0}; Point(2) = {0.6, -0.6, 0}; Point(3) = {0.6, 0.6, 0};
Point(4) = {-0.6, 0.6, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
e[] = Extrude {0, 0, )" + std::to_string(t) + R"(} { Surface{1}; };
Physical Volume("solid") = {e[1]};
Physical Surface("bottom") = {1};
Physical Surface("top") = {e[0]};
)";
}

std::string pad_toml(double h) {
  return R"(title = "thin pad"
[problem]
dimension = 3
mesh_size = )" + std::to_string(h) + R"(
[steps]
load_factors = [1.0, 1.0]
[[body]]
name = "pad"
mesh = "pad.geo"
group = "solid"
material = { E = 1.0, nu = 0.3 }
[[body.dirichlet]]
boundary = "top"
uz = -0.004
uy = 0.0
[[body.dirichlet]]
boundary = "top"
ux = 0.04
factors = [0.0, 1.0]
[[contact]]
name = "interface"
a = "pad.bottom"
friction = "coulomb"
mu = 0.3
[contact.obstacle]
type = "plane"
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]
)";
}

/// |R_x / R_z| of the top at the last step, and the DOFs the last solve was condensed onto (0: none).
struct PadAnswer {
  double ratio = 0.0;
  Index condensed = -1;
};

PadAnswer solve_pad(double t, double h, const std::string& name) {
  const std::string dir = test_temp_dir(name);
  write_text(dir, "pad.geo", pad_geo(t));
  const auto c = solve_case(pad_toml(h), dir);
  const auto& r = c->reactions.back();
  return {std::abs(r[1][0] / r[0][2]), c->report.num_condensed};
}

}  // namespace

TEST(SparseContactPath, CoarseIsCondensedFineIsNotAndBothSlideAtMu) {
  const PadAnswer coarse = solve_pad(0.4, 0.1, "sparse_path_coarse");
  const PadAnswer fine = solve_pad(0.15, 0.05, "sparse_path_fine");
  std::printf("  coarse: %ld condensed DOFs, |Rx/Rz| = %.6f; fine: %ld, |Rx/Rz| = %.6f\n",
              static_cast<long>(coarse.condensed), coarse.ratio, static_cast<long>(fine.condensed), fine.ratio);
  EXPECT_GT(coarse.condensed, 0);
  EXPECT_EQ(fine.condensed, 0);
  EXPECT_NEAR(coarse.ratio, 0.3, 1e-3 * 0.3);
  EXPECT_NEAR(fine.ratio, 0.3, 1e-3 * 0.3);
}
