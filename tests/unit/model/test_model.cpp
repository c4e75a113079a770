// Tests of the discrete model (src/symcontact/model/model.hpp) on small structured meshes: the DOF numbering
// of several bodies, the Dirichlet values and loads of each load step and of fractions of a step
// (fixed_dofs(), set_step()), and the reactions of a solved problem.

#include "symcontact/model/model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "support/model_case.hpp"
#include "support/problem_snippet.hpp"
#include "support/rectangle_msh.hpp"
#include "support/temp_folder.hpp"
#include "symcontact/core/error.hpp"
#include "symcontact/solvers/equilibrium_solver.hpp"

namespace symcontact {
namespace {

namespace fs = std::filesystem;
using testing::ProblemSnippet;

/// A 2 × 1 block (block.msh: 2 × 1 squares, 6 nodes) clamped at its bottom, its left side moved by ux = 0.1
/// and its top by uy = −0.3, over two load steps at factors 0.5 and 1.
const ProblemSnippet kBlock =
    testing::clamped_block() + testing::dirichlet_toml("left", "ux = 0.1\n") + testing::dirichlet_toml("top", "uy = -0.3\n");

/// A problem and its model (the model refers to the spec, so both live here), built from `text` with the
/// meshes block.msh (2 × 1, 2 × 1 squares) and lid.msh (1 × 1, one square) in a temporary folder.
class ModelTest : public ::testing::Test {
 protected:
  void build(const std::string& text) {
    testing::write_rectangle_msh(folder_ / "block.msh", 2.0, 1.0, 2, 1);
    testing::write_rectangle_msh(folder_ / "lid.msh", 1.0, 1.0, 1, 1);
    case_ = testing::build_model(text, folder_.path());
    model_ = case_->model.get();
  }
  /// The global DOF of component `comp` of the node of body `body` at (x, y).
  Index dof_at(int body, double x, double y, int comp) const {
    const Mesh& mesh = model_->bodies()[body]->mesh;
    for (Index a = 0; a < mesh.num_nodes(); ++a)
      if (std::abs(mesh.x(0, a) - x) < 1e-12 && std::abs(mesh.x(1, a) - y) < 1e-12)
        return model_->dofs().dof(body, a, comp);
    ADD_FAILURE() << "no node at (" << x << ", " << y << ")";
    return 0;
  }
  /// The Dirichlet values of `fixed` as a full vector (zero on free DOFs).
  VectorXd imposed(const FixedDofs& fixed) const {
    VectorXd u = VectorXd::Zero(model_->dofs().num_dofs());
    fixed.impose(u);
    return u;
  }
  /// Σ of component `comp` of the external load vector.
  double total_load(int comp) const {
    const VectorXd f = model_->external_load();
    double s = 0.0;
    for (Index d = comp; d < f.size(); d += model_->dim()) s += f[d];
    return s;
  }

