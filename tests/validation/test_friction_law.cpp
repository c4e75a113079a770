// V4 (VALIDATION.md): the regularised friction law, on the block of examples/friction_block — an elastic
// block (E = 1, ν = 0, W = 4, H = 1) pressed on a rigid plane by p = 0.01 on its top, then its top
// dragged sideways by U in load steps, with Coulomb friction μ = 0.3 (regularised Tresca with τ = μ p
// at the fixed point).
//
//  a. The law at every contact node and every step: σ_T/σ_n (the nodal tangential traction over the
//     nodal pressure, both recovered from the nodal contact forces) against μ s / sqrt(s² + α²), s the
//     node's slip increment of the step; the traction opposes the slip. Writes the pairs to a CSV for
//     tools/plot_friction_law.py (docs/img/friction_law.png).
//  b. The homogeneous limits of the unregularised law (α = 1e-7): in gross slip the tangential reaction
//     on the top is μ × the normal one; with the shear carried by the laterals, stick until
//     U* = μ p H / G and slip U − U* beyond.
//  c. Convergence in α: ‖u_α − u_ref‖∞ / ‖u_ref‖∞ falls at least linearly with α.
//  d. Tresca and Coulomb agree: Tresca with the nodal threshold τ = μ p of the converged Coulomb
//     pressure reproduces the Coulomb displacements; and with the shear carried by the laterals (uniform
//     pressure) a constant Tresca τ = μ p through the problem file does too.
//  e. Where the thresholds are updated (CoulombUpdate): following the interior point's iterates reaches the
//     fixed point of updating them between solves, in fewer solves.
//  f. Thresholds followed by the interior point are the loop's fixed point (a pad dragged on a cylinder).
//  g. The predictor of a second equal step from the unloaded start (u and τ doubled) is its answer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

#include "support/pad_geo.hpp"
#include "support/solve_case.hpp"
#include "symcontact/app/run.hpp"
#include "symcontact/model/problem_reader.hpp"

using namespace symcontact;
using namespace symcontact::testing;

