/// End-to-end tests of the command-line program (app/main.cpp): exit codes, output files, and that
/// every input error names the file and the key or group at fault and leaves no output folder behind.
/// The binary is SYMCONTACT_CLI; each test works in its own temporary folder (CTest runs them in
/// parallel) and runs the program through the shell, capturing stdout and stderr together.

#include <gtest/gtest.h>

#include "support/cli_fixture.hpp"
#include "symcontact/core/blas_kernels.hpp"
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

using symcontact::testing::CliResult;
using symcontact::testing::read_text;
using symcontact::testing::shell_quote;

/// The [problem] table and one 2D linear-elastic body; `extra` is appended (dirichlet, pressure, ...).
std::string problem_toml(const std::string& mesh, const std::string& group, const std::string& nu,
                         const std::string& extra, const std::string& problem_extra = "") {
  return "[problem]\ndimension = 2\nmodel = \"plane_strain\"\n" + problem_extra +
         "\n[[body]]\nname = \"block\"\nmesh = \"" + mesh + "\"\ngroup = \"" + group +
         "\"\n\n[body.material]\nmodel = \"linear_elastic\"\nE = 1000.0\nnu = " + nu + "\n\n" + extra;
}

const std::string kClampBottom = "[[body.dirichlet]]\nboundary = \"bottom\"\nux = 0.0\nuy = 0.0\n\n";
const std::string kPressTop = "[[body.pressure]]\nboundary = \"top\"\npressure = 10.0\n";

std::string example_geo() { return std::string(SYMCONTACT_EXAMPLES) + "/block_2d/block.geo"; }
std::string test_mesh(const std::string& name) { return std::string(SYMCONTACT_TEST_DATA) + "/meshes/" + name; }

class Cli : public symcontact::testing::CliTest {
 protected:
  Cli() : CliTest("symcontact_cli_") {}
};

TEST_F(Cli, VersionPrintsTheVersion) {
  const CliResult r = run("--version");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find(std::string("symcontact ") + SYMCONTACT_VERSION), std::string::npos) << r.output;
}

TEST_F(Cli, NoSubcommandOrUnknownOptionIsAnInputError) {
  EXPECT_EQ(run("").exit_code, 2);
  EXPECT_EQ(run("run").exit_code, 2);  // the case file is required
  EXPECT_EQ(run("run x.toml --no-such-option").exit_code, 2);
}

TEST_F(Cli, RunBlockExampleWritesResults) {
  const fs::path out = dir_ / "block_out";
  const CliResult r = run("run " + shell_quote(std::string(SYMCONTACT_EXAMPLES) + "/block_2d/block.toml") + " --out " +
                          shell_quote(out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  ASSERT_TRUE(fs::is_regular_file(out / "summary.json")) << r.output;
  const std::string summary = read_text(out / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"ok\""), std::string::npos) << summary;
  EXPECT_TRUE(fs::is_regular_file(out / "results.pvd"));
  int vtu = 0;
  for (const auto& e : fs::directory_iterator(out)) vtu += e.path().extension() == ".vtu" ? 1 : 0;
  EXPECT_EQ(vtu, 2) << "one body, two load steps";
  EXPECT_TRUE(fs::is_regular_file(out / "block_0001.vtu"));
  EXPECT_TRUE(fs::is_regular_file(out / "block_0002.vtu"));
}

TEST_F(Cli, DefaultOutputFolderIsNamedAfterTheCase) {
  write("press.toml", problem_toml(example_geo(), "block", "0.3", kClampBottom + kPressTop));
  const CliResult r = run("run press.toml -q");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::is_regular_file(dir_ / "press_results" / "summary.json"));
  EXPECT_EQ(r.output, "") << "-q prints errors only";
}

TEST_F(Cli, CheckBuildsTheModelAndWritesNothing) {
  const fs::path case_file = write("press.toml", problem_toml(example_geo(), "block", "0.3", kClampBottom + kPressTop));
  const CliResult r = run("check " + shell_quote(case_file));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("OK"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "press_results"));
}

// OpenBLAS's fallback kernels (blas_kernels.hpp): where this process got a family without AVX on a CPU with
// AVX2 (a CPU newer than OpenBLAS's table), `symcontact` restarts itself with better kernels and says so at -v;
// elsewhere, and whenever OPENBLAS_CORETYPE is set, it keeps the kernels it was given and says nothing.
TEST_F(Cli, FallbackBlasKernelsAreReplacedOnlyWhenTheUserChoseNone) {
  const fs::path case_file = write("press.toml", problem_toml(example_geo(), "block", "0.3", kClampBottom + kPressTop));
  const std::string better = std::getenv("OPENBLAS_CORETYPE") ? "" : symcontact::better_blas_core(symcontact::blas_core_name());
  const CliResult r = run("-v check " + shell_quote(case_file));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("running with OPENBLAS_CORETYPE=") != std::string::npos, !better.empty()) << r.output;
  if (!better.empty()) {
    EXPECT_NE(r.output.find("running with OPENBLAS_CORETYPE=" + better), std::string::npos) << r.output;
  }
  const CliResult chosen = run_with_env("OPENBLAS_CORETYPE=Prescott", "-v check " + shell_quote(case_file));
  EXPECT_EQ(chosen.exit_code, 0) << chosen.output;
  EXPECT_EQ(chosen.output.find("OPENBLAS_CORETYPE"), std::string::npos) << chosen.output;
}

