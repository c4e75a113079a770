#include "symcontact/distributed/model_problems.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <fstream>
#include <functional>
#include <stdexcept>

#include "symcontact/energy/external_load.hpp"
#include "symcontact/energy/linear_elastic_energy.hpp"
#include "symcontact/fem/dof_map.hpp"
#include "symcontact/fem/matrix_sink.hpp"
#include "symcontact/materials/linear_elastic.hpp"
#include "symcontact/mesh/gmsh_io.hpp"
#include "symcontact/mesh/structured.hpp"

namespace symcontact {

namespace {

/// The lower triangle of part `part`'s share of the stiffness of s.mesh (E = 1, ν = 0.3): its cells
/// [c·part/parts, c·(part+1)/parts); f = 0. On the structured blocks those are slabs that match the ranks'
/// node ranges but for their boundaries.
void stiffness_share(BlockSystem& s, int dim, int part, int parts) {
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
}

BlockSystem block_share(int dim, int n, int part, int parts) {
  BlockSystem s;
  s.mesh = dim == 2 ? rectangle_mesh(0, 0, 1, 1, n, n) : box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), n, n, n);
  stiffness_share(s, dim, part, parts);
  return s;
}

/// Every node of `group`'s DOF `comp` fixed at 0.
void fix_component(BlockSystem& s, const std::string& group, int comp, std::vector<double>& values) {
  const Index dim = s.mesh.x.rows();
  for (const Index v : s.mesh.group_nodes(group)) {
    s.fixed.push_back(dim * v + comp);
    values.push_back(0.0);
  }
}

const char* bottom_group(int dim) { return dim == 2 ? "bottom" : "zmin"; }
const char* top_group(int dim) { return dim == 2 ? "top" : "zmax"; }

/// The block with its top moved by (shift, 0, −depth) (2D: (shift, −depth)) and one vertical constraint per
/// bottom node, u_z ≥ obstacle(x, y) (2D: u_y ≥ obstacle(x)).
ObstacleSystem pressed_block(int dim, int n, double depth, double shift, const std::function<double(const double*)>& obstacle,
                             int part, int parts) {
  ObstacleSystem o{block_share(dim, n, part, parts), {}};
  BlockSystem& s = o.block;
  std::vector<double> values;
  for (const Index v : s.mesh.group_nodes(top_group(dim)))
    for (int c = 0; c < dim; ++c) {
      s.fixed.push_back(dim * v + c);
      values.push_back(c == dim - 1 ? -depth : c == 0 ? shift : 0.0);
    }
  s.fixed_values = Eigen::Map<VectorXd>(values.data(), static_cast<Index>(values.size()));
  o.contact.node = s.mesh.group_nodes(bottom_group(dim));
  const Index m = o.contact.size();
  o.contact.normal = Eigen::MatrixXd::Zero(dim, m);
  o.contact.normal.row(dim - 1).setOnes();
  o.contact.lower.resize(m);
  for (Index j = 0; j < m; ++j) o.contact.lower[j] = obstacle(&s.mesh.x(0, o.contact.node[j]));
  return o;
}

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
  return pressed_block(dim, n, depth, 0.0,
                       [&](const double* x) {
                         double r2 = 0.0;
                         for (int c = 0; c + 1 < dim; ++c) r2 += (x[c] - 0.5) * (x[c] - 0.5);
                         return -(radius - std::sqrt(radius * radius - r2));
                       },
                       part, parts);
}

ObstacleSystem block_on_plane_system(int dim, int n, double depth, double shift, double tau, double alpha, int part,
                                     int parts) {
  ObstacleSystem o = pressed_block(dim, n, depth, shift, [](const double*) { return 0.0; }, part, parts);
  const VectorXd area = lumped_measures(o.block.mesh, bottom_group(dim));
  o.contact.friction_bound.resize(o.contact.size());
  for (Index j = 0; j < o.contact.size(); ++j) o.contact.friction_bound[j] = tau * area[o.contact.node[j]];
  o.contact.friction_alpha = VectorXd::Constant(o.contact.size(), alpha);
  return o;
}

ObstacleSystem hertz_sphere_system(const std::string& sphere_geo, double h, const std::string& work_dir,
                                   int part, int parts) {
  const std::string wrapper = work_dir + "/hertz_sphere.geo";
  std::ofstream(wrapper) << "h = " << h << ";\nInclude \"" << sphere_geo << "\";\n";
  MeshReadOptions read;
  read.dim = 3;
  read.max_predicted_cells = 0.0;
  ObstacleSystem o;
  BlockSystem& s = o.block;
  s.mesh = extract_body(read_mesh_file(wrapper, read), 3, "sphere", "group");
  stiffness_share(s, 3, part, parts);
  DofMap dofs(3);
  dofs.add_body(s.mesh.num_nodes());
  const double pressure = 0.01 / M_PI;
  s.f = boundary_load_vector(s.mesh, dofs, 0, s.mesh.facet_groups.at("load"),
                             [&](const double*, const double* n, double* t) {
                               for (int c = 0; c < 3; ++c) t[c] = -pressure * n[c];
                             },
                             AnalysisModel::kThreeD);
  std::vector<double> values;
  fix_component(s, "symmetry_x", 0, values);
  fix_component(s, "symmetry_y", 1, values);
  s.fixed_values = Eigen::Map<VectorXd>(values.data(), static_cast<Index>(values.size()));
  o.contact.node = s.mesh.group_nodes("contact");
  const Index m = o.contact.size();
  o.contact.normal = Eigen::MatrixXd::Zero(3, m);
  o.contact.normal.row(2).setOnes();
  o.contact.lower.resize(m);
  for (Index j = 0; j < m; ++j) o.contact.lower[j] = -s.mesh.x(2, o.contact.node[j]);
  return o;
}

double vertical_load(const BlockSystem& s) {
  double load = 0.0;
  for (Index v = 0; v < s.mesh.num_nodes(); ++v) load -= s.f[3 * v + 2];
  return load;
}

VectorXd lumped_measures(const Mesh& mesh, const std::string& surface) {
  VectorXd area = VectorXd::Zero(mesh.num_nodes());
  const std::vector<Index>& f = mesh.facet_groups.at(surface).facets;
  if (mesh.x.rows() == 2) {
    for (std::size_t k = 0; k + 1 < f.size(); k += 2) {
      const double half = 0.5 * (mesh.x.col(f[k + 1]) - mesh.x.col(f[k])).norm();
      area[f[k]] += half;
      area[f[k + 1]] += half;
    }
    return area;
  }
  for (std::size_t k = 0; k + 2 < f.size(); k += 3) {
    const Vec3 a = mesh.x.col(f[k]), b = mesh.x.col(f[k + 1]), d = mesh.x.col(f[k + 2]);
    const double third = (b - a).cross(d - a).norm() / 6.0;
    for (std::size_t i = 0; i < 3; ++i) area[f[k + i]] += third;
  }
  return area;
}

VectorXd nodal_pressures(const Mesh& mesh, const std::string& surface, const NodalConstraints& c,
                         const VectorXd& lambda) {
  const VectorXd area = lumped_measures(mesh, surface);
  VectorXd p(c.size());
  for (Index j = 0; j < c.size(); ++j) p[j] = lambda[j] / area[c.node[j]];
  return p;
}

}  // namespace symcontact
