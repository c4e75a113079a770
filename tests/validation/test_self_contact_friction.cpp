// Self-contact WITH friction (issue #6): a surface paired with itself carries Coulomb friction as two
// surfaces do. A C-shaped body whose upper arm is pressed onto its own lower block and dragged along it
// (drag_arm() below); the facing faces are either ONE group paired with itself or two groups of the same
// body in a symmetric pair. The drag's reaction must be the same (to 1e-4: measured 2e-7 in 2D, 5e-5 in 3D), with
// friction carrying a good part of it (against the frictionless drag), and the reactions must balance.
// A self-contact surface holds both sides of the interface and every node of it carries a friction
// point; each side carries half of the interface's friction (contact_solver.cpp): with the full weight the
// drag was 15 % larger in 2D.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/solve_case.hpp"

using namespace symcontact;
using namespace symcontact::testing;

namespace {

struct Drag {
  double pressing = 0.0;  ///< the top's reaction along the normal
  double drag = 0.0;      ///< the top's reaction along the drag
  double base_drag = 0.0; ///< the base's reaction along the drag
  int coulomb_iterations = 0;
};

/// A C-shaped body (2D; 3D: extruded by 0.5 in z): a lower block [0, 2] × [−1, 0] held at its base, a back
/// [−0.3, 0] × [−1, 0.35] and an upper arm [0, 1.45] × [0.02, 0.32], whose bottom faces the lower block's
/// top across a gap of 0.02. The arm's top is pressed by p and dragged by U along x: the arm closes the
/// gap and slides on the block, the back bending. The facing faces are one group paired with itself
/// (`self_contact`) or two groups of the same body in a symmetric pair.
Drag drag_arm(int dim, bool self_contact, double mu, double p, double U) {
  const std::string dir = test_temp_dir(std::string("self_friction_") + std::to_string(dim) + "d_" +
                                        (self_contact ? "self" : "pair"));
  const bool d3 = dim == 3;
  const double W = 0.5;
  std::string geo = "SetFactory(\"OpenCASCADE\");\n";
  char buf[1024];
  if (d3)
    std::snprintf(buf, sizeof buf, "Box(1) = {0, -1, 0, 2, 1, %g};\nBox(2) = {-0.3, -1, 0, 0.3, 1.35, %g};\n"
                  "Box(3) = {0, 0.02, 0, 1.45, 0.3, %g};\nBooleanUnion(4) = {Volume{1}; Delete;}{Volume{2}; Volume{3}; Delete;};\n"
                  "MeshSize{PointsOf{Volume{4};}} = 0.2;\n", W, W, W);
  else
    std::snprintf(buf, sizeof buf, "Rectangle(1) = {0, -1, 0, 2, 1};\nRectangle(2) = {-0.3, -1, 0, 0.3, 1.35};\n"
                  "Rectangle(3) = {0, 0.02, 0, 1.45, 0.3};\nBooleanUnion(4) = {Surface{1}; Delete;}{Surface{2}; Surface{3}; Delete;};\n"
                  "MeshSize{PointsOf{Surface{4};}} = 0.06;\n");
  geo += buf;
  const std::string kind = d3 ? "Surface" : "Curve", vol = d3 ? "Volume" : "Surface";
  auto in_box = [&](double x0, double y0, double x1, double y1) {
    char b[256];
    std::snprintf(b, sizeof b, "%s In BoundingBox{%g, %g, %g, %g, %g, %g}", kind.c_str(), x0, y0, -1e-3, x1, y1,
                  d3 ? W + 1e-3 : 1e-3);
    return std::string(b);
  };
  geo += "lower() = " + in_box(-1e-3, -1e-3, 2.001, 1e-3) + ";\n";
  geo += "upper() = " + in_box(-1e-3, 0.02 - 1e-3, 1.451, 0.02 + 1e-3) + ";\n";
  geo += "base() = " + in_box(-0.301, -1.001, 2.001, -0.999) + ";\n";
  geo += "top() = " + in_box(-1e-3, 0.32 - 1e-3, 1.451, 0.32 + 1e-3) + ";\n";
  geo += "Physical " + vol + "(\"body\") = {4};\n";
  if (self_contact) geo += "Physical " + kind + "(\"interface\") = {lower(), upper()};\n";
  geo += "Physical " + kind + "(\"lower_face\") = {lower()};\nPhysical " + kind + "(\"upper_face\") = {upper()};\n";
  geo += "Physical " + kind + "(\"base\") = {base()};\nPhysical " + kind + "(\"top\") = {top()};\n";
  write_text(dir, "arm.geo", geo);
  char toml[2048];
  std::snprintf(toml, sizeof toml, R"([problem]
dimension = %d
order = 1
[steps]
load_factors = [0.5, 1.0, 1.5, 2.0]
[[body]]
name = "c"
mesh = "arm.geo"
group = "body"
material = { E = 1.0, nu = 0.3 }
[[body.dirichlet]]
boundary = "base"
ux = 0.0
uy = 0.0
%s[[body.dirichlet]]
boundary = "top"
ux = %.17g
[[body.pressure]]
boundary = "top"
pressure = %.17g
factors = [1.0, 1.0, 1.0, 1.0]
[[contact]]
name = "interface"
a = "c.%s"
b = "c.%s"
friction = "coulomb"
mu = %.17g
)", dim, d3 ? "uz = 0.0\n" : "", U / 2.0, p, self_contact ? "interface" : "lower_face",
                self_contact ? "interface" : "upper_face", mu);
  auto c = solve_case(toml, dir);
  EXPECT_EQ(c->history.size(), 4u);
  const auto& R = c->reactions.back();
  const auto& bounds = c->model->dirichlet_boundaries();
  Drag out;
  for (std::size_t k = 0; k < bounds.size(); ++k) {
    if (bounds[k].name == "top") {
      out.drag = R[k][0];
      out.pressing = R[k][1];
    }
    if (bounds[k].name == "base") out.base_drag = R[k][0];
  }
  out.coulomb_iterations = c->report.coulomb_iterations;
  return out;
}

