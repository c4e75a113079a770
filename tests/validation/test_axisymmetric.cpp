// Axisymmetric bodies (problem.model = "axisymmetric", issue #22): sections in the (r, z) = (x, y) plane,
// every integral over the whole ring (2π r). Three closed forms:
//
//  - Lamé tube with free ends under internal pressure p (inner radius a, outer b, E, ν): the plane-stress
//    Lamé field σ_rr = A − B/r², σ_θθ = A + B/r², σ_zz = 0, A = p a²/(b² − a²), B = p a² b²/(b² − a²),
//    u_r = ((1 − ν) A r + (1 + ν) B / r)/E, u_z = −2νA z/E. σ_rr + σ_θθ = 2A is constant, so ε_zz is, and
//    this field is an exact solution of 3D elasticity for a tube of any length with traction-free ends
//    (Timoshenko & Goodier, Theory of Elasticity, 3rd ed. 1970, §28 and §140) — not only a thin-disc
//    approximation. The half tube z ∈ [0, L] with u_z = 0 on z = 0 (its plane of symmetry) is modelled.
//  - Press fit of two such rings of the same length (inner ring a..b, outer ring b..c, both free ends,
//    frictionless interface at r = b): the inner ring's bore is pushed out by u_r(a) = δ, so that the
//    interface closes under a pressure p. Each ring carries a Lamé field; the three conditions u_i(a) = δ,
//    σ_rr,i(b) = −p = σ_rr,o(b) (the outer ring free at c) and u_i(b) = u_o(b) give A_i, B_i and p. The two
//    rings' axial strains differ (−2νA/E each), which the frictionless interface lets them take.
//  - Hertz (V2, VALIDATION.md) solved on the section of the sphere: a quarter disc of radius R = 1 on a
//    rigid plane, the load P = 0.01 of the whole sphere as the pressure P/(πR²) on its equatorial cut;
//    a = (3PR/(4E*))^(1/3), p0 = 3P/(2πa²). The same tolerances as the 3D model: a within max(2 %, one
//    element), p0 within 5 %; the total contact force equals the applied load to 1e-8, which checks that
//    the contact and the load integrals take the same 2π r.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

#include "support/solve_case.hpp"
#include "symcontact/post/stress_recovery.hpp"

using namespace symcontact;
using namespace symcontact::testing;

namespace {

constexpr double kE = 1.0, kNu = 0.3;

/// A Lamé field: σ_rr = A − B/r², u_r = ((1 − ν) A r + (1 + ν) B / r)/E.
struct Lame {
  double A = 0, B = 0;
  double sigma_rr(double r) const { return A - B / (r * r); }
  double sigma_tt(double r) const { return A + B / (r * r); }
  double u_r(double r) const { return ((1 - kNu) * A * r + (1 + kNu) * B / r) / kE; }
  double eps_zz() const { return -2 * kNu * A / kE; }
};

/// The .geo of a ring section [r0, r1] × [0, L] of element size h, its groups prefixed by `name`:
/// `name` (surface), `name`_bore (r = r0), `name`_face (r = r1), `name`_bottom (z = 0); first point tag `p`.
std::string ring_geo(const std::string& name, double r0, double r1, double L, double h, int p) {
  char b[1024];
  std::snprintf(b, sizeof b,
                "Point(%d) = {%.17g, 0, 0, %.17g}; Point(%d) = {%.17g, 0, 0, %.17g};\n"
                "Point(%d) = {%.17g, %.17g, 0, %.17g}; Point(%d) = {%.17g, %.17g, 0, %.17g};\n"
                "Line(%d) = {%d, %d}; Line(%d) = {%d, %d}; Line(%d) = {%d, %d}; Line(%d) = {%d, %d};\n"
                "Curve Loop(%d) = {%d, %d, %d, %d}; Plane Surface(%d) = {%d};\n"
                "Physical Surface(\"%s\") = {%d};\n"
                "Physical Curve(\"%s_bottom\") = {%d}; Physical Curve(\"%s_face\") = {%d};\n"
                "Physical Curve(\"%s_bore\") = {%d};\n",
                p, r0, h, p + 1, r1, h, p + 2, r1, L, h, p + 3, r0, L, h,  //
                p, p, p + 1, p + 1, p + 1, p + 2, p + 2, p + 2, p + 3, p + 3, p + 3, p,  //
                p, p, p + 1, p + 2, p + 3, p, p,  //
                name.c_str(), p, name.c_str(), p, name.c_str(), p + 1, name.c_str(), p + 3);
  return b;
}

std::string body_toml(const std::string& name, const std::string& extra) {
  return "[[body]]\nname = \"" + name + "\"\nmesh = \"rings.geo\"\ngroup = \"" + name +
         "\"\n[body.material]\nE = 1.0\nnu = 0.3\n[[body.dirichlet]]\nboundary = \"" + name +
         "_bottom\"\nuy = 0.0\n" + extra;
}

constexpr const char* kHead = "[problem]\ndimension = 2\nmodel = \"axisymmetric\"\norder = 2\n\n";

/// Largest |u_r − exact| over the nodes of body b, relative to the largest |exact u_r|.
double radial_error(const SolvedCase& c, int b, const Lame& exact) {
  const Mesh& mesh = c.model->bodies()[b]->mesh;
  double err = 0, scale = 0;
  for (Index v = 0; v < mesh.num_nodes(); ++v) {
    const double r = mesh.x(0, v);
    err = std::max(err, std::abs(c.u[c.model->dofs().dof(b, v, 0)] - exact.u_r(r)));
    scale = std::max(scale, std::abs(exact.u_r(r)));
  }
  return err / scale;
}

}  // namespace

