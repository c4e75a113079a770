#include "symcontact/contact/contact_surface.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>
#include <map>
#include <unordered_map>

#include "symcontact/contact/closest_point.hpp"

#include "symcontact/fem/shape_functions.hpp"

namespace symcontact {

Eigen::VectorXd facet_normal(CellType type, const Eigen::MatrixXd& xf, const double* xi) {
  const int npf = cell_num_nodes(type);
  const int d = cell_dim(type);
  double dN[20];
  shape_functions(type, xi, nullptr, dN);
  if (d == 1) {
    Eigen::Vector2d t = Eigen::Vector2d::Zero();
    for (int a = 0; a < npf; ++a) t += xf.col(a).head<2>() * dN[a];
    return Eigen::Vector2d(t.y(), -t.x());
  }
  Vec3 t0 = Vec3::Zero(), t1 = Vec3::Zero();
  for (int a = 0; a < npf; ++a) {
    t0 += xf.col(a).head<3>() * dN[2 * a];
    t1 += xf.col(a).head<3>() * dN[2 * a + 1];
  }
  return t0.cross(t1);
}

bool has_modified_test_basis(CellType t) { return t == CellType::kTri6 || t == CellType::kQuad8; }

bool has_modified_test_basis(const ContactSurface& s) {
  return has_modified_test_basis(s.facet_type) ||
         (s.facet_type == CellType::kLine3 && s.model == AnalysisModel::kAxisymmetric);
}

int basis_num_edges(CellType t) { return t == CellType::kLine3 ? 1 : facet_num_edges(t); }

const int* basis_edge(CellType t, int e) {
  static const int segment[2] = {0, 1};
  return t == CellType::kLine3 ? segment : facet_edge(t, e);
}

namespace {

/// φ = T N in place (the modification of test_functions()).
void modify_test_functions(CellType type, double* phi) {
  constexpr double c = kModifiedTri6Coefficient;
  const int nv = cell_num_vertices(type);  // edge e's node is nv + e
  for (int e = 0; e < basis_num_edges(type); ++e) {
    const int* ab = basis_edge(type, e);
    phi[ab[0]] += c * phi[nv + e];
    phi[ab[1]] += c * phi[nv + e];
    phi[nv + e] *= 1.0 - 2.0 * c;
  }
}

}  // namespace

void test_functions(CellType type, const double* xi, double* phi) {
  shape_functions(type, xi, phi, nullptr);
  if (has_modified_test_basis(type)) modify_test_functions(type, phi);
}

void test_functions(const ContactSurface& s, const double* xi, double* phi) {
  shape_functions(s.facet_type, xi, phi, nullptr);
  if (has_modified_test_basis(s)) modify_test_functions(s.facet_type, phi);
}

Eigen::MatrixXd test_basis_forces(const ContactSurface& s, const Eigen::MatrixXd& F) {
  if (!has_modified_test_basis(s)) return F;
  constexpr double c = kModifiedTri6Coefficient;
  const int nv = cell_num_vertices(s.facet_type);
  Eigen::MatrixXd out = F;
  // Every edge node once: it belongs to one or two facets, with the same two vertices.
  std::vector<char> done(s.num_nodes(), 0);
  for (Index f = 0; f < s.num_facets(); ++f)
    for (int e = 0; e < basis_num_edges(s.facet_type); ++e) {
      const Index m = s.facet(f)[nv + e];
      if (done[m]) continue;
      done[m] = 1;
      out.col(s.facet(f)[basis_edge(s.facet_type, e)[0]]) += c * F.col(m);
      out.col(s.facet(f)[basis_edge(s.facet_type, e)[1]]) += c * F.col(m);
      out.col(m) = (1.0 - 2.0 * c) * F.col(m);
    }
  return out;
}

double facet_size(const ContactSurface& s, Index f) {
  const int nv = cell_num_vertices(s.facet_type);
  double h = 0.0;
  for (int i = 0; i < nv; ++i)
    for (int j = i + 1; j < nv; ++j) h = std::max(h, (s.X.col(s.facet(f)[i]) - s.X.col(s.facet(f)[j])).norm());
  return h;
}

namespace {

Eigen::VectorXd mean_facet_size_at_nodes(const ContactSurface& s) {
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(s.num_nodes()), count = Eigen::VectorXd::Zero(s.num_nodes());
  for (Index f = 0; f < s.num_facets(); ++f) {
    const double h = facet_size(s, f);
    for (int a = 0; a < s.nodes_per_facet(); ++a) {
      sum[s.facet(f)[a]] += h;
      count[s.facet(f)[a]] += 1.0;
    }
  }
  return sum.cwiseQuotient(count.cwiseMax(1.0));
}

}  // namespace

ContactSurface make_contact_surface(const Mesh& mesh, const std::string& group, int body, const std::string& name,
                                    AnalysisModel model) {
  const FacetGroup& g = mesh.facet_groups.at(group);
  ContactSurface s;
  s.name = name;
  s.body = body;
  s.model = model;
  s.dim = mesh.dim;
  s.facet_type = mesh.facet_type_of(g);
  const int nv = cell_num_vertices(s.facet_type);
  std::unordered_map<Index, Index> local;
  for (Index v : g.facets) {
    if (local.emplace(v, static_cast<Index>(s.nodes.size())).second) s.nodes.push_back(v);
    s.facets.push_back(local[v]);
  }
  s.X.resize(s.dim, s.num_nodes());
  for (Index k = 0; k < s.num_nodes(); ++k) s.X.col(k) = mesh.x.col(s.nodes[k]);
  s.valence.assign(s.num_nodes(), 0);
  for (Index f = 0; f < s.num_facets(); ++f)
    for (int a = 0; a < nv; ++a) ++s.valence[s.facet(f)[a]];
  if (s.dim == 2) {
    // Corners: the outward unit normals of the two facets at a vertex of valence 2 (Line2/Line3 facets run
    // from local node 0 to local node 1) differ by more than kCornerAngleDegrees.
    const Eigen::MatrixXd n = facet_end_normals(s, s.X);
    const double c = std::cos(kCornerAngleDegrees * M_PI / 180.0);
    s.corner.assign(s.num_nodes(), 0);
    for (Index k = 0; k < s.num_nodes(); ++k)
      s.corner[k] = s.valence[k] == 2 && n.block<2, 1>(0, k).dot(n.block<2, 1>(2, k)) < c;
  }
  if (s.dim == 3) {
    // Border edges: edges held by a single facet.
    const int ne = facet_num_edges(s.facet_type);
    std::map<std::pair<Index, Index>, int> count;
    auto key = [&](Index f, int e) {
      const Index a = s.facet(f)[facet_edge(s.facet_type, e)[0]], b = s.facet(f)[facet_edge(s.facet_type, e)[1]];
      return std::make_pair(std::min(a, b), std::max(a, b));
    };
    for (Index f = 0; f < s.num_facets(); ++f)
      for (int e = 0; e < ne; ++e) ++count[key(f, e)];
    s.boundary_edge.assign(ne * s.num_facets(), 0);
    s.boundary_vertex.assign(s.num_nodes(), 0);
    for (Index f = 0; f < s.num_facets(); ++f)
      for (int e = 0; e < ne; ++e)
        if (count[key(f, e)] == 1) {
          s.boundary_edge[ne * f + e] = 1;
          s.boundary_vertex[s.facet(f)[facet_edge(s.facet_type, e)[0]]] = 1;
          s.boundary_vertex[s.facet(f)[facet_edge(s.facet_type, e)[1]]] = 1;
        }
  }
  s.nodal_area = lumped_areas(s, s.X);
  s.nodal_size = mean_facet_size_at_nodes(s);
  return s;
}

Eigen::VectorXd lumped_areas(const ContactSurface& s, const Eigen::MatrixXd& x) {
  // A rule exact for the (polynomial, straight-facet) integrand.
  const int npf = s.nodes_per_facet();
  Eigen::VectorXd area = Eigen::VectorXd::Zero(s.num_nodes());
  const QuadratureRule rule = cell_quadrature(s.facet_type, 2 * cell_order(s.facet_type) + 1);
  Eigen::MatrixXd xf(s.dim, npf);
  std::vector<double> N(npf);
  for (Index f = 0; f < s.num_facets(); ++f) {
    for (int a = 0; a < npf; ++a) xf.col(a) = x.col(s.facet(f)[a]);
    for (int q = 0; q < rule.size(); ++q) {
      test_functions(s, rule.point(q), N.data());
      const double J = surface_measure(s, xf, rule.point(q));
      for (int a = 0; a < npf; ++a) area[s.facet(f)[a]] += rule.weights[q] * J * N[a];
    }
  }
  return area;
}

double surface_measure(const ContactSurface& s, const Eigen::MatrixXd& xf, const double* xi) {
  const double ds = facet_normal(s.facet_type, xf, xi).norm();
  if (s.model != AnalysisModel::kAxisymmetric) return ds;
  double N[9];  // at most 9 nodes on a facet (Quad9)
  shape_functions(s.facet_type, xi, N, nullptr);
  double r = 0.0;
  for (int a = 0; a < s.nodes_per_facet(); ++a) r += xf(0, a) * N[a];
  return section_measure(s.model, r) * ds;
}

Eigen::MatrixXd current_positions(const ContactSurface& s, const DofMap& dofs, const VectorXd& u) {
  Eigen::MatrixXd x = s.X;
  if (s.is_rigid()) return x;
  for (Index k = 0; k < s.num_nodes(); ++k)
    for (int i = 0; i < s.dim; ++i) x(i, k) += u[dofs.dof(s.body, s.nodes[k], i)];
  return x;
}

Eigen::MatrixXd nodal_normals(const ContactSurface& s, const Eigen::MatrixXd& x) {
  const int npf = s.nodes_per_facet();
  const std::vector<double> ref = reference_nodes(s.facet_type);
  const int d = cell_dim(s.facet_type);
  Eigen::MatrixXd n = Eigen::MatrixXd::Zero(s.dim, s.num_nodes());
  Eigen::MatrixXd xf(s.dim, npf);
  for (Index f = 0; f < s.num_facets(); ++f) {
    for (int a = 0; a < npf; ++a) xf.col(a) = x.col(s.facet(f)[a]);
    for (int a = 0; a < npf; ++a) n.col(s.facet(f)[a]) += facet_normal(s.facet_type, xf, ref.data() + a * d);
  }
  for (Index k = 0; k < s.num_nodes(); ++k) {
    const double len = n.col(k).norm();
    if (len > 0) n.col(k) /= len;
  }
  return n;
}

Eigen::MatrixXd facet_end_normals(const ContactSurface& s, const Eigen::MatrixXd& x) {
  const std::vector<double> ref = reference_nodes(s.facet_type);
  const int npf = s.nodes_per_facet();
  Eigen::MatrixXd n = Eigen::MatrixXd::Zero(4, s.num_nodes());
  Eigen::MatrixXd xf(2, npf);
  for (Index f = 0; f < s.num_facets(); ++f) {
    for (int a = 0; a < npf; ++a) xf.col(a) = x.col(s.facet(f)[a]).head<2>();
    for (int a = 0; a < 2; ++a) {
      const Eigen::VectorXd nf = facet_normal(s.facet_type, xf, &ref[a]);
      if (nf.norm() > 0) n.block<2, 1>(a == 1 ? 0 : 2, s.facet(f)[a]) = nf.normalized();
    }
  }
  return n;
}

}  // namespace symcontact
