// Tests of the TOML problem-file reader (src/symcontact/model/problem_reader.hpp): a complete valid
// file lands field by field in the ProblemSpec, and every kind of bad input throws an InputError that
// names the file, the TOML key and what was expected.

#include "symcontact/model/problem_reader.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "support/problem_snippet.hpp"
#include "support/temp_folder.hpp"
#include "symcontact/core/error.hpp"

namespace symcontact {
namespace {

namespace fs = std::filesystem;
using testing::ProblemSnippet;

/// A folder holding the (empty) mesh files the problems refer to: the reader only checks existence.
const std::string& mesh_dir() {
  static const std::string dir = [] {
    const fs::path d = fs::path(::testing::TempDir()) / "symcontact_problem_reader";
    testing::write_placeholders(d, {"block.geo", "block.msh", "block.stl", "meshes/foundation.msh", "upper.geo",
                                    "lower.geo", "die.geo"});
    testing::write_text(d / "param.geo", "DefineConstant[ h = 0.5, n = 4 ];\n");
    return d.string();
  }();
  return dir;
}

std::string resolved(const std::string& relative) {
  return (fs::path(mesh_dir()) / relative).lexically_normal().string();
}

ProblemSpec parse(const std::string& text) { return parse_problem(text, "case.toml", mesh_dir()); }

/// The number of a value given as a number (nullopt for an unset one; an expression fails the test).
std::optional<double> number(const std::optional<LoadValue>& v) {
  if (!v) return std::nullopt;
  EXPECT_FALSE(v->is_expression()) << v->expression;
  return v->number;
}

std::vector<double> numbers(const std::vector<LoadValue>& values) {
  std::vector<double> out;
  for (const LoadValue& v : values) out.push_back(*number(v));
  return out;
}

/// A valid 2D file with one body; bad cases are one edit away from it.
const ProblemSnippet kBase(R"(title = "base"
[problem]
dimension = 2
[steps]
load_factors = [0.5, 1.0]
[[body]]
name = "block"
mesh = "block.geo"
[body.material]
E = 1.0
nu = 0.3
[[body.dirichlet]]
boundary = "bottom"
uy = 0.0
)");

TEST(ProblemReader, BaseFileIsValid) { EXPECT_NO_THROW(parse(kBase)); }

TEST(ProblemReader, NonAsciiInStringsAndCommentsIsValid) {
  // Non-ASCII text in comments, basic, literal and multi-line strings, quoted keys; a byte order mark.
  const std::string text = "\xEF\xBB\xBF# \u03bd = 0.3, in a comment\n" +
                           kBase.replaced("title = \"base\"", "title = \"Bloc d'\u00e9t\u00e9 \\\" \u03bd\"") +
                           "[ipopt]\n\"\u03bd\" = \"\"\"\u0436\n\u013e\"\"\"\nother = '''\n\u013e'''\nlit = '\u00e9'\n"
                           // a line-ending backslash, then a non-ASCII character (toml++ 3.3 alone: undefined
                           // behaviour), a character beyond the BMP, an escape next to the raw character
                           "joined = \"\"\"a \\\n  \u013e \U0001F600 \\u00e9\u00e9\"\"\"\n";
  ProblemSpec spec;
  ASSERT_NO_THROW(spec = parse(text));
  EXPECT_EQ(spec.title, "Bloc d'\u00e9t\u00e9 \" \u03bd");
  EXPECT_EQ(spec.contact_solver.friction.contact.ipopt.string_options.at("\u03bd"), "\u0436\n\u013e");
  EXPECT_EQ(spec.contact_solver.friction.contact.ipopt.string_options.at("other"), "\u013e");
  EXPECT_EQ(spec.contact_solver.friction.contact.ipopt.string_options.at("lit"), "\u00e9");
  EXPECT_EQ(spec.contact_solver.friction.contact.ipopt.string_options.at("joined"), "a \u013e \U0001F600 \u00e9\u00e9");
}

TEST(ProblemReader, CompleteFileRoundTrips) {
  const std::string text = R"(
title = "Block under pressure"

[problem]
dimension = 2
model = "plane_stress"
order = 2
mesh_size = 0.05

[steps]
load_factors = [0.5, 1]

[output]
vtu = false
summary = true

[[body]]
name = "block"
mesh = "block.geo"
group = "solid"
body_force = [0.0, -1]
body_force_factors = [0.0, 1.0]

[body.material]
model = "linear_elastic"
E = 210
nu = 0.3

[[body.dirichlet]]
boundary = "bottom"
uy = 0

[[body.dirichlet]]
boundary = "left_corner"
ux = -0.25
uy = 0.5
factors = [1.0, 2.0]

[[body.traction]]
boundary = "right"
traction = [1.5, 0.0]
factors = [0.0, 1.0]

[[body.pressure]]
boundary = "top"
pressure = 0.01

[[body.traction]]
boundary = "left"
total_force = [0.0, -3]

[[body.point_load]]
group = "left_corner"
force = [2.5, -1]
factors = [1.0, 0.0]

[[body]]
name = "foundation-2"
mesh = "meshes/../meshes/foundation.msh"
material = { E = 1e3, nu = -0.2 }

# holds the foundation, which has no boundary condition of its own (its defaults are checked below)
[[contact]]
a = "block.bottom"
b = "foundation-2.top"
)";
  const ProblemSpec spec = parse(text);
  EXPECT_EQ(spec.file, "case.toml");
  EXPECT_EQ(spec.title, "Block under pressure");
  EXPECT_EQ(spec.dim, 2);
  EXPECT_EQ(spec.model, AnalysisModel::kPlaneStress);
  EXPECT_EQ(spec.order, 2);
  EXPECT_DOUBLE_EQ(spec.mesh_size, 0.05);
  EXPECT_EQ(spec.load_factors, (std::vector<double>{0.5, 1.0}));
  EXPECT_FALSE(spec.output.vtu);
  EXPECT_TRUE(spec.output.summary);
  ASSERT_EQ(spec.bodies.size(), 2u);

  const BodySpec& b = spec.bodies[0];
  EXPECT_EQ(b.key, "body[0]");
  EXPECT_EQ(b.name, "block");
  EXPECT_EQ(b.mesh_file, "block.geo");
  EXPECT_EQ(b.mesh_path, resolved("block.geo"));
  EXPECT_EQ(b.group, "solid");
  EXPECT_EQ(b.body_force, (std::vector<double>{0.0, -1.0}));
  EXPECT_EQ(b.body_force_factors, (std::vector<double>{0.0, 1.0}));
  EXPECT_EQ(b.materials[0].key, "body[0].material");
  EXPECT_EQ(b.materials[0].model, "linear_elastic");
  EXPECT_EQ(b.materials[0].young, 210.0);
  EXPECT_EQ(b.materials[0].poisson, 0.3);

  ASSERT_EQ(b.dirichlet.size(), 2u);
  EXPECT_EQ(b.dirichlet[0].key, "body[0].dirichlet[0]");
  EXPECT_EQ(b.dirichlet[0].group, "bottom");
  EXPECT_FALSE(b.dirichlet[0].value[0].has_value());
  EXPECT_EQ(number(b.dirichlet[0].value[1]), std::optional<double>(0.0));
  EXPECT_FALSE(b.dirichlet[0].value[2].has_value());
  EXPECT_TRUE(b.dirichlet[0].factors.empty());
  EXPECT_EQ(b.dirichlet[1].key, "body[0].dirichlet[1]");
  EXPECT_EQ(b.dirichlet[1].group, "left_corner");
  EXPECT_EQ(number(b.dirichlet[1].value[0]), std::optional<double>(-0.25));
  EXPECT_EQ(number(b.dirichlet[1].value[1]), std::optional<double>(0.5));
  EXPECT_EQ(b.dirichlet[1].factors, (std::vector<double>{1.0, 2.0}));

  ASSERT_EQ(b.tractions.size(), 2u);
  EXPECT_EQ(b.tractions[0].key, "body[0].traction[0]");
  EXPECT_EQ(b.tractions[0].group, "right");
  EXPECT_EQ(b.tractions[0].input, TractionInput::kTraction);
  EXPECT_EQ(numbers(b.tractions[0].traction), (std::vector<double>{1.5, 0.0}));
  EXPECT_EQ(b.tractions[0].factors, (std::vector<double>{0.0, 1.0}));
  EXPECT_EQ(b.tractions[1].key, "body[0].traction[1]");
  EXPECT_EQ(b.tractions[1].input, TractionInput::kTotalForce);
  EXPECT_EQ(numbers(b.tractions[1].traction), (std::vector<double>{0.0, -3.0}));
  EXPECT_TRUE(b.tractions[1].factors.empty());

  ASSERT_EQ(b.point_loads.size(), 1u);
  EXPECT_EQ(b.point_loads[0].key, "body[0].point_load[0]");
  EXPECT_EQ(b.point_loads[0].group, "left_corner");
  EXPECT_EQ(b.point_loads[0].force, (std::vector<double>{2.5, -1.0}));
  EXPECT_EQ(b.point_loads[0].factors, (std::vector<double>{1.0, 0.0}));

  ASSERT_EQ(b.pressures.size(), 1u);
  EXPECT_EQ(b.pressures[0].key, "body[0].pressure[0]");
  EXPECT_EQ(b.pressures[0].group, "top");
  EXPECT_EQ(number(b.pressures[0].pressure), 0.01);
  EXPECT_TRUE(b.pressures[0].factors.empty());