TEST(Axisymmetric, LameTubeUnderInternalPressureMatchesTheClosedForm) {
  const double a = 1.0, b = 2.0, L = 1.0, p = 0.01;
  const Lame exact{p * a * a / (b * b - a * a), p * a * a * b * b / (b * b - a * a)};
  const std::string dir = test_temp_dir("axisym_lame");
  double previous = 1.0;
  for (double h : {0.25, 0.125}) {
    write_text(dir, "rings.geo", ring_geo("tube", a, b, L, h, 1));
    char load[160];
    std::snprintf(load, sizeof load, "[[body.pressure]]\nboundary = \"tube_bore\"\npressure = %.17g\n", p);
    const auto c = solve_case(std::string(kHead) + body_toml("tube", load), dir);
    const double err = radial_error(*c, 0, exact);
    // u_z of the top face, and σ_θθ at the bore's nodes (nodal recovery).
    const Mesh& mesh = c->model->bodies()[0]->mesh;
    const BodyFields f = recover_fields(*c->model->bodies()[0], c->model->dofs(), 0, c->u);
    double uz_err = 0, hoop_err = 0;
    for (Index v = 0; v < mesh.num_nodes(); ++v) {
      if (std::abs(mesh.x(1, v) - L) < 1e-12)
        uz_err = std::max(uz_err, std::abs(c->u[c->model->dofs().dof(0, v, 1)] - exact.eps_zz() * L));
      if (std::abs(mesh.x(0, v) - a) < 1e-12)
        hoop_err = std::max(hoop_err, std::abs(f.stress(2, v) / exact.sigma_tt(a) - 1));
    }
    std::printf("  Lamé tube h = %.3f: max |u_r error| / max u_r = %.2e, top u_z error / |ε_zz L| = %.2e, "
                "bore σ_θθ error %.2e\n", h, err, uz_err / std::abs(exact.eps_zz() * L), hoop_err);
    EXPECT_LT(err, 1e-3) << "h = " << h;
    EXPECT_LT(uz_err, 1e-3 * std::abs(exact.eps_zz() * L)) << "h = " << h;
    EXPECT_LT(hoop_err, 0.02) << "h = " << h;
    EXPECT_LT(err, previous) << "the error falls under refinement";
    previous = err;
    // The reaction of the plane of symmetry: σ_zz = 0, so none (whole ring).
    const Eigen::VectorXd& R = c->reactions.back().at(0);
    EXPECT_LT(std::abs(R[1]), 1e-3 * p * 2 * M_PI * a * L);
  }
}

