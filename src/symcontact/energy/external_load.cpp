#include "symcontact/energy/external_load.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include "symcontact/fem/shape_functions.hpp"

namespace symcontact {

namespace {
/// The quadrature degree of a load integral: `degree` + the cell's order, + 1 for the factor r.
int load_degree(AnalysisModel model, int degree, CellType t) {
  return degree + cell_order(t) + (model == AnalysisModel::kAxisymmetric ? 1 : 0);
}
}  // namespace

VectorXd body_force_vector(const Mesh& mesh, const DofMap& dofs, int body, const BodyForceFn& b,
                           AnalysisModel model, int degree) {
  const int D = mesh.dim;
  VectorXd f = VectorXd::Zero(dofs.num_dofs());
  double bx[3], xq[3];
  for (const CellBlock& block : mesh.cell_blocks) {
    const int NN = cell_num_nodes(block.type);
    const Tabulation tab = tabulate(block.type, cell_quadrature(block.type, load_degree(model, degree, block.type)));
    Eigen::MatrixXd X(D, NN);
    for (Index c = block.begin; c < block.end; ++c) {
      const Index* n = mesh.cell(c);
      for (int a = 0; a < NN; ++a) X.col(a) = mesh.x.col(n[a]);
      for (int q = 0; q < tab.rule.size(); ++q) {
        const Eigen::Map<const Eigen::VectorXd> N(tab.N_at(q), NN);
        const Eigen::Map<const Eigen::MatrixXd> dNt(tab.dN_at(q), D, NN);  // column a = ∇_ξ N_a
        const Eigen::MatrixXd J = X * dNt.transpose();
        const Eigen::VectorXd x = X * N;
        for (int i = 0; i < D; ++i) xq[i] = x[i];
        b(xq, bx);
        const double w = tab.rule.weights[q] * J.determinant() * section_measure(model, x[0]);
        for (int a = 0; a < NN; ++a)
          for (int i = 0; i < D; ++i) f[dofs.dof(body, n[a], i)] += w * N[a] * bx[i];
      }
    }
  }
  return f;
}

namespace {
/// Point, outward unit normal and surface-measure factor of a facet at one reference point.
void facet_point(const Eigen::MatrixXd& X, const double* Nq, const double* dNq, int D, int NN, double* x,
                 double* normal, double& dS) {
  const Eigen::Map<const Eigen::VectorXd> N(Nq, NN);
  const Eigen::VectorXd xv = X * N;
  for (int i = 0; i < D; ++i) x[i] = xv[i];
  if (D == 2) {
    Eigen::Vector2d t = Eigen::Vector2d::Zero();
    for (int a = 0; a < NN; ++a) t += X.col(a) * dNq[a];
    dS = t.norm();
    normal[0] = t.y() / dS;  // facet traversed with the body on its left: outward is to the right
    normal[1] = -t.x() / dS;
  } else {
    Vec3 t0 = Vec3::Zero(), t1 = Vec3::Zero();
    for (int a = 0; a < NN; ++a) {
      t0 += X.col(a) * dNq[2 * a];
      t1 += X.col(a) * dNq[2 * a + 1];
    }
    const Vec3 nv = t0.cross(t1);
    dS = nv.norm();
    for (int i = 0; i < 3; ++i) normal[i] = nv[i] / dS;
  }
}
}  // namespace

VectorXd boundary_load_vector(const Mesh& mesh, const DofMap& dofs, int body, const FacetGroup& group,
                              const TractionFn& t, AnalysisModel model, int degree) {
  const int D = mesh.dim;
  const CellType ft = mesh.facet_type_of(group);
  const int NN = cell_num_nodes(ft);
  const Tabulation tab = tabulate(ft, cell_quadrature(ft, load_degree(model, degree, ft)));
  VectorXd f = VectorXd::Zero(dofs.num_dofs());
  Eigen::MatrixXd X(D, NN);
  double x[3], nrm[3], tv[3], dS;
  for (Index k = 0; k < mesh.num_facets(group); ++k) {
    const Index* n = group.facets.data() + k * NN;
    for (int a = 0; a < NN; ++a) X.col(a) = mesh.x.col(n[a]);
    for (int q = 0; q < tab.rule.size(); ++q) {
      facet_point(X, tab.N_at(q), tab.dN_at(q), D, NN, x, nrm, dS);
      t(x, nrm, tv);
      const double w = tab.rule.weights[q] * dS * section_measure(model, x[0]);
      const double* N = tab.N_at(q);
      for (int a = 0; a < NN; ++a)
        for (int i = 0; i < D; ++i) f[dofs.dof(body, n[a], i)] += w * N[a] * tv[i];
    }
  }
  return f;
}

double facet_group_measure(const Mesh& mesh, const FacetGroup& group, Eigen::VectorXd* normal_integral,
                           AnalysisModel model, int degree) {
  const int D = mesh.dim;
  const CellType ft = mesh.facet_type_of(group);
  const int NN = cell_num_nodes(ft);
  const Tabulation tab = tabulate(ft, cell_quadrature(ft, load_degree(model, degree, ft)));
  Eigen::MatrixXd X(D, NN);
  double x[3], nrm[3], dS, m = 0.0;
  if (normal_integral) normal_integral->setZero(D);
  for (Index k = 0; k < mesh.num_facets(group); ++k) {
    const Index* n = group.facets.data() + k * NN;
    for (int a = 0; a < NN; ++a) X.col(a) = mesh.x.col(n[a]);
    for (int q = 0; q < tab.rule.size(); ++q) {
      facet_point(X, tab.N_at(q), tab.dN_at(q), D, NN, x, nrm, dS);
      const double w = tab.rule.weights[q] * dS * section_measure(model, x[0]);
      m += w;
      if (normal_integral)
        for (int i = 0; i < D; ++i) (*normal_integral)[i] += w * nrm[i];
    }
  }
  return m;
}

VectorXd point_load_vector(const DofMap& dofs, int body, const std::vector<Index>& nodes, const double* F) {
  VectorXd f = VectorXd::Zero(dofs.num_dofs());
  for (Index a : nodes)
    for (int i = 0; i < dofs.dim(); ++i) f[dofs.dof(body, a, i)] += F[i];
  return f;
}

}  // namespace symcontact
