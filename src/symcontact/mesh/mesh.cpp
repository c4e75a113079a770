#include "symcontact/mesh/mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include <Eigen/Geometry>

#include "symcontact/core/error.hpp"

namespace symcontact {

std::vector<Index> Mesh::group_nodes(const std::string& name) const {
  std::vector<Index> nodes;
  if (auto it = facet_groups.find(name); it != facet_groups.end()) {
    nodes = it->second.facets;
  } else if (auto jt = node_groups.find(name); jt != node_groups.end()) {
    nodes = jt->second;
  } else {
    throw std::out_of_range("no group named '" + name + "'");
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

std::string Mesh::cell_label(Index c) const {
  if (c >= 0 && c < static_cast<Index>(cell_tags.size())) return "element " + std::to_string(cell_tags[c]);
  return "cell " + std::to_string(c + 1);
}

std::string Mesh::node_label(Index v) const {
  if (v >= 0 && v < static_cast<Index>(node_tags.size())) return "node " + std::to_string(node_tags[v]);
  return "node " + std::to_string(v + 1);
}

CellType Mesh::cell_type(Index c) const {
  auto it = std::upper_bound(cell_blocks.begin(), cell_blocks.end(), c,
                             [](Index i, const CellBlock& b) { return i < b.end; });
  if (it == cell_blocks.end()) throw std::out_of_range("Mesh::cell_type: no cell " + std::to_string(c));
  return it->type;
}

int Mesh::max_nodes_per_cell() const {
  int n = 0;
  for (const CellBlock& b : cell_blocks) n = std::max(n, cell_num_nodes(b.type));
  return n;
}

std::vector<std::pair<CellType, Index>> Mesh::cell_type_counts() const {
  std::vector<std::pair<CellType, Index>> counts;
  for (const CellBlock& b : cell_blocks) {
    auto it = std::find_if(counts.begin(), counts.end(), [&](const auto& e) { return e.first == b.type; });
    if (it == counts.end()) counts.emplace_back(b.type, b.end - b.begin);
    else it->second += b.end - b.begin;
  }
  return counts;
}

std::string Mesh::cell_types_label() const {
  const auto counts = cell_type_counts();
  if (counts.size() == 1) return cell_name(counts.front().first);
  std::string s;
  for (const auto& [t, n] : counts) s += (s.empty() ? "" : " + ") + cell_name(t) + " (" + std::to_string(n) + ")";
  return s;
}

bool compatible_cell_types(CellType a, CellType b) {
  if (cell_dim(a) != cell_dim(b) || cell_order(a) != cell_order(b)) return false;
  for (int f = 0; f < cell_num_facets(a); ++f)
    for (int g = 0; g < cell_num_facets(b); ++g) {
      const CellType fa = cell_facet_type(a, f), fb = cell_facet_type(b, g);
      if (cell_shape(fa) == cell_shape(fb) && fa != fb) return false;
    }
  return true;
}

void Mesh::set_cells(CellType t, std::vector<Index> connectivity) {
  const int npc = cell_num_nodes(t);
  const Index n = static_cast<Index>(connectivity.size()) / npc;
  cells = std::move(connectivity);
  cell_offsets.resize(static_cast<std::size_t>(n) + 1);
  for (Index c = 0; c <= n; ++c) cell_offsets[c] = c * npc;
  cell_blocks.assign(1, CellBlock{t, 0, n});
}

void Mesh::add_cells(CellType t, const Index* connectivity, Index count) {
  const Index first = num_cells();
  if (first == 0) {
    cell_blocks.assign(1, CellBlock{t, 0, 0});
  } else {
    for (const CellBlock& b : cell_blocks)
      if (!compatible_cell_types(t, b.type))
        throw std::invalid_argument("cells of type " + cell_name(t) + " cannot join cells of type " +
                                    cell_name(b.type) + " in one mesh (another order, or no facet type in common)");
  }
  if (first > 0 && cell_blocks.back().type != t) {
    cell_blocks.push_back(CellBlock{t, first, first});
  }
  const int npc = cell_num_nodes(t);
  cells.insert(cells.end(), connectivity, connectivity + count * npc);
  for (Index c = 1; c <= count; ++c) cell_offsets.push_back(cell_offsets.back() + npc);
  cell_blocks.back().end = first + count;
}

bool Mesh::has_group(const std::string& name) const {
  return facet_groups.count(name) > 0 || node_groups.count(name) > 0;
}

std::vector<std::string> Mesh::group_names() const {
  std::vector<std::string> names;
  for (const auto& g : facet_groups) names.push_back(g.first);
  for (const auto& g : node_groups) names.push_back(g.first);
  return names;
}

double simplex_determinant(const Mesh& m, Index c) {
  if (cell_shape(m.cell_type(c)) != CellShape::kSimplex) return corner_determinant(m, c, 0);
  const Index* n = m.cell(c);
  if (m.dim == 2) {
    const Eigen::Vector2d a = m.x.col(n[1]) - m.x.col(n[0]);
    const Eigen::Vector2d b = m.x.col(n[2]) - m.x.col(n[0]);
    return a.x() * b.y() - a.y() * b.x();
  }
  const Vec3 a = m.x.col(n[1]) - m.x.col(n[0]);
  const Vec3 b = m.x.col(n[2]) - m.x.col(n[0]);
  const Vec3 d = m.x.col(n[3]) - m.x.col(n[0]);
  return a.cross(b).dot(d);
}

double corner_determinant(const Mesh& m, Index c, int corner) {
  const CellShape shape = cell_shape(m.cell_type(c));
  if (shape == CellShape::kSimplex) return simplex_determinant(m, c);
  const Index* n = m.cell(c);
  const auto edge = [&](int to) -> Vec3 {
    Vec3 e = Vec3::Zero();
    e.head(m.dim) = m.x.col(n[to]) - m.x.col(n[corner]);
    return e;
  };
  if (shape == CellShape::kPrism) {
    // J at vertex a of the 6-node prism: ∂x/∂ξ, ∂x/∂η are the edges of a's triangle from its first vertex
    // b, ∂x/∂ζ the vertical edge through a.
    const int b = corner < 3 ? 0 : 3, v = corner % 3;
    const Vec3 d_xi = m.x.col(n[b + 1]) - m.x.col(n[b]), d_eta = m.x.col(n[b + 2]) - m.x.col(n[b]);
    const Vec3 d_zeta = m.x.col(n[v + 3]) - m.x.col(n[v]);
    return d_xi.cross(d_eta).dot(d_zeta);
  }
  if (shape == CellShape::kPyramid) {
    // The 5-node pyramid is x = (1 − ζ) B(a, b) + ζ x4 with B the bilinear base and a = ξ / (1 − ζ),
    // b = η / (1 − ζ), so det J = det[∂B/∂a, ∂B/∂b, x4 − B] depends on (a, b) alone: at a base vertex, or
    // for the apex at the centre of the base (a = b = ½).
    const Vec3 x0 = m.x.col(n[0]), x1 = m.x.col(n[1]), x2 = m.x.col(n[2]), x3 = m.x.col(n[3]), x4 = m.x.col(n[4]);
    static const double ab[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}};
    const double a = ab[corner][0], b = ab[corner][1];
    const Vec3 Ba = (1 - b) * (x1 - x0) + b * (x2 - x3), Bb = (1 - a) * (x3 - x0) + a * (x2 - x1);
    const Vec3 B = (1 - a) * (1 - b) * x0 + a * (1 - b) * x1 + a * b * x2 + (1 - a) * b * x3;
    return Ba.cross(Bb).dot(x4 - B);
  }
  if (m.dim == 2) {  // neighbours v_{a+1} and v_{a−1}: counter-clockwise at every corner
    const Vec3 a = edge((corner + 1) % 4), b = edge((corner + 3) % 4);
    return a.x() * b.y() - a.y() * b.x();
  }
  // Neighbours along ξ, η, ζ of each vertex of the unit cube, and the sign of the reference edges'
  // determinant there (−1 for each axis along which the vertex is at 1).
  static const int along[8][3] = {{1, 3, 4}, {0, 2, 5}, {3, 1, 6}, {2, 0, 7},
                                  {5, 7, 0}, {4, 6, 1}, {7, 5, 2}, {6, 4, 3}};
  static const double sign[8] = {1, -1, 1, -1, -1, 1, -1, 1};
  return sign[corner] * edge(along[corner][0]).cross(edge(along[corner][1])).dot(edge(along[corner][2]));
}

Index Mesh::orient_cells() {
  Index flipped = 0;
  std::array<Index, 27> tmp{};
  for (const CellBlock& b : cell_blocks) {
    if (cell_dim(b.type) != dim || dim < 2) continue;
    const int* perm = cell_reflection(b.type);
    const int npc = cell_num_nodes(b.type);
    for (Index c = b.begin; c < b.end; ++c) {
      if (simplex_determinant(*this, c) >= 0) continue;
      Index* n = cell(c);
      for (int k = 0; k < npc; ++k) tmp[k] = n[perm[k]];
      std::copy(tmp.begin(), tmp.begin() + npc, n);
      ++flipped;
    }
  }
  return flipped;
}

void Mesh::check() const {
  if (num_cells() == 0) throw InputError("", "", "the mesh has no cells of dimension " + std::to_string(dim));
  for (Index j = 0; j < num_nodes(); ++j)
    for (int i = 0; i < dim; ++i)
      if (!std::isfinite(x(i, j)))
        throw InputError("", node_label(j), "coordinate is not a finite number");
  const Index nn = num_nodes();
  for (Index v : cells)
    if (v < 0 || v >= nn) throw InputError("", "", "a cell refers to node index out of range");
  // Relative size against the bounding box, so that a tolerance for "degenerate" is scale-free.
  const double diam = (x.rowwise().maxCoeff() - x.rowwise().minCoeff()).norm();
  const double ref = std::pow(diam, dim);
  for (const CellBlock& b : cell_blocks) {
    const int corners = cell_shape(b.type) != CellShape::kSimplex ? cell_num_vertices(b.type) : 1;
    for (Index c = b.begin; c < b.end; ++c) {
      double d = simplex_determinant(*this, c);
      for (int a = 1; a < corners; ++a) d = std::min(d, corner_determinant(*this, c, a));
      if (!(d > 1e-14 * ref))
        throw InputError("", cell_label(c),
                         d < 0 ? "inverted element (negative Jacobian determinant " + std::to_string(d) + ")"
                               : "degenerate element (zero area/volume)");
    }
  }
}

std::size_t FacetKeyHash::operator()(const FacetKey& k) const {
  std::size_t h = 1469598103934665603ull;  // FNV-1a
  for (Index v : k) h = (h ^ static_cast<std::size_t>(v)) * 1099511628211ull;
  return h;
}

FacetKey facet_key(const Index* v, int num_vertices) {
  FacetKey k{-1, -1, -1, -1};
  for (int i = 0; i < num_vertices; ++i) k[i] = v[i];
  for (int i = 1; i < num_vertices; ++i)  // insertion sort of at most four entries
    for (int j = i; j > 0 && k[j - 1] > k[j]; --j) std::swap(k[j - 1], k[j]);
  return k;
}

void Mesh::locate_facets() {
  // Facet lookup keyed by the sorted vertices (facet_key()): the first cell that has the
  // facet, its local number, and the second cell (-1 while there is none: a boundary facet).
  struct Where {
    Index first;
    int facet;
    Index second;
  };
  std::unordered_map<FacetKey, Where, FacetKeyHash> where;
  Index fv[4];
  for (const CellBlock& b : cell_blocks)
    for (Index c = b.begin; c < b.end; ++c) {
      const Index* n = cell(c);
      for (int f = 0; f < cell_num_facets(b.type); ++f) {
        const int* loc = cell_facet_nodes(b.type, f);
        const int nfv = cell_num_vertices(cell_facet_type(b.type, f));
        for (int i = 0; i < nfv; ++i) fv[i] = n[loc[i]];
        auto k = facet_key(fv, nfv);
        auto it = where.find(k);
        if (it == where.end())
          where.emplace(k, Where{c, f, -1});
        else
          it->second.second = c;  // interior facet: seen twice
      }
    }
  std::vector<std::string> interior;
  for (auto& [name, g] : facet_groups) {
    const Index m = num_facets(g);
    const int npf = cell_num_nodes(facet_type_of(g)), nfv = cell_num_vertices(facet_type_of(g));
    g.cell.assign(m, -1);
    g.local_facet.assign(m, -1);
    for (Index k = 0; k < m; ++k) {
      Index* fn = g.facets.data() + k * npf;
      auto it = where.find(facet_key(fn, nfv));
      const std::string facet = k < static_cast<Index>(g.tags.size()) ? "element " + std::to_string(g.tags[k])
                                                                      : "facet " + std::to_string(k + 1);
      if (it == where.end())
        throw InputError("", name,
                         facet + " of this group is not a facet of any element of the body, so not on its boundary "
                                 "(a boundary group must be made of facets of the body's boundary)");
      if (it->second.second >= 0) {
        interior_facet_groups[name] =
            facet + " of this group is shared by " + cell_label(it->second.first) + " and " +
            cell_label(it->second.second) +
            ": it lies inside the body, not on its boundary (a boundary group, such as a contact surface or a "
            "load, must be made of facets of the body's boundary; a Dirichlet condition may hold its nodes)";
        interior.push_back(name);
        break;
      }
      const Index c = it->second.first;
      const int f = it->second.facet;
      const int* loc = cell_facet_nodes(cell_type(c), f);
      for (int i = 0; i < npf; ++i) fn[i] = cell(c)[loc[i]];  // outward orientation from the cell
      g.cell[k] = c;
      g.local_facet[k] = f;
    }
  }
  for (const std::string& name : interior) {
    node_groups[name] = group_nodes(name);
    node_group_dims[name] = dim - 1;
    facet_groups.erase(name);
  }
}

}  // namespace symcontact
