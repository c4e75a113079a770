// Finite-strain hyperelastic bodies (Neo-Hookean, Mooney–Rivlin; materials/hyperelastic.hpp):
//  (a) small-strain limit: with every load scaled by 1e-6 the Newton solution of the hyperelastic energy
//      equals the linear-elastic displacement to 1e-5 relative (P1/P2, 2D plane strain/3D);
//  (b) homogeneous uniaxial stretch of a block up to λ₁ = 2 with free lateral faces (rollers on the
//      symmetry faces): the reaction force on the stretched face equals the closed form P₁₁ × reference
//      area to 1e-8 relative, solved in load steps, Newton starting from the previous step;
//      and the output fields there: Cauchy stress, J and Green–Lagrange strain against the closed form;
//  (c) the same stretch through the problem-file path (reader → Model → reactions), both parameter sets;
//  (d) a large deflection solved in one load step (globalised Newton) equals continuation.
//
// Closed form of (b): for F = diag(λ₁, λ₂, λ₃), principal first Piola stresses P_i = ∂ψ/∂λ_i,
//   Neo-Hookean:   P_i = μ (λ_i − 1/λ_i) + λ ln J / λ_i,
//   Mooney–Rivlin: P_i = C₁ J^{-2/3} (2λ_i − ⅔ I₁/λ_i) + C₂ J^{-4/3} (2λ_i (I₁ − λ_i²) − ⁴⁄₃ I₂/λ_i)
//                        + κ (J − 1) J / λ_i,
// with I₁ = Σλ_j², I₂ = Σ_{j<k} λ_j² λ_k², J = λ₁λ₂λ₃. Uniaxial stress: λ₃ = λ₂ (3D) or λ₃ = 1 (plane
// strain), and λ₂ solves P₂(λ₁, λ₂) = 0 (bisection to machine precision, in the test). The deformation
// is homogeneous, so P1 and P2 elements represent it exactly and the reaction is Σ_a∈face ∂E/∂u_(a,x)
// = P₁₁ × area.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>

#include "symcontact/core/log.hpp"
#include "symcontact/energy/energy_sum.hpp"
#include "symcontact/energy/external_load.hpp"
#include "symcontact/energy/hyperelastic_energy.hpp"
#include "symcontact/energy/linear_elastic_energy.hpp"
#include "symcontact/mesh/structured.hpp"
#include "symcontact/model/model.hpp"
#include "symcontact/model/problem_reader.hpp"
#include "symcontact/post/stress_recovery.hpp"
#include "symcontact/solvers/equilibrium_solver.hpp"

using namespace symcontact;