namespace {

const std::string kBlockGeo = std::string(SYMCONTACT_EXAMPLES) + "/friction_block/block.geo";
const double kW = 4.0, kH = 1.0, kE = 1.0, kG = kE / 2.0;  // ν = 0: G = E / 2
const double kP = 0.01, kMu = 0.3;
const double kUStar = kMu * kP * kH / kG;  // 6.0e-3

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string list(const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + num(v[i]);
  return s + "]";
}

/// The V4 block, step k dragging the top to U[k] (U[0] = 0: the press).
struct BlockCase {
  int n = 8;                      ///< elements through the height (block.geo)
  std::string friction = "coulomb";
  double mu = kMu;
  double tau = 0.0;               ///< Tresca only
  double alpha = 2e-4;
  std::vector<double> U;
  /// The laterals carry the shear of the homogeneous solution: traction (0, ±G min(U, U*)/H) on right
  /// and left (see ShearCarriedByTheLateralsStickThenSlip).
  bool shear_laterals = false;
  double coulomb_tolerance = 1e-6;
  std::string coulomb_update;  ///< [contact_solver] coulomb_update; empty: the default
  std::string extra_body;      ///< more [[body.*]] tables of the block (TOML)
};

std::string block_toml(const BlockCase& b) {
  std::ostringstream t;
  t << "[problem]\ndimension = 2\nmodel = \"plane_strain\"\norder = 1\n\n"
    << "[steps]\nload_factors = " << list(b.U) << "\n\n"
    << "[[body]]\nname = \"block\"\nmesh = \"block.geo\"\ngroup = \"block\"\n"
    << "material = { E = " << num(kE) << ", nu = 0.0 }\n"
    << "[[body.pressure]]\nboundary = \"top\"\npressure = " << num(kP) << "\nfactors = "
    << list(std::vector<double>(b.U.size(), 1.0)) << "\n"
    << "[[body.dirichlet]]\nboundary = \"top\"\nux = 1.0\n" << b.extra_body;
  if (b.shear_laterals) {
    std::vector<double> T;
    for (double u : b.U) T.push_back(kG * std::min(u, kUStar) / kH);
    t << "[[body.traction]]\nboundary = \"right\"\ntraction = [0.0, 1.0]\nfactors = " << list(T) << "\n"
      << "[[body.traction]]\nboundary = \"left\"\ntraction = [0.0, -1.0]\nfactors = " << list(T) << "\n";
  }
  t << "\n[[contact]]\nname = \"floor\"\na = \"block.bottom\"\nfriction = \"" << b.friction << "\"\n";
  if (b.friction == "coulomb") t << "mu = " << num(b.mu) << "\n";
  else t << "tau = " << num(b.tau) << "\n";
  t << "alpha = " << num(b.alpha) << "\n"
    << "[contact.obstacle]\ntype = \"plane\"\npoint = [0.0, 0.0]\nnormal = [0.0, 1.0]\n\n"
    << "[contact_solver]\ncoulomb_tolerance = " << num(b.coulomb_tolerance) << "\n";
  if (!b.coulomb_update.empty()) t << "coulomb_update = \"" << b.coulomb_update << "\"\n";
  return t.str();
}

std::string case_dir(const std::string& name, int n) {
  const std::string dir = test_temp_dir("v4_" + name);
  write_text(dir, "block.geo", "n = " + std::to_string(n) + ";\nInclude \"" + kBlockGeo + "\";\n");
  return dir;
}

std::unique_ptr<SolvedCase> solve_block(const BlockCase& b, const std::string& name) {
  return solve_case(block_toml(b), case_dir(name, b.n));
}

/// U from 0 by `du` up to `u_end` (inclusive), after the press.
std::vector<double> ramp(double du, double u_end) {
  std::vector<double> U = {0.0};
  for (int k = 1; k * du <= u_end * (1 + 1e-12); ++k) U.push_back(k * du);
  return U;
}

double law(double s, double alpha) { return kMu * s / std::sqrt(s * s + alpha * alpha); }

struct LawCheck {
  double max_inside = 0.0, max_end = 0.0;  ///< max |σ_T/σ_n + μ s/r| over interior / end nodes
  double s_inside = 0.0, s_end = 0.0;      ///< the slips where they occur
  int step_inside = -1, step_end = -1;
  double max_ratio = 0.0;                  ///< max |σ_T/σ_n| over all nodes and steps
  int node_steps = 0, slipping = 0, wrong_sign = 0;
  int near_threshold = 0;  ///< node-steps whose traction is within 5 % of the threshold (s ≥ 3 α)
  int mislabelled = 0;     ///< node-steps labelled slip where |t|/τ = |s|/r < kSlipRatio, or the reverse
};

/// Solves the V4 block at `n` with `alpha` and the drag steps `U`, checks the law node by node and
/// step by step, and writes the CSV (`csv_path` non-empty).
LawCheck check_law(int n, double alpha, const std::vector<double>& U, double coulomb_tolerance,
                   const std::string& csv_path) {
  BlockCase b;
  b.n = n;
  b.alpha = alpha;
  b.U = U;
  b.coulomb_tolerance = coulomb_tolerance;
  auto c = solve_block(b, "law_n" + std::to_string(n));
  LawCheck r;
  EXPECT_EQ(c->history.size(), b.U.size());
  const ContactSurface& surf = c->model->contacts().surfaces[c->history[0][0].sides[0].surface];
  std::ofstream csv;
  if (!csv_path.empty()) {
    csv.open(csv_path);
    csv << "# V4 regularised friction law: mu = " << num(kMu) << ", alpha = " << num(b.alpha) << ", n = " << n
        << "\n"
        << "step,U,node,x,slip,ratio,pressure,tangential,end,du\n";
  }
  for (std::size_t step = 0; step < c->history.size(); ++step) {
    const ContactSideResult& side = c->history[step][0].sides[0];
    for (Index k = 0; k < side.pressure.size(); ++k) {
      const double X = surf.X(0, k);
      const bool end = std::abs(X) < 1e-12 || std::abs(X - kW) < 1e-12;
      EXPECT_GE(side.status[k], 1) << "node " << k << " open at step " << step;  // p stays > 0 all along
      const double p = side.pressure[k], t = side.tangential(0, k), s = side.slip(0, k);
      if (!(p > 0.0)) continue;
      const double ratio = t / p;
      const double err = std::abs(ratio + law(s, alpha));  // σ_T = −τ s / r: opposes the slip
      if (std::abs(s) > 1e-3 * alpha && t * s > 0) ++r.wrong_sign;
      r.max_ratio = std::max(r.max_ratio, std::abs(ratio));
      if (end && err > r.max_end) {
        r.max_end = err;
        r.step_end = static_cast<int>(step);
        r.s_end = s;
      }
      if (!end && err > r.max_inside) {
        r.max_inside = err;
        r.step_inside = static_cast<int>(step);
        r.s_inside = s;
      }
      r.node_steps++;
      if (side.status[k] == 2) ++r.slipping;
      if (std::abs(s) >= 3 * alpha) ++r.near_threshold;
      if ((side.status[k] == 2) != (std::abs(law(s, alpha)) / kMu >= kSlipRatio)) ++r.mislabelled;
      if (csv.is_open())
        csv << step << "," << num(b.U[step]) << "," << k << "," << num(X) << "," << num(s) << "," << num(-ratio)
            << "," << num(p) << "," << num(t) << "," << (end ? 1 : 0) << ","
            << num(step > 0 ? side.x(0, k) - c->history[step - 1][0].sides[0].x(0, k) : 0.0) << "\n";
    }
  }
  std::printf("  V4 law, n = %d, alpha = %g, Coulomb tolerance %g: %d node-steps (%d slipping); "
              "max |sigma_T/sigma_n + mu s/r| / mu: inside %.3e (step %d, s/alpha = %.2f), ends %.3e (step %d, "
              "s/alpha = %.2f); max |sigma_T/sigma_n| / mu = %.4f\n",
              n, alpha, coulomb_tolerance, r.node_steps, r.slipping, r.max_inside / kMu, r.step_inside,
              r.s_inside / alpha, r.max_end / kMu, r.step_end, r.s_end / alpha, r.max_ratio / kMu);
  return r;
}

/// The drag of the law test: steps of 5e-4 (2.5 α for α = 2e-4) to 8e-3, past U* = 6e-3, then two of
/// 2e-3 (10 α).
std::vector<double> law_steps() {
  std::vector<double> U = ramp(5e-4, 8e-3);
  U.push_back(1.0e-2);
  U.push_back(1.2e-2);
  return U;
}

}  // namespace

