// 2D ironing (issue #5; Yang, Laursen and Meng 2005; examples/ironing_2d): a stiff Neo-Hookean half-ring
// die pressed 1.4 into a soft Neo-Hookean slab in 10 steps, then slid 4 along it in 100 — finite strain
// and large sliding (each slab point passes under many die facets). Frictionless, on a coarser mesh than
// the example (slab h = 0.25, die h = 0.12, to keep the test near a minute). Asserted:
//  - every one of the 110 steps converges (solve_case throws otherwise);
//  - penetration: the most negative nodal gap of either surface, over all steps, is above −2 % of the
//    slab element size (the weak, integrated constraints let single nodes sink by O(h²/R));
//  - global equilibrium at every step: the die's support reaction balances the slab's to 1e-8 of it
//    (no external loads: the contact forces are equal and opposite);
//  - no spurious oscillation in steady sliding (steps 30–110): the vertical reaction's second difference
//    stays below 1 % of the reaction (facet-to-facet jumps of node-to-segment methods are larger);
//  - the die is pushed up (R_y on its supports < 0) and the vertical force grows while pressing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "support/solve_case.hpp"

using namespace symcontact;
using namespace symcontact::testing;

TEST(Ironing2D, FrictionlessRunsThroughEveryStepWithoutPenetrationOrOscillation) {
  const std::string examples = std::string(SYMCONTACT_EXAMPLES) + "/ironing_2d";
  const std::string dir = ::testing::TempDir() + "ironing2d/";
  const double hs = 0.25, hd = 0.12;
  char head[96];
  std::snprintf(head, sizeof head, "hs = %g;\nhd = %g;\n", hs, hd);
  write_text(dir, "ironing.geo", std::string(head) + "Include \"" + examples + "/ironing.geo\";\n");
  std::ifstream in(examples + "/ironing.toml");
  std::string toml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto c = solve_case(toml, dir);
  ASSERT_EQ(c->reactions.size(), 110u);

  // Reactions per body (each body's conditions summed).
  const auto& boundaries = c->model->dirichlet_boundaries();
  const int die = c->model->body_index("die");
  std::vector<Eigen::Vector2d> r_die, r_slab;
  for (const auto& step : c->reactions) {
    Eigen::Vector2d d = Eigen::Vector2d::Zero(), s = Eigen::Vector2d::Zero();
    for (std::size_t k = 0; k < step.size(); ++k) (boundaries[k].body == die ? d : s) += step[k].head<2>();
    r_die.push_back(d);
    r_slab.push_back(s);
  }
  double worst_balance = 0.0, worst_wiggle = 0.0, worst_gap = 0.0;
  for (std::size_t k = 0; k < r_die.size(); ++k) {
    worst_balance = std::max(worst_balance, (r_die[k] + r_slab[k]).norm() / r_die[k].norm());
    if (k >= 30 && k + 1 < r_die.size())
      worst_wiggle = std::max(worst_wiggle, std::abs(r_die[k + 1].y() - 2 * r_die[k].y() + r_die[k - 1].y()) /
                                                std::abs(r_die[k].y()));
    for (const auto& pair : c->history[k]) {
      for (const auto& side : pair.sides) {
        for (Index n = 0; n < side.gap.size(); ++n) {
          if (std::isfinite(side.gap[n])) worst_gap = std::min(worst_gap, side.gap[n]);
        }
      }
    }
    if (k > 0 && k < 10) {
      EXPECT_LT(r_die[k].y(), r_die[k - 1].y()) << "step " << k + 1;
    }
  }
  std::printf("ironing (frictionless, slab h = %.2f): die reaction at step 10 (%.4f, %.4f), step 110 (%.4f, %.4f)\n",
              hs, r_die[9].x(), r_die[9].y(), r_die.back().x(), r_die.back().y());
  std::printf("  worst |R_die + R_slab| / |R_die| = %.2e, worst steady second difference / R_y = %.2e, "
              "deepest penetration = %.3e (%.2f %% of h)\n",
              worst_balance, worst_wiggle, -worst_gap, -100 * worst_gap / hs);
  EXPECT_LT(r_die.back().y(), 0.0);
  EXPECT_LT(worst_balance, 1e-8);
  EXPECT_LT(worst_wiggle, 0.01);
  EXPECT_GT(worst_gap, -0.02 * hs);
}