namespace {

AnalysisModel analysis(int dim) { return dim == 2 ? AnalysisModel::kPlaneStrain : AnalysisModel::kThreeD; }

/// The block [0, 2] × [0, 1] (× [0, 1]): structured simplices of `order`, or cells of the tensor type `tensor`.
Mesh block(int dim, int order, std::optional<CellType> tensor = {}) {
  if (tensor) return structured_mesh(*tensor, Vec3(0, 0, 0), Vec3(2, 1, 1), dim == 2 ? 8 : 4, dim == 2 ? 4 : 2, 2);
  return dim == 2 ? rectangle_mesh(0, 0, 2, 1, 8, 4, order) : box_mesh(Vec3(0, 0, 0), Vec3(2, 1, 1), 4, 2, 2, order);
}

// ---- closed form ----------------------------------------------------------------------------------

/// P_i for principal stretches l[0..2] (see the file comment).
double principal_stress(const Hyperelastic& m, const double l[3], int i) {
  const double J = l[0] * l[1] * l[2];
  if (m.law == HyperelasticLaw::kNeoHookean) return m.mu * (l[i] - 1.0 / l[i]) + m.lambda * std::log(J) / l[i];
  const double s0 = l[0] * l[0], s1 = l[1] * l[1], s2 = l[2] * l[2];
  const double I1 = s0 + s1 + s2, I2 = s0 * s1 + s1 * s2 + s2 * s0;
  return m.c1 * std::pow(J, -2.0 / 3.0) * (2.0 * l[i] - 2.0 / 3.0 * I1 / l[i]) +
         m.c2 * std::pow(J, -4.0 / 3.0) * (2.0 * l[i] * (I1 - l[i] * l[i]) - 4.0 / 3.0 * I2 / l[i]) +
         m.kappa * (J - 1.0) * J / l[i];
}

/// Uniaxial stress at axial stretch l1: the lateral stretch (P₂ = 0) and the axial P₁₁.
std::pair<double, double> uniaxial(const Hyperelastic& m, double l1, int dim) {
  auto P2 = [&](double l2) {
    const double l[3] = {l1, l2, dim == 3 ? l2 : 1.0};
    return principal_stress(m, l, 1);
  };
  double lo = 1e-3, hi = 10.0;
  EXPECT_LT(P2(lo), 0.0);
  EXPECT_GT(P2(hi), 0.0);
  for (int it = 0; it < 200 && hi - lo > 1e-16 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (P2(mid) < 0 ? lo : hi) = mid;
  }
  const double l2 = 0.5 * (lo + hi);
  const double l[3] = {l1, l2, dim == 3 ? l2 : 1.0};
  return {l2, principal_stress(m, l, 0)};
}

// ---- (a) small-strain limit -----------------------------------------------------------------------

/// Cantilever block (2 × 1 (× 1), E = 1) clamped on the left (xmin), a body force and a traction on the
/// top, both × scale. At scale 1 the linear solution has max|u| ≈ 2–3.6 for a block of length 2, a load far
/// beyond small strain; at scale 1e-6 the hyperelastic solution differs from it by O(1e-6) relative.
/// Returns the solution of `elastic` + loads by Newton, the load applied in `steps` equal increments
/// (each solve starting from the previous one); `report` gets the last solve's report.
VectorXd solve_cantilever(const Mesh& m, const DofMap& dofs, std::unique_ptr<EnergyTerm> elastic, double scale,
                          int steps = 1, EquilibriumReport* report = nullptr) {
  const int dim = m.dim;
  EnergySum sum;
  sum.add(std::move(elastic));
  VectorXd bf = body_force_vector(m, dofs, 0, [&](const double* x, double* b) {
    for (int i = 0; i < dim; ++i) b[i] = 0.05 * (i == dim - 1 ? -1.0 : 0.2) * (1.0 + 0.3 * x[0]);
  });
  const auto& top = m.facet_groups.at(dim == 2 ? "top" : "zmax");
  VectorXd tr = boundary_load_vector(m, dofs, 0, top, [&](const double* x, const double*, double* t) {
    for (int i = 0; i < dim; ++i) t[i] = 0.05 * (i == dim - 1 ? -0.5 : 0.3) * x[0];
  });
  auto load = std::make_unique<LinearLoad>("loads", bf + tr);
  LinearLoad& handle = *load;
  sum.add(std::move(load));
  FixedDofs fixed;
  for (Index a : m.group_nodes(dim == 2 ? "left" : "xmin"))
    for (int i = 0; i < dim; ++i) fixed.fix(dofs.dof(0, a, i), 0.0);
  VectorXd u = VectorXd::Zero(dofs.num_dofs());
  for (int k = 1; k <= steps; ++k) {
    handle.set_scale(scale * k / steps);
    const EquilibriumReport rep = solve_equilibrium(sum, fixed, u);
    if (report) *report = rep;
  }
  return u;
}

// ---- (b) uniaxial stretch ---------------------------------------------------------------------------

/// Stretches the block (length 2 along x) to λ₁ = 1 + k Δ for k = 1..steps (Δ = (stretch − 1)/steps) and
/// returns the worst relative reaction error; `newton_iterations` gets the total count.
double uniaxial_stretch_error(const Hyperelastic& mat, int dim, int order, double stretch, int steps,
                              int& newton_iterations, std::optional<CellType> tensor = {}) {
  const Mesh m = block(dim, order, tensor);
  DofMap dofs(dim);
  dofs.add_body(m.num_nodes());
  const HyperelasticEnergy e(m, dofs, 0, mat, "block");
  const char* sym[3] = {dim == 2 ? "left" : "xmin", dim == 2 ? "bottom" : "ymin", "zmin"};
  const std::string pulled = dim == 2 ? "right" : "xmax";
  const double length = 2.0, area = 1.0;  // reference length along x and area of the pulled face
  VectorXd u = VectorXd::Zero(dofs.num_dofs());
  double worst = 0.0;
  newton_iterations = 0;
  for (int k = 1; k <= steps; ++k) {
    const double l1 = 1.0 + (stretch - 1.0) * k / steps;
    FixedDofs fixed;
    for (int i = 0; i < dim; ++i)
      for (Index a : m.group_nodes(sym[i])) fixed.fix(dofs.dof(0, a, i), 0.0);
    const std::vector<Index> face = m.group_nodes(pulled);
    for (Index a : face) fixed.fix(dofs.dof(0, a, 0), (l1 - 1.0) * length);
    newton_iterations += solve_equilibrium(e, fixed, u).iterations;
    VectorXd g = VectorXd::Zero(u.size());
    e.add_gradient(u, g);
    double reaction = 0.0;
    for (Index a : face) reaction += g[dofs.dof(0, a, 0)];
    const auto [l2, P11] = uniaxial(mat, l1, dim);
    const double exact = P11 * area;
    worst = std::max(worst, std::abs(reaction - exact) / std::abs(exact));
    // The lateral stretch too: u_y at the top (y = 1) is (λ₂ − 1).
    double uy = 0.0;
    for (Index a = 0; a < m.num_nodes(); ++a)
      if (m.x(1, a) == 1.0) uy = u[dofs.dof(0, a, 1)];
    EXPECT_NEAR(uy, l2 - 1.0, 1e-9) << "λ₁ = " << l1;
    // Output fields (post/stress_recovery): Cauchy σ_ii = P_i λ_i / J (σ_zz ≠ 0 in plane strain), no
    // shear, J = λ₁λ₂λ₃, the Green–Lagrange strain E_xx = (λ₁² − 1)/2, at every node and cell.
    const double l[3] = {l1, l2, dim == 3 ? l2 : 1.0}, J = l[0] * l[1] * l[2];
    double sig[3];
    for (int i = 0; i < 3; ++i) sig[i] = principal_stress(mat, l, i) * l[i] / J;
    const double sxx = sig[0];
    const double vm = std::sqrt(0.5 * ((sig[0] - sig[1]) * (sig[0] - sig[1]) + (sig[1] - sig[2]) * (sig[1] - sig[2]) +
                                       (sig[2] - sig[0]) * (sig[2] - sig[0])));
    const BodyFields f = recover_fields(m, dofs, 0, hyperelastic_point_law(mat), u);
    for (Index a = 0; a < m.num_nodes(); ++a) {
      for (int c = 0; c < 6; ++c)
        EXPECT_NEAR(f.stress(c, a), c < 3 ? sig[c] : 0.0, 1e-9 * std::abs(sxx)) << "node " << a << ", component " << c;
      EXPECT_NEAR(f.volume_ratio[a], J, 1e-12);
      EXPECT_NEAR(f.strain(0, a), 0.5 * (l1 * l1 - 1.0), 1e-12);
      EXPECT_NEAR(f.von_mises[a], vm, 1e-9 * std::abs(sxx));
    }
    for (Index c = 0; c < m.num_cells(); ++c) {
      EXPECT_NEAR(f.cell_stress(0, c), sxx, 1e-9 * std::abs(sxx));
      EXPECT_NEAR(f.cell_volume_ratio[c], J, 1e-12);
    }
  }
  return worst;
}

std::vector<std::pair<std::string, Hyperelastic>> materials() {
  return {{"neo_hookean", Hyperelastic::from_young_poisson(HyperelasticLaw::kNeoHookean, 1.0, 0.3)},
          {"mooney_rivlin", Hyperelastic::from_young_poisson(HyperelasticLaw::kMooneyRivlin, 1.0, 0.3)},
          {"mooney_rivlin(c1=0.3,c2=0.1,kappa=2)", Hyperelastic::mooney_rivlin(0.3, 0.1, 2.0)}};
}

}  // namespace