  const BodySpec& f = spec.bodies[1];
  EXPECT_EQ(f.key, "body[1]");
  EXPECT_EQ(f.name, "foundation-2");
  EXPECT_EQ(f.mesh_path, resolved("meshes/foundation.msh"));
  EXPECT_TRUE(f.group.empty());
  EXPECT_TRUE(f.body_force.empty());
  EXPECT_EQ(f.materials[0].key, "body[1].material");
  EXPECT_EQ(f.materials[0].young, 1000.0);
  EXPECT_EQ(f.materials[0].poisson, -0.2);
  EXPECT_TRUE(f.dirichlet.empty() && f.tractions.empty() && f.pressures.empty() && f.point_loads.empty());
}

// steps.count alone is a linear ramp; a load curve { at, values } is piecewise linear in the step number.
TEST(ProblemReader, StepCountAndLoadCurves) {
  const ProblemSpec ramp = parse(kBase.replaced("load_factors = [0.5, 1.0]", "count = 4"));
  EXPECT_EQ(ramp.load_factors, (std::vector<double>{0.25, 0.5, 0.75, 1.0}));
  const ProblemSpec curve = parse(
      kBase.replaced("load_factors = [0.5, 1.0]", "count = 5\nload_factors = { at = [0, 2, 6], values = [0, 1, 3] }"));
  EXPECT_EQ(curve.load_factors, (std::vector<double>{0.5, 1.0, 1.5, 2.0, 2.5}));
  const ProblemSpec own = parse(kBase.replaced("load_factors = [0.5, 1.0]", "count = 4").replaced("uy = 0.0",
                                         "uy = 0.0\nfactors = { at = [0, 1, 4], values = [0, 1, -2] }"));
  EXPECT_EQ(own.bodies[0].dirichlet[0].factors, (std::vector<double>{1.0, 0.0, -1.0, -2.0}));
}

TEST(ProblemReader, DefaultsIn3D) {
  const ProblemSpec spec = parse(R"(
[problem]
dimension = 3
[[body]]
name = "cube"
mesh = "block.msh"
body_force = [0, 0, -9.81]
[body.material]
E = 1
nu = 0
[[body.dirichlet]]
boundary = "base"
uz = 0
[[body.traction]]
boundary = "side"
traction = [1, 2, 3]
)");
  EXPECT_EQ(spec.title, "");
  EXPECT_EQ(spec.dim, 3);
  EXPECT_EQ(spec.model, AnalysisModel::kThreeD);
  EXPECT_EQ(spec.order, 1);
  EXPECT_EQ(spec.mesh_size, 0.0);
  EXPECT_EQ(spec.load_factors, (std::vector<double>{1.0}));
  EXPECT_TRUE(spec.output.vtu);
  EXPECT_TRUE(spec.output.summary);
  ASSERT_EQ(spec.bodies.size(), 1u);
  EXPECT_EQ(spec.bodies[0].materials[0].model, "linear_elastic");
  EXPECT_EQ(spec.bodies[0].body_force, (std::vector<double>{0.0, 0.0, -9.81}));
  EXPECT_EQ(number(spec.bodies[0].dirichlet[0].value[2]), std::optional<double>(0.0));
  EXPECT_EQ(numbers(spec.bodies[0].tractions[0].traction), (std::vector<double>{1.0, 2.0, 3.0}));
}

// A string where a Dirichlet component, a pressure or a traction component takes a number is an expression,
// kept as written; numbers beside it stay numbers.
TEST(ProblemReader, ExpressionsForDirichletPressureAndTraction) {
  const ProblemSpec spec = parse(kBase.replaced("uy = 0.0", "uy = \"(cos(0.1*t)-1)*y + sin(0.1*t)*x\"\nux = 0") +
                                 "[[body.pressure]]\nboundary = \"top\"\npressure = \"9.81*(1 - y)*t\"\n"
                                 "[[body.traction]]\nboundary = \"right\"\ntraction = [2.5, \"x*t\"]\n");
  const BodySpec& b = spec.bodies[0];
  EXPECT_EQ(number(b.dirichlet[0].value[0]), std::optional<double>(0.0));
  ASSERT_TRUE(b.dirichlet[0].value[1].has_value());
  EXPECT_EQ(b.dirichlet[0].value[1]->expression, "(cos(0.1*t)-1)*y + sin(0.1*t)*x");
  EXPECT_EQ(b.pressures[0].pressure.expression, "9.81*(1 - y)*t");
  ASSERT_EQ(b.tractions[0].traction.size(), 2u);
  EXPECT_EQ(number(b.tractions[0].traction[0]), 2.5);
  EXPECT_EQ(b.tractions[0].traction[1].expression, "x*t");
}

// ---- hyperelastic materials ----

TEST(ProblemReader, HyperelasticMaterialsFromYoungAndPoisson) {
  for (const char* model : {"neo_hookean", "mooney_rivlin"}) {
    const ProblemSpec spec = parse(kBase.replaced("E = 1.0", std::string("model = \"") + model + "\"\nE = 1.0"));
    const MaterialSpec& m = spec.bodies[0].materials[0];
    EXPECT_EQ(m.model, model);
    EXPECT_FALSE(m.own_constants);
    EXPECT_EQ(m.young, 1.0);
    EXPECT_EQ(m.poisson, 0.3);
  }
}

TEST(ProblemReader, NeoHookeanOwnConstants) {
  const ProblemSpec spec = parse(kBase.replaced("E = 1.0\nnu = 0.3", "model = \"neo_hookean\"\nmu = 0.5\nlambda = 1.5"));
  const MaterialSpec& m = spec.bodies[0].materials[0];
  EXPECT_EQ(m.model, "neo_hookean");
  EXPECT_TRUE(m.own_constants);
  EXPECT_EQ(m.mu, 0.5);
  EXPECT_EQ(m.lambda, 1.5);
  // Small-strain equivalent: E = μ(3λ + 2μ)/(λ + μ) = 1.375, ν = λ/(2(λ + μ)) = 0.375.
  EXPECT_DOUBLE_EQ(m.young, 1.375);
  EXPECT_DOUBLE_EQ(m.poisson, 0.375);
}

TEST(ProblemReader, MooneyRivlinOwnConstantsIn3D) {
  const ProblemSpec spec =
      parse(kBase.replaced("E = 1.0\nnu = 0.3", "model = \"mooney_rivlin\"\nc1 = 0.3\nc2 = 0\nkappa = 2").in_3d());
  const MaterialSpec& m = spec.bodies[0].materials[0];
  EXPECT_EQ(m.model, "mooney_rivlin");
  EXPECT_TRUE(m.own_constants);
  EXPECT_EQ(m.c1, 0.3);
  EXPECT_EQ(m.c2, 0.0);
  EXPECT_EQ(m.kappa, 2.0);
  // μ = 2(c1 + c2) = 0.6, K = 2: E = 9Kμ/(3K + μ), ν = (3K − 2μ)/(2(3K + μ)).
  EXPECT_DOUBLE_EQ(m.young, 9 * 2 * 0.6 / (6 + 0.6));
  EXPECT_DOUBLE_EQ(m.poisson, (6 - 1.2) / (2 * (6 + 0.6)));
}

// ---- contact ----

/// kBase plus a second body "lower" and one contact between them; bad contact cases edit it.
const ProblemSnippet kTwoBodies = kBase + R"(
[[body]]
name = "lower"
mesh = "block.msh"
material = { E = 2.0, nu = 0.25 }

[[contact]]
a = "block.bottom"
b = "lower.top"
)";

/// kBase plus one contact of block.bottom against a rigid plane.
const ProblemSnippet kPlane = kBase + R"(
[[contact]]
a = "block.bottom"
[contact.obstacle]
type = "plane"
point = [0.0, 0.0]
normal = [0.0, 1.0]
)";

/// kBase plus one contact of block.bottom against a rigid circle.
const ProblemSnippet kCircle = kBase + R"(
[[contact]]
a = "block.bottom"
[contact.obstacle]
type = "circle"
center = [0.0, -1.0]
radius = 1.0
)";

/// kBase plus one contact of block.bottom against the group "surface" of the rigid mesh die.geo.
const ProblemSnippet kMeshObstacle = kBase + R"(
[[contact]]
a = "block.bottom"
[contact.obstacle]
type = "mesh"
mesh = "die.geo"
boundary = "surface"
)";

TEST(ProblemReader, NoContactIsPureElasticity) {
  const ProblemSpec spec = parse(kBase);
  EXPECT_TRUE(spec.contacts.empty());
  EXPECT_EQ(spec.contact_solver.friction.contact.geometry_tolerance, 1e-6);
  EXPECT_EQ(spec.contact_solver.friction.contact.max_geometry_iterations, 50);
  EXPECT_EQ(spec.contact_solver.friction.coulomb_tolerance, 1e-6);
  EXPECT_EQ(spec.contact_solver.friction.max_coulomb_iterations, 50);
  EXPECT_EQ(spec.contact_solver.friction.coulomb_update, CoulombUpdate::kInsideOptimizer);
  EXPECT_TRUE(spec.contact_solver.friction.converge_past_tolerance);
  EXPECT_EQ(spec.contact_solver.max_step_cuts, 0);
  EXPECT_EQ(spec.contact_solver.friction.contact.subproblem_solver, SubproblemSolver::kDualInteriorPoint);
  EXPECT_EQ(spec.linear_solver, LinearSolverChoice::kAutomatic);
  EXPECT_TRUE(spec.contact_solver.friction.contact.ipopt.string_options.empty());
  EXPECT_TRUE(spec.contact_solver.friction.contact.ipopt.numeric_options.empty());
  EXPECT_TRUE(spec.contact_solver.friction.contact.ipopt.integer_options.empty());
}

TEST(ProblemReader, TwoBodyContactRoundTrips) {
  const ProblemSpec spec = parse(kBase + R"(
[[body]]
name = "lower"
mesh = "block.msh"
material = { E = 2.0, nu = 0.25 }

[[contact]]
name = "interface"
a = "block.bottom"
b = "lower.top.left"        # split at the first dot: the group is "top.left"
mode = "one-pass"
slave = "b"
search_distance = 0.05
geometry = "reference"

[contact_solver]
geometry_tolerance = 1e-8
max_geometry_iterations = 7

[ipopt]
tol = 1e-10
print_level = 5
mu_strategy = "adaptive"
acceptable_tol = 1
)");
  ASSERT_EQ(spec.contacts.size(), 1u);
  const ContactSpec& c = spec.contacts[0];
  EXPECT_EQ(c.key, "contact[0]");
  EXPECT_EQ(c.name, "interface");
  EXPECT_EQ(c.body_a, "block");
  EXPECT_EQ(c.boundary_a, "bottom");
  EXPECT_EQ(c.body_b, "lower");
  EXPECT_EQ(c.boundary_b, "top.left");
  EXPECT_FALSE(c.obstacle.has_value());
  EXPECT_EQ(c.mode, "one-pass");
  EXPECT_EQ(c.slave, "b");
  EXPECT_EQ(c.search_distance, 0.05);
  EXPECT_EQ(c.geometry, ContactGeometry::kReference);

  const ContactSolveOptions& s = spec.contact_solver.friction.contact;
  EXPECT_EQ(s.geometry_tolerance, 1e-8);
  EXPECT_EQ(s.max_geometry_iterations, 7);
  // Sorted by the TOML type of the value: an integer stays an integer option even for a numeric one.
  EXPECT_EQ(s.ipopt.numeric_options, (std::map<std::string, double>{{"tol", 1e-10}}));
  EXPECT_EQ(s.ipopt.integer_options, (std::map<std::string, int>{{"print_level", 5}, {"acceptable_tol", 1}}));
  EXPECT_EQ(s.ipopt.string_options, (std::map<std::string, std::string>{{"mu_strategy", "adaptive"}}));
}

TEST(ProblemReader, ContactDefaults) {
  const ProblemSpec spec = parse(kTwoBodies + "[[contact]]\na = \"lower.top\"\nb = \"block.bottom\"\n");
  ASSERT_EQ(spec.contacts.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const ContactSpec& c = spec.contacts[i];
    EXPECT_EQ(c.key, "contact[" + std::to_string(i) + "]");
    EXPECT_EQ(c.name, "contact" + std::to_string(i));
    EXPECT_EQ(c.mode, "symmetric");
    EXPECT_EQ(c.slave, "a");
    EXPECT_EQ(c.search_distance, 0.0);
    EXPECT_FALSE(c.obstacle.has_value());
    EXPECT_EQ(c.friction, "none");  // frictionless
    EXPECT_EQ(c.mu, 0.0);
    EXPECT_EQ(c.tau, 0.0);
    EXPECT_EQ(c.alpha, 0.0);        // automatic
    EXPECT_EQ(c.geometry, ContactGeometry::kCurrent);
  }
  EXPECT_EQ(spec.contacts[1].body_a, "lower");
  EXPECT_EQ(spec.contacts[1].boundary_b, "bottom");
  EXPECT_EQ(spec.contact_solver.friction.contact.geometry_tolerance, 1e-6);
  EXPECT_EQ(spec.contact_solver.friction.contact.max_geometry_iterations, 50);
  EXPECT_EQ(spec.contact_solver.friction.coulomb_tolerance, 1e-6);
  EXPECT_EQ(spec.contact_solver.friction.max_coulomb_iterations, 50);
}

