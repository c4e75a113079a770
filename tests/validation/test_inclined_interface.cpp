// V5 (VALIDATION.md), the talk's second validation: sliding on an inclined interface. The examples
// examples/inclined_2d/inclined_mu0.toml, inclined_mu0.1.toml and inclined.toml (μ = 0.2) are solved as
// they are, on a coarser mesh (h = 0.1 through a wrapper .geo, 452 DOFs; the check is global and holds on
// any mesh): the unit square cut along y = 0.45 + 0.1 x into two bodies, the lower one clamped, the upper
// one's top edge pressed down by δ = 5e-4 and then pushed up the slope by up to 1.5e-3, Coulomb friction.
//
// In gross slip the upper body is held by its top-edge reaction R and the interface force
// N n − μ N t (n = (−sin α, cos α), t = (cos α, sin α) the sliding direction), so
//     |R_x / R_y| = (tan α + μ) / (1 − μ tan α) = tan(α + φ),   tan φ = μ.
// Checks, in the last three load steps (gross slip):
//  - the ratio against that closed form, to 0.5 %;
//  - every node of the friction side in contact is slipping;
//  - the ratio against tan(α_c + φ), α_c the current inclination of the interface (the direction of the
//    pair's normal force), to 1e-3: the friction law itself, without the geometric effect below;
//  - R balances the contact force on the upper body (round-off).
// The geometric effect. Contact is written in the current configuration: the interface turns with the
// deformation (mostly the lower body bending under the tangential load), by about 0.7 rad per unit
// compression here, and tan α_c drops below 0.1. The closed form is the small-displacement limit; the
// loads of the examples are small enough for the ratio to stay within 0.25 % of it (with δ = 0.01 it
// is off by 3.6 % for μ = 0.2, while the check against α_c still holds).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>

#include "support/solve_case.hpp"
#include "symcontact/app/run.hpp"
#include "symcontact/model/problem_reader.hpp"

using namespace symcontact;
using namespace symcontact::testing;

