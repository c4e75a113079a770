// Rigid obstacles through the problem-file path: a circle with the body inside it (a rigid hole, exact
// Lamé solution), a meshed rigid surface against the analytic plane it represents, and a plane with a
// tilted, non-unit normal against the same case unrotated.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include "support/solve_case.hpp"
#include "symcontact/core/error.hpp"
#include "symcontact/mesh/gmsh_io.hpp"

using namespace symcontact;
using namespace symcontact::testing;

namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// ---------------------------------------------------------------------------------------------------
// 1. A ring expanding into a rigid hole.
//
// The inner ring of examples/rings_2d (r ∈ [a, b] = [0.5, 1], E = 1, ν = 0.3, plane strain, quarter
// model with symmetry conditions) under an internal pressure p on r = a, inside a rigid circle of radius
// b + g, g = 0.001, centred at the origin (obstacle "circle", inside = true).
//
// Lamé: u_r = A r + B/r, σ_rr = 2(λ + μ) A − 2μ B/r², λ = Eν/((1 + ν)(1 − 2ν)), μ = E/(2(1 + ν)).
// Contact closed (u_r(b) = g) with σ_rr(a) = −p:
//   A b + B/b = g                          ⇒ A = g/b − B/b²
//   2(λ + μ) A − 2μ B/a² = −p              ⇒ B = (p + 2(λ + μ) g/b) / (2(λ + μ)/b² + 2μ/a²)
// and the contact pressure is q = −σ_rr(b) = 2μ B/b² − 2(λ + μ) A (valid while q ≥ 0).
// The gap closes when the free ring (σ_rr(b) = 0) reaches u_r(b) = g. Free ring: 2(λ + μ) A = 2μ B/b²
// and 2μ B (1/b² − 1/a²) = −p, so B = p / (2μ (1/a² − 1/b²)), u_r(b) = (B/b)(1 + μ/(λ + μ)), and
//   p_close = 2μ (1/a² − 1/b²) g b / (1 + μ/(λ + μ))  (= 0.0016484, the closing load of V6).
// The measured pressure is |resultant on the quarter| / (√2 b): a uniform pressure q on a quarter circle
// of radius b has the resultant q b (1, 1) (small strain: reference radius b = 1, as in test_rings.cpp).
//
// Discretisation: the body's surface is a polygon with nodes on r = b, the obstacle an exact circle. A
// chord of angle Δθ = π/(2 nc) sags inside the circle by b Δθ²/8 at its middle (parabolically), so
// the weak constraints ∫ θ φ_i = 0 of a uniformly pressed ring leave the nodes past the circle by
// (2/3) b Δθ²/8 = b Δθ²/12: the polygon sees an effective gap g + b Δθ²/12, and the pressure is low
// by (dq/dg) b Δθ²/12, an O(h²) geometric error (−0.68 % at nc = 32) on top of the O(h²) error of
// the linear elements (in V6 both surfaces are polygons that sag alike, and it cancels). So: within
// 0.5 % at nc = 32 of the closed form with the effective gap, within 0.5 % of the plain closed form at
// nc = 64, and second order (the error divided by ≥ 3.5 per halving of h) from nc = 16 to 64.
// ---------------------------------------------------------------------------------------------------

const std::string kRings = std::string(SYMCONTACT_EXAMPLES) + "/rings_2d/rings.geo";
const double kA = 0.5, kB = 1.0, kGap = 0.001, kE = 1.0, kNu = 0.3;
const double kLambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu));
const double kMu = kE / (2 * (1 + kNu));

double lame_contact_pressure(double p, double gap = kGap) {
  const double B = (p + 2 * (kLambda + kMu) * gap / kB) / (2 * (kLambda + kMu) / (kB * kB) + 2 * kMu / (kA * kA));
  const double A = gap / kB - B / (kB * kB);
  return 2 * kMu * B / (kB * kB) - 2 * (kLambda + kMu) * A;
}

double closing_pressure() {
  return 2 * kMu * (1 / (kA * kA) - 1 / (kB * kB)) * kGap * kB / (1 + kMu / (kLambda + kMu));
}

