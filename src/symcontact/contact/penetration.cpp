#include "symcontact/contact/penetration.hpp"

#include <cmath>
#include <algorithm>
#include <array>
#include <limits>
#include <unordered_set>
#include <memory>
#include <stdexcept>

#include "symcontact/contact/bvh.hpp"
#include "symcontact/contact/closest_point.hpp"
#include "symcontact/contact/contact_points.hpp"
#include "symcontact/contact/contact_surface.hpp"
#include "symcontact/fem/shape_functions.hpp"

namespace symcontact {

namespace {

using Box = BoundingVolumeHierarchy::Box;
constexpr double kInf = std::numeric_limits<double>::infinity();

Eigen::Vector3d pad3(const Eigen::VectorXd& v) {
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  r.head(v.size()) = v;
  return r;
}

Eigen::MatrixXd facet_positions(const ContactSurface& s, const Eigen::MatrixXd& x, Index f) {
  const int npf = s.nodes_per_facet();
  Eigen::MatrixXd xf(s.dim, npf);
  for (int a = 0; a < npf; ++a) xf.col(a) = x.col(s.facet(f)[a]);
  return xf;
}

/// Largest distance between two vertices of a facet.
double facet_diameter(const ContactSurface& s, const Eigen::MatrixXd& x, Index f) {
  const int nv = cell_num_vertices(s.facet_type);
  double h = 0.0;
  for (int a = 0; a < nv; ++a)
    for (int b = a + 1; b < nv; ++b) h = std::max(h, (x.col(s.facet(f)[a]) - x.col(s.facet(f)[b])).norm());
  return h;
}

/// Longest reference facet at each node of s.
Eigen::VectorXd nodal_sizes(const ContactSurface& s) {
  Eigen::VectorXd h = Eigen::VectorXd::Zero(s.num_nodes());
  for (Index f = 0; f < s.num_facets(); ++f) {
    const double d = facet_diameter(s, s.X, f);
    for (int a = 0; a < s.nodes_per_facet(); ++a) h[s.facet(f)[a]] = std::max(h[s.facet(f)[a]], d);
  }
  return h;
}

/// A surface's facets at node positions x, with a hierarchy for nearest-facet queries.
struct FacetSearch {
  const ContactSurface* s = nullptr;
  Eigen::MatrixXd x;
  BoundingVolumeHierarchy bvh;

  FacetSearch(const ContactSurface& surface, const Eigen::MatrixXd& positions) : s(&surface), x(positions) {
    std::vector<Box> boxes(s->num_facets());
    for (Index f = 0; f < s->num_facets(); ++f) boxes[f] = facet_box(s->facet_type, facet_positions(*s, x, f), 0.0);
    bvh.build(boxes);
  }

  /// Nearest facet to p (global): its index, the projection, and the signed distance along the facet's unit
  /// normal at the projection (NaN unless the projection is inside the facet).
  int nearest(const Eigen::Vector3d& p, FacetProjection& proj, double& signed_distance) const {
    const Eigen::VectorXd q = p.head(s->dim);
    const int f = bvh.nearest(p, kInf, [&](int k) {
      return project_on_facet(s->facet_type, facet_positions(*s, x, k), q).distance2;
    });
    signed_distance = std::nan("");
    if (f < 0) return f;
    proj = project_on_facet(s->facet_type, facet_positions(*s, x, f), q);
    if (proj.inside()) {
      const Eigen::VectorXd n = facet_normal(s->facet_type, facet_positions(*s, x, f), proj.eta);
      if (n.norm() > 0) signed_distance = (q - proj.point.head(s->dim)).dot(n.normalized());
    }
    return f;
  }
};

using FacetSet = std::unordered_set<FacetKey, FacetKeyHash>;

/// The vertex facet of cell c number f (cell_facet_nodes()).
FacetKey cell_facet_key(const Mesh& m, Index c, int f) {
  const int* loc = cell_facet_nodes(m.cell_type(c), f);
  const int nfv = cell_num_vertices(cell_facet_type(m.cell_type(c), f));
  Index v[4];
  for (int i = 0; i < nfv; ++i) v[i] = m.cell(c)[loc[i]];
  return facet_key(v, nfv);
}

/// The vertex facet of simplex c opposite its vertex a.
FacetKey opposite_facet(const Mesh& m, Index c, int a) {
  Index v[3];
  int n = 0;
  for (int b = 0; b <= m.dim; ++b)
    if (b != a) v[n++] = m.cell(c)[b];
  return facet_key(v, m.dim);
}

/// The reference distance of the point ξ of a Quad4, Hex8 or Prism6 from the plane of its facet f
/// (cell_facet_nodes()), positive inside: ξ_i or 1 − ξ_i on the axis and side all the facet's vertices
/// share; for the prism ζ, 1 − ζ, η, ξ, 1 − ξ − η.
double facet_distance(CellType linear, int f, const double* xi) {
  if (linear == CellType::kPrism6) {
    const double d[5] = {xi[2], 1.0 - xi[2], xi[1], xi[0], 1.0 - xi[0] - xi[1]};
    return d[f];
  }
  const int D = cell_dim(linear), nfv = cell_num_vertices(facet_type(linear));
  const int* loc = cell_facet_nodes(linear, f);
  for (int i = 0; i < D; ++i) {
    const int side = tensor_node_coordinates(linear, loc[0])[i];
    bool on = true;
    for (int k = 1; k < nfv; ++k) on = on && tensor_node_coordinates(linear, loc[k])[i] == side;
    if (on) return side < 0 ? xi[i] : 1.0 - xi[i];
  }
  throw std::logic_error("facet_distance: no axis shared by the facet's vertices");
}

/// The cells of a body at node positions X + u, with a hierarchy for point location.
struct CellSearch {
  const Mesh* mesh = nullptr;
  Eigen::MatrixXd x;  ///< dim × nodes
  BoundingVolumeHierarchy bvh;
  FacetSet boundary;  ///< facets of one cell only