/// `base` with `keys` (lines "key = value\n") added to its first [[contact]] table, after `b` or `a`.
ProblemSnippet with_contact_keys(const ProblemSnippet& base, const std::string& keys) {
  const std::string b = "b = \"lower.top\"\n";
  return base.after(base.text().find(b) != std::string::npos ? b : "a = \"block.bottom\"\n", keys);
}

TEST(ProblemReader, TrescaFriction) {
  const ProblemSpec spec = parse(with_contact_keys(kTwoBodies, "friction = \"tresca\"\ntau = 0.002\nalpha = 1e-6\n"));
  const ContactSpec& c = spec.contacts.at(0);
  EXPECT_EQ(c.friction, "tresca");
  EXPECT_EQ(c.tau, 0.002);
  EXPECT_EQ(c.alpha, 1e-6);
  EXPECT_EQ(c.mu, 0.0);

  // alpha is optional (0: automatic); a zero threshold, written as an integer, is accepted.
  const ContactSpec d = parse(with_contact_keys(kTwoBodies, "friction = \"tresca\"\ntau = 0\n")).contacts.at(0);
  EXPECT_EQ(d.friction, "tresca");
  EXPECT_EQ(d.tau, 0.0);
  EXPECT_EQ(d.alpha, 0.0);
}

TEST(ProblemReader, CoulombFriction) {
  const ProblemSpec spec = parse(with_contact_keys(kTwoBodies, "friction = \"coulomb\"\nmu = 0.3\nalpha = 2e-6\n") +
                                 "[contact_solver]\ncoulomb_tolerance = 1e-8\nmax_coulomb_iterations = 12\n"
                                 "max_step_cuts = 3\nsubproblem_solver = \"dual_ipopt\"\nconverge_past_tolerance = false\n"
                                 "coulomb_update = \"between_solves\"\nwarm_start = \"interior_point\"\n"
                                 "ipopt_problem = \"uncondensed\"\n");
  const ContactSpec& c = spec.contacts.at(0);
  EXPECT_EQ(c.friction, "coulomb");
  EXPECT_EQ(c.mu, 0.3);
  EXPECT_EQ(c.alpha, 2e-6);
  EXPECT_EQ(c.tau, 0.0);
  EXPECT_EQ(spec.contact_solver.friction.coulomb_tolerance, 1e-8);
  EXPECT_EQ(spec.contact_solver.friction.max_coulomb_iterations, 12);
  EXPECT_FALSE(spec.contact_solver.friction.converge_past_tolerance);
  EXPECT_EQ(spec.contact_solver.friction.coulomb_update, CoulombUpdate::kBetweenSolves);
  EXPECT_EQ(spec.contact_solver.max_step_cuts, 3);
  EXPECT_EQ(spec.contact_solver.friction.contact.subproblem_solver, SubproblemSolver::kDualIpopt);
  EXPECT_EQ(spec.contact_solver.friction.contact.warm_start, WarmStart::kInteriorPoint);
  EXPECT_EQ(spec.contact_solver.friction.contact.ipopt_problem, IpoptProblem::kUncondensed);
  EXPECT_EQ(spec.contact_solver.friction.contact.geometry_tolerance, 1e-6);  // the others keep their defaults
  EXPECT_EQ(spec.contact_solver.friction.contact.max_geometry_iterations, 50);
}

TEST(ProblemReader, LinearSolverChoices) {
  for (const auto& [text, choice] : {std::pair{"automatic", LinearSolverChoice::kAutomatic},
                                     std::pair{"direct", LinearSolverChoice::kDirect},
                                     std::pair{"iterative", LinearSolverChoice::kIterative}})
    EXPECT_EQ(parse(kTwoBodies + "[contact_solver]\nlinear_solver = \"" + text + "\"\n").linear_solver, choice) << text;
}

TEST(ProblemReader, FrictionAgainstAnObstacle) {
  const ContactSpec c = parse(with_contact_keys(kPlane, "friction = \"coulomb\"\nmu = 1\n")).contacts.at(0);
  EXPECT_EQ(c.friction, "coulomb");
  EXPECT_EQ(c.mu, 1.0);
  EXPECT_EQ(c.alpha, 0.0);
  ASSERT_TRUE(c.obstacle.has_value());

  const ContactSpec d = parse(with_contact_keys(kCircle, "friction = \"none\"\n")).contacts.at(0);
  EXPECT_EQ(d.friction, "none");
}

TEST(ProblemReader, BodyHeldOnlyByAContactIsValid) {
  // No Dirichlet condition, but a contact with an obstacle or another body that can hold it.
  const std::string no_support = "[[body.dirichlet]]\nboundary = \"bottom\"\nuy = 0.0\n";
  EXPECT_NO_THROW(parse(kPlane.replaced(no_support, "")));
  EXPECT_NO_THROW(parse(kTwoBodies.replaced(no_support, "") + "[[body.dirichlet]]\nboundary = \"bottom\"\nuy = 0.0\n"));
}

TEST(ProblemReader, SelfContactIsAllowed) {
  const ProblemSpec spec = parse(kBase + "[[contact]]\na = \"block.skin\"\nb = \"block.skin\"\n");
  ASSERT_EQ(spec.contacts.size(), 1u);
  EXPECT_EQ(spec.contacts[0].body_a, "block");
  EXPECT_EQ(spec.contacts[0].body_b, "block");
  EXPECT_EQ(spec.contacts[0].boundary_a, "skin");
  EXPECT_EQ(spec.contacts[0].boundary_b, "skin");
}

TEST(ProblemReader, PlaneObstacle) {
  const ProblemSpec spec = parse(kPlane.replaced("normal = [0.0, 1.0]", "normal = [0, 2]"));
  ASSERT_EQ(spec.contacts.size(), 1u);
  const ContactSpec& c = spec.contacts[0];
  EXPECT_EQ(c.body_a, "block");
  EXPECT_EQ(c.boundary_a, "bottom");
  EXPECT_TRUE(c.body_b.empty() && c.boundary_b.empty());
  ASSERT_TRUE(c.obstacle.has_value());
  const ObstacleSpec& o = *c.obstacle;
  EXPECT_EQ(o.key, "contact[0].obstacle");
  EXPECT_EQ(o.type, "plane");
  EXPECT_EQ(o.point, (std::vector<double>{0.0, 0.0}));
  EXPECT_EQ(o.normal, (std::vector<double>{0.0, 2.0}));  // kept as given: the solver normalises
  EXPECT_TRUE(o.center.empty());
  EXPECT_TRUE(o.mesh_file.empty());
}

TEST(ProblemReader, CircleObstacleIn2D) {
  const ProblemSpec spec = parse(kCircle.after("radius = 1.0\n", "inside = true\n"));
  const ObstacleSpec& o = spec.contacts.at(0).obstacle.value();
  EXPECT_EQ(o.type, "circle");
  EXPECT_EQ(o.center, (std::vector<double>{0.0, -1.0}));
  EXPECT_EQ(o.radius, 1.0);
  EXPECT_TRUE(o.inside);
  EXPECT_FALSE(parse(kCircle).contacts.at(0).obstacle->inside);  // default: the body is outside
}

TEST(ProblemReader, SphereObstacleIn3D) {
  const ProblemSpec spec = parse(kBase.in_3d() + R"(
[[contact]]
name = "ball"
a = "block.bottom"
mode = "one-pass"
[contact.obstacle]
type = "sphere"
center = [0, 0, -2]
radius = 2
inside = false
)");
  const ContactSpec& c = spec.contacts.at(0);
  EXPECT_EQ(c.name, "ball");
  EXPECT_EQ(c.mode, "one-pass");
  EXPECT_EQ(c.slave, "a");
  const ObstacleSpec& o = c.obstacle.value();
  EXPECT_EQ(o.type, "sphere");
  EXPECT_EQ(o.center, (std::vector<double>{0.0, 0.0, -2.0}));
  EXPECT_EQ(o.radius, 2.0);
  EXPECT_FALSE(o.inside);
}

TEST(ProblemReader, MeshObstacle) {
  const ProblemSpec spec = parse(kMeshObstacle);
  const ObstacleSpec& o = spec.contacts.at(0).obstacle.value();
  EXPECT_EQ(o.key, "contact[0].obstacle");
  EXPECT_EQ(o.type, "mesh");
  EXPECT_EQ(o.mesh_file, "die.geo");
  EXPECT_EQ(o.mesh_path, resolved("die.geo"));
  EXPECT_EQ(o.boundary, "surface");
  EXPECT_TRUE(o.point.empty() && o.normal.empty() && o.center.empty());
}

#ifdef SYMCONTACT_TEST_DATA
/// The ```toml blocks of docs/input.md, docs/loads.md and docs/friction.md, in that order.
std::vector<std::string> documentation_examples() {
  std::string text;
  for (const char* page : {"input.md", "loads.md", "friction.md"}) {
    std::ifstream in(std::string(SYMCONTACT_TEST_DATA) + "/../../docs/" + page);
    EXPECT_TRUE(in) << "cannot open docs/" << page;
    std::stringstream doc;
    doc << in.rdbuf();
    text += doc.str();
  }
  std::vector<std::string> blocks;
  for (std::size_t begin = text.find("```toml\n"); begin != std::string::npos;
       begin = text.find("```toml\n", begin + 8)) {
    const std::size_t end = text.find("```", begin + 8);
    if (end == std::string::npos) break;
    blocks.push_back(text.substr(begin + 8, end - begin - 8));
  }
  return blocks;
}

