// Manufactured-solution convergence of linear elasticity, 2D (plane strain) and 3D, P1 and P2 simplices,
// and quadrilaterals and hexahedra: Q1 (Quad4, Hex8), serendipity (Quad8, Hex20) and Q2 (Quad9, Hex27);
// 6- and 18-node prisms; and meshes of two cell types, quadrilaterals and triangles in a checkerboard (Quad4 + Tri3,
// Quad9 + Tri6).
// Exact field: u_i(x) = A_i Π_d sin(k_id x_d + φ_id); body force b = −div σ(u) with
// div σ = μ Δu + (λ + μ) ∇(div u); Dirichlet data = u on the whole boundary.
// Expected rates (Ciarlet, The Finite Element Method for Elliptic Problems, Thm 3.2.5 and §3.2):
// L2 error O(h^{p+1}), H1 seminorm O(h^p); the same for the serendipity cells, which hold every polynomial of
// degree p = 2 (Ciarlet §3.2, Thm 3.1.6 for the interpolation on Q_k and serendipity elements).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>

#include "symcontact/energy/energy_sum.hpp"
#include "symcontact/energy/external_load.hpp"
#include "symcontact/energy/linear_elastic_energy.hpp"
#include "symcontact/fem/error_norms.hpp"
#include "symcontact/mesh/structured.hpp"
#include "symcontact/solvers/equilibrium_solver.hpp"

using namespace symcontact;

namespace {

struct TrigField {
  int dim;
  double A[3] = {0.3, -0.2, 0.25};
  double k[3][3] = {{1.1, 0.7, 0.9}, {0.8, 1.3, 0.6}, {0.5, 0.9, 1.2}};
  double phi[3][3] = {{0.3, 0.5, 0.2}, {0.1, 0.4, 0.6}, {0.7, 0.2, 0.3}};

  double s(int i, int d, const double* x) const { return std::sin(k[i][d] * x[d] + phi[i][d]); }
  double c(int i, int d, const double* x) const { return k[i][d] * std::cos(k[i][d] * x[d] + phi[i][d]); }
  /// ∂^{a} u_i with a derivative order per coordinate (0, 1 or 2).
  double deriv(int i, const double* x, const int* order) const {
    double v = A[i];
    for (int d = 0; d < dim; ++d) {
      if (order[d] == 0) v *= s(i, d, x);
      if (order[d] == 1) v *= c(i, d, x);
      if (order[d] == 2) v *= -k[i][d] * k[i][d] * s(i, d, x);
    }
    return v;
  }
  void value(const double* x, double* u) const {
    const int z[3] = {0, 0, 0};
    for (int i = 0; i < dim; ++i) u[i] = deriv(i, x, z);
  }
  void gradient(const double* x, double* g) const {
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j) {
        int o[3] = {0, 0, 0};
        o[j] = 1;
        g[i * dim + j] = deriv(i, x, o);
      }
  }
  double second(int i, int a, int b, const double* x) const {
    int o[3] = {0, 0, 0};
    ++o[a];
    ++o[b];
    return deriv(i, x, o);
  }
  void body_force(const double* x, double lambda, double mu, double* b) const {
    for (int i = 0; i < dim; ++i) {
      double lap = 0, graddiv = 0;
      for (int j = 0; j < dim; ++j) {
        lap += second(i, j, j, x);
        graddiv += second(j, i, j, x);
      }
      b[i] = -(mu * lap + (lambda + mu) * graddiv);
    }
  }
};

/// The unit square or cube: structured simplices of `order`, or n^dim cells of the tensor type `tensor`, every
/// other one cut into two triangles when `mixed`.
Mesh unit_mesh(int dim, int order, std::optional<CellType> tensor, int n, bool mixed) {
  if (tensor && mixed) return mixed_rectangle_mesh(*tensor, 0, 0, 1, 1, n, n);
  if (tensor) return structured_mesh(*tensor, Vec3(0, 0, 0), Vec3(1, 1, 1), n, n, n);
  return dim == 2 ? rectangle_mesh(0, 0, 1, 1, n, n, order) : box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), n, n, n, order);
}