std::unique_ptr<SolvedCase> ring_in_hole(int nc, int nr, double p_in) {
  const std::string dir = test_temp_dir("obstacle_hole");
  write_text(dir, "ring.geo",
             "nc = " + std::to_string(nc) + "; nr = " + std::to_string(nr) + ";\nInclude \"" + kRings + "\";\n");
  const std::string toml = R"(
[problem]
dimension = 2
model = "plane_strain"
order = 1

[[body]]
name = "inner"
mesh = "ring.geo"
group = "inner"
material = { E = 1.0, nu = 0.3 }
[[body.dirichlet]]
boundary = "inner_bottom"
uy = 0.0
[[body.dirichlet]]
boundary = "inner_left"
ux = 0.0
[[body.pressure]]
boundary = "inner_bore"
pressure = )" + num(p_in) + R"(

[[contact]]
name = "hole"
a = "inner.inner_outside"
[contact.obstacle]
type = "circle"
center = [0.0, 0.0]
radius = 1.001
inside = true
)";
  return solve_case(toml, dir);
}

TEST(Obstacles, RingExpandingIntoRigidHoleMatchesLame) {
  const double p_in = 0.05;
  const double q = lame_contact_pressure(p_in);
  std::printf("  rigid hole: p_in = %.3f, Lamé contact pressure q = %.8f\n", p_in, q);
  const int ncs[3] = {16, 32, 64};
  double err[3], err_effective[3];
  for (int i = 0; i < 3; ++i) {
    const int nc = ncs[i];
    auto c = ring_in_hole(nc, nc / 4, p_in);
    const ContactPairResult& r = c->contact[0];
    const double measured = r.total_force.norm() / (std::sqrt(2.0) * kB);
    const double dtheta = M_PI / (2 * nc);
    const double q_effective = lame_contact_pressure(p_in, kGap + kB * dtheta * dtheta / 12);
    err[i] = measured / q - 1;
    err_effective[i] = measured / q_effective - 1;
    std::printf("  nc = %d, nr = %d: q = %.8f (error %+.3f%%; %+.3f%% against %.8f, the effective gap's), "
                "%d geometry / %d IPOPT iterations\n",
                nc, nc / 4, measured, 100 * err[i], 100 * err_effective[i], q_effective, c->report.geometry_iterations,
                c->report.ipopt_iterations);
    // The resultant points to the centre, along the diagonal of the quarter (to the asymmetry of the
    // structured mesh, whose triangles all lean one way).
    EXPECT_NEAR(r.total_force[0], r.total_force[1], 1e-3 * r.total_force.norm());
    EXPECT_LT(r.total_force[0], 0.0);
  }
  EXPECT_LT(std::abs(err_effective[1]), 0.005);
  EXPECT_LT(std::abs(err[2]), 0.005);
  EXPECT_GT(std::abs(err[0]), 3.5 * std::abs(err[1]));
  EXPECT_GT(std::abs(err[1]), 3.5 * std::abs(err[2]));
}

TEST(Obstacles, RingBelowClosingLoadTouchesNothing) {
  const double p_close = closing_pressure();
  EXPECT_NEAR(p_close, 0.001648, 5e-7);  // the closing load quoted in VALIDATION.md, V6
  const double p_in = 0.6 * p_close;
  auto c = ring_in_hole(32, 8, p_in);
  const ContactPairResult& r = c->contact[0];
  // Free ring: u_r(b) = 0.6 g, so the gap left is 0.4 g = 4e-4 all round.
  const double gap_left = 0.4 * kGap;
  double min_gap = 1e300;
  for (Index k = 0; k < r.sides[0].gap.size(); ++k) min_gap = std::min(min_gap, r.sides[0].gap[k]);
  std::printf("  rigid hole: p_close = %.8f; at p_in = %.8f: |contact force| = %.3e, max pressure %.3e, "
              "min gap %.6e (free ring: %.6e), contact length %.3e\n",
              p_close, p_in, r.total_force.norm(), r.max_pressure, min_gap, gap_left, r.contact_measure);
  // Zero, against the force scale of the load on the quarter bore (p_in a √2), up to what the interior
  // point leaves on open constraints (multipliers of order barrier / gap; no active set to polish).
  EXPECT_LT(r.total_force.norm(), 1e-5 * p_in * kA * std::sqrt(2.0));
  EXPECT_LT(r.max_pressure, 1e-5 * p_in);
  EXPECT_NEAR(min_gap, gap_left, 0.01 * gap_left);
}

