// V3 contact patch test with Coulomb friction, 2D (VALIDATION.md): the blocks of test_contact_patch.cpp
// (tests/support/contact_patch_case.hpp) with friction = "coulomb", μ = 0.3 on the interface. With
// identical materials both blocks expand sideways alike, u_x = ν (1 + ν) p x / E on both sides of the
// interface: there is no relative slip, the regularised friction term has a zero gradient there, and the
// answer is the frictionless one, exactly: uniform contact pressure p, zero tangential traction, exact
// linear displacements. Non-matching meshes (4, 5) and (5, 4), P1 and P2, symmetric and one-pass.
#include <gtest/gtest.h>

#include <cstdio>

#include "support/contact_patch_case.hpp"

using namespace symcontact::testing;

namespace {

class ContactPatchFriction2D : public ::testing::TestWithParam<ContactPatchCase> {};

ContactPatchCase patch(int n1, int n2, int order, const char* mode) {
  ContactPatchCase c;
  c.n1 = n1;
  c.n2 = n2;
  c.order = order;
  c.mode = mode;
  c.mu = 0.3;
  return c;
}

}  // namespace

TEST_P(ContactPatchFriction2D, UniformPressureExactDisplacementsNoShear) {
  const ContactPatchCase pc = GetParam();
  const ContactPatchErrors e = contact_patch_errors(pc);
  std::printf("  (%d, %d) P%d %s mu = %.1f: displacement error %.2e, pressure error %.2e, tangential traction %.2e p,"
              " %d Coulomb / %d geometry / %d IPOPT iterations\n",
              pc.n1, pc.n2, pc.order, pc.mode.c_str(), pc.mu, e.displacement, e.pressure, e.tangential,
              e.coulomb_iterations, e.geometry_iterations, e.ipopt_iterations);
  EXPECT_LT(e.pressure, 1e-6);
  EXPECT_LT(e.displacement, 1e-8);
  EXPECT_LT(e.tangential, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(V3, ContactPatchFriction2D,
                         ::testing::Values(patch(4, 5, 1, "one-pass"), patch(5, 4, 1, "one-pass")),
                         [](const auto& p) { return contact_patch_name(p.param); });

// The symmetric cases and one-pass P2 need the active-set polish of a non-quadratic energy (friction): it
// is accepted when the stationarity error stays at its level (active_set_polish.cpp), and it closes the
// interior point's barrier offset (~1e-5 here otherwise).
INSTANTIATE_TEST_SUITE_P(V3Closing, ContactPatchFriction2D,
                         ::testing::Values(patch(4, 5, 1, "symmetric"), patch(5, 4, 1, "symmetric"),
                                           patch(4, 5, 2, "symmetric"), patch(5, 4, 2, "symmetric"),
                                           patch(4, 5, 2, "one-pass"), patch(5, 4, 2, "one-pass")),
                         [](const auto& p) { return contact_patch_name(p.param); });
