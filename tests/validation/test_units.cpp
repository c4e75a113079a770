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
#include "support/solve_case.hpp"

namespace symcontact::testing {
namespace {

struct UnitsCase {
  std::string example;  ///< under examples/
  double length, force;
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

std::unique_ptr<SolvedCase> solve_in(const std::string& example, const UnitChange& change, const std::string& dir) {
  const std::string path = rescale_problem(std::string(SYMCONTACT_EXAMPLES) + "/" + example, change, dir);
  return solve_case(read_text(path), dir);
}

class Units : public ::testing::TestWithParam<UnitsCase> {};

TEST_P(Units, RescaledProblemGivesTheSameDimensionlessAnswer) {
  const UnitsCase& c = GetParam();
  const std::string dir = test_temp_dir("units");
  const UnitChange change{c.length, c.force};
  const auto ref = solve_in(c.example, UnitChange{}, dir + "ref");
  const auto scaled = solve_in(c.example, change, dir + "scaled");
  const int dim = ref->model->dofs().dim();
  const double force_unit = dim == 2 ? c.force / c.length : c.force;  // 2D: per unit thickness

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
  for (std::size_t s = 0; s < ref->reactions.size(); ++s) {
    double diff = 0.0;
    for (std::size_t k = 0; k < ref->reactions[s].size(); ++k)
      diff = std::max(diff, (scaled->reactions[s][k] / force_unit - ref->reactions[s][k]).lpNorm<Eigen::Infinity>());
    EXPECT_LE(diff, 1e-8 * r_max) << "step " << s + 1;
  }
  const auto& tau_ref = ref->report.friction_state.nodal_tau;
  const auto& tau_scaled = scaled->report.friction_state.nodal_tau;
  ASSERT_EQ(tau_ref.size(), tau_scaled.size());
  for (std::size_t p = 0; p < tau_ref.size(); ++p) {
    if (tau_ref[p].size() == 0) continue;
    EXPECT_LE((tau_scaled[p] / change.stress() - tau_ref[p]).lpNorm<Eigen::Infinity>(),
              1e-8 * tau_ref[p].lpNorm<Eigen::Infinity>())
        << "pair " << p;
  }
  // The same iterations, give or take a couple per step (round-off can tip a stopping test).
  EXPECT_NEAR(scaled->report.coulomb_iterations, ref->report.coulomb_iterations, 2);
  std::cout << c.example << ": |u| " << u_norm << ", relative difference " << (scaled->u / c.length - ref->u).norm() / u_norm << ", last step Coulomb iterations " << ref->report.coulomb_iterations
            << " / " << scaled->report.coulomb_iterations << "\n";
}

// m–N–Pa → mm–N–MPa (stresses × 1e-6), lengths × 1e3 with forces × 1e6 (stresses unchanged), and a
// shrink (lengths × 1e-2, forces × 1e3).
INSTANTIATE_TEST_SUITE_P(
    FrictionExamples, Units,
    ::testing::Values(UnitsCase{"inclined_2d/inclined_mu0.1.toml", 1e3, 1.0},
                      UnitsCase{"inclined_2d/inclined.toml", 1e3, 1.0},
                      UnitsCase{"inclined_2d/inclined.toml", 1e3, 1e6},
                      UnitsCase{"inclined_2d/inclined.toml", 1e-2, 1e3},
                      UnitsCase{"friction_block/block.toml", 1e3, 1.0},
                      UnitsCase{"inclined_3d/inclined.toml", 1e3, 1.0}),
    case_name);

}  // namespace
}  // namespace symcontact::testing