  const testing::TempFolder folder_;
  std::unique_ptr<testing::ModelCase> case_;
  Model* model_ = nullptr;
};

TEST_F(ModelTest, DofNumberingOfTwoBodies) {
  build(kBlock + testing::body_toml("lid", "lid.msh", "block", "E = 2.0, nu = 0.25",
                                    testing::dirichlet_toml("bottom", "uy = 0.0\n")));
  EXPECT_EQ(model_->dim(), 2);
  EXPECT_EQ(model_->num_steps(), 2);
  ASSERT_EQ(model_->bodies().size(), 2u);
  EXPECT_EQ(model_->bodies()[0]->mesh.num_nodes(), 6);
  EXPECT_EQ(model_->bodies()[1]->mesh.num_nodes(), 4);
  EXPECT_EQ(model_->dofs().num_dofs(), 2 * (6 + 4));
  EXPECT_EQ(model_->dofs().dof(1, 0, 0), 12);  // the lid's DOFs follow the block's
  EXPECT_EQ(model_->dofs().dof(1, 3, 1), 19);
  EXPECT_EQ(model_->body_index("lid"), 1);
  EXPECT_EQ(model_->body_index("block"), 0);
  EXPECT_EQ(model_->body_index("nobody"), -1);
  // One Dirichlet boundary per condition, in problem-file order, with its body and nodes.
  const std::vector<DirichletBoundary>& b = model_->dirichlet_boundaries();
  ASSERT_EQ(b.size(), 4u);
  EXPECT_EQ(b[0].name, "bottom");
  EXPECT_EQ(b[0].nodes.size(), 3u);
  EXPECT_EQ(b[1].name, "left");
  EXPECT_EQ(b[1].nodes.size(), 2u);
  EXPECT_EQ(b[3].body, 1);
  EXPECT_EQ(b[3].nodes.size(), 2u);
  // The lid's bottom holds its uy only, at the lid's own DOFs.
  const std::vector<int> owner = model_->fixed_dofs(1).owner_of(model_->dofs().num_dofs());
  EXPECT_EQ(owner[dof_at(1, 0.0, 0.0, 1)], 3);
  EXPECT_EQ(owner[dof_at(1, 0.0, 0.0, 0)], -1);
}

TEST_F(ModelTest, DirichletValuesAtEachStepAndBetweenSteps) {
  build(kBlock);
  const Index corner_x = dof_at(0, 0.0, 0.0, 0), corner_y = dof_at(0, 0.0, 0.0, 1);
  const Index top_left_x = dof_at(0, 0.0, 1.0, 0), top_right_y = dof_at(0, 2.0, 1.0, 1);
  const Index top_mid_x = dof_at(0, 1.0, 1.0, 0);
  // (step, fraction) → the factor: the step's own, or linear from the previous step (0 before step 0).
  const struct {
    int step;
    double fraction, factor;
  } cases[] = {{0, 1.0, 0.5}, {1, 1.0, 1.0}, {1, 0.5, 0.75}, {0, 0.5, 0.25}, {0, 0.0, 0.0}};
  for (const auto& c : cases) {
    SCOPED_TRACE("step " + std::to_string(c.step) + ", fraction " + std::to_string(c.fraction));
    const FixedDofs fixed = model_->fixed_dofs(c.step, c.fraction);
    const VectorXd u = imposed(fixed);
    EXPECT_DOUBLE_EQ(u[corner_x], 0.1 * c.factor);  // named by bottom, then left: the last one holds
    EXPECT_EQ(u[corner_y], 0.0);
    EXPECT_DOUBLE_EQ(u[top_left_x], 0.1 * c.factor);
    EXPECT_DOUBLE_EQ(u[top_right_y], -0.3 * c.factor);
    std::vector<Index> free_index;
    // 12 DOFs; fixed: bottom 3 × 2, left adds the top-left ux, top 3 × uy: the top ux of x = 1, 2 stay free.
    EXPECT_EQ(fixed.free_numbering(model_->dofs().num_dofs(), free_index), 2);
    EXPECT_GE(free_index[top_mid_x], 0);
  }
  const std::vector<int> owner = model_->fixed_dofs(1).owner_of(model_->dofs().num_dofs());
  EXPECT_EQ(owner[corner_x], 1);  // left, given after bottom
  EXPECT_EQ(owner[corner_y], 0);
  EXPECT_EQ(owner[top_right_y], 2);
}

TEST_F(ModelTest, OwnDirichletFactorsReplaceTheGlobalOnes) {
  build(kBlock.after("uy = -0.3\n", "factors = [1.0, 0.0]\n"));
  const Index top_right_y = dof_at(0, 2.0, 1.0, 1), corner_x = dof_at(0, 0.0, 0.0, 0);
  EXPECT_DOUBLE_EQ(imposed(model_->fixed_dofs(0))[top_right_y], -0.3);
  EXPECT_DOUBLE_EQ(imposed(model_->fixed_dofs(1))[top_right_y], 0.0);
  EXPECT_DOUBLE_EQ(imposed(model_->fixed_dofs(1, 0.25))[top_right_y], -0.3 * 0.75);
  EXPECT_DOUBLE_EQ(imposed(model_->fixed_dofs(0, 0.5))[top_right_y], -0.15);
  EXPECT_DOUBLE_EQ(imposed(model_->fixed_dofs(1, 0.25))[corner_x], 0.1 * 0.625);  // the others: global
}

TEST_F(ModelTest, LoadsFollowTheirFactorsThroughSetStep) {
  // A traction on the right side (length 1) with the global factors, a body force over the area 2 with its
  // own, a pressure on the top (length 2, outward normal +y) with its own.
  build(kBlock.after("group = \"block\"\n", "body_force = [0.0, -1.0]\nbody_force_factors = [0.0, 1.0]\n") +
        "[[body.traction]]\nboundary = \"right\"\ntraction = [2.0, 0.0]\n"
        "[[body.pressure]]\nboundary = \"top\"\npressure = 3.0\nfactors = [1.0, 1.0]\n");
  const struct {
    int step;
    double fraction, fx, fy;
  } cases[] = {{0, 1.0, 2.0 * 0.5, -6.0},
               {1, 1.0, 2.0, -2.0 - 6.0},
               {1, 0.5, 2.0 * 0.75, -2.0 * 0.5 - 6.0},
               {0, 0.5, 2.0 * 0.25, -6.0 * 0.5}};
  for (const auto& c : cases) {
    SCOPED_TRACE("step " + std::to_string(c.step) + ", fraction " + std::to_string(c.fraction));
    model_->set_step(c.step, c.fraction);
    EXPECT_NEAR(total_load(0), c.fx, 1e-12);
    EXPECT_NEAR(total_load(1), c.fy, 1e-12);
    // The energy sees the same loads: ∇E(0) = −f (the elastic part vanishes at u = 0).
    VectorXd g = VectorXd::Zero(model_->dofs().num_dofs());
    model_->energy().add_gradient(VectorXd::Zero(g.size()), g);
    EXPECT_LT((g + model_->external_load()).lpNorm<Eigen::Infinity>(), 1e-12);
  }
}

TEST_F(ModelTest, ReactionsBalanceTheAppliedLoad) {
  // Clamped at the bottom only, pulled up and sideways on the top: the support carries the whole load.
  build(kBlock.replaced("[[body.dirichlet]]\nboundary = \"left\"\nux = 0.1\n", "")
            .replaced("[[body.dirichlet]]\nboundary = \"top\"\nuy = -0.3\n",
                      "[[body.traction]]\nboundary = \"top\"\ntraction = [0.25, 1.0]\n"));
  model_->set_step(1);
  const FixedDofs fixed = model_->fixed_dofs(1);
  VectorXd u = VectorXd::Zero(model_->dofs().num_dofs());
  solve_equilibrium(model_->energy(), fixed, u);
  VectorXd g = VectorXd::Zero(u.size());
  model_->energy().add_gradient(u, g);
  const std::vector<Eigen::VectorXd> r = model_->reactions(fixed, g);
  ASSERT_EQ(r.size(), 1u);
  // The support's force on the body balances the traction's resultant 2 × (0.25, 1).
  EXPECT_NEAR(r[0][0], -0.5, 1e-10);
  EXPECT_NEAR(r[0][1], -2.0, 1e-10);
}

/// A unit square cut into n × n squares of two triangles each, n a DefineConstant (default 4).
const char* const kSquareGeo = R"(DefineConstant[ n = 4 ];
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n + 1;
Transfinite Surface{1};
Physical Surface("block") = {1};
Physical Curve("bottom") = {1};
)";

TEST_F(ModelTest, MeshParametersSetTheGeoConstants) {
  testing::write_text(folder_ / "square.geo", kSquareGeo);
  auto cells = [&](const std::string& parameters) {
    const std::string text = "[problem]\ndimension = 2\n" +
                             testing::body_toml("block", "square.geo", "block", "E = 1.0, nu = 0.3",
                                                parameters + testing::dirichlet_toml("bottom", "ux = 0.0\nuy = 0.0\n"));
    const auto c = testing::build_model(text, folder_.path());
    return c->model->bodies()[0]->mesh.num_cells();
  };
  EXPECT_EQ(cells(""), 2 * 4 * 4);  // the .geo's own n = 4
  EXPECT_EQ(cells("mesh_parameters = { n = 4 }\n"), 2 * 4 * 4);
  EXPECT_EQ(cells("mesh_parameters = { n = 8 }\n"), 2 * 8 * 8);
}

TEST_F(ModelTest, BodiesOfOneGeoWithOtherMeshParametersHaveTheirOwnMesh) {
  testing::write_text(folder_ / "square.geo", kSquareGeo);
  const std::string clamp = testing::dirichlet_toml("bottom", "ux = 0.0\nuy = 0.0\n");
  const auto c = testing::build_model(
      "[problem]\ndimension = 2\n" +
          testing::body_toml("coarse", "square.geo", "block", "E = 1.0, nu = 0.3",
                             "mesh_parameters = { n = 2 }\n" + clamp) +
          testing::body_toml("fine", "square.geo", "block", "E = 1.0, nu = 0.3", "mesh_parameters = { n = 3 }\n" + clamp),
      folder_.path());
  EXPECT_EQ(c->model->bodies()[0]->mesh.num_cells(), 2 * 2 * 2);
  EXPECT_EQ(c->model->bodies()[1]->mesh.num_cells(), 2 * 3 * 3);
}

/// Two unit squares side by side, "left" and "right", both in "bar"; "bottom" under both.
const char* const kBarGeo = R"(Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {2, 0, 0};
Point(4) = {2, 1, 0}; Point(5) = {1, 1, 0}; Point(6) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6}; Line(6) = {6, 1};
Line(7) = {2, 5};
Curve Loop(1) = {1, 7, 5, 6}; Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7}; Plane Surface(2) = {2};
Transfinite Curve{1:7} = 3;
Transfinite Surface{1, 2};
Physical Surface("left") = {1}; Physical Surface("right") = {2}; Physical Surface("bar") = {1, 2};
Physical Curve("bottom") = {1, 2};
)";