// The contact examples of docs/input.md, the expression example of docs/loads.md and the friction example of
// docs/friction.md are complete, valid files too.
TEST(ProblemReader, DocumentationContactExamplesAreValid) {
  const std::vector<std::string> blocks = documentation_examples();
  ASSERT_EQ(blocks.size(), 5u)
      << "expected the complete example, two contact examples, an expression example and a friction example";

  const ProblemSpec expressions = parse(blocks[3]);
  ASSERT_EQ(expressions.bodies.size(), 1u);
  ASSERT_TRUE(expressions.bodies[0].dirichlet[0].value[1].has_value());
  EXPECT_EQ(expressions.bodies[0].dirichlet[0].value[1]->expression, "sin(0.2*t)*(x - 1) + (cos(0.2*t) - 1)*y");
  EXPECT_TRUE(expressions.bodies[0].pressures[0].pressure.is_expression());

  const ProblemSpec two_bodies = parse(blocks[1]);
  ASSERT_EQ(two_bodies.contacts.size(), 1u);
  EXPECT_EQ(two_bodies.contacts[0].name, "interface");
  EXPECT_EQ(two_bodies.contacts[0].body_b, "lower");
  EXPECT_EQ(two_bodies.contact_solver.friction.contact.ipopt.string_options.at("mu_strategy"), "adaptive");

  const ProblemSpec obstacles = parse(blocks[2]);
  ASSERT_EQ(obstacles.contacts.size(), 2u);
  EXPECT_EQ(obstacles.contacts[0].obstacle.value().type, "plane");
  EXPECT_EQ(obstacles.contacts[1].obstacle.value().type, "circle");

  const ProblemSpec friction = parse(blocks[4]);
  ASSERT_EQ(friction.contacts.size(), 1u);
  EXPECT_EQ(friction.contacts[0].friction, "coulomb");
  EXPECT_EQ(friction.contacts[0].mu, 0.3);
  EXPECT_GT(friction.contacts[0].alpha, 0.0);
  EXPECT_EQ(friction.contacts[0].obstacle.value().type, "plane");
  EXPECT_EQ(friction.contact_solver.friction.max_coulomb_iterations, 50);
}
#endif

#ifdef SYMCONTACT_TEST_DATA
// docs/input.md is documentation that must stay true: its complete example is a valid file.
TEST(ProblemReader, DocumentationExampleIsValid) {
  std::ifstream in(std::string(SYMCONTACT_TEST_DATA) + "/../../docs/input.md");
  ASSERT_TRUE(in) << "cannot open docs/input.md";
  std::stringstream doc;
  doc << in.rdbuf();
  const std::string text = doc.str();
  const std::size_t begin = text.find("```toml\n");
  ASSERT_NE(begin, std::string::npos) << "no ```toml block in docs/input.md";
  const std::size_t end = text.find("```", begin + 8);
  ASSERT_NE(end, std::string::npos);
  const ProblemSpec spec = parse(text.substr(begin + 8, end - begin - 8));
  EXPECT_EQ(spec.title, "Block under pressure");
  EXPECT_EQ(spec.load_factors.size(), 4u);
  ASSERT_EQ(spec.bodies.size(), 1u);
  EXPECT_EQ(spec.bodies[0].dirichlet.size(), 2u);
  EXPECT_EQ(spec.bodies[0].pressures[0].factors, (std::vector<double>{0.0, 0.5, 1.0, 1.0}));
}
#endif

TEST(ProblemReader, MeshParametersOfAGeo) {
  const ProblemSpec spec = parse(
      kBase.replaced("mesh = \"block.geo\"", "mesh = \"param.geo\"\nmesh_parameters = { h = 0.3, n = 7 }"));
  EXPECT_EQ(spec.bodies[0].mesh_parameters, (std::map<std::string, double>{{"h", 0.3}, {"n", 7.0}}));
  EXPECT_TRUE(parse(kBase).bodies[0].mesh_parameters.empty());
}

/// kBase with two materials, "steel" and "rubber", each on its group of cells.
const ProblemSnippet kTwoMaterials = kBase.replaced("[body.material]\nE = 1.0\nnu = 0.3\n",
                                                    "[[body.material]]\ngroup = \"steel\"\nE = 1.0\nnu = 0.3\n"
                                                    "[[body.material]]\ngroup = \"rubber\"\nE = 0.01\nnu = 0.45\n");

TEST(ProblemReader, MaterialsPerGroupOfCells) {
  const std::vector<MaterialSpec> m = parse(kTwoMaterials).bodies[0].materials;
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].key, "body[0].material[0]");
  EXPECT_EQ(m[0].group, "steel");
  EXPECT_EQ(m[0].young, 1.0);
  EXPECT_EQ(m[1].key, "body[0].material[1]");
  EXPECT_EQ(m[1].group, "rubber");
  EXPECT_EQ(m[1].poisson, 0.45);
  // One table: the whole body (no group), or the group it names.
  EXPECT_EQ(parse(kBase).bodies[0].materials[0].group, "");
  EXPECT_EQ(parse(kBase.after("[body.material]\n", "group = \"core\"\n")).bodies[0].materials[0].group, "core");
  // Hyperelastic laws may differ from group to group.
  const ProblemSpec rubbers = parse(kTwoMaterials.replaced("E = 1.0", "model = \"neo_hookean\"\nE = 1.0")
                                        .replaced("E = 0.01", "model = \"mooney_rivlin\"\nE = 0.01"));
  EXPECT_EQ(rubbers.bodies[0].materials[1].model, "mooney_rivlin");
}

TEST(ProblemReader, DefaultModelIn2DIsPlaneStrain) { EXPECT_EQ(parse(kBase).model, AnalysisModel::kPlaneStrain); }

TEST(ProblemReader, ReadsFileAndResolvesMeshAgainstItsFolder) {
  const fs::path problem = fs::path(mesh_dir()) / "meshes" / "problem.toml";
  testing::write_text(problem, kBase.replaced("mesh = \"block.geo\"", "mesh = \"../block.geo\""));
  const ProblemSpec spec = read_problem_file(problem.string());
  EXPECT_EQ(spec.file, problem.string());
  ASSERT_EQ(spec.bodies.size(), 1u);
  EXPECT_EQ(spec.bodies[0].mesh_file, "../block.geo");
  EXPECT_EQ(fs::path(spec.bodies[0].mesh_path), fs::absolute(resolved("block.geo")).lexically_normal());
}

TEST(ProblemReader, FileThatCannotBeOpened) {
  const std::string missing = (fs::path(mesh_dir()) / "no_such_problem.toml").string();
  try {
    read_problem_file(missing);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), missing);
    EXPECT_EQ(e.key(), "");
    EXPECT_NE(e.message().find("cannot open the problem file"), std::string::npos) << e.what();
  }
}

TEST(ProblemReader, ErrorsFromAFileNameTheFile) {
  const fs::path problem = fs::path(mesh_dir()) / "bad.toml";
  testing::write_text(problem, kBase.replaced("nu = 0.3", "nu = 0.7"));
  try {
    read_problem_file(problem.string());
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), problem.string());
    EXPECT_EQ(e.key(), "body[0].material.nu");
    EXPECT_EQ(std::string(e.what()), problem.string() + ": body[0].material.nu: " + e.message());
  }
}

// ---- bad input: each case is one edit of kBase ----

using testing::InputErrorCase;

class ProblemReaderBadInput : public ::testing::TestWithParam<InputErrorCase> {};

TEST_P(ProblemReaderBadInput, ThrowsInputErrorWithKeyAndMessage) {
  const InputErrorCase& c = GetParam();
  testing::expect_input_error_case([&] { parse(c.text); }, c, "case.toml");
}

const std::string kSecondBody = R"(
[[body]]
name = "block"
mesh = "block.msh"
[body.material]
E = 2.0
nu = 0.25
)";

