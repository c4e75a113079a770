// V2 Hertz 3D (VALIDATION.md): a sphere (R = 1, E = 1, ν = 0.3) on a rigid plane, quarter model
// (examples/hertz_3d/sphere_on_plane.*): a = (3 P R/(4 E*))^(1/3), p0 = 3P/(2π a²), P = 0.01 on the whole
// sphere (0.189686 and 0.132701). The quarter model's load is a pressure 0.01/π on its flat cut, the
// quarter disk; meshed by flat facets (P1) that disk is a polygon of slightly smaller area (−0.8 % at the
// example's equator size), so the load actually applied is P_h = 4 × its resultant, and the closed
// form is evaluated at P_h (the nominal P is printed too). Tolerances: a within max(2 %, one element)
// (a is measured at the nodes), p0 within 5 %, total contact force = applied load to 1e-8.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <vector>

#include "support/solve_case.hpp"

using namespace symcontact;
using namespace symcontact::testing;

namespace {

const std::string kExamples = std::string(SYMCONTACT_EXAMPLES) + "/hertz_3d";
const double kP = 0.01, kE = 1.0, kNu = 0.3;
const double kEstar = kE / (1 - kNu * kNu);

double a_of(double P) { return std::cbrt(3 * P * 1.0 / (4 * kEstar)); }
double p0_of(double P) { return 3 * P / (2 * M_PI * a_of(P) * a_of(P)); }

struct Hertz3DMeasure {
  double h = 0, p0 = 0, a = 0, force = 0, load = 0, seconds = 0;
  CellType cell = CellType::kTet4;  ///< of the sphere's mesh
  double a_current = 0;  ///< the same edge measured at the nodes' current positions
};

/// The example at element size h near the contact and order `order`; `obstacle`, when given, replaces the
/// example's [contact.obstacle] table; `geo_options`, Gmsh commands run before the example's .geo.
Hertz3DMeasure solve_sphere(double h, int order, const std::string& dir, const std::string& obstacle = "",
                            const std::string& geo_options = "") {
  char buf[64];
  std::snprintf(buf, sizeof buf, "h = %.6g;\n", h);
  write_text(dir, "sphere.geo",
             std::string(buf) + geo_options + "Include \"" + kExamples + "/sphere_on_plane.geo\";\n");
  std::string toml = read_text(kExamples + "/sphere_on_plane.toml");
  toml.replace(toml.find("sphere_on_plane.geo"), 19, "sphere.geo");
  toml.replace(toml.find("order = 1"), 9, "order = " + std::to_string(order));
  if (!obstacle.empty()) toml = toml.substr(0, toml.find("[contact.obstacle]")) + obstacle;
  const auto t0 = std::chrono::steady_clock::now();
  auto c = solve_case(toml, dir);
  Hertz3DMeasure m;
  m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  m.h = h;
  const auto& side = c->contact.at(0).sides.at(0);
  for (Index k = 0; k < side.pressure.size(); ++k) m.p0 = std::max(m.p0, side.pressure[k]);
  for (Index k = 0; k < side.pressure.size(); ++k)
    if (side.pressure[k] > 1e-3 * m.p0) {
      m.a = std::max(m.a, std::hypot(side.X(0, k), side.X(1, k)));
      m.a_current = std::max(m.a_current, std::hypot(side.x(0, k), side.x(1, k)));
    }
  m.force = 4 * c->contact[0].total_force[2];
  // The applied load: 4 × the resultant of the pressure on the (meshed) cut, pointing down.
  const VectorXd f = c->model->external_load();
  const Mesh& mesh = c->model->bodies()[0]->mesh;
  m.cell = mesh.first_cell_type();
  for (Index v = 0; v < mesh.num_nodes(); ++v) m.load -= 4 * f[c->model->dofs().dof(0, v, 2)];
  return m;
}

void print(const char* what, const Hertz3DMeasure& m) {
  const double a_ref = a_of(m.load), p0_ref = p0_of(m.load);
  std::printf("  %s h = %.3f: applied P_h = %.8f (P %+.2f%%), p0 = %.6f (err %+.2f%%; vs nominal P %+.2f%%), "
              "a = %.5f (err %+.2f%%, %.2f elements; current positions %+.2f%%), force / P_h - 1 = %.1e, %.1f s\n",
              what, m.h, m.load, 100 * (m.load / kP - 1), m.p0, 100 * (m.p0 / p0_ref - 1), 100 * (m.p0 / p0_of(kP) - 1),
              m.a, 100 * (m.a / a_ref - 1), std::abs(m.a - a_ref) / m.h, 100 * (m.a_current / a_ref - 1),
              m.force / m.load - 1, m.seconds);
}

void expect_hertz(const Hertz3DMeasure& m) {
  EXPECT_NEAR(m.p0, p0_of(m.load), 0.05 * p0_of(m.load)) << "h = " << m.h;
  EXPECT_NEAR(m.a, a_of(m.load), std::max(0.02 * a_of(m.load), m.h)) << "h = " << m.h;
  EXPECT_NEAR(m.force, m.load, 1e-8 * m.load) << "h = " << m.h;
  EXPECT_NEAR(m.load, kP, 0.01 * kP);  // the meshed cut is within 1 % of the quarter disk
}

// All-hexahedral meshes of the same sphere: Gmsh splits each tetrahedron into four hexahedra
// (Mesh.SubdivisionAlgorithm = 2), so the contact surface is made of quadrilaterals (issue: quadrilaterals and
// hexahedra). The split halves every edge, so "one element" of the tolerance on a is h / 2. Hex8 at two sizes,
// the contact radius converging; Hex27 on a coarser mesh.
const char* const kAllHexahedra = "Mesh.SubdivisionAlgorithm = 2;\n";

Hertz3DMeasure solve_sphere_on_hexahedra(double h, int order, const std::string& dir) {
  Hertz3DMeasure m = solve_sphere(h, order, dir, "", kAllHexahedra);
  m.h = h / 2;
  return m;
}

/// At order 1 with h = 0.04 and 0.02 (`solve(h)` meshes and solves): V2's tolerances at each size, the
/// expected cell type, and a contact radius closer to the closed form on the finer mesh.
void expect_converging(const char* what, CellType cell, const std::function<Hertz3DMeasure(double)>& solve) {
  std::vector<Hertz3DMeasure> ms;
  for (double h : {0.04, 0.02}) {
    ms.push_back(solve(h));
    print(what, ms.back());
    EXPECT_EQ(ms.back().cell, cell);
    expect_hertz(ms.back());
  }
  EXPECT_LT(std::abs(ms[1].a - a_of(ms[1].load)), std::abs(ms[0].a - a_of(ms[0].load)));
}

}  // namespace

