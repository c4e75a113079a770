#include "symcontact/mesh/mesh_topology.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <unordered_map>

#include <Eigen/Geometry>

#include "symcontact/core/error.hpp"

namespace symcontact {

namespace {

Index find_root(std::vector<Index>& parent, Index v) {
  while (parent[v] != v) {
    parent[v] = parent[parent[v]];  // path halving
    v = parent[v];
  }
  return v;
}

std::string position(const Mesh& m, Index v) {
  std::ostringstream s;
  s.precision(10);
  s << "(";
  for (int i = 0; i < m.dim; ++i) s << (i ? ", " : "") << m.x(i, v);
  s << ")";
  return s.str();
}

}  // namespace

Index cell_components(const Mesh& m, std::vector<Index>* component) {
  const Index nc = m.num_cells();
  // Union-find over the nodes: the nodes of a cell are merged; a cell's component is its first node's.
  std::vector<Index> parent(m.num_nodes());
  std::iota(parent.begin(), parent.end(), Index(0));
  for (Index c = 0; c < nc; ++c) {
    const Index* n = m.cell(c);
    const Index r0 = find_root(parent, n[0]);
    for (int k = 1; k < m.nodes_per_cell(c); ++k) {
      const Index r = find_root(parent, n[k]);
      if (r != r0) parent[r] = r0;
    }
  }
  std::vector<Index> label(m.num_nodes(), -1);
  Index count = 0;
  if (component) component->assign(nc, -1);
  for (Index c = 0; c < nc; ++c) {
    const Index r = find_root(parent, m.cell(c)[0]);
    if (label[r] < 0) label[r] = count++;
    if (component) (*component)[c] = label[r];
  }
  return count;
}

std::size_t NodeGrid::KeyHash::operator()(const Key& k) const {
  std::size_t h = 1469598103934665603ull;
  for (std::int64_t v : k) h = (h ^ static_cast<std::size_t>(v)) * 1099511628211ull;
  return h;
}

NodeGrid::NodeGrid(const Mesh& m, double relative_tolerance) : m_(m) {
  const Index n = m.num_nodes();
  lo_ = n > 0 ? Eigen::VectorXd(m.x.rowwise().minCoeff()) : Eigen::VectorXd::Zero(m.dim);
  const double diagonal = n > 0 ? (m.x.rowwise().maxCoeff() - m.x.rowwise().minCoeff()).norm() : 0.0;
  tol_ = relative_tolerance * diagonal;
  cell_ = tol_ > 0 ? tol_ : 1.0;
  grid_.reserve(static_cast<std::size_t>(n));
  for (Index v = 0; v < n; ++v) grid_[key_of(m.x.col(v))].push_back(v);
}

NodeGrid::Key NodeGrid::key_of(const Eigen::VectorXd& y) const {
  Key k{0, 0, 0};
  for (int i = 0; i < m_.dim; ++i) k[i] = static_cast<std::int64_t>(std::floor((y[i] - lo_[i]) / cell_));
  return k;
}

void NodeGrid::near(const Eigen::VectorXd& y, std::vector<Index>& out) const {
  const Key k = key_of(y);
  const int reach_z = m_.dim == 3 ? 1 : 0;
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dz = -reach_z; dz <= reach_z; ++dz) {
        const auto it = grid_.find(Key{k[0] + dx, k[1] + dy, k[2] + dz});
        if (it == grid_.end()) continue;
        for (Index b : it->second)
          if ((m_.x.col(b) - y).norm() <= tol_) out.push_back(b);
      }
}

Index NodeGrid::at(const Eigen::VectorXd& y) const {
  std::vector<Index> found;
  near(y, found);
  return found.empty() ? -1 : *std::min_element(found.begin(), found.end());
}

std::vector<std::pair<Index, Index>> coincident_nodes(const Mesh& m, double relative_tolerance) {
  std::vector<std::pair<Index, Index>> pairs;
  const Index n = m.num_nodes();
  if (n < 2) return pairs;
  const NodeGrid grid(m, relative_tolerance);
  std::vector<Index> found;
  for (Index a = 0; a < n; ++a) {
    found.clear();
    grid.near(m.x.col(a), found);
    for (Index b : found)
      if (b > a) pairs.emplace_back(a, b);
  }
  if (pairs.empty()) return pairs;
  // Keep the pairs that share no cell (two coincident nodes of one cell make it degenerate, which
  // Mesh::check() reports as such).
  std::vector<std::vector<Index>> cells_of(n);
  for (Index c = 0; c < m.num_cells(); ++c)
    for (int k = 0; k < m.nodes_per_cell(c); ++k) cells_of[m.cell(c)[k]].push_back(c);
  std::vector<std::pair<Index, Index>> unshared;
  for (const auto& [a, b] : pairs) {
    const auto& ca = cells_of[a];
    const auto& cb = cells_of[b];
    const bool shared = std::any_of(ca.begin(), ca.end(), [&](Index c) { return std::find(cb.begin(), cb.end(), c) != cb.end(); });
    if (!shared) unshared.emplace_back(a, b);
  }
  std::sort(unshared.begin(), unshared.end());
  return unshared;
}

