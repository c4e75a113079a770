/// End-to-end tests of inputs that used to crash, hang or be reported as internal errors (issue #19):
/// a .geo Gmsh cannot mesh, absurd or invalid mesh sizes, problem and mesh files that are not regular
/// files, IPOPT options IPOPT rejects, results that overflow, an output folder that cannot be written,
/// and .geo files that run programs. Each input error must exit 2 with a message naming the file and
/// the key and what was expected, and leave no output folder; an overflowing solve exits 3 and keeps
/// the finished steps. Conventions of test_cli.cpp (support/cli_fixture.hpp).

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <regex>
#include <string>

#include "support/cli_fixture.hpp"
#include "support/problem_snippet.hpp"

namespace {

namespace fs = std::filesystem;

using symcontact::testing::CliResult;
using symcontact::testing::read_text;
using symcontact::testing::shell_quote;

const std::string kBlockGeo = std::string(SYMCONTACT_EXAMPLES) + "/block_2d/block.geo";

/// The 2 × 1 block of examples/block_2d, clamped at the bottom and pressed on top by `pressure`, with
/// its mesh `mesh`; `extra` is appended (tables after the body).
std::string block_toml(const std::string& mesh, const std::string& E = "1000.0", const std::string& pressure = "10.0",
                       const std::string& extra = "", const std::string& problem_extra = "") {
  return "[problem]\ndimension = 2\nmodel = \"plane_strain\"\n" + problem_extra +
         "\n[steps]\nload_factors = [0.5, 1.0]\n\n[[body]]\nname = \"block\"\nmesh = \"" + mesh +
         "\"\ngroup = \"block\"\n\n[body.material]\nmodel = \"linear_elastic\"\nE = " + E +
         "\nnu = 0.3\n\n[[body.dirichlet]]\nboundary = \"bottom\"\nux = 0.0\nuy = 0.0\n\n"
         "[[body.pressure]]\nboundary = \"top\"\npressure = " + pressure + "\n\n" + extra;
}

/// block.geo with `from` replaced by `to`.
std::string block_geo_with(const std::string& from, const std::string& to) {
  return symcontact::testing::replaced(read_text(kBlockGeo), from, to);
}

class CliInputErrors : public symcontact::testing::CliTest {
 protected:
  CliInputErrors() : CliTest("symcontact_cli_errors_") {}
};

// ---- 1. Gmsh cannot mesh the .geo ----

TEST_F(CliInputErrors, OpenCurveLoopIsAnInputErrorWithGmshsMessage) {
  // Gmsh throws from inside its parallel meshing loop, which used to abort the process.
  write("open.geo", block_geo_with("Curve Loop(1) = {1, 2, 3, 4};", "Curve Loop(1) = {1, 2, 3};"));
  const fs::path f = write("open.toml", block_toml("open.geo"));
  expect_input_error(f, {"open.toml", "body[0].mesh", "body 'block'", "open.geo", "Gmsh failed while meshing",
                         "not to be forming a closed loop"});
  const CliResult r = run("check " + shell_quote(f));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output.find("terminate"), std::string::npos) << r.output;
}

// ---- 2. mesh sizes ----

TEST_F(CliInputErrors, MeshSizeThatWouldExhaustMemoryIsRefusedBeforeMeshing) {
  const fs::path f = write("press.toml", block_toml(kBlockGeo));
  // 2·A/h² = 2·2/1e-10 = 4e10 triangles.
  expect_input_error(f, {"press.toml", "body[0].mesh", "--mesh-size = 1e-05", "about 4e+10 triangles",
                         "limit of 5e+06 cells", "--allow-large-mesh"},
                     "--mesh-size 1e-5");
  // The same size from the problem file names its key.
  const fs::path g = write("fine.toml", block_toml(kBlockGeo, "1000.0", "10.0", "", "mesh_size = 1e-5\n"));
  expect_input_error(g, {"fine.toml", "problem.mesh_size = 1e-05", "4e+10"});
}