TEST_F(Cli, MissingDirichletGroupIsAnInputError) {
  const fs::path f = write("missing_group.toml",
                           problem_toml(example_geo(), "block", "0.3",
                                        "[[body.dirichlet]]\nboundary = \"nowhere\"\nuy = 0.0\n\n" + kPressTop));
  expect_input_error(f, {"missing_group.toml", "body[0].dirichlet[0].boundary", "nowhere"});
}

TEST_F(Cli, MissingBodyGroupIsAnInputError) {
  const fs::path f = write("missing_body.toml", problem_toml(example_geo(), "nobody", "0.3", kClampBottom));
  expect_input_error(f, {"missing_body.toml", "body[0].group", "nobody"});
}

TEST_F(Cli, UnknownKeyIsAnInputError) {
  const fs::path f =
      write("unknown_key.toml", problem_toml(example_geo(), "block", "0.3", kClampBottom, "colour = \"red\"\n"));
  expect_input_error(f, {"unknown_key.toml", "problem.colour"});
}

TEST_F(Cli, IncompressiblePoissonRatioIsAnInputError) {
  const fs::path f = write("nu_half.toml", problem_toml(example_geo(), "block", "0.5", kClampBottom + kPressTop));
  expect_input_error(f, {"nu_half.toml", "body[0].material.nu"});
}

TEST_F(Cli, MissingMeshFileIsAnInputError) {
  const fs::path f = write("no_mesh.toml", problem_toml("does_not_exist.msh", "block", "0.3", kClampBottom));
  expect_input_error(f, {"no_mesh.toml", "body[0].mesh", "does_not_exist.msh"});
}

TEST_F(Cli, HandWrittenMshRuns) {
  // The control for the two broken meshes below: the same file format, well formed, solves.
  const fs::path f = write("square.toml", problem_toml(test_mesh("unit_square.msh"), "square", "0.3",
                                                       kClampBottom + kPressTop));
  const fs::path& out = out_;
  const CliResult r = run_case(f);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(read_text(out / "summary.json").find("\"status\": \"ok\""), std::string::npos);
}

TEST_F(Cli, TruncatedMshIsAnInputError) {
  const fs::path f = write("truncated.toml", problem_toml(test_mesh("truncated_nodes.msh"), "square", "0.3",
                                                          kClampBottom + kPressTop));
  expect_input_error(f, {"truncated_nodes.msh"});
}

TEST_F(Cli, DegenerateTriangleIsAnInputErrorNamingTheCell) {
  // The third triangle of the body, (0,0) (0.5,0) (1,0), has zero area; it is element 5 of the file,
  // and the message names it by that tag, with the problem file, the body and the mesh file.
  const fs::path f = write("degenerate.toml", problem_toml(test_mesh("degenerate_triangle.msh"), "square", "0.3",
                                                           kClampBottom + kPressTop));
  expect_input_error(f, {"degenerate.toml", "body[0].mesh", "degenerate_triangle.msh", "element 5", "degenerate"});
}

TEST_F(Cli, BodyHeldByNothingIsAnInputError) {
  // No Dirichlet condition and no contact: nothing can hold the body, whatever the loads (docs/checks.md).
  const fs::path f = write("rigid.toml", problem_toml(example_geo(), "block", "0.3", kPressTop));
  expect_input_error(f, {"rigid.toml", "body[0]", "body \"block\"", "no [[body.dirichlet]]", "no [[contact]]",
                         "rigid motion"});
}

TEST_F(Cli, PartlyConstrainedBodyIsAnInputError) {
  // A Dirichlet condition on ux alone leaves the pressed body free to move along y: found before the solve
  // (model/setup_checks.hpp), naming the body and the free motion.
  const fs::path f = write("sliding.toml", problem_toml(example_geo(), "block", "0.3",
                                                        "[[body.dirichlet]]\nboundary = \"bottom\"\nux = 0.0\n\n" +
                                                            kPressTop));
  expect_input_error(f, {"sliding.toml", "body[0]", "body 'block'",
                         "rigid motion left free: translation in y; a combination of translation in x + rotation about z",
                         "No Dirichlet condition holds it"});
}

