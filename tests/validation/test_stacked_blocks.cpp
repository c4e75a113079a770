// Three stacked bodies with non-matching interfaces (issue #6; the V3 patch test with a third block):
// "lower" [0,1]×[0,1], "middle" [0,1]×[1,2], "upper" [0,1]×[2,3] (3D: unit cubes stacked in z) with
// different mesh divisions each, E = 1, ν = 0.3, bottom held normally, point conditions that only remove
// rigid motions (each block as the upper block of the two-block patch test), pressure p = 0.01 on top,
// two symmetric contact pairs (lower/middle, middle/upper). Exact: the linear field of V3, the pressure p
// at BOTH interfaces. Also: the support reactions balance the applied load, and declaring the bodies and
// the pairs in reverse order (each pair's a and b swapped) changes nothing. The case is the shared V3
// helper (support/contact_patch_case.hpp, n3 > 0). With Coulomb friction (μ = 0.3) the answer is the same:
// identical materials, so no relative slip and no tangential traction.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <map>

#include "support/contact_patch_case.hpp"

using namespace symcontact;
using namespace symcontact::testing;

namespace {

class StackedBlocks : public ::testing::TestWithParam<ContactPatchCase> {};

ContactPatchCase stack(int dim, int n1, int n2, int n3, int order, double mu = -1.0) {
  ContactPatchCase c;
  c.mu = mu;
  c.dim = dim;
  c.n1 = n1;
  c.n2 = n2;
  c.n3 = n3;
  c.order = order;
  return c;
}

using Point = std::array<double, 3>;

Point point(const Eigen::MatrixXd& X, Index k) {
  Point p{0.0, 0.0, 0.0};
  for (Eigen::Index i = 0; i < X.rows(); ++i) p[i] = X(i, k);
  return p;
}

/// max |u_a − u_b| over every node of every body, bodies matched by name and nodes by position.
double displacement_difference(const SolvedCase& a, const SolvedCase& b) {
  double worst = 0.0;
  for (int ba = 0; ba < a.model->dofs().num_bodies(); ++ba) {
    const Body& body = *a.model->bodies()[ba];
    const int bb = b.model->body_index(body.name);
    EXPECT_GE(bb, 0) << body.name;
    if (bb < 0) return INFINITY;
    const Mesh& mb = b.model->bodies()[bb]->mesh;
    std::map<Point, Index> node;
    for (Index v = 0; v < mb.num_nodes(); ++v) node[point(mb.x, v)] = v;
    for (Index v = 0; v < body.mesh.num_nodes(); ++v) {
      const auto it = node.find(point(body.mesh.x, v));
      EXPECT_NE(it, node.end()) << body.name << " node " << v;
      if (it == node.end()) return INFINITY;
      for (int i = 0; i < a.model->dofs().dim(); ++i)
        worst = std::max(worst, std::abs(a.u[a.model->dofs().dof(ba, v, i)] - b.u[b.model->dofs().dof(bb, it->second, i)]));
    }
  }
  return worst;
}

/// max |p_a − p_b| over the nodes of every side of every pair, pairs matched by name, sides by their
/// surface's name (a and b are swapped in the reordered file), nodes by position.
double pressure_difference(const SolvedCase& a, const SolvedCase& b) {
  double worst = 0.0;
  const auto& sa = a.model->contacts().surfaces;
  const auto& sb = b.model->contacts().surfaces;
  for (const ContactPairResult& pa : a.contact) {
    const auto pb = std::find_if(b.contact.begin(), b.contact.end(), [&](const auto& p) { return p.name == pa.name; });
    EXPECT_NE(pb, b.contact.end()) << pa.name;
    if (pb == b.contact.end()) return INFINITY;
    for (const ContactSideResult& side : pa.sides) {
      const auto other = std::find_if(pb->sides.begin(), pb->sides.end(),
                                      [&](const auto& s) { return sb[s.surface].name == sa[side.surface].name; });
      EXPECT_NE(other, pb->sides.end()) << sa[side.surface].name;
      if (other == pb->sides.end()) return INFINITY;
      std::map<Point, Index> node;
      for (Index k = 0; k < other->pressure.size(); ++k) node[point(sb[other->surface].X, k)] = k;
      for (Index k = 0; k < side.pressure.size(); ++k) {
        const auto it = node.find(point(sa[side.surface].X, k));
        EXPECT_NE(it, node.end());
        if (it == node.end()) return INFINITY;
        worst = std::max(worst, std::abs(side.pressure[k] - other->pressure[it->second]));
      }
    }
  }
  return worst;
}

}  // namespace

TEST_P(StackedBlocks, UniformPressureAtBothInterfacesAndOrderIndependent) {
  const ContactPatchCase c = GetParam();
  ContactPatchCase r = c;
  r.swap = true;
  const auto t0 = std::chrono::steady_clock::now();
  const auto s = contact_patch_solve(c);
  const auto sr = contact_patch_solve(r);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(s->contact.size(), 2u);
  ASSERT_EQ(sr->contact.size(), 2u);
  const ContactPatchErrors e = contact_patch_errors(c, *s), er = contact_patch_errors(r, *sr);
  const double du = displacement_difference(*s, *sr), dp = pressure_difference(*s, *sr);
  double umax = 0.0;
  for (Eigen::Index k = 0; k < s->u.size(); ++k) umax = std::max(umax, std::abs(s->u[k]));
  std::printf("  %dD (%d, %d, %d) P%d mu = %.1f: pressure error %.2e (reordered %.2e), displacement error %.2e (%.2e), "
              "tangential %.2e p, equilibrium %.2e (%.2e) of the load %.6g; reordered vs not: displacement %.2e, pressure %.2e p; "
              "%d geometry / %d IPOPT iterations; both solves %.1f s\n",
              c.dim, c.n1, c.n2, c.n3, c.order, c.mu < 0 ? 0.0 : c.mu, e.pressure, er.pressure, e.displacement, er.displacement,
              std::max(e.tangential, er.tangential), e.equilibrium,
              er.equilibrium, e.applied_load, du / umax, dp / 0.01, e.geometry_iterations, e.ipopt_iterations, secs);
  EXPECT_LT(e.pressure, 1e-6);
  EXPECT_LT(er.pressure, 1e-6);
  // As the two-block V3 tests: 1e-8 in 2D, 1e-7 in 3D (the polish's residual opening with P2 there).
  const double tol_u = c.dim == 2 ? 1e-8 : 1e-7;
  EXPECT_LT(e.displacement, tol_u);
  EXPECT_LT(er.displacement, tol_u);
  EXPECT_NEAR(e.applied_load, 0.01, 1e-12);
  EXPECT_LT(e.equilibrium, 1e-8);
  EXPECT_LT(er.equilibrium, 1e-8);
  if (c.mu >= 0) {  // no relative slip: no friction force
    EXPECT_LT(std::max(e.tangential, er.tangential), 1e-6);
  }
  EXPECT_LT(du, 1e-6 * umax);
  EXPECT_LT(dp, 1e-6 * 0.01);
}

INSTANTIATE_TEST_SUITE_P(Stacked, StackedBlocks,
                         ::testing::Values(stack(2, 4, 5, 3, 1), stack(2, 4, 5, 3, 2), stack(2, 4, 5, 3, 1, 0.3),
                                           stack(3, 3, 5, 4, 1), stack(3, 3, 5, 4, 2), stack(3, 3, 5, 4, 1, 0.3)),
                         [](const auto& p) { return contact_patch_name(p.param); });
