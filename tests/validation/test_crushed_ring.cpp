// The self-contact showcase (issue #6; examples/crushed_ring_2d): a Neo-Hookean ring (radii 0.8 and 1,
// plane strain) crushed between two pads — the outer arcs within 15° of its poles, moved towards each
// other by 0.84 each in 40 steps — until its bore closes and the inner surface touches itself over a
// zone. The bore is one contact surface paired with itself. Coarser mesh than the example (nl = 20,
// ns = 6, nr = 2). The mesh is mirror-symmetric about x = 0 and y = 0 node for node (ring.geo), and so
// is the loading. Asserted at every step:
//  - no penetration, as the method imposes it: every weak gap g_i = ∫ θ φ_i (talk eq. 10, gap_constraints.hpp)
//    of the last step, divided by its support ∫ φ_i, is above −1e-9 (× the ring's outer radius 1);
//  - and node by node: the most negative nodal gap of the bore, over all steps, is above −3 % of the wall
//    thickness t = 0.2. The integrated constraints let single nodes sink where the gap varies fast across
//    an element: here the deepest is the pads' corner, where the contact zone ends at a kink of the bore
//    (measured: 2.6 % of t on this mesh, 0.7 % on the example's);
//  - mirror symmetry: u(−x, y) = (−u_x, u_y)(x, y) and u(x, −y) = (u_x, −u_y)(x, y) at every node pair,
//    to 1e-5 of max |u|. The mesh is symmetric to Gmsh's round-off (~3e-9) and every step of the
//    algorithm is symmetric, but the geometry fixed point stops once an iteration changes u by less than
//    1e-6 of it (contact_solver.hpp), so u is only defined to about that (measured: 6e-7);
//  - equilibrium: no external load but the pads, so R_top + R_bottom = 0 to 1e-8 of |R_top|; and, once the
//    bore is closed, its self-contact forces sum to zero (action and reaction within one surface) to 1e-8
//    of Σ|f_k|;
// and the bore touches itself: from some step before the last on, the contact force on its upper half
// exceeds 1 % of the pad force; at the end — the contact force on the upper half of the bore pushes
// it up with at least 10 % of the pad force (measured: see the printed line).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "support/solve_case.hpp"

using namespace symcontact;
using namespace symcontact::testing;

namespace {

/// The node of `x` (dim × n) nearest to p; its distance in `dist`.
Index nearest_node(const Eigen::MatrixXd& x, const Eigen::Vector2d& p, double& dist) {
  Index best = -1;
  dist = INFINITY;
  for (Index a = 0; a < x.cols(); ++a) {
    const double d = (x.col(a).head<2>() - p).norm();
    if (d < dist) {
      dist = d;
      best = a;
    }
  }
  return best;
}

}  // namespace

