#include "symcontact/post/stress_recovery.hpp"

#include <cassert>

#include "symcontact/core/error.hpp"
#include "symcontact/fem/cell_dispatch.hpp"
#include "symcontact/fem/element_geometry.hpp"
#include "symcontact/fem/shape_functions.hpp"

namespace symcontact {

Eigen::Matrix<double, 6, 1> to_voigt6(const Eigen::Matrix3d& t) {
  Eigen::Matrix<double, 6, 1> v;
  v << t(0, 0), t(1, 1), t(2, 2), t(0, 1), t(1, 2), t(0, 2);
  return v;
}

PointLaw linear_point_law(const LinearElastic& material) {
  return [material](const Eigen::Matrix3d& H) {
    PointState s;
    s.strain = 0.5 * (H + H.transpose());
    s.stress = material.stress(s.strain);
    s.volume_ratio = (Eigen::Matrix3d::Identity() + H).determinant();
    return s;
  };
}

PointLaw hyperelastic_point_law(const Hyperelastic& material) {
  return [material](const Eigen::Matrix3d& H) {
    PointState s;
    const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + H;  // F₃₃ = 1 in plane strain
    s.strain = 0.5 * (H + H.transpose() + H.transpose() * H);
    s.volume_ratio = F.determinant();
    try {
      Eigen::Matrix3d P;
      material.evaluate_displacement_gradient<3>(H, &P, nullptr);
      s.stress = P * F.transpose() / s.volume_ratio;
      s.stress = 0.5 * (s.stress + s.stress.transpose());  // symmetric up to round-off
    } catch (const EvaluationError&) {
      s.stress.setZero();  // J ≤ 0: no stress exists; J itself marks the point
    }
    return s;
  };
}

BodyFields recover_fields(const Mesh& mesh, const DofMap& dofs, int body, const LinearElastic& material,
                          const VectorXd& u) {
  return recover_fields(mesh, dofs, body, linear_point_law(material), u);
}

BodyFields recover_fields(const Body& body, const DofMap& dofs, int b, const VectorXd& u) {
  std::vector<PointLaw> laws;
  if (body.hyperelastic.empty())
    for (const LinearElastic& m : body.materials) laws.push_back(linear_point_law(m));
  else
    for (const Hyperelastic& m : body.hyperelastic) laws.push_back(hyperelastic_point_law(m));
  return recover_fields(body.mesh, dofs, b, laws, body.cell_material, u, body.materials.front().model);
}

BodyFields recover_fields(const Mesh& mesh, const DofMap& dofs, int body, const PointLaw& law, const VectorXd& u) {
  return recover_fields(mesh, dofs, body, std::vector<PointLaw>{law}, {}, u);
}

BodyFields recover_fields(const Mesh& mesh, const DofMap& dofs, int body, const std::vector<PointLaw>& laws,
                          const std::vector<int>& cell_law, const VectorXd& u, AnalysisModel model) {
  assert(!laws.empty());
  assert(cell_law.empty() || static_cast<Index>(cell_law.size()) == mesh.num_cells());
  BodyFields f;
  const Index nn = mesh.num_nodes(), nc = mesh.num_cells();
  const int D = mesh.dim;
  f.displacement = Eigen::MatrixXd::Zero(3, nn);
  for (Index v = 0; v < nn; ++v)
    for (int i = 0; i < D; ++i) f.displacement(i, v) = u[dofs.dof(body, v, i)];
  f.strain = Eigen::MatrixXd::Zero(6, nn);
  f.stress = Eigen::MatrixXd::Zero(6, nn);
  f.von_mises = Eigen::VectorXd::Zero(nn);
  f.cell_stress = Eigen::MatrixXd::Zero(6, nc);
  f.cell_von_mises = Eigen::VectorXd::Zero(nc);
  f.volume_ratio = Eigen::VectorXd::Zero(nn);
  f.cell_volume_ratio = Eigen::VectorXd::Zero(nc);
  Eigen::VectorXd weight = Eigen::VectorXd::Zero(nn);

  for (const CellBlock& block : mesh.cell_blocks) {
    // Evaluation points: the cell's own nodes (nodal values) and its quadrature points (cell values).
    const CellType t = block.type;
    QuadratureRule at_nodes;
    at_nodes.dim = D;
    at_nodes.points = reference_nodes(t);
    at_nodes.weights.assign(cell_num_nodes(t), 1.0);
    const Tabulation tn = tabulate(t, at_nodes);
    // Cell averages: degree 2(p − 1) on simplices (exact for straight ones), the stiffness rule on
    // quadrilaterals and hexahedra.
    const int degree = cell_shape(t) == CellShape::kTensor ? stiffness_quadrature_degree(t) : 2 * (cell_order(t) - 1);
    const Tabulation tq = tabulate(t, cell_quadrature(t, degree));

    dispatch_cell(t, [&](auto Dc, auto NNc) {
      constexpr int DD = decltype(Dc)::value, NN = decltype(NNc)::value;
      Eigen::Matrix<double, NN, DD> G;
      Eigen::Matrix<double, DD, NN> U;
      const PointLaw* law = &laws[0];
      auto state_at = [&](const Eigen::Matrix<double, DD, NN>& X, const Tabulation& tab, int point, double& det) {
        det = physical_gradients<DD, NN>(X, tab.dN_at(point), G);
        Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
        if (det > 0) H.topLeftCorner<DD, DD>() = U * G;  // ∇_X u
        if (model == AnalysisModel::kAxisymmetric && det > 0) {
          const Eigen::Map<const Eigen::Matrix<double, NN, 1>> N(tab.N_at(point));
          const double R = X.row(0).dot(N);
          H(2, 2) = R > 0 ? U.row(0).dot(N) / R : H(0, 0);
        }
        return (*law)(H);
      };
      for (Index c = block.begin; c < block.end; ++c) {
        law = &laws[cell_law.empty() ? 0 : cell_law[c]];
        const Index* n = mesh.cell(c);
        const auto X = gather_coordinates<DD, NN>(mesh.x, n);
        for (int a = 0; a < NN; ++a) U.col(a) = f.displacement.col(n[a]).template head<DD>();
        double det = 0.0, vol = 0.0, J_avg = 0.0;
        Eigen::Matrix3d sig_avg = Eigen::Matrix3d::Zero();
        for (int q = 0; q < tq.rule.size(); ++q) {
          const PointState s = state_at(X, tq, q, det);
          sig_avg += tq.rule.weights[q] * det * s.stress;
          J_avg += tq.rule.weights[q] * det * s.volume_ratio;
          vol += tq.rule.weights[q] * det;
        }
        if (vol > 0) {
          sig_avg /= vol;
          J_avg /= vol;
        }
        f.cell_stress.col(c) = to_voigt6(sig_avg);
        f.cell_von_mises[c] = von_mises(sig_avg);
        f.cell_volume_ratio[c] = J_avg;
        for (int a = 0; a < NN; ++a) {
          const PointState s = state_at(X, tn, a, det);
          f.strain.col(n[a]) += vol * to_voigt6(s.strain);
          f.stress.col(n[a]) += vol * to_voigt6(s.stress);
          f.volume_ratio[n[a]] += vol * s.volume_ratio;
          weight[n[a]] += vol;
        }
      }
    });
  }
  for (Index v = 0; v < nn; ++v) {
    if (weight[v] > 0) {
      f.strain.col(v) /= weight[v];
      f.stress.col(v) /= weight[v];
      f.volume_ratio[v] /= weight[v];
    }
    Eigen::Matrix3d s;
    const auto& c = f.stress.col(v);
    s << c[0], c[3], c[5], c[3], c[1], c[4], c[5], c[4], c[2];
    f.von_mises[v] = von_mises(s);
  }
  return f;
}

}  // namespace symcontact