namespace {

constexpr double kTanAlpha = 0.1;
const std::string kExampleDir = std::string(SYMCONTACT_EXAMPLES) + "/inclined_2d";
const std::string kExampleDir3D = std::string(SYMCONTACT_EXAMPLES) + "/inclined_3d";

/// (tan α + μ) / (1 − μ tan α) for an interface of slope `tan_alpha`.
double exact_ratio(double tan_alpha, double mu) { return (tan_alpha + mu) / (1 - mu * tan_alpha); }

struct StepResult {
  Eigen::Vector2d reaction;       ///< Σ of the upper body's Dirichlet reactions (its top edge)
  Eigen::Vector2d contact_force;  ///< contact force on the upper body (side a of the pair)
  double interface_slope = 0.0;   ///< tan α_c = −N_x / N_y of the pair's normal force
  int sticking = 0;               ///< friction-side nodes in contact but not slipping
  int slipping = 0;
  int coulomb_iterations = 0;
  int geometry_iterations = 0;    ///< summed over the step's contact solves
  Eigen::VectorXd tau;            ///< the Coulomb thresholds the step converged to (the pair's friction side)
  bool converged = false;         ///< the step's last solve went to the geometry tolerance (not an inexact one)
  bool deferred = false;          ///< the step's last solve left the interior to the end of the step
  double interior_residual = 0.0; ///< max |∇E| on free DOFs off the contact surfaces, relative to max |∇E|
};

/// Solves `file` of `example_dir` (examples/inclined_2d or inclined_3d) on the mesh of size h, step by
/// step, as `symcontact run` does. In 3D the reaction and the forces are their x and y components.
/// `configure`, when given, changes the solver options read from the file; `edit`, the file's text.
std::vector<StepResult> solve_inclined(const std::string& file, double h, const std::string& example_dir = kExampleDir,
                                       const std::function<void(FrictionalOptions&)>& configure = nullptr,
                                       const std::function<void(std::string&)>& edit = nullptr) {
  const std::string dir = test_temp_dir("inclined_interface");
  char geo[512];
  std::snprintf(geo, sizeof geo, "h = %.9g;\nInclude \"%s/inclined.geo\";\n", h, example_dir.c_str());
  write_text(dir, "inclined_h.geo", geo);
  std::string toml = read_text(example_dir + "/" + file);
  const std::string from = "mesh = \"inclined.geo\"";
  std::size_t count = 0;
  for (std::size_t at = 0; (at = toml.find(from, at)) != std::string::npos; ++count)
    toml.replace(at, from.size(), "mesh = \"inclined_h.geo\"");
  EXPECT_EQ(count, 2u) << file << ": both bodies should read inclined.geo";
  if (edit) edit(toml);

  const ProblemSpec spec = parse_problem(toml, file, dir);
  std::ostringstream sink;
  const Logger log(sink, Verbosity::kQuiet);
  PhaseTimes times;
  const auto model = Model::build(spec, log, times);
  const DofMap& dofs = model->dofs();
  const int upper = model->body_index("upper");
  EXPECT_GE(upper, 0);
  FrictionalOptions opt = contact_options(spec, log).friction;
  if (configure) configure(opt);
  VectorXd u = VectorXd::Zero(dofs.num_dofs());
  std::vector<StepResult> steps;
  FrictionState previous;
  for (int step = 0; step < model->num_steps(); ++step) {
    model->set_step(step);
    const FixedDofs fixed = model->fixed_dofs(step);
    const SolveReport rep = solve_frictional_contact(model->energy(), fixed, model->contacts(), dofs, u, opt, log,
                                                     step > 0 ? &previous : nullptr);
    previous = rep.friction_state;
    const std::vector<ContactPairResult> pairs = contact_results(model->contacts(), dofs, u, rep);
    StepResult s;
    VectorXd g = VectorXd::Zero(dofs.num_dofs());
    model->energy().add_gradient(u, g);
    const std::vector<Eigen::VectorXd> r = model->reactions(fixed, g);
    s.reaction.setZero();
    for (std::size_t k = 0; k < r.size(); ++k)
      if (model->dirichlet_boundaries()[k].body == upper) s.reaction += r[k].head<2>();
    const ContactPairResult& pair = pairs.at(0);
    s.contact_force = pair.total_force.head<2>();
    s.interface_slope = -pair.normal_force[0] / pair.normal_force[1];
    for (const ContactSideResult& side : pair.sides)
      for (Index k = 0; k < side.status.size(); ++k) {
        if (!std::isfinite(side.slip(0, k)) || side.status[k] == 0) continue;  // other side, or open
        (side.status[k] == 2 ? s.slipping : s.sticking) += 1;
      }
    s.coulomb_iterations = rep.coulomb_iterations;
    s.geometry_iterations = rep.geometry_iterations;
    s.tau = rep.friction_state.nodal_tau.at(0);
    s.converged = rep.converged;
    s.deferred = rep.interior_deferred;
    {
      // Equilibrium of the interior: ∇E = 0 on free DOFs that no contact surface holds (a u whose interior were
      // out of date would fail it).
      std::vector<char> on_surface(dofs.num_dofs(), 0);
      for (const ContactSurface& cs : model->contacts().surfaces)
        for (Index node : cs.nodes)
          for (int i = 0; i < cs.dim; ++i) on_surface[dofs.dof(cs.body, node, i)] = 1;
      std::vector<Index> free_index;
      fixed.free_numbering(dofs.num_dofs(), free_index);
      double interior = 0.0;
      for (Index d = 0; d < dofs.num_dofs(); ++d)
        if (free_index[d] >= 0 && !on_surface[d]) interior = std::max(interior, std::abs(g[d]));
      s.interior_residual = interior / g.lpNorm<Eigen::Infinity>();
    }
    steps.push_back(s);
  }
  return steps;
}

struct InclinedCase {
  std::string file;
  double mu;
};

class InclinedInterface : public ::testing::TestWithParam<InclinedCase> {};

/// The checks of the header, step by step (printed).
void check_reaction_ratio(const InclinedCase& c, const std::vector<StepResult>& steps) {
  const double exact = exact_ratio(kTanAlpha, c.mu);
  ASSERT_EQ(steps.size(), 10u);
  std::printf("  %s, mu = %.1f: exact |Rx/Ry| = %.6f\n", c.file.c_str(), c.mu, exact);
  std::printf("  step     Rx            Ry           |Rx/Ry|    error     tan a_c   vs tan(a_c+phi)  slip/stick  Coulomb it\n");
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const StepResult& s = steps[k];
    const double ratio = std::abs(s.reaction[0] / s.reaction[1]);
    const double current = exact_ratio(s.interface_slope, c.mu);
    std::printf("  %4zu  %+.6e  %+.6e  %.6f  %+.3f %%  %.5f   %+.2e        %2d / %-2d     %d\n", k + 1, s.reaction[0],
                s.reaction[1], ratio, 100 * (ratio / exact - 1), s.interface_slope, ratio / current - 1, s.slipping,
                s.sticking, s.coulomb_iterations);
    // The top-edge reaction balances the contact force on the upper body (no other load on it).
    EXPECT_LT((s.reaction + s.contact_force).norm(), 1e-8 * s.reaction.norm()) << "step " << k + 1;
    if (k + 3 < steps.size()) continue;
    // Gross slip: the last three steps.
    EXPECT_NEAR(ratio / exact, 1.0, 5e-3) << "step " << k + 1;
    EXPECT_NEAR(ratio / current, 1.0, 1e-3) << "step " << k + 1;
    EXPECT_GT(s.slipping, 0) << "step " << k + 1;
    EXPECT_EQ(s.sticking, 0) << "step " << k + 1;
  }
}

}  // namespace