TEST(Axisymmetric, PressFitOfTwoRingsMatchesTheLameClosedForm) {
  const double a = 1.0, b = 1.5, c_ = 2.0, L = 0.5, delta = 1e-3, h = 0.0625;
  // Unknowns (A_i, B_i, p): u_i(a) = δ; σ_rr,i(b) = −p; u_i(b) = u_o(b) with the outer ring's
  // u_o(b) = (p b / E) ((c² + b²)/(c² − b²) + ν).
  Eigen::Matrix3d M;
  M << (1 - kNu) * a / kE, (1 + kNu) / (a * kE), 0.0,  //
      1.0, -1.0 / (b * b), 1.0,                          //
      (1 - kNu) * b / kE, (1 + kNu) / (b * kE), -(b / kE) * ((c_ * c_ + b * b) / (c_ * c_ - b * b) + kNu);
  const Eigen::Vector3d s = M.lu().solve(Eigen::Vector3d(delta, 0.0, 0.0));
  const double p = s[2];
  const Lame inner{s[0], s[1]};
  const Lame outer{p * b * b / (c_ * c_ - b * b), p * b * b * c_ * c_ / (c_ * c_ - b * b)};

  const std::string dir = test_temp_dir("axisym_press_fit");
  write_text(dir, "rings.geo", ring_geo("inner", a, b, L, h, 1) + ring_geo("outer", b, c_, L, h, 11));
  char bore[160];
  std::snprintf(bore, sizeof bore, "[[body.dirichlet]]\nboundary = \"inner_bore\"\nux = %.17g\n", delta);
  const std::string toml = std::string(kHead) + body_toml("inner", bore) + body_toml("outer", "") +
                           "[[contact]]\nname = \"fit\"\na = \"inner.inner_face\"\nb = \"outer.outer_bore\"\n";
  const auto c = solve_case(toml, dir);

  const ContactSideResult& side = c->contact.at(0).sides.at(0);
  double p_err = 0;
  for (Index k = 0; k < side.pressure.size(); ++k) p_err = std::max(p_err, std::abs(side.pressure[k] / p - 1));
  // Whole-ring forces: the interface carries p · 2π b L; the support of the bore pushes the inner ring out
  // with −σ_rr,i(a) · 2π a L (the reaction: the force of the support on the body).
  const double ring_force = p * 2 * M_PI * b * L;
  const double fn = std::abs(c->contact[0].total_force[0]);
  const double bore_force = c->reactions.back().at(1)[0];  // boundaries: inner_bottom, inner_bore, outer_bottom
  const double bore_exact = -inner.sigma_rr(a) * 2 * M_PI * a * L;
  std::printf("  press fit h = %.4f: p = %.6e (closed form), nodal pressure error %.2e, ring force %.2e "
              "(error %.2e), bore force error %.2e, u_r error inner %.2e outer %.2e\n",
              h, p, p_err, fn, fn / ring_force - 1, bore_force / bore_exact - 1, radial_error(*c, 0, inner),
              radial_error(*c, 1, outer));
  EXPECT_LT(p_err, 5e-3);
  EXPECT_NEAR(fn, ring_force, 1e-3 * ring_force);
  EXPECT_NEAR(bore_force, bore_exact, 1e-3 * std::abs(bore_exact));
  EXPECT_LT(radial_error(*c, 0, inner), 1e-3);
  EXPECT_LT(radial_error(*c, 1, outer), 1e-3);
}

namespace {

/// The section of the sphere of radius 1 (centre (0, 1)): the quarter disc r ∈ [0, 1] below its equator,
/// element size h at the south pole (the contact point) and H away from it.
std::string sphere_section_geo(double h) {
  char b[1024];
  std::snprintf(b, sizeof b,
                "Point(1) = {0, 1, 0, 0.1}; Point(2) = {0, 0, 0, %.17g}; Point(3) = {1, 1, 0, 0.1};\n"
                "Circle(1) = {2, 1, 3}; Line(2) = {3, 1}; Line(3) = {1, 2};\n"
                "Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};\n"
                "Field[1] = Distance; Field[1].PointsList = {2};\n"
                "Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = %.17g; Field[2].SizeMax = 0.1;\n"
                "Field[2].DistMin = 0.25; Field[2].DistMax = 0.6; Background Field = 2;\n"
                "Physical Surface(\"sphere\") = {1}; Physical Curve(\"contact\") = {1};\n"
                "Physical Curve(\"load\") = {2}; Physical Curve(\"axis\") = {3};\n",
                h, h);
  return b;
}

}  // namespace