void check(int dim) {
  const double mu = 0.3, p = 0.002, U = 0.05;
  const Drag self = drag_arm(dim, true, mu, p, U), pair = drag_arm(dim, false, mu, p, U);
  const Drag frictionless = drag_arm(dim, true, 0.0, p, U);
  std::printf("self-contact friction %dD: drag reaction %.10f (self-contact), %.10f (two groups, symmetric pair), "
              "%.10f frictionless; base %.10f / %.10f; Coulomb iterations %d / %d; relative difference %.2e\n",
              dim, self.drag, pair.drag, frictionless.drag, self.base_drag, pair.base_drag, self.coulomb_iterations,
              pair.coulomb_iterations, std::abs(self.drag - pair.drag) / std::abs(pair.drag));
  // Friction carries a good part of the drag (the rest bends the back) ...
  EXPECT_GT(std::abs(self.drag - frictionless.drag), 0.1 * std::abs(self.drag));
  // ... and the self-contact's equals the two-surface pair's; the reactions balance.
  // Not the same discretisation (each side's nodes at half weight against one side's at full weight): they agree
  // to what falls with the mesh (3D: 5.0e-5 at the test's size 0.2, 1.3e-6 at 0.12; 2D: 2e-7).
  EXPECT_NEAR(self.drag, pair.drag, 1e-4 * std::abs(pair.drag));
  EXPECT_NEAR(self.drag + self.base_drag, 0.0, 1e-8 * std::abs(self.drag));
}

}  // namespace

TEST(SelfContactFriction2D, AnArmSlidingOnItsOwnBodyLikeTwoSurfaces) { check(2); }
TEST(SelfContactFriction3D, AnArmSlidingOnItsOwnBodyLikeTwoSurfaces) { check(3); }
