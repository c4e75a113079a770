// The axisymmetric energies and loads (fem/analysis_model.hpp) on the section [0, 2] × [0, 1] (its left side
// on the axis r = 0): finite-difference checks of the linear and hyperelastic terms (STYLE.md §5, shared
// helper); the hyperelastic Hessian at u = 0 is the linear stiffness; a uniform expansion u = (ε r, κ z) has
// the energy of its constant 3D strain times the ring's volume 2π ∫ r dA = 4π exactly; an axial
// translation costs nothing and a radial one does (the hoop strain); loads integrate 2π r.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>

#include "support/finite_difference.hpp"
#include "symcontact/energy/external_load.hpp"
#include "symcontact/energy/hyperelastic_energy.hpp"
#include "symcontact/energy/linear_elastic_energy.hpp"
#include "symcontact/fem/matrix_sink.hpp"

using namespace symcontact;
using symcontact::testing::check_derivatives;
using symcontact::testing::distorted_mesh;

namespace {

constexpr AnalysisModel kAxi = AnalysisModel::kAxisymmetric;
const double kRingVolume = 4 * M_PI;  // 2π ∫ r dA over [0, 2] × [0, 1]

struct Case {
  int order;
  std::optional<CellType> tensor;  ///< a quadrilateral type; none: triangles
};
class AxisymmetricEnergy : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    mesh = distorted_mesh(2, GetParam().order, GetParam().tensor);
    dofs = DofMap(2);
    dofs.add_body(mesh.num_nodes());
  }
  /// u_r = 0 on the axis (as symmetry asks), a smooth field plus noise elsewhere, of amplitude `scale`.
  VectorXd field(double scale, unsigned seed) const {
    std::mt19937 rng(seed);
    std::normal_distribution<double> N01;
    VectorXd u(dofs.num_dofs());
    for (Index a = 0; a < mesh.num_nodes(); ++a) {
      const double r = mesh.x(0, a), z = mesh.x(1, a);
      u[dofs.dof(0, a, 0)] = scale * r * (0.3 + 0.2 * z * z + 0.05 * N01(rng));
      u[dofs.dof(0, a, 1)] = scale * (-0.1 * r * z + 0.15 * z + 0.05 * N01(rng));
    }
    return u;
  }
  VectorXd uniform_expansion(double eps, double kappa) const {
    VectorXd u(dofs.num_dofs());
    for (Index a = 0; a < mesh.num_nodes(); ++a) {
      u[dofs.dof(0, a, 0)] = eps * mesh.x(0, a);
      u[dofs.dof(0, a, 1)] = kappa * mesh.x(1, a);
    }
    return u;
  }
  Mesh mesh;
  DofMap dofs{2};
};

Eigen::MatrixXd dense_hessian(const EnergyTerm& e, const VectorXd& u) {
  TripletSink sink;
  e.add_hessian(u, sink);
  return Eigen::MatrixXd(sink.to_matrix(u.size()));
}

}  // namespace

TEST_P(AxisymmetricEnergy, LinearGradientAndHessianMatchFiniteDifferences) {
  const LinearElasticEnergy e(mesh, dofs, 0, LinearElastic::from_young_poisson(3.0, 0.3, kAxi), "test");
  const auto r = check_derivatives(e, field(0.1, 11));
  EXPECT_LT(r.gradient_error, 1e-7);
  EXPECT_LT(r.hessian_error, 1e-7);
}

TEST_P(AxisymmetricEnergy, HyperelasticGradientAndHessianMatchFiniteDifferences) {
  for (HyperelasticLaw law : {HyperelasticLaw::kNeoHookean, HyperelasticLaw::kMooneyRivlin}) {
    const HyperelasticEnergy e(mesh, dofs, 0, Hyperelastic::from_young_poisson(law, 3.0, 0.3), "test", kAxi);
    for (double scale : {0.05, 0.4}) {
      const auto r = check_derivatives(e, field(scale, 7));
      EXPECT_LT(r.gradient_error, 1e-6) << "scale " << scale;
      EXPECT_LT(r.hessian_error, 1e-6) << "scale " << scale;
    }
  }
}