/// The bar with a material on each group of `groups` (E = 1 + its index).
std::unique_ptr<testing::ModelCase> build_bar(const testing::TempFolder& folder,
                                              std::initializer_list<const char*> groups) {
  testing::write_text(folder / "bar.geo", kBarGeo);
  std::string materials;
  double E = 1.0;
  for (const char* g : groups)
    materials += "[[body.material]]\ngroup = \"" + std::string(g) + "\"\nE = " + std::to_string(E++) + "\nnu = 0.0\n";
  return testing::build_model("[problem]\ndimension = 2\n[[body]]\nname = \"bar\"\nmesh = \"bar.geo\"\n"
                              "group = \"bar\"\n" + materials +
                                  testing::dirichlet_toml("bottom", "ux = 0.0\nuy = 0.0\n"),
                              folder.path());
}

TEST_F(ModelTest, EachCellTakesTheMaterialOfItsGroup) {
  const auto bar_case = build_bar(folder_, {"left", "right"});
  const Body& bar = *bar_case->model->bodies()[0];
  ASSERT_EQ(bar.materials.size(), 2u);
  EXPECT_EQ(bar.materials[1].mu, 1.0);  // E = 2, nu = 0: mu = E / 2
  ASSERT_EQ(static_cast<Index>(bar.cell_material.size()), bar.mesh.num_cells());
  EXPECT_EQ(bar.mesh.num_cells(), 16);
  for (Index c = 0; c < bar.mesh.num_cells(); ++c) {
    const Index* n = bar.mesh.cell(c);
    const double x = (bar.mesh.x(0, n[0]) + bar.mesh.x(0, n[1]) + bar.mesh.x(0, n[2])) / 3.0;
    EXPECT_EQ(bar.cell_material[c], x < 1.0 ? 0 : 1) << "cell " << c;
  }
}