TEST_F(Cli, ExpressionThatDoesNotCompileIsAnInputErrorGivingThePosition) {
  const fs::path f = write("expr.toml", problem_toml(example_geo(), "block", "0.3",
                                                     kClampBottom + "[[body.pressure]]\nboundary = \"top\"\n"
                                                                    "pressure = \"10*t*(1 + q)\"\n"));
  expect_input_error(f, {"expr.toml: body[0].pressure[0].pressure:", "character 11 of \"10*t*(1 + q)\"",
                         "unexpected token \"q\" (the variables are x, y, z and t)"});
}

TEST_F(Cli, ExpressionNotFiniteAtANodeIsAnInputErrorNamingTheNode) {
  // block.geo: the 2 × 1 block; its bottom runs from (0, 0) to (2, 0).
  const fs::path f = write("inf.toml", problem_toml(example_geo(), "block", "0.3",
                                                    "[[body.dirichlet]]\nboundary = \"bottom\"\nux = 0.0\n"
                                                    "uy = \"t/(x - 2)\"\n\n" + kPressTop));
  expect_input_error(f, {"inf.toml: body[0].dirichlet[0].uy:", "the expression \"t/(x - 2)\" is",
                         "at the node (x, y, z) = (2, 0, 0)"});
}

TEST_F(Cli, DuplicateNodesAreAnInputErrorNamingTheNodes) {
  // Node 6 repeats node 1 at (0, 0) but no triangle has both: the square is cut from (0, 0) to its
  // centre. The message names the problem file, the body, the mesh file and the two node tags.
  const fs::path f = write("crack.toml", problem_toml(test_mesh("crack_duplicate_nodes.msh"), "square", "0.3",
                                                      kClampBottom + kPressTop));
  expect_input_error(f, {"crack.toml", "body[0].mesh", "body 'block'", "crack_duplicate_nodes.msh",
                         "node 1 and node 6 at (0, 0)", "same position without sharing any element"});
}

