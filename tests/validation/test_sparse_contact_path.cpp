// The two forms of a frictional subproblem (solvers/condensation_cache.hpp, kDenseOverSparse). On a rigid obstacle:
// a pad [−0.6, 0.6]² × [0, t] pressed onto the rigid plane z = 0 and dragged along x with Coulomb friction
// μ = 0.3, its whole bottom face in contact. Thick and coarse (t = 0.4, h = 0.1: |B| = 594) its contact DOFs are
// few and the subproblems are condensed; thin and finer (t = 0.15, h = 0.05: |B| = 2,184) a dense factorisation
// on them costs about 30 times a sparse one of K_ff, and the primal interior point takes the uncondensed problem.
// Either way the bottom slides as a whole in the last step, so that the top's reaction has |R_x / R_z| = μ up to
// the friction regularisation (slips of 0.04 against α of a few 1e-4).
// Between two elastic bodies (a symmetric pair, which IPOPT solves): two plates with a hole clamped by a washer
// ring and sheared, the last step's subproblems optimised on the condensed problem or on the uncondensed one
// ([contact_solver] ipopt_problem), the polish on the condensed one either way: the same reactions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

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

namespace {

/// A plate [−½, ½]² × [z0, z0 + 0.2] with a hole of radius 0.1 and the washer annulus 0.1 ≤ r ≤ 0.2 on its
/// bottom and top faces (docs/performance.md, clamped-plates).
std::string plate_geo(double z0) {
  return "z0 = " + std::to_string(z0) + R"(; t = 0.2; rh = 0.1; rw = 0.2;
Point(1) = {0, 0, z0};
For k In {0:1}
  r = (k == 0) ? rh : rw;
  Point(2 + 4*k) = {r, 0, z0}; Point(3 + 4*k) = {0, r, z0}; Point(4 + 4*k) = {-r, 0, z0}; Point(5 + 4*k) = {0, -r, z0};
  Circle(1 + 4*k) = {2 + 4*k, 1, 3 + 4*k}; Circle(2 + 4*k) = {3 + 4*k, 1, 4 + 4*k};
  Circle(3 + 4*k) = {4 + 4*k, 1, 5 + 4*k}; Circle(4 + 4*k) = {5 + 4*k, 1, 2 + 4*k};
EndFor
Point(10) = {-0.5, -0.5, z0}; Point(11) = {0.5, -0.5, z0}; Point(12) = {0.5, 0.5, z0}; Point(13) = {-0.5, 0.5, z0};
Line(9) = {10, 11}; Line(10) = {11, 12}; Line(11) = {12, 13}; Line(12) = {13, 10};
Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {5, 6, 7, 8}; Curve Loop(3) = {9, 10, 11, 12};
Plane Surface(1) = {2, 1};
Plane Surface(2) = {3, 2};
e[] = Extrude {0, 0, t} { Surface{1, 2}; };
Coherence;
Physical Volume("solid") = {e[1], e[11]};
Physical Surface("bottom") = {1, 2};
Physical Surface("top") = {e[0], e[10]};
Physical Surface("washer_bottom") = {1};
Physical Surface("washer_top") = {e[0]};
)";
}

std::string plates_toml(const std::string& ipopt_problem) {
  return R"(title = "clamped plates"
[problem]
dimension = 3
mesh_size = 0.16
[steps]
load_factors = [1.0, 1.0]
[[body]]
name = "upper"
mesh = "upper.geo"
group = "solid"
material = { E = 1.0, nu = 0.3 }
[[body.dirichlet]]
boundary = "washer_top"
uz = -0.002
uy = 0.0
[[body.dirichlet]]
boundary = "washer_top"
ux = 0.0005
factors = [0.0, 1.0]
[[body]]
name = "lower"
mesh = "lower.geo"
group = "solid"
material = { E = 1.0, nu = 0.3 }
[[body.dirichlet]]
boundary = "washer_bottom"
ux = 0.0
uy = 0.0
uz = 0.0
[[contact]]
name = "interface"
a = "upper.bottom"
b = "lower.top"
friction = "coulomb"
mu = 0.3
[contact_solver]
coulomb_tolerance = 1e-12
ipopt_problem = ")" + ipopt_problem + "\"\n";
}

struct PlatesAnswer {
  std::vector<std::vector<Eigen::VectorXd>> reactions;
  Index condensed = 0;
  int uncondensed_solves = 0;  ///< of the last solve
};

PlatesAnswer solve_plates(const std::string& ipopt_problem) {
  const std::string dir = test_temp_dir("sparse_path_plates_" + ipopt_problem);
  write_text(dir, "upper.geo", plate_geo(0.0));
  write_text(dir, "lower.geo", plate_geo(-0.2));
  const auto c = solve_case(plates_toml(ipopt_problem), dir);
  return {c->reactions, c->report.num_condensed, c->report.uncondensed_solves};
}

}  // namespace

TEST(SparseContactPath, IpoptOnTheUncondensedSymmetricPairGivesTheCondensedAnswer) {
  const PlatesAnswer condensed = solve_plates("condensed");
  const PlatesAnswer uncondensed = solve_plates("uncondensed");
  EXPECT_GT(condensed.condensed, 0);
  EXPECT_GT(uncondensed.condensed, 0);  // the polish's problem
  EXPECT_EQ(condensed.uncondensed_solves, 0);
  EXPECT_GT(uncondensed.uncondensed_solves, 0);
  ASSERT_EQ(condensed.reactions.size(), uncondensed.reactions.size());
  double scale = 0.0, difference = 0.0;
  for (std::size_t step = 0; step < condensed.reactions.size(); ++step)
    for (std::size_t k = 0; k < condensed.reactions[step].size(); ++k) {
      const Eigen::VectorXd& a = condensed.reactions[step][k];
      scale = std::max(scale, a.lpNorm<Eigen::Infinity>());
      difference = std::max(difference, (a - uncondensed.reactions[step][k]).lpNorm<Eigen::Infinity>());
    }
  // The upper washer: R_z on its first condition (uz, uy), R_x on its second (ux).
  const double rz = condensed.reactions.back()[0][2], rx = condensed.reactions.back()[1][0];
  std::printf("  %ld condensed DOFs; |R_x/R_z| of the upper washer %.8f; reactions apart by %.2e of %.3e\n",
              static_cast<long>(condensed.condensed), std::abs(rx / rz), difference, scale);
  EXPECT_GT(std::abs(rx), 1e-3 * std::abs(rz));  // the shear is carried by friction
  EXPECT_LE(difference, 1e-8 * scale);
}
