// Finite-difference checks of every energy term (STYLE.md §5), through the shared helper.
#include <gtest/gtest.h>

#include <optional>

#include <random>

#include "support/finite_difference.hpp"
#include "symcontact/energy/energy_sum.hpp"
#include "symcontact/energy/external_load.hpp"
#include "symcontact/energy/linear_elastic_energy.hpp"
#include "symcontact/mesh/structured.hpp"

using namespace symcontact;
using symcontact::testing::check_derivatives;
using symcontact::testing::distorted_mesh;

namespace {
VectorXd random_vector(Index n, unsigned seed, double scale = 1.0) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> N01;
  VectorXd v(n);
  for (Index i = 0; i < n; ++i) v[i] = scale * N01(rng);
  return v;
}

struct Case {
  int dim, order;
  std::optional<CellType> tensor;  ///< a quadrilateral or hexahedron type; none: simplices
  bool mixed = false;              ///< every other quadrilateral cut into two triangles (Quad4, Quad9)
};
class EnergyDerivatives : public ::testing::TestWithParam<Case> {};
}  // namespace

TEST_P(EnergyDerivatives, LinearElasticGradientAndHessian) {
  const auto [dim, order, tensor, mixed] = GetParam();
  const Mesh m = distorted_mesh(dim, order, tensor, mixed);
  DofMap dofs(dim);
  dofs.add_body(m.num_nodes());
  const auto mat = LinearElastic::from_young_poisson(3.0, 0.3, dim == 2 ? AnalysisModel::kPlaneStrain : AnalysisModel::kThreeD);
  LinearElasticEnergy e(m, dofs, 0, mat, "test");
  const auto r = check_derivatives(e, random_vector(dofs.num_dofs(), 11, 0.1));
  EXPECT_LT(r.gradient_error, 1e-7);
  EXPECT_LT(r.hessian_error, 1e-7);
}

TEST_P(EnergyDerivatives, LoadsAndSumGradientAndHessian) {
  const int dim = GetParam().dim;  // not a structured binding: the lambdas below capture it (C++17)
  const Mesh m = distorted_mesh(dim, GetParam().order, GetParam().tensor, GetParam().mixed);
  DofMap dofs(dim);
  dofs.add_body(m.num_nodes());
  EnergySum sum;
  const auto mat = LinearElastic::from_young_poisson(2.0, 0.25, dim == 2 ? AnalysisModel::kPlaneStress : AnalysisModel::kThreeD);
  sum.add(std::make_unique<LinearElasticEnergy>(m, dofs, 0, mat, "test"));
  auto bf = body_force_vector(m, dofs, 0, [&](const double* x, double* b) {
    for (int i = 0; i < dim; ++i) b[i] = std::sin(x[0] + i) * x[1];
  });
  auto* load = sum.add(std::make_unique<LinearLoad>("body force", bf));
  load->set_scale(0.7);
  const auto& top = m.facet_groups.at(dim == 2 ? "top" : "zmax");
  auto tr = boundary_load_vector(m, dofs, 0, top, [&](const double*, const double* n, double* t) {
    for (int i = 0; i < dim; ++i) t[i] = -0.3 * n[i] + 0.1 * i;
  });
  sum.add(std::make_unique<LinearLoad>("traction", tr));
  const auto r = check_derivatives(sum, random_vector(dofs.num_dofs(), 5, 0.1));
  EXPECT_LT(r.gradient_error, 1e-7);
  EXPECT_LT(r.hessian_error, 1e-7);
  const auto rl = check_derivatives(*load, random_vector(dofs.num_dofs(), 6));
  EXPECT_LT(rl.gradient_error, 1e-7);
  EXPECT_TRUE(sum.hessian_is_constant());
}