TEST_P(InclinedInterface, ReactionRatioInGrossSlipMatchesTheIncline) {
  const InclinedCase c = GetParam();
  check_reaction_ratio(c, solve_inclined(c.file, 0.1));
}

// The same extruded to 3D (examples/inclined_3d: a slab of thickness 0.2, u_z = 0 on both z faces, so
// the plane-strain answer holds), μ = 0.2, on unstructured tetrahedra of size 0.1 (0.075 above).
TEST(InclinedInterface3D, ReactionRatioInGrossSlipMatchesTheIncline) {
  const auto t0 = std::chrono::steady_clock::now();
  check_reaction_ratio(InclinedCase{"inclined.toml", 0.2}, solve_inclined("inclined.toml", 0.1, kExampleDir3D));
  std::printf("  3D: %.1f s\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

const auto kCaseName = [](const auto& p) { return "mu" + std::to_string(static_cast<int>(10 * p.param.mu + 0.5)); };

INSTANTIATE_TEST_SUITE_P(V5, InclinedInterface,
                         ::testing::Values(InclinedCase{"inclined_mu0.toml", 0.0}, InclinedCase{"inclined_mu0.1.toml", 0.1},
                                           InclinedCase{"inclined.toml", 0.2}),
                         kCaseName);

// The Coulomb fixed point's shortcuts change its path, not its answer: inexact inner solves (each Tresca
// solve's geometry fixed point stopped at a tolerance proportional to the threshold change while τ still
// moves, FrictionalOptions::inner_tolerance_factor) and the predictor (the previous step's increment of u
// and τ extrapolated, FrictionalOptions::extrapolate) against the plain nested iteration (every solve to the
// geometry tolerance, from the previous step's u and τ), μ = 0.2 on the coarse mesh: the same reactions and
// thresholds at every step to the solver's tolerances, in fewer geometry iterations. Each run stops once
// τ moves by less than 1e-6 of max τ, which puts τ within that divided by (1 − slope of τ ↦ μ p(τ)) of
// the fixed point, a few times it where the slope nears 1: two runs' τ within 2e-5 of max τ here
// (measured up to 4.9e-6, at step 2); the reactions, to 1e-6 (measured up to 1.2e-8). A very loose factor (every solve but the ones that end a step stopped after one
// geometry iteration or so) reaches the same answer too: a step never ends on an inexact solve (with that
// factor every step ends on one more solve, to the geometry tolerance, after τ has settled). These shortcuts
// serve thresholds updated between solves (CoulombUpdate::kBetweenSolves, pinned here); the default, τ
// following the dense primal interior point's iterates, reaches the same answer within the same bounds.
TEST(InclinedInterface, InexactInnerSolvesAndPredictorKeepTheAnswer) {
  const auto between = [](double factor, bool extrapolate) {
    return [factor, extrapolate](FrictionalOptions& o) {
      o.coulomb_update = CoulombUpdate::kBetweenSolves;
      o.inner_tolerance_factor = factor;
      o.extrapolate = extrapolate;
    };
  };
  const FrictionalOptions defaults;
  const auto exact = solve_inclined("inclined.toml", 0.1, kExampleDir, between(0.0, false));
  const auto fast = solve_inclined("inclined.toml", 0.1, kExampleDir, between(defaults.inner_tolerance_factor, true));
  const auto loose = solve_inclined("inclined.toml", 0.1, kExampleDir, between(1e3, true));
  const auto followed = solve_inclined("inclined.toml", 0.1);
  ASSERT_EQ(exact.size(), 10u);
  ASSERT_EQ(fast.size(), exact.size());
  ASSERT_EQ(loose.size(), exact.size());
  ASSERT_EQ(followed.size(), exact.size());
  int geometry_exact = 0, geometry_fast = 0;
  const char* names[] = {" (fast)", " (loose)", " (followed)"};
  std::printf("  step  geometry it. exact / fast / loose / followed   max rel. diff. of R and tau, the last three\n");
  for (std::size_t k = 0; k < exact.size(); ++k) {
    geometry_exact += exact[k].geometry_iterations;
    geometry_fast += fast[k].geometry_iterations;
    const double r_scale = exact[k].reaction.norm(), t_scale = exact[k].tau.lpNorm<Eigen::Infinity>();
    ASSERT_GT(r_scale, 0.0);
    ASSERT_GT(t_scale, 0.0);
    const std::vector<StepResult>* others[] = {&fast, &loose, &followed};
    double dr[3], dt[3];
    for (int v = 0; v < 3; ++v) {
      const StepResult& o = (*others[v])[k];
      ASSERT_EQ(o.tau.size(), exact[k].tau.size());
      dr[v] = (o.reaction - exact[k].reaction).norm() / r_scale;
      dt[v] = (o.tau - exact[k].tau).lpNorm<Eigen::Infinity>() / t_scale;
      EXPECT_TRUE(o.converged) << "step " << k + 1 << names[v];
      EXPECT_LT(dr[v], 1e-6) << "step " << k + 1 << names[v];
      EXPECT_LT(dt[v], 2e-5) << "step " << k + 1 << names[v];
    }
    std::printf("  %4zu  %4d / %4d / %4d / %4d   R %.1e %.1e %.1e   tau %.1e %.1e %.1e\n", k + 1,
                exact[k].geometry_iterations, fast[k].geometry_iterations, loose[k].geometry_iterations,
                followed[k].geometry_iterations, dr[0], dr[1], dr[2], dt[0], dt[1], dt[2]);
  }
  std::printf("  geometry iterations: %d exact, %d default\n", geometry_exact, geometry_fast);
  EXPECT_LT(geometry_fast, 0.75 * geometry_exact);
}

// The solves of a load step leave the interior out of date and the step completes u once
// (ContactSolveOptions::lazy_interior, on in FrictionalOptions::contact): the same answer as expanding after every
// solve, to round-off, and a u in equilibrium away from the contact surfaces. With τ updated between solves: where
// it follows the interior point's iterates, each solve takes τ from an iterate and keeps it while it moves by
// less than a tenth of the Coulomb tolerance, so that round-off in the start moves τ within that (1.2e-9 of max τ
// measured here, against 1e-7).
TEST(InclinedInterface, LazyInteriorKeepsTheAnswer) {
  const auto eager = solve_inclined("inclined.toml", 0.1, kExampleDir, [](FrictionalOptions& o) {
    o.contact.lazy_interior = false;
    o.coulomb_update = CoulombUpdate::kBetweenSolves;
  });
  const auto lazy = solve_inclined("inclined.toml", 0.1, kExampleDir,
                                   [](FrictionalOptions& o) { o.coulomb_update = CoulombUpdate::kBetweenSolves; });
  ASSERT_EQ(eager.size(), 10u);
  ASSERT_EQ(lazy.size(), eager.size());
  int deferred = 0;
  for (std::size_t k = 0; k < eager.size(); ++k) {
    EXPECT_FALSE(eager[k].deferred) << "step " << k + 1;
    deferred += lazy[k].deferred;
    EXPECT_EQ(lazy[k].geometry_iterations, eager[k].geometry_iterations) << "step " << k + 1;
    EXPECT_EQ(lazy[k].coulomb_iterations, eager[k].coulomb_iterations) << "step " << k + 1;
    EXPECT_LT((lazy[k].reaction - eager[k].reaction).norm(), 1e-10 * eager[k].reaction.norm()) << "step " << k + 1;
    EXPECT_LT((lazy[k].tau - eager[k].tau).lpNorm<Eigen::Infinity>(), 1e-10 * eager[k].tau.lpNorm<Eigen::Infinity>())
        << "step " << k + 1;
    EXPECT_LT(lazy[k].interior_residual, 1e-10) << "step " << k + 1;
    EXPECT_LT(eager[k].interior_residual, 1e-10) << "step " << k + 1;
  }
  EXPECT_EQ(deferred, 10) << "every step's solves deferred the interior (the condensed set holds the interface)";
  const auto followed_eager =
      solve_inclined("inclined.toml", 0.1, kExampleDir, [](FrictionalOptions& o) { o.contact.lazy_interior = false; });
  const auto followed_lazy = solve_inclined("inclined.toml", 0.1);
  ASSERT_EQ(followed_eager.size(), eager.size());
  ASSERT_EQ(followed_lazy.size(), eager.size());
  for (std::size_t k = 0; k < eager.size(); ++k) {
    const StepResult &e = followed_eager[k], &l = followed_lazy[k];
    EXPECT_TRUE(l.deferred) << "step " << k + 1;
    EXPECT_LT((l.reaction - e.reaction).norm(), 1e-7 * e.reaction.norm()) << "step " << k + 1;
    EXPECT_LT((l.tau - e.tau).lpNorm<Eigen::Infinity>(), 1e-7 * e.tau.lpNorm<Eigen::Infinity>()) << "step " << k + 1;
    EXPECT_LT(l.interior_residual, 1e-10) << "step " << k + 1;
  }
}

/// Replaces the one occurrence of `from` in `text` by `to`.
void replace_once(std::string& text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  ASSERT_EQ(text.find(from, at + 1), std::string::npos) << from;
  text.replace(at, from.size(), to);
}

// Small sliding ([[contact]] geometry = "reference", contact/contact_geometry.hpp): the example
// examples/inclined_2d/inclined_reference.toml (μ = 0.2, δ = 0.01, U = 0.03, α = 1e-7) with its loads and α
// scaled by k = 1/20, 1/4 and 1 (δ = 5e-4, the loads of inclined.toml, to 0.01), in the reference and in
// the current geometry. The reference geometry writes exactly the problem of the closed form: in gross slip
// (from step 6; required in the last three) |R_x/R_y| = tan(α + φ) to 1e-8 whatever the load, after a first
// gross-slip step within 1e-6 (measured 3.2e-7, then at most 8.5e-10, the same at every k: the
// problem is linear in the load; what is left is the regularisation, (α/s)²/2 = 3.6e-10 with s ≈ 3.7e-3 k
// the slip of a step, and the Coulomb tolerance 1e-6 on τ). The current geometry drifts with the load, as
// the interface turns: −0.15 %, −0.77 % and −3.2 % at step 10 for k = 1/20, 1/4 and 1 on this mesh. A
// reference solve takes at most two geometry iterations: its rows do not depend on the iterate, so the
// second subproblem is the first one again (an inexact inner solve may stop after the first). τ is updated
// between solves, whose loop converges it below the figures above; where it follows the interior point's
// iterates (the default), a solve keeps τ while it moves by less than 1e-7 of itself, and the ratio in gross
// slip is within that (measured 1.8e-8), as the loop's tolerance allows.
TEST(InclinedInterface, ReferenceGeometryMeetsTheClosedFormAtEveryLoad) {
  const auto between_solves = [](FrictionalOptions& o) { o.coulomb_update = CoulombUpdate::kBetweenSolves; };
  const double exact = exact_ratio(kTanAlpha, 0.2);
  std::printf("  exact |Rx/Ry| = %.10f; every step, reference | current\n", exact);
  for (const double k : {0.05, 0.25, 1.0}) {
    char loads[128];
    std::snprintf(loads, sizeof loads, "uy = %.9g|ux = %.9g|alpha = %.9g", -0.01 * k, 0.03 * k, 1e-7 * k);
    std::vector<std::string> lines;
    std::istringstream in(loads);
    for (std::string line; std::getline(in, line, '|');) lines.push_back(line);
    auto scale = [&](std::string& t) {
      replace_once(t, "uy = -0.01\n", lines.at(0) + "\n");
      replace_once(t, "ux = 0.03\n", lines.at(1) + "\n");
      replace_once(t, "alpha = 1e-7 ", lines.at(2) + " ");
    };
    const auto reference = solve_inclined("inclined_reference.toml", 0.1, kExampleDir, between_solves, scale);
    const auto current = solve_inclined("inclined_reference.toml", 0.1, kExampleDir, between_solves,
                                        [&](std::string& t) {
      scale(t);
      replace_once(t, "\ngeometry = \"reference\"", "\ngeometry = \"current\"");
    });
    ASSERT_EQ(reference.size(), 10u);
    ASSERT_EQ(current.size(), 10u);
    for (std::size_t s = 0; s < 10; ++s)  // at most two geometry iterations per contact solve (one Coulomb iteration)
      EXPECT_LE(reference[s].geometry_iterations, 2 * reference[s].coulomb_iterations) << "step " << s + 1;
    for (std::size_t s = 0; s < 10; ++s) {
      const double r = std::abs(reference[s].reaction[0] / reference[s].reaction[1]);
      const double c = std::abs(current[s].reaction[0] / current[s].reaction[1]);
      // Gross slip: every friction-side node in contact slips (from step 7 on; required in the last three).
      const bool gross = reference[s].sticking == 0 && reference[s].slipping > 0;
      std::printf("  delta = %.2e, step %2zu: %.10f (%+.2e)%s |  %.6f (%+.3f %%); geometry iterations %2d | %2d, "
                  "Coulomb %2d | %2d\n",
                  0.01 * k, s + 1, r, r / exact - 1, gross ? " slip " : " stick", c, 100 * (c / exact - 1),
                  reference[s].geometry_iterations, current[s].geometry_iterations, reference[s].coulomb_iterations,
                  current[s].coulomb_iterations);
      // The normal force is along the normal of X: the interface's slope as meshed, 0.1.
      EXPECT_NEAR(reference[s].interface_slope, kTanAlpha, 1e-12) << "delta " << 0.01 * k << ", step " << s + 1;
      if (s >= 7) {
        EXPECT_TRUE(gross) << "delta " << 0.01 * k << ", step " << s + 1;
      }
      if (!gross) continue;
      // The first step in gross slip is off by the regularisation of the node that started slipping last,
      // within it (measured 3.2e-7: its slip is about 125 α); the later ones to 1e-8.
      const bool first = s == 0 || !(reference[s - 1].sticking == 0 && reference[s - 1].slipping > 0);
      EXPECT_NEAR(r / exact, 1.0, first ? 1e-6 : 1e-8) << "delta " << 0.01 * k << ", step " << s + 1;
      // The current geometry's drift grows with the load (about −3.2 % k): above 1 % at k = 1.
      if (k == 1.0 && s >= 7) {
        EXPECT_LT(c / exact - 1, -1e-2) << "step " << s + 1;
      }
    }
  }
}

// The three example files are one problem: they may differ only in lines that mention mu (the
// coefficient, the title and the header comment), and each states its own coefficient.
TEST(InclinedInterface, ExampleFilesDifferOnlyInMu) {
  const auto lines = [](const std::string& file) {
    std::vector<std::string> out;
    std::istringstream in(read_text(kExampleDir + "/" + file));
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
  };
  const std::vector<std::string> ref = lines("inclined.toml");
  for (const InclinedCase& c : {InclinedCase{"inclined_mu0.toml", 0.0}, InclinedCase{"inclined_mu0.1.toml", 0.1}}) {
    const std::vector<std::string> other = lines(c.file);
    ASSERT_EQ(other.size(), ref.size()) << c.file;
    for (std::size_t k = 0; k < ref.size(); ++k)
      if (other[k] != ref[k]) {
        EXPECT_NE(other[k].find("mu"), std::string::npos) << c.file << ":" << k + 1 << ": " << other[k];
      }
    const ProblemSpec spec = parse_problem(read_text(kExampleDir + "/" + c.file), c.file, kExampleDir);
    ASSERT_EQ(spec.contacts.size(), 1u);
    EXPECT_EQ(spec.contacts[0].mu, c.mu) << c.file;
  }
}