// Nothing touches, so every node is open and the contact length is 0. A regression check: a status
// threshold relative to the pair's largest pressure alone (1e-4 × max p, as in commit 749d64c) labels
// every node "contact" when nothing touches — the largest pressure is then the interior point's residue
// (3.5e-9 here) — and reported a contact length of a quarter circumference (1.571).
TEST(Obstacles, RingBelowClosingLoadHasAllNodesOpen) {
  auto c = ring_in_hole(32, 8, 0.6 * closing_pressure());
  const ContactPairResult& r = c->contact[0];
  EXPECT_EQ(r.contact_measure, 0.0);
  for (Index k = 0; k < r.sides[0].status.size(); ++k) EXPECT_EQ(r.sides[0].status[k], 0) << "node " << k;
}

// ---------------------------------------------------------------------------------------------------
// 2. Hertz 2D (V1) on a meshed rigid floor instead of the analytic plane y = 0.
//
// Orientation of a rigid surface: its facets keep the orientation of the file (extract_surface), and
// its normal is computed as a body surface's outward normal, n = (t_y, −t_x) for a curve with tangent
// t, i.e. pointing to the right of the direction of travel. That normal must point towards the
// deformable body, so the floor y = 0 under the cylinder is drawn from right to left, from (1.5, 0) to
// (−0.5, 0): t = (−1, 0), n = (0, 1). Drawn the other way (n = (0, −1)) the cylinder lies behind the
// rigid surface: every projection is rejected (the normals do not face each other) and the floor is
// not there at all. Such a problem is refused before the solve (model/setup_checks.hpp: more of the body's
// surface nodes behind the facets than in front of them), checked below with the cut pushed down by an
// imposed displacement.
// ---------------------------------------------------------------------------------------------------

const std::string kHertz = std::string(SYMCONTACT_EXAMPLES) + "/hertz_2d/";
const double kP = 0.01;

struct HertzResult {
  double p0 = 0;
  Eigen::VectorXd force;
};

HertzResult hertz_measure(const SolvedCase& c) {
  HertzResult m;
  const auto& side = c.contact[0].sides[0];
  for (Index k = 0; k < side.pressure.size(); ++k) m.p0 = std::max(m.p0, side.pressure[k]);
  m.force = c.contact[0].total_force;
  return m;
}

/// The example cylinder_on_plane.toml at h = 0.008 with its [contact.obstacle] table replaced, and its
/// [[body.pressure]] table too if `load` is not empty.
std::unique_ptr<SolvedCase> hertz_half_model(const std::string& dir, const std::string& obstacle,
                                             const std::string& load = "") {
  write_text(dir, "cyl.geo", "h = 0.008;\nInclude \"" + kHertz + "cylinder_on_plane.geo\";\n");
  std::string toml = read_text(kHertz + "cylinder_on_plane.toml");
  toml.replace(toml.find("cylinder_on_plane.geo"), 21, "cyl.geo");
  if (!load.empty()) {
    const std::size_t from = toml.find("[[body.pressure]]"), to = toml.find("[[contact]]");
    toml.replace(from, to - from, load + "\n");
  }
  toml.erase(toml.find("[contact.obstacle]"));
  return solve_case(toml + obstacle, dir);
}

std::string floor_geo(double x_from, double x_to, double lc) {
  return "Point(1) = {" + num(x_from) + ", 0, 0, " + num(lc) + "};\nPoint(2) = {" + num(x_to) + ", 0, 0, " + num(lc) +
         "};\nLine(1) = {1, 2};\nPhysical Curve(\"floor\") = {1};\n";
}