namespace {

/// Marks the nodes of group `name` (facet or node group) in `mask`; a group the mesh lacks marks none.
void mark_group(const Mesh& m, const std::string& name, std::vector<char>& mask) {
  if (!m.has_group(name)) return;
  for (Index v : m.group_nodes(name)) mask[v] = 1;
}

std::vector<char> group_mask(const Mesh& m, const std::string& name) {
  std::vector<char> mask(m.num_nodes(), 0);
  mark_group(m, name, mask);
  return mask;
}

/// "a, b and c" (names quoted), or "none".
std::string name_list(const std::vector<std::string>& names) {
  if (names.empty()) return "none";
  std::string s;
  for (std::size_t k = 0; k < names.size(); ++k)
    s += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + ("'" + names[k] + "'");
  return s;
}

/// "<body>" for messages: the body's name, or a placeholder when it is not known.
std::string body_name(const TopologyAllowances& allow) { return allow.body.empty() ? "<body>" : allow.body; }

/// Coincident nodes sharing no cell that no self-contact of `allow` covers: refused (see check_topology()).
void check_twins(const Mesh& m, const TopologyAllowances& allow) {
  const std::vector<std::pair<Index, Index>> twins = coincident_nodes(m);
  if (twins.empty()) return;
  std::vector<std::pair<std::vector<char>, std::vector<char>>> sides;
  std::vector<std::string> surfaces;
  for (const auto& [g, h] : allow.self_contacts) {
    sides.emplace_back(group_mask(m, g), group_mask(m, h));
    surfaces.push_back(g == h ? g : g + "' with '" + h);
  }
  std::vector<std::pair<Index, Index>> refused;
  for (const auto& [a, b] : twins) {
    const bool covered = std::any_of(sides.begin(), sides.end(), [a = a, b = b](const auto& s) {
      return (s.first[a] && s.second[b]) || (s.first[b] && s.second[a]);
    });
    if (!covered) refused.emplace_back(a, b);
  }
  if (refused.empty()) return;
  std::string list;
  for (std::size_t k = 0; k < refused.size() && k < 3; ++k) {
    list += (k ? "; " : "") + m.node_label(refused[k].first) + " and " + m.node_label(refused[k].second) + " at " +
            position(m, refused[k].first);
  }
  if (refused.size() > 3) list += "; and " + std::to_string(refused.size() - 3) + " more pairs";
  const std::size_t allowed = twins.size() - refused.size();
  throw InputError(
      "", "",
      std::to_string(refused.size()) + " pair" + (refused.size() == 1 ? " of nodes is" : "s of nodes are") +
          " at the same position without sharing any element (" + list + ")" +
          (allowed ? " and on no self-contact of the body (" + std::to_string(allowed) + " other pair" +
                         (allowed == 1 ? " is" : "s are") + " on one, allowed)"
                   : "") +
          ": the body is cut there, like a crack; merge the duplicate nodes (Gmsh: Coherence, or "
          "Geometry.AutoCoherence) or declare the parts as separate bodies; a cut that is meant (a crack, two parts of "
          "the body that touch) is allowed when its faces are declared in contact: both faces in one boundary group G "
          "with a [[contact]] a = b = \"" +
          body_name(allow) + ".G\" (self-contact surfaces of this body: " + name_list(surfaces) + ")");
}

/// A body in pieces with a piece that no group of `allow` holds: refused (see check_topology()).
void check_pieces(const Mesh& m, const TopologyAllowances& allow) {
  std::vector<Index> component;
  const Index count = cell_components(m, &component);
  if (count <= 1) return;
  std::vector<char> holding(m.num_nodes(), 0);
  for (const std::string& g : allow.contact_surfaces) mark_group(m, g, holding);
  for (const std::string& g : allow.dirichlet_boundaries) mark_group(m, g, holding);
  std::vector<Index> size(count, 0), first(count, -1);
  std::vector<char> held(count, 0);
  for (Index c = 0; c < m.num_cells(); ++c) {
    const Index k = component[c];
    ++size[k];
    if (first[k] < 0) first[k] = c;
    for (int a = 0; a < m.nodes_per_cell(c); ++a) held[k] = held[k] || holding[m.cell(c)[a]];
  }
  const auto piece = [&](Index k) {
    return std::to_string(size[k]) + " element" + (size[k] == 1 ? "" : "s") + " from " + m.cell_label(first[k]);
  };
  std::string parts, free;
  Index num_free = 0;
  for (Index k = 0; k < count; ++k) {
    if (k < 5) parts += (k ? ", " : "") + piece(k);
    if (!held[k] && num_free++ < 5) free += (num_free > 1 ? ", " : "") + piece(k);
  }
  if (num_free == 0) return;
  if (count > 5) parts += ", ...";
  if (num_free > 5) free += ", ...";
  throw InputError(
      "", "",
      "the body is disconnected: its elements form " + std::to_string(count) + " separate pieces that share no node (" +
          parts + "), and " +
          (num_free == count ? std::string("none of them has a node")
                             : std::to_string(num_free) + " of them (" + free + ") " + (num_free == 1 ? "has" : "have") +
                                   " no node") +
          " on a contact surface or a Dirichlet boundary of the body (contact surfaces: " +
          name_list(allow.contact_surfaces) + "; Dirichlet boundaries: " + name_list(allow.dirichlet_boundaries) +
          "); give each piece its own [[body]] (its own physical group), or hold every piece: a node of it on a "
          "[[body.dirichlet]] boundary or on a surface of a [[contact]]");
}

}  // namespace

