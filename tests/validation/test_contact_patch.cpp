// V3 contact patch test, 2D (VALIDATION.md): two unit blocks pressed together through a non-matching
// (or matching) interface must transmit a uniform pressure exactly. Lower block [0,1]×[0,1], upper
// [0,1]×[1,2], n1 and n2 divisions per side; E = 1, ν = 0.3, plane strain; bottom u_y = 0 and u_x = 0
// at (0, 0); u_x = 0 at (0, 2) removes the upper block's free sliding; pressure p = 0.01 on top.
// Exact: σ_yy = −p, contact pressure p, u_y = −(1 − ν²) p y / E, u_x = ν (1 + ν) p x / E.
// The same blocks as ONE body whose two blocks touch at y = 1 (their own nodes there, coincident where the
// divisions meet), held together by a self-contact on the group holding both faces: the same exact answer
// (V3OneBody: the mesh checks allow the cut and the two pieces, mesh/mesh_topology.hpp).
// The case itself (geometry, problem file, errors) is tests/support/contact_patch_case.hpp, shared with
// the frictional variant (test_contact_patch_friction.cpp).
#include <gtest/gtest.h>

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
  const ContactPatchErrors e = contact_patch_errors(pc);
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

class ContactPatchOneBody : public ::testing::TestWithParam<ContactPatchCase> {};

TEST_P(ContactPatchOneBody, UniformPressureAndExactDisplacements) {
  const ContactPatchCase pc = GetParam();
  const auto solved = contact_patch_solve(pc);
  ASSERT_EQ(solved->model->bodies().size(), 1u);
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
                                           patch(4, 4, 1, "symmetric", true), patch(4, 4, 2, "symmetric", true)),
                         [](const auto& p) { return contact_patch_name(p.param); });