TEST_F(ModelTest, MaterialGroupsMustCoverEveryCellOnce) {
  auto error_of = [&](std::initializer_list<const char*> groups) {
    const auto e = testing::input_error_of([&] { build_bar(folder_, groups); });
    return e ? e->key() + ": " + e->message() : std::string("no error");
  };
  EXPECT_EQ(error_of({"left", "middle"}),
            "body[0].material[1].group: body 'bar' (mesh bar.geo) has no physical group 'middle' of dimension 2 among "
            "its cells; its groups of cells: 'bar', 'left', 'right'");
  EXPECT_NE(error_of({"left", "bar"}).find("body[0].material[1].group: body 'bar' (mesh bar.geo): element "),
            std::string::npos);
  EXPECT_NE(error_of({"left", "bar"}).find("is in group 'bar' and in group 'left' (body[0].material[0]): each cell "
                                           "takes one material"),
            std::string::npos);
  EXPECT_NE(error_of({"left"}).find("body[0].material: body 'bar' (mesh bar.geo): element "), std::string::npos);
  EXPECT_NE(error_of({"left"}).find(" and 7 other cells are in no material's group"), std::string::npos);
}

// A Dirichlet expression is evaluated at each node's reference coordinates with t = the condition's load
// factor, as written (not multiplied by the factor); numbers beside it keep their meaning.
TEST_F(ModelTest, DirichletExpressionsAreEvaluatedAtTheNodesWithTheLoadFactor) {
  build(kBlock.replaced("uy = -0.3\n", "uy = \"x*t^2 - y\"\nux = 0.2\n"));
  const Index top_right_y = dof_at(0, 2.0, 1.0, 1), top_mid_y = dof_at(0, 1.0, 1.0, 1);
  const Index top_mid_x = dof_at(0, 1.0, 1.0, 0);
  for (const auto& [step, fraction, t] : {std::tuple{0, 1.0, 0.5}, {1, 1.0, 1.0}, {1, 0.5, 0.75}, {0, 0.0, 0.0}}) {
    SCOPED_TRACE("step " + std::to_string(step) + ", fraction " + std::to_string(fraction));
    const VectorXd u = imposed(model_->fixed_dofs(step, fraction));
    EXPECT_EQ(u[top_right_y], 2.0 * t * t - 1.0);
    EXPECT_EQ(u[top_mid_y], 1.0 * t * t - 1.0);
    EXPECT_EQ(u[top_mid_x], 0.2 * t);
  }
}

