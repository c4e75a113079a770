// Tests of the TOML problem-file reader (src/symcontact/model/problem_reader.hpp): a complete valid
// file lands field by field in the ProblemSpec, and every kind of bad input throws an InputError that
// names the file, the TOML key and what was expected.

#include "symcontact/model/problem_reader.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "symcontact/core/error.hpp"

namespace symcontact {
namespace {

namespace fs = std::filesystem;

/// A folder holding the (empty) mesh files the problems refer to: the reader only checks existence.
const std::string& mesh_dir() {
  static const std::string dir = [] {
    const fs::path d = fs::path(::testing::TempDir()) / "symcontact_problem_reader";
    fs::create_directories(d / "meshes");
    for (const char* name : {"block.geo", "block.msh", "block.stl", "meshes/foundation.msh"}) {
      std::ofstream(d / name) << "// placeholder\n";
    }
    return d.string();
  }();
  return dir;
}

std::string resolved(const std::string& relative) {
  return (fs::path(mesh_dir()) / relative).lexically_normal().string();
}

ProblemSpec parse(const std::string& text) { return parse_problem(text, "case.toml", mesh_dir()); }

/// Parses `text` and returns the InputError it must throw.
std::optional<InputError> error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e;
  }
  return std::nullopt;
}

/// A valid 2D file with one body; bad cases are one edit away from it.
const std::string kBase = R"(title = "base"
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
)";

/// kBase with the first occurrence of `from` replaced by `to`.
std::string edit(const std::string& from, const std::string& to) {
  std::string s = kBase;
  const std::size_t at = s.find(from);
  if (at == std::string::npos) ADD_FAILURE() << "test bug: \"" << from << "\" is not in the base file";
  else s.replace(at, from.size(), to);
  return s;
}

std::string with_dimension_3(const std::string& text) {
  std::string s = text;
  s.replace(s.find("dimension = 2"), 13, "dimension = 3");
  return s;
}

TEST(ProblemReader, BaseFileIsValid) { EXPECT_NO_THROW(parse(kBase)); }

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

[[body]]
name = "foundation-2"
mesh = "meshes/../meshes/foundation.msh"
material = { E = 1e3, nu = -0.2 }
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
  EXPECT_EQ(b.material.key, "body[0].material");
  EXPECT_EQ(b.material.model, "linear_elastic");
  EXPECT_EQ(b.material.young, 210.0);
  EXPECT_EQ(b.material.poisson, 0.3);

  ASSERT_EQ(b.dirichlet.size(), 2u);
  EXPECT_EQ(b.dirichlet[0].key, "body[0].dirichlet[0]");
  EXPECT_EQ(b.dirichlet[0].group, "bottom");
  EXPECT_FALSE(b.dirichlet[0].value[0].has_value());
  EXPECT_EQ(b.dirichlet[0].value[1], std::optional<double>(0.0));
  EXPECT_FALSE(b.dirichlet[0].value[2].has_value());
  EXPECT_TRUE(b.dirichlet[0].factors.empty());
  EXPECT_EQ(b.dirichlet[1].key, "body[0].dirichlet[1]");
  EXPECT_EQ(b.dirichlet[1].group, "left_corner");
  EXPECT_EQ(b.dirichlet[1].value[0], std::optional<double>(-0.25));
  EXPECT_EQ(b.dirichlet[1].value[1], std::optional<double>(0.5));
  EXPECT_EQ(b.dirichlet[1].factors, (std::vector<double>{1.0, 2.0}));

  ASSERT_EQ(b.tractions.size(), 1u);
  EXPECT_EQ(b.tractions[0].key, "body[0].traction[0]");
  EXPECT_EQ(b.tractions[0].group, "right");
  EXPECT_EQ(b.tractions[0].traction, (std::vector<double>{1.5, 0.0}));
  EXPECT_EQ(b.tractions[0].factors, (std::vector<double>{0.0, 1.0}));

  ASSERT_EQ(b.pressures.size(), 1u);
  EXPECT_EQ(b.pressures[0].key, "body[0].pressure[0]");
  EXPECT_EQ(b.pressures[0].group, "top");
  EXPECT_EQ(b.pressures[0].pressure, 0.01);
  EXPECT_TRUE(b.pressures[0].factors.empty());

  const BodySpec& f = spec.bodies[1];
  EXPECT_EQ(f.key, "body[1]");
  EXPECT_EQ(f.name, "foundation-2");
  EXPECT_EQ(f.mesh_path, resolved("meshes/foundation.msh"));
  EXPECT_TRUE(f.group.empty());
  EXPECT_TRUE(f.body_force.empty());
  EXPECT_EQ(f.material.key, "body[1].material");
  EXPECT_EQ(f.material.young, 1000.0);
  EXPECT_EQ(f.material.poisson, -0.2);
  EXPECT_TRUE(f.dirichlet.empty() && f.tractions.empty() && f.pressures.empty());
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
  EXPECT_EQ(spec.bodies[0].material.model, "linear_elastic");
  EXPECT_EQ(spec.bodies[0].body_force, (std::vector<double>{0.0, 0.0, -9.81}));
  EXPECT_EQ(spec.bodies[0].dirichlet[0].value[2], std::optional<double>(0.0));
  EXPECT_EQ(spec.bodies[0].tractions[0].traction, (std::vector<double>{1.0, 2.0, 3.0}));
}

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

