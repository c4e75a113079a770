// Symmetry of the method: swapping the order of the two bodies (and of the pair's surfaces) in the
// problem file gives the same displacements and pressures to 1e-6 — the symmetric formulation has no
// master/slave choice to depend on. Checked on the curved two-cylinder Hertz case and on a non-matching
// flat interface.
#include <gtest/gtest.h>

#include <fstream>
#include <map>

#include "support/solve_case.hpp"

using namespace symcontact;
using namespace symcontact::testing;

namespace {

/// Swaps the two [[body]] blocks of a problem file (the text between "[[body]]" markers up to
/// "[[contact]]") and the pair's a and b.
std::string swap_bodies(const std::string& toml) {
  const std::size_t b1 = toml.find("[[body]]");
  const std::size_t b2 = toml.find("[[body]]", b1 + 1);
  const std::size_t c = toml.find("[[contact]]");
  std::string out = toml.substr(0, b1) + toml.substr(b2, c - b2) + toml.substr(b1, b2 - b1) + toml.substr(c);
  const std::size_t a = out.find("\na = "), b = out.find("\nb = ");
  const std::size_t ae = out.find('\n', a + 1), be = out.find('\n', b + 1);
  const std::string av = out.substr(a + 5, ae - a - 5), bv = out.substr(b + 5, be - b - 5);
  out.replace(b + 5, be - b - 5, av);
  out.replace(a + 5, ae - a - 5, bv);
  return out;
}

struct Field {
  std::map<std::string, VectorXd> u;         ///< per body name
  std::map<std::string, VectorXd> pressure;  ///< per surface name
};

Field fields(const SolvedCase& c) {
  Field f;
  const Model& m = *c.model;
  for (int b = 0; b < m.dofs().num_bodies(); ++b)
    f.u[m.bodies()[b]->name] = c.u.segment(m.dofs().offset(b), m.dofs().num_body_dofs(b));
  for (const auto& side : c.contact[0].sides) f.pressure[m.contacts().surfaces[side.surface].name] = side.pressure;
  return f;
}

void expect_same(const Field& x, const Field& y) {
  double umax = 0, du = 0, pmax = 0, dp = 0;
  for (const auto& [name, u] : x.u) {
    ASSERT_TRUE(y.u.count(name));
    umax = std::max(umax, u.cwiseAbs().maxCoeff());
    du = std::max(du, (u - y.u.at(name)).cwiseAbs().maxCoeff());
  }
  for (const auto& [name, p] : x.pressure) {
    ASSERT_TRUE(y.pressure.count(name));
    pmax = std::max(pmax, p.cwiseAbs().maxCoeff());
    dp = std::max(dp, (p - y.pressure.at(name)).cwiseAbs().maxCoeff());
  }
  std::printf("  max displacement difference %.2e (relative), max pressure difference %.2e (relative)\n",
              du / umax, dp / pmax);
  EXPECT_LT(du, 1e-6 * umax);
  EXPECT_LT(dp, 1e-6 * pmax);
}

std::string read(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

TEST(ContactSymmetry, SwappingBodiesChangesNothingCurvedHertz) {
  const std::string dir = std::string(SYMCONTACT_EXAMPLES) + "/hertz_2d";
  const std::string wrap = test_temp_dir("symmetry_hertz");
  write_text(wrap, "cyl.geo", "h = 0.008;\nInclude \"" + dir + "/two_cylinders.geo\";\n");
  std::string toml = read(dir + "/two_cylinders.toml");
  for (std::size_t at; (at = toml.find("two_cylinders.geo")) != std::string::npos;) toml.replace(at, 17, "cyl.geo");
  const auto c1 = solve_case(toml, wrap);
  const auto c2 = solve_case(swap_bodies(toml), wrap);
  EXPECT_EQ(c2->model->bodies()[0]->name, "lower");  // the swap happened
  expect_same(fields(*c1), fields(*c2));
}

TEST(ContactSymmetry, SwappingBodiesChangesNothingRings) {
  const std::string dir = std::string(SYMCONTACT_EXAMPLES) + "/rings_2d";
  const std::string toml = read(dir + "/rings.toml");
  const auto c1 = solve_case(toml, dir);
  // Determinism first: the same input twice gives the same numbers (Gmsh's node order is not stable
  // between runs; the reader sorts by tag).
  const auto c0 = solve_case(toml, dir);
  EXPECT_EQ((c1->u - c0->u).cwiseAbs().maxCoeff(), 0.0);
  const auto c2 = solve_case(swap_bodies(toml), dir);
  EXPECT_EQ(c2->model->bodies()[0]->name, "outer");

  expect_same(fields(*c1), fields(*c2));
}