// ---------------------------------------------------------------------------------------------------
// a. The regularised law, node by node.
//
// What the library computes at a node k of the bottom (P1, obstacle): the nodal friction force is
// f_k = −∫ N_k τ_h s_h / sqrt(s_h² + α²) (3-point Gauss per facet), with τ_h the linear interpolant of
// the nodal thresholds τ_j = μ p_j, p_j = −F_j·n_j / A_j the lumped nodal pressure; the reported
// traction is f_k / A_k and the reported slip the weak average ∫ N_k s_h / A_k. So σ_T/σ_n at the node
// is a weighted mean of μ s/r over the two facets around it, weighted by N_k τ_h / (A_k τ_k), and it
// equals μ s_k/r_k only where p and s are uniform over those facets. At an end node the weights are
// (2 τ_0 + τ_1) / (3 τ_0) — not 1 when the pressure varies — and the V4 block's pressure varies
// strongly at its ends (the drag tilts it: 0.0023 at the trailing end, 0.021 at the leading one).
//
// That was the first implementation, measured at 4.7e-2 μ inside and 0.58 μ at the end nodes (|σ_T| up
// to 1.58 μ σ_n, outside the Coulomb cone), unchanged by mesh (n = 4 / 8 / 16) and Coulomb tolerance.
// The solver now integrates friction node by node (j = Σ_k A_k τ_k η_α(s_k), the node's own slip and
// threshold; contact/contact_points.hpp nodal_contact_points) and decomposes the nodal force along the
// interface normal the constraints use; then σ_T/σ_n = μ s_k/r_k at the Coulomb fixed point, node by
// node. Measured now: 4.0e-6 μ inside, 4.8e-6 μ at the ends.
// ---------------------------------------------------------------------------------------------------
TEST(V4FrictionLaw, TractionOverPressureFollowsTheRegularisedLawAtEveryNodeAndStep) {
  const LawCheck r = check_law(8, 2e-4, law_steps(), 1e-6, "");
  EXPECT_EQ(r.wrong_sign, 0);
  EXPECT_LT(r.max_inside, 1e-3 * kMu);
  EXPECT_LT(r.max_end, 1e-2 * kMu);
  EXPECT_LE(r.max_ratio, kMu * (1 + 1e-6));  // inside the Coulomb cone
}

TEST(V4FrictionLaw, TractionOpposesSlipAndLawPointsAreWritten) {
  const std::string dir = test_temp_dir("v4_law");
  const std::string csv = dir + "friction_law.csv";
  const LawCheck r = check_law(8, 2e-4, law_steps(), 1e-6, csv);
  std::printf("  wrote %s (plot: python3 tools/plot_friction_law.py %s docs/img/friction_law.png)\n", csv.c_str(),
              csv.c_str());
  EXPECT_EQ(r.node_steps, 33 * static_cast<int>(law_steps().size()));  // every bottom node in contact throughout
  EXPECT_EQ(r.wrong_sign, 0);
  // The label follows the law: slip where the traction has reached the threshold (|s| ≥ 22.3 α); the drag's
  // steps (2.5 α to 10 α) bring many node-steps near it (|t| ≥ 0.95 τ) and, at 10 α, to 0.995 τ: stick.
  EXPECT_GT(r.near_threshold, 0);
  EXPECT_EQ(r.mislabelled, 0);
}

// The investigation above: the error against the mesh and the Coulomb tolerance (~20 s).
TEST(V4FrictionLaw, DISABLED_ErrorOfTheLawAgainstMeshAndCoulombTolerance) {
  for (int n : {4, 8, 16}) check_law(n, 2e-4, law_steps(), 1e-6, "");
  check_law(8, 2e-4, law_steps(), 1e-9, "");
}