// The contact radius converges (p0 is already at the finite-sphere level, ~1 % above the half-space closed
// form, measured 0.26 % / 0.65 % / 0.98 % / 0.89 % at h = 0.04 / 0.02 / 0.014 / 0.01 with P1 tetrahedra).
TEST(Hertz3D, SphereOnRigidPlaneP1) {
  expect_converging("P1", CellType::kTet4,
                    [dir = test_temp_dir("hertz3d_p1")](double h) { return solve_sphere(h, 1, dir); });
}

TEST(Hertz3D, SphereOnRigidPlaneHex8) {
  expect_converging("Hex8", CellType::kHex8,
                    [dir = test_temp_dir("hertz3d_hex8")](double h) { return solve_sphere_on_hexahedra(h, 1, dir); });
}

TEST(Hertz3D, SphereOnRigidPlaneHex27) {
  const Hertz3DMeasure m = solve_sphere_on_hexahedra(0.08, 2, test_temp_dir("hertz3d_hex27"));
  print("Hex27", m);
  EXPECT_EQ(m.cell, CellType::kHex27);
  expect_hertz(m);
}

TEST(Hertz3D, SphereOnRigidPlaneP2) {
  const Hertz3DMeasure m = solve_sphere(0.04, 2, test_temp_dir("hertz3d_p2"));
  print("P2", m);
  expect_hertz(m);
}