const std::string kMeshObstacle = "[contact.obstacle]\ntype = \"mesh\"\nmesh = \"floor.geo\"\nboundary = \"floor\"\n";

TEST(Obstacles, MeshedFloorGivesTheAnalyticPlaneAnswer) {
  const std::string dir = test_temp_dir("obstacle_mesh");
  const HertzResult plane = hertz_measure(
      *hertz_half_model(dir, "[contact.obstacle]\ntype = \"plane\"\npoint = [0.0, 0.0]\nnormal = [0.0, 1.0]\n"));
  std::printf("  analytic plane:       p0 = %.10f, force = (%.3e, %.12f)\n", plane.p0, plane.force[0], plane.force[1]);
  EXPECT_NEAR(2 * plane.force[1], kP, 1e-8 * kP);
  // One facet over the whole floor, and facets of 0.0137 whose nodes fall between the cylinder's.
  for (double lc : {4.0, 0.0137}) {
    write_text(dir, "floor.geo", floor_geo(1.5, -0.5, lc));
    const HertzResult m = hertz_measure(*hertz_half_model(dir, kMeshObstacle));
    std::printf("  meshed floor (lc %.4g): p0 = %.10f (rel. diff %.2e), force = (%.3e, %.12f) (rel. diff %.2e)\n",
                lc, m.p0, m.p0 / plane.p0 - 1, m.force[0], m.force[1], (m.force - plane.force).norm() / plane.force.norm());
    EXPECT_NEAR(m.p0, plane.p0, 1e-6 * plane.p0) << "lc = " << lc;
    EXPECT_LT((m.force - plane.force).norm(), 1e-6 * plane.force.norm()) << "lc = " << lc;
  }
}

TEST(Obstacles, MeshedFloorFacingAwayFromTheBodyIsRefused) {
  const std::string dir = test_temp_dir("obstacle_mesh_orientation");
  // The cut pushed down by 0.002: the cylinder is held by the symmetry line and the cut, the floor
  // only pushes back if it is seen.
  const auto pushed = [&](const std::string& obstacle) {
    auto c = hertz_half_model(dir, obstacle, "[[body.dirichlet]]\nboundary = \"load\"\nuy = -0.002\n");
    return hertz_measure(*c);
  };
  const HertzResult plane = pushed("[contact.obstacle]\ntype = \"plane\"\npoint = [0.0, 0.0]\nnormal = [0.0, 1.0]\n");
  write_text(dir, "floor.geo", floor_geo(1.5, -0.5, 0.0137));  // n = (0, 1): towards the cylinder
  const HertzResult facing = pushed(kMeshObstacle);
  std::printf("  cut pushed down by 0.002: force of the analytic plane %.10f, of the meshed floor facing the body "
              "%.10f\n",
              plane.force[1], facing.force[1]);
  EXPECT_GT(plane.force[1], 0.0);
  EXPECT_NEAR(facing.force[1], plane.force[1], 1e-6 * plane.force[1]);
  // Facing away, the contact search would never see the cylinder, which would sink through the floor:
  // refused before the solve (model/setup_checks.hpp), naming the obstacle.
  write_text(dir, "floor.geo", floor_geo(-0.5, 1.5, 0.0137));  // n = (0, −1): away from it
  try {
    pushed(kMeshObstacle);
    ADD_FAILURE() << "a floor facing away from the body was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "contact[0].obstacle");
    EXPECT_NE(e.message().find("face away from body"), std::string::npos) << e.message();
  }
}