INSTANTIATE_TEST_SUITE_P(
    ProblemReader, ProblemReaderBadInput,
    ::testing::Values(
        // syntax
        InputErrorCase{"MalformedToml", kBase.replaced("dimension = 2", "dimension = = 2"), "", "line 3, column "},
        InputErrorCase{"UnterminatedTableHeader", kBase.replaced("[steps]", "[steps"), "", "line 4, column "},
        // non-ASCII characters outside strings (toml++ 3.3 alone reaches undefined behaviour on them, found by
        // fuzzing; see toml_parse.hpp) and text that is not UTF-8
        InputErrorCase{"NonAsciiKey", kBase.replaced("nu = 0.3", "\u03bd = 0.3"), "",
                "line 11, column 1: Error while parsing root table: expected keys, tables, whitespace or comments, "
                "saw '\u03bd' (the character '\u03bd', U+03BD: outside strings and comments TOML allows ASCII only"},
        InputErrorCase{"NonAsciiAfterAKey", kBase.replaced("nu = 0.3", "nu\u013e = 0.3"), "",
                "line 11, column 3: Error while parsing key-value pair: expected '=', saw '\u013e' (the character "
                "'\u013e', U+013E: outside strings"},
        InputErrorCase{"NonAsciiInsideAnInvalidValueWithQuotes", kBase.replaced("nu = 0.3", "nu = 1'''x\"\ufee2"), "",
                "line 11, column 7: Error while parsing decimal integer: expected digit, saw '''"},
        InputErrorCase{"NonAsciiAfterAFloatAndAQuote", kBase.replaced("nu = 0.3", "nu = [0.'!!\ufe7f."), "",
                "line 11, column 9: Error while parsing floating-point: expected decimal digit"},
        InputErrorCase{"InvalidUtf8Byte", kBase.replaced("nu = 0.3", "nu = 0.3 # caf\xE9"), "",
                "line 11, column 15: the byte 0xE9 is not valid UTF-8 (the problem file must be UTF-8 encoded)"},
        InputErrorCase{"OverlongUtf8", kBase.replaced("title = \"base\"", "title = \"\xC0\xAF\""), "",
                "line 1, column 10: the byte 0xC0 is not valid UTF-8"},
        InputErrorCase{"Utf8Surrogate", kBase.replaced("title = \"base\"", "title = \"\xED\xA0\x80\""), "",
                "line 1, column 10: the byte 0xED is not valid UTF-8"},
        InputErrorCase{"TruncatedUtf8AtTheEnd", kBase + "# \xE2\x82", "", "the byte 0xE2 is not valid UTF-8"},
        InputErrorCase{"PlaneFifteenCharacter", kBase.replaced("title = \"base\"", "title = \"\U000F03BD\""), "",
                "line 1, column 10: the private-use character U+F03BD (plane 15) is not supported"},
        InputErrorCase{"SameKeyRawAndEscaped", kBase + "[ipopt]\n\"\u00e9\" = 1\n\"\\u00e9\" = 2\n", "",
                "the key \"\u00e9\" is defined twice in one table"},
        // unknown keys
        InputErrorCase{"UnknownTopLevelKey", "solver = \"ipopt\"\n" + kBase, "solver",
                "unknown key \"solver\"; allowed keys at the top level: title, problem, steps, output, body, contact, "
                "contact_solver, ipopt"},
        InputErrorCase{"UnknownProblemKey", kBase.after("dimension = 2\n", "odrer = 1\n"), "problem.odrer",
                "unknown key \"odrer\" (did you mean \"order\"?)"},
        InputErrorCase{"UnknownBodyKey", kBase.after("mesh = \"block.geo\"\n", "colour = \"red\"\n"),
                "body[0].colour", "allowed keys in body[0]: name, mesh, mesh_parameters, group, body_force"},
        InputErrorCase{"UnknownMaterialKey", kBase.after("nu = 0.3\n", "Nu = 0.3\n"), "body[0].material.Nu",
                "unknown key \"Nu\" (did you mean \"nu\"?); allowed keys in body[0].material: model, E, nu, group"},
        InputErrorCase{"UnknownDirichletKey", kBase.after("uy = 0.0\n", "value = 1.0\n"), "body[0].dirichlet[0].value",
                "allowed keys in body[0].dirichlet[0]: boundary, ux, uy, uz, factors"},
        InputErrorCase{"UnknownKeyInSecondBody", kBase + kSecondBody + "density = 7.8\n", "body[1].material.density",
                "unknown key \"density\""},
        // types
        InputErrorCase{"StringForNumber", kBase.replaced("E = 1.0", "E = \"1.0\""), "body[0].material.E",
                "expected a number, got a string (\"1.0\")"},
        InputErrorCase{"FloatForInteger", kBase.replaced("dimension = 2", "dimension = 2.0"), "problem.dimension",
                "expected an integer, got a floating-point number (2.0)"},
        InputErrorCase{"StringForBoolean", kBase + "[output]\nvtu = \"yes\"\n", "output.vtu",
                "expected a boolean (true or false), got a string"},
        InputErrorCase{"NumberForVectorEntry", kBase + "[[body.traction]]\nboundary = \"r\"\ntraction = [1.0, true]\n",
                "body[0].traction[0].traction[1]",
                "expected a number or an expression of x, y, z, t (a string), got a boolean"},
        InputErrorCase{"ExpressionSyntaxError", kBase.replaced("uy = 0.0", "uy = \"2*x +\""),
                "body[0].dirichlet[0].uy",
                "expected a number or an expression of x, y, z, t; character 6 of \"2*x +\": unexpected end of "
                "expression"},
        InputErrorCase{"ExpressionUnknownVariable", kBase + "[[body.pressure]]\nboundary = \"top\"\npressure = \"r*t\"\n",
                "body[0].pressure[0].pressure",
                "character 1 of \"r*t\": unexpected token \"r\" (the variables are x, y, z and t)"},
        InputErrorCase{"ExpressionEmpty", kBase + "[[body.traction]]\nboundary = \"r\"\ntraction = [0, \" \"]\n",
                "body[0].traction[0].traction[1]", "the expression is empty"},
        InputErrorCase{"BodyAsTable", kBase.replaced("[[body]]", "[body]"), "body",
                "expected an array of tables ([[body]]), got a table"},
        // missing keys
        InputErrorCase{"MissingProblemTable", kBase.replaced("[problem]\ndimension = 2\n", ""), "problem",
                "missing required table [problem]"},
        InputErrorCase{"MissingDimension", kBase.replaced("dimension = 2", "order = 1"), "problem.dimension",
                "missing required key (expected 2 or 3)"},
        InputErrorCase{"MissingNu", kBase.replaced("nu = 0.3\n", ""), "body[0].material.nu", "missing required key"},
        InputErrorCase{"MissingMesh", kBase.replaced("mesh = \"block.geo\"\n", ""), "body[0].mesh", "missing required key"},
        InputErrorCase{"MissingMaterial", kBase.replaced("[body.material]\nE = 1.0\nnu = 0.3\n", ""), "body[0].material",
                "missing required key"},
        InputErrorCase{"MissingPressureValue", kBase + "[[body.pressure]]\nboundary = \"top\"\n",
                "body[0].pressure[0].pressure",
                "missing required key (expected a number or an expression)"},
        InputErrorCase{"NoBody", "[problem]\ndimension = 2\n", "body", "at least one body"},
        // bodies that nothing holds (no Dirichlet condition, no contact with another body or an obstacle)
        InputErrorCase{"BodyHeldByNothing", kBase.replaced("[[body.dirichlet]]\nboundary = \"bottom\"\nuy = 0.0\n", ""), "body[0]",
                "body \"block\" has no [[body.dirichlet]] and is in no [[contact]] with another body or an obstacle: "
                "nothing holds it against rigid motion"},
        InputErrorCase{"BodyInSelfContactOnly",
                kBase.replaced("[[body.dirichlet]]\nboundary = \"bottom\"\nuy = 0.0\n", "") +
                    "[[contact]]\na = \"block.top\"\nb = \"block.bottom\"\n",
                "body[0]", "body \"block\" has no [[body.dirichlet]] and is in no [[contact]]"},
        InputErrorCase{"TwoBodiesHoldingOnlyEachOther",
                kTwoBodies.replaced("[[body.dirichlet]]\nboundary = \"bottom\"\nuy = 0.0\n", ""), "body[0]",
                "body \"block\" has no [[body.dirichlet]] and its [[contact]] pairs link it only to bodies that "
                "nothing holds either"},
        InputErrorCase{"SecondBodyHeldByNothing", kBase + "[[body]]\nname = \"lid\"\nmesh = \"block.msh\"\n"
                                                   "material = { E = 2.0, nu = 0.25 }\n",
                "body[1]", "body \"lid\" has no [[body.dirichlet]]"},
        // values
        InputErrorCase{"YoungZero", kBase.replaced("E = 1.0", "E = 0"), "body[0].material.E", "expected a number > 0, got 0"},
        InputErrorCase{"YoungNegative", kBase.replaced("E = 1.0", "E = -3.5"), "body[0].material.E", "expected a number > 0, got -3.5"},
        InputErrorCase{"PoissonHalf", kBase.replaced("nu = 0.3", "nu = 0.5"), "body[0].material.nu",
                "expected a number in (-1, 0.5), got 0.5"},
        InputErrorCase{"PoissonMinusOne", kBase.replaced("nu = 0.3", "nu = -1"), "body[0].material.nu",
                "expected a number in (-1, 0.5), got -1"},
        InputErrorCase{"PoissonNan", kBase.replaced("nu = 0.3", "nu = nan"), "body[0].material.nu", "expected a finite number, got nan"},
        InputErrorCase{"InfiniteLoadFactor", kBase.replaced("[0.5, 1.0]", "[0.5, inf]"), "steps.load_factors[1]",
                "expected a finite number, got inf"},
        InputErrorCase{"UnknownMaterialModel", kBase.replaced("E = 1.0", "model = \"saint_venant\"\nE = 1.0"), "body[0].material.model",
                "expected \"linear_elastic\", \"neo_hookean\" or \"mooney_rivlin\", got \"saint_venant\""},
        // hyperelastic materials
        InputErrorCase{"NeoHookeanConstantsForLinearElastic", kBase.after("nu = 0.3\n", "mu = 1.0\n"), "body[0].material.mu",
                "unknown key \"mu\" for model \"linear_elastic\" (mu, lambda are constants of model = \"neo_hookean\"); "
                "allowed keys in body[0].material: model, E, nu, group"},
        InputErrorCase{"MooneyRivlinConstantsForLinearElastic", kBase.after("nu = 0.3\n", "kappa = 1.0\n"),
                "body[0].material.kappa", "c1, c2, kappa are constants of model = \"mooney_rivlin\""},
        InputErrorCase{"MooneyRivlinKeyForNeoHookean", kBase.replaced("E = 1.0\nnu = 0.3", "model = \"neo_hookean\"\nc1 = 1.0"),
                "body[0].material.c1", "allowed keys in body[0].material: model, E, nu, mu, lambda, group"},
        InputErrorCase{"NeoHookeanMixedParameterSets", kBase.replaced("E = 1.0", "model = \"neo_hookean\"\nmu = 1.0\nE = 1.0"),
                "body[0].material.mu", "give either E, nu or mu, lambda for \"neo_hookean\", not both (E is also given)"},
        InputErrorCase{"MooneyRivlinMixedParameterSets",
                kBase.replaced("E = 1.0\nnu = 0.3", "model = \"mooney_rivlin\"\nnu = 0.3\nc1 = 1\nc2 = 1\nkappa = 1"),
                "body[0].material.c1", "give either E, nu or c1, c2, kappa for \"mooney_rivlin\", not both (nu is also given)"},
        InputErrorCase{"HyperelasticNoParameters", kBase.replaced("E = 1.0\nnu = 0.3", "model = \"mooney_rivlin\""), "body[0].material",
                "missing material parameters (expected E, nu or c1, c2, kappa for \"mooney_rivlin\")"},
        InputErrorCase{"NeoHookeanMissingLambda", kBase.replaced("E = 1.0\nnu = 0.3", "model = \"neo_hookean\"\nmu = 1.0"),
                "body[0].material.lambda", "missing required key"},
        InputErrorCase{"MooneyRivlinMissingKappa", kBase.replaced("E = 1.0\nnu = 0.3", "model = \"mooney_rivlin\"\nc1 = 1\nc2 = 0"),
                "body[0].material.kappa", "missing required key (expected the bulk modulus, a number > 0)"},
        InputErrorCase{"NeoHookeanMissingNu", kBase.replaced("E = 1.0\nnu = 0.3", "model = \"neo_hookean\"\nE = 1.0"),
                "body[0].material.nu", "missing required key"},
        InputErrorCase{"NeoHookeanPoissonHalf", kBase.replaced("E = 1.0\nnu = 0.3", "model = \"neo_hookean\"\nE = 1.0\nnu = 0.5"),
                "body[0].material.nu", "expected a number in (-1, 0.5), got 0.5"},
        InputErrorCase{"MooneyRivlinYoungNegative", kBase.replaced("E = 1.0", "model = \"mooney_rivlin\"\nE = -2"),
                "body[0].material.E", "expected a number > 0, got -2"},
        InputErrorCase{"NeoHookeanMuZero", kBase.replaced("E = 1.0\nnu = 0.3", "model = \"neo_hookean\"\nmu = 0\nlambda = 1"),
                "body[0].material.mu", "expected a number > 0, got 0"},
        InputErrorCase{"NeoHookeanLambdaTooNegative",
                kBase.replaced("E = 1.0\nnu = 0.3", "model = \"neo_hookean\"\nmu = 3\nlambda = -2"), "body[0].material.lambda",
                "expected a number > -2 mu / 3 = -2 (a positive bulk modulus lambda + 2 mu / 3), got -2"},
        InputErrorCase{"MooneyRivlinNegativeC2",
                kBase.replaced("E = 1.0\nnu = 0.3", "model = \"mooney_rivlin\"\nc1 = 1\nc2 = -0.5\nkappa = 1"),
                "body[0].material.c2", "expected a number >= 0, got -0.5"},
        InputErrorCase{"MooneyRivlinZeroShear",
                kBase.replaced("E = 1.0\nnu = 0.3", "model = \"mooney_rivlin\"\nc1 = 0\nc2 = 0\nkappa = 1"),
                "body[0].material.c2", "expected c1 + c2 > 0"},
        InputErrorCase{"MooneyRivlinZeroKappa",
                kBase.replaced("E = 1.0\nnu = 0.3", "model = \"mooney_rivlin\"\nc1 = 1\nc2 = 0\nkappa = 0"),
                "body[0].material.kappa", "expected a number > 0, got 0"},
        InputErrorCase{"HyperelasticPlaneStress",
                kBase.after("dimension = 2\n", "model = \"plane_stress\"\n").replaced("E = 1.0",
                         "model = \"neo_hookean\"\nE = 1.0"),
                "body[0].material.model", "needs problem.model = \"plane_strain\" or \"axisymmetric\" (or dimension = 3)"},
        InputErrorCase{"DimensionFour", kBase.replaced("dimension = 2", "dimension = 4"), "problem.dimension", "expected 2 or 3, got 4"},
        InputErrorCase{"OrderThree", kBase.after("dimension = 2\n", "order = 3\n"), "problem.order",
                "expected 1 or 2, got 3"},
        InputErrorCase{"PlaneStressIn3D", kBase.after("dimension = 2\n", "model = \"plane_stress\"\n").in_3d(),
                "problem.model", "expected \"3d\" (problem.dimension = 3), got \"plane_stress\""},
        InputErrorCase{"ThreeDModelIn2D", kBase.after("dimension = 2\n", "model = \"3d\"\n"), "problem.model",
                "expected \"plane_strain\", \"plane_stress\" or \"axisymmetric\""},
        InputErrorCase{"AxisymmetricIn3D", kBase.after("dimension = 2\n", "model = \"axisymmetric\"\n").in_3d(),
                "problem.model", "expected \"3d\" (problem.dimension = 3), got \"axisymmetric\""},
        InputErrorCase{"NonPositiveMeshSize", kBase.after("dimension = 2\n", "mesh_size = -0.1\n"), "problem.mesh_size",
                "expected a number > 0, got -0.1"},
        // materials per group of cells
        InputErrorCase{"MaterialListEntryWithoutGroup", kTwoMaterials.replaced("group = \"rubber\"\n", ""),
                "body[0].material[1].group", "missing required key"},
        InputErrorCase{"MaterialListSameGroupTwice", kTwoMaterials.replaced("\"rubber\"", "\"steel\""),
                "body[0].material[1].group", "group \"steel\" already has a material (body[0].material[0])"},
        InputErrorCase{"MaterialListMixesLinearAndHyperelastic",
                kTwoMaterials.replaced("E = 0.01", "model = \"neo_hookean\"\nE = 0.01"), "body[0].material[1].model",
                "the materials of one body must be all \"linear_elastic\" or all hyperelastic"},
        InputErrorCase{"MaterialListEmpty", kBase.replaced("[body.material]\nE = 1.0\nnu = 0.3\n", "material = []\n"),
                "body[0].material", "expected at least one [[body.material]], got an empty array"},
        InputErrorCase{"MaterialNotATable", kBase.replaced("[body.material]\nE = 1.0\nnu = 0.3\n", "material = 3\n"),
                "body[0].material", "expected a table [body.material], or an array of tables"},
        InputErrorCase{"MaterialGroupEmpty", kTwoMaterials.replaced("\"rubber\"", "\"\""),
                "body[0].material[1].group", "expected a non-empty string"},
        InputErrorCase{"MaterialListEntryBadValue", kTwoMaterials.replaced("nu = 0.45", "nu = 0.5"),
                "body[0].material[1].nu", "expected a number in (-1, 0.5)"},
        // mesh_parameters (param.geo declares DefineConstant[ h, n ])
        InputErrorCase{"MeshParameterNotANumber",
                kBase.replaced("mesh = \"block.geo\"", "mesh = \"param.geo\"\nmesh_parameters = { h = \"0.3\" }"),
                "body[0].mesh_parameters.h", "expected a number, got a string (\"0.3\")"},
        InputErrorCase{"MeshParameterNotFinite",
                kBase.replaced("mesh = \"block.geo\"", "mesh = \"param.geo\"\nmesh_parameters = { n = inf }"),
                "body[0].mesh_parameters.n", "expected a finite number, got inf"},
        InputErrorCase{"MeshParameterNotAnIdentifier",
                kBase.replaced("mesh = \"block.geo\"", "mesh = \"param.geo\"\nmesh_parameters = { \"2h\" = 1 }"),
                "body[0].mesh_parameters.2h", "expected a Gmsh variable name"},
        InputErrorCase{"MeshParameterNotDeclared",
                kBase.replaced("mesh = \"block.geo\"", "mesh = \"param.geo\"\nmesh_parameters = { lc = 1 }"),
                "body[0].mesh_parameters.lc", "declares no DefineConstant[ lc = ... ]"},
        InputErrorCase{"MeshParametersOfAMsh",
                kBase.replaced("mesh = \"block.geo\"", "mesh = \"block.msh\"\nmesh_parameters = { h = 1 }"),
                "body[0].mesh_parameters", "is a .msh file"},
        InputErrorCase{"MeshParametersNotATable",
                kBase.replaced("mesh = \"block.geo\"", "mesh = \"param.geo\"\nmesh_parameters = 0.3"),
                "body[0].mesh_parameters", "expected a table"},
        InputErrorCase{"EmptyLoadFactors", kBase.replaced("[0.5, 1.0]", "[]"), "steps.load_factors",
                "expected at least one load factor, got an empty array"},
        // vectors and factors
        InputErrorCase{"BodyForceWrongLength", kBase.after("mesh = \"block.geo\"\n", "body_force = [0, -1, 0]\n"),
                "body[0].body_force", "expected 2 components (problem.dimension = 2), got 3"},
        InputErrorCase{"TractionWrongLengthIn3D",
                kBase.in_3d() + "[[body.traction]]\nboundary = \"r\"\ntraction = [1.0, 0.0]\n",
                "body[0].traction[0].traction", "expected 3 components (problem.dimension = 3), got 2"},
        InputErrorCase{"TractionAndTotalForce",
                kBase + "[[body.traction]]\nboundary = \"r\"\ntraction = [1.0, 0.0]\ntotal_force = [1.0, 0.0]\n",
                "body[0].traction[0].total_force", "expected either traction or total_force (one of the two), got both"},
        InputErrorCase{"TractionNorTotalForce", kBase + "[[body.traction]]\nboundary = \"r\"\n", "body[0].traction[0]",
                "missing required key traction or total_force (expected 2 numbers"},
        InputErrorCase{"TotalForceWrongLength", kBase + "[[body.traction]]\nboundary = \"r\"\ntotal_force = [1.0]\n",
                "body[0].traction[0].total_force", "expected 2 components (problem.dimension = 2), got 1"},
        InputErrorCase{"PointLoadWrongLengthIn3D", kBase.in_3d() + "[[body.point_load]]\ngroup = \"tip\"\nforce = [1.0, 0.0]\n",
                "body[0].point_load[0].force", "expected 3 components (problem.dimension = 3), got 2"},
        InputErrorCase{"PointLoadWithoutGroup", kBase + "[[body.point_load]]\nforce = [1.0, 0.0]\n",
                "body[0].point_load[0].group", "missing required key (expected the name of a physical point group)"},
        InputErrorCase{"PointLoadWithoutForce", kBase + "[[body.point_load]]\ngroup = \"tip\"\n",
                "body[0].point_load[0].force", "missing required key (expected 2 numbers)"},
        InputErrorCase{"PointLoadBoundaryKey", kBase + "[[body.point_load]]\nboundary = \"tip\"\nforce = [1.0, 0.0]\n",
                "body[0].point_load[0].boundary", "allowed keys in body[0].point_load[0]: group, force, factors"},
        InputErrorCase{"PointLoadFactorsLength",
                kBase + "[[body.point_load]]\ngroup = \"tip\"\nforce = [1.0, 0.0]\nfactors = [1.0]\n",
                "body[0].point_load[0].factors", "expected 2 entries"},
        InputErrorCase{"DirichletFactorsLength", kBase.after("uy = 0.0\n", "factors = [1.0, 1.0, 1.0]\n"),
                "body[0].dirichlet[0].factors",
                "expected 2 entries (one per load step, as in steps.load_factors), got 3"},
        InputErrorCase{"BodyForceFactorsLength",
                kBase.after("mesh = \"block.geo\"\n", "body_force = [0, -1]\nbody_force_factors = [1]\n"),
                "body[0].body_force_factors", "expected 2 entries"},
        // load curves (steps.count, { at, values })
        InputErrorCase{"CurveWithoutCount", kBase.replaced("load_factors = [0.5, 1.0]", "load_factors = { at = [0, 2], values = [0, 1] }"),
                "steps.load_factors", "a load curve needs steps.count"},
        InputErrorCase{"CountNotPositive", kBase.replaced("load_factors = [0.5, 1.0]", "count = 0"), "steps.count",
                "expected a number of load steps in [1, 1000000], got 0"},
        InputErrorCase{"CurveTooShort", kBase.after("uy = 0.0\n", "factors = { at = [0, 1], values = [0, 1] }\n"),
                "body[0].dirichlet[0].factors.at", "the curve ends at step 1, before the last load step 2"},
        InputErrorCase{"CurveNotIncreasing", kBase.after("uy = 0.0\n", "factors = { at = [0, 2, 2], values = [0, 1, 1] }\n"),
                "body[0].dirichlet[0].factors.at[2]", "strictly increasing from 0, got 2"},
        InputErrorCase{"CurveNotFromZero", kBase.after("uy = 0.0\n", "factors = { at = [1, 2], values = [0, 1] }\n"),
                "body[0].dirichlet[0].factors.at[0]", "strictly increasing from 0, got 1"},
        InputErrorCase{"CurveFractionalStep", kBase.after("uy = 0.0\n", "factors = { at = [0, 1.5, 2], values = [0, 1, 1] }\n"),
                "body[0].dirichlet[0].factors.at[1]", "expected whole step numbers"},
        InputErrorCase{"CurveLengthsDiffer", kBase.after("uy = 0.0\n", "factors = { at = [0, 2], values = [0, 1, 1] }\n"),
                "body[0].dirichlet[0].factors", "expected 'at' and 'values' of the same length"},
        InputErrorCase{"CurveUnknownKey", kBase.after("uy = 0.0\n", "factors = { at = [0, 2], values = [0, 1], kind = 1 }\n"),
                "body[0].dirichlet[0].factors.kind", ""},
        InputErrorCase{"CurveMissingValues", kBase.after("uy = 0.0\n", "factors = { at = [0, 2] }\n"),
                "body[0].dirichlet[0].factors", "needs both 'at'"},
        InputErrorCase{"BodyForceFactorsWithoutBodyForce",
                kBase.after("mesh = \"block.geo\"\n", "body_force_factors = [1, 1]\n"),
                "body[0].body_force_factors", "given without body_force"},
        // bodies and meshes
        InputErrorCase{"DuplicateBodyName", kBase + kSecondBody, "body[1].name",
                "duplicate body name \"block\" (already used by body[0])"},
        InputErrorCase{"InvalidBodyName", kBase.replaced("name = \"block\"", "name = \"my block\""), "body[0].name",
                "expected a non-empty name of letters, digits, '_' and '-', got \"my block\""},
        InputErrorCase{"MissingMeshFile", kBase.replaced("block.geo", "missing.geo"), "body[0].mesh",
                "mesh file \"" + resolved("missing.geo") + "\" does not exist"},
        InputErrorCase{"UnsupportedMeshExtension", kBase.replaced("block.geo", "block.stl"), "body[0].mesh",
                "expected a Gmsh .geo or .msh file, got \"block.stl\" (extension \".stl\")"},
        InputErrorCase{"MeshWithoutExtension", kBase.replaced("block.geo", "meshes"), "body[0].mesh", "(extension missing)"},
        // boundary conditions
        InputErrorCase{"DirichletWithoutComponent", kBase.replaced("uy = 0.0\n", ""), "body[0].dirichlet[0]",
                "expected at least one imposed component (ux, uy), got none"},
        InputErrorCase{"UzIn2D", kBase.replaced("uy = 0.0", "uz = 0.0"), "body[0].dirichlet[0].uz", "uz is only allowed in 3D"},
        InputErrorCase{"EmptyBoundaryName", kBase.replaced("boundary = \"bottom\"", "boundary = \"\""), "body[0].dirichlet[0].boundary",
                "expected a non-empty string"},
        InputErrorCase{"DirichletNotAnArray", kBase.replaced("[[body.dirichlet]]", "[body.dirichlet]"), "body[0].dirichlet",
                "expected an array of tables ([[body.dirichlet]]), got a table"},
        // contact: structure and surfaces
        InputErrorCase{"ContactNotAnArray", kTwoBodies.replaced("[[contact]]", "[contact]"), "contact",
                "expected an array of tables ([[contact]]), got a table"},
        InputErrorCase{"UnknownContactKey", kTwoBodies.replaced("b = ", "master = \"a\"\nb = "), "contact[0].master",
                "unknown key \"master\"; allowed keys in contact[0]: name, a, b, obstacle, mode, slave, "
                "search_distance, friction, mu, tau, alpha, geometry"},
        InputErrorCase{"MissingContactA", kTwoBodies.replaced("a = \"block.bottom\"\n", ""), "contact[0].a",
                "missing required key (expected a surface \"<body>.<boundary>\")"},
        InputErrorCase{"ContactANotAString", kTwoBodies.replaced("a = \"block.bottom\"", "a = 1"), "contact[0].a",
                "expected a string, got an integer (1)"},
        InputErrorCase{"ContactAWithoutDot", kTwoBodies.replaced("a = \"block.bottom\"", "a = \"block\""), "contact[0].a",
                "expected \"<body>.<boundary>\" (a body name, a dot, a physical group of its boundary), got \"block\""},
        InputErrorCase{"ContactAWithEmptyGroup", kTwoBodies.replaced("a = \"block.bottom\"", "a = \"block.\""),
                "contact[0].a", "expected \"<body>.<boundary>\""},
        InputErrorCase{"ContactAWithEmptyBody", kTwoBodies.replaced("a = \"block.bottom\"", "a = \".bottom\""),
                "contact[0].a", "expected \"<body>.<boundary>\""},
        InputErrorCase{"UnknownBodyInA", kTwoBodies.replaced("a = \"block.bottom\"", "a = \"blok.bottom\""), "contact[0].a",
                "unknown body \"blok\" in \"blok.bottom\"; declared bodies: block, lower"},
        InputErrorCase{"UnknownBodyInB", kTwoBodies.replaced("b = \"lower.top\"", "b = \"upper.top\""), "contact[0].b",
                "unknown body \"upper\" in \"upper.top\"; declared bodies: block, lower"},
        InputErrorCase{"BothBAndObstacle", kTwoBodies + "[contact.obstacle]\ntype = \"plane\"\n", "contact[0]",
                "expected either b (another surface) or [contact.obstacle] (a rigid obstacle), got both"},
        InputErrorCase{"NeitherBNorObstacle", kTwoBodies.replaced("b = \"lower.top\"\n", ""), "contact[0]",
                "missing the opposite surface (expected b = \"<body>.<boundary>\" or a table [contact.obstacle])"},
        InputErrorCase{"InvalidContactName", kTwoBodies.after("[[contact]]\n", "name = \"my contact\"\n"),
                "contact[0].name", "expected a non-empty name of letters, digits, '_' and '-', got \"my contact\""},
        InputErrorCase{"DuplicateContactNames",
                kTwoBodies.after("[[contact]]\n", "name = \"x\"\n") +
                    "[[contact]]\nname = \"x\"\na = \"lower.top\"\nb = \"block.bottom\"\n",
                "contact[1].name", "duplicate contact name \"x\" (already used by contact[0])"},
        InputErrorCase{"ContactNameClashesWithADefaultName",
                kTwoBodies.after("[[contact]]\n", "name = \"contact1\"\n") +
                    "[[contact]]\na = \"lower.top\"\nb = \"block.bottom\"\n",
                "contact[1].name", "duplicate contact name \"contact1\" (already used by contact[0])"},
        // contact: mode, slave, search distance
        InputErrorCase{"BadContactMode", with_contact_keys(kTwoBodies, "mode = \"two-pass\"\n"),
                "contact[0].mode", "expected \"symmetric\" or \"one-pass\", got \"two-pass\""},
        InputErrorCase{"ContactGeometryUnknown", with_contact_keys(kTwoBodies, "geometry = \"deformed\"\n"),
                "contact[0].geometry", "expected \"current\" or \"reference\", got \"deformed\""},
        InputErrorCase{"ContactGeometryNotAString", with_contact_keys(kTwoBodies, "geometry = 1\n"),
                "contact[0].geometry", "expected a string, got an integer (1)"},
        InputErrorCase{"SlaveWithDefaultSymmetricMode", with_contact_keys(kTwoBodies, "slave = \"b\"\n"),
                "contact[0].slave",
                "slave is only used with mode = \"one-pass\", got mode = \"symmetric\" (the symmetric mode writes the "
                "constraints from both surfaces in turn, so there is no slave to choose)"},
        InputErrorCase{"SlaveWithExplicitSymmetricMode",
                with_contact_keys(kTwoBodies, "slave = \"a\"\nmode = \"symmetric\"\n"),
                "contact[0].slave", "slave is only used with mode = \"one-pass\""},
        InputErrorCase{"BadSlaveValue",
                with_contact_keys(kTwoBodies, "mode = \"one-pass\"\nslave = \"c\"\n"),
                "contact[0].slave", "expected \"a\" or \"b\", got \"c\""},
        InputErrorCase{"SlaveBWithObstacle",
                with_contact_keys(kPlane, "mode = \"one-pass\"\nslave = \"b\"\n"),
                "contact[0].slave", "expected \"a\" with an obstacle"},
        InputErrorCase{"SearchDistanceZero",
                with_contact_keys(kTwoBodies, "search_distance = 0\n"),
                "contact[0].search_distance", "expected a number > 0, got 0"},
        InputErrorCase{"SearchDistanceNegative",
                with_contact_keys(kTwoBodies, "search_distance = -0.5\n"),
                "contact[0].search_distance", "expected a number > 0, got -0.5"},
        // contact: friction
        InputErrorCase{"UnknownFrictionLaw", with_contact_keys(kTwoBodies, "friction = \"stick\"\n"), "contact[0].friction",
                "expected \"none\", \"tresca\" or \"coulomb\", got \"stick\""},
        InputErrorCase{"FrictionNotAString", with_contact_keys(kTwoBodies, "friction = true\n"), "contact[0].friction",
                "expected a string, got a boolean (true)"},
        InputErrorCase{"MisspeltFrictionKey", with_contact_keys(kTwoBodies, "friction = \"coulomb\"\nmuu = 0.3\n"),
                "contact[0].muu", "unknown key \"muu\" (did you mean \"mu\"?)"},
        InputErrorCase{"MuWithoutFriction", with_contact_keys(kTwoBodies, "mu = 0.3\n"), "contact[0].mu",
                "mu (the friction coefficient) is only used with friction = \"coulomb\", got friction = \"none\" (the "
                "default)"},
        InputErrorCase{"MuWithTresca", with_contact_keys(kTwoBodies, "friction = \"tresca\"\ntau = 0.002\nmu = 0.3\n"),
                "contact[0].mu",
                "mu (the friction coefficient) is only used with friction = \"coulomb\", got friction = \"tresca\""},
        InputErrorCase{"TauWithCoulomb", with_contact_keys(kTwoBodies, "friction = \"coulomb\"\nmu = 0.3\ntau = 0.002\n"),
                "contact[0].tau",
                "tau (the sliding threshold) is only used with friction = \"tresca\", got friction = \"coulomb\""},
        InputErrorCase{"AlphaWithExplicitNone", with_contact_keys(kTwoBodies, "friction = \"none\"\nalpha = 1e-6\n"),
                "contact[0].alpha",
                "alpha (the regularisation of the slip) is only used with friction = \"tresca\" or \"coulomb\", got "
                "friction = \"none\""},
        InputErrorCase{"AlphaWithDefaultNone", with_contact_keys(kPlane, "alpha = 1e-6\n"), "contact[0].alpha",
                "got friction = \"none\" (the default)"},
        InputErrorCase{"MissingMu", with_contact_keys(kTwoBodies, "friction = \"coulomb\"\n"), "contact[0].mu",
                "missing required key (expected the friction coefficient, a number >= 0, with friction = "
                "\"coulomb\")"},
        InputErrorCase{"MissingTau", with_contact_keys(kPlane, "friction = \"tresca\"\nalpha = 1e-6\n"), "contact[0].tau",
                "missing required key (expected the sliding threshold, a number >= 0, with friction = \"tresca\")"},
        InputErrorCase{"NegativeMu", with_contact_keys(kTwoBodies, "friction = \"coulomb\"\nmu = -0.1\n"), "contact[0].mu",
                "expected a number >= 0, got -0.1"},
        InputErrorCase{"MuNotANumber", with_contact_keys(kTwoBodies, "friction = \"coulomb\"\nmu = \"0.3\"\n"),
                "contact[0].mu", "expected a number, got a string (\"0.3\")"},
        InputErrorCase{"MuInfinite", with_contact_keys(kTwoBodies, "friction = \"coulomb\"\nmu = inf\n"), "contact[0].mu",
                "expected a finite number, got inf"},
        InputErrorCase{"NegativeTau", with_contact_keys(kTwoBodies, "friction = \"tresca\"\ntau = -2\n"), "contact[0].tau",
                "expected a number >= 0, got -2"},
        InputErrorCase{"AlphaZero", with_contact_keys(kTwoBodies, "friction = \"tresca\"\ntau = 0.002\nalpha = 0\n"),
                "contact[0].alpha", "expected a number > 0, got 0"},
        InputErrorCase{"AlphaNegative", with_contact_keys(kTwoBodies, "friction = \"coulomb\"\nmu = 0.3\nalpha = -1e-6\n"),
                "contact[0].alpha", "expected a number > 0, got -1e-06"},
        // contact: obstacles
        InputErrorCase{"ObstacleNotATable", kTwoBodies.replaced("b = \"lower.top\"", "obstacle = \"plane\""),
                "contact[0].obstacle", "expected a table, got a string (\"plane\")"},
        InputErrorCase{"MissingObstacleType", kPlane.replaced("type = \"plane\"\n", ""), "contact[0].obstacle.type",
                "missing required key (expected \"plane\", \"circle\", \"sphere\" or \"mesh\")"},
        InputErrorCase{"UnknownObstacleType", kPlane.replaced("type = \"plane\"", "type = \"cone\""),
                "contact[0].obstacle.type",
                "expected \"plane\", \"circle\" (2D), \"sphere\" (3D) or \"mesh\", got \"cone\""},
        InputErrorCase{"UnknownObstacleKey", kCircle.replaced("radius = 1.0", "radious = 1.0"), "contact[0].obstacle.radious",
                "unknown key \"radious\" (did you mean \"radius\"?)"},
        InputErrorCase{"CircleIn3D", kCircle.replaced("[0.0, -1.0]", "[0.0, 0.0, -1.0]").in_3d(),
                "contact[0].obstacle.type",
                "\"circle\" is only allowed in 2D (problem.dimension = 2), got problem.dimension = 3; use \"sphere\" in "
                "3D"},
        InputErrorCase{"SphereIn2D", kCircle.replaced("type = \"circle\"", "type = \"sphere\""), "contact[0].obstacle.type",
                "\"sphere\" is only allowed in 3D (problem.dimension = 3), got problem.dimension = 2; use \"circle\" in "
                "2D"},
        InputErrorCase{"MissingRadius", kCircle.replaced("radius = 1.0\n", ""), "contact[0].obstacle.radius",
                "missing required key (expected a number > 0)"},
        InputErrorCase{"RadiusZero", kCircle.replaced("radius = 1.0", "radius = 0"), "contact[0].obstacle.radius",
                "expected a number > 0, got 0"},
        InputErrorCase{"RadiusNegative", kCircle.replaced("radius = 1.0", "radius = -2.5"), "contact[0].obstacle.radius",
                "expected a number > 0, got -2.5"},
        InputErrorCase{"MissingCenter", kCircle.replaced("center = [0.0, -1.0]\n", ""), "contact[0].obstacle.center",
                "missing required key (expected 2 numbers)"},
        InputErrorCase{"InsideNotABoolean", kCircle.after("radius = 1.0\n", "inside = 1\n"),
                "contact[0].obstacle.inside", "expected a boolean (true or false), got an integer (1)"},
        InputErrorCase{"ZeroNormal", kPlane.replaced("normal = [0.0, 1.0]", "normal = [0.0, 0]"), "contact[0].obstacle.normal",
                "expected a nonzero vector, got the zero vector"},
        InputErrorCase{"MissingNormal", kPlane.replaced("normal = [0.0, 1.0]\n", ""), "contact[0].obstacle.normal",
                "missing required key (expected 2 numbers, nonzero)"},
        InputErrorCase{"PlanePointWrongLength", kPlane.replaced("point = [0.0, 0.0]", "point = [0.0, 0.0, 0.0]"),
                "contact[0].obstacle.point", "expected 2 components (problem.dimension = 2), got 3"},
        InputErrorCase{"RadiusWithPlane", kPlane.after("normal = [0.0, 1.0]\n", "radius = 1.0\n"),
                "contact[0].obstacle.radius",
                "key \"radius\" does not belong to an obstacle of type \"plane\"; keys of this type: type, point, normal"},
        InputErrorCase{"NormalWithCircle", kCircle.after("radius = 1.0\n", "normal = [0.0, 1.0]\n"),
                "contact[0].obstacle.normal",
                "key \"normal\" does not belong to an obstacle of type \"circle\"; keys of this type: type, center, "
                "radius, inside"},
        InputErrorCase{"BoundaryWithSphere",
                kCircle.replaced("circle", "sphere").replaced("[0.0, -1.0]", "[0.0, 0.0, -1.0]").in_3d() +
                    "boundary = \"surface\"\n",
                "contact[0].obstacle.boundary", "does not belong to an obstacle of type \"sphere\""},
        InputErrorCase{"MeshObstacleMissingBoundary", kMeshObstacle.replaced("boundary = \"surface\"\n", ""),
                "contact[0].obstacle.boundary", "missing required key (expected the name of a physical group)"},
        InputErrorCase{"MeshObstacleMissingMeshKey", kMeshObstacle.replaced("mesh = \"die.geo\"\n", ""),
                "contact[0].obstacle.mesh", "missing required key (expected the path of a .geo or .msh file)"},
        InputErrorCase{"MeshObstacleMissingFile", kMeshObstacle.replaced("die.geo", "dye.geo"), "contact[0].obstacle.mesh",
                "mesh file \"" + resolved("dye.geo") + "\" does not exist"},
        InputErrorCase{"MeshObstacleWrongExtension", kMeshObstacle.replaced("die.geo", "block.stl"),
                "contact[0].obstacle.mesh", "expected a Gmsh .geo or .msh file, got \"block.stl\""},
        InputErrorCase{"RadiusWithMeshObstacle", kMeshObstacle.replaced("boundary = \"surface\"", "radius = 1.0\nboundary = \"surface\""),
                "contact[0].obstacle.radius", "keys of this type: type, mesh, boundary"},
        // contact solver and IPOPT options
        InputErrorCase{"UnknownContactSolverKey", kTwoBodies + "[contact_solver]\ntolerance = 1e-6\n",
                "contact_solver.tolerance",
                "unknown key \"tolerance\"; allowed keys in contact_solver: geometry_tolerance, max_geometry_iterations, "
                "coulomb_tolerance, converge_past_tolerance, max_coulomb_iterations, coulomb_update, static_condensation, "
                "subproblem_solver, warm_start, ipopt_problem, max_step_cuts, linear_solver"},
        InputErrorCase{"WarmStartUnknown", kTwoBodies + "[contact_solver]\nwarm_start = \"cold\"\n",
                "contact_solver.warm_start", "expected \"active_set\" or \"interior_point\", got \"cold\""},
        InputErrorCase{"IpoptProblemUnknown", kTwoBodies + "[contact_solver]\nipopt_problem = \"dense\"\n",
                "contact_solver.ipopt_problem", "expected \"automatic\", \"condensed\" or \"uncondensed\", got \"dense\""},
        InputErrorCase{"LinearSolverUnknown", kTwoBodies + "[contact_solver]\nlinear_solver = \"cg\"\n",
                "contact_solver.linear_solver", "expected \"automatic\", \"direct\" or \"iterative\", got \"cg\""},
        InputErrorCase{"CoulombUpdateUnknown", kTwoBodies + "[contact_solver]\ncoulomb_update = \"always\"\n",
                "contact_solver.coulomb_update",
                "expected \"inside_optimizer\" or \"between_solves\", got \"always\""},
        InputErrorCase{"SubproblemSolverUnknown", kTwoBodies + "[contact_solver]\nsubproblem_solver = \"mumps\"\n",
                "contact_solver.subproblem_solver",
                "expected \"dual_interior_point\", \"dual_ipopt\", \"primal_ipopt\" or \"primal_interior_point\", got "
                "\"mumps\""},
        InputErrorCase{"SubproblemSolverNotAString", kTwoBodies + "[contact_solver]\nsubproblem_solver = 1\n",
                "contact_solver.subproblem_solver", "expected a string"},
        InputErrorCase{"DualSolveReplaced", kTwoBodies + "[contact_solver]\ndual_solve = false\n",
                "contact_solver.dual_solve", "replaced by subproblem_solver = \"dual_interior_point\" (the default)"},
        InputErrorCase{"DualOptimizerReplaced", kTwoBodies + "[contact_solver]\ndual_optimizer = \"ipopt\"\n",
                "contact_solver.dual_optimizer", "\"dual_ipopt\" (dual_optimizer = \"ipopt\")"},
        InputErrorCase{"MaxStepCutsNegative", kTwoBodies + "[contact_solver]\nmax_step_cuts = -1\n",
                "contact_solver.max_step_cuts", "expected an integer in [0, 20], got -1"},
        InputErrorCase{"MaxStepCutsTooMany", kTwoBodies + "[contact_solver]\nmax_step_cuts = 21\n",
                "contact_solver.max_step_cuts", "expected an integer in [0, 20], got 21"},
        InputErrorCase{"MaxStepCutsFloat", kTwoBodies + "[contact_solver]\nmax_step_cuts = 2.0\n",
                "contact_solver.max_step_cuts", "expected an integer, got a floating-point number (2.0)"},
        InputErrorCase{"GeometryToleranceZero", kTwoBodies + "[contact_solver]\ngeometry_tolerance = 0.0\n",
                "contact_solver.geometry_tolerance", "expected a number > 0, got 0"},
        InputErrorCase{"MaxGeometryIterationsZero", kTwoBodies + "[contact_solver]\nmax_geometry_iterations = 0\n",
                "contact_solver.max_geometry_iterations", "expected an integer in [1, 2147483647], got 0"},
        InputErrorCase{"MaxGeometryIterationsFloat", kTwoBodies + "[contact_solver]\nmax_geometry_iterations = 10.0\n",
                "contact_solver.max_geometry_iterations", "expected an integer, got a floating-point number (10.0)"},
        InputErrorCase{"CoulombToleranceZero", kTwoBodies + "[contact_solver]\ncoulomb_tolerance = 0\n",
                "contact_solver.coulomb_tolerance", "expected a number > 0, got 0"},
        InputErrorCase{"CoulombToleranceNegative", kTwoBodies + "[contact_solver]\ncoulomb_tolerance = -1e-6\n",
                "contact_solver.coulomb_tolerance", "expected a number > 0, got -1e-06"},
        InputErrorCase{"MaxCoulombIterationsZero", kTwoBodies + "[contact_solver]\nmax_coulomb_iterations = 0\n",
                "contact_solver.max_coulomb_iterations", "expected an integer in [1, 2147483647], got 0"},
        InputErrorCase{"MaxCoulombIterationsFloat", kTwoBodies + "[contact_solver]\nmax_coulomb_iterations = 5.5\n",
                "contact_solver.max_coulomb_iterations", "expected an integer, got a floating-point number (5.5)"},
        InputErrorCase{"ContactSolverNotATable", "contact_solver = 3\n" + kTwoBodies, "contact_solver",
                "expected a table, got an integer (3)"},
        InputErrorCase{"IpoptBoolean", kTwoBodies + "[ipopt]\ntol = 1e-8\nwarm_start_init_point = true\n",
                "ipopt.warm_start_init_point",
                "expected a string, an integer or a floating-point number (an IPOPT option value), got a boolean (true)"},
        InputErrorCase{"IpoptArray", kTwoBodies + "[ipopt]\ntol = [1e-8, 1e-6]\n", "ipopt.tol",
                "expected a string, an integer or a floating-point number (an IPOPT option value), got an array"},
        InputErrorCase{"IpoptTable", kTwoBodies + "[ipopt.tol]\nvalue = 1e-8\n", "ipopt.tol", "got a table"},
        InputErrorCase{"IpoptNan", kTwoBodies + "[ipopt]\ntol = nan\n", "ipopt.tol", "expected a finite number, got nan"},
        InputErrorCase{"IpoptIntegerTooLarge", kTwoBodies + "[ipopt]\nmax_iter = 3000000000\n", "ipopt.max_iter",
                "expected an integer that fits in an int (IPOPT integer option), got 3000000000"},
        InputErrorCase{"IpoptNotATable", "ipopt = \"tol=1e-8\"\n" + kTwoBodies, "ipopt",
                "expected a table, got a string (\"tol=1e-8\")"}),
    [](const ::testing::TestParamInfo<InputErrorCase>& case_info) { return case_info.param.name; });

}  // namespace
}  // namespace symcontact
