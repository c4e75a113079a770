// The reported contact quantities add up (post/contact_results.hpp): per side and per pair the normal and
// tangential parts sum to the total as vectors, the tangential part is exactly zero without friction, the
// two sides of a pair carry opposite forces, each pair reports the force of its own rows only (a surface
// in two pairs, a pair declared twice, an open pair), their sum is the body's contact force (the applied
// load here, and the solve's residual), and the status follows the friction law. Cases: the Hertz
// cylinders of examples/hertz_2d (curved), with dissimilar materials, frictionless and with Coulomb
// friction; the cylinder on a rigid plane in several pairs; the two spheres of examples/hertz_3d with
// dissimilar materials. Self-contact: test_self_contact.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>

#include "support/solve_case.hpp"

using namespace symcontact;
using namespace symcontact::testing;

namespace {

const std::string kExamples = std::string(SYMCONTACT_EXAMPLES) + "/hertz_2d";
const double kLoad = 0.005;  // the half model's resultant (pressure 0.005 on a cut of width 1)

std::string geo(const std::string& example, double h) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "h = %.6g;\n", h);
  return std::string(buf) + "Include \"" + kExamples + "/" + example + "\";\n";
}

/// The two Hertz cylinders with Young's moduli 1 (upper) and `E_lower`, and `contact` as their pairs.
std::string two_cylinders(double E_lower, const std::string& contact) {
  return "[problem]\ndimension = 2\nmodel = \"plane_strain\"\n"
         "[[body]]\nname = \"upper\"\nmesh = \"cyl.geo\"\ngroup = \"upper\"\n[body.material]\nE = 1.0\nnu = 0.3\n"
         "[[body.dirichlet]]\nboundary = \"upper_symmetry\"\nux = 0.0\n"
         "[[body.pressure]]\nboundary = \"upper_load\"\npressure = 0.005\n"
         "[[body]]\nname = \"lower\"\nmesh = \"cyl.geo\"\ngroup = \"lower\"\n[body.material]\nE = " +
         std::to_string(E_lower) +
         "\nnu = 0.3\n[[body.dirichlet]]\nboundary = \"lower_symmetry\"\nux = 0.0\n"
         "[[body.dirichlet]]\nboundary = \"lower_base\"\nuy = 0.0\n" + contact;
}

/// The cylinder of examples/hertz_2d on rigid planes: `contact` holds its pairs.
std::string cylinder_on_planes(const std::string& contact) {
  return "[problem]\ndimension = 2\nmodel = \"plane_strain\"\n"
         "[[body]]\nname = \"cylinder\"\nmesh = \"cyl.geo\"\ngroup = \"cylinder\"\n[body.material]\nE = 1.0\nnu = 0.3\n"
         "[[body.dirichlet]]\nboundary = \"symmetry\"\nux = 0.0\n"
         "[[body.pressure]]\nboundary = \"load\"\npressure = 0.005\n" + contact;
}

std::string plane_pair(const std::string& name, double y) {
  return "[[contact]]\nname = \"" + name + "\"\na = \"cylinder.contact\"\n[contact.obstacle]\ntype = \"plane\"\n"
         "point = [0.0, " + std::to_string(y) + "]\nnormal = [0.0, 1.0]\n";
}

/// Per side and per pair: normal + tangential = total (vectors) and Σ_k nodal force = total, to 1e-10 of
/// `scale`; side b = −side a (two deformable sides); without friction the tangential part is exactly zero.
void expect_sums(const SolvedCase& c, double scale) {
  for (std::size_t pi = 0; pi < c.contact.size(); ++pi) {
    const ContactPairResult& r = c.contact[pi];
    const bool frictionless = c.model->contacts().pairs[pi].friction == FrictionLaw::kNone;
    EXPECT_LE((r.normal_force + r.tangential_force - r.total_force).norm(), 1e-10 * scale) << r.name;
    for (const ContactSideResult& s : r.sides) {
      EXPECT_LE((s.normal_force + s.tangential_force - s.total_force).norm(), 1e-10 * scale) << r.name;
      EXPECT_LE((s.force.rowwise().sum() - s.total_force).norm(), 1e-10 * scale) << r.name;
      EXPECT_LE((s.normal_part.rowwise().sum() - s.normal_force).norm(), 1e-10 * scale) << r.name;
      if (frictionless) {
        EXPECT_EQ(s.tangential_force.norm(), 0.0) << r.name;
        EXPECT_EQ(s.tangential.norm(), 0.0) << r.name;
        EXPECT_EQ((s.force - s.normal_part).norm(), 0.0) << r.name;
      }
    }
    if (r.sides.size() == 2) {
      EXPECT_LE((r.sides[0].total_force + r.sides[1].total_force).norm(), 1e-10 * scale) << r.name;
    }
  }
}