// ---------------------------------------------------------------------------------------------------
// 3. Hertz 2D on a tilted plane given by a non-unit normal.
//
// The plane through the origin with normal 3 (sin 30°, cos 30°): the y = 0 case turned clockwise by
// 30° (the rotation Q by −30° takes (0, 1) to (sin 30°, cos 30°)). The half model's symmetry condition
// becomes u·t = 0 on the turned symmetry line, t = Q e_x = (cos 30°, −sin 30°), which per-component
// Dirichlet conditions cannot express. So the turned case is a full model: the half disk of radius 1
// below its centre C (pressure 0.005 on the cut of width 2 through C: resultant P = 0.01 along −n).
//
// Its mesh is the half model's mesh (cylinder_on_plane.geo, h = 0.008, meshed by Gmsh through the
// library) and its mirror image x → −x, glued on the symmetry line, then turned by Q node by node and
// written as a .msh. A .geo of the turned half disk would be meshed afresh: tried, Gmsh's mesh of the
// turned geometry is not the turned mesh and p0 moved by 3.6e-3; the mirror half is not the mirror
// mesh either (1.4e-4). Congruent, mirror-symmetric meshes make the full model's solution the half
// model's exactly, so p0 can be compared with the half model to 1e-6.
//
// Rigid motions of the full model: the contact alone holds the body along n, and against a rotation
// about the first contact point O (it tilts the arc into the plane on one side, out of it on the other:
// resisted both ways by the contact zone); a translation along t and a rotation about C (the arc slides
// along itself) cost nothing. The condition u_x(O) = 0 (a Physical Point) removes both: a translation
// c t moves O by c t, a rotation ω about C moves O by ω R t, and t·e_x = cos 30° ≠ 0; what is left
// at O is a rotation about O itself, which the contact resists. The support is statically determinate:
// frictionless, every other force on the body is along n, so equilibrium along t gives R cos 30° = 0 for
// its reaction R e_x. It fixes a rigid motion and changes no pressure; by symmetry u(O) = 0 anyway.
// ---------------------------------------------------------------------------------------------------

/// The full-model mesh described above, turned by −`deg` degrees, as MSH 2.2 text with the physical
/// groups "cylinder" (triangles), "contact" and "load" (lines) and "pin" (the point O).
std::string full_model_msh(const std::string& dir, double deg) {
  write_text(dir, "half.geo", "h = 0.008;\nInclude \"" + kHertz + "cylinder_on_plane.geo\";\n");
  MeshReadOptions opt;
  opt.dim = 2;
  opt.order = 1;
  const MeshFile half = read_mesh_file(dir + "half.geo", opt);
  const Index n = half.x.cols();
  // Mirror node numbers: nodes on x = 0 are their own mirror.
  std::vector<Index> mirror(n);
  Index next = n, on_axis = 0, pin = -1;
  for (Index v = 0; v < n; ++v) {
    const bool axis = std::abs(half.x(0, v)) < 1e-12;
    mirror[v] = axis ? v : next++;
    on_axis += axis ? 1 : 0;
    if (axis && std::abs(half.x(1, v)) < 1e-12) pin = v;
  }
  EXPECT_GE(pin, 0) << "no node at the contact point O";
  Eigen::MatrixXd x(2, next);
  for (Index v = 0; v < n; ++v) {
    x.col(v) = half.x.col(v).head(2);
    x.col(mirror[v]) << -half.x(0, v), half.x(1, v);
  }
  const double th = -deg * M_PI / 180;
  const Eigen::Matrix2d q = (Eigen::Matrix2d() << std::cos(th), -std::sin(th), std::sin(th), std::cos(th)).finished();
  x = q * x;
  x.col(pin).setZero();  // O stays on the plane through the origin, exactly

  std::ostringstream elements;
  int count = 0;
  auto element = [&](int type, int tag, std::vector<Index> nodes) {
    elements << ++count << ' ' << type << " 2 " << tag << ' ' << tag;
    for (Index v : nodes) elements << ' ' << v + 1;
    elements << '\n';
  };
  // A group's cells and their mirror images (vertex order reversed, to keep the orientation).
  auto group = [&](const char* name, int dim, int tag) {
    const MeshFile::Group* g = half.find(name, dim);
    EXPECT_NE(g, nullptr) << name;
    if (!g) return;
    for (const auto& b : g->blocks) {
      const int npc = cell_num_nodes(b.type);
      for (std::size_t c = 0; c < b.nodes.size(); c += npc) {
        std::vector<Index> cell(b.nodes.begin() + c, b.nodes.begin() + c + npc), image;
        for (auto it = cell.rbegin(); it != cell.rend(); ++it) image.push_back(mirror[*it]);
        element(gmsh_element_type(b.type), tag, cell);
        element(gmsh_element_type(b.type), tag, image);
      }
    }
  };
  group("cylinder", 2, 1);
  group("contact", 1, 2);
  group("load", 1, 3);
  element(15, 4, {pin});
  std::printf("  full model mesh: %ld nodes (%ld on the symmetry line), %d elements\n", static_cast<long>(next),
              static_cast<long>(on_axis), count);

  std::ostringstream msh;
  msh.precision(17);
  msh << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n4\n2 1 \"cylinder\"\n1 2 \"contact\"\n"
         "1 3 \"load\"\n0 4 \"pin\"\n$EndPhysicalNames\n$Nodes\n"
      << next << '\n';
  for (Index v = 0; v < next; ++v) msh << v + 1 << ' ' << x(0, v) << ' ' << x(1, v) << " 0\n";
  msh << "$EndNodes\n$Elements\n" << count << '\n' << elements.str() << "$EndElements\n";
  return msh.str();
}

