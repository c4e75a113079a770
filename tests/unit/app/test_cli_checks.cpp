/// End-to-end tests of the checks that stand between a solve and a result (issue #19): the checks before the
/// solve (model/setup_checks.hpp, mesh_topology.hpp check_folds(): exit 2, nothing written, `symcontact check`
/// too) and the checks of each load step's answer (post/step_checks.hpp: exit 3, summary.json
/// "solve_failed"). Each wrong problem is one an outside tester found reported as a success, and each has a
/// corrected twin that must still pass. Conventions of test_cli.cpp.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli_fixture.hpp"

namespace {

namespace fs = std::filesystem;

using symcontact::testing::CliResult;
using symcontact::testing::read_text;

const std::string kGeo = std::string(SYMCONTACT_TEST_DATA) + "/geo/";
const std::string kMeshes = std::string(SYMCONTACT_TEST_DATA) + "/meshes/";

class CliChecks : public symcontact::testing::CliTest {
 protected:
  CliChecks() : CliTest("symcontact_cli_checks_") {}

  fs::path write_case(const std::string& toml) const {
    const fs::path p = dir_ / "case.toml";
    std::ofstream(p) << toml;
    return p;
  }
  std::string summary() const { return read_text(dir_ / "out" / "summary.json"); }
};

/// two_blocks.geo: "lower" [0,1]² held at its bottom, "upper" [0,1]×[1,2] driven down by `down` at its top,
/// one symmetric frictionless pair on the shared line.
std::string driven_blocks(double down, const std::string& material = "", const std::string& contact_extra = "") {
  const std::string geo = kGeo + "two_blocks.geo";
  return R"(
[problem]
dimension = 2
[[body]]
name = "lower"
mesh = ")" + geo + R"("
group = "lower"
material = { E = 10.0, nu = 0.3 )" + material + R"( }
[[body.dirichlet]]
boundary = "bottom"
ux = 0.0
uy = 0.0
[[body]]
name = "upper"
mesh = ")" + geo + R"("
group = "upper"
material = { E = 10.0, nu = 0.3 )" + material + R"( }
[[body.dirichlet]]
boundary = "top"
ux = 0.0
uy = )" + std::to_string(-down) + R"(
[[contact]]
name = "interface"
a = "lower.interface"
b = "upper.interface"
)" + contact_extra;
}