// Pressures that vary along the boundary: the nodal forces' resultant and first moment equal the integrals
// of the closed form (exact: the quadrature integrates a linear pressure times the linear shape functions).
// An expression that is not linear in t is assembled again at each factor.
TEST_F(ModelTest, VaryingPressureMatchesItsClosedFormResultant) {
  // Right side x = 2, y ∈ [0, 1], outward normal +x: p = 10 (1 − y) t (hydrostatic), so
  //   Σ f_x = −∫ p dy = −5 t,  Σ f_x y = −∫ p y dy = −10 t / 6.
  // Top y = 1, x ∈ [0, 2], outward normal +y: p = 3 x t², so Σ f_y = −6 t², Σ f_y x = −8 t².
  build(kBlock + "[[body.pressure]]\nboundary = \"right\"\npressure = \"10*(1 - y)*t\"\n"
                 "[[body.pressure]]\nboundary = \"top\"\npressure = \"3*x*t^2\"\n");
  const Mesh& mesh = model_->bodies()[0]->mesh;
  for (const auto& [step, fraction, t] : {std::tuple{0, 1.0, 0.5}, {1, 1.0, 1.0}, {1, 0.5, 0.75}}) {
    SCOPED_TRACE("step " + std::to_string(step) + ", fraction " + std::to_string(fraction));
    model_->set_step(step, fraction);
    const VectorXd f = model_->external_load();
    double fx = 0, fx_y = 0, fy = 0, fy_x = 0;
    for (Index a = 0; a < mesh.num_nodes(); ++a) {
      fx += f[model_->dofs().dof(0, a, 0)];
      fx_y += f[model_->dofs().dof(0, a, 0)] * mesh.x(1, a);
      fy += f[model_->dofs().dof(0, a, 1)];
      fy_x += f[model_->dofs().dof(0, a, 1)] * mesh.x(0, a);
    }
    EXPECT_NEAR(fx, -5.0 * t, 1e-12);
    EXPECT_NEAR(fx_y, -10.0 * t / 6.0, 1e-12);
    EXPECT_NEAR(fy, -6.0 * t * t, 1e-12);
    EXPECT_NEAR(fy_x, -8.0 * t * t, 1e-12);
    VectorXd g = VectorXd::Zero(f.size());  // the energy sees the same load: ∇E(0) = −f
    model_->energy().add_gradient(VectorXd::Zero(g.size()), g);
    EXPECT_LT((g + f).lpNorm<Eigen::Infinity>(), 1e-12);
  }
}

// An expression that is not finite at a node of its group, at t = 0, 1 or a step's factor, is an input error
// naming the key, the node and t.
TEST_F(ModelTest, NonFiniteExpressionIsAnInputErrorNamingTheNode) {
  const struct {
    std::string text, key, fragment;
  } cases[] = {
      {kBlock.replaced("uy = -0.3", "uy = \"1/(x - 2)\""), "body[0].dirichlet[2].uy",
       "the expression \"1/(x - 2)\" is inf at t = 0, at the node (x, y, z) = (2, 1, 0)"},
      {kBlock + "[[body.traction]]\nboundary = \"right\"\ntraction = [0, \"sqrt(0.75 - t)*y\"]\n",
       "body[0].traction[0].traction[1]", "is NaN at t = 1, at the node (x, y, z) = (2, "},
      {kBlock + "[[body.pressure]]\nboundary = \"top\"\npressure = \"log(t - 0.5)\"\n",
       "body[0].pressure[0].pressure", "\"log(t - 0.5)\" is NaN at t = 0, at the node (x, y, z) = ("},
  };
  for (const auto& c : cases) {
    try {
      build(c.text);
      ADD_FAILURE() << "expected an InputError for " << c.key;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), "case.toml");
      EXPECT_EQ(e.key(), c.key);
      EXPECT_NE(e.message().find(c.fragment), std::string::npos) << e.what();
    }
  }
}