/// Σ over the pairs and sides of the contact force on body `b`, and the same sum of the solve's own
/// contact force (report.contact_force: the bodies' residual on free DOFs) over the body's contact nodes.
std::pair<Eigen::Vector2d, Eigen::Vector2d> body_force(const SolvedCase& c, int b) {
  Eigen::Vector2d pairs = Eigen::Vector2d::Zero(), residual = Eigen::Vector2d::Zero();
  std::set<Index> nodes;
  const ContactSet& cs = c.model->contacts();
  for (const ContactPairResult& r : c.contact)
    for (const ContactSideResult& s : r.sides) {
      if (cs.surfaces[s.surface].body != b) continue;
      pairs += s.total_force;
      nodes.insert(cs.surfaces[s.surface].nodes.begin(), cs.surfaces[s.surface].nodes.end());
    }
  for (Index v : nodes)
    for (int i = 0; i < 2; ++i) residual[i] += c.report.contact_force[c.model->dofs().dof(b, v, i)];
  return {pairs, residual};
}

double peak(const ContactSideResult& s) { return s.pressure.maxCoeff(); }

}  // namespace

// Frictionless, dissimilar (E = 1 on 3): the upper cylinder carries the load through the contact alone.
TEST(ContactResults, DissimilarCylindersAddUp) {
  const std::string dir = test_temp_dir("contact_results");
  write_text(dir, "cyl.geo", geo("two_cylinders.geo", 0.008));
  auto c = solve_case(two_cylinders(3.0, "[[contact]]\nname = \"interface\"\na = \"upper.upper_contact\"\n"
                                         "b = \"lower.lower_contact\"\n"),
                      dir);
  expect_sums(*c, kLoad);
  const ContactPairResult& r = c->contact.at(0);
  ASSERT_EQ(r.sides.size(), 2u);
  const auto [pairs, residual] = body_force(*c, 0);
  std::printf("dissimilar cylinders: force on the upper body %.15e (pairs) %.15e (residual); normal load %.15e; "
              "peak pressure a %.6e, b %.6e (b/a - 1 = %.3e)\n",
              pairs.y(), residual.y(), r.normal_load, peak(r.sides[0]), peak(r.sides[1]),
              peak(r.sides[1]) / peak(r.sides[0]) - 1);
  const double ca = r.sides[0].current_pressure.maxCoeff(), cb = r.sides[1].current_pressure.maxCoeff();
  std::printf("  per current length: peak a %.6e, b %.6e (b/a - 1 = %.3e)\n", ca, cb, cb / ca - 1);
  // Upward force on the upper body = the applied load; the residual (free DOFs) agrees.
  EXPECT_NEAR(pairs.y(), kLoad, 1e-10 * kLoad);
  EXPECT_NEAR(residual.y(), kLoad, 1e-10 * kLoad);
  EXPECT_NEAR(r.normal_force.y(), kLoad, 1e-10 * kLoad);
  // ∫ λ dΓ: the interface is counted once; the zone is nearly flat (a/R = 0.1), so |F_n| to cos of its slope.
  EXPECT_NEAR(r.normal_load, kLoad, 5e-3 * kLoad);
  EXPECT_GE(r.normal_load, kLoad * (1 - 1e-10));
  // Each side's pressure is per its own reference length: the sides differ by their tangential stretches
  // (measured 2.1 %); per current length they share one interface and agree (measured 2.3e-4).
  EXPECT_GT(std::abs(peak(r.sides[1]) / peak(r.sides[0]) - 1), 0.01);
  EXPECT_LT(std::abs(cb / ca - 1), 1e-3);
}

