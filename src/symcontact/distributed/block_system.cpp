#include "symcontact/distributed/block_system.hpp"

#include <Eigen/SparseCholesky>

#include "symcontact/energy/linear_elastic_energy.hpp"
#include "symcontact/fem/dof_map.hpp"
#include "symcontact/fem/matrix_sink.hpp"
#include "symcontact/materials/linear_elastic.hpp"
#include "symcontact/mesh/structured.hpp"

namespace symcontact {

BlockSystem clamped_block_system(int dim, int n) {
  BlockSystem s;
  s.mesh = dim == 2 ? rectangle_mesh(0, 0, 1, 1, n, n) : box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), n, n, n);
  DofMap dofs(dim);
  dofs.add_body(s.mesh.num_nodes());
  const auto model = dim == 2 ? AnalysisModel::kPlaneStrain : AnalysisModel::kThreeD;
  const LinearElasticEnergy energy(s.mesh, dofs, 0, LinearElastic::from_young_poisson(1.0, 0.3, model), "block");
  TripletSink sink;
  energy.add_hessian(VectorXd::Zero(dofs.num_dofs()), sink);
  s.K_lower = SparseMatrix(sink.to_matrix(dofs.num_dofs()).triangularView<Eigen::Lower>());
  s.f = VectorXd::Zero(dofs.num_dofs());
  for (Index v = 0; v < s.mesh.num_nodes(); ++v) s.f[dofs.dof(0, v, dim - 1)] = -1e-3;
  std::vector<double> values;
  for (const Index v : s.mesh.group_nodes(dim == 2 ? "bottom" : "zmin"))
    for (int c = 0; c < dim; ++c) {
      s.fixed.push_back(dofs.dof(0, v, c));
      values.push_back(0.0);
    }
  for (const Index v : s.mesh.group_nodes(dim == 2 ? "top" : "zmax")) {
    s.fixed.push_back(dofs.dof(0, v, 0));
    values.push_back(0.01);
  }
  s.fixed_values = Eigen::Map<VectorXd>(values.data(), static_cast<Index>(values.size()));
  return s;
}

VectorXd cholesky_solution(const BlockSystem& s) {
  const Index n = s.f.size();
  VectorXd u = VectorXd::Zero(n);
  std::vector<Index> free_index(n, 0);
  for (std::size_t k = 0; k < s.fixed.size(); ++k) {
    u[s.fixed[k]] = s.fixed_values[static_cast<Index>(k)];
    free_index[s.fixed[k]] = -1;
  }
  Index nf = 0;
  for (Index& i : free_index)
    if (i == 0) i = nf++;
  const SparseMatrix K = SparseMatrix(s.K_lower.selfadjointView<Eigen::Lower>());
  const VectorXd rhs_all = s.f - K * u;
  std::vector<Triplet> t;
  for (int j = 0; j < K.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(K, j); it; ++it)
      if (free_index[it.row()] >= 0 && free_index[j] >= 0) t.emplace_back(free_index[it.row()], free_index[j], it.value());
  SparseMatrix Kff(nf, nf);
  Kff.setFromTriplets(t.begin(), t.end());
  VectorXd rhs(nf);
  for (Index i = 0; i < n; ++i)
    if (free_index[i] >= 0) rhs[free_index[i]] = rhs_all[i];
  const VectorXd uf = Eigen::SimplicialLLT<SparseMatrix>(Kff).solve(rhs);
  for (Index i = 0; i < n; ++i)
    if (free_index[i] >= 0) u[i] = uf[free_index[i]];
  return u;
}

}  // namespace symcontact
