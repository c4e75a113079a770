#include "support/contact_patch_case.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "support/solve_case.hpp"

namespace symcontact::testing {

namespace {

constexpr double kP = 0.01, kNu = 0.3;

}  // namespace

std::string contact_patch_geo(int n1, int n2, int dim) {
  char buf[2048];
  if (dim == 3) {
    // OpenCASCADE boxes: faces 1..6 of box 1 are xmin, xmax, ymin, ymax, zmin, zmax; 7..12 for box 2. The
    // boxes are not fused, so the two faces at z = 1 are meshed independently (non-matching).
    std::snprintf(buf, sizeof buf, R"(
SetFactory("OpenCASCADE");
h1 = 1.0 / %d; h2 = 1.0 / %d; e = 1e-6;
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {0, 0, 1, 1, 1, 1};
MeshSize{PointsOf{Volume{1};}} = h1;
MeshSize{PointsOf{Volume{2};}} = h2;
Physical Volume("lower") = {1}; Physical Volume("upper") = {2};
Physical Surface("bottom") = {5}; Physical Surface("lower_top") = {6};
Physical Surface("upper_bottom") = {11}; Physical Surface("top") = {12};
Physical Point("origin") = Point In BoundingBox{-e, -e, -e, e, e, e};
Physical Point("lower_x") = Point In BoundingBox{1 - e, -e, -e, 1 + e, e, e};
Physical Point("upper_corner") = Point In BoundingBox{-e, -e, 2 - e, e, e, 2 + e};
Physical Point("upper_x") = Point In BoundingBox{1 - e, -e, 2 - e, 1 + e, e, 2 + e};
)",
                  n1, n2);
    return buf;
  }
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

namespace {

std::string contact_patch_toml_3d(const ContactPatchCase& c) {
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
uz = 0.0
[[body.dirichlet]]
boundary = "origin"
ux = 0.0
uy = 0.0
[[body.dirichlet]]
boundary = "lower_x"
uy = 0.0
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
uy = 0.0
[[body.dirichlet]]
boundary = "upper_x"
uy = 0.0
[[body.pressure]]
boundary = "top"
pressure = 0.01
)";
  return "[problem]\ndimension = 3\norder = " + std::to_string(c.order) + "\n" + (c.swap ? upper + lower : lower + upper);
}

}  // namespace

std::string contact_patch_toml(const ContactPatchCase& c) {
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
  std::string t = c.dim == 3 ? contact_patch_toml_3d(c)
                             : "[problem]\ndimension = 2\norder = " + std::to_string(c.order) + "\n" +
                                   (c.swap ? upper + lower : lower + upper);
  t += "[[contact]]\nname = \"interface\"\n";
  t += c.swap ? "a = \"upper.upper_bottom\"\nb = \"lower.lower_top\"\n" : "a = \"lower.lower_top\"\nb = \"upper.upper_bottom\"\n";
  t += "mode = \"" + c.mode + "\"\n";
  if (c.mode == "one-pass") t += "slave = \"b\"\n";
  if (c.mu >= 0) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "friction = \"coulomb\"\nmu = %.17g\n", c.mu);
    t += buf;
    if (c.alpha > 0) {
      std::snprintf(buf, sizeof buf, "alpha = %.17g\n", c.alpha);
      t += buf;
    }
  }
  return t;
}

ContactPatchErrors contact_patch_errors(const ContactPatchCase& c) {
  const std::string dir = ::testing::TempDir() + (c.dim == 3 ? "contact_patch_3d/" : "contact_patch/");
  write_text(dir, "blocks.geo", contact_patch_geo(c.n1, c.n2, c.dim));
  auto s = solve_case(contact_patch_toml(c), dir);
  ContactPatchErrors e;
  e.geometry_iterations = s->frictional.geometry_iterations;
  e.ipopt_iterations = s->frictional.ipopt_iterations;
  e.coulomb_iterations = s->frictional.coulomb_iterations;
  double umax = 0;
  const Model& m = *s->model;
  for (int b = 0; b < m.dofs().num_bodies(); ++b) {
    const Mesh& mesh = m.bodies()[b]->mesh;
    for (Index v = 0; v < mesh.num_nodes(); ++v) {
      Eigen::Vector3d exact;
      if (c.dim == 2) {
        exact << kNu * (1 + kNu) * kP * mesh.x(0, v), -(1 - kNu * kNu) * kP * mesh.x(1, v), 0.0;
      } else {
        exact << kNu * kP * mesh.x(0, v), kNu * kP * mesh.x(1, v), -kP * mesh.x(2, v);
      }
      for (int i = 0; i < c.dim; ++i) {
        e.displacement = std::max(e.displacement, std::abs(s->u[m.dofs().dof(b, v, i)] - exact[i]));
        umax = std::max(umax, std::abs(exact[i]));
      }
    }
  }
  e.displacement /= umax;
  for (const auto& side : s->contact.at(0).sides)
    for (Index k = 0; k < side.pressure.size(); ++k) {
      e.pressure = std::max(e.pressure, std::abs(side.pressure[k] - kP) / kP);
      e.tangential = std::max(e.tangential, side.tangential.col(k).norm() / kP);
    }
  return e;
}

std::string contact_patch_name(const ContactPatchCase& c) {
  std::string name = std::string(c.dim == 3 ? "3D_" : "") + "n" + std::to_string(c.n1) + "_" + std::to_string(c.n2) + "_P" + std::to_string(c.order) + "_" +
                     (c.mode == "symmetric" ? std::string("symmetric") : std::string("onepass"));
  if (c.swap) name += "_swapped";
  if (c.mu >= 0) name += "_mu" + std::to_string(static_cast<int>(std::lround(10 * c.mu)));
  return name;
}

}  // namespace symcontact::testing
