// V3 contact patch test, 2D (VALIDATION.md): two unit blocks pressed together through a non-matching
// (or matching) interface must transmit a uniform pressure exactly. Lower block [0,1]×[0,1], upper
// [0,1]×[1,2], n1 and n2 divisions per side; E = 1, ν = 0.3, plane strain; bottom u_y = 0 and u_x = 0
// at (0, 0); u_x = 0 at (0, 2) removes the upper block's free sliding; pressure p = 0.01 on top.
// Exact: σ_yy = −p, contact pressure p, u_y = −(1 − ν²) p y / E, u_x = ν (1 + ν) p x / E.
// The same blocks as ONE body whose two blocks touch at y = 1 (their own nodes there, coincident where the
// divisions meet), held together by a self-contact on the group holding both faces: the same exact answer
// (V3OneBody: the mesh checks allow the cut and the two pieces, mesh/mesh_topology.hpp), also with the upper
// block of a second, softer material of the same body (its exact field: contact_patch_case.hpp).
// The case itself (geometry, problem file, errors) is tests/support/contact_patch_case.hpp, shared with
// the frictional variant (test_contact_patch_friction.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "support/contact_patch_case.hpp"
#include "symcontact/mesh/mesh_topology.hpp"

using namespace symcontact::testing;

namespace {

class ContactPatch2D : public ::testing::TestWithParam<ContactPatchCase> {};

ContactPatchCase patch(int n1, int n2, int order, const char* mode, bool one_body = false) {
  ContactPatchCase c;
  c.one_body = one_body;
  c.n1 = n1;
  c.n2 = n2;
  c.order = order;
  c.mode = mode;
  return c;
}

}  // namespace

TEST_P(ContactPatch2D, UniformPressureAndExactDisplacements) {
  const ContactPatchCase pc = GetParam();
  const auto solved = contact_patch_solve(pc);
  // Each block has the cells it was meshed with: quadrilaterals where recombined, triangles elsewhere.
  for (const auto& body : solved->model->bodies()) {
    const bool quads = std::count(pc.quad_blocks.begin(), pc.quad_blocks.end(), body->name) > 0;
    const symcontact::CellType expected =
        quads ? (pc.order == 1 ? symcontact::CellType::kQuad4
                               : (pc.serendipity ? symcontact::CellType::kQuad8 : symcontact::CellType::kQuad9))
              : (pc.order == 1 ? symcontact::CellType::kTri3 : symcontact::CellType::kTri6);
    EXPECT_EQ(body->mesh.first_cell_type(), expected) << body->name;
  }
  const ContactPatchErrors e = contact_patch_errors(pc, *solved);
  std::printf("  (%d, %d) P%d %s: displacement error %.2e, pressure error %.2e, %d geometry / %d IPOPT iterations\n",
              pc.n1, pc.n2, pc.order, pc.mode.c_str(), e.displacement, e.pressure, e.geometry_iterations,
              e.ipopt_iterations);
  EXPECT_LT(e.pressure, 1e-6);
  EXPECT_LT(e.displacement, 1e-8);
}

INSTANTIATE_TEST_SUITE_P(
    V3, ContactPatch2D,
    ::testing::Values(patch(4, 5, 1, "symmetric"), patch(5, 4, 1, "symmetric"), patch(4, 5, 2, "symmetric"),
                      patch(5, 4, 2, "symmetric"), patch(4, 5, 1, "one-pass"), patch(5, 4, 1, "one-pass"),
                      patch(4, 5, 2, "one-pass"), patch(5, 4, 2, "one-pass"),
                      // Matching meshes: the two constraint families are exactly dependent.
                      patch(4, 4, 1, "symmetric"), patch(4, 4, 2, "symmetric")),
    [](const auto& p) { return contact_patch_name(p.param); });

