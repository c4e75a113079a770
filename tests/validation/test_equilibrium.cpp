// Global equilibrium through the whole input path (problem file → Model → solve): the reactions on
// the Dirichlet boundaries balance the applied loads (body force, traction, pressure) to 1e-10
// relative, in 2D with two bodies from one .geo and in 3D, P1 and P2.
#include <gtest/gtest.h>

#include <fstream>

#include "symcontact/core/error.hpp"
#include "symcontact/core/log.hpp"
#include "symcontact/model/model.hpp"
#include "symcontact/model/problem_reader.hpp"
#include "symcontact/solvers/equilibrium_solver.hpp"

using namespace symcontact;

namespace {

const std::string kGeo = std::string(SYMCONTACT_TEST_DATA) + "/geo/";

double equilibrium_error(const std::string& toml) {
  const ProblemSpec spec = parse_problem(toml, "equilibrium.toml", kGeo);
  std::ostringstream sink;
  Logger log(sink, Verbosity::kQuiet);
  PhaseTimes times;
  auto model = Model::build(spec, log, times);
  double worst = 0;
  VectorXd u = VectorXd::Zero(model->dofs().num_dofs());
  for (int step = 0; step < model->num_steps(); ++step) {
    model->set_step(step);
    const FixedDofs fixed = model->fixed_dofs(step);
    solve_equilibrium(model->energy(), fixed, u);
    VectorXd g = VectorXd::Zero(u.size());
    model->energy().add_gradient(u, g);
    // Per body: Σ reactions + Σ applied loads = 0.
    for (int b = 0; b < model->dofs().num_bodies(); ++b) {
      Eigen::VectorXd total = Eigen::VectorXd::Zero(spec.dim), applied = Eigen::VectorXd::Zero(spec.dim);
      const auto r = model->reactions(fixed, g);
      for (std::size_t k = 0; k < r.size(); ++k)
        if (model->dirichlet_boundaries()[k].body == b) total += r[k];
      const VectorXd f = model->external_load();
      for (Index d = model->dofs().offset(b); d < model->dofs().offset(b) + model->dofs().num_body_dofs(b); ++d)
        applied[d % spec.dim] += f[d];
      EXPECT_GT(applied.norm(), 0.0);
      worst = std::max(worst, (total + applied).norm() / applied.norm());
    }
  }
  return worst;
}

}  // namespace

TEST(Equilibrium, ReactionsBalanceLoads2DTwoBodies) {
  for (int order = 1; order <= 2; ++order) {
    const std::string toml = R"(
[problem]
dimension = 2
order = )" + std::to_string(order) + R"(
[steps]
load_factors = [0.5, 1.0]
[[body]]
name = "lower"
mesh = "two_blocks.geo"
group = "lower"
body_force = [0.1, -0.3]
[body.material]
E = 10.0
nu = 0.25
[[body.dirichlet]]
boundary = "bottom"
ux = 0.0
uy = 0.0
[[body.pressure]]
boundary = "interface"
pressure = 0.2
[[body]]
name = "upper"
mesh = "two_blocks.geo"
group = "upper"
[body.material]
E = 3.0
nu = 0.4
[[body.dirichlet]]
boundary = "interface"
uy = 0.0
[[body.dirichlet]]
boundary = "origin_upper_missing_is_not_used"
ux = 0.0
)";
    // The second body's second condition names a group that does not exist: an input error.
    EXPECT_THROW(equilibrium_error(toml), InputError);
    std::string ok = toml.substr(0, toml.rfind("[[body.dirichlet]]"));
    ok += R"([[body.dirichlet]]
boundary = "top"
ux = 0.001
[[body.traction]]
boundary = "top"
traction = [0.05, -0.1]
)";
    EXPECT_LT(equilibrium_error(ok), 1e-10) << "order " << order;
  }
}

TEST(Equilibrium, ReactionsBalanceLoads3D) {
  for (int order = 1; order <= 2; ++order) {
    const std::string toml = R"(
[problem]
dimension = 3
order = )" + std::to_string(order) + R"(
mesh_size = 0.4
[[body]]
name = "cube"
mesh = "cube.geo"
group = "cube"
body_force = [0.0, 0.2, -1.0]
[body.material]
E = 100.0
nu = 0.3
[[body.dirichlet]]
boundary = "zmin"
ux = 0.0
uy = 0.0
uz = 0.0
[[body.dirichlet]]
boundary = "xmin"
ux = 0.0
[[body.pressure]]
boundary = "zmax"
pressure = 2.0
[[body.traction]]
boundary = "xmax"
traction = [0.5, 0.3, 0.1]
)";
    EXPECT_LT(equilibrium_error(toml), 1e-10) << "order " << order;
  }
}