TEST(HyperelasticValidation, SmallStrainLimitIsLinearElasticity) {
  for (int dim : {2, 3})
    for (int order : {1, 2}) {
      const Mesh m = block(dim, order);
      DofMap dofs(dim);
      dofs.add_body(m.num_nodes());
      const double E = 1.0, nu = 0.3, scale = 1e-6;
      const VectorXd ul = solve_cantilever(
          m, dofs, std::make_unique<LinearElasticEnergy>(m, dofs, 0, LinearElastic::from_young_poisson(E, nu, analysis(dim)), "b"),
          scale);
      for (HyperelasticLaw law : {HyperelasticLaw::kNeoHookean, HyperelasticLaw::kMooneyRivlin}) {
        const VectorXd uh = solve_cantilever(
            m, dofs, std::make_unique<HyperelasticEnergy>(m, dofs, 0, Hyperelastic::from_young_poisson(law, E, nu), "b"),
            scale);
        const double err = (uh - ul).cwiseAbs().maxCoeff() / ul.cwiseAbs().maxCoeff();
        EXPECT_LT(err, 1e-5) << "dim " << dim << " order " << order << " law " << static_cast<int>(law);
        // The difference is the geometric/material nonlinearity, O(load): at 1e-6 loads it is ~1e-6.
        std::printf("small-strain limit D%d P%d law %d: max|u_lin| = %.3e (%.3f at scale 1), "
                    "max|u_hyper - u_lin| / max|u_lin| = %.3e\n",
                    dim, order, static_cast<int>(law), ul.cwiseAbs().maxCoeff(), ul.cwiseAbs().maxCoeff() / scale, err);
      }
    }
}