// Quadrilaterals (Recombine) on one or both sides: Quad4 at order 1, Quad9 (and Quad8 with the incomplete
// second order) at order 2. Their boundaries are segments like the triangles', so the same exactness holds.
namespace {
ContactPatchCase quad_patch(int n1, int n2, int order, const char* mode, std::vector<std::string> blocks,
                            bool serendipity = false) {
  ContactPatchCase c = patch(n1, n2, order, mode);
  c.quad_blocks = std::move(blocks);
  c.serendipity = serendipity;
  return c;
}
}  // namespace

INSTANTIATE_TEST_SUITE_P(
    V3Quads, ContactPatch2D,
    ::testing::Values(quad_patch(4, 5, 1, "symmetric", {"lower", "upper"}), quad_patch(5, 4, 1, "one-pass", {"upper"}),
                      quad_patch(4, 5, 1, "symmetric", {"lower"}), quad_patch(4, 5, 2, "symmetric", {"lower", "upper"}),
                      quad_patch(5, 4, 2, "one-pass", {"lower"}),
                      quad_patch(4, 5, 2, "symmetric", {"lower", "upper"}, true)),
    [](const auto& p) { return contact_patch_name(p.param); });

namespace {
/// E_u = 0.1 and ν_u (1 + ν_u) / E_u = ν (1 + ν) / E: the same lateral strain as the lower block, so no slip.
ContactPatchCase soft_upper(ContactPatchCase c) {
  c.upper_E = 0.1;
  c.upper_nu = 0.5 * (std::sqrt(1 + 4 * c.upper_E * 0.3 * 1.3) - 1);
  return c;
}
/// E_u = 0.1, ν_u = 0.3: the upper block spreads ten times more; small sliding (contact_patch_case.hpp).
ContactPatchCase sliding_soft_upper(ContactPatchCase c) {
  c.upper_E = 0.1;
  c.geometry = "reference";
  return c;
}
}  // namespace

class ContactPatchOneBody : public ::testing::TestWithParam<ContactPatchCase> {};

TEST_P(ContactPatchOneBody, UniformPressureAndExactDisplacements) {
  const ContactPatchCase pc = GetParam();
  const auto solved = contact_patch_solve(pc);
  ASSERT_EQ(solved->model->bodies().size(), 1u);
  // One block recombined: one body of quadrilaterals and triangles.
  EXPECT_EQ(solved->model->bodies()[0]->mesh.mixed(), !pc.quad_blocks.empty());
  // The blocks keep their own nodes at y = 1: twins where the two node spacings 1/(order n1) and 1/(order n2)
  // meet, at x = k / (order gcd(n1, n2)) (every interface node with matching divisions).
  const std::size_t twins = coincident_nodes(solved->model->bodies()[0]->mesh).size();
  EXPECT_EQ(twins, static_cast<std::size_t>(pc.order * std::gcd(pc.n1, pc.n2) + 1));
  const ContactPatchErrors e = contact_patch_errors(pc, *solved);
  std::printf("  one body (%d, %d) P%d: displacement error %.2e, pressure error %.2e, equilibrium %.2e, "
              "%d geometry / %d IPOPT iterations\n",
              pc.n1, pc.n2, pc.order, e.displacement, e.pressure, e.equilibrium, e.geometry_iterations,
              e.ipopt_iterations);
  EXPECT_LT(e.pressure, 1e-6);
  EXPECT_LT(e.displacement, 1e-8);
  EXPECT_LT(e.equilibrium, 1e-8);
}

INSTANTIATE_TEST_SUITE_P(V3OneBody, ContactPatchOneBody,
                         ::testing::Values(patch(4, 5, 1, "symmetric", true), patch(5, 4, 1, "symmetric", true),
                                           patch(4, 5, 2, "symmetric", true), patch(5, 4, 2, "symmetric", true),
                                           // Matching divisions: every interface node has a twin.
                                           patch(4, 4, 1, "symmetric", true), patch(4, 4, 2, "symmetric", true),
                                           // The upper block of a second, ten times softer material that
                                           // spreads sideways as much as the lower block (ν_u below).
                                           soft_upper(patch(4, 5, 1, "symmetric", true)),
                                           soft_upper(patch(5, 4, 2, "symmetric", true)),
                                           soft_upper(patch(4, 4, 2, "symmetric", true)),
                                           // The same E_u with ν = 0.3: the blocks slide on each other, an
                                           // exact answer of small sliding.
                                           sliding_soft_upper(patch(4, 5, 1, "symmetric", true)),
                                           sliding_soft_upper(patch(5, 4, 2, "symmetric", true))),
                         [](const auto& p) { return contact_patch_name(p.param); });