TEST_F(Cli, AGroupFacetOnDuplicateNodesIsAnInputErrorNamingTheNodes) {
  // The top edge of the square is written from node 3 to node 6, a twin of the corner node 4 that no triangle
  // uses (as Gmsh's Geometry.AutoCoherence = 0 leaves a surface's boundary nodes). Left out as the edge of
  // another body would be, it would take the pressure of the top away without a word; held in a Dirichlet
  // condition, node 4 would stay free.
  const std::string mesh = test_mesh("surface_duplicate_nodes.msh");
  const fs::path f = write("twin.toml", problem_toml(mesh, "square", "0.3", kClampBottom + kPressTop));
  expect_input_error(f, {"twin.toml", "body[0].pressure[0].boundary", "body 'block'", "surface_duplicate_nodes.msh",
                         "group 'top'", "node 6 of one of its facets", "sits at the position of body node 4",
                         "duplicate nodes", "AutoCoherence"});
  const std::string clamp_top = "[[body.dirichlet]]\nboundary = \"top\"\nux = 0.0\n\n";
  const fs::path held = write("twin_held.toml", problem_toml(mesh, "square", "0.3", kClampBottom + clamp_top));
  expect_input_error(held, {"twin_held.toml", "body[0].dirichlet[1].boundary", "group 'top'", "node 6"});
  // A group no condition names is harmless.
  const fs::path unused = write("twin_unused.toml", problem_toml(mesh, "square", "0.3", kClampBottom));
  const CliResult r = run("check " + shell_quote(unused.string()));
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST_F(Cli, CrackWithItsFacesInSelfContactIsAllowed) {
  // crack_faces.msh: crack_duplicate_nodes.msh with the crack's two faces in the boundary group "crack". In
  // self-contact, the twins are allowed; a contact of the crack with another surface does not allow them.
  const std::string crack = "[[contact]]\na = \"block.crack\"\nb = \"block.crack\"\n";
  const fs::path ok = write("crack_ok.toml", problem_toml(test_mesh("crack_faces.msh"), "square", "0.3",
                                                          kClampBottom + kPressTop + crack));
  const CliResult r = run("check " + shell_quote(ok.string()));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const std::string other = "[[contact]]\na = \"block.crack\"\nb = \"block.top\"\n";
  const fs::path f = write("crack_top.toml", problem_toml(test_mesh("crack_faces.msh"), "square", "0.3",
                                                          kClampBottom + kPressTop + other));
  expect_input_error(f, {"crack_top.toml", "body[0].mesh", "body 'block'", "crack_faces.msh",
                         "node 1 and node 6 at (0, 0)", "[[contact]] a = b = \"block.G\"",
                         "self-contact surfaces of this body: 'crack' with 'top'"});
}

TEST_F(Cli, DisconnectedBodyIsAnInputErrorGivingThePieces) {
  // Two unit squares, [0, 1] and [2, 3] along x, in one physical group; only the first one clamped.
  const std::string clamp_left = "[[body.dirichlet]]\nboundary = \"bottom_left\"\nux = 0.0\nuy = 0.0\n\n";
  const fs::path f = write("two_pieces.toml", problem_toml(test_mesh("two_pieces_groups.msh"), "square", "0.3",
                                                           clamp_left + kPressTop));
  expect_input_error(f, {"two_pieces.toml", "body[0].mesh", "body 'block'", "two_pieces_groups.msh", "disconnected",
                         "2 separate pieces", "2 elements from element 5, 2 elements from element 7",
                         "1 of them (2 elements from element 7) has no node on a contact surface or a Dirichlet "
                         "boundary of the body (contact surfaces: none; Dirichlet boundaries: 'bottom_left')"});
}

TEST_F(Cli, BodyInPiecesEachClampedIsAllowed) {
  // The same two squares, each with its own clamped bottom (disconnected.msh: one group over both bottoms).
  const std::string clamp_right = "[[body.dirichlet]]\nboundary = \"bottom_right\"\nux = 0.0\nuy = 0.0\n\n";
  const std::string clamp_left = "[[body.dirichlet]]\nboundary = \"bottom_left\"\nux = 0.0\nuy = 0.0\n\n";
  const fs::path f = write("two_clamped.toml", problem_toml(test_mesh("two_pieces_groups.msh"), "square", "0.3",
                                                            clamp_left + clamp_right + kPressTop));
  const CliResult r = run("check " + shell_quote(f.string()));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const fs::path g = write("one_group.toml", problem_toml(test_mesh("disconnected.msh"), "square", "0.3",
                                                          kClampBottom + kPressTop));
  EXPECT_EQ(run("check " + shell_quote(g.string())).exit_code, 0);
}

TEST_F(Cli, NonFiniteMshCoordinateIsAnInputErrorNamingTheLine) {
  // unit_square.msh with node 3's x written "nan" (line 25): found before Gmsh reads the file.
  const fs::path f = write("nan.toml", problem_toml(test_mesh("nan_coordinate.msh"), "square", "0.3",
                                                    kClampBottom + kPressTop));
  expect_input_error(f, {"nan.toml", "body[0].mesh", "body 'block'", "nan_coordinate.msh", "line 25", "node 3",
                         "not a finite number"});
}

TEST_F(Cli, ContactSurfaceInsideTheBodyIsAnInputError) {
  // The group "diagonal" (element 3) is the edge shared by the square's two triangles (elements 4 and 5).
  const std::string contact =
      "[[contact]]\na = \"block.diagonal\"\n[contact.obstacle]\ntype = \"plane\"\npoint = [0.0, -1.0]\n"
      "normal = [0.0, 1.0]\n";
  const fs::path f = write("inside.toml", problem_toml(test_mesh("interior_facet_group.msh"), "square", "0.3",
                                                       kClampBottom + kPressTop + contact));
  expect_input_error(f, {"inside.toml", "contact[0].a", "body 'block'", "interior_facet_group.msh", "'diagonal'",
                         "element 3 of this group is shared by element 4 and element 5", "not on its boundary"});
  // The same group as a traction boundary: refused under that key.
  const std::string load = "[[body.traction]]\nboundary = \"diagonal\"\ntraction = [0.0, -1.0]\n\n";
  const fs::path t = write("inside_load.toml", problem_toml(test_mesh("interior_facet_group.msh"), "square", "0.3",
                                                            kClampBottom + load));
  expect_input_error(t, {"inside_load.toml", "body[0].traction[0].boundary", "'diagonal'", "not on its boundary"});
}

TEST_F(Cli, FacetGroupInsideTheBodyIsAllowedUnusedOrForDirichlet) {
  // A mesh with an interface curve inside the body (two materials, a line of sensors) is a valid mesh: the
  // group is refused only where a boundary is needed, and a Dirichlet condition may hold its nodes.
  const fs::path f = write("unused.toml", problem_toml(test_mesh("interior_facet_group.msh"), "square", "0.3",
                                                       kClampBottom + kPressTop));
  CliResult r = run("check " + shell_quote(f.string()));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const std::string hold = "[[body.dirichlet]]\nboundary = \"diagonal\"\nux = 0.0\nuy = 0.0\n\n";
  const fs::path g = write("held.toml", problem_toml(test_mesh("interior_facet_group.msh"), "square", "0.3",
                                                     hold + kPressTop));
  r = run("run " + shell_quote(g.string()) + " -o " + shell_quote((dir_ / "held_out").string()));
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

}  // namespace