TEST_F(ModelTest, MissingDirichletGroupIsAnInputError) {
  try {
    build(kBlock.replaced("boundary = \"left\"", "boundary = \"nowhere\""));
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "case.toml");
    EXPECT_EQ(e.key(), "body[0].dirichlet[1].boundary");
    EXPECT_NE(e.message().find("has no group 'nowhere'"), std::string::npos) << e.what();
  }
}

TEST_F(ModelTest, PointLoadActsAtItsNodeWithItsFactors) {
  // corner_lr, the physical point at (2, 0) of block.msh; factors 0.5 and 1 (the global ones), then its own.
  build(kBlock + "[[body.point_load]]\ngroup = \"corner_lr\"\nforce = [3.0, -1.5]\n"
                 "[[body.point_load]]\ngroup = \"corner_ll\"\nforce = [0.0, 2.0]\nfactors = [1.0, 0.0]\n");
  for (int step : {0, 1}) {
    model_->set_step(step);
    const double s = step == 0 ? 0.5 : 1.0, own = step == 0 ? 1.0 : 0.0;
    const VectorXd f = model_->external_load();
    EXPECT_EQ(f[dof_at(0, 2.0, 0.0, 0)], 3.0 * s);
    EXPECT_EQ(f[dof_at(0, 2.0, 0.0, 1)], -1.5 * s);
    EXPECT_EQ(f[dof_at(0, 0.0, 0.0, 1)], 2.0 * own);
    EXPECT_EQ(f.lpNorm<1>(), 4.5 * s + 2.0 * own) << "no force at any other DOF";
  }
}

TEST_F(ModelTest, PointLoadOnABoundaryOrMissingGroupIsAnInputError) {
  const struct {
    std::string group, fragment;
  } cases[] = {{"top", "expected a physical point group, got 'top', a boundary group (dimension 1) of body 'block' (mesh block.msh)"},
               {"nowhere", "body 'block' (mesh block.msh) has no physical point group 'nowhere'; its groups: 'bottom'"}};
  for (const auto& c : cases) {
    try {
      build(kBlock + "[[body.point_load]]\ngroup = \"" + c.group + "\"\nforce = [1.0, 0.0]\n");
      ADD_FAILURE() << "expected an InputError for " << c.group;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), "case.toml");
      EXPECT_EQ(e.key(), "body[0].point_load[0].group");
      EXPECT_NE(e.message().find(c.fragment), std::string::npos) << e.what();
    }
  }
}

/// A quarter disk of radius 1 (2D) or a quarter cylinder of it, height 0.5 (3D), coarsely meshed (h = 0.3),
/// its arc (the curved face) "arc", in 3D a physical curve "axis_edge" (its bottom edge on the x axis).
std::string quarter_disk_geo(int dim) {
  std::string geo =
      "h = 0.3;\nPoint(1) = {0, 0, 0, h};\nPoint(2) = {1, 0, 0, h};\nPoint(3) = {0, 1, 0, h};\n"
      "Line(1) = {1, 2};\nCircle(2) = {2, 1, 3};\nLine(3) = {3, 1};\nCurve Loop(1) = {1, 2, 3};\n"
      "Plane Surface(1) = {1};\n";
  if (dim == 2)
    return geo + "Physical Surface(\"disk\") = {1};\nPhysical Curve(\"arc\") = {2};\n"
                 "Physical Curve(\"left\") = {3};\n";
  return geo + "out[] = Extrude {0, 0, 0.5} { Surface{1}; };\nPhysical Volume(\"disk\") = {out[1]};\n"
               "Physical Surface(\"arc\") = {out[3]};\nPhysical Surface(\"left\") = {out[4]};\n"
               "Physical Curve(\"axis_edge\") = {1};\n";
}

