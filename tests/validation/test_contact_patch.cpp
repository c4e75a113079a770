// V3 contact patch test, 2D (VALIDATION.md): two unit blocks pressed together through a non-matching
// (or matching) interface must transmit a uniform pressure exactly. Lower block [0,1]×[0,1], upper
// [0,1]×[1,2], n1 and n2 divisions per side; E = 1, ν = 0.3, plane strain; bottom u_y = 0 and u_x = 0
// at (0, 0); u_x = 0 at (0, 2) removes the upper block's free sliding; pressure p = 0.01 on top.
// Exact: σ_yy = −p, contact pressure p, u_y = −(1 − ν²) p y / E, u_x = ν (1 + ν) p x / E.
#include <gtest/gtest.h>

#include <cstdio>

#include "support/solve_case.hpp"

using namespace symcontact;
using namespace symcontact::testing;

namespace {

const double kP = 0.01, kNu = 0.3;

std::string blocks_geo(int n1, int n2) {
  char buf[2048];
  std::snprintf(buf, sizeof buf, R"(
n1 = %d; n2 = %d;
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Point(5) = {0, 1, 0}; Point(6) = {1, 1, 0}; Point(7) = {1, 2, 0}; Point(8) = {0, 2, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Transfinite Curve{1, 2, 3, 4} = n1 + 1;
Transfinite Curve{5, 6, 7, 8} = n2 + 1;
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1}; Transfinite Surface{1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2}; Transfinite Surface{2};
Physical Surface("lower") = {1}; Physical Surface("upper") = {2};
Physical Curve("bottom") = {1}; Physical Curve("lower_top") = {3};
Physical Curve("upper_bottom") = {5}; Physical Curve("top") = {7};
Physical Point("origin") = {1}; Physical Point("upper_corner") = {8};
)",
                n1, n2);
  return buf;
}

std::string blocks_toml(int order, const std::string& mode, bool swap) {
  const std::string lower = R"(
[[body]]
name = "lower"
mesh = "blocks.geo"
group = "lower"
[body.material]
E = 1.0
nu = 0.3
[[body.dirichlet]]
boundary = "bottom"
uy = 0.0
[[body.dirichlet]]
boundary = "origin"
ux = 0.0
)";
  const std::string upper = R"(
[[body]]
name = "upper"
mesh = "blocks.geo"
group = "upper"
[body.material]
E = 1.0
nu = 0.3
[[body.dirichlet]]
boundary = "upper_corner"
ux = 0.0
[[body.pressure]]
boundary = "top"
pressure = 0.01
)";
  std::string t = "[problem]\ndimension = 2\norder = " + std::to_string(order) + "\n";
  t += swap ? upper + lower : lower + upper;
  t += "[[contact]]\nname = \"interface\"\n";
  t += swap ? "a = \"upper.upper_bottom\"\nb = \"lower.lower_top\"\n" : "a = \"lower.lower_top\"\nb = \"upper.upper_bottom\"\n";
  t += "mode = \"" + mode + "\"\n";
  if (mode == "one-pass") t += "slave = \"b\"\n";
  return t;
}

struct PatchErrors {
  double displacement, pressure;
  int geometry_iterations, ipopt_iterations;
};

PatchErrors patch_errors(int n1, int n2, int order, const std::string& mode, bool swap = false) {
  const std::string dir = ::testing::TempDir() + "contact_patch/";
  write_text(dir, "blocks.geo", blocks_geo(n1, n2));
  auto c = solve_case(blocks_toml(order, mode, swap), dir);
  PatchErrors e{0, 0, c->report.geometry_iterations, c->report.ipopt_iterations};
  double umax = 0;
  const Model& m = *c->model;
  for (int b = 0; b < m.dofs().num_bodies(); ++b) {
    const Mesh& mesh = m.bodies()[b]->mesh;
    for (Index v = 0; v < mesh.num_nodes(); ++v) {
      const double x = mesh.x(0, v), y = mesh.x(1, v);
      const double ux = kNu * (1 + kNu) * kP * x, uy = -(1 - kNu * kNu) * kP * y;
      e.displacement = std::max({e.displacement, std::abs(c->u[m.dofs().dof(b, v, 0)] - ux),
                                 std::abs(c->u[m.dofs().dof(b, v, 1)] - uy)});
      umax = std::max({umax, std::abs(ux), std::abs(uy)});
    }
  }
  e.displacement /= umax;
  for (const auto& side : c->contact[0].sides)
    for (Index k = 0; k < side.pressure.size(); ++k)
      e.pressure = std::max(e.pressure, std::abs(side.pressure[k] - kP) / kP);
  return e;
}

struct PatchCase {
  int n1, n2, order;
  std::string mode;
};

class ContactPatch2D : public ::testing::TestWithParam<PatchCase> {};

}  // namespace

TEST_P(ContactPatch2D, UniformPressureAndExactDisplacements) {
  const PatchCase pc = GetParam();
  const PatchErrors e = patch_errors(pc.n1, pc.n2, pc.order, pc.mode);
  std::printf("  (%d, %d) P%d %s: displacement error %.2e, pressure error %.2e, %d geometry / %d IPOPT iterations\n",
              pc.n1, pc.n2, pc.order, pc.mode.c_str(), e.displacement, e.pressure, e.geometry_iterations,
              e.ipopt_iterations);
  EXPECT_LT(e.pressure, 1e-6);
  EXPECT_LT(e.displacement, 1e-8);
}

INSTANTIATE_TEST_SUITE_P(
    V3, ContactPatch2D,
    ::testing::Values(PatchCase{4, 5, 1, "symmetric"}, PatchCase{5, 4, 1, "symmetric"}, PatchCase{4, 5, 2, "symmetric"},
                      PatchCase{5, 4, 2, "symmetric"}, PatchCase{4, 5, 1, "one-pass"}, PatchCase{5, 4, 1, "one-pass"},
                      PatchCase{4, 5, 2, "one-pass"}, PatchCase{5, 4, 2, "one-pass"},
                      // Matching meshes: the two constraint families are exactly dependent.
                      PatchCase{4, 4, 1, "symmetric"}, PatchCase{4, 4, 2, "symmetric"}),
    [](const auto& p) {
      return "n" + std::to_string(p.param.n1) + "_" + std::to_string(p.param.n2) + "_P" + std::to_string(p.param.order) +
             "_" + (p.param.mode == "symmetric" ? std::string("symmetric") : std::string("onepass"));
    });