  CellSearch(const Mesh& m, const DofMap& dofs, int body, const VectorXd& u) : mesh(&m), x(m.x) {
    for (Index v = 0; v < m.num_nodes(); ++v)
      for (int i = 0; i < m.dim; ++i) x(i, v) += u[dofs.dof(body, v, i)];
    std::vector<Box> boxes(m.num_cells());
    for (Index c = 0; c < m.num_cells(); ++c) {
      boxes[c].setEmpty();
      for (int a = 0; a < m.nodes_per_cell(c); ++a) boxes[c].extend(pad3(x.col(m.cell(c)[a])));
    }
    bvh.build(boxes);
    FacetSet seen;
    for (Index c = 0; c < m.num_cells(); ++c)
      for (int f = 0; f < cell_num_facets(m.cell_type(c)); ++f) {
        const FacetKey k = cell_facet_key(m, c, f);
        if (!seen.insert(k).second) boundary.erase(k);
        else boundary.insert(k);
      }
  }

  /// Whether p lies inside the body: in the closed vertex cell of some cell (the simplex of its vertices,
  /// barycentric coordinates ≥ −1e-9; the bilinear or trilinear cell of the vertices of a quadrilateral,
  /// hexahedron, prism or pyramid, reference coordinates in [−1e-9, 1 + 1e-9]) and on none of that cell's facets that
  /// lie on the body's boundary (a point on a facet or edge shared by cells is inside; one on the
  /// boundary touches the body, it is not in it).
  bool contains(const Eigen::Vector3d& p) const {
    bool found = false;
    bvh.for_each_overlap(Box(p, p), [&](int c) {
      if (!found) found = cell_shape(mesh->cell_type(c)) == CellShape::kSimplex ? in_simplex(c, p) : in_mapped_cell(c, p);
    });
    return found;
  }

 private:
  static constexpr double eps = 1e-9;

  bool in_simplex(Index c, const Eigen::Vector3d& p) const {
    const int D = mesh->dim;
    const Index* n = mesh->cell(c);
    Eigen::MatrixXd J(D, D);
    for (int i = 0; i < D; ++i) J.col(i) = x.col(n[i + 1]) - x.col(n[0]);
    const Eigen::VectorXd l = J.partialPivLu().solve(p.head(D) - x.col(n[0]));
    Eigen::VectorXd lambda(D + 1);  // barycentric coordinates of vertices 0..D
    lambda << 1.0 - l.sum(), l;
    if (lambda.minCoeff() < -eps) return false;
    for (int a = 0; a <= D; ++a)
      if (lambda[a] <= eps && boundary.count(opposite_facet(*mesh, c, a))) return false;
    return true;
  }

