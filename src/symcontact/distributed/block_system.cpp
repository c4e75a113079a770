#include "symcontact/distributed/block_system.hpp"

#include "symcontact/energy/linear_elastic_energy.hpp"
#include "symcontact/fem/dof_map.hpp"
#include "symcontact/fem/matrix_sink.hpp"
#include "symcontact/materials/linear_elastic.hpp"
#include "symcontact/mesh/structured.hpp"

namespace symcontact {

BlockSystem clamped_block_system(int dim, int n, int part, int parts) {
  BlockSystem s;
  s.mesh = dim == 2 ? rectangle_mesh(0, 0, 1, 1, n, n) : box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), n, n, n);
  DofMap dofs(dim);
  dofs.add_body(s.mesh.num_nodes());
  const auto model = dim == 2 ? AnalysisModel::kPlaneStrain : AnalysisModel::kThreeD;
  // The part's cells, on the same nodes: cells [c·part/parts, c·(part+1)/parts) of the structured order,
  // slabs of the block that match the ranks' node ranges but for their boundaries.
  Mesh cells = s.mesh;
  const Index c = s.mesh.num_cells(), first = c * part / parts, last = c * (part + 1) / parts;
  const int npc = s.mesh.nodes_per_cell(0);
  cells.set_cells(s.mesh.first_cell_type(),
                  std::vector<Index>(s.mesh.cell(0) + first * npc, s.mesh.cell(0) + last * npc));
  const LinearElasticEnergy energy(cells, dofs, 0, LinearElastic::from_young_poisson(1.0, 0.3, model), "block");
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

}  // namespace symcontact
