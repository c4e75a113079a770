/// End-to-end tests of `symcontact run` on contact problems (app/main.cpp, app/run.cpp): the contact
/// outputs (contact_<pair>_<step>.csv, the "contact" entries of summary.json, the contact point data of
/// the .vtu files), a failed contact solve (exit 3, what it keeps and what it must not leave behind) and a
/// contact pair naming a missing boundary group (exit 2). Conventions of test_cli.cpp: the binary is
/// SYMCONTACT_CLI, each test works in its own temporary folder and runs the program through the shell,
/// capturing stdout and stderr together.

#include <gtest/gtest.h>

#include "support/cli_fixture.hpp"
#include "support/problem_snippet.hpp"
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

using symcontact::testing::CliResult;
using symcontact::testing::read_text;
using symcontact::testing::replaced;

const fs::path kHertzDir = fs::path(SYMCONTACT_EXAMPLES) / "hertz_2d";
const fs::path kHertzCase = kHertzDir / "cylinder_on_plane.toml";

/// The numbers of the JSON array that follows the `occurrence`-th (from 0) "key": in `json`; empty if
/// there is none. Enough for the flat arrays of summary.json.
std::vector<double> json_array(const std::string& json, const std::string& key, int occurrence = 0) {
  std::size_t at = 0;
  for (int i = 0; i <= occurrence; ++i) {
    at = json.find("\"" + key + "\":", i == 0 ? 0 : at + 1);
    if (at == std::string::npos) return {};
  }
  const std::size_t open = json.find('[', at), close = json.find(']', at);
  if (open == std::string::npos || close == std::string::npos || close < open) return {};
  std::string body = json.substr(open + 1, close - open - 1);
  std::replace(body.begin(), body.end(), ',', ' ');
  std::istringstream in(body);
  std::vector<double> v;
  for (double x; in >> x;) v.push_back(x);
  return v;
}

/// The number that follows the first "key": in `json` (NaN if absent).
double json_number(const std::string& json, const std::string& key) {
  const std::size_t at = json.find("\"" + key + "\":");
  if (at == std::string::npos) return std::nan("");
  return std::strtod(json.c_str() + at + key.size() + 3, nullptr);
}

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(line);
  while (std::getline(in, item, sep)) out.push_back(item);
  if (!line.empty() && line.back() == sep) out.emplace_back();
  return out;
}

class CliContact : public symcontact::testing::CliTest {
 protected:
  CliContact() : CliTest("symcontact_cli_contact_") {}

  /// The Hertz example's problem file, its mesh referred to by absolute path, edited by `edit`, written
  /// as `name` in the test's folder.
  template <class Edit>
  fs::path write_hertz_case(const std::string& name, Edit edit) const {
    const std::string geo = "cylinder_on_plane.geo";
    std::string toml = replaced(read_text(kHertzCase), "\"" + geo + "\"", "\"" + (kHertzDir / geo).string() + "\"");
    edit(toml);
    return write(name, toml);
  }

};