// Load steps for the stretch to λ₁ = 2: four, to check the reaction at λ₁ = 1.25, 1.5, 1.75 and 2.
// (Newton moves the pulled face with a linear predictor, so that a single step to λ₁ = 2 also converges,
// in 5–7 iterations; with the face simply moved, a plain Newton method needed 40 steps before it no
// longer inverted the cells next to it.)
constexpr int kSteps = 4;

TEST(HyperelasticValidation, UniaxialStretchReactionMatchesClosedForm) {
  for (int dim : {2, 3})
    for (int order : {1, 2})
      for (const auto& [name, mat] : materials()) {
        int iterations = 0;
        const double err = uniaxial_stretch_error(mat, dim, order, 2.0, kSteps, iterations);
        EXPECT_LT(err, 1e-8) << name << " dim " << dim << " order " << order;
        std::printf("uniaxial stretch to 2, D%d P%d %-38s: max reaction rel. error %.2e, %d Newton iterations / %d steps\n",
                    dim, order, name.c_str(), err, iterations, kSteps);
      }
}

// The same homogeneous stretch on quadrilaterals and hexahedra of every type (Neo-Hookean): reaction,
// lateral stretch and recovered fields exact, as on simplices.
TEST(HyperelasticValidation, UniaxialStretchOnQuadrilateralsHexahedraPrismsAndPyramids) {
  const auto mat = materials().front().second;
  for (CellType t : {CellType::kQuad4, CellType::kQuad8, CellType::kQuad9, CellType::kHex8, CellType::kHex20,
                     CellType::kHex27, CellType::kPrism6, CellType::kPrism15, CellType::kPrism18, CellType::kPyramid5,
                     CellType::kPyramid13, CellType::kPyramid14}) {
    int iterations = 0;
    const double err = uniaxial_stretch_error(mat, cell_dim(t), cell_order(t), 2.0, kSteps, iterations, t);
    EXPECT_LT(err, 1e-8) << cell_name(t);
    std::printf("uniaxial stretch to 2, %-5s %-38s: max reaction rel. error %.2e, %d Newton iterations / %d steps\n",
                cell_name(t).c_str(), materials().front().first.c_str(), err, iterations, kSteps);
  }
}

// The globalised Newton method (line search, shifted tangent) solves a large deflection in one load
// step: the cantilever at scale 1 bends by ~1–2 lengths of itself; the answer must be the one reached by
// continuation in 20 small steps (the same minimiser), to 1e-8 relative.
TEST(HyperelasticValidation, LargeDeflectionInOneStepMatchesContinuation) {
  for (int dim : {2, 3}) {
    const Mesh m = block(dim, 1);
    DofMap dofs(dim);
    dofs.add_body(m.num_nodes());
    const Hyperelastic mat = Hyperelastic::from_young_poisson(HyperelasticLaw::kNeoHookean, 1.0, 0.3);
    EquilibriumReport one, many;
    const VectorXd u1 = solve_cantilever(m, dofs, std::make_unique<HyperelasticEnergy>(m, dofs, 0, mat, "b"), 1.0, 1, &one);
    const VectorXd u20 = solve_cantilever(m, dofs, std::make_unique<HyperelasticEnergy>(m, dofs, 0, mat, "b"), 1.0, 20, &many);
    const double err = (u1 - u20).cwiseAbs().maxCoeff() / u20.cwiseAbs().maxCoeff();
    EXPECT_LT(err, 1e-8) << "dim " << dim;
    EXPECT_GT(u20.cwiseAbs().maxCoeff(), 0.5) << "the load should be far beyond small strain";
    std::printf("large deflection D%d: max|u| = %.3f; one step: %d Newton iterations, %d halvings, %d shifted "
                "factorisations; |u_1 - u_20|/|u| = %.2e\n",
                dim, u20.cwiseAbs().maxCoeff(), one.iterations, one.backtracks, one.shifted_factorizations, err);
  }
}