TEST_F(CliInputErrors, MeshSizeMustBeAFinitePositiveNumberShownAsTyped) {
  const fs::path f = write("press.toml", block_toml(kBlockGeo));
  for (const std::string h : {"nan", "0", "-1", "inf", "-inf", "1e-400x"}) {
    for (const std::string command : {"run", "check"}) {
      const CliResult r = run(command + " " + shell_quote(f) + " --out out --mesh-size " + h);
      EXPECT_EQ(r.exit_code, 2) << h << ": " << r.output;
      EXPECT_NE(r.output.find("--mesh-size"), std::string::npos) << r.output;
      EXPECT_NE(r.output.find("got '" + h + "'"), std::string::npos) << r.output;
      EXPECT_FALSE(std::regex_search(r.output, std::regex("[0-9]{20}"))) << "an unreadable number: " << r.output;
      EXPECT_FALSE(fs::exists(dir_ / "out"));
    }
  }
}

// ---- 3. files that are not regular files ----

TEST_F(CliInputErrors, ProblemFileThatIsAFifoIsAnInputErrorNotAHang) {
  const fs::path fifo = dir_ / "pipe.toml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expect_input_error(fifo, {"pipe.toml", "is a FIFO", "expected a regular file"});
}

TEST_F(CliInputErrors, ProblemFileLinkedToADeviceIsAnInputError) {
  fs::create_symlink("/dev/zero", dir_ / "zero.toml");
  expect_input_error(dir_ / "zero.toml", {"zero.toml", "is a character device", "/dev/zero", "expected a regular file"});
}

TEST_F(CliInputErrors, SymbolicLinkLoopIsReportedAsALoop) {
  fs::create_symlink(dir_ / "b.toml", dir_ / "a.toml");
  fs::create_symlink(dir_ / "a.toml", dir_ / "b.toml");
  expect_input_error(dir_ / "a.toml", {"a.toml", "symbolic link loop"});
  const CliResult r = run("check " + shell_quote(dir_ / "a.toml"));
  EXPECT_EQ(r.output.find("does not exist"), std::string::npos) << r.output;
}

TEST_F(CliInputErrors, ProblemFileAboveTheSizeLimitIsAnInputError) {
  const fs::path big = write("big.toml", block_toml(kBlockGeo));
  fs::resize_file(big, (std::uintmax_t{64} << 20) + 1);  // sparse: costs no disk
  expect_input_error(big, {"big.toml", "67108865 bytes", "limit of 67108864 bytes (64 MiB)"});
}

TEST_F(CliInputErrors, MeshFileThatIsAFifoOrALoopIsAnInputError) {
  ASSERT_EQ(::mkfifo((dir_ / "pipe.msh").c_str(), 0600), 0);
  expect_input_error(write("fifo_mesh.toml", block_toml("pipe.msh")),
                     {"fifo_mesh.toml", "body[0].mesh", "pipe.msh", "is a FIFO"});
  fs::create_symlink(dir_ / "loop.geo", dir_ / "loop.geo");
  expect_input_error(write("loop_mesh.toml", block_toml("loop.geo")),
                     {"loop_mesh.toml", "body[0].mesh", "loop.geo", "symbolic link loop"});
}

// ---- 4. IPOPT options, overflow, the output folder ----

TEST_F(CliInputErrors, UnknownOrInvalidIpoptOptionIsAnInputErrorBeforeAnyWork) {
  const fs::path f = write("unknown.toml", block_toml(kBlockGeo, "1000.0", "10.0", "[ipopt]\nno_such_option = 3\n"));
  expect_input_error(f, {"unknown.toml", "ipopt.no_such_option", "no such IPOPT option"});
  const CliResult r = run("check " + shell_quote(f));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("ipopt.no_such_option"), std::string::npos) << r.output;
  const fs::path g = write("range.toml", block_toml(kBlockGeo, "1000.0", "10.0", "[ipopt]\nmax_iter = -3\n"));
  expect_input_error(g, {"range.toml", "ipopt.max_iter", "out of range"});
  const fs::path h = write("type.toml", block_toml(kBlockGeo, "1000.0", "10.0", "[ipopt]\nmu_strategy = 2\n"));
  expect_input_error(h, {"type.toml", "ipopt.mu_strategy", "expected a string"});
}