TEST_F(CliContact, HertzExampleWritesContactResults) {
  const fs::path& out = out_;
  const CliResult r = run_case(kHertzCase);
  ASSERT_EQ(r.exit_code, 0) << r.output;

  // summary.json: one "contact" entry per pair and step, the force of the floor on the half cylinder
  // balancing the load P/2 = 0.005.
  const std::string summary = read_text(out / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"ok\""), std::string::npos) << summary;
  ASSERT_NE(summary.find("\"contact\":"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"name\": \"floor\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"csv\": \"contact_floor_0001.csv\""), std::string::npos) << summary;
  const std::vector<double> force = json_array(summary, "total_force");
  ASSERT_EQ(force.size(), 2u) << summary;
  EXPECT_NEAR(force[0], 0.0, 1e-10);
  EXPECT_NEAR(force[1], 0.005, 1e-10);
  const double max_pressure = json_number(summary, "max_pressure");
  EXPECT_GT(max_pressure, 0.05);  // Hertz: p0 = 0.059143
  EXPECT_LT(max_pressure, 0.065);
  EXPECT_GT(json_number(summary, "contact_length"), 0.05);  // a = 0.107641 on the half model
  // Frictionless: the tangential part is exactly zero; on a plane the normal load is |normal_force|.
  const std::vector<double> tangential = json_array(summary, "tangential_force");
  ASSERT_EQ(tangential.size(), 2u) << summary;
  EXPECT_EQ(tangential[0], 0.0);
  EXPECT_EQ(tangential[1], 0.0);
  EXPECT_NEAR(json_number(summary, "normal_load"), 0.005, 1e-10);
  {
    // Undefined cells (no friction: slips, accumulated slip) are "nan", never blank: numpy reads them.
    const std::string text = read_text(out / "contact_floor_0001.csv");
    EXPECT_EQ(text.find(",,"), std::string::npos);
    EXPECT_EQ(text.find(",\n"), std::string::npos);
    EXPECT_NE(text.find(",nan,"), std::string::npos);
    const std::string header = text.substr(0, text.find('\n'));
    for (const char* column : {",current_pressure,", ",fn_x,", ",fn_y,"})
      EXPECT_NE(header.find(column), std::string::npos) << column << " missing from " << header;
  }

  // contact_floor_0001.csv: one row per node of the contact surface, consistent with summary.json.
  std::ifstream csv(out / "contact_floor_0001.csv");
  ASSERT_TRUE(csv.good());
  std::string line;
  std::getline(csv, line);
  // The columns this test reads, in this order; others (friction) may come between them.
  const std::vector<std::string> columns = split(line, ',');
  const auto column = [&](const char* name) {
    return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
  };
  EXPECT_EQ(line.rfind("side,surface,node,x,y,x_ref,y_ref,gap,pressure,", 0), 0u) << line;
  EXPECT_LT(column("pressure"), column("fx")) << line;
  EXPECT_EQ(column("fy"), column("fx") + 1) << line;
  ASSERT_EQ(column("status"), columns.size() - 1) << line;
  EXPECT_EQ(column("z"), columns.size()) << "no z column in 2D: " << line;
  EXPECT_NE(line.find(",accumulated_slip,ux,uy,t_tangential,slip_tangential,status"), std::string::npos) << line;
  double p_max = 0.0, fy = 0.0;
  int rows = 0, in_contact = 0;
  while (std::getline(csv, line)) {
    const std::vector<std::string> v = split(line, ',');
    ASSERT_EQ(v.size(), columns.size()) << line;
    EXPECT_EQ(v[column("side")], "a") << line;  // an obstacle has no side b
    EXPECT_EQ(v[column("surface")], "cylinder.contact") << line;
    const double p = std::stod(v[column("pressure")]);
    EXPECT_GE(p, -1e-12) << line;  // round-off on open nodes
    p_max = std::max(p_max, p);
    fy += std::stod(v[column("fy")]);
    const std::string status = v[column("status")];
    EXPECT_TRUE(status == "contact" || status == "open") << line;
    in_contact += status == "contact" ? 1 : 0;
    // The displacement columns are the field u = x − X at the node; frictionless: no tangential traction,
    // no slip.
    for (const char* c : {"x", "y"})
      EXPECT_NEAR(std::stod(v[column((std::string("u") + c).c_str())]),
                  std::stod(v[column(c)]) - std::stod(v[column((std::string(c) + "_ref").c_str())]), 1e-14)
          << c << ": " << line;
    EXPECT_EQ(std::stod(v[column("t_tangential")]), 0.0) << line;
    EXPECT_EQ(v[column("slip_tangential")], "nan") << line;
    ++rows;
  }
  EXPECT_GT(rows, 50);  // 80 nodes on the arc of the example mesh
  EXPECT_GT(in_contact, 10);
  EXPECT_LT(in_contact, rows);
  EXPECT_NEAR(p_max, max_pressure, 1e-12 * max_pressure);
  EXPECT_NEAR(fy, force[1], 1e-12);

  // The .vtu carries the contact fields as point data.
  const std::string vtu = read_text(out / "cylinder_0001.vtu");
  EXPECT_NE(vtu.find("Name=\"contact_pressure\""), std::string::npos);
  EXPECT_NE(vtu.find("Name=\"contact_gap\""), std::string::npos);
  EXPECT_TRUE(fs::is_regular_file(out / "results.pvd"));
}

