// Cattaneo–Mindlin (Johnson, Contact Mechanics, 1985, §7.2): two identical elastic cylinders pressed
// together by a normal force P, then loaded tangentially by Q < μP. Elastically similar bodies: the pressure
// stays Hertz's, p(x) = p0 sqrt(1 − x²/a²), and the interface sticks in the centre, |x| < c, slips outside,
//     c = a sqrt(1 − Q / (μP)),   a = sqrt(4 P R_eff / (π E*)),  R_eff = R/2,  E* = E / (2 (1 − ν²)),
// with q(x) = μp0 sqrt(1 − x²/a²) − μp0 (c/a) sqrt(1 − x²/c²) in |x| < c. Full models (not halves: the
// tangential load breaks the symmetry), tests/data/geo/cattaneo_mindlin.geo, plane strain, E = 1, ν = 0.3,
// R = 1, μ = 0.3, Coulomb friction (the fixed point on regularised Tresca). The upper cylinder's flat top is
// moved down by δ and then sideways in four equal steps; the lower one is clamped at its flat base. P and Q
// are the reactions of the top, so the closed form needs no guess of the compliance.
// VALIDATION.md, V8. Three contact sizes at the same a/h = 13.7 (kCases):
//  - a/R = 0.11 (δ = 0.035, P ≈ 0.0103, Q/μP ≈ 0.63 at the end), arcs at h = 0.008, matching and non-matching
//    interface meshes;
//  - a/R = 0.055 (δ = 0.0107, P ≈ 0.00257, Q/μP ≈ 0.64), h = 0.004, matching and non-matching;
//  - a/R = 0.028 (δ = 0.00318, P ≈ 0.00066, Q/μP ≈ 0.63), h = 0.002, matching.
// The closed form is a half-space one, with small strains (here of order p0/E* = a/R). The finite cylinders
// depart from it in the stick zone: its relief μp − q falls short of the closed form's
// μp0 (c/a) sqrt(1 − x²/c²) by 1.2 % of μp0 at x = 0 for a/R = 0.11, 0.5 % at 0.055, 0.1 % at 0.028, the
// same a/h (1.3, 0.9, 0.1 % at half the h; docs/validation-friction.md, V8). Refining h does not remove it, and q(x)
// is held to VALIDATION.md's 2 % of μp0 at the two smaller a/R only (and on matching meshes: see kCases).
// Checked at every tangential step:
//  - the stick zone, by the law itself (nodes of the upper surface with |q| < μp, to 1e-3 of μp: a slipping
//    node of the regularised law is within 1e-3 once its slip exceeds 22α), its half-width within two elements
//    of c, and centred (its two ends within two elements of each other); nodes with p < 0.1 max p, within an
//    element of the contact zone's edge, are left out (there p(c) ≥ 0.39 p0 for the loads here);
//  - Σ of the tangential nodal contact forces on the upper body = −Q to 1e-8 (∫q = Q);
//  - no pressure where the gap is open: at nodes more than two elements outside the contact zone, |p| ≤ 1e-5
//    of the peak pressure (in weak contact the node next to the zone's edge carries the force of its
//    constraint ∫θφ_k = 0 although its own gap is open; beyond, what remains is the optimiser's force
//    defect, measured 1.7e-6 of the peak);
//  - at a/R = 0.055 and 0.028, matching meshes, after the last step: q of the upper surface at x/a = 0, 0.3, 0.5, 0.8
//    within 2 % of μp0 (printed for the other cases).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "support/solve_case.hpp"