// ---------------------------------------------------------------------------------------------------
// b. Homogeneous limits of the unregularised law (α = 1e-7, far below every slip increment).
//
// Free laterals: the shear is not homogeneous (the block tilts its pressure to balance the moment of
// the drag, and stress concentrates at the ends), so the stick limit U* is not exact, but in gross slip
// every node slides and the global balance is exact: the tangential reaction on the top equals the
// total friction force μ Σ_k A_k p_k s_k/r_k → μ × the normal reaction p W.
//
// Laterals carrying the shear: imposing u_x = U y/H on them is NOT the right condition. It is the
// stick solution, but it pins the bottom corners (y = 0) at u_x = 0, so the block can never slide as
// a whole; the homogeneous solution with slip s is u_x = s + (U − s) y/H, whose lateral values depend on
// the unknown s. The homogeneous state is a Neumann one instead: with ν = 0, σ_xx = 0 and σ_xy = G γ
// uniform, so the laterals carry the traction (0, ±σ_xy), σ_xy = G min(U, U*)/H (right +, left −).
// With it the exact solution of the unregularised problem is homogeneous: stick (s = 0, bottom
// traction G U/H < μ p) for U < U*, and for U > U* slip s = U − U* with traction μ p. The tractions
// are built from U* = μ p H / G, so this checks that the solver reproduces the exact solution of
// that boundary-value problem — no slip below U*, the slip U − U* and the traction μ p above — not
// that it predicts U* on its own (the free-lateral block does that, inexactly).
// ---------------------------------------------------------------------------------------------------
static void check_gross_slip(int n) {
  BlockCase b;
  b.n = n;
  b.alpha = 1e-7;
  b.U = {0.0, 4e-3, 8e-3, 1.2e-2, 1.6e-2};  // U* = 6e-3 (homogeneous estimate)
  auto c = solve_block(b, "gross_slip");
  const ContactPairResult& r = c->contact[0];
  // Reaction of the top's Dirichlet condition (u_x held): Σ ∇E over its DOFs.
  const FixedDofs fixed = c->model->fixed_dofs(c->model->num_steps() - 1);
  VectorXd g = VectorXd::Zero(c->u.size());
  c->model->energy().add_gradient(c->u, g);
  const std::vector<Eigen::VectorXd> reactions = c->model->reactions(fixed, g);
  ASSERT_EQ(reactions.size(), 1u);
  const double N = -r.normal_force[1];  // the floor pushes up: the force on the block is +y
  const double T = std::abs(reactions[0][0]);
  std::printf("  gross slip (n = %d, alpha = 1e-7, U = %.3g): normal reaction %.10f (p W = %.10f), tangential reaction on "
              "the top %.10f, friction force %.10f; T / (mu N) - 1 = %.3e; slip of the last step from %.6e to %.6e\n",
              n, b.U.back(), -N, kP * kW, T, r.tangential_force[0], T / (kMu * std::abs(N)) - 1,
              c->contact[0].sides[0].slip.row(0).minCoeff(), c->contact[0].sides[0].slip.row(0).maxCoeff());
  EXPECT_NEAR(T, kMu * std::abs(N), 1e-3 * kMu * std::abs(N));
  EXPECT_NEAR(T, kMu * kP * kW, 1e-3 * kMu * kP * kW);
  // Global balance, to the optimiser's tolerance (measured 5e-6 vertically, 5e-5 horizontally at n = 4).
  EXPECT_NEAR(std::abs(N), kP * kW, 1e-4 * kP * kW);
  EXPECT_NEAR(std::abs(r.tangential_force[0]), T, 1e-4 * T);
  for (Index k = 0; k < r.sides[0].status.size(); ++k) EXPECT_EQ(r.sides[0].status[k], 2) << "node " << k;
}

TEST(V4FrictionLaw, GrossSlipTangentialReactionIsMuTimesNormal) { check_gross_slip(4); }

// The same on the n = 8 mesh: IPOPT stops with Restoration_Failed at geometry iteration 1 of a drag
// step past U = 4e-3 (the press and U = 4e-3 solve) — the regularised stick stiffness τ/α = 3e4 against
// E = 1. Reported; see docs/validation.md.
TEST(V4FrictionLaw, DISABLED_GrossSlipOnTheFinerMesh) { check_gross_slip(8); }