TEST_F(CliContact, FailedContactSolveKeepsTheSummaryAndTheLastIterateOnly) {
  // IPOPT as the dual's optimiser too (the default interior point does not read [ipopt] max_iter).
  const fs::path f = write_hertz_case("one_iteration.toml", [](std::string& t) {
    t += "\n[contact_solver]\nsubproblem_solver = \"dual_ipopt\"\n[ipopt]\nmax_iter = 1\n";
  });
  const fs::path& out = out_;
  const CliResult r = run_case(f);
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("solve failed"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Maximum_Iterations_Exceeded"), std::string::npos) << r.output;

  const std::string summary = read_text(out / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"solve_failed\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("Maximum_Iterations_Exceeded"), std::string::npos) << summary;
  EXPECT_NE(summary.find("cylinder_failed_step1.vtu"), std::string::npos) << summary;
  const std::string vtu = read_text(out / "cylinder_failed_step1.vtu");
  EXPECT_NE(vtu.find("</VTKFile>"), std::string::npos) << "the last iterate, written whole";
  // Nothing else: no step results, no contact CSV, no collection, no temporary files.
  std::set<std::string> files;
  for (const auto& e : fs::directory_iterator(out)) files.insert(e.path().filename().string());
  EXPECT_EQ(files, (std::set<std::string>{"summary.json", "cylinder_failed_step1.vtu"}));
}

TEST_F(CliContact, ContactOnAMissingBoundaryGroupIsAnInputError) {
  const fs::path f = write_hertz_case("missing_group.toml", [](std::string& t) {
    t = replaced(t, "a = \"cylinder.contact\"", "a = \"cylinder.nowhere\"");
  });
  expect_input_error(f, {"missing_group.toml", "contact[0].a", "nowhere"});
}

}  // namespace

TEST_F(CliContact, FrictionRunWritesTractionsSlipsAndStatus) {
  // The V4 friction block (Coulomb μ = 0.3): the last step is in gross slip.
  const fs::path& out = out_;
  const CliResult r = run_case(std::string(SYMCONTACT_EXAMPLES) + "/friction_block/block.toml", "-q");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string csv = read_text(out / "contact_floor_0011.csv");
  const std::string header = csv.substr(0, csv.find('\n'));
  for (const char* column : {"pressure", "tx", "ty", "slip_x", "slip_y", "accumulated_slip", "status"})
    EXPECT_NE(header.find(column), std::string::npos) << column << " missing from " << header;
  EXPECT_NE(csv.find(",slip\n"), std::string::npos) << "no slipping node in gross slip";
  {
    // 2D: t_tangential is ±|(tx, ty)| along the tangent, slip_tangential ±|slip|; friction opposes slip.
    std::istringstream rows(csv);
    std::string line;
    std::getline(rows, line);
    const std::vector<std::string> columns = split(line, ',');
    const auto at = [&](const std::vector<std::string>& v, const char* name) {
      const auto it = std::find(columns.begin(), columns.end(), name);
      EXPECT_NE(it, columns.end()) << name;
      return it == columns.end() ? std::nan("") : std::stod(v[it - columns.begin()]);
    };
    int slipping = 0;
    while (std::getline(rows, line)) {
      const std::vector<std::string> v = split(line, ',');
      const double t = at(v, "t_tangential"), s = at(v, "slip_tangential");
      EXPECT_NEAR(std::abs(t), std::hypot(at(v, "tx"), at(v, "ty")), 1e-15 + 1e-12 * std::abs(t)) << line;
      EXPECT_NEAR(std::abs(s), std::hypot(at(v, "slip_x"), at(v, "slip_y")), 1e-15 + 1e-12 * std::abs(s)) << line;
      EXPECT_NEAR(at(v, "ux"), at(v, "x") - at(v, "x_ref"), 1e-14) << line;
      if (v.back() != "slip") continue;
      EXPECT_LT(t * s, 0.0) << "friction opposes slip: " << line;
      ++slipping;
    }
    EXPECT_GT(slipping, 0);
  }
  const std::string vtu = read_text(out / "block_0011.vtu");
  for (const char* field : {"contact_tangential_traction", "slip_increment", "accumulated_slip", "contact_pressure"})
    EXPECT_NE(vtu.find(std::string("Name=\"") + field + "\""), std::string::npos) << field;
  const std::string summary = read_text(out / "summary.json");
  EXPECT_NE(summary.find("\"tangential_force\""), std::string::npos);
  EXPECT_NE(summary.find("\"coulomb_iterations\""), std::string::npos);
}

TEST_F(CliContact, Hertz3DExampleWritesContactResults) {
  // examples/hertz_3d/sphere_on_plane.toml (quarter sphere on a rigid plane, P1, ~3 s): 3D contact output.
  const fs::path& out = out_;
  const CliResult r = run_case(std::string(SYMCONTACT_EXAMPLES) + "/hertz_3d/sphere_on_plane.toml", "-q");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string summary = read_text(out / "summary.json");
  const std::vector<double> force = json_array(summary, "total_force");
  ASSERT_EQ(force.size(), 3u) << summary;
  // P/4 = 0.0025 on the quarter disk, less 0.84 % for its polygonal mesh (test_hertz_3d.cpp).
  EXPECT_NEAR(force[2], 0.0025 * (1 - 0.0084), 1e-5);
  EXPECT_NEAR(force[0], 0.0, 1e-10);
  EXPECT_NEAR(force[1], 0.0, 1e-10);
  EXPECT_NEAR(json_number(summary, "max_pressure"), 0.132701, 0.05 * 0.132701);
  // The contact area of the quarter model, π a² / 4 = 0.0283 for a = 0.1897, to about one element.
  const double area = json_number(summary, "contact_area");
  EXPECT_GT(area, 0.02);
  EXPECT_LT(area, 0.04);
  const std::string csv = read_text(out / "contact_floor_0001.csv");
  EXPECT_EQ(csv.rfind("side,surface,node,x,y,z,x_ref,y_ref,z_ref,gap,pressure,", 0), 0u) << csv.substr(0, csv.find('\n'));
  // The displacements; no signed tangential values in 3D.
  EXPECT_NE(csv.find(",accumulated_slip,ux,uy,uz,status\n"), std::string::npos) << csv.substr(0, csv.find('\n'));
  const std::string vtu = read_text(out / "sphere_0001.vtu");
  EXPECT_NE(vtu.find("Name=\"contact_pressure\""), std::string::npos);
}