namespace {

/// examples/hertz_3d/two_spheres.* at h = 0.04 and order `order`: symmetric contact of two curved,
/// non-matching surfaces (the mirrored sphere is meshed on its own), R_eff = 1/2 and E* halved: the same
/// a and p0, on both sides.
void expect_two_spheres_hertz(int order, const std::string& dir) {
  write_text(dir, "spheres.geo", "h = 0.04;\nInclude \"" + kExamples + "/two_spheres.geo\";\n");
  std::string toml = read_text(kExamples + "/two_spheres.toml");
  for (std::size_t at; (at = toml.find("two_spheres.geo")) != std::string::npos;) toml.replace(at, 15, "spheres.geo");
  toml.replace(toml.find("order = 1"), 9, "order = " + std::to_string(order));
  const auto t0 = std::chrono::steady_clock::now();
  auto c = solve_case(toml, dir);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const VectorXd f = c->model->external_load();
  double load = 0.0;
  for (Index v = 0; v < c->model->bodies()[0]->mesh.num_nodes(); ++v) load -= 4 * f[c->model->dofs().dof(0, v, 2)];
  double p0_side[2] = {0, 0};
  for (int side = 0; side < 2; ++side) {
    const ContactSideResult& sr = c->contact.at(0).sides.at(side);
    Hertz3DMeasure m;
    m.h = 0.04;
    m.load = load;
    m.seconds = seconds;
    for (Index k = 0; k < sr.pressure.size(); ++k) m.p0 = std::max(m.p0, sr.pressure[k]);
    for (Index k = 0; k < sr.pressure.size(); ++k)
      if (sr.pressure[k] > 1e-3 * m.p0) {
        m.a = std::max(m.a, std::hypot(sr.X(0, k), sr.X(1, k)));
        m.a_current = std::max(m.a_current, std::hypot(sr.x(0, k), sr.x(1, k)));
      }
    m.force = (side == 0 ? 4 : -4) * sr.force.row(2).sum();
    print(side == 0 ? "upper" : "lower", m);
    expect_hertz(m);
    p0_side[side] = m.p0;
  }
  EXPECT_NEAR(p0_side[0], p0_side[1], 0.01 * p0_of(load));
}

}  // namespace

TEST(Hertz3D, TwoElasticSpheresMatchTheSameClosedForm) { expect_two_spheres_hertz(1, test_temp_dir("hertz3d_spheres")); }

TEST(Hertz3D, TwoElasticSpheresP2) { expect_two_spheres_hertz(2, test_temp_dir("hertz3d_spheres_p2")); }

TEST(Hertz3D, MeshedRigidFloorGivesTheAnalyticPlaneAnswer) {
  // The same sphere (P1, h = 0.04) on a meshed rigid square z = 0 (one-pass, 3D segment-based mortar
  // integration of a curved slave against flat master facets): exact on the flat floor, so the same
  // answer as the analytic plane up to the solver's tolerance. The square's facets are oriented by its
  // counter-clockwise boundary seen from +z: normal +z, towards the sphere.
  const std::string dir = test_temp_dir("hertz3d_floor");
  const Hertz3DMeasure plane = solve_sphere(0.04, 1, dir);
  write_text(dir, "floor.geo",
             "lc = 0.05;\nPoint(1) = {-0.5, -0.5, 0, lc}; Point(2) = {1.5, -0.5, 0, lc};\n"
             "Point(3) = {1.5, 1.5, 0, lc}; Point(4) = {-0.5, 1.5, 0, lc};\n"
             "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
             "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\nPhysical Surface(\"floor\") = {1};\n");
  const Hertz3DMeasure floor = solve_sphere(
      0.04, 1, dir, "[contact.obstacle]\ntype = \"mesh\"\nmesh = \"floor.geo\"\nboundary = \"floor\"\n");
  print("P1 plane", plane);
  print("P1 floor", floor);
  EXPECT_NEAR(floor.p0, plane.p0, 1e-6 * plane.p0);
  EXPECT_NEAR(floor.force, plane.force, 1e-8 * plane.force);
  EXPECT_NEAR(floor.a, plane.a, 1e-12);
}
