#include "symcontact/mesh/mesh_topology.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <unordered_map>

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
  const int npc = m.nodes_per_cell();
  // Union-find over the nodes: the nodes of a cell are merged; a cell's component is its first node's.
  std::vector<Index> parent(m.num_nodes());
  std::iota(parent.begin(), parent.end(), Index(0));
  for (Index c = 0; c < nc; ++c) {
    const Index* n = m.cell(c);
    const Index r0 = find_root(parent, n[0]);
    for (int k = 1; k < npc; ++k) {
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

std::vector<std::pair<Index, Index>> coincident_nodes(const Mesh& m, double relative_tolerance) {
  std::vector<std::pair<Index, Index>> pairs;
  const Index n = m.num_nodes();
  if (n < 2) return pairs;
  const double diagonal = (m.x.rowwise().maxCoeff() - m.x.rowwise().minCoeff()).norm();
  const double tol = relative_tolerance * diagonal;
  // A hash grid of cells of size tol over the bounding box: twins lie in the same or neighbouring cells.
  // O(n), whatever the layout (a sweep along one axis would be quadratic on structured meshes).
  const double cell = tol > 0 ? tol : 1.0;
  const Eigen::VectorXd lo = m.x.rowwise().minCoeff();
  using Key = std::array<std::int64_t, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::size_t h = 1469598103934665603ull;
      for (std::int64_t v : k) h = (h ^ static_cast<std::size_t>(v)) * 1099511628211ull;
      return h;
    }
  };
  auto key_of = [&](Index v) {
    Key k{0, 0, 0};
    for (int i = 0; i < m.dim; ++i) k[i] = static_cast<std::int64_t>(std::floor((m.x(i, v) - lo[i]) / cell));
    return k;
  };
  std::unordered_map<Key, std::vector<Index>, KeyHash> grid;
  grid.reserve(static_cast<std::size_t>(n));
  for (Index v = 0; v < n; ++v) grid[key_of(v)].push_back(v);
  const int reach_z = m.dim == 3 ? 1 : 0;
  for (Index a = 0; a < n; ++a) {
    const Key k = key_of(a);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -reach_z; dz <= reach_z; ++dz) {
          const auto it = grid.find(Key{k[0] + dx, k[1] + dy, k[2] + dz});
          if (it == grid.end()) continue;
          for (Index b : it->second)
            if (b > a && (m.x.col(a) - m.x.col(b)).norm() <= tol) pairs.emplace_back(a, b);
        }
  }
  if (pairs.empty()) return pairs;
  // Keep the pairs that share no cell (two coincident nodes of one cell make it degenerate, which
  // Mesh::check() reports as such).
  std::vector<std::vector<Index>> cells_of(n);
  for (Index c = 0; c < m.num_cells(); ++c)
    for (int k = 0; k < m.nodes_per_cell(); ++k) cells_of[m.cell(c)[k]].push_back(c);
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

void check_topology(const Mesh& m) {
  const std::vector<std::pair<Index, Index>> twins = coincident_nodes(m);
  if (!twins.empty()) {
    std::string list;
    for (std::size_t k = 0; k < twins.size() && k < 3; ++k) {
      list += (k ? "; " : "") + m.node_label(twins[k].first) + " and " + m.node_label(twins[k].second) + " at " +
              position(m, twins[k].first);
    }
    if (twins.size() > 3) list += "; and " + std::to_string(twins.size() - 3) + " more pairs";
    throw InputError("", "",
                     std::to_string(twins.size()) + " pair" + (twins.size() == 1 ? " of nodes is" : "s of nodes are") +
                         " at the same position without sharing any element (" + list +
                         "): the body is cut there, like a crack; merge the duplicate nodes (Gmsh: Coherence, or "
                         "Geometry.AutoCoherence) or declare the parts as separate bodies");
  }
  std::vector<Index> component;
  const Index count = cell_components(m, &component);
  if (count > 1) {
    std::vector<Index> size(count, 0), first(count, -1);
    for (Index c = 0; c < m.num_cells(); ++c) {
      ++size[component[c]];
      if (first[component[c]] < 0) first[component[c]] = c;
    }
    std::string parts;
    for (Index k = 0; k < count && k < 5; ++k) {
      parts += (k ? ", " : "") + std::to_string(size[k]) + " element" + (size[k] == 1 ? "" : "s") + " from " +
               m.cell_label(first[k]);
    }
    if (count > 5) parts += ", ...";
    throw InputError("", "",
                     "the body is disconnected: its elements form " + std::to_string(count) +
                         " separate pieces that share no node (" + parts +
                         "); a body must be one piece: give each piece its own [[body]] (its own physical group)");
  }
}

}  // namespace symcontact