// One surface in three pairs: the floor declared twice, and a plane 0.01 below it, never reached.
TEST(ContactResults, EachPairReportsItsOwnRows) {
  const std::string dir = test_temp_dir("contact_results");
  write_text(dir, "cyl.geo", geo("cylinder_on_plane.geo", 0.008));
  auto one = solve_case(cylinder_on_planes(plane_pair("floor", 0.0)), dir);
  auto c = solve_case(cylinder_on_planes(plane_pair("floor", 0.0) + plane_pair("again", 0.0) +
                                         plane_pair("below", -0.01)),
                      dir);
  expect_sums(*one, kLoad);
  expect_sums(*c, kLoad);
  ASSERT_EQ(c->contact.size(), 3u);
  const auto [pairs, residual] = body_force(*c, 0);
  std::printf("one surface in three pairs: floor %.6e, again %.6e, below %.3e; sum %.15e (residual %.15e); "
              "normal loads %.6e + %.6e = %.6e (one pair: %.6e)\n",
              c->contact[0].total_force.y(), c->contact[1].total_force.y(), c->contact[2].total_force.norm(), pairs.y(),
              residual.y(), c->contact[0].normal_load, c->contact[1].normal_load,
              c->contact[0].normal_load + c->contact[1].normal_load, one->contact[0].normal_load);
  EXPECT_NEAR(one->contact[0].total_force.y(), kLoad, 1e-10 * kLoad);
  EXPECT_NEAR(pairs.y(), kLoad, 1e-10 * kLoad);
  EXPECT_NEAR(residual.y(), kLoad, 1e-10 * kLoad);
  EXPECT_LE(c->contact[2].total_force.norm(), 1e-10 * kLoad);
  EXPECT_EQ(c->contact[2].sides[0].status.maxCoeff(), 0);
  // The duplicated floor shares the load (in some split); together they are the single floor.
  EXPECT_NEAR(c->contact[0].total_force.y() + c->contact[1].total_force.y(), kLoad, 1e-10 * kLoad);
  EXPECT_NEAR(c->contact[0].normal_load + c->contact[1].normal_load, one->contact[0].normal_load,
              1e-6 * one->contact[0].normal_load);
}

// Coulomb friction on the dissimilar cylinders: the mismatch of their surface strains makes the edges of
// the zone slip and its centre stick. Sums as above; open nodes carry no pressure; slip where |t| = μ p.
TEST(ContactResults, FrictionalDissimilarCylindersFollowTheLaw) {
  const std::string dir = test_temp_dir("contact_results");
  write_text(dir, "cyl.geo", geo("two_cylinders.geo", 0.008));
  const double mu = 0.1;
  auto c = solve_case(two_cylinders(3.0, "[[contact]]\nname = \"interface\"\na = \"upper.upper_contact\"\n"
                                         "b = \"lower.lower_contact\"\nfriction = \"coulomb\"\nmu = 0.1\n"),
                      dir);
  expect_sums(*c, kLoad);
  const ContactPairResult& r = c->contact.at(0);
  const auto [pairs, residual] = body_force(*c, 0);
  const ContactSideResult& a = r.sides.at(0);  // the friction side
  const double pmax = r.max_pressure;
  int counts[3] = {0, 0, 0};
  double worst_ratio = 0.0, open_traction = 0.0, open_pressure = 0.0;
  for (Index k = 0; k < a.pressure.size(); ++k) {
    const int st = a.status[k];
    ++counts[st];
    const double t = a.tangential.col(k).norm();
    if (st == 0) {
      open_traction = std::max(open_traction, t);
      open_pressure = std::max(open_pressure, a.pressure[k]);
      continue;
    }
    worst_ratio = std::max(worst_ratio, t / (mu * a.pressure[k]));
    const double s = a.slip.col(k).norm();
    // The node's regularisation length (automatic here: a fraction of its facets' size).
    const ContactPair& pair = c->model->contacts().pairs[0];
    const double alpha = pair.regularisation_length(c->model->contacts().surfaces[a.surface].nodal_size[k]);
    const double law = s / std::sqrt(s * s + alpha * alpha);
    EXPECT_EQ(st == 2, law >= kSlipRatio) << "node " << k;
  }
  std::printf("frictional dissimilar cylinders: force on the upper body %.15e (pairs) %.15e (residual); tangential "
              "%.6e; nodes open %d, stick %d, slip %d; max |t|/(mu p) %.6f; open nodes: max |t| %.2e p_max, max p "
              "%.2e p_max\n",
              pairs.y(), residual.y(), r.tangential_force.x(), counts[0], counts[1], counts[2], worst_ratio,
              open_traction / pmax, open_pressure / pmax);
  // In y (x holds the support of the symmetry node, where the residual keeps Aᵀμ alone).
  EXPECT_NEAR(pairs.y(), kLoad, 1e-10 * kLoad);
  EXPECT_NEAR(residual.y(), kLoad, 1e-10 * kLoad);
  EXPECT_GT(std::abs(r.tangential_force.x()), 1e-4 * kLoad);  // friction acts
  EXPECT_GT(counts[1], 0);
  EXPECT_GT(counts[2], 0);
  EXPECT_LE(worst_ratio, 1.0 + 1e-3);
  EXPECT_LE(open_pressure, kContactPressureFraction * pmax);
}