TEST_P(AxisymmetricEnergy, HyperelasticHessianAtRestIsTheLinearStiffness) {
  const LinearElasticEnergy lin(mesh, dofs, 0, LinearElastic::from_young_poisson(3.0, 0.3, kAxi), "test");
  const HyperelasticEnergy hyp(mesh, dofs, 0, Hyperelastic::from_young_poisson(HyperelasticLaw::kNeoHookean, 3.0, 0.3),
                               "test", kAxi);
  const VectorXd zero = VectorXd::Zero(dofs.num_dofs());
  const Eigen::MatrixXd K = dense_hessian(lin, zero), H = dense_hessian(hyp, zero);
  EXPECT_LT((K - H).cwiseAbs().maxCoeff(), 1e-12 * K.cwiseAbs().maxCoeff());
}

TEST_P(AxisymmetricEnergy, UniformExpansionHasTheEnergyOfItsStrainOverTheRing) {
  const double E = 3.0, nu = 0.3, eps = 1e-3, kappa = -4e-4;
  const LinearElastic m = LinearElastic::from_young_poisson(E, nu, kAxi);
  const LinearElasticEnergy e(mesh, dofs, 0, m, "test");
  // ε = diag(ε, κ, ε) in (r, z, θ): W = λ/2 (tr ε)² + μ ε : ε.
  const double W = 0.5 * m.lambda * std::pow(2 * eps + kappa, 2) + m.mu * (2 * eps * eps + kappa * kappa);
  EXPECT_NEAR(e.value(uniform_expansion(eps, kappa)), W * kRingVolume, 1e-12 * W * kRingVolume);
}

TEST_P(AxisymmetricEnergy, AxialTranslationIsFreeAndRadialTranslationIsNot) {
  const LinearElasticEnergy e(mesh, dofs, 0, LinearElastic::from_young_poisson(3.0, 0.3, kAxi), "test");
  VectorXd axial = VectorXd::Zero(dofs.num_dofs()), radial = axial;
  for (Index a = 0; a < mesh.num_nodes(); ++a) {
    axial[dofs.dof(0, a, 1)] = 0.7;
    radial[dofs.dof(0, a, 0)] = 0.01;
  }
  EXPECT_NEAR(e.value(axial), 0.0, 1e-13);
  EXPECT_GT(e.value(radial), 1e-6);  // ε_θθ = 0.01 / r: a ring cannot move sideways as a whole
}

TEST_P(AxisymmetricEnergy, LoadsIntegrateOverTheWholeRing) {
  // A unit body force along z: Σ f_z = the ring's volume; a unit traction on the top z = 1: its area
  // 2π ∫₀² r dr = 4π; the same area from facet_group_measure().
  const VectorXd fb = body_force_vector(mesh, dofs, 0, [](const double*, double* b) { b[0] = 0, b[1] = 1; }, kAxi);
  const FacetGroup& top = mesh.facet_groups.at("top");
  const VectorXd ft = boundary_load_vector(mesh, dofs, 0, top,
                                           [](const double*, const double*, double* t) { t[0] = 0, t[1] = 1; }, kAxi);
  double sb = 0, st = 0;
  for (Index a = 0; a < mesh.num_nodes(); ++a) {
    sb += fb[dofs.dof(0, a, 1)];
    st += ft[dofs.dof(0, a, 1)];
  }
  EXPECT_NEAR(sb, kRingVolume, 1e-12 * kRingVolume);
  EXPECT_NEAR(st, 4 * M_PI, 1e-12 * 4 * M_PI);
  EXPECT_NEAR(facet_group_measure(mesh, top, nullptr, kAxi), 4 * M_PI, 1e-12 * 4 * M_PI);
}

INSTANTIATE_TEST_SUITE_P(Cells, AxisymmetricEnergy,
                         ::testing::Values(Case{1, {}}, Case{2, {}}, Case{1, CellType::kQuad4},
                                           Case{2, CellType::kQuad8}, Case{2, CellType::kQuad9}),
                         [](const ::testing::TestParamInfo<Case>& i) {
                           return (i.param.tensor ? std::string(cell_name(*i.param.tensor)) : "Tri") + "_P" +
                                  std::to_string(i.param.order);
                         });