TEST(Axisymmetric, SphereOnRigidPlaneMatchesHertz) {
  const double P = 0.01, Estar = kE / (1 - kNu * kNu);
  const std::string dir = test_temp_dir("axisym_hertz");
  for (int order : {1, 2}) {
    const double h = order == 1 ? 0.01 : 0.02;
    write_text(dir, "sphere.geo", sphere_section_geo(h));
    const std::string toml = std::string("[problem]\ndimension = 2\nmodel = \"axisymmetric\"\norder = ") +
                             std::to_string(order) +
                             "\n[[body]]\nname = \"sphere\"\nmesh = \"sphere.geo\"\ngroup = \"sphere\"\n"
                             "[body.material]\nE = 1.0\nnu = 0.3\n[[body.dirichlet]]\nboundary = \"axis\"\nux = 0.0\n"
                             "[[body.pressure]]\nboundary = \"load\"\npressure = 0.0031830988618379067\n"
                             "[[contact]]\nname = \"floor\"\na = \"sphere.contact\"\n[contact.obstacle]\n"
                             "type = \"plane\"\npoint = [0.0, 0.0]\nnormal = [0.0, 1.0]\n";
    const auto c = solve_case(toml, dir);
    // The applied load: the resultant of the pressure on the meshed cut (whole ring).
    const VectorXd f = c->model->external_load();
    const Mesh& mesh = c->model->bodies()[0]->mesh;
    double load = 0;
    for (Index v = 0; v < mesh.num_nodes(); ++v) load -= f[c->model->dofs().dof(0, v, 1)];
    const double a_ref = std::cbrt(3 * load / (4 * Estar)), p0_ref = 3 * load / (2 * M_PI * a_ref * a_ref);
    const ContactSideResult& side = c->contact.at(0).sides.at(0);
    double p0 = 0, a_meas = 0;
    for (Index k = 0; k < side.pressure.size(); ++k) p0 = std::max(p0, side.pressure[k]);
    for (Index k = 0; k < side.pressure.size(); ++k)
      if (side.pressure[k] > 1e-3 * p0) a_meas = std::max(a_meas, side.X(0, k));
    const double force = c->contact[0].total_force[1];
    std::printf("  axisymmetric Hertz P%d h = %.3f: load %.8f (P %+.2f%%), p0 = %.6f (err %+.2f%%), a = %.5f "
                "(err %+.2f%%, %.2f elements), force / load - 1 = %.1e\n",
                order, h, load, 100 * (load / P - 1), p0, 100 * (p0 / p0_ref - 1), a_meas,
                100 * (a_meas / a_ref - 1), std::abs(a_meas - a_ref) / h, force / load - 1);
    EXPECT_NEAR(p0, p0_ref, 0.05 * p0_ref) << "order " << order;
    EXPECT_NEAR(a_meas, a_ref, std::max(0.02 * a_ref, h)) << "order " << order;
    EXPECT_NEAR(force, load, 1e-8 * load) << "order " << order;
    EXPECT_NEAR(load, P, 1e-6 * P) << "order " << order;  // a straight cut: exact up to quadrature
  }
}

TEST(Axisymmetric, ASectionReachingNegativeRadiusIsAnInputError) {
  const std::string dir = test_temp_dir("axisym_negative_r");
  write_text(dir, "rings.geo", ring_geo("tube", -0.5, 1.0, 1.0, 0.25, 1));
  try {
    solve_case(std::string(kHead) + body_toml("tube", ""), dir);
    FAIL() << "a section across the axis was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "body[0].mesh");
    EXPECT_NE(std::string(e.what()).find("x = r = -0.5"), std::string::npos) << e.what();
  }
}