TEST(V4FrictionLaw, ShearCarriedByTheLateralsStickThenSlip) {
  BlockCase b;
  b.n = 4;
  b.alpha = 1e-7;
  b.shear_laterals = true;
  b.U = {0.0, 0.5 * kUStar, 0.95 * kUStar, 1.05 * kUStar, 1.5 * kUStar, 2.0 * kUStar};
  auto c = solve_block(b, "homogeneous");
  ASSERT_EQ(c->history.size(), b.U.size());
  for (std::size_t step = 1; step < b.U.size(); ++step) {
    const ContactSideResult& side = c->history[step][0].sides[0];
    const double U = b.U[step], U_prev = b.U[step - 1];
    const double s_exact = U > kUStar ? U - std::max(U_prev, kUStar) : 0.0;  // slip increment of the step
    const double t_exact = -kG * std::min(U, kUStar) / kH;                   // on the block, against +x
    double s_err = 0.0, t_err = 0.0, p_err = 0.0;
    for (Index k = 0; k < side.pressure.size(); ++k) {
      s_err = std::max(s_err, std::abs(side.slip(0, k) - s_exact));
      t_err = std::max(t_err, std::abs(side.tangential(0, k) - t_exact));
      p_err = std::max(p_err, std::abs(side.pressure[k] - kP));
    }
    std::printf("  homogeneous, U/U* = %.2f: slip increment %.4e (exact %.4e), max error %.2e; traction error "
                "%.2e of %.4e; pressure error %.2e\n",
                U / kUStar, side.slip(0, 0), s_exact, s_err, t_err, -t_exact, p_err);
    // The regularised stick slides by s = α ρ / sqrt(1 − ρ²), ρ = G U / (H μ p) (3.0e-7 at ρ = 0.95),
    // which the next step's increment then lacks; the laterals' traction, set for s = 0, then differs
    // from the shear by G s / H: O(α) errors, hence the absolute tolerances of a few α.
    EXPECT_LT(s_err, 10 * b.alpha) << (U < kUStar ? "sticks below U*" : "slips U − U* above U*");
    EXPECT_LT(t_err, 1e-3 * std::abs(t_exact));
    EXPECT_LT(p_err, 1e-4 * kP);
  }
}

// ---------------------------------------------------------------------------------------------------
// c. Convergence in α: ‖u_α − u_ref‖∞ / ‖u_ref‖∞ at α = 4e-4, 2e-4, 1e-4 against α = 1e-7 (METHOD.md:
// ‖u_α − u‖ ≤ C α). Free laterals (the inhomogeneous V4 block), partial then gross slip.
// ---------------------------------------------------------------------------------------------------
TEST(V4FrictionLaw, DISABLED_AlphaStudy) {
  for (int n : {4, 8}) {
    BlockCase b;
    b.n = n;
    b.U = {0.0, 3e-3, 6e-3, 9e-3};
    b.alpha = 1e-7;
    const VectorXd u_ref = solve_block(b, "alpha_ref")->u;
    double prev = 0;
    for (double a : {1.6e-3, 8e-4, 4e-4, 2e-4, 1e-4, 5e-5, 2.5e-5, 1.25e-5}) {
      b.alpha = a;
      const VectorXd u = solve_block(b, "alpha_s")->u;
      const double e = (u - u_ref).lpNorm<Eigen::Infinity>() / u_ref.lpNorm<Eigen::Infinity>();
      std::printf("  n = %d alpha = %.3e: err %.4e rate %.3f\n", n, a, e, prev > 0 ? std::log2(prev / e) : 0.0);
      prev = e;
    }
  }
}

TEST(V4FrictionLaw, DisplacementsConvergeLinearlyInAlpha) {
  BlockCase b;
  b.n = 8;
  b.U = {0.0, 3e-3, 6e-3, 9e-3};
  b.alpha = 1e-7;
  const VectorXd u_ref = solve_block(b, "alpha_ref")->u;
  const double alphas[3] = {4e-4, 2e-4, 1e-4};
  double err[3];
  for (int i = 0; i < 3; ++i) {
    b.alpha = alphas[i];
    const VectorXd u = solve_block(b, "alpha_" + std::to_string(i))->u;
    err[i] = (u - u_ref).lpNorm<Eigen::Infinity>() / u_ref.lpNorm<Eigen::Infinity>();
    std::printf("  alpha = %.0e: |u - u_ref|/|u_ref| = %.4e%s", alphas[i], err[i], i ? "" : "\n");
    if (i) std::printf(", rate %.3f\n", std::log2(err[i - 1] / err[i]));
  }
  for (int i = 1; i < 3; ++i) EXPECT_GE(std::log2(err[i - 1] / err[i]), 1.0 - 0.2) << "alpha " << alphas[i];
}

// ---------------------------------------------------------------------------------------------------
// d. Tresca and Coulomb agree.
// ---------------------------------------------------------------------------------------------------

