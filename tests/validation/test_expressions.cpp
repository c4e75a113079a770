// Expressions in the problem file (core/expression.hpp, docs/loads.md "Expressions"): a Dirichlet condition
// written as an expression of x, y, z and the load factor t imposes a finite rigid rotation on the whole
// boundary of a Neo-Hookean body. A rigid motion is stress-free for a hyperelastic law (ψ(R) = 0,
// P(R) = 0), so it is the solution, also inside:
//   u(X) = (R(a t) − I)(X − C),  R the rotation by the angle a t about the axis k through the centre C,
//   R = cos θ I + sin θ [k]× + (1 − cos θ) k kᵀ (Rodrigues), θ = a t;
// the displacement at every node equals it to 1e-10 and the reaction force of every face vanishes to
// round-off. 2D (plane strain, P1 and P2) about the z axis, 3D (P1) about (1, 1, 1)/√3; a = 0.5 (29°),
// reached in two load steps.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "support/solve_case.hpp"

using namespace symcontact;

namespace {

struct RotationCase {
  int dim;
  int order;
};

void PrintTo(const RotationCase& c, std::ostream* os) { *os << c.dim << "D, order " << c.order; }

constexpr double kAngle = 0.5;

Eigen::Vector3d axis(int dim) { return dim == 2 ? Eigen::Vector3d(0, 0, 1) : Eigen::Vector3d(1, 1, 1).normalized(); }

/// Component i of (R(θ) − I)(X − C) as an expression of x, y, z, t, with θ = kAngle t and C = (0.5, 0.5, 0.5)
/// (the z term drops in 2D, where k = e_z makes row and column 3 of R − I zero).
std::string rotation_expression(int dim, int i) {
  const Eigen::Vector3d k = axis(dim);
  const Eigen::Matrix3d K = (Eigen::Matrix3d() << 0, -k.z(), k.y(), k.z(), 0, -k.x(), -k.y(), k.x(), 0).finished();
  const Eigen::Matrix3d kk = k * k.transpose();
  std::ostringstream s;
  s.precision(17);
  const char* X[3] = {"(x - 0.5)", "(y - 0.5)", "(z - 0.5)"};
  // (R − I)_ij = (cos θ − 1)(δ_ij − k_i k_j) + sin θ K_ij.
  for (int j = 0; j < dim; ++j) {
    s << (j ? " + " : "") << "((cos(" << kAngle << "*t) - 1)*(" << (i == j ? 1.0 : 0.0) - kk(i, j) << ") + sin(" << kAngle
      << "*t)*(" << K(i, j) << "))*" << X[j];
  }
  return s.str();
}

Eigen::Vector3d rotation_displacement(int dim, const double* X) {
  const Eigen::Vector3d c(0.5, 0.5, dim == 3 ? 0.5 : 0.0);
  Eigen::Vector3d p(X[0], X[1], dim == 3 ? X[2] : 0.0);
  return Eigen::AngleAxisd(kAngle, axis(dim)).toRotationMatrix() * (p - c) - (p - c);
}

std::string problem(const RotationCase& c) {
  std::ostringstream s;
  s << "[problem]\ndimension = " << c.dim << "\norder = " << c.order << "\n"
    << (c.dim == 3 ? "mesh_size = 0.34\n" : "") << "[steps]\nload_factors = [0.5, 1.0]\n"
    << "[[body]]\nname = \"body\"\nmesh = \"" << (c.dim == 2 ? "square.geo" : "cube.geo") << "\"\ngroup = \""
    << (c.dim == 2 ? "square" : "cube") << "\"\n[body.material]\nmodel = \"neo_hookean\"\nE = 1000.0\nnu = 0.3\n";
  const std::vector<std::string> faces = c.dim == 2 ? std::vector<std::string>{"bottom", "right", "top", "left"}
                                                    : std::vector<std::string>{"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  const char* names[3] = {"ux", "uy", "uz"};
  for (const std::string& f : faces) {
    s << "[[body.dirichlet]]\nboundary = \"" << f << "\"\n";
    for (int i = 0; i < c.dim; ++i) s << names[i] << " = \"" << rotation_expression(c.dim, i) << "\"\n";
  }
  return s.str();
}

class RigidRotation : public ::testing::TestWithParam<RotationCase> {};

TEST_P(RigidRotation, ExpressionDirichletGivesTheStressFreeRotation) {
  const RotationCase c = GetParam();
  const auto solved = symcontact::testing::solve_case(problem(c), std::string(SYMCONTACT_TEST_DATA) + "/geo");
  const Mesh& mesh = solved->model->bodies()[0]->mesh;
  double error = 0.0, largest = 0.0;
  for (Index a = 0; a < mesh.num_nodes(); ++a) {
    const Eigen::Vector3d exact = rotation_displacement(c.dim, &mesh.x(0, a));
    for (int i = 0; i < c.dim; ++i) {
      error = std::max(error, std::abs(solved->u[solved->model->dofs().dof(0, a, i)] - exact[i]));
      largest = std::max(largest, std::abs(exact[i]));
    }
  }
  double reaction = 0.0;
  for (const Eigen::VectorXd& r : solved->reactions.back()) reaction = std::max(reaction, r.lpNorm<Eigen::Infinity>());
  std::printf("%dD order %d: %ld nodes, largest |u| %.3f, |u - u_exact| %.2e, largest reaction %.2e\n", c.dim,
              c.order, static_cast<long>(mesh.num_nodes()), largest, error, reaction);
  EXPECT_GT(largest, 0.2);  // a finite rotation, not a small one
  EXPECT_LT(error, 1e-10);
  EXPECT_LT(reaction, 1e-9);  // E = 1000 on faces of measure ≤ 1: round-off
}

INSTANTIATE_TEST_SUITE_P(Expressions, RigidRotation,
                         ::testing::Values(RotationCase{2, 1}, RotationCase{2, 2}, RotationCase{3, 1}),
                         [](const ::testing::TestParamInfo<RotationCase>& i) {
                           return std::to_string(i.param.dim) + "D_P" + std::to_string(i.param.order);
                         });

}  // namespace
