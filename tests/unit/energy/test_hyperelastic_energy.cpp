// Finite-difference checks of the assembled hyperelastic energy (STYLE.md §5, shared helper), P1/P2,
// 2D plane strain / 3D, both laws, at random moderate displacements of distorted meshes; the small-strain
// limit of its Hessian is the linear-elastic stiffness; an inverted element throws EvaluationError naming
// the cell.
#include <gtest/gtest.h>

#include <optional>

#include <cmath>
#include <random>
#include <string>

#include "support/finite_difference.hpp"
#include "symcontact/core/error.hpp"
#include "symcontact/energy/hyperelastic_energy.hpp"
#include "symcontact/energy/linear_elastic_energy.hpp"
#include "symcontact/mesh/structured.hpp"

using namespace symcontact;
using symcontact::testing::check_derivatives;
using symcontact::testing::distorted_mesh;

namespace {

/// A smooth displacement of amplitude `scale` (a rotation-free stretch-and-bend field) plus small noise,
/// moderate enough that no element inverts.
VectorXd moderate_displacement(const Mesh& m, const DofMap& dofs, double scale, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> N01;
  VectorXd u(dofs.num_dofs());
  for (Index a = 0; a < m.num_nodes(); ++a)
    for (int i = 0; i < m.dim; ++i) {
      const double x = m.x(0, a), y = m.x(1, a);
      const double smooth = i == 0 ? 0.3 * x + 0.2 * y * y : (i == 1 ? -0.1 * x * y + 0.15 * y : 0.1 * x);
      u[dofs.dof(0, a, i)] = scale * (smooth + 0.05 * N01(rng));
    }
  return u;
}

struct Case {
  int dim, order;
  std::optional<CellType> tensor;  ///< a quadrilateral or hexahedron type; none: simplices
  bool mixed = false;              ///< every other quadrilateral cut into two triangles (Quad4, Quad9)
};
class HyperelasticEnergyDerivatives : public ::testing::TestWithParam<Case> {};

AnalysisModel analysis(int dim) { return dim == 2 ? AnalysisModel::kPlaneStrain : AnalysisModel::kThreeD; }

}  // namespace

TEST_P(HyperelasticEnergyDerivatives, GradientAndHessianMatchFiniteDifferences) {
  const auto [dim, order, tensor, mixed] = GetParam();
  const Mesh m = distorted_mesh(dim, order, tensor, mixed);
  DofMap dofs(dim);
  dofs.add_body(m.num_nodes());
  for (HyperelasticLaw law : {HyperelasticLaw::kNeoHookean, HyperelasticLaw::kMooneyRivlin}) {
    const Hyperelastic mat = Hyperelastic::from_young_poisson(law, 3.0, 0.3);
    const HyperelasticEnergy e(m, dofs, 0, mat, "test");
    EXPECT_FALSE(e.hessian_is_constant());
    for (double scale : {0.05, 0.4}) {
      const auto r = check_derivatives(e, moderate_displacement(m, dofs, scale, 11));
      EXPECT_LT(r.gradient_error, 1e-7) << "law " << static_cast<int>(law) << " scale " << scale;
      EXPECT_LT(r.hessian_error, 1e-7) << "law " << static_cast<int>(law) << " scale " << scale;
    }
  }
}

