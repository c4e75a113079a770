// V7 self-contact by symmetry (VALIDATION.md): a hairpin (C-shaped body) whose arms are pressed together.
// The whole hairpin, meshed as the mirror image of its upper half node for node
// (support/mirrored_mesh), with its "inner" surface (both arms' inner faces) in contact with ITSELF,
// must give the same contact pressure as the upper half pressed on a rigid frictionless plane at the
// symmetry plane y = 0: to 1e-5 of the largest pressure at every node (VALIDATION.md), and the same
// displacements. Linear elasticity, P1, frictionless. In 2D the arms' inner faces carry circular bumps;
// in 3D (a hairpin of width 1.4 in z) spherical ones, so that the contact stays inside the surface.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>

#include "support/mirrored_mesh.hpp"
#include "support/solve_case.hpp"

using namespace symcontact;
using namespace symcontact::testing;

namespace {

using Point = std::array<double, 3>;

Point point(const Eigen::MatrixXd& X, Index k, double sign_y = 1.0) {
  Point p{0.0, 0.0, 0.0};
  for (Eigen::Index i = 0; i < X.rows(); ++i) p[i] = X(i, k);
  p[1] *= sign_y;
  return p;
}

/// The problem file: `mesh`, the symmetry condition on "symmetry" (a facet group in the half model, a
/// node group in the whole), the load on "top", the back held in x (and z in 3D), and `contact`.
std::string problem(int dim, const std::string& mesh, const std::string& contact) {
  return "[problem]\ndimension = " + std::to_string(dim) + "\n[[body]]\nname = \"hairpin\"\nmesh = \"" + mesh +
         "\"\ngroup = \"hairpin\"\n[body.material]\nE = 1.0\nnu = 0.3\n"
         "[[body.dirichlet]]\nboundary = \"symmetry\"\nuy = 0.0\n"
         "[[body.dirichlet]]\nboundary = \"back\"\nux = 0.0\n" + std::string(dim == 3 ? "uz = 0.0\n" : "") +
         "[[body.pressure]]\nboundary = \"top\"\npressure = 2e-4\n" + contact;
}

/// Meshes `geo` (the half hairpin, h set by `h_line`), mirrors it, solves the half model on a rigid plane
/// and the whole in self-contact, and checks pressures and displacements node by node.
void check_self_contact_equals_half_model(int dim, const std::string& geo, const std::string& h_line) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::string dir = ::testing::TempDir() + "self_contact_" + std::to_string(dim) + "d/";
  write_text(dir, "half.geo", h_line + "\nInclude \"" + geo + "\";\n");
  MeshReadOptions ro;
  ro.dim = dim;
  const MeshFile half = read_mesh_file(dir + "half.geo", ro);
  // The cut must lie exactly on the plane, or the mirror would not share its nodes.
  const MeshFile::Group* cut = half.find("symmetry", dim - 1);
  ASSERT_NE(cut, nullptr);
  for (const auto& b : cut->blocks)
    for (Index a : b.nodes) ASSERT_EQ(half.x(1, a), 0.0) << "cut node " << a;
  write_mirrored_msh(half, 1, "symmetry", dir + "full.msh");

  const std::string plane = dim == 3 ? "point = [0.0, 0.0, 0.0]\nnormal = [0.0, 1.0, 0.0]\n"
                                     : "point = [0.0, 0.0]\nnormal = [0.0, 1.0]\n";
  auto h = solve_case(problem(dim, "half.geo", "[[contact]]\nname = \"floor\"\na = \"hairpin.inner\"\n"
                                               "[contact.obstacle]\ntype = \"plane\"\n" + plane),
                      dir);
  auto f = solve_case(problem(dim, "full.msh", "[[contact]]\nname = \"self\"\na = \"hairpin.inner\"\nb = \"hairpin.inner\"\n"),
                      dir);