std::unique_ptr<SolvedCase> hertz_full_model(const std::string& dir, double deg) {
  write_text(dir, "disk.msh", full_model_msh(dir, deg));
  const double th = deg * M_PI / 180;
  const std::string toml = R"(
[problem]
dimension = 2
model = "plane_strain"
order = 1

[[body]]
name = "cylinder"
mesh = "disk.msh"
group = "cylinder"
material = { E = 1.0, nu = 0.3 }
[[body.dirichlet]]
boundary = "pin"
ux = 0.0
[[body.pressure]]
boundary = "load"
pressure = 0.005

[[contact]]
name = "floor"
a = "cylinder.contact"
[contact.obstacle]
type = "plane"
point = [0.0, 0.0]
normal = [)" + num(3 * std::sin(th)) + ", " + num(3 * std::cos(th)) + "]\n";
  return solve_case(toml, dir);
}

TEST(Obstacles, TiltedPlaneWithNonUnitNormalMatchesTheUnturnedCase) {
  const std::string dir = test_temp_dir("obstacle_tilted");
  const HertzResult half = hertz_measure(*hertz_half_model(
      dir, "[contact.obstacle]\ntype = \"plane\"\npoint = [0.0, 0.0]\nnormal = [0.0, 1.0]\n"));
  const HertzResult flat = hertz_measure(*hertz_full_model(dir, 0.0));
  const HertzResult tilted = hertz_measure(*hertz_full_model(dir, 30.0));
  const Eigen::Vector2d n(std::sin(M_PI / 6), std::cos(M_PI / 6));
  std::printf("  half model, plane y = 0:  p0 = %.10f, force = (%.3e, %.12f)\n", half.p0, half.force[0],
              half.force[1]);
  std::printf("  full model, plane y = 0:  p0 = %.10f (rel. diff %+.2e), force = (%.3e, %.12f)\n", flat.p0,
              flat.p0 / half.p0 - 1, flat.force[0], flat.force[1]);
  std::printf("  full model, plane at 30°: p0 = %.10f (rel. diff %+.2e), force = (%.12f, %.12f), "
              "|F − P n| / P = %.2e\n",
              tilted.p0, tilted.p0 / half.p0 - 1, tilted.force[0], tilted.force[1],
              (tilted.force - kP * n).norm() / kP);
  EXPECT_LT((flat.force - kP * Eigen::Vector2d::UnitY()).norm(), 1e-8 * kP);
  EXPECT_LT((tilted.force - kP * n).norm(), 1e-8 * kP);
  EXPECT_NEAR(flat.p0, half.p0, 1e-6 * half.p0);
  EXPECT_NEAR(tilted.p0, half.p0, 1e-6 * half.p0);
}

}  // namespace