TEST(ProblemReader, DefaultModelIn2DIsPlaneStrain) { EXPECT_EQ(parse(kBase).model, AnalysisModel::kPlaneStrain); }

TEST(ProblemReader, ReadsFileAndResolvesMeshAgainstItsFolder) {
  const fs::path problem = fs::path(mesh_dir()) / "meshes" / "problem.toml";
  std::ofstream(problem) << edit("mesh = \"block.geo\"", "mesh = \"../block.geo\"");
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
  std::ofstream(problem) << edit("nu = 0.3", "nu = 0.7");
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

struct BadCase {
  const char* name;       ///< test name suffix
  std::string text;       ///< the problem file
  std::string key;        ///< expected InputError::key()
  std::string fragment;   ///< expected part of InputError::message()
};

void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

class ProblemReaderBadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(ProblemReaderBadInput, ThrowsInputErrorWithKeyAndMessage) {
  const BadCase& c = GetParam();
  const std::optional<InputError> e = error_of(c.text);
  ASSERT_TRUE(e.has_value()) << "no error for:\n" << c.text;
  EXPECT_EQ(e->file(), "case.toml");
  EXPECT_EQ(e->key(), c.key) << e->what();
  EXPECT_NE(e->message().find(c.fragment), std::string::npos)
      << "message: " << e->message() << "\nexpected to contain: " << c.fragment;
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
        BadCase{"MalformedToml", edit("dimension = 2", "dimension = = 2"), "", "line 3, column "},
        BadCase{"UnterminatedTableHeader", edit("[steps]", "[steps"), "", "line 4, column "},
        // unknown keys
        BadCase{"UnknownTopLevelKey", "solver = \"ipopt\"\n" + kBase, "solver",
                "unknown key \"solver\"; allowed keys at the top level: title, problem, steps, output, body"},
        BadCase{"UnknownProblemKey", edit("dimension = 2", "dimension = 2\nodrer = 1"), "problem.odrer",
                "unknown key \"odrer\" (did you mean \"order\"?)"},
        BadCase{"UnknownBodyKey", edit("mesh = \"block.geo\"", "mesh = \"block.geo\"\ncolour = \"red\""),
                "body[0].colour", "allowed keys in body[0]: name, mesh, group, body_force"},
        BadCase{"UnknownMaterialKey", edit("nu = 0.3", "nu = 0.3\nNu = 0.3"), "body[0].material.Nu",
                "unknown key \"Nu\" (did you mean \"nu\"?); allowed keys in body[0].material: model, E, nu"},
        BadCase{"UnknownDirichletKey", edit("uy = 0.0", "uy = 0.0\nvalue = 1.0"), "body[0].dirichlet[0].value",
                "allowed keys in body[0].dirichlet[0]: boundary, ux, uy, uz, factors"},
        BadCase{"UnknownKeyInSecondBody", kBase + kSecondBody + "density = 7.8\n", "body[1].material.density",
                "unknown key \"density\""},
        // types
        BadCase{"StringForNumber", edit("E = 1.0", "E = \"1.0\""), "body[0].material.E",
                "expected a number, got a string (\"1.0\")"},
        BadCase{"FloatForInteger", edit("dimension = 2", "dimension = 2.0"), "problem.dimension",
                "expected an integer, got a floating-point number (2.0)"},
        BadCase{"StringForBoolean", kBase + "[output]\nvtu = \"yes\"\n", "output.vtu",
                "expected a boolean (true or false), got a string"},
        BadCase{"NumberForVectorEntry", kBase + "[[body.traction]]\nboundary = \"r\"\ntraction = [1.0, true]\n",
                "body[0].traction[0].traction[1]", "expected a number, got a boolean"},
        BadCase{"BodyAsTable", edit("[[body]]", "[body]"), "body",
                "expected an array of tables ([[body]]), got a table"},
        // missing keys
        BadCase{"MissingProblemTable", edit("[problem]\ndimension = 2\n", ""), "problem",
                "missing required table [problem]"},
        BadCase{"MissingDimension", edit("dimension = 2", "order = 1"), "problem.dimension",
                "missing required key (expected 2 or 3)"},
        BadCase{"MissingNu", edit("nu = 0.3\n", ""), "body[0].material.nu", "missing required key"},
        BadCase{"MissingMesh", edit("mesh = \"block.geo\"\n", ""), "body[0].mesh", "missing required key"},
        BadCase{"MissingMaterial", edit("[body.material]\nE = 1.0\nnu = 0.3\n", ""), "body[0].material",
                "missing required key"},
        BadCase{"MissingPressureValue", kBase + "[[body.pressure]]\nboundary = \"top\"\n",
                "body[0].pressure[0].pressure",
                "missing required key (expected a number)"},
        BadCase{"NoBody", "[problem]\ndimension = 2\n", "body", "at least one body"},
        // values
        BadCase{"YoungZero", edit("E = 1.0", "E = 0"), "body[0].material.E", "expected a number > 0, got 0"},
        BadCase{"YoungNegative", edit("E = 1.0", "E = -3.5"), "body[0].material.E", "expected a number > 0, got -3.5"},
        BadCase{"PoissonHalf", edit("nu = 0.3", "nu = 0.5"), "body[0].material.nu",
                "expected a number in (-1, 0.5), got 0.5"},
        BadCase{"PoissonMinusOne", edit("nu = 0.3", "nu = -1"), "body[0].material.nu",
                "expected a number in (-1, 0.5), got -1"},
        BadCase{"PoissonNan", edit("nu = 0.3", "nu = nan"), "body[0].material.nu", "expected a finite number, got nan"},
        BadCase{"InfiniteLoadFactor", edit("[0.5, 1.0]", "[0.5, inf]"), "steps.load_factors[1]",
                "expected a finite number, got inf"},
        BadCase{"UnknownMaterialModel", edit("E = 1.0", "model = \"neo_hookean\"\nE = 1.0"), "body[0].material.model",
                "expected \"linear_elastic\", got \"neo_hookean\""},
        BadCase{"DimensionFour", edit("dimension = 2", "dimension = 4"), "problem.dimension", "expected 2 or 3, got 4"},
        BadCase{"OrderThree", edit("dimension = 2", "dimension = 2\norder = 3"), "problem.order",
                "expected 1 or 2, got 3"},
        BadCase{"PlaneStressIn3D", with_dimension_3(edit("dimension = 2", "dimension = 2\nmodel = \"plane_stress\"")),
                "problem.model", "expected \"3d\" (problem.dimension = 3), got \"plane_stress\""},
        BadCase{"ThreeDModelIn2D", edit("dimension = 2", "dimension = 2\nmodel = \"3d\""), "problem.model",
                "expected \"plane_strain\" or \"plane_stress\""},
        BadCase{"NonPositiveMeshSize", edit("dimension = 2", "dimension = 2\nmesh_size = -0.1"), "problem.mesh_size",
                "expected a number > 0, got -0.1"},
        BadCase{"EmptyLoadFactors", edit("[0.5, 1.0]", "[]"), "steps.load_factors",
                "expected at least one load factor, got an empty array"},
        // vectors and factors
        BadCase{"BodyForceWrongLength", edit("mesh = \"block.geo\"", "mesh = \"block.geo\"\nbody_force = [0, -1, 0]"),
                "body[0].body_force", "expected 2 components (problem.dimension = 2), got 3"},
        BadCase{"TractionWrongLengthIn3D",
                with_dimension_3(kBase) + "[[body.traction]]\nboundary = \"r\"\ntraction = [1.0, 0.0]\n",
                "body[0].traction[0].traction", "expected 3 components (problem.dimension = 3), got 2"},
        BadCase{"DirichletFactorsLength", edit("uy = 0.0", "uy = 0.0\nfactors = [1.0, 1.0, 1.0]"),
                "body[0].dirichlet[0].factors",
                "expected 2 entries (one per load step, as in steps.load_factors), got 3"},
        BadCase{"BodyForceFactorsLength",
                edit("mesh = \"block.geo\"", "mesh = \"block.geo\"\nbody_force = [0, -1]\nbody_force_factors = [1]"),
                "body[0].body_force_factors", "expected 2 entries"},
        BadCase{"BodyForceFactorsWithoutBodyForce",
                edit("mesh = \"block.geo\"", "mesh = \"block.geo\"\nbody_force_factors = [1, 1]"),
                "body[0].body_force_factors", "given without body_force"},
        // bodies and meshes
        BadCase{"DuplicateBodyName", kBase + kSecondBody, "body[1].name",
                "duplicate body name \"block\" (already used by body[0])"},
        BadCase{"InvalidBodyName", edit("name = \"block\"", "name = \"my block\""), "body[0].name",
                "expected a non-empty name of letters, digits, '_' and '-', got \"my block\""},
        BadCase{"MissingMeshFile", edit("block.geo", "missing.geo"), "body[0].mesh",
                "mesh file \"" + resolved("missing.geo") + "\" does not exist"},
        BadCase{"UnsupportedMeshExtension", edit("block.geo", "block.stl"), "body[0].mesh",
                "expected a Gmsh .geo or .msh file, got \"block.stl\" (extension \".stl\")"},
        BadCase{"MeshWithoutExtension", edit("block.geo", "meshes"), "body[0].mesh", "(extension missing)"},
        // boundary conditions
        BadCase{"DirichletWithoutComponent", edit("uy = 0.0\n", ""), "body[0].dirichlet[0]",
                "expected at least one imposed component (ux, uy), got none"},
        BadCase{"UzIn2D", edit("uy = 0.0", "uz = 0.0"), "body[0].dirichlet[0].uz", "uz is only allowed in 3D"},
        BadCase{"EmptyBoundaryName", edit("boundary = \"bottom\"", "boundary = \"\""), "body[0].dirichlet[0].boundary",
                "expected a non-empty string"},
        BadCase{"DirichletNotAnArray", edit("[[body.dirichlet]]", "[body.dirichlet]"), "body[0].dirichlet",
                "expected an array of tables ([[body.dirichlet]]), got a table"}),
    [](const ::testing::TestParamInfo<BadCase>& case_info) { return std::string(case_info.param.name); });

}  // namespace
}  // namespace symcontact