// A Neo-Hookean cylinder r ≤ 1, z ∈ [0, 1] (E = 1, ν = 0.3) stretched radially to λ = 1.5 by its mantle
// (u_r = (λ − 1) r there), its bottom on rollers, its top free: the deformation is homogeneous,
// F = diag(λ, λ_z, λ) in (r, z, θ) with λ_z from σ_zz = 0 — P_zz = μ (λ_z − 1/λ_z) + λ_L ln J / λ_z = 0,
// J = λ² λ_z (materials/hyperelastic.hpp) — so the finite-strain axisymmetric kernel (F_θθ = 1 + u_r/R)
// must give it to round-off: u_z = (λ_z − 1) z at every node, and the mantle's radial reaction is
// P_rr 2π R H (first Piola–Kirchhoff stress times the reference area) with P_rr = μ (λ − 1/λ) + λ_L ln J / λ.
TEST(Axisymmetric, NeoHookeanRadialStretchIsHomogeneous) {
  const double lambda = 1.5, mu = kE / (2 * (1 + kNu)), lame = kE * kNu / ((1 + kNu) * (1 - 2 * kNu));
  double lz = 1.0;
  for (int it = 0; it < 50; ++it) {  // Newton on P_zz(λ_z) = 0
    const double J = lambda * lambda * lz;
    const double f = mu * (lz - 1 / lz) + lame * std::log(J) / lz;
    const double df = mu * (1 + 1 / (lz * lz)) + lame * (1 - std::log(J)) / (lz * lz);
    lz -= f / df;
  }
  const double P_rr = mu * (lambda - 1 / lambda) + lame * std::log(lambda * lambda * lz) / lambda;
  const std::string dir = test_temp_dir("axisym_stretch");
  for (int order : {1, 2}) {
    write_text(dir, "rings.geo", ring_geo("disc", 0.0, 1.0, 1.0, 0.2, 1));
    char extra[512];
    std::snprintf(extra, sizeof extra,
                  "[[body.dirichlet]]\nboundary = \"disc_bore\"\nux = 0.0\n"
                  "[[body.dirichlet]]\nboundary = \"disc_face\"\nux = \"%.17g * x * t\"\n",
                  lambda - 1);
    std::string toml = std::string(kHead) + "[steps]\ncount = 4\n" + body_toml("disc", extra);
    toml.replace(toml.find("order = 2"), 9, "order = " + std::to_string(order));
    toml.replace(toml.find("E = 1.0"), 7, "model = \"neo_hookean\"\nE = 1.0");
    const auto c = solve_case(toml, dir);
    const Mesh& mesh = c->model->bodies()[0]->mesh;
    double err = 0;
    for (Index v = 0; v < mesh.num_nodes(); ++v) {
      err = std::max(err, std::abs(c->u[c->model->dofs().dof(0, v, 0)] - (lambda - 1) * mesh.x(0, v)));
      err = std::max(err, std::abs(c->u[c->model->dofs().dof(0, v, 1)] - (lz - 1) * mesh.x(1, v)));
    }
    const double reaction = c->reactions.back().at(2)[0];  // disc_bottom, disc_bore, disc_face
    const double exact = P_rr * 2 * M_PI * 1.0 * 1.0;
    std::printf("  Neo-Hookean radial stretch λ = %.2f, P%d: λ_z = %.10f, displacement error %.2e, mantle "
                "reaction %.12f (closed form %.12f, %.1e)\n",
                lambda, order, lz, err, reaction, exact, reaction / exact - 1);
    EXPECT_LT(err, 1e-9) << "order " << order;
    EXPECT_NEAR(reaction, exact, 1e-8 * exact) << "order " << order;
  }
}

// The finite-strain axisymmetric model against the 3D model of the same body: a Neo-Hookean tube a = 1,
// b = 2, half length L = 1 (E = 1, ν = 0.3; u_z = 0 on its plane of symmetry z = 0, the other end free),
// its bore under a pressure p = 0.1 that opens it by about 20 % (dead load, the reference normal: the
// same in both models). The section [a, b] × [0, L] is meshed with 4 × 4 transfinite Quad9; the 3D model
// is that section revolved by 90° about the axis in `layers` layers of Hex27 (the quarter tube, u = 0
// normal to its two cut planes). No closed form is needed: both discretise the same section, so the 3D
// nodes lie on the axisymmetric ones' circles, and what differs is only the circumferential
// discretisation of the 3D model, which must fall as the layers are refined: below 1e-2 of the bore's
// opening with 3 layers, 1e-3 with 6, and by more than 4 between them (measured 3.3e-3 and 2.8e-4).
namespace {

/// The tube's section (dim 2) or the quarter tube (dim 3, revolved about the y axis from the plane z = 0
/// towards x = 0): groups "tube", "tube_bottom" (y = 0), "tube_bore" (r = a), and in 3D "cut_z" (z = 0),
/// "cut_x" (x = 0).
std::string tube_geo(int dim, int layers) {
  std::string g =
      "Point(1) = {1, 0, 0}; Point(2) = {2, 0, 0}; Point(3) = {2, 1, 0}; Point(4) = {1, 1, 0};\n"
      "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
      "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
      "Transfinite Curve{1, 2, 3, 4} = 5; Transfinite Surface{1}; Recombine Surface{1};\n";
  if (dim == 2)
    return g + "Physical Surface(\"tube\") = {1};\nPhysical Curve(\"tube_bottom\") = {1};\n"
               "Physical Curve(\"tube_bore\") = {4};\n";
  return g + "out[] = Extrude {{0, 1, 0}, {0, 0, 0}, Pi / 2} { Surface{1}; Layers{" + std::to_string(layers) +
         "}; Recombine; };\n"
         "Physical Volume(\"tube\") = {out[1]};\nPhysical Surface(\"tube_bottom\") = {out[2]};\n"
         "Physical Surface(\"tube_bore\") = {out[5]};\nPhysical Surface(\"cut_z\") = {1};\n"
         "Physical Surface(\"cut_x\") = {out[0]};\n";
}

std::unique_ptr<SolvedCase> solve_tube(int dim, int layers, const std::string& dir) {
  write_text(dir, "tube.geo", tube_geo(dim, layers));
  std::string toml = dim == 2 ? "[problem]\ndimension = 2\nmodel = \"axisymmetric\"\norder = 2\n"
                              : "[problem]\ndimension = 3\norder = 2\n";
  toml += "[steps]\ncount = 4\n[[body]]\nname = \"tube\"\nmesh = \"tube.geo\"\ngroup = \"tube\"\n"
          "[body.material]\nmodel = \"neo_hookean\"\nE = 1.0\nnu = 0.3\n"
          "[[body.dirichlet]]\nboundary = \"tube_bottom\"\nuy = 0.0\n"
          "[[body.pressure]]\nboundary = \"tube_bore\"\npressure = 0.1\n";
  if (dim == 3)
    toml += "[[body.dirichlet]]\nboundary = \"cut_z\"\nuz = 0.0\n[[body.dirichlet]]\nboundary = \"cut_x\"\nux = 0.0\n";
  return solve_case(toml, dir);
}

}  // namespace