namespace symcontact::testing {
namespace {

constexpr double kMu = 0.3;

/// One variant of the problem: the geometry's mesh parameters (cattaneo_mindlin.geo) and the load.
struct CattaneoCase {
  const char* name;
  double h;            ///< element size along the uniformly meshed contact arcs (upper body)
  double x_fine;       ///< the arcs |x| < x_fine are uniform; 0: the whole quarter arcs
  double d_min, d_max; ///< interior: h within d_min of the contact point, graded to 0.1 beyond d_max
  double depth;        ///< downward displacement of the upper top (step 1, then held)
  double ux;           ///< its sideways displacement after step 5 (steps 2–5 in equal parts)
  double alpha;        ///< regularisation α of the slip; 0: automatic
  double ipopt_tol;    ///< IPOPT's tol; 0: symcontact's default
  bool nonmatching;    ///< the lower arcs with 3/4 of the upper's nodes
  bool profile;        ///< q(x) held to the half-space profile (a/R small enough)
};

/// a/R = 0.11, 0.055 and 0.028 at a/h = 13.7, α ∝ a² below the first. The slips scale with a²
/// (μ p0 a / E*), and at a/R = 0.055 the automatic α (4e-6, 10⁻³ of the facet size) smears the stick zone's
/// edge: q at x = 0.5a is 1.8 % of μp0 higher than with α = 7e-8 (0.04 % between 7e-8 and 1.75e-8), and the
/// stick zone read from the law is 2.6 elements too wide at the last step. With α = 7e-8 the sticking nodes
/// are springs τ/α 60 times stiffer, and at IPOPT's default tol the
/// optimiser's force defect leaves up to 2.8e-5 of the peak pressure on open nodes 2–3 elements outside the
/// zone; tol = 1e-12 brings it under the 1e-5 asked. q(x) is held to the profile on matching meshes only:
/// on non-matching ones the nodal q of the finer side oscillates with the period of the mismatch (at
/// h = 0.003, every fourth node of the upper surface's stick zone 3.5 % of μp0 below the closed form, its
/// neighbours 2 % above).
const CattaneoCase kCases[] = {
    {"Matching", 0.008, 0.0, 0.2, 0.6, 0.035, 0.012, 0.0, 0.0, false, false},
    {"NonMatching", 0.008, 0.0, 0.2, 0.6, 0.035, 0.012, 0.0, 0.0, true, false},
    {"SmallContactMatching", 0.004, 0.15, 0.1, 0.3, 0.0107, 0.0034, 7e-8, 1e-12, false, true},
    {"SmallContactNonMatching", 0.004, 0.15, 0.1, 0.3, 0.0107, 0.0034, 7e-8, 1e-12, true, false},
    {"SmallerContactMatching", 0.002, 0.075, 0.05, 0.15, 0.00318, 0.00095, 1.75e-8, 1e-12, false, true},
};

std::string number(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

std::string cattaneo_geo(const CattaneoCase& k, const std::string& geo) {
  std::string w = "h = " + number(k.h) + ";\nd_min = " + number(k.d_min) + ";\nd_max = " + number(k.d_max) + ";\n";
  if (k.x_fine > 0) w += "x_fine = " + number(k.x_fine) + ";\n";
  if (k.nonmatching) w += "lower_scale = 0.75;\n";
  return w + "Include \"" + geo + "\";\n";
}

std::string cattaneo_toml(const CattaneoCase& k, const std::string& mesh) {
  return R"(
[problem]
dimension = 2
model = "plane_strain"
[steps]
load_factors = [0.0, 0.25, 0.5, 0.75, 1.0]
[[body]]
name = "upper"
mesh = ")" + mesh + R"("
group = "upper"
material = { E = 1.0, nu = 0.3 }
[[body.dirichlet]]
boundary = "upper_top"
uy = )" + number(-k.depth) + R"(
factors = [1.0, 1.0, 1.0, 1.0, 1.0]
[[body.dirichlet]]
boundary = "upper_top"
ux = )" + number(k.ux) + R"(
[[body]]
name = "lower"
mesh = ")" + mesh + R"("
group = "lower"
material = { E = 1.0, nu = 0.3 }
[[body.dirichlet]]
boundary = "lower_base"
ux = 0.0
uy = 0.0
[[contact]]
name = "interface"
a = "upper.upper_contact"
b = "lower.lower_contact"
friction = "coulomb"
mu = 0.3
)" + (k.alpha > 0 ? "alpha = " + number(k.alpha) + "\n" : std::string()) +
         (k.ipopt_tol > 0 ? "[ipopt]\ntol = " + number(k.ipopt_tol) + "\n" : std::string());
}

/// |q| of the upper surface at x/a = 0, 0.3, 0.5, 0.8, linear between its nodes, minus Cattaneo's q(x), in
/// units of μ p0. x is the reference abscissa: the closed form is a small-strain one, and the material point
/// X = 0 of either surface is the centre of the stick zone (both surfaces' stick zones are measured
/// symmetric about it; the lower surface's q agrees with the upper's there to 0.01 % of μp0).
std::vector<double> traction_profile_errors(const ContactSideResult& upper, double a, double c, double P) {
  const double p0 = 2.0 * P / (M_PI * a);
  auto exact = [&](double x) {
    double q = kMu * p0 * std::sqrt(std::max(0.0, 1.0 - x * x / (a * a)));
    if (std::abs(x) < c) q -= kMu * p0 * (c / a) * std::sqrt(1.0 - x * x / (c * c));
    return q;
  };
  std::vector<double> errors;
  for (double xa : {0.0, 0.3, 0.5, 0.8}) {
    const double x = xa * a;
    // The two nodes around x (the surface's nodes are not sorted).
    Index left = -1, right = -1;
    for (Index k = 0; k < upper.X.cols(); ++k) {
      const double xk = upper.X(0, k);
      if (xk <= x && (left < 0 || xk > upper.X(0, left))) left = k;
      if (xk > x && (right < 0 || xk < upper.X(0, right))) right = k;
    }
    if (left < 0 || right < 0) {
      ADD_FAILURE() << "no nodes around x = " << x;
      return {};
    }
    const double x0 = upper.X(0, left), x1 = upper.X(0, right);
    const double w = (x - x0) / (x1 - x0);
    const double q = (1 - w) * std::abs(upper.tangential(0, left)) + w * std::abs(upper.tangential(0, right));
    const double p = (1 - w) * upper.pressure[left] + w * upper.pressure[right];
    errors.push_back((q - exact(x)) / (kMu * p0));
    std::printf("  q(%.1f a) = %.6g, exact %.6g (%+.2f %% of mu p0); p %+.2f %% of p0 from Hertz's\n", xa, q, exact(x),
                100 * errors.back(), 100 * (p / p0 - std::sqrt(1.0 - xa * xa)));
  }
  return errors;
}

class CattaneoMindlin : public ::testing::TestWithParam<CattaneoCase> {};

TEST_P(CattaneoMindlin, StickZoneAndTangentialForceMatchTheClosedForm) {
  const CattaneoCase& k = GetParam();
  const std::string dir = test_temp_dir("cattaneo");
  write_text(dir, "cm.geo", cattaneo_geo(k, std::string(SYMCONTACT_TEST_DATA) + "/geo/cattaneo_mindlin.geo"));
  const auto c = solve_case(cattaneo_toml(k, "cm.geo"), dir);
  const auto& bounds = c->model->dirichlet_boundaries();
  ASSERT_EQ(bounds.size(), 3u);  // upper_top uy, upper_top ux, lower_base
  ASSERT_EQ(c->history.size(), 5u);
  const double E_star = 1.0 / (2.0 * (1.0 - 0.09)), R_eff = 0.5;
  for (std::size_t s = 1; s < c->history.size(); ++s) {
    const double P = -c->reactions[s][0][1];
    const double Q = c->reactions[s][1][0];
    ASSERT_GT(P, 0.0);
    ASSERT_GT(Q, 0.0);
    ASSERT_LT(Q, kMu * P);
    const double a = std::sqrt(4.0 * P * R_eff / (M_PI * E_star));
    const double c_exact = a * std::sqrt(1.0 - Q / (kMu * P));
    const ContactPairResult& pair = c->history[s][0];
    const ContactSideResult& upper = pair.sides[0];
    double lo = 0.0, hi = 0.0, p_max = upper.pressure.maxCoeff();
    for (Index n = 0; n < upper.X.cols(); ++n)
      if (upper.pressure[n] > 0.1 * p_max && std::abs(upper.tangential(0, n)) < (1 - 1e-3) * kMu * upper.pressure[n]) {
        lo = std::min(lo, upper.X(0, n));
        hi = std::max(hi, upper.X(0, n));
      }
    std::printf("step %zu: P %.6g, Q/muP %.4f, a %.5f, c %.5f, stick zone [%.5f, %.5f]\n", s + 1, P,
                Q / (kMu * P), a, c_exact, lo, hi);
    EXPECT_NEAR(hi, c_exact, 2 * k.h) << "step " << s + 1;
    EXPECT_NEAR(-lo, c_exact, 2 * k.h) << "step " << s + 1;
    EXPECT_NEAR(-lo, hi, 2 * k.h) << "step " << s + 1;
    // ∫q = Q: the tangential contact force on the upper body balances the top's reaction.
    EXPECT_NEAR(pair.total_force[0], -Q, 1e-8 * Q) << "step " << s + 1;
    for (const ContactSideResult& side : pair.sides) {
      for (Index n = 0; n < side.X.cols(); ++n) {
        if (std::abs(side.X(0, n)) > a + 2 * k.h) {
          EXPECT_LE(std::abs(side.pressure[n]), 1e-5 * p_max)
              << "step " << s + 1 << ", node " << n << " at X = " << side.X(0, n) << ", gap " << side.gap[n];
        }
      }
    }
    if (s + 1 == c->history.size()) {
      const std::vector<double> errors = traction_profile_errors(upper, a, c_exact, P);
      if (k.profile) {
        for (double e : errors) EXPECT_LE(std::abs(e), 0.02) << "q(x) against Cattaneo's, in units of mu p0";
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(V8, CattaneoMindlin, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<CattaneoCase>& i) { return std::string(i.param.name); });

}  // namespace
}  // namespace symcontact::testing