  // Pressure at every node of the upper arm's inner face, and at its mirror image on the lower arm.
  const auto& hs = h->contact[0].sides[0];
  const auto& fs = f->contact[0].sides[0];
  const Eigen::MatrixXd& hX = h->model->contacts().surfaces[hs.surface].X;  // reference positions
  const Eigen::MatrixXd& fX = f->model->contacts().surfaces[fs.surface].X;
  std::map<Point, Index> full_node;
  for (Index k = 0; k < fs.pressure.size(); ++k) full_node[point(fX, k)] = k;
  const double pmax = hs.pressure.maxCoeff();
  ASSERT_GT(pmax, 0.0) << "the arm should touch the plane";
  double worst = 0.0, worst_mirror = 0.0;
  Index worst_node = 0;
  // The same comparison for the nodal contact forces' component along the plane's normal, per unit
  // lumped area (printed only): the pressure is the force along the interface normal, for the
  // self-contact the bisector of the arm's own normal and the opposite arm's (contact_points.hpp,
  // interface_normal()), which is the plane's normal when the solution is mirror-symmetric.
  const ContactSurface& hsurf = h->model->contacts().surfaces[hs.surface];
  const ContactSurface& fsurf = f->model->contacts().surfaces[fs.surface];
  auto force_y = [](const SolvedCase& c, const ContactSurface& s, Index k) {
    return c.report.contact_force[c.model->dofs().dof(s.body, s.nodes[k], 1)];
  };
  double worst_force = 0.0;
  int touching = 0;
  for (Index k = 0; k < hs.pressure.size(); ++k) {
    auto it = full_node.find(point(hX, k));
    ASSERT_NE(it, full_node.end()) << "node " << k << " of the half model's surface not in the whole model";
    if (std::abs(fs.pressure[it->second] - hs.pressure[k]) > worst) worst_node = k;
    worst = std::max(worst, std::abs(fs.pressure[it->second] - hs.pressure[k]));
    auto im = full_node.find(point(hX, k, -1.0));
    ASSERT_NE(im, full_node.end());
    worst_mirror = std::max(worst_mirror, std::abs(fs.pressure[im->second] - hs.pressure[k]));
    const double fh = force_y(*h, hsurf, k);
    worst_force = std::max({worst_force, std::abs(force_y(*f, fsurf, it->second) - fh) / hsurf.nodal_area[k],
                            std::abs(-force_y(*f, fsurf, im->second) - fh) / hsurf.nodal_area[k]});
    if (hs.status[k] != 0) ++touching;
  }
  // The plane pushes along its normal only; the self-contact force follows the smoothed normals of the
  // deformed opposite arm (printed: its tangential part).
  double tangential_self = 0.0;
  for (Index k = 0; k < fs.pressure.size(); ++k) tangential_self = std::max(tangential_self, fs.tangential.col(k).norm());
  // Displacements: the whole model's upper half is the half model (nodes matched by position).
  const Mesh& mh = h->model->bodies()[0]->mesh;
  const Mesh& mf = f->model->bodies()[0]->mesh;
  std::map<Point, Index> full_body_node;
  for (Index a = 0; a < mf.num_nodes(); ++a) full_body_node[point(mf.x, a)] = a;
  double worst_u = 0.0, umax = 0.0;
  for (Index a = 0; a < mh.num_nodes(); ++a) {
    auto it = full_body_node.find(point(mh.x, a));
    ASSERT_NE(it, full_body_node.end());
    for (int i = 0; i < dim; ++i) {
      const double uh = h->u[h->model->dofs().dof(0, a, i)], uf = f->u[f->model->dofs().dof(0, it->second, i)];
      worst_u = std::max(worst_u, std::abs(uh - uf));
      umax = std::max(umax, std::abs(uh));
    }
  }
  // The self-contact solution's own mirror symmetry: node a and its mirror image R a (R: y -> -y) must
  // have u(R a) = R u(a); a symmetric problem whose discrete solution is not symmetric is an unconverged
  // solve or a one-sided ingredient.
  double worst_sym = 0.0, worst_sym_p = 0.0;
  for (Index a = 0; a < mf.num_nodes(); ++a) {
    auto im = full_body_node.find(point(mf.x, a, -1.0));
    ASSERT_NE(im, full_body_node.end());
    for (int i = 0; i < dim; ++i) {
      const double s = i == 1 ? -1.0 : 1.0;
      worst_sym = std::max(worst_sym, std::abs(f->u[f->model->dofs().dof(0, a, i)] -
                                               s * f->u[f->model->dofs().dof(0, im->second, i)]));
    }
  }
  for (Index k = 0; k < fs.pressure.size(); ++k)
    worst_sym_p = std::max(worst_sym_p, std::abs(fs.pressure[k] - fs.pressure[full_node.at(point(fX, k, -1.0))]));
  {
    const Point w = point(hX, worst_node);
    const Index fk = full_node.at(w);
    std::printf("V7 %dD hairpin: worst node (%.4f, %.4f, %.4f): p_half %.6e (status %d, gap %.3e), p_self %.6e "
                "(status %d, gap %.3e)\n", dim, w[0], w[1], w[2], hs.pressure[worst_node], hs.status[worst_node],
                hs.gap[worst_node], fs.pressure[fk], fs.status[fk], fs.gap[fk]);
  }
  std::printf("V7 %dD hairpin: self-contact geometry iterations %d, relative changes", dim, f->report.geometry_iterations);
  for (double c : f->report.change_history) std::printf(" %.1e", c);
  std::printf("\n");
  std::printf("V7 %dD hairpin: self-contact mirror symmetry: max |u(R a) - R u(a)| / max |u| = %.2e, "
              "max |p(R k) - p(k)| / p_max = %.2e\n", dim, worst_sym / umax, worst_sym_p / pmax);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("V7 %dD hairpin (%td nodes in the whole): max |u_self - u_half| / max |u| = %.2e\n", dim,
              static_cast<std::ptrdiff_t>(mf.num_nodes()), worst_u / umax);
  std::printf("V7 %dD hairpin: max pressure %.6e, %d of %td surface nodes in contact; |p_self - p_half| / p_max = "
              "%.2e (upper arm), %.2e (lower arm); nodal force along the plane's normal per unit area: %.2e p_max; self-contact "
              "tangential traction %.2e p_max; contact force on the half model %.9e; %.1f s\n",
              dim, pmax, touching, static_cast<std::ptrdiff_t>(hs.pressure.size()), worst / pmax, worst_mirror / pmax,
              worst_force / pmax, tangential_self / pmax, h->contact[0].total_force.norm(), secs);
  // The self-contact pair reports one side, the surface: its force sums to zero (action and reaction), its
  // normal load ∫ λ dΓ is the force across the interface, the half model's on the plane; no tangential part.
  const ContactPairResult& self = f->contact[0];
  const double load = h->contact[0].normal_load;
  std::printf("V7 %dD hairpin: normal load %.9e (self) %.9e (half); |F_n| on the plane %.9e; self total force "
              "%.2e\n", dim, self.normal_load, load, h->contact[0].normal_force.norm(), self.total_force.norm());
  EXPECT_EQ(self.sides.size(), 1u);
  EXPECT_GT(load, 0.0);
  EXPECT_NEAR(self.normal_load, load, 1e-5 * load);
  EXPECT_LE(self.total_force.norm(), 1e-10 * load);
  EXPECT_LE((self.normal_force + self.tangential_force - self.total_force).norm(), 1e-10 * load);
  EXPECT_EQ(self.tangential_force.norm(), 0.0);
  EXPECT_NEAR(h->contact[0].normal_force.norm(), load, 1e-10 * load);  // a plane: one normal
  EXPECT_LT(worst_sym, 1e-5 * umax);
  EXPECT_LT(worst_u, 1e-5 * umax);
  EXPECT_LT(worst, 1e-5 * pmax);
  EXPECT_LT(worst_mirror, 1e-5 * pmax);
}

}  // namespace

