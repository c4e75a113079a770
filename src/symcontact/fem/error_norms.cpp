#include "symcontact/fem/error_norms.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "symcontact/fem/shape_functions.hpp"

namespace symcontact {

ErrorNorms compute_errors(const Mesh& mesh, const DofMap& dofs, int body, const VectorXd& u,
                          const VectorField& exact, const GradientField& exact_gradient) {
  const int D = mesh.dim;
  double ue[3], ge[9];
  ErrorNorms e;
  for (const CellBlock& block : mesh.cell_blocks) {
    const int NN = cell_num_nodes(block.type);
    const Tabulation tab = tabulate(block.type, cell_quadrature(block.type, 2 * cell_order(block.type) + 4));
    Eigen::MatrixXd X(D, NN), U(D, NN);
    for (Index c = block.begin; c < block.end; ++c) {
      const Index* n = mesh.cell(c);
      for (int a = 0; a < NN; ++a) {
        X.col(a) = mesh.x.col(n[a]);
        for (int i = 0; i < D; ++i) U(i, a) = u[dofs.dof(body, n[a], i)];
      }
      for (int q = 0; q < tab.rule.size(); ++q) {
        const Eigen::Map<const Eigen::VectorXd> N(tab.N_at(q), NN);
        const Eigen::Map<const Eigen::MatrixXd> dNt(tab.dN_at(q), D, NN);  // column a = ∇_ξ N_a
        const Eigen::MatrixXd J = X * dNt.transpose();
        const double w = tab.rule.weights[q] * J.determinant();
        const Eigen::MatrixXd G = J.transpose().partialPivLu().solve(dNt);  // column a = ∇_x N_a
        const Eigen::VectorXd x = X * N;
        exact(x.data(), ue);
        exact_gradient(x.data(), ge);
        const Eigen::VectorXd uh = U * N;
        const Eigen::MatrixXd gh = U * G.transpose();  // (i, j) = ∂u_i/∂x_j
        for (int i = 0; i < D; ++i) {
          e.l2 += w * (uh[i] - ue[i]) * (uh[i] - ue[i]);
          e.l2_exact += w * ue[i] * ue[i];
          for (int j = 0; j < D; ++j) e.h1_semi += w * std::pow(gh(i, j) - ge[i * D + j], 2);
        }
      }
    }
  }
  e.l2 = std::sqrt(e.l2);
  e.h1_semi = std::sqrt(e.h1_semi);
  e.l2_exact = std::sqrt(e.l2_exact);
  return e;
}

}  // namespace symcontact