ErrorNorms solve_manufactured(int dim, int order, std::optional<CellType> tensor, int n, bool mixed) {
  const Mesh m = unit_mesh(dim, order, tensor, n, mixed);
  if (mixed && !m.mixed()) ADD_FAILURE() << "expected a mesh of two cell types";
  DofMap dofs(dim);
  dofs.add_body(m.num_nodes());
  const auto mat = LinearElastic::from_young_poisson(1.0, 0.3, dim == 2 ? AnalysisModel::kPlaneStrain : AnalysisModel::kThreeD);
  TrigField u{dim};
  EnergySum energy;
  energy.add(std::make_unique<LinearElasticEnergy>(m, dofs, 0, mat, "cube"));
  energy.add(std::make_unique<LinearLoad>(
      "b", body_force_vector(m, dofs, 0, [&](const double* x, double* b) { u.body_force(x, mat.lambda, mat.mu, b); },
                                 AnalysisModel::kPlaneStrain, 4)));
  FixedDofs fixed;
  for (const auto& [name, g] : m.facet_groups)
    for (Index v : g.facets) {
      double uv[3];
      u.value(m.x.col(v).data(), uv);
      for (int i = 0; i < dim; ++i) fixed.fix(dofs.dof(0, v, i), uv[i]);
    }
  VectorXd sol = VectorXd::Zero(dofs.num_dofs());
  solve_equilibrium(energy, fixed, sol);
  return compute_errors(
      m, dofs, 0, sol, [&](const double* x, double* out) { u.value(x, out); },
      [&](const double* x, double* out) { u.gradient(x, out); });
}

struct Study {
  int dim, order;
  std::vector<int> n;
  std::optional<CellType> tensor;  ///< a quadrilateral or hexahedron type; none: simplices
  bool mixed = false;              ///< every other quadrilateral cut into two triangles
};

class ManufacturedConvergence : public ::testing::TestWithParam<Study> {};

}  // namespace

TEST_P(ManufacturedConvergence, RatesMatchTheory) {
  const Study st = GetParam();
  std::vector<ErrorNorms> e;
  for (int n : st.n) e.push_back(solve_manufactured(st.dim, st.order, st.tensor, n, st.mixed));
  std::printf("  %dD %s%s   h        L2 error     rate   H1 error     rate\n", st.dim,
              st.tensor ? cell_name(*st.tensor).c_str() : ("P" + std::to_string(st.order)).c_str(),
              st.mixed ? " + triangles" : "");
  double rate_l2 = 0, rate_h1 = 0;
  for (std::size_t k = 0; k < e.size(); ++k) {
    if (k > 0) {
      const double r = std::log(double(st.n[k]) / st.n[k - 1]);
      rate_l2 = std::log(e[k - 1].l2 / e[k].l2) / r;
      rate_h1 = std::log(e[k - 1].h1_semi / e[k].h1_semi) / r;
    }
    std::printf("        1/%-4d  %.4e  %5.2f  %.4e  %5.2f\n", st.n[k], e[k].l2, k ? rate_l2 : 0.0, e[k].h1_semi,
                k ? rate_h1 : 0.0);
  }
  // Asserted on the finest pair.
  EXPECT_NEAR(rate_l2, st.order + 1, 0.2);
  EXPECT_NEAR(rate_h1, st.order, 0.2);
}

INSTANTIATE_TEST_SUITE_P(Elasticity, ManufacturedConvergence,
                         ::testing::Values(Study{2, 1, {8, 16, 32, 64}, {}}, Study{2, 2, {4, 8, 16, 32}, {}},
                                           Study{3, 1, {4, 8, 16}, {}}, Study{3, 2, {2, 4, 8}, {}}),
                         [](const auto& p) {
                           return "D" + std::to_string(p.param.dim) + "P" + std::to_string(p.param.order);
                         });

INSTANTIATE_TEST_SUITE_P(
    ElasticityTensorCells, ManufacturedConvergence,
    ::testing::Values(Study{2, 1, {8, 16, 32}, CellType::kQuad4}, Study{2, 2, {4, 8, 16}, CellType::kQuad8},
                      Study{2, 2, {4, 8, 16}, CellType::kQuad9}, Study{3, 1, {2, 4, 8}, CellType::kHex8},
                      Study{3, 2, {2, 4, 8}, CellType::kHex20}, Study{3, 2, {2, 4, 8}, CellType::kHex27},
                      Study{3, 1, {4, 8, 16}, CellType::kPrism6}, Study{3, 2, {2, 4, 8}, CellType::kPrism18},
                      Study{3, 2, {2, 4, 8}, CellType::kPrism15}, Study{3, 1, {2, 4, 8}, CellType::kPyramid5},
                      Study{3, 2, {2, 4, 8}, CellType::kPyramid13}, Study{3, 2, {2, 4, 8}, CellType::kPyramid14}),
    [](const auto& p) { return cell_name(*p.param.tensor); });

INSTANTIATE_TEST_SUITE_P(
    ElasticityMixedCells, ManufacturedConvergence,
    ::testing::Values(Study{2, 1, {8, 16, 32}, CellType::kQuad4, true}, Study{2, 2, {4, 8, 16}, CellType::kQuad9, true}),
    [](const auto& p) { return cell_name(*p.param.tensor) + "WithTriangles"; });