TEST(SelfContact2D, HairpinEqualsHalfModelOnARigidPlane) {
  check_self_contact_equals_half_model(2, std::string(SYMCONTACT_TEST_DATA) + "/geo/hairpin_half.geo", "h = 0.05;");
}

// Before the self-contact projected along the bisector of the two sides' normals (ContactPair::bisector_ray(),
// contact_points.hpp) this case missed its tolerance, 1.01e-5 of p_max, by the gap to the tilted mirrored
// facet, 2y cos t (n_f·n̄) instead of 2y (docs/validation.md, V7); with it the two discrete problems are
// the same, and the difference is round-off.
TEST(SelfContact3D, HairpinEqualsHalfModelOnARigidPlane) {
  check_self_contact_equals_half_model(3, std::string(SYMCONTACT_TEST_DATA) + "/geo/hairpin_half_3d.geo", "h = 0.15;");
}

// The same comparison on finer bump meshes (h = 0.15 elsewhere), a study for docs/validation.md (V7): with
// the closest-point projection the difference fell with the bump mesh to 1.0e-5 at 0.05 and the solve
// ended unclosed or slid at 0.04 and 0.035. Minutes per mesh; run with --gtest_also_run_disabled_tests.
TEST(SelfContact3D, DISABLED_BumpMeshRefinementStudy) {
  for (const char* hb : {"0.1", "0.07", "0.04", "0.035", "0.03"}) {
    SCOPED_TRACE(std::string("hb = ") + hb);
    check_self_contact_equals_half_model(3, std::string(SYMCONTACT_TEST_DATA) + "/geo/hairpin_half_3d.geo",
                                         std::string("h = 0.15; hb = ") + hb + ";");
  }
}