// 3D, frictionless, dissimilar spheres (E = 1 on 3, quarter models, examples/hertz_3d at h = 0.04): the
// tangential part is exactly zero, the sides balance, and the upper sphere, held by the contact alone, gets
// from the pair what its residual says.
TEST(ContactResults, DissimilarSpheres3DAddUp) {
  const std::string dir = test_temp_dir("contact_results");
  write_text(dir, "spheres.geo", "h = 0.04;\nInclude \"" + std::string(SYMCONTACT_EXAMPLES) +
                                     "/hertz_3d/two_spheres.geo\";\n");
  std::string toml = read_text(std::string(SYMCONTACT_EXAMPLES) + "/hertz_3d/two_spheres.toml");
  for (std::size_t at; (at = toml.find("two_spheres.geo")) != std::string::npos;) toml.replace(at, 15, "spheres.geo");
  const std::size_t lower = toml.find("name = \"lower\"");
  ASSERT_NE(lower, std::string::npos);
  toml.replace(toml.find("E = 1.0", lower), 7, "E = 3.0");
  auto c = solve_case(toml, dir);
  const ContactPairResult& r = c->contact.at(0);
  ASSERT_EQ(r.sides.size(), 2u);
  const double scale = r.normal_load;
  ASSERT_GT(scale, 0.0);
  expect_sums(*c, scale);
  // The upper body's residual over its contact nodes (free DOFs in z).
  const ContactSurface& s = c->model->contacts().surfaces[r.sides[0].surface];
  double residual_z = 0.0;
  for (Index v : s.nodes) residual_z += c->report.contact_force[c->model->dofs().dof(s.body, v, 2)];
  std::printf("dissimilar spheres: F_z %.15e (pair) %.15e (residual); normal load %.9e; tangential %.1e; peak "
              "pressure a %.6e, b %.6e; per current area a %.6e, b %.6e\n",
              r.total_force.z(), residual_z, r.normal_load, r.tangential_force.norm(), peak(r.sides[0]),
              peak(r.sides[1]), r.sides[0].current_pressure.maxCoeff(), r.sides[1].current_pressure.maxCoeff());
  EXPECT_NEAR(r.total_force.z(), residual_z, 1e-10 * scale);
  EXPECT_NEAR(r.normal_force.z(), residual_z, 1e-10 * scale);
  EXPECT_EQ(r.tangential_force.norm(), 0.0);
  // Peaks: 2.2 % apart per reference area, 1.1e-3 per current area (measured, h = 0.04).
  const double ca = r.sides[0].current_pressure.maxCoeff(), cb = r.sides[1].current_pressure.maxCoeff();
  EXPECT_GT(std::abs(peak(r.sides[1]) / peak(r.sides[0]) - 1), 0.01);
  EXPECT_LT(std::abs(cb / ca - 1), 5e-3);
}