// The V4 block with free laterals (nonuniform pressure): solve Coulomb step by step, then the last step
// again as one regularised Tresca solve (solve_contact) with the nodal threshold τ = μ p of the
// converged Coulomb pressure, from the same start of step. The Coulomb tolerance is tightened to 1e-10
// so that the fixed point's own error is far below the 1e-6 compared.
TEST(V4FrictionLaw, TrescaWithTheCoulombThresholdReproducesCoulomb) {
  BlockCase b;
  b.n = 4;
  b.alpha = 2e-4;
  b.U = {0.0, 4e-3, 8e-3};
  b.coulomb_tolerance = 1e-9;
  const ProblemSpec spec = parse_problem(block_toml(b), "case.toml", case_dir("tresca_coulomb", b.n));
  std::ostringstream sink;
  const Logger log(sink, Verbosity::kQuiet);
  PhaseTimes times;
  auto model = Model::build(spec, log, times);
  const DofMap& dofs = model->dofs();
  const FrictionalOptions opt = contact_options(spec, log).friction;
  VectorXd u = VectorXd::Zero(dofs.num_dofs()), u_prev = u;
  SolveReport rep;
  for (int step = 0; step < model->num_steps(); ++step) {
    model->set_step(step);
    u_prev = u;
    rep = solve_frictional_contact(model->energy(), model->fixed_dofs(step), model->contacts(), dofs, u, opt, log,
                                   step > 0 ? &rep.friction_state : nullptr);
  }
  const std::vector<ContactPairResult> res = contact_results(model->contacts(), dofs, u, rep);
  const Eigen::VectorXd p = res[0].sides[0].pressure.cwiseMax(0.0);
  FrictionState tresca;
  tresca.nodal_tau = {kMu * p};
  tresca.u_start = u_prev;
  VectorXd u_tresca = u_prev;
  ContactSolveOptions tresca_options = opt.contact;
  tresca_options.lazy_interior = false;  // one solve, outside a Coulomb loop: u whole on return
  solve_contact(model->energy(), model->fixed_dofs(model->num_steps() - 1), model->contacts(), dofs, u_tresca,
                tresca_options, log, &tresca);
  const double diff = (u_tresca - u).lpNorm<Eigen::Infinity>() / u.lpNorm<Eigen::Infinity>();
  std::printf("  Coulomb (%d fixed-point iterations in the last step) vs Tresca with tau = mu p: pressure %.5f to "
              "%.5f; |u_T - u_C| / |u_C| = %.3e\n",
              rep.coulomb_iterations, p.minCoeff(), p.maxCoeff(), diff);
  EXPECT_GT(p.maxCoeff() - p.minCoeff(), 0.1 * kP);  // a really nonuniform threshold
  EXPECT_LT(diff, 1e-6);
}

// With the shear carried by the laterals the pressure is uniform, p = 0.01, so a constant Tresca
// threshold τ = μ p = 0.003 through the problem file must give the Coulomb solution.
TEST(V4FrictionLaw, UniformPressureTrescaAndCoulombProblemFilesAgree) {
  BlockCase b;
  b.n = 4;
  b.alpha = 2e-4;
  b.shear_laterals = true;
  b.U = {0.0, 0.5 * kUStar, 1.5 * kUStar, 2.0 * kUStar};
  b.alpha = 1e-7;
  const VectorXd u_coulomb = solve_block(b, "uniform_coulomb")->u;
  b.friction = "tresca";
  b.tau = kMu * kP;
  const VectorXd u_tresca = solve_block(b, "uniform_tresca")->u;
  const double diff = (u_tresca - u_coulomb).lpNorm<Eigen::Infinity>() / u_coulomb.lpNorm<Eigen::Infinity>();
  std::printf("  uniform pressure: Coulomb mu = 0.3 vs Tresca tau = 0.003: |u_T - u_C| / |u_C| = %.3e\n", diff);
  EXPECT_LT(diff, 1e-6);
}

// e. The same dragged block with τ updated between the interior point's iterations and between solves only:
// one fixed point (displacements and thresholds to 1e-8 of their size, with the loop's tolerance on τ set
// to 1e-9 so that both get that close to it: at 1e-10 the pressures read inside the interior point and from
// the polished answer differ by their noise, 1.2e-10 here), the first in at most half the solves of the second.
TEST(V4FrictionLaw, ThresholdsFollowingTheOptimizerReachTheSameFixedPointInFewerSolves) {
  BlockCase b;
  b.n = 4;
  b.U = ramp(2e-3, 1e-2);
  b.coulomb_tolerance = 1e-9;
  std::unique_ptr<SolvedCase> c[2];
  int solves[2] = {0, 0};
  const char* updates[2] = {"inside_optimizer", "between_solves"};
  for (int k = 0; k < 2; ++k) {
    b.coulomb_update = updates[k];
    c[k] = solve_block(b, std::string("update_") + updates[k]);
    solves[k] = c[k]->report.coulomb_iterations + 1;
  }
  std::printf("  solves of the last step: %d following the optimizer, %d between solves\n", solves[0], solves[1]);
  const double u_size = c[1]->u.lpNorm<Eigen::Infinity>();
  EXPECT_LT((c[0]->u - c[1]->u).lpNorm<Eigen::Infinity>(), 1e-8 * u_size);
  const Eigen::VectorXd& tau0 = c[0]->report.friction_state.nodal_tau[0];
  const Eigen::VectorXd& tau1 = c[1]->report.friction_state.nodal_tau[0];
  EXPECT_LT((tau0 - tau1).lpNorm<Eigen::Infinity>(), 1e-8 * tau1.lpNorm<Eigen::Infinity>());
  EXPECT_LE(2 * solves[0], solves[1]) << "solves of the last step: " << solves[0] << " following, " << solves[1]
                                      << " between solves";
  EXPECT_GT(tau0.maxCoeff(), 0.0);
}