// One body of two cell types: the upper block recombined (Quad4, Quad9, or Quad8 with the incomplete second
// order), the lower one triangles (Tri3, Tri6), held together by the self-contact of the interface.
namespace {
ContactPatchCase mixed_one_body(int n1, int n2, int order, bool serendipity = false) {
  ContactPatchCase c = patch(n1, n2, order, "symmetric", true);
  c.quad_blocks = {"upper"};
  c.serendipity = serendipity;
  return c;
}
}  // namespace

INSTANTIATE_TEST_SUITE_P(V3OneBodyMixed, ContactPatchOneBody,
                         ::testing::Values(mixed_one_body(4, 5, 1), mixed_one_body(5, 4, 2),
                                           mixed_one_body(4, 5, 2, true)),
                         [](const auto& p) { return contact_patch_name(p.param); });

// Small sliding ([[contact]] geometry = "reference", contact/contact_geometry.hpp): the linearised gap
// g(X) + A u with the projections and normals of the undeformed interface holds the exact solution too
// (both sides of the interface move alike: u_y is the same at y = 1, u_x the same function of x), so the
// patch test passes as in the current geometry, to the same tolerances; and the geometry fixed point ends
// at its second iteration, whose rows are the first's (nothing in them depends on the iterate).
TEST(ContactPatch2DReference, UniformPressureExactDisplacementsAndTwoGeometryIterations) {
  for (ContactPatchCase pc : {patch(4, 5, 1, "symmetric"), patch(5, 4, 2, "symmetric"), patch(4, 5, 1, "one-pass"),
                              patch(5, 4, 2, "one-pass")}) {
    pc.geometry = "reference";
    const auto solved = contact_patch_solve(pc);
    const ContactPatchErrors e = contact_patch_errors(pc, *solved);
    // The reported gap is the linearised one, g(X) + ν̄·(u − u_opposite): zero at every node that projects
    // (the interface moves down by (1 − ν²) p, which a wrong sign or a missing term would show).
    double max_gap = 0.0;
    int projected = 0;
    for (const symcontact::ContactSideResult& side : solved->contact.at(0).sides)
      for (symcontact::Index k = 0; k < side.gap.size(); ++k)
        if (std::isfinite(side.gap[k])) {
          max_gap = std::max(max_gap, std::abs(side.gap[k]));
          ++projected;
        }
    EXPECT_GT(projected, 0) << contact_patch_name(pc);
    EXPECT_LT(max_gap, 1e-12) << contact_patch_name(pc);
    std::printf("  %s: displacement error %.2e, pressure error %.2e, max |gap| %.1e, %d geometry / %d IPOPT iterations\n",
                contact_patch_name(pc).c_str(), e.displacement, e.pressure, max_gap, e.geometry_iterations,
                e.ipopt_iterations);
    EXPECT_LT(e.pressure, 1e-6) << contact_patch_name(pc);
    EXPECT_LT(e.displacement, 1e-8) << contact_patch_name(pc);
    EXPECT_EQ(e.geometry_iterations, 2) << contact_patch_name(pc);
    // The second iteration solves the first subproblem again: its change is the subproblem's round-off
    // (measured 0: the closing polish solves both exactly alike).
    ASSERT_EQ(solved->report.change_history.size(), 2u) << contact_patch_name(pc);
    std::printf("    change at geometry iteration 2: %.1e\n", solved->report.change_history[1]);
    EXPECT_LT(solved->report.change_history[1], 1e-10) << contact_patch_name(pc);
  }
}
