// The same problem in other consistent units gives the same dimensionless answer (issue: stopping rules
// relative to the problem's own scales). Each frictional example is written twice by rescale_problem():
// once as it is (the reference, on the written mesh) and once with lengths × L and forces × F; the
// displacements / L (norm-wise, last step), the reactions / (F / L in 2D, F in 3D) at every step (relative to
// the largest reaction of the run) and the last Coulomb thresholds / (F / L²) must agree to 1e-8, and the
// iteration counts within a couple.

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <ostream>
#include <string>

#include "support/rescale_problem.hpp"
#include "symcontact/core/expression.hpp"
#include "support/solve_case.hpp"

namespace symcontact::testing {
namespace {

namespace fs = std::filesystem;

struct UnitsCase {
  std::string example;  ///< under examples/
  double length, force;
  int steps = 0;  ///< > 0: only the first `steps` load steps (ProblemVariant::step_count)
};

void PrintTo(const UnitsCase& c, std::ostream* os) {
  *os << c.example << ", lengths x " << c.length << ", forces x " << c.force;
}

std::string case_name(const ::testing::TestParamInfo<UnitsCase>& info) {
  std::string s = info.param.example + "_L" + std::to_string(static_cast<int>(std::log10(info.param.length))) +
                  "_F" + std::to_string(static_cast<int>(std::log10(info.param.force)));
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

std::unique_ptr<SolvedCase> solve_in(const std::string& example, const UnitChange& change, const std::string& dir,
                                     int steps = 0) {
  std::string path = std::string(SYMCONTACT_EXAMPLES) + "/" + example;
  if (steps > 0) {
    ProblemVariant first_steps;
    first_steps.step_count = steps;
    path = write_variant(path, first_steps, dir + "_steps");
  }
  path = rescale_problem(path, change, dir);
  return solve_case(read_text(path), dir);
}

class Units : public ::testing::TestWithParam<UnitsCase> {};

TEST_P(Units, RescaledProblemGivesTheSameDimensionlessAnswer) {
  const UnitsCase& c = GetParam();
  const std::string dir = test_temp_dir("units");
  const UnitChange change{c.length, c.force};
  const auto ref = solve_in(c.example, UnitChange{}, dir + "ref", c.steps);
  const auto scaled = solve_in(c.example, change, dir + "scaled", c.steps);
  const int dim = ref->model->dofs().dim();
  // Plane strain and stress: per unit thickness; 3D and axisymmetric (the whole ring): forces.
  const bool per_thickness = dim == 2 && ref->spec.model != AnalysisModel::kAxisymmetric;
  const double force_unit = per_thickness ? c.force / c.length : c.force;

  // Displacements: norm-wise relative difference of the last step.
  ASSERT_EQ(ref->u.size(), scaled->u.size());
  const double u_norm = ref->u.norm();
  ASSERT_GT(u_norm, 0.0);
  EXPECT_LE((scaled->u / c.length - ref->u).norm(), 1e-8 * u_norm);

  // Reactions of every step, relative to the largest reaction of the run.
  ASSERT_EQ(ref->reactions.size(), scaled->reactions.size());
  double r_max = 0.0;
  for (const auto& step : ref->reactions)
    for (const Eigen::VectorXd& r : step) r_max = std::max(r_max, r.lpNorm<Eigen::Infinity>());
  ASSERT_GT(r_max, 0.0);
  double reaction_diff = 0.0, tau_diff = 0.0;  // relative, for the record
  for (std::size_t s = 0; s < ref->reactions.size(); ++s) {
    double diff = 0.0;
    for (std::size_t k = 0; k < ref->reactions[s].size(); ++k)
      diff = std::max(diff, (scaled->reactions[s][k] / force_unit - ref->reactions[s][k]).lpNorm<Eigen::Infinity>());
    EXPECT_LE(diff, 1e-8 * r_max) << "step " << s + 1;
    reaction_diff = std::max(reaction_diff, diff / r_max);
  }
  const auto& tau_ref = ref->report.friction_state.nodal_tau;
  const auto& tau_scaled = scaled->report.friction_state.nodal_tau;
  ASSERT_EQ(tau_ref.size(), tau_scaled.size());
  for (std::size_t p = 0; p < tau_ref.size(); ++p) {
    if (tau_ref[p].size() == 0) continue;
    const double d = (tau_scaled[p] / change.stress() - tau_ref[p]).lpNorm<Eigen::Infinity>();
    EXPECT_LE(d, 1e-8 * tau_ref[p].lpNorm<Eigen::Infinity>()) << "pair " << p;
    tau_diff = std::max(tau_diff, d / tau_ref[p].lpNorm<Eigen::Infinity>());
  }
  // The same iterations, give or take a couple per step (round-off can tip a stopping test).
  EXPECT_NEAR(scaled->report.coulomb_iterations, ref->report.coulomb_iterations, 2);
  std::cout << c.example << ": |u| " << u_norm << ", relative difference " << (scaled->u / c.length - ref->u).norm() / u_norm
            << ", reactions " << reaction_diff << ", thresholds " << tau_diff << ", last step Coulomb iterations "
            << ref->report.coulomb_iterations << " / " << scaled->report.coulomb_iterations << "\n";
}

// m–N–Pa → mm–N–MPa (stresses × 1e-6), lengths × 1e3 with forces × 1e6 (stresses unchanged), and a
// shrink (lengths × 1e-2, forces × 1e3); the O-ring, written in mm–N–MPa, in m–N–Pa, μm–N, m–kN, μm–MN and
// dm–100 kN (a finite-strain, frictional problem whose inner solves take different paths in each).
INSTANTIATE_TEST_SUITE_P(
    FrictionExamples, Units,
    ::testing::Values(UnitsCase{"inclined_2d/inclined_mu0.1.toml", 1e3, 1.0},
                      UnitsCase{"inclined_2d/inclined.toml", 1e3, 1.0},
                      UnitsCase{"inclined_2d/inclined.toml", 1e3, 1e6},
                      UnitsCase{"inclined_2d/inclined.toml", 1e-2, 1e3},
                      UnitsCase{"friction_block/block.toml", 1e3, 1.0},
                      UnitsCase{"inclined_3d/inclined.toml", 1e3, 1.0},
                      UnitsCase{"inclined_2d/inclined_reference.toml", 1e3, 1.0},
                      UnitsCase{"oring_axisymmetric/oring.toml", 1e-3, 1.0},
                      UnitsCase{"oring_axisymmetric/oring.toml", 1e3, 1.0},
                      UnitsCase{"oring_axisymmetric/oring.toml", 1e-3, 1e3},
                      UnitsCase{"oring_axisymmetric/oring.toml", 1e3, 1e6},
                      UnitsCase{"oring_axisymmetric/oring.toml", 1e-2, 1e-5}),
    case_name);

// The frictional ironing's first 52 of 110 finite-strain steps (the die pressed in, sticking, and coming
// unstuck at steps 45–52, where its geometry fixed point wanders: examples/ironing_2d/ironing_mu0.3.toml,
// docs/validation-friction.md), in mm–N–MPa. About 2 min of CPU per unit system (tests/long_tests.cmake).
INSTANTIATE_TEST_SUITE_P(FrictionalIroning, Units, ::testing::Values(UnitsCase{"ironing_2d/ironing_mu0.3.toml", 1e3, 1.0, 52}),
                         case_name);

// An expression's value in the new units at the new coordinates of a point is its old value there times the
// key's factor; numbers with exponents and names holding x, y or z are left whole.
TEST(RescaleProblem, GivesTheOldValueTimesTheFactorAtTheScaledPoint) {
  const double L = 1e3, factor = 1e-6;
  for (const std::string text : {"0.1*x*t", "2e-3*x + exp(y)*t - 1.5E+2*z", "max(x, 1e-1)*sin(pi*z) + sqrt(abs(y))",
                                 "(cos(pi/6*t) - 1)*x - sin(pi/6*t)*y", "x>0.5 ? y^2 : -z"}) {
    const Expression before(text), after(scale_expression(text, factor, L));
    for (const double p : {0.25, 0.75, 1.5}) {
      const double x = p, y = 0.5 * p + 0.1, z = 1.0 - p, t = 0.3 * p;
      const double want = factor * before(x, y, z, t);
      EXPECT_NEAR(after(L * x, L * y, L * z, t), want, 1e-13 * std::abs(want)) << text << " -> " << after.text();
    }
  }
}

// The expression-driven rigid rotation (Dirichlet values as expressions of x, y and t) in millimetres turns
// the block the same way.
TEST(RescaleProblem, RotationByExpressionsInMillimetres) {
  const std::string dir = test_temp_dir("units_expr");
  const auto ref = solve_in("rotation_2d/rotation.toml", UnitChange{}, dir + "ref");
  const auto mm = solve_in("rotation_2d/rotation.toml", UnitChange{1e3, 1.0}, dir + "mm");
  ASSERT_EQ(ref->u.size(), mm->u.size());
  ASSERT_GT(ref->u.norm(), 0.0);
  EXPECT_LE((mm->u / 1e3 - ref->u).norm(), 1e-8 * ref->u.norm());
}

// A .geo meshed with the problem's mesh_parameters (h = 0.1, not the file's own 0.2): the same mesh, in mm.
TEST(RescaleProblem, MeshParametersGiveTheSameMeshInMillimetres) {
  const std::string dir = test_temp_dir("units_params");
  const auto ref = solve_in("bimaterial_2d/bimaterial.toml", UnitChange{}, dir + "ref");
  const auto mm = solve_in("bimaterial_2d/bimaterial.toml", UnitChange{1e3, 1.0}, dir + "mm");
  const std::string shipped = std::string(SYMCONTACT_EXAMPLES) + "/bimaterial_2d/bimaterial.toml";
  const auto as_shipped = solve_case(read_text(shipped), fs::path(shipped).parent_path().string());
  ASSERT_EQ(ref->u.size(), as_shipped->u.size());
  ASSERT_EQ(ref->u.size(), mm->u.size());
  ASSERT_GT(ref->u.norm(), 0.0);
  EXPECT_LE((mm->u / 1e3 - ref->u).norm(), 1e-8 * ref->u.norm());
}

}  // namespace
}  // namespace symcontact::testing