TEST(CrushedRing2D, BoreTouchesItselfWithoutPenetrationKeepingMirrorSymmetryAndEquilibrium) {
  const std::string examples = std::string(SYMCONTACT_EXAMPLES) + "/crushed_ring_2d";
  const std::string dir = test_temp_dir("crushed_ring_2d");
  const int nl = 20, ns = 6, nr = 2;
  const double t = 0.2;  // wall thickness
  write_text(dir, "ring.geo",
             "nl = " + std::to_string(nl) + ";\nns = " + std::to_string(ns) + ";\nnr = " + std::to_string(nr) +
                 ";\nInclude \"" + examples + "/ring.geo\";\n");
  std::ifstream in(examples + "/ring.toml");
  const std::string toml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto t0 = std::chrono::steady_clock::now();
  auto c = solve_case(toml, dir);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(c->history.size(), 40u);

  // Mirror node pairs (the mesh is symmetric to round-off).
  const Mesh& mesh = c->model->bodies()[0]->mesh;
  const DofMap& dofs = c->model->dofs();
  std::vector<Index> mirror_x(mesh.num_nodes()), mirror_y(mesh.num_nodes());
  for (Index a = 0; a < mesh.num_nodes(); ++a) {
    double d1, d2;
    mirror_x[a] = nearest_node(mesh.x, Eigen::Vector2d(-mesh.x(0, a), mesh.x(1, a)), d1);
    mirror_y[a] = nearest_node(mesh.x, Eigen::Vector2d(mesh.x(0, a), -mesh.x(1, a)), d2);
    ASSERT_LT(std::max(d1, d2), 1e-8) << "node " << a << ": the mesh is not mirror-symmetric";
  }
  // The reactions' order is that of the problem file: plate_top, then plate_bottom.
  const auto& boundaries = c->model->dirichlet_boundaries();
  ASSERT_EQ(boundaries.size(), 2u);
  // The contact force on the upper half of the bore (surface nodes above y = 0, reference positions).
  const ContactSurface& bore = c->model->contacts().surfaces[c->contact[0].sides[0].surface];
  auto upper_force = [&](const ContactSideResult& side) {
    Eigen::Vector2d f = Eigen::Vector2d::Zero();
    for (Index n = 0; n < bore.num_nodes(); ++n)
      if (bore.X(1, n) > 0) f += side.force.col(n).head<2>();
    return f;
  };
  double worst_gap = 0.0, worst_balance = 0.0, worst_action = 0.0;
  int first_contact = -1;
  for (std::size_t k = 0; k < c->history.size(); ++k) {
    const auto& side = c->history[k][0].sides[0];
    for (Index n = 0; n < side.gap.size(); ++n)
      if (std::isfinite(side.gap[n])) worst_gap = std::min(worst_gap, side.gap[n]);
    const Eigen::VectorXd& rt = c->reactions[k][0];
    const Eigen::VectorXd& rb = c->reactions[k][1];
    worst_balance = std::max(worst_balance, (rt + rb).norm() / rt.norm());
    if (first_contact < 0 && upper_force(side).y() > 0.01 * rt.norm()) first_contact = static_cast<int>(k) + 1;
    if (first_contact > 0)
      worst_action = std::max(worst_action, side.force.rowwise().sum().norm() / side.force.colwise().norm().sum());
  }
  // Weak gaps of the last step, per unit support.
  const auto& lin = c->report.linearization;
  double worst_weak = 0.0;
  for (Index r = 0; r < c->constraint_values.size(); ++r)
    worst_weak = std::min(worst_weak, c->constraint_values[r] / lin.row_support[r]);
  // Symmetry of the final displacement.
  double worst_sym = 0.0, umax = 0.0;
  for (Index a = 0; a < mesh.num_nodes(); ++a) {
    const Eigen::Vector2d u(c->u[dofs.dof(0, a, 0)], c->u[dofs.dof(0, a, 1)]);
    const Eigen::Vector2d ux(c->u[dofs.dof(0, mirror_x[a], 0)], c->u[dofs.dof(0, mirror_x[a], 1)]);
    const Eigen::Vector2d uy(c->u[dofs.dof(0, mirror_y[a], 0)], c->u[dofs.dof(0, mirror_y[a], 1)]);
    worst_sym = std::max({worst_sym, (ux - Eigen::Vector2d(-u.x(), u.y())).norm(),
                          (uy - Eigen::Vector2d(u.x(), -u.y())).norm()});
    umax = std::max(umax, u.norm());
  }
  const auto& last = c->contact[0];
  const Eigen::Vector2d f_upper = upper_force(last.sides[0]);
  const double pad = std::abs(c->reactions.back()[0][1]);
  std::printf("crushed ring (nl %d, ns %d, nr %d; %td nodes): bore first closed at step %d of 40; at step 40 pad "
              "force %.6e, contact force on the upper half of the bore (%.3e, %.6e) = %.3f of it, contact length "
              "%.4f, max pressure %.4e\n",
              nl, ns, nr, static_cast<std::ptrdiff_t>(mesh.num_nodes()), first_contact, pad, f_upper.x(),
              f_upper.y(), f_upper.y() / pad, last.contact_measure, last.max_pressure);
  std::printf("  most negative weak gap / support %.2e; deepest nodal penetration %.3e (%.2f %% of t); mirror symmetry max |u - S u(S x)| / "
              "max |u| = %.2e; worst |R_top + R_bottom| / |R_top| = %.2e; worst |sum f_k| / sum |f_k| = %.2e; %.1f s\n",
              worst_weak, -worst_gap, -100 * worst_gap / t, worst_sym / umax, worst_balance, worst_action, secs);
  EXPECT_GT(first_contact, 0) << "the bore never touched itself";
  EXPECT_LT(first_contact, 40) << "the bore should touch itself before the last step";
  EXPECT_GT(worst_weak, -1e-9);
  EXPECT_GT(worst_gap, -0.03 * t);
  EXPECT_LT(worst_sym, 1e-5 * umax);
  EXPECT_LT(worst_balance, 1e-8);
  EXPECT_LT(worst_action, 1e-8);
  EXPECT_GT(f_upper.y(), 0.1 * pad);
  EXPECT_LT(std::abs(f_upper.x()), 1e-6 * f_upper.y());
}
