// V7 self-contact by symmetry (VALIDATION.md), 2D: a hairpin (C-shaped body) whose arms are pressed
// together. The whole hairpin, meshed as the mirror image of its upper half node for node
// (support/mirrored_mesh), with its "inner" surface (both arms' inner faces) in contact with ITSELF,
// must give the same contact pressure as the upper half pressed on a rigid frictionless plane at the
// symmetry line y = 0: to 1e-5 of the largest pressure at every node (VALIDATION.md), and the same
// displacements. Linear elasticity, P1, frictionless.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

#include "support/mirrored_mesh.hpp"
#include "support/solve_case.hpp"

using namespace symcontact;
using namespace symcontact::testing;

namespace {

const std::string kHalfGeo = std::string(SYMCONTACT_TEST_DATA) + "/geo/hairpin_half.geo";

/// The problem file: `mesh`, the symmetry condition on `symmetry` (a line group in the half model, a
/// node group in the whole), the load on "top", the back held in x, and `contact`.
std::string problem(const std::string& mesh, const std::string& contact) {
  return "[problem]\ndimension = 2\n[[body]]\nname = \"hairpin\"\nmesh = \"" + mesh +
         "\"\ngroup = \"hairpin\"\n[body.material]\nE = 1.0\nnu = 0.3\n"
         "[[body.dirichlet]]\nboundary = \"symmetry\"\nuy = 0.0\n"
         "[[body.dirichlet]]\nboundary = \"back\"\nux = 0.0\n"
         "[[body.pressure]]\nboundary = \"top\"\npressure = 2e-4\n" + contact;
}

}  // namespace

TEST(SelfContact2D, HairpinEqualsHalfModelOnARigidPlane) {
  const std::string dir = ::testing::TempDir() + "self_contact_2d/";
  write_text(dir, "half.geo", "h = 0.05;\nInclude \"" + kHalfGeo + "\";\n");
  MeshReadOptions ro;
  ro.dim = 2;
  const MeshFile half = read_mesh_file(dir + "half.geo", ro);
  write_mirrored_msh(half, 1, "symmetry", dir + "full.msh");

  auto h = solve_case(problem("half.geo", "[[contact]]\nname = \"floor\"\na = \"hairpin.inner\"\n"
                                          "[contact.obstacle]\ntype = \"plane\"\npoint = [0.0, 0.0]\nnormal = [0.0, 1.0]\n"),
                      dir);
  auto f = solve_case(problem("full.msh", "[[contact]]\nname = \"self\"\na = \"hairpin.inner\"\nb = \"hairpin.inner\"\n"), dir);

  // Pressure and displacement at every node of the upper arm's inner face, matched by position.
  const auto& hs = h->contact[0].sides[0];
  std::map<std::pair<double, double>, Index> full_node;
  const auto& fs = f->contact[0].sides[0];
  const Eigen::MatrixXd& hX = h->model->contacts().surfaces[hs.surface].X;  // reference positions
  const Eigen::MatrixXd& fX = f->model->contacts().surfaces[fs.surface].X;
  for (Index k = 0; k < fs.pressure.size(); ++k) full_node[{fX(0, k), fX(1, k)}] = k;
  double pmax = hs.pressure.maxCoeff(), worst = 0.0;
  ASSERT_GT(pmax, 0.0) << "the arm should touch the plane";
  for (Index k = 0; k < hs.pressure.size(); ++k) {
    auto it = full_node.find({hX(0, k), hX(1, k)});
    ASSERT_NE(it, full_node.end()) << "node at (" << hX(0, k) << ", " << hX(1, k) << ") not in the whole model";
    worst = std::max(worst, std::abs(fs.pressure[it->second] - hs.pressure[k]));
  }
  // The lower arm is the mirror image: the same pressures at the mirrored nodes.
  double worst_mirror = 0.0;
  for (Index k = 0; k < hs.pressure.size(); ++k) {
    auto it = full_node.find({hX(0, k), -hX(1, k)});
    ASSERT_NE(it, full_node.end());
    worst_mirror = std::max(worst_mirror, std::abs(fs.pressure[it->second] - hs.pressure[k]));
  }
  // Displacements: the whole model's upper half is the half model (nodes matched by position).
  const Mesh& mh = h->model->bodies()[0]->mesh;
  const Mesh& mf = f->model->bodies()[0]->mesh;
  std::map<std::pair<double, double>, Index> full_body_node;
  for (Index a = 0; a < mf.num_nodes(); ++a) full_body_node[{mf.x(0, a), mf.x(1, a)}] = a;
  double worst_u = 0.0, umax = 0.0;
  for (Index a = 0; a < mh.num_nodes(); ++a) {
    auto it = full_body_node.find({mh.x(0, a), mh.x(1, a)});
    ASSERT_NE(it, full_body_node.end());
    for (int i = 0; i < 2; ++i) {
      const double uh = h->u[h->model->dofs().dof(0, a, i)], uf = f->u[f->model->dofs().dof(0, it->second, i)];
      worst_u = std::max(worst_u, std::abs(uh - uf));
      umax = std::max(umax, std::abs(uh));
    }
  }
  std::printf("V7 2D hairpin: max |u_self - u_half| / max |u| = %.2e\n", worst_u / umax);
  EXPECT_LT(worst_u, 1e-5 * umax);
  std::printf("V7 2D hairpin: max pressure %.6e; |p_self - p_half| / p_max = %.2e (upper arm), %.2e (lower arm); "
              "contact force on the half model %.9e\n",
              pmax, worst / pmax, worst_mirror / pmax, h->contact[0].total_force.norm());
  EXPECT_LT(worst, 1e-5 * pmax);
  EXPECT_LT(worst_mirror, 1e-5 * pmax);
}