void check_topology(const Mesh& m, const TopologyAllowances& allow) {
  check_twins(m, allow);
  check_pieces(m, allow);
}

}  // namespace symcontact

namespace symcontact {

namespace {

/// Side of the hyperplane through the first facet vertices of k (sorted indices: two in 2D, three in 3D)
/// on which point r lies: the sign of det[q − p, (s − p,) r − p].
int side_of(const Mesh& m, const FacetKey& k, const Eigen::VectorXd& r) {
  const Eigen::VectorXd p = m.x.col(k[0]);
  double d = 0.0;
  if (m.dim == 2) {
    const Eigen::Vector2d a = m.x.col(k[1]) - p, b = r - p;
    d = a.x() * b.y() - a.y() * b.x();
  } else {
    const Eigen::Vector3d a = m.x.col(k[1]) - p, b = m.x.col(k[2]) - p, c = r - p;
    d = a.cross(b).dot(c);
  }
  return (d > 0) - (d < 0);
}

}  // namespace

void check_folds(const Mesh& m) {
  Index positive = 0, negative = 0;
  for (Index c = 0; c < m.num_cells(); ++c) (simplex_determinant(m, c) > 0 ? positive : negative) += 1;
  const int majority = positive >= negative ? 1 : -1;
  struct Seen {
    Index cell;
    int side;
  };
  std::unordered_map<FacetKey, Seen, FacetKeyHash> seen;
  seen.reserve(static_cast<std::size_t>(m.num_cells()) * cell_num_facets(m.first_cell_type()));
  for (Index c = 0; c < m.num_cells(); ++c) {
    const Index* n = m.cell(c);
    const CellType t = m.cell_type(c);
    const int nv = cell_num_vertices(t);
    for (int f = 0; f < cell_num_facets(t); ++f) {
      const int* loc = cell_facet_nodes(t, f);
      const int nfv = cell_num_vertices(cell_facet_type(t, f));
      Index fv[4];
      for (int i = 0; i < nfv; ++i) fv[i] = n[loc[i]];
      const FacetKey k = facet_key(fv, nfv);
      // The centroid of the cell's vertices not on facet f (the opposite vertex of a simplex).
      Eigen::VectorXd opposite = Eigen::VectorXd::Zero(m.dim);
      int off = 0;
      for (int a = 0; a < nv; ++a)
        if (std::find(k.begin(), k.begin() + nfv, n[a]) == k.begin() + nfv) {
          opposite += m.x.col(n[a]);
          ++off;
        }
      const int side = side_of(m, k, opposite / off);
      auto [it, inserted] = seen.emplace(k, Seen{c, side});
      if (inserted || side == 0 || it->second.side != side) continue;
      // Both cells on the same side of their common facet: they overlap. Name the one whose orientation
      // differs from the body's majority (both when neither does).
      const Index other = it->second.cell;
      const bool c_odd = (simplex_determinant(m, c) > 0 ? 1 : -1) != majority;
      const bool o_odd = (simplex_determinant(m, other) > 0 ? 1 : -1) != majority;
      const Index named = c_odd || !o_odd ? c : other, partner = named == c ? other : c;
      throw InputError("", m.cell_label(named),
                       std::string("folded element: it lies on the same side of its ") +
                           (m.dim == 2 ? "edge" : "face") + " shared with " + m.cell_label(partner) +
                           " as that element, so the two overlap" +
                           (c_odd || o_odd ? " (its orientation is opposite to that of the rest of the body: a node "
                                             "was moved across an edge or face of the mesh)"
                                           : ""));
    }
  }
}

}  // namespace symcontact