// The block with its left side held vertically (uy = 0): the bottom-left node's normal is along a fixed DOF. Its
// weighted gap still holds the next node's free DOFs, so its multiplier is determined, and its force on the
// fixed DOF is part of the pressure the loop reads there (contact_forces.hpp). Thresholds that follow the interior
// point read the same force (GeometrySubproblem::add_fixed_dof_force): the loop converges in as few solves as
// on the free block, to the answer of thresholds updated between solves. Were the follower to read zero force on
// the fixed DOF, it would set that node's τ from a smaller pressure than the loop's, and the loop would stagnate
// at their difference.
TEST(V4FrictionLaw, ThresholdsFollowTheForceOnAFixedDofAsTheLoopReadsIt) {
  BlockCase b;
  b.n = 4;
  b.U = ramp(2e-3, 1e-2);
  b.coulomb_tolerance = 1e-9;
  b.extra_body = "[[body.dirichlet]]\nboundary = \"left\"\nuy = 0.0\n";
  std::unique_ptr<SolvedCase> c[2];
  const char* updates[2] = {"inside_optimizer", "between_solves"};
  for (int k = 0; k < 2; ++k) {
    b.coulomb_update = updates[k];
    c[k] = solve_block(b, std::string("held_left_") + updates[k]);
  }
  for (std::size_t s = 0; s < c[0]->coulomb_iterations.size(); ++s)
    EXPECT_LE(c[0]->coulomb_iterations[s], 1) << "step " << s + 1;
  const double u_size = c[1]->u.lpNorm<Eigen::Infinity>();
  EXPECT_LT((c[0]->u - c[1]->u).lpNorm<Eigen::Infinity>(), 1e-8 * u_size);
  const Eigen::VectorXd& tau0 = c[0]->report.friction_state.nodal_tau[0];
  const Eigen::VectorXd& tau1 = c[1]->report.friction_state.nodal_tau[0];
  EXPECT_LT((tau0 - tau1).lpNorm<Eigen::Infinity>(), 1e-8 * tau1.lpNorm<Eigen::Infinity>());
  EXPECT_GT(tau0.minCoeff(), 0.0) << "every node, the held one too, carries a pressure";
}

// f. Thresholds followed inside the dense primal interior point end where the Coulomb loop reads them: a pad
// pressed onto a rigid cylinder (the zone grows from a point, its edge moves at every step) and dragged, every
// solve by the interior point ([contact_solver] warm_start = "interior_point"). The loop reads the pressure
// from the bodies' force at the answer the solve returns; were the thresholds left at an iterate the answer
// moves from (by the closing of the active set), each solve would restore them there and the loop would re-solve
// without end, up to its budget. Each step takes its first solve, at most one more; the answer is the active-set
// start's to the loop's tolerance.
TEST(V4FrictionLaw, ThresholdsFollowedByTheInteriorPointAreTheLoopsFixedPoint) {
  const std::string dir = test_temp_dir("followed_pad");
  write_text(dir, "pad.geo", pad_geo_2d(0.012));
  const auto problem = [](const char* warm_start) {
    return std::string("[problem]\ndimension = 2\n\n[steps]\nload_factors = [0.25, 0.5, 0.75, 1.0, 1.0, 1.0]\n\n"
                       "[contact_solver]\nwarm_start = \"") +
           warm_start +
           "\"\n\n[[body]]\nname = \"pad\"\nmesh = \"pad.geo\"\ngroup = \"solid\"\nmaterial = { E = 1.0, nu = 0.3 }\n"
           "[[body.dirichlet]]\nboundary = \"top\"\nuy = -0.03\n[[body.dirichlet]]\nboundary = \"top\"\nux = 0.05\n"
           "factors = [0.0, 0.0, 0.0, 0.0, 0.5, 1.0]\n\n[[contact]]\nname = \"interface\"\na = \"pad.bottom\"\n"
           "friction = \"coulomb\"\nmu = 0.3\n[contact.obstacle]\ntype = \"circle\"\ncenter = [0.0, -1.0]\n"
           "radius = 1.0\n";
  };
  const auto interior_point = solve_case(problem("interior_point"), dir);
  const auto active_set = solve_case(problem("active_set"), dir);
  std::printf("  Coulomb iterations per step, interior point:");
  for (const int k : interior_point->coulomb_iterations) std::printf(" %d", k);
  std::printf("\n");
  ASSERT_EQ(interior_point->coulomb_iterations.size(), 6u);
  for (std::size_t s = 0; s < 6; ++s) EXPECT_LE(interior_point->coulomb_iterations[s], 1) << "step " << s + 1;
  const Eigen::VectorXd& tau = active_set->report.friction_state.nodal_tau[0];
  EXPECT_GT(tau.maxCoeff(), 0.0);
  const double u_size = active_set->u.lpNorm<Eigen::Infinity>();
  EXPECT_LT((interior_point->u - active_set->u).lpNorm<Eigen::Infinity>(), 1e-6 * u_size);
  EXPECT_LT((interior_point->report.friction_state.nodal_tau[0] - tau).lpNorm<Eigen::Infinity>(),
            1e-6 * tau.lpNorm<Eigen::Infinity>());
}

