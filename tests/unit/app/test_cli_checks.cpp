/// End-to-end tests of the checks that stand between a solve and a result (issue #19): the checks before the
/// solve (model/setup_checks.hpp, mesh_topology.hpp check_folds(): exit 2, nothing written, `symcontact check`
/// too) and the checks of each load step's answer (post/step_checks.hpp: exit 3, summary.json
/// "solve_failed"). Each wrong problem is one an outside tester found reported as a success, and each has a
/// corrected twin that must still pass. Conventions of test_cli.cpp.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/cli_fixture.hpp"
#include "support/problem_snippet.hpp"

namespace {

namespace fs = std::filesystem;

using symcontact::testing::CliResult;
using symcontact::testing::body_toml;
using symcontact::testing::dirichlet_toml;
using symcontact::testing::expect_all_in;
using symcontact::testing::read_text;

const std::string kGeo = std::string(SYMCONTACT_TEST_DATA) + "/geo/";
const std::string kMeshes = std::string(SYMCONTACT_TEST_DATA) + "/meshes/";

class CliChecks : public symcontact::testing::CliTest {
 protected:
  CliChecks() : CliTest("symcontact_cli_checks_") {}

  fs::path write_case(const std::string& toml) const { return write("case.toml", toml); }
  std::string summary() const { return read_text(dir_ / "out" / "summary.json"); }
};

const std::string kProblem2d = "[problem]\ndimension = 2\n";
const std::string kClamped = "ux = 0.0\nuy = 0.0\n";

/// two_blocks.geo: "lower" [0,1]² held at its bottom, "upper" [0,1]×[1,2] (material `law`, tables
/// `upper_tables`), one symmetric frictionless pair "interface" on the shared line (plus `contact_extra`).
std::string two_blocks(const std::string& law, const std::string& upper_tables, const std::string& contact_extra) {
  const std::string geo = kGeo + "two_blocks.geo";
  return kProblem2d + body_toml("lower", geo, "lower", law, dirichlet_toml("bottom", kClamped)) +
         body_toml("upper", geo, "upper", law, upper_tables) +
         "[[contact]]\nname = \"interface\"\na = \"lower.interface\"\nb = \"upper.interface\"\n" + contact_extra;
}

/// two_blocks() with "upper" driven down by `down` at its top.
std::string driven_blocks(double down, const std::string& material = "", const std::string& contact_extra = "") {
  return two_blocks("E = 10.0, nu = 0.3" + material,
                    dirichlet_toml("top", "ux = 0.0\nuy = " + std::to_string(-down) + "\n"), contact_extra);
}

TEST_F(CliChecks, BlockDrivenThroughTheOtherFailsTheStepCheck) {
  for (const std::string material : {"", ", model = \"neo_hookean\""}) {
    write_case(driven_blocks(5.0, material));
    const CliResult r = run("run case.toml --out out");
    EXPECT_EQ(r.exit_code, 3) << material << "\n" << r.output;
    expect_all_in(r.output, {"load step 1: check of the answer", "contact 'interface'", "went through each other"});
    EXPECT_NE(summary().find("\"status\": \"solve_failed\""), std::string::npos);
    EXPECT_EQ(summary().find("\"status\": \"ok\""), std::string::npos);
    fs::remove_all(dir_ / "out");
  }
}

TEST_F(CliChecks, MotionBeyondTheSearchDistanceFailsTheStepCheck) {
  write_case(driven_blocks(0.7, "", "search_distance = 0.6\n"));
  const CliResult r = run("run case.toml --out out");
  EXPECT_EQ(r.exit_code, 3) << r.output;
  expect_all_in(r.output, {"contact 'interface'", "% of the element size"});
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

const std::string kPressTop = "[[body.pressure]]\nboundary = \"top\"\npressure = ";

/// square.geo pushed down by a pressure onto the meshed floor of `floor_geo`, held in x on its left side.
std::string block_on_meshed_floor(const std::string& floor_geo) {
  return kProblem2d +
         body_toml("block", kGeo + "square.geo", "square", "E = 100.0, nu = 0.3",
                   dirichlet_toml("left", "ux = 0.0\n") + kPressTop + "1.0\n") +
         "[[contact]]\nname = \"floor\"\na = \"block.bottom\"\n[contact.obstacle]\ntype = \"mesh\"\nmesh = \"" + kGeo +
         floor_geo + "\"\nboundary = \"floor\"\n";
}

TEST_F(CliChecks, MeshedObstacleFacingAwayIsRefused) {
  write_case(block_on_meshed_floor("floor_facing_away.geo"));
  expect_refused_by_check_and_run("case.toml", {"contact[0].obstacle", "face away from body 'block'"});
}

TEST_F(CliChecks, MeshedObstacleFacingTheBodyIsAccepted) {
  write_case(block_on_meshed_floor("floor_facing_up.geo"));
  const CliResult r = run("check case.toml");
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST_F(CliChecks, FoldedTriangleIsRefusedBeforeAnyReorientation) {
  write_case(kProblem2d + body_toml("block", kMeshes + "folded_triangle.msh", "", "E = 1.0, nu = 0.3",
                                    dirichlet_toml("bottom", kClamped) + dirichlet_toml("top", "uy = 0.1\n")));
  // Element 5 = (3, 4, 5) is the one turned over by node 5 above the top edge.
  expect_refused_by_check_and_run("case.toml", {"body[0].mesh", "element 5: folded element", "element 4"});
}

/// The upper block of two_blocks.geo under a pressure, held only through its contact with the lower block.
std::string upper_held_by_contact(const std::string& contact_extra) {
  return two_blocks("E = 10.0, nu = 0.3", kPressTop + "0.1\n", contact_extra);
}

TEST_F(CliChecks, BodyHeldOnlyByFrictionlessContactIsRefused) {
  write_case(upper_held_by_contact(""));
  expect_refused_by_check_and_run("case.toml",
                                  {"body[1]: body 'upper': rigid motion left free: translation in x.", "'interface'"});
}

TEST_F(CliChecks, BodyHeldThroughFrictionPassesTheSetupCheck) {
  write_case(upper_held_by_contact("friction = \"tresca\"\ntau = 0.01\n"));
  const CliResult r = run("check case.toml");
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST_F(CliChecks, BlockOnAFrictionlessPlaneUnderAVerticalLoadIsRefused) {
  const std::string toml =
      kProblem2d + body_toml("block", kGeo + "square.geo", "square", "E = 1.0, nu = 0.3", kPressTop + "0.1\n") +
      "[[contact]]\nname = \"floor\"\na = \"block.bottom\"\n[contact.obstacle]\ntype = \"plane\"\n"
      "point = [0.0, 0.0]\nnormal = [0.0, 1.0]\n";
  write_case(toml);
  CliResult r = run("check case.toml");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("body[0]: body 'block': rigid motion left free: translation in x."), std::string::npos)
      << r.output;
  // Held in x at one side: accepted (the floor's normal holds y and the rotation).
  write_case(toml + dirichlet_toml("left", "ux = 0.0\n"));
  r = run("check case.toml");
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST_F(CliChecks, BodiesOverlappingAtTheStartAreRefused) {
  const std::string geo = kGeo + "overlapping_blocks.geo";
  write_case(kProblem2d +
             body_toml("lower", geo, "lower", "E = 1.0, nu = 0.3", dirichlet_toml("lower_bottom", kClamped)) +
             body_toml("upper", geo, "upper", "E = 1.0, nu = 0.3", dirichlet_toml("upper_top", kClamped)) +
             "[[contact]]\nname = \"stack\"\na = \"lower.lower_top\"\nb = \"upper.upper_bottom\"\n");
  expect_refused_by_check_and_run(
      "case.toml", {"contact[0]: contact 'stack': the bodies overlap at the start", " lies 0.5 inside"});
}

/// disk_in_bowl.geo's disk in a bowl of radius 2 (an analytic circle, inside), slid sideways by 0.5 along the
/// bowl's bottom tangent and pressed down by 0.003 at its top, with the contact's `geometry` as given.
std::string disk_in_bowl(const std::string& geometry) {
  return kProblem2d + "[steps]\ncount = 2\n\n" +
         body_toml("disk", kGeo + "disk_in_bowl.geo", "disk", "E = 1000.0, nu = 0.3",
                   dirichlet_toml("disk_top", "ux = 0.5\nuy = -0.003\n")) +
         "[[contact]]\nname = \"seat\"\na = \"disk.disk_bottom\"\ngeometry = \"" + geometry +
         "\"\n[contact.obstacle]\ntype = \"circle\"\ncenter = [0.0, 2.0]\nradius = 2.0\ninside = true\n";
}

TEST_F(CliChecks, SmallSlidingBeyondItsAssumptionIsAWarningNotAFailure) {
  // Small sliding holds the disk to the bowl's gaps and normals at the start: it slides along the bottom's
  // tangent and ends 0.5² / 4 ≈ 0.06 inside the rising bowl (3 elements deep). That is the model the user
  // chose, solved correctly (its linearised gaps hold): the run is ok and says where the assumption broke.
  write_case(disk_in_bowl("reference"));
  CliResult r = run("run case.toml --out out");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  expect_all_in(r.output, {"warning: load step 2: contact 'seat'", "of 'disk.disk_bottom' is", "inside the obstacle",
                           "in the deformed configuration", "geometry = \"reference\" (small sliding)",
                           "geometry = \"current\" follows the motion"});
  expect_all_in(summary(), {"\"status\": \"ok\"", "\"warnings\": [\n", "in the deformed configuration"});
  // Finite sliding follows the bowl up: no warning, and every step's list of warnings is empty.
  write_case(disk_in_bowl("current"));
  r = run("run case.toml --out out");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
  EXPECT_EQ(summary().find("deformed configuration"), std::string::npos);
  EXPECT_NE(summary().find("\"warnings\": []"), std::string::npos);
}

}  // namespace