/// Runs `toml`, expects a failed solve (exit 3) reporting non-finite values in body 'block' at `step`,
/// with summary.json "solve_failed" and the VTU of every step before `step` kept.
void expect_non_finite_failure(const CliResult& r, const fs::path& out, int step) {
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("non-finite values in body 'block' at step " + std::to_string(step)), std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
  const std::string summary = read_text(out / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"solve_failed\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("non-finite values"), std::string::npos) << summary;
  for (int k = 1; k < step; ++k) EXPECT_TRUE(fs::is_regular_file(out / ("block_000" + std::to_string(k) + ".vtu")));
  EXPECT_FALSE(fs::exists(out / ("block_000" + std::to_string(step) + ".vtu")));
}

TEST_F(CliInputErrors, TinyYoungsModulusIsAFailedSolveNotAnInternalError) {
  const fs::path f = write("soft.toml", block_toml(kBlockGeo, "1e-300"));
  const CliResult r = run("run " + shell_quote(f) + " --out out");
  expect_non_finite_failure(r, dir_ / "out", 1);
}

TEST_F(CliInputErrors, HugePressureFailsAtTheStepThatOverflowsKeepingTheOthers) {
  // Step 1 at factor 1e-190 gives a pressure of 1e10, finite; step 2 at 1e200 overflows the stresses.
  std::string toml = block_toml(kBlockGeo, "1000.0", "1e200");
  toml.replace(toml.find("[0.5, 1.0]"), 10, "[1e-190, 1.0]");
  const fs::path f = write("huge.toml", toml);
  const CliResult r = run("run " + shell_quote(f) + " --out out");
  expect_non_finite_failure(r, dir_ / "out", 2);
  EXPECT_NE(read_text(dir_ / "out" / "summary.json").find("\"step\": 1"), std::string::npos);
}

TEST_F(CliInputErrors, OutputFolderThatCannotBeWrittenIsAnInputErrorBeforeAnyWork) {
  // Checked before the problem is read: the model's log line "body 'block': ..." must not appear.
  const fs::path f = write("press.toml", block_toml(kBlockGeo));
  write("taken", "a file");
  struct Case {
    std::string out, expected;
  };
  const std::string long_part(300, 'x');
  std::string long_path;
  for (int i = 0; i < 20; ++i) long_path += std::string(200, 'd') + "/";
  for (const Case& c : {Case{"taken", "is a file, not a folder"}, Case{"taken/sub", "which is a file"},
                        Case{"/proc/symcontact_out", "is not writable"},
                        Case{long_part, "more than the limit of 255"}, Case{long_path, "is too long"}}) {
    const CliResult r = run("run " + shell_quote(f) + " --out " + shell_quote(c.out));
    EXPECT_EQ(r.exit_code, 2) << c.out << ": " << r.output;
    EXPECT_NE(r.output.find("--out"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("block'"), std::string::npos) << "the model was built: " << r.output;
  }
  EXPECT_EQ(read_text(dir_ / "taken"), "a file");
  std::error_code ec;  // the names are too long for the system: fs::exists(name) throws
  EXPECT_FALSE(fs::exists(dir_ / long_part, ec));
  EXPECT_FALSE(fs::exists(dir_ / std::string(200, 'd'), ec));
}

// ---- 6. .geo files that run programs ----

TEST_F(CliInputErrors, GeoRunningAProgramIsRefusedUnlessAllowed) {
  // Line 3 of the .geo would create the file "marker" in the test's folder.
  write("call.geo", block_geo_with("lc = 0.1;\n", "lc = 0.1;\n// SystemCall \"in a comment\";\nSystemCall \"touch " +
                                                      (dir_ / "marker").string() + "\";\n"));
  const fs::path f = write("call.toml", block_toml("call.geo"));
  expect_input_error(f, {"call.toml", "body[0].mesh", "call.geo", "line 4", "'SystemCall' runs another program",
                         "--allow-geo-commands"});
  const CliResult checked = run("check " + shell_quote(f));
  EXPECT_EQ(checked.exit_code, 2) << checked.output;
  EXPECT_FALSE(fs::exists(dir_ / "marker")) << "the command ran";
  // A file that includes it is refused the same way, naming the included file.
  write("outer.geo", "Include \"call.geo\";\n");
  expect_input_error(write("outer.toml", block_toml("outer.geo")), {"outer.toml", "call.geo", "line 4", "SystemCall"});
  // With the flag, the user takes responsibility: the command runs.
  const CliResult allowed = run("check " + shell_quote(f) + " --allow-geo-commands");
  EXPECT_EQ(allowed.exit_code, 0) << allowed.output;
  EXPECT_TRUE(fs::exists(dir_ / "marker"));
}

// ---- 7. point loads and total-force tractions ----

TEST_F(CliInputErrors, PointLoadOnAMissingOrNonPointGroupIsAnInputError) {
  // examples/block_2d's mesh: "origin" is its physical point, "top" a physical curve.
  const auto point_load = [](const std::string& group, const std::string& force) {
    return "[[body.point_load]]\ngroup = \"" + group + "\"\nforce = " + force + "\n";
  };
  expect_input_error(write("curve.toml", block_toml(kBlockGeo, "1000.0", "10.0", point_load("top", "[1.0, 0.0]"))),
                     {"curve.toml", "body[0].point_load[0].group", "expected a physical point group, got 'top'",
                      "a boundary group (dimension 1)"});
  expect_input_error(write("missing.toml", block_toml(kBlockGeo, "1000.0", "10.0", point_load("tip", "[1.0, 0.0]"))),
                     {"missing.toml", "body[0].point_load[0].group", "no physical point group 'tip'", "'origin'"});
  expect_input_error(write("short.toml", block_toml(kBlockGeo, "1000.0", "10.0", point_load("origin", "[1.0]"))),
                     {"short.toml", "body[0].point_load[0].force", "expected 2 components", "got 1"});
  // The correct one runs.
  const CliResult ok = run("check " + shell_quote(write("ok.toml", block_toml(kBlockGeo, "1000.0", "10.0",
                                                                             point_load("origin", "[1.0, 0.0]")))));
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
}

TEST_F(CliInputErrors, TractionWithBothOrNeitherOfTractionAndTotalForceIsAnInputError) {
  const std::string both = "[[body.traction]]\nboundary = \"right\"\ntraction = [1.0, 0.0]\ntotal_force = [1.0, 0.0]\n";
  expect_input_error(write("both.toml", block_toml(kBlockGeo, "1000.0", "10.0", both)),
                     {"both.toml", "body[0].traction[0].total_force", "either traction or total_force", "got both"});
  const std::string neither = "[[body.traction]]\nboundary = \"right\"\n";
  expect_input_error(write("neither.toml", block_toml(kBlockGeo, "1000.0", "10.0", neither)),
                     {"neither.toml", "body[0].traction[0]", "traction or total_force", "got neither"});
  const std::string total = "[[body.traction]]\nboundary = \"nowhere\"\ntotal_force = [1.0, 0.0]\n";
  expect_input_error(write("total.toml", block_toml(kBlockGeo, "1000.0", "10.0", total)),
                     {"total.toml", "body[0].traction[0].boundary", "no boundary group 'nowhere'"});
}

}  // namespace

// ---- 7. Element types ----

// A recombined block, a body half recombined (quadrilaterals and triangles) and a mesh of 6-node prisms are
// accepted by `check`; 15-node prisms are an input error.
TEST_F(CliInputErrors, ElementTypesAcceptedAndRefused) {
  write("quads.geo", block_geo_with("Plane Surface(1) = {1};", "Plane Surface(1) = {1};\nRecombine Surface{1};"));
  const fs::path quads = write("quads.toml", block_toml("quads.geo"));
  const CliResult checked = run("check " + shell_quote(quads.string()));
  EXPECT_EQ(checked.exit_code, 0) << checked.output;
  EXPECT_NE(checked.output.find("quad4 cells"), std::string::npos) << checked.output;

  // The block split at x = 1 into two surfaces of one physical group, only the left one recombined.
  write("mixed.geo", "Point(1) = {0, 0, 0, 0.25}; Point(2) = {1, 0, 0, 0.25}; Point(3) = {2, 0, 0, 0.25};\n"
                     "Point(4) = {2, 1, 0, 0.25}; Point(5) = {1, 1, 0, 0.25}; Point(6) = {0, 1, 0, 0.25};\n"
                     "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6};\n"
                     "Line(6) = {6, 1}; Line(7) = {2, 5};\n"
                     "Curve Loop(1) = {1, 7, 5, 6}; Plane Surface(1) = {1};\n"
                     "Curve Loop(2) = {2, 3, 4, -7}; Plane Surface(2) = {2};\nRecombine Surface{1};\n"
                     "Physical Surface(\"block\") = {1, 2};\nPhysical Curve(\"bottom\") = {1, 2};\n"
                     "Physical Curve(\"top\") = {4, 5};\n");
  const CliResult mixed = run("check " + shell_quote(write("mixed.toml", block_toml("mixed.geo")).string()));
  EXPECT_EQ(mixed.exit_code, 0) << mixed.output;
  EXPECT_NE(mixed.output.find("quad4 ("), std::string::npos) << mixed.output;
  EXPECT_NE(mixed.output.find("tri3 ("), std::string::npos) << mixed.output;

  write("prisms.geo", "Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5}; Point(3) = {0, 1, 0, 0.5};\n"
                      "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};\n"
                      "Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};\n"
                      "out[] = Extrude {0, 0, 1} { Surface{1}; Layers{2}; Recombine; };\n"
                      "Physical Volume(\"block\") = {out[1]};\nPhysical Surface(\"bottom\") = {1};\n"
                      "Physical Surface(\"top\") = {out[0]};\n");
  const std::string solid = "[problem]\ndimension = 3\n\n[[body]]\nname = \"block\"\nmesh = \"MESH\"\ngroup = \"block\"\n"
                            "[body.material]\nE = 1.0\nnu = 0.3\n";
  const std::string held = "[[body.dirichlet]]\nboundary = \"bottom\"\nux = 0.0\nuy = 0.0\nuz = 0.0\n";
  const CliResult prisms =
      run("check " + shell_quote(write("prisms.toml", symcontact::testing::replaced(solid, "MESH", "prisms.geo") + held).string()));
  EXPECT_EQ(prisms.exit_code, 0) << prisms.output;
  EXPECT_NE(prisms.output.find("prism6 cells"), std::string::npos) << prisms.output;
  // Serendipity prisms (15 nodes).
  write("prisms15.geo", read_text(dir_ / "prisms.geo") + "Mesh.SecondOrderIncomplete = 1;\n");
  const CliResult prisms15 = run("check " + shell_quote(write("prisms15.toml", symcontact::testing::replaced(
                                                                                  symcontact::testing::replaced(solid, "MESH", "prisms15.geo"),
                                                                                  "dimension = 3\n", "dimension = 3\norder = 2\n") + held)
                                                                .string()));
  EXPECT_EQ(prisms15.exit_code, 0) << prisms15.output;
  EXPECT_NE(prisms15.output.find("prism15 cells"), std::string::npos) << prisms15.output;
  // Elements of order 3 are refused, named as Gmsh names them.
  write("cubic.geo", read_text(kBlockGeo) + "Mesh.ElementOrder = 3;\n");
  expect_input_error(write("cubic.toml", block_toml("cubic.geo")),
                     {"cubic.toml", "body[0].mesh", "cubic.geo", "unsupported element type 'Triangle 10'", "order 1 or 2"});
}