TEST_F(ModelTest, TotalForceIsTheResultantOnACurvedFacetedSurface) {
  // t = F / |Γ_h| with |Γ_h| the measure of the facets by the load's own quadrature: Σ f = F to round-off,
  // though |Γ_h| is not the exact arc length (π/2) nor cylinder area (π/4), and differs between P1 and P2.
  for (int dim : {2, 3})
    for (int order : {1, 2}) {
      SCOPED_TRACE("dimension " + std::to_string(dim) + ", order " + std::to_string(order));
      testing::write_text(folder_ / "disk.geo", quarter_disk_geo(dim));
      const std::string F = dim == 2 ? "[0.7, -1.3]" : "[0.7, -1.3, 0.4]";
      const std::string toml = "[problem]\ndimension = " + std::to_string(dim) + "\norder = " + std::to_string(order) +
                               "\n[steps]\nload_factors = [0.5, 1.0]\n" +
                               testing::body_toml("disk", "disk.geo", "disk", "E = 1.0, nu = 0.3",
                                                  testing::dirichlet_toml("left", "ux = 0.0\n") +
                                                      "[[body.traction]]\nboundary = \"arc\"\ntotal_force = " + F + "\n");
      case_ = testing::build_model(toml, folder_.path());
      model_ = case_->model.get();
      model_->set_step(1);
      const double expected[] = {0.7, -1.3, 0.4};
      for (int i = 0; i < dim; ++i) EXPECT_NEAR(total_load(i), expected[i], 1e-12 * 1.3) << "component " << i;
      const Mesh& mesh = model_->bodies()[0]->mesh;
      const double measure = facet_group_measure(mesh, mesh.facet_groups.at("arc"));
      EXPECT_GT(std::abs(measure / (dim == 2 ? M_PI / 2 : M_PI / 4) - 1), 1e-6) << "the faceting changes the measure";
      model_->set_step(0);
      EXPECT_NEAR(total_load(1), -1.3 * 0.5, 1e-12);
    }
}

TEST_F(ModelTest, PointLoadOnAPhysicalCurveIn3DIsAnInputError) {
  testing::write_text(folder_ / "disk.geo", quarter_disk_geo(3));
  const std::string toml = "[problem]\ndimension = 3\n[steps]\nload_factors = [1.0]\n" +
                           testing::body_toml("disk", "disk.geo", "disk", "E = 1.0, nu = 0.3",
                                              testing::dirichlet_toml("left", "ux = 0.0\n") +
                                                  "[[body.point_load]]\ngroup = \"axis_edge\"\nforce = [1, 0, 0]\n");
  try {
    testing::build_model(toml, folder_.path());
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "body[0].point_load[0].group");
    EXPECT_NE(e.message().find("expected a physical point group, got 'axis_edge', a group of dimension 1"),
              std::string::npos)
        << e.what();
  }
}

// An axisymmetric body whose section touches the axis (block.msh's left side, x = 0) with u_r free there: one
// warning naming the body and the nodes; none once ux = 0 holds the axis, and none in plane strain.
TEST_F(ModelTest, AxisNodesWithAFreeRadialDisplacementAreAWarning) {
  const ProblemSnippet axisymmetric = kBlock.after("dimension = 2\n", "model = \"axisymmetric\"\n");
  build(axisymmetric);  // the bottom holds (0, 0); left holds ux = 0.1 (not 0, yet held): no warning
  EXPECT_TRUE(model_->warnings().empty());
  build(testing::clamped_block().after("dimension = 2\n", "model = \"axisymmetric\"\n") +
        testing::dirichlet_toml("left", "uy = 0.0\n"));
  ASSERT_EQ(model_->warnings().size(), 1u);
  const std::string& w = model_->warnings()[0];
  EXPECT_NE(w.find("body 'block': 1 node on the axis (x = r = 0) with u_r free"), std::string::npos) << w;
  EXPECT_NE(w.find("at y = 1"), std::string::npos) << w;
  build(testing::clamped_block());
  EXPECT_TRUE(model_->warnings().empty());
}

// The load factors (step_factor): a step's own factors or the global ones, and within a step (the sub-steps
// of an automatic step cut) linear between step − 1 and step.
TEST(ModelLoads, StepFactorsAreInterpolatedBetweenSteps) {
  const std::vector<double> global = {0.5, 1.0}, own = {0.2, 0.6};
  EXPECT_EQ(step_factor({}, global, 0, 0.5), 0.25);  // from the unloaded start
  EXPECT_EQ(step_factor({}, global, 1, 0.5), 0.75);
  EXPECT_DOUBLE_EQ(step_factor(own, global, 1, 0.25), 0.3);
  EXPECT_EQ(step_factor(own, global, 1, 1.0), 0.6);
  EXPECT_EQ(step_factor(own, global, 1), 0.6);
}

}  // namespace
}  // namespace symcontact