// g. Proportional loading from the unloaded start: a pad pressed onto a rigid plane in two equal steps, Coulomb
// μ = 0.1 (ν = 0.3: the ends slip outwards, the middle sticks). With a linear body, a plane and slips measured
// from each step's start, the second step's answer is the first's doubled, thresholds included (the stick nodes'
// force τ s / sqrt(s² + α²) doubles with τ at the same slip increment). The predictor extrapolates u and τ from
// the unloaded start (τ = 0 there): its point is that answer, and the second step is one Newton step on the
// previous active set. Were τ not extrapolated, the solve would start from half the thresholds, slide the ends
// further, and follow them back.
TEST(V4FrictionLaw, ASecondEqualStepFromTheUnloadedStartIsTheFirstDoubled) {
  const std::string dir = test_temp_dir("doubled_pad");
  write_text(dir, "pad.geo", pad_geo_2d(0.02));
  const std::string toml =
      "[problem]\ndimension = 2\n\n[steps]\nload_factors = [0.5, 1.0]\n\n"
      "[[body]]\nname = \"pad\"\nmesh = \"pad.geo\"\ngroup = \"solid\"\nmaterial = { E = 1.0, nu = 0.3 }\n"
      "[[body.dirichlet]]\nboundary = \"top\"\nux = 0.0\nuy = -0.02\n\n[[contact]]\nname = \"interface\"\n"
      "a = \"pad.bottom\"\nfriction = \"coulomb\"\nmu = 0.1\n[contact.obstacle]\ntype = \"plane\"\n"
      "point = [0.0, 0.0]\nnormal = [0.0, 1.0]\n";
  const auto c = solve_case(toml, dir);
  ASSERT_EQ(c->reactions.size(), 2u);
  ASSERT_EQ(c->optimizer_iterations.size(), 2u);
  std::printf("  optimizer iterations per step: %d, %d; Coulomb iterations: %d, %d\n", c->optimizer_iterations[0],
              c->optimizer_iterations[1], c->coulomb_iterations[0], c->coulomb_iterations[1]);
  const Eigen::VectorXd& r1 = c->reactions[0][0];
  const Eigen::VectorXd& r2 = c->reactions[1][0];
  EXPECT_GT(std::abs(r1[1]), 0.0);
  EXPECT_LT((r2 - 2.0 * r1).lpNorm<Eigen::Infinity>(), 1e-8 * r2.lpNorm<Eigen::Infinity>());
  const Eigen::VectorXd& tau = c->report.friction_state.nodal_tau[0];
  const Eigen::VectorXd& tau1 = c->report.friction_state.previous_tau[0];
  EXPECT_LT((tau - 2.0 * tau1).lpNorm<Eigen::Infinity>(), 1e-8 * tau.lpNorm<Eigen::Infinity>());
  // The ends slide, the middle sticks: not a uniform state, where any thresholds large enough would do.
  ASSERT_FALSE(c->contact.empty());
  const Eigen::VectorXi& status = c->contact[0].sides[0].status;
  EXPECT_GT((status.array() == 2).count(), 0);
  EXPECT_GT((status.array() == 1).count(), 0);
  EXPECT_EQ(c->coulomb_iterations[1], 0) << "the predicted thresholds are the fixed point's";
  EXPECT_LE(c->optimizer_iterations[1], 2) << "one Newton step from the predicted point";
}