  /// Reference coordinates ξ of p in the cell of c's vertices by Newton's method (x(ξ) = Σ X_a N_a(ξ)
  /// over the Quad4, Hex8 or Prism6 shape functions; a pyramid as the hexahedron whose face ζ = 1 is
  /// collapsed to the apex, x = (1 − ζ) B(ξ, η) + ζ X_4, which is its 5-node map in the collapsed
  /// coordinates); then the test of contains() on facet_distance().
  bool in_mapped_cell(Index c, const Eigen::Vector3d& p) const {
    const int D = mesh->dim;
    const CellType type = mesh->cell_type(c);
    const bool pyramid = cell_shape(type) == CellShape::kPyramid;
    const CellType linear =
        cell_shape(type) == CellShape::kPrism ? CellType::kPrism6 : (D == 2 ? CellType::kQuad4 : CellType::kHex8);
    static const int kVertex[8] = {0, 1, 2, 3, 4, 5, 6, 7}, kCollapsed[8] = {0, 1, 2, 3, 4, 4, 4, 4};
    static const int kPyramidFacet[6] = {4, 0, 1, 2, 3, -1};  // the hexahedron's facets as the pyramid's
    const int* vertex = pyramid ? kCollapsed : kVertex;
    const int nv = cell_num_vertices(linear);
    const Index* n = mesh->cell(c);
    Eigen::VectorXd xi = Eigen::VectorXd::Constant(D, 0.5);
    double N[8], dN[24];
    for (int it = 0; it < 30; ++it) {
      shape_functions(linear, xi.data(), N, dN);
      Eigen::VectorXd r = -p.head(D);
      Eigen::MatrixXd J = Eigen::MatrixXd::Zero(D, D);
      for (int a = 0; a < nv; ++a) {
        r += N[a] * x.col(n[vertex[a]]);
        for (int i = 0; i < D; ++i) J.col(i) += dN[a * D + i] * x.col(n[vertex[a]]);
      }
      const Eigen::VectorXd step = J.partialPivLu().solve(r);
      if (!step.allFinite()) return false;
      xi -= step;
      if (step.norm() < 1e-13 || xi.cwiseAbs().maxCoeff() > 1e3) break;
    }
    for (int f = 0; f < cell_num_facets(linear); ++f)
      if (facet_distance(linear, f, xi.data()) < -eps) return false;
    for (int f = 0; f < cell_num_facets(linear); ++f) {
      const int own = pyramid ? kPyramidFacet[f] : f;
      if (own >= 0 && facet_distance(linear, f, xi.data()) <= eps && boundary.count(cell_facet_key(*mesh, c, own)))
        return false;
    }
    return true;
  }
};

/// The slave nodes of `slave` against the opposite surface `master` of a pair (see the file comment).
void scan_side(const ContactSurface& slave, const ContactSurface& master, const CellSearch* cells,
               const DofMap& dofs, const VectorXd& u, double rel, Penetration& deepest) {
  const Eigen::MatrixXd xs = current_positions(slave, dofs, u);
  const Eigen::MatrixXd xm = current_positions(master, dofs, u);
  const FacetSearch now(master, xm), ref(master, master.X);
  const Eigen::VectorXd h = nodal_sizes(slave);
  for (Index k = 0; k < slave.num_nodes(); ++k) {
    FacetProjection proj;
    double d = 0.0, d0 = 0.0;
    const int f = now.nearest(pad3(xs.col(k)), proj, d);
    if (f < 0) continue;
    const double size = std::max(h[k], facet_diameter(master, master.X, f));
    const double tol = rel * size;
    double depth = 0.0;
    bool through = false;
    if (cells && cells->contains(pad3(xs.col(k)))) depth = std::sqrt(proj.distance2);
    if (std::isfinite(d) && d < -tol && -d > depth) {
      FacetProjection p0;
      ref.nearest(pad3(slave.X.col(k)), p0, d0);
      if (!(d0 < -tol)) {  // in front (or beside) at the start, behind now
        depth = -d;
        through = cells && !cells->contains(pad3(xs.col(k)));
        if (!cells) through = true;
      }
    }
    if (depth > 0 && depth / size > deepest.ratio()) {
      deepest.node = k;
      deepest.depth = depth;
      deepest.size = size;
      deepest.passed_through = through;
    }
  }
}

void scan_obstacle(const ContactSurface& slave, const Obstacle& ob, const DofMap& dofs, const VectorXd& u,
                   Penetration& deepest) {
  const Eigen::MatrixXd xs = current_positions(slave, dofs, u);
  const Eigen::VectorXd h = nodal_sizes(slave);
  for (Index k = 0; k < slave.num_nodes(); ++k) {
    Eigen::Vector3d xbar, n;
    const Eigen::Vector3d p = pad3(xs.col(k));
    ob.project(p, xbar, n);
    const double depth = -(p - xbar).dot(n);
    if (depth > 0 && depth / h[k] > deepest.ratio()) {
      deepest.node = k;
      deepest.depth = depth;
      deepest.size = h[k];
    }
  }
}

}  // namespace

Eigen::VectorXd signed_distances(const ContactSurface& s, const Eigen::MatrixXd& x, const Eigen::MatrixXd& points) {
  const FacetSearch search(s, x);
  Eigen::VectorXd d(points.cols());
  for (Index k = 0; k < points.cols(); ++k) {
    FacetProjection proj;
    search.nearest(pad3(points.col(k)), proj, d[k]);
  }
  return d;
}

std::vector<Penetration> find_penetrations(const ContactSet& contacts, const std::vector<const Mesh*>& meshes,
                                           const DofMap& dofs, const VectorXd& u, double relative_tolerance) {
  std::vector<Penetration> out;
  for (int p = 0; p < static_cast<int>(contacts.pairs.size()); ++p) {
    const ContactPair& pair = contacts.pairs[p];
    if (pair.surface_a == pair.surface_b) continue;  // self-contact
    std::vector<std::pair<int, int>> sides;          // (slave, master)
    if (pair.obstacle >= 0 || contacts.surfaces[pair.surface_b].is_rigid() || pair.mode == ContactMode::kSymmetric) {
      sides.push_back({pair.surface_a, pair.surface_b});
      if (pair.obstacle < 0 && !contacts.surfaces[pair.surface_b].is_rigid())
        sides.push_back({pair.surface_b, pair.surface_a});
    } else {
      sides.push_back(pair.slave_is_b ? std::make_pair(pair.surface_b, pair.surface_a)
                                      : std::make_pair(pair.surface_a, pair.surface_b));
    }
    for (const auto& [s, m] : sides) {
      Penetration deepest;
      deepest.pair = p;
      deepest.slave = s;
      deepest.master = m;
      const ContactSurface& slave = contacts.surfaces[s];
      if (m < 0) {
        scan_obstacle(slave, contacts.obstacles[pair.obstacle], dofs, u, deepest);
      } else {
        const ContactSurface& master = contacts.surfaces[m];
        std::unique_ptr<CellSearch> cells;
        // Two surfaces of one body: its nodes lie on its own cells, so only the "passed through" test applies.
        if (!master.is_rigid() && master.body != slave.body)
          cells = std::make_unique<CellSearch>(*meshes[master.body], dofs, master.body, u);
        scan_side(slave, master, cells.get(), dofs, u, relative_tolerance, deepest);
      }
      if (deepest.node >= 0) out.push_back(deepest);
    }
  }
  return out;
}

namespace {

/// Per family, the node of largest depth −g_i(u) / s_i over the rows i of `lin` that `counts` selects.
template <class Counts>
std::vector<Penetration> deepest_rows(const ContactSet& contacts, const ContactLinearization& lin, const VectorXd& u,
                                      Counts counts) {
  const VectorXd g = lin.A * u + lin.b;
  const auto& families = contacts.families();
  std::vector<Penetration> out(families.size());
  std::vector<Eigen::VectorXd> h(families.size());
  for (Index r = 0; r < g.size(); ++r) {
    const int f = lin.row_family[r];
    const ContactFamily& fam = families[f];
    if (!counts(r) || !(lin.row_support[r] > 0)) continue;
    if (h[f].size() == 0) h[f] = nodal_sizes(contacts.surfaces[fam.slave]);
    Penetration& deepest = out[f];
    const Index k = lin.row_node[r];
    const double depth = -g[r] / lin.row_support[r];
    if (depth > 0 && depth / h[f][k] > deepest.ratio()) {
      deepest = Penetration{fam.pair, fam.slave, fam.master, k, depth, h[f][k], false};
    }
  }
  out.erase(std::remove_if(out.begin(), out.end(), [](const Penetration& p) { return p.node < 0; }), out.end());
  return out;
}

}  // namespace

std::vector<Penetration> find_linearized_penetrations(const ContactSet& contacts, const ContactLinearization& lin,
                                                      const VectorXd& u) {
  return deepest_rows(contacts, lin, u, [&](Index r) {
    return contacts.pairs[contacts.families()[lin.row_family[r]].pair].geometry == ContactGeometry::kReference;
  });
}

std::vector<char> held_rows(const ContactLinearization& lin, const std::vector<char>& is_fixed) {
  std::vector<char> held(static_cast<std::size_t>(lin.A.rows()), 1);
  std::vector<char> touched(held.size(), 0);
  for (int col = 0; col < lin.A.outerSize(); ++col)
    for (SparseMatrix::InnerIterator e(lin.A, col); e; ++e) {
      if (e.value() == 0.0) continue;
      touched[static_cast<std::size_t>(e.row())] = 1;
      if (!is_fixed[static_cast<std::size_t>(col)]) held[static_cast<std::size_t>(e.row())] = 0;
    }
  for (std::size_t r = 0; r < held.size(); ++r) held[r] = held[r] && touched[r];
  return held;
}

std::vector<Penetration> find_held_penetrations(const ContactSet& contacts, const ContactLinearization& lin,
                                                const VectorXd& u, const std::vector<char>& held) {
  return deepest_rows(contacts, lin, u, [&](Index r) { return held[static_cast<std::size_t>(r)] != 0; });
}

}  // namespace symcontact