TEST_P(HyperelasticEnergyDerivatives, SmallStrainLimitIsTheLinearStiffness) {
  const auto [dim, order, tensor, mixed] = GetParam();
  const Mesh m = distorted_mesh(dim, order, tensor, mixed);
  DofMap dofs(dim);
  dofs.add_body(m.num_nodes());
  const LinearElasticEnergy lin(m, dofs, 0, LinearElastic::from_young_poisson(3.0, 0.3, analysis(dim)), "lin");
  TripletSink ls;
  lin.add_hessian(VectorXd::Zero(dofs.num_dofs()), ls);
  const SparseMatrix K = ls.to_matrix(dofs.num_dofs());
  for (HyperelasticLaw law : {HyperelasticLaw::kNeoHookean, HyperelasticLaw::kMooneyRivlin}) {
    const HyperelasticEnergy e(m, dofs, 0, Hyperelastic::from_young_poisson(law, 3.0, 0.3), "test");
    const VectorXd zero = VectorXd::Zero(dofs.num_dofs());
    EXPECT_EQ(e.value(zero), 0.0);
    TripletSink hs;
    e.add_hessian(zero, hs);
    const SparseMatrix H = hs.to_matrix(dofs.num_dofs());
    EXPECT_LT(MatrixXd(H - K).cwiseAbs().maxCoeff(), 1e-13 * MatrixXd(K).cwiseAbs().maxCoeff());
    // Rigid translation: no energy, no force (up to the rounding of Σ_a G_a = 0).
    VectorXd t(dofs.num_dofs());
    for (Index a = 0; a < m.num_nodes(); ++a)
      for (int i = 0; i < dim; ++i) t[dofs.dof(0, a, i)] = 0.7 + i;
    EXPECT_LT(std::abs(e.value(t)), 1e-25);
    VectorXd g = VectorXd::Zero(t.size());
    e.add_gradient(t, g);
    EXPECT_LT(g.cwiseAbs().maxCoeff(), 1e-13);
  }
}

TEST_P(HyperelasticEnergyDerivatives, InvertedElementThrowsEvaluationErrorNamingTheCell) {
  const auto [dim, order, tensor, mixed] = GetParam();
  const Mesh m = distorted_mesh(dim, order, tensor, mixed);
  DofMap dofs(dim);
  dofs.add_body(m.num_nodes());
  const HyperelasticEnergy e(m, dofs, 0, Hyperelastic::from_young_poisson(HyperelasticLaw::kNeoHookean, 3.0, 0.3),
                             "block");
  // u_x = −2x: F = diag(−1, 1, 1), every cell inverted (a reflection); the first one is reported.
  VectorXd u = VectorXd::Zero(dofs.num_dofs());
  for (Index a = 0; a < m.num_nodes(); ++a) u[dofs.dof(0, a, 0)] = -2.0 * m.x(0, a);
  try {
    e.value(u);
    ADD_FAILURE() << "no EvaluationError";
  } catch (const EvaluationError& err) {
    const std::string what = err.what();
    EXPECT_NE(what.find("hyperelastic(block): " + m.cell_label(0) + ":"), std::string::npos) << what;
    EXPECT_NE(what.find("det F"), std::string::npos) << what;
  }
  VectorXd g = VectorXd::Zero(u.size());
  EXPECT_THROW(e.add_gradient(u, g), EvaluationError);
  TripletSink s;
  EXPECT_THROW(e.add_hessian(u, s), EvaluationError);
}

INSTANTIATE_TEST_SUITE_P(AllCells, HyperelasticEnergyDerivatives,
                         ::testing::Values(Case{2, 1, {}}, Case{2, 2, {}}, Case{3, 1, {}}, Case{3, 2, {}},
                                           Case{2, 1, CellType::kQuad4}, Case{2, 2, CellType::kQuad8},
                                           Case{2, 2, CellType::kQuad9}, Case{3, 1, CellType::kHex8},
                                           Case{3, 2, CellType::kHex20}, Case{3, 2, CellType::kHex27},
                                           Case{2, 1, CellType::kQuad4, true}, Case{2, 2, CellType::kQuad9, true},
                                           Case{3, 1, CellType::kPrism6}, Case{3, 2, CellType::kPrism18},
                                           Case{3, 2, CellType::kPrism15}, Case{3, 1, CellType::kPyramid5},
                                           Case{3, 2, CellType::kPyramid13}, Case{3, 2, CellType::kPyramid14}),
                         [](const ::testing::TestParamInfo<Case>& c) {
                           if (c.param.tensor) return cell_name(*c.param.tensor) + (c.param.mixed ? "WithTriangles" : "");
                           return "D" + std::to_string(c.param.dim) + "P" + std::to_string(c.param.order);
                         });
