#include "symcontact/distributed/block_system.hpp"

#include <cmath>
#include <stdexcept>

#include "symcontact/energy/linear_elastic_energy.hpp"
#include "symcontact/fem/dof_map.hpp"
#include "symcontact/fem/matrix_sink.hpp"
#include "symcontact/materials/linear_elastic.hpp"
#include "symcontact/mesh/structured.hpp"

namespace symcontact {

namespace {

/// The unit block's mesh and the lower triangle of part `part`'s share of its stiffness: the cells
/// [c·part/parts, c·(part+1)/parts) of the structured order, slabs of the block that match the ranks' node
/// ranges but for their boundaries.
BlockSystem block_share(int dim, int n, int part, int parts) {
  BlockSystem s;
  s.mesh = dim == 2 ? rectangle_mesh(0, 0, 1, 1, n, n) : box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), n, n, n);
  DofMap dofs(dim);
  dofs.add_body(s.mesh.num_nodes());
  const auto model = dim == 2 ? AnalysisModel::kPlaneStrain : AnalysisModel::kThreeD;
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
  return s;
}

const char* bottom_group(int dim) { return dim == 2 ? "bottom" : "zmin"; }
const char* top_group(int dim) { return dim == 2 ? "top" : "zmax"; }

}  // namespace

BlockSystem clamped_block_system(int dim, int n, int part, int parts) {
  BlockSystem s = block_share(dim, n, part, parts);
  for (Index v = 0; v < s.mesh.num_nodes(); ++v) s.f[dim * v + dim - 1] = -1e-3;
  std::vector<double> values;
  for (const Index v : s.mesh.group_nodes(bottom_group(dim)))
    for (int c = 0; c < dim; ++c) {
      s.fixed.push_back(dim * v + c);
      values.push_back(0.0);
    }
  for (const Index v : s.mesh.group_nodes(top_group(dim))) {
    s.fixed.push_back(dim * v);
    values.push_back(0.01);
  }
  s.fixed_values = Eigen::Map<VectorXd>(values.data(), static_cast<Index>(values.size()));
  return s;
}

ObstacleSystem block_on_ball_system(int dim, int n, double radius, double depth, int part, int parts) {
  if (radius * radius <= 0.25 * (dim - 1))
    throw std::invalid_argument("block_on_ball_system: the ball must reach under the whole bottom face");
  ObstacleSystem o{block_share(dim, n, part, parts), {}};
  BlockSystem& s = o.block;
  std::vector<double> values;
  for (const Index v : s.mesh.group_nodes(top_group(dim)))
    for (int c = 0; c < dim; ++c) {
      s.fixed.push_back(dim * v + c);
      values.push_back(c == dim - 1 ? -depth : 0.0);
    }
  s.fixed_values = Eigen::Map<VectorXd>(values.data(), static_cast<Index>(values.size()));
  const std::vector<Index> bottom = s.mesh.group_nodes(bottom_group(dim));
  o.contact.node = bottom;
  o.contact.normal = Eigen::MatrixXd::Zero(dim, static_cast<Index>(bottom.size()));
  o.contact.lower.resize(static_cast<Index>(bottom.size()));
  for (std::size_t j = 0; j < bottom.size(); ++j) {
    const Index col = static_cast<Index>(j);
    double r2 = 0.0;
    for (int c = 0; c + 1 < dim; ++c) r2 += std::pow(s.mesh.x(c, bottom[j]) - 0.5, 2);
    o.contact.normal(dim - 1, col) = 1.0;
    o.contact.lower[col] = -(radius - std::sqrt(radius * radius - r2));
  }
  return o;
}

}  // namespace symcontact