TEST(Axisymmetric, NeoHookeanTubeMatchesTheRevolved3DModel) {
  const std::string dir = test_temp_dir("axisym_vs_3d");
  const auto axi = solve_tube(2, 0, dir);
  const Mesh& section = axi->model->bodies()[0]->mesh;
  // (r, z) of a node, rounded, → its axisymmetric displacement (u_r, u_z).
  auto key = [](double r, double z) { return std::make_pair(std::lround(r * 1e6), std::lround(z * 1e6)); };
  std::map<std::pair<long, long>, Eigen::Vector2d> by_position;
  double bore_opening = 0.0;
  for (Index v = 0; v < section.num_nodes(); ++v) {
    const Eigen::Vector2d u(axi->u[axi->model->dofs().dof(0, v, 0)], axi->u[axi->model->dofs().dof(0, v, 1)]);
    by_position[key(section.x(0, v), section.x(1, v))] = u;
    bore_opening = std::max(bore_opening, std::abs(u[0]));
  }
  ASSERT_GT(bore_opening, 0.15);  // finite strain: the bore opens by more than 15 %
  double previous = 1.0;
  for (int layers : {3, 6}) {
    const auto solid = solve_tube(3, layers, dir);
    const Mesh& mesh = solid->model->bodies()[0]->mesh;
    double err = 0.0;
    Index matched = 0;
    for (Index v = 0; v < mesh.num_nodes(); ++v) {
      const double x = mesh.x(0, v), y = mesh.x(1, v), z = mesh.x(2, v), r = std::hypot(x, z);
      auto it = by_position.find(key(r, y));
      if (it == by_position.end()) continue;  // a node between the section's circles (none expected)
      ++matched;
      const auto& d = solid->model->dofs();
      const double ur = (solid->u[d.dof(0, v, 0)] * x + solid->u[d.dof(0, v, 2)] * z) / r;
      const double ut = (solid->u[d.dof(0, v, 2)] * x - solid->u[d.dof(0, v, 0)] * z) / r;
      err = std::max({err, std::abs(ur - it->second[0]), std::abs(solid->u[d.dof(0, v, 1)] - it->second[1]),
                      std::abs(ut)});
    }
    err /= bore_opening;
    std::printf("  Neo-Hookean tube, bore opened by %.4f: 3D model with %d Hex27 layers over 90 degrees, "
                "largest displacement difference %.2e of it (%ld nodes matched)\n",
                bore_opening, layers, err, static_cast<long>(matched));
    EXPECT_GE(2 * matched, mesh.num_nodes()) << "the 3D nodes on the section's circles";
    EXPECT_LT(err, layers == 3 ? 1e-2 : 1e-3) << layers << " layers";
    EXPECT_LT(err, 0.25 * previous) << "the difference falls under circumferential refinement";
    previous = err;
  }
}