TEST_P(EnergyDerivatives, RigidMotionsCostNoEnergy) {
  const auto [dim, order, tensor, mixed] = GetParam();
  const Mesh m = distorted_mesh(dim, order, tensor, mixed);
  DofMap dofs(dim);
  dofs.add_body(m.num_nodes());
  const auto mat = LinearElastic::from_young_poisson(1.0, 0.3, dim == 2 ? AnalysisModel::kPlaneStrain : AnalysisModel::kThreeD);
  LinearElasticEnergy e(m, dofs, 0, mat, "test");
  // Translation plus infinitesimal rotation u = c + W x (W skew): zero strain.
  Eigen::Matrix3d W;
  W << 0, -0.3, 0.2, 0.3, 0, -0.1, -0.2, 0.1, 0;
  const Vec3 c(0.5, -1.0, 2.0);
  VectorXd u(dofs.num_dofs());
  for (Index v = 0; v < m.num_nodes(); ++v) {
    Vec3 x = Vec3::Zero();
    x.head(dim) = m.x.col(v);
    const Vec3 uv = c + W * x;
    for (int i = 0; i < dim; ++i) u[dofs.dof(0, v, i)] = uv[i];
  }
  EXPECT_NEAR(e.value(u), 0.0, 1e-13);
  VectorXd g = VectorXd::Zero(u.size());
  e.add_gradient(u, g);
  EXPECT_LT(g.cwiseAbs().maxCoeff(), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(AllElements, EnergyDerivatives,
                         ::testing::Values(Case{2, 1, {}}, Case{2, 2, {}}, Case{3, 1, {}}, Case{3, 2, {}},
                                           Case{2, 1, CellType::kQuad4}, Case{2, 2, CellType::kQuad8},
                                           Case{2, 2, CellType::kQuad9}, Case{3, 1, CellType::kHex8},
                                           Case{3, 2, CellType::kHex20}, Case{3, 2, CellType::kHex27},
                                           Case{2, 1, CellType::kQuad4, true}, Case{2, 2, CellType::kQuad9, true},
                                           Case{3, 1, CellType::kPrism6}, Case{3, 2, CellType::kPrism18},
                                           Case{3, 2, CellType::kPrism15}, Case{3, 1, CellType::kPyramid5},
                                           Case{3, 2, CellType::kPyramid13}, Case{3, 2, CellType::kPyramid14}),
                         [](const auto& p) {
                           if (p.param.tensor) return cell_name(*p.param.tensor) + (p.param.mixed ? "WithTriangles" : "");
                           return "D" + std::to_string(p.param.dim) + "P" + std::to_string(p.param.order);
                         });

TEST(ExternalLoad, TractionIntegratesToForceTimesArea) {
  // Uniform pressure p on the top of a 2 × 1 rectangle: total force −p · 2 in y; in 3D on a 1 × 1 face.
  for (int order = 1; order <= 2; ++order) {
    const Mesh m = rectangle_mesh(0, 0, 2, 1, 5, 3, order);
    DofMap dofs(2);
    dofs.add_body(m.num_nodes());
    const VectorXd f = boundary_load_vector(m, dofs, 0, m.facet_groups.at("top"),
                                            [](const double*, const double* n, double* t) {
                                              t[0] = -0.5 * n[0];
                                              t[1] = -0.5 * n[1];
                                            });
    double fx = 0, fy = 0;
    for (Index v = 0; v < m.num_nodes(); ++v) fx += f[2 * v], fy += f[2 * v + 1];
    EXPECT_NEAR(fx, 0.0, 1e-14);
    EXPECT_NEAR(fy, -1.0, 1e-14);  // outward normal of "top" is +y
    const Mesh b = box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), 2, 3, 2, order);
    DofMap d3(3);
    d3.add_body(b.num_nodes());
    Eigen::VectorXd nint;
    for (const char* face : {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"}) {
      EXPECT_NEAR(facet_group_measure(b, b.facet_groups.at(face), &nint), 1.0, 1e-14);
      EXPECT_NEAR(nint.norm(), 1.0, 1e-14);
    }
    facet_group_measure(b, b.facet_groups.at("zmax"), &nint);
    EXPECT_NEAR(nint[2], 1.0, 1e-14);  // outward
  }
}