TEST(HyperelasticValidation, UniaxialStretchThroughTheProblemFile) {
  const std::string geo = std::string(SYMCONTACT_TEST_DATA) + "/geo/";
  struct Case {
    int dim;
    std::string material;
    Hyperelastic expected;
  };
  const Case cases[] = {
      {2, "model = \"neo_hookean\"\nmu = 0.4\nlambda = 0.6", Hyperelastic::neo_hookean(0.4, 0.6)},
      {2, "model = \"mooney_rivlin\"\nE = 1.0\nnu = 0.3",
       Hyperelastic::from_young_poisson(HyperelasticLaw::kMooneyRivlin, 1.0, 0.3)},
      {3, "model = \"mooney_rivlin\"\nc1 = 0.3\nc2 = 0.1\nkappa = 2.0", Hyperelastic::mooney_rivlin(0.3, 0.1, 2.0)},
      {3, "model = \"neo_hookean\"\nE = 1.0\nnu = 0.3",
       Hyperelastic::from_young_poisson(HyperelasticLaw::kNeoHookean, 1.0, 0.3)},
  };
  std::string factors;  // 20 steps to λ₁ = 2 (see kSteps)
  for (int k = 1; k <= 20; ++k) factors += (k > 1 ? ", " : "") + std::to_string(k / 20.0);
  for (const Case& c : cases) {
    std::ostringstream toml;
    toml << "[problem]\ndimension = " << c.dim << "\n" << (c.dim == 3 ? "mesh_size = 0.5\n" : "")
         << "[steps]\nload_factors = [" << factors << "]\n"
         << "[[body]]\nname = \"block\"\nmesh = \"" << (c.dim == 2 ? "square.geo" : "cube.geo") << "\"\n"
         << "group = \"" << (c.dim == 2 ? "square" : "cube") << "\"\n[body.material]\n" << c.material << "\n";
    const char* sym[3] = {c.dim == 2 ? "left" : "xmin", c.dim == 2 ? "bottom" : "ymin", "zmin"};
    const char* comp[3] = {"ux", "uy", "uz"};
    for (int i = 0; i < c.dim; ++i)
      toml << "[[body.dirichlet]]\nboundary = \"" << sym[i] << "\"\n" << comp[i] << " = 0.0\n";
    toml << "[[body.dirichlet]]\nboundary = \"" << (c.dim == 2 ? "right" : "xmax") << "\"\nux = 1.0\n";
    const ProblemSpec spec = parse_problem(toml.str(), "stretch.toml", geo);
    std::ostringstream sink;
    Logger log(sink, Verbosity::kQuiet);
    PhaseTimes times;
    auto model = Model::build(spec, log, times);
    EXPECT_FALSE(model->energy().hessian_is_constant());
    VectorXd u = VectorXd::Zero(model->dofs().num_dofs());
    double worst = 0.0;
    for (int step = 0; step < model->num_steps(); ++step) {
      model->set_step(step);
      const FixedDofs fixed = model->fixed_dofs(step);
      solve_equilibrium(model->energy(), fixed, u);
      VectorXd g = VectorXd::Zero(u.size());
      model->energy().add_gradient(u, g);
      const auto r = model->reactions(fixed, g);
      const double l1 = 1.0 + spec.load_factors[step];  // unit block, ux = 1 × factor
      const double exact = uniaxial(c.expected, l1, c.dim).second;  // × area 1
      worst = std::max(worst, std::abs(r.back()[0] - exact) / exact);
    }
    EXPECT_LT(worst, 1e-8) << c.material;
    std::string label = c.material;
    std::replace(label.begin(), label.end(), '\n', ' ');
    std::printf("problem file, D%d, %s: max reaction rel. error %.2e\n", c.dim, label.c_str(), worst);
  }
}