TEST_F(CliChecks, BlockDrivenThroughTheOtherFailsTheStepCheck) {
  for (const std::string material : {"", ", model = \"neo_hookean\""}) {
    write_case(driven_blocks(5.0, material));
    const CliResult r = run("run case.toml --out out");
    EXPECT_EQ(r.exit_code, 3) << material << "\n" << r.output;
    EXPECT_NE(r.output.find("load step 1: check of the answer"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("contact 'interface'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("went through each other"), std::string::npos) << r.output;
    EXPECT_NE(summary().find("\"status\": \"solve_failed\""), std::string::npos);
    EXPECT_EQ(summary().find("\"status\": \"ok\""), std::string::npos);
    fs::remove_all(dir_ / "out");
  }
}

TEST_F(CliChecks, MotionBeyondTheSearchDistanceFailsTheStepCheck) {
  write_case(driven_blocks(0.7, "", "search_distance = 0.6\n"));
  const CliResult r = run("run case.toml --out out");
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("contact 'interface'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("% of the element size"), std::string::npos) << r.output;
  EXPECT_NE(summary().find("\"status\": \"solve_failed\""), std::string::npos);
}

TEST_F(CliChecks, FailedStepCheckKeepsTheFinishedSteps) {
  // Step 1 (1 % of the motion) holds; step 2 goes 0.7 down with the search distance at 0.6.
  write_case("[steps]\nload_factors = [0.01, 1.0]\n" + driven_blocks(0.7, "", "search_distance = 0.6\n"));
  const CliResult r = run("run case.toml --out out");
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("load step 2: check of the answer: contact 'interface'"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "lower_0001.vtu"));
  EXPECT_TRUE(fs::exists(dir_ / "out" / "upper_failed_step2.vtu"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "lower_0002.vtu"));
  const std::string s = summary();
  EXPECT_NE(s.find("\"status\": \"solve_failed\""), std::string::npos);
  EXPECT_NE(s.find("\"step\": 1"), std::string::npos);
  EXPECT_EQ(s.find("\"step\": 2"), std::string::npos);
}

TEST_F(CliChecks, ContactThatHoldsPassesTheStepChecks) {
  write_case(driven_blocks(0.05));
  const CliResult r = run("run case.toml --out out");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(summary().find("\"status\": \"ok\""), std::string::npos);
  EXPECT_NE(summary().find("\"equilibrium_residual\""), std::string::npos);
}

/// square.geo pushed down by a pressure onto the meshed floor of `floor_geo`, held in x on its left side.
std::string block_on_meshed_floor(const std::string& floor_geo) {
  return R"(
[problem]
dimension = 2
[[body]]
name = "block"
mesh = ")" + kGeo + R"(square.geo"
group = "square"
material = { E = 100.0, nu = 0.3 }
[[body.dirichlet]]
boundary = "left"
ux = 0.0
[[body.pressure]]
boundary = "top"
pressure = 1.0
[[contact]]
name = "floor"
a = "block.bottom"
[contact.obstacle]
type = "mesh"
mesh = ")" + kGeo + floor_geo + R"("
boundary = "floor"
)";
}

TEST_F(CliChecks, MeshedObstacleFacingAwayIsRefused) {
  write_case(block_on_meshed_floor("floor_facing_away.geo"));
  for (const std::string cmd : {"check case.toml", "run case.toml --out out"}) {
    const CliResult r = run(cmd);
    EXPECT_EQ(r.exit_code, 2) << cmd << "\n" << r.output;
    EXPECT_NE(r.output.find("contact[0].obstacle"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("face away from body 'block'"), std::string::npos) << r.output;
  }
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(CliChecks, MeshedObstacleFacingTheBodyIsAccepted) {
  write_case(block_on_meshed_floor("floor_facing_up.geo"));
  const CliResult r = run("check case.toml");
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST_F(CliChecks, FoldedTriangleIsRefusedBeforeAnyReorientation) {
  write_case(R"(
[problem]
dimension = 2
[[body]]
name = "block"
mesh = ")" + kMeshes + R"(folded_triangle.msh"
material = { E = 1.0, nu = 0.3 }
[[body.dirichlet]]
boundary = "bottom"
ux = 0.0
uy = 0.0
[[body.dirichlet]]
boundary = "top"
uy = 0.1
)");
  for (const std::string cmd : {"check case.toml", "run case.toml --out out"}) {
    const CliResult r = run(cmd);
    EXPECT_EQ(r.exit_code, 2) << cmd << "\n" << r.output;
    EXPECT_NE(r.output.find("body[0].mesh"), std::string::npos) << r.output;
    // Element 5 = (3, 4, 5) is the one turned over by node 5 above the top edge.
    EXPECT_NE(r.output.find("element 5: folded element"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("element 4"), std::string::npos) << r.output;
  }
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

/// The upper block of two_blocks.geo under a pressure, held only through its contact with the lower block.
std::string upper_held_by_contact(const std::string& contact_extra) {
  const std::string geo = kGeo + "two_blocks.geo";
  return R"(
[problem]
dimension = 2
[[body]]
name = "lower"
mesh = ")" + geo + R"("
group = "lower"
material = { E = 10.0, nu = 0.3 }
[[body.dirichlet]]
boundary = "bottom"
ux = 0.0
uy = 0.0
[[body]]
name = "upper"
mesh = ")" + geo + R"("
group = "upper"
material = { E = 10.0, nu = 0.3 }
[[body.pressure]]
boundary = "top"
pressure = 0.1
[[contact]]
name = "interface"
a = "lower.interface"
b = "upper.interface"
)" + contact_extra;
}

TEST_F(CliChecks, BodyHeldOnlyByFrictionlessContactIsRefused) {
  write_case(upper_held_by_contact(""));
  for (const std::string cmd : {"check case.toml", "run case.toml --out out"}) {
    const CliResult r = run(cmd);
    EXPECT_EQ(r.exit_code, 2) << cmd << "\n" << r.output;
    EXPECT_NE(r.output.find("body[1]: body 'upper': rigid motion left free: translation in x."),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("'interface'"), std::string::npos) << r.output;
  }
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(CliChecks, BodyHeldThroughFrictionPassesTheSetupCheck) {
  write_case(upper_held_by_contact("friction = \"tresca\"\ntau = 0.01\n"));
  const CliResult r = run("check case.toml");
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST_F(CliChecks, BlockOnAFrictionlessPlaneUnderAVerticalLoadIsRefused) {
  const std::string toml = R"(
[problem]
dimension = 2
[[body]]
name = "block"
mesh = ")" + kGeo + R"(square.geo"
group = "square"
material = { E = 1.0, nu = 0.3 }
[[body.pressure]]
boundary = "top"
pressure = 0.1
[[contact]]
name = "floor"
a = "block.bottom"
[contact.obstacle]
type = "plane"
point = [0.0, 0.0]
normal = [0.0, 1.0]
)";
  write_case(toml);
  CliResult r = run("check case.toml");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("body[0]: body 'block': rigid motion left free: translation in x."), std::string::npos)
      << r.output;
  // Held in x at one side: accepted (the floor's normal holds y and the rotation).
  write_case(toml + R"(
[[body.dirichlet]]
boundary = "left"
ux = 0.0
)");
  r = run("check case.toml");
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST_F(CliChecks, BodiesOverlappingAtTheStartAreRefused) {
  const std::string geo = kGeo + "overlapping_blocks.geo";
  write_case(R"(
[problem]
dimension = 2
[[body]]
name = "lower"
mesh = ")" + geo + R"("
group = "lower"
material = { E = 1.0, nu = 0.3 }
[[body.dirichlet]]
boundary = "lower_bottom"
ux = 0.0
uy = 0.0
[[body]]
name = "upper"
mesh = ")" + geo + R"("
group = "upper"
material = { E = 1.0, nu = 0.3 }
[[body.dirichlet]]
boundary = "upper_top"
ux = 0.0
uy = 0.0
[[contact]]
name = "stack"
a = "lower.lower_top"
b = "upper.upper_bottom"
)");
  for (const std::string cmd : {"check case.toml", "run case.toml --out out"}) {
    const CliResult r = run(cmd);
    EXPECT_EQ(r.exit_code, 2) << cmd << "\n" << r.output;
    EXPECT_NE(r.output.find("contact[0]: contact 'stack': the bodies overlap at the start"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(" lies 0.5 inside"), std::string::npos) << r.output;
  }
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

}  // namespace
