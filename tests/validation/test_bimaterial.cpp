// A body of two materials (one [[body.material]] per physical group of its cells): a bar of two halves,
// E1 on 0 ≤ x ≤ L1 and E2 on L1 ≤ x ≤ L1 + L2, ν = 0, pulled by a traction t on its end. With ν = 0 the
// stress is uniaxial, σ_xx = t, in plane stress and plane strain alike, and the displacement is piecewise
// linear, u_x = t x / E1 in the first half and t (L1 / E1 + (x − L1) / E2) in the second, u_y = 0, which
// P1 and P2 elements hold exactly: every node meets it to round-off (1e-10 of the tip displacement
// t (L1 / E1 + L2 / E2)), and the output's stress is σ_xx = t in every cell. The same geometry as two
// bodies, one per material, pressed together through a frictionless contact on their shared interface
// gives the same displacements under compression, to the same 1e-10. A neo-Hookean bar of two materials
// under a small load meets the linear figure to the order of its strain.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/solve_case.hpp"
#include "symcontact/post/stress_recovery.hpp"

namespace symcontact::testing {
namespace {

constexpr double kE1 = 200.0, kE2 = 10.0, kL1 = 1.0;

/// A folder with the example's bar as bar.geo, and as split.geo with the interface line as a curve group of
/// its own ("interface", for the two-body model; a facet group inside a body is refused, so the one-body
/// model reads bar.geo). Gmsh meshes both alike.
std::string bar_folder() {
  const std::string dir = test_temp_dir("bimaterial");
  const std::string geo = read_text(std::string(SYMCONTACT_EXAMPLES) + "/bimaterial_2d/bimaterial.geo");
  write_text(dir, "bar.geo", geo);
  write_text(dir, "split.geo", geo + "Physical Curve(\"interface\") = {7};\n");
  return dir;
}

/// The exact u_x at x of a bar under traction t.
double exact_ux(double x, double t) { return x <= kL1 ? t * x / kE1 : t * (kL1 / kE1 + (x - kL1) / kE2); }

/// The largest |u − exact| over the nodes of every body, relative to the tip displacement.
double worst_error(const SolvedCase& c, double t) {
  double worst = 0.0;
  const double tip = std::abs(exact_ux(2.0, t));
  for (int b = 0; b < static_cast<int>(c.model->bodies().size()); ++b) {
    const Mesh& mesh = c.model->bodies()[b]->mesh;
    for (Index v = 0; v < mesh.num_nodes(); ++v) {
      const double ux = c.u[c.model->dofs().dof(b, v, 0)], uy = c.u[c.model->dofs().dof(b, v, 1)];
      worst = std::max({worst, std::abs(ux - exact_ux(mesh.x(0, v), t)) / tip, std::abs(uy) / tip});
    }
  }
  return worst;
}

std::string header(const std::string& model, int order) {
  return "[problem]\ndimension = 2\nmodel = \"" + model + "\"\norder = " + std::to_string(order) + "\n";
}

std::string materials(const std::string& law) {
  return "[[body.material]]\ngroup = \"steel\"\n" + law + "E = " + std::to_string(kE1) +
         "\nnu = 0.0\n[[body.material]]\ngroup = \"rubber\"\n" + law + "E = " + std::to_string(kE2) + "\nnu = 0.0\n";
}

std::string one_body(const std::string& law, double t) {
  return "[[body]]\nname = \"bar\"\nmesh = \"bar.geo\"\nmesh_parameters = { h = 0.1 }\ngroup = \"bar\"\n" +
         materials(law) +
         "[[body.dirichlet]]\nboundary = \"left\"\nux = 0.0\n[[body.dirichlet]]\nboundary = \"bottom\"\nuy = 0.0\n"
         "[[body.traction]]\nboundary = \"right\"\ntraction = [" + std::to_string(t) + ", 0.0]\n";
}

TEST(Bimaterial, BarOfTwoMaterialsMeetsTheClosedFormAtEveryNode) {
  const std::string dir = bar_folder();
  for (const char* model : {"plane_stress", "plane_strain"})
    for (int order = 1; order <= 2; ++order) {
      const auto c = solve_case(header(model, order) + one_body("", 1.0), dir);
      const double error = worst_error(*c, 1.0);
      std::printf("%s, P%d: worst nodal error %.2e of the tip displacement\n", model, order, error);
      EXPECT_LT(error, 1e-10) << model << " P" << order;
      // The output's stress: σ_xx = t in every cell of either material.
      const BodyFields f = recover_fields(*c->model->bodies()[0], c->model->dofs(), 0, c->u);
      EXPECT_LT((f.cell_stress.row(0).array() - 1.0).abs().maxCoeff(), 1e-10) << model << " P" << order;
    }
}

TEST(Bimaterial, OneBodyOfTwoMaterialsEqualsTwoBodiesInContact) {
  const std::string dir = bar_folder();
  const double t = -1.0;  // compression: the interface stays closed
  const auto one = solve_case(header("plane_stress", 1) + one_body("", t), dir);
  const std::string two_bodies =
      header("plane_stress", 1) +
      "[[body]]\nname = \"steel\"\nmesh = \"split.geo\"\nmesh_parameters = { h = 0.1 }\ngroup = \"steel\"\n"
      "material = { E = " + std::to_string(kE1) + ", nu = 0.0 }\n"
      "[[body.dirichlet]]\nboundary = \"left\"\nux = 0.0\n[[body.dirichlet]]\nboundary = \"bottom\"\nuy = 0.0\n"
      "[[body]]\nname = \"rubber\"\nmesh = \"split.geo\"\nmesh_parameters = { h = 0.1 }\ngroup = \"rubber\"\n"
      "material = { E = " + std::to_string(kE2) + ", nu = 0.0 }\n"
      "[[body.dirichlet]]\nboundary = \"bottom\"\nuy = 0.0\n"
      "[[body.traction]]\nboundary = \"right\"\ntraction = [" + std::to_string(t) + ", 0.0]\n"
      "[[contact]]\na = \"steel.interface\"\nb = \"rubber.interface\"\n";
  const auto two = solve_case(two_bodies, dir);
  const double one_error = worst_error(*one, t), two_error = worst_error(*two, t);
  std::printf("one body: %.2e, two bodies in contact: %.2e of the tip displacement\n", one_error, two_error);
  EXPECT_LT(one_error, 1e-10);
  EXPECT_LT(two_error, 1e-10);
}

TEST(Bimaterial, NeoHookeanBarOfTwoMaterialsMeetsTheSmallStrainFigure) {
  const std::string dir = bar_folder();
  const double t = 1e-4;  // strain t / E2 = 1e-5 in the softer half
  const auto c = solve_case(header("plane_strain", 1) + one_body("model = \"neo_hookean\"\n", t), dir);
  const double error = worst_error(*c, t);
  std::printf("neo-Hookean: worst nodal error %.2e of the tip displacement\n", error);
  EXPECT_LT(error, 3.0 * t / kE2);  // a few times the strain of the softer half
}

}  // namespace
}  // namespace symcontact::testing
