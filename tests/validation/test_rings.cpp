// V6 concentric rings (VALIDATION.md): a curved two-body contact with an exact Lamé solution,
// p_c = 0.02056264 at p_in = 0.05. The contact pressure is measured as |resultant on the quarter| /
// (√2 · r), r = 1 the reference radius of the inner ring's outer surface; tolerance 0.5 % at 32 elements
// per quarter circumference, falling with h.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "support/solve_case.hpp"

using namespace symcontact;
using namespace symcontact::testing;

namespace {
const std::string kExample = std::string(SYMCONTACT_EXAMPLES) + "/rings_2d/";
const double kPc = 0.02056264;

double ring_pressure(int nc, int nr, const std::string& extra_toml = "") {
  const std::string dir = test_temp_dir("rings");
  write_text(dir, "rings.geo",
             "nc = " + std::to_string(nc) + "; nr = " + std::to_string(nr) + ";\nInclude \"" + kExample + "rings.geo\";\n");
  std::ifstream in(kExample + "rings.toml");
  std::string toml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto c = solve_case(toml + extra_toml, dir);
  const double pc = c->contact[0].total_force.norm() / std::sqrt(2.0);
  // Equal and opposite forces on the two rings.
  const Eigen::VectorXd fb = c->contact[0].sides[1].force.rowwise().sum();
  EXPECT_LT((c->contact[0].total_force + fb).norm(), 1e-8 * c->contact[0].total_force.norm());
  std::printf("  nc = %d, nr = %d: p_c = %.8f (error %+.3f%%), %d geometry / %d IPOPT iterations\n", nc, nr, pc,
              100 * (pc / kPc - 1), c->report.geometry_iterations, c->report.ipopt_iterations);
  return pc;
}
}  // namespace

TEST(Rings, ContactPressureMatchesLameSolution) {
  const double p16 = ring_pressure(16, 4);
  const double p32 = ring_pressure(32, 8);
  EXPECT_NEAR(p32, kPc, 0.005 * kPc);
  EXPECT_LT(std::abs(p32 - kPc), std::abs(p16 - kPc));
}
