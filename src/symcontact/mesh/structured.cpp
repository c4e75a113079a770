#include "symcontact/mesh/structured.hpp"

#include <array>
#include <algorithm>
#include <map>
#include <random>
#include <stdexcept>

namespace symcontact {

Mesh rectangle_mesh(double x0, double y0, double x1, double y1, int nx, int ny, int order) {
  if (nx < 1 || ny < 1) throw std::invalid_argument("rectangle_mesh: nx, ny must be >= 1");
  Mesh m;
  m.dim = 2;
  std::vector<Index> cells;
  auto id = [&](int i, int j) -> Index { return static_cast<Index>(j) * (nx + 1) + i; };
  m.x.resize(2, static_cast<Index>(nx + 1) * (ny + 1));
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      m.x(0, id(i, j)) = x0 + (x1 - x0) * i / nx;
      m.x(1, id(i, j)) = y0 + (y1 - y0) * j / ny;
    }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Index a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + j) % 2 == 0) {
        cells.insert(cells.end(), {a, b, c, a, c, d});
      } else {
        cells.insert(cells.end(), {a, b, d, b, c, d});
      }
    }
  m.set_cells(CellType::kTri3, std::move(cells));
  auto& bottom = m.facet_groups["bottom"].facets;
  auto& top = m.facet_groups["top"].facets;
  for (int i = 0; i < nx; ++i) {
    bottom.insert(bottom.end(), {id(i, 0), id(i + 1, 0)});
    top.insert(top.end(), {id(i + 1, ny), id(i, ny)});
  }
  auto& left = m.facet_groups["left"].facets;
  auto& right = m.facet_groups["right"].facets;
  for (int j = 0; j < ny; ++j) {
    left.insert(left.end(), {id(0, j + 1), id(0, j)});
    right.insert(right.end(), {id(nx, j), id(nx, j + 1)});
  }
  m.node_groups["corner_ll"] = {id(0, 0)};
  m.node_groups["corner_lr"] = {id(nx, 0)};
  m.locate_facets();
  return order == 2 ? elevate_to_p2(m) : m;
}

Mesh box_mesh(const Vec3& lo, const Vec3& hi, int nx, int ny, int nz, int order) {
  if (nx < 1 || ny < 1 || nz < 1) throw std::invalid_argument("box_mesh: divisions must be >= 1");
  Mesh m;
  m.dim = 3;
  std::vector<Index> cells;
  const int n[3] = {nx, ny, nz};
  auto id = [&](int i, int j, int k) -> Index {
    return (static_cast<Index>(k) * (ny + 1) + j) * (nx + 1) + i;
  };
  m.x.resize(3, static_cast<Index>(nx + 1) * (ny + 1) * (nz + 1));
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const Index v = id(i, j, k);
        m.x(0, v) = lo.x() + (hi.x() - lo.x()) * i / nx;
        m.x(1, v) = lo.y() + (hi.y() - lo.y()) * j / ny;
        m.x(2, v) = lo.z() + (hi.z() - lo.z()) * k / nz;
      }
  // Kuhn split: the six tetrahedra along the main diagonal (0,0,0)→(1,1,1), one per permutation
  // of the axes; identical on every cube, hence conforming.
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& p : perms) {
          int c[3] = {i, j, k};
          Index tet[4];
          tet[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[p[s]];
            tet[s + 1] = id(c[0], c[1], c[2]);
          }
          cells.insert(cells.end(), tet, tet + 4);
        }
  m.set_cells(CellType::kTet4, std::move(cells));
  m.orient_cells();
  // Boundary faces: two triangles per boundary square, with diagonals matching the Kuhn split
  // (every face diagonal goes from the lower to the upper corner of the square).
  const char* names[3][2] = {{"xmin", "xmax"}, {"ymin", "ymax"}, {"zmin", "zmax"}};
  for (int ax = 0; ax < 3; ++ax) {
    const int u = (ax + 1) % 3, v = (ax + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      auto& faces = m.facet_groups[names[ax][side]].facets;
      for (int b = 0; b < n[v]; ++b)
        for (int a = 0; a < n[u]; ++a) {
          auto node = [&](int da, int db) {
            int c[3];
            c[ax] = side * n[ax];
            c[u] = a + da;
            c[v] = b + db;
            return id(c[0], c[1], c[2]);
          };
          faces.insert(faces.end(), {node(0, 0), node(1, 0), node(1, 1)});
          faces.insert(faces.end(), {node(0, 0), node(1, 1), node(0, 1)});
        }
    }
  }
  m.node_groups["origin"] = {id(0, 0, 0)};
  m.locate_facets();
  return order == 2 ? elevate_to_p2(m) : m;
}

Mesh tensor_mesh(CellType type, const Vec3& lo, const Vec3& hi, int nx, int ny, int nz) {
  if (cell_shape(type) != CellShape::kTensor) throw std::invalid_argument("tensor_mesh: expects a tensor cell type");
  const int D = cell_dim(type), q = cell_order(type), npc = cell_num_nodes(type);
  const int n[3] = {nx, ny, D == 3 ? nz : 1};
  for (int i = 0; i < D; ++i)
    if (n[i] < 1) throw std::invalid_argument("tensor_mesh: divisions must be >= 1");
  // A lattice of q·n + 1 points per direction; the cells' nodes are the lattice points at
  // q·(cell index) + q·(c + 1)/2, c ∈ {−1, 0, 1} their reference coordinates. Unused points are dropped.
  const Index m0 = q * n[0] + 1, m1 = q * n[1] + 1, m2 = D == 3 ? q * n[2] + 1 : 1;
  std::vector<Index> index(static_cast<std::size_t>(m0 * m1 * m2), -1);
  Mesh m;
  m.dim = D;
  std::vector<Index> lattice, cells;
  const auto point = [&](const int* cell, const int* c) {
    Index l[3] = {0, 0, 0};
    for (int i = 0; i < D; ++i) l[i] = q * cell[i] + q * (c[i] + 1) / 2;
    const Index p = (l[2] * m1 + l[1]) * m0 + l[0];
    if (index[p] < 0) {
      index[p] = static_cast<Index>(lattice.size());
      lattice.push_back(p);
    }
    return index[p];
  };
  int cell[3] = {0, 0, 0};
  for (cell[2] = 0; cell[2] < n[2]; ++cell[2])
    for (cell[1] = 0; cell[1] < n[1]; ++cell[1])
      for (cell[0] = 0; cell[0] < n[0]; ++cell[0])
        for (int a = 0; a < npc; ++a) cells.push_back(point(cell, tensor_node_coordinates(type, a)));
  m.set_cells(type, std::move(cells));
  m.x.resize(D, static_cast<Index>(lattice.size()));
  for (std::size_t k = 0; k < lattice.size(); ++k) {
    const Index l[3] = {lattice[k] % m0, (lattice[k] / m0) % m1, lattice[k] / (m0 * m1)};
    for (int i = 0; i < D; ++i) m.x(i, static_cast<Index>(k)) = lo[i] + (hi[i] - lo[i]) * l[i] / (q * n[i]);
  }
  // Boundary facets: local facet f of the cells on its side (cell_facet_nodes() order: quadrilateral
  // η = 0, ξ = 1, η = 1, ξ = 0; hexahedron ζ = 0, η = 0, ξ = 0, ξ = 1, η = 1, ζ = 1).
  static const int quad_side[4][2] = {{1, 0}, {0, 1}, {1, 1}, {0, 0}};  // (axis, side)
  static const int hex_side[6][2] = {{2, 0}, {1, 0}, {0, 0}, {0, 1}, {1, 1}, {2, 1}};
  static const char* quad_names[2][2] = {{"left", "right"}, {"bottom", "top"}};
  static const char* hex_names[3][2] = {{"xmin", "xmax"}, {"ymin", "ymax"}, {"zmin", "zmax"}};
  const int npf = cell_num_nodes(facet_type(type));
  for (Index c = 0; c < m.num_cells(); ++c) {
    const Index ijk[3] = {c % n[0], (c / n[0]) % n[1], c / (n[0] * n[1])};
    for (int f = 0; f < cell_num_facets(type); ++f) {
      const int axis = D == 2 ? quad_side[f][0] : hex_side[f][0], side = D == 2 ? quad_side[f][1] : hex_side[f][1];
      if (ijk[axis] != (side == 0 ? 0 : n[axis] - 1)) continue;
      auto& facets = m.facet_groups[D == 2 ? quad_names[axis][side] : hex_names[axis][side]].facets;
      const int* loc = cell_facet_nodes(type, f);
      for (int a = 0; a < npf; ++a) facets.push_back(m.cell(c)[loc[a]]);
    }
  }
  if (D == 2) {
    m.node_groups["corner_ll"] = {m.cell(0)[0]};
    m.node_groups["corner_lr"] = {m.cell(n[0] - 1)[1]};
  } else {
    m.node_groups["origin"] = {m.cell(0)[0]};
  }
  m.locate_facets();
  return m;
}

namespace {
/// Removes the nodes no cell uses, keeping the others' order, and renumbers cells and groups.
void drop_unused_nodes(Mesh& m) {
  std::vector<Index> to(static_cast<std::size_t>(m.num_nodes()), -1);
  for (Index v : m.cells) to[v] = 0;
  Index next = 0;
  for (Index v = 0; v < m.num_nodes(); ++v)
    if (to[v] == 0) {
      m.x.col(next) = m.x.col(v);
      to[v] = next++;
    }
  m.x.conservativeResize(Eigen::NoChange, next);
  for (Index& v : m.cells) v = to[v];
  for (auto& [name, g] : m.facet_groups)
    for (Index& v : g.facets) v = to[v];
  for (auto& [name, g] : m.node_groups)
    for (Index& v : g) v = to[v];
}
}  // namespace

Mesh prism_mesh(CellType type, const Vec3& lo, const Vec3& hi, int nx, int ny, int nz) {
  if (nx < 1 || ny < 1 || nz < 1) throw std::invalid_argument("prism_mesh: divisions must be >= 1");
  if (cell_shape(type) != CellShape::kPrism) throw std::invalid_argument("prism_mesh: expects a prism type");
  Mesh m;
  m.dim = 3;
  // A lattice of q·n + 1 points per direction (q the order); every point is a node (but the sides' centres
  // of 15-node prisms, dropped at the end).
  const int q = cell_order(type), n[3] = {nx, ny, nz}, l[3] = {q * nx + 1, q * ny + 1, q * nz + 1};
  using P = std::array<int, 3>;
  auto id = [&](const P& p) -> Index { return (static_cast<Index>(p[2]) * l[1] + p[1]) * l[0] + p[0]; };
  auto mid = [](const P& a, const P& b) { return P{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2}; };
  auto up = [](P a, int dk) {
    a[2] += dk;
    return a;
  };
  m.x.resize(3, static_cast<Index>(l[0]) * l[1] * l[2]);
  for (int k = 0; k < l[2]; ++k)
    for (int j = 0; j < l[1]; ++j)
      for (int i = 0; i < l[0]; ++i) {
        const P p{i, j, k};
        for (int a = 0; a < 3; ++a) m.x(a, id(p)) = lo[a] + (hi[a] - lo[a]) * p[a] / (q * n[a]);
      }
  // The square (i, j) cut along its diagonal from (i, j) to (i + 1, j + 1): triangles counter-clockwise
  // seen from z > 0 (lattice points at level k), each extruded from level k to k + 1.
  const auto triangles = [&](int i, int j, int k) {
    const P a{q * i, q * j, q * k}, b{q * (i + 1), q * j, q * k}, c{q * (i + 1), q * (j + 1), q * k},
        d{q * i, q * (j + 1), q * k};
    return std::array<std::array<P, 3>, 2>{{{a, b, c}, {a, c, d}}};
  };
  // Gmsh's order (cell_type.hpp): Prism18 adds m01 m02 m03 m12 m14 m25 m34 m35 m45, then the sides'
  // centres (0 1 4 3) (0 2 5 3) (1 2 5 4).
  const auto prism = [&](const std::array<P, 3>& t) {
    std::vector<P> v{t[0], t[1], t[2], up(t[0], q), up(t[1], q), up(t[2], q)};
    if (q == 2)
      v.insert(v.end(), {mid(t[0], t[1]), mid(t[0], t[2]), up(t[0], 1), mid(t[1], t[2]), up(t[1], 1), up(t[2], 1),
                         up(mid(t[0], t[1]), 2), up(mid(t[0], t[2]), 2), up(mid(t[1], t[2]), 2),
                         up(mid(t[0], t[1]), 1), up(mid(t[0], t[2]), 1), up(mid(t[1], t[2]), 1)});
    return v;
  };
  std::vector<Index> cells;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& t : triangles(i, j, k)) {
          const std::vector<P> v = prism(t);
          for (int a = 0; a < cell_num_nodes(type); ++a) cells.push_back(id(v[a]));
        }
  m.set_cells(type, std::move(cells));
  // Facet groups: their vertices (locate_facets() takes the other nodes from the cells, in their order).
  const int tri_nodes = cell_num_nodes(facet_type(type)), quad_nodes = cell_num_nodes(cell_facet_type(type, 2));
  for (int side = 0; side < 2; ++side) {
    FacetGroup& g = m.facet_groups[side == 0 ? "zmin" : "zmax"];
    g.type = facet_type(type);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& t : triangles(i, j, side * nz))
          for (int a = 0; a < tri_nodes; ++a) g.facets.push_back(id(t[a % 3]));
  }
  const char* names[2][2] = {{"xmin", "xmax"}, {"ymin", "ymax"}};
  for (int ax = 0; ax < 2; ++ax)
    for (int side = 0; side < 2; ++side) {
      FacetGroup& g = m.facet_groups[names[ax][side]];
      g.type = cell_facet_type(type, 2);
      for (int k = 0; k < nz; ++k)
        for (int t = 0; t < n[1 - ax]; ++t) {
          const auto node = [&](int dt, int dk) {
            P c;
            c[ax] = q * side * n[ax];
            c[1 - ax] = q * (t + dt);
            c[2] = q * (k + dk);
            return id(c);
          };
          const Index corners[4] = {node(0, 0), node(1, 0), node(1, 1), node(0, 1)};
          for (int a = 0; a < quad_nodes; ++a) g.facets.push_back(corners[a % 4]);
        }
    }
  m.node_groups["origin"] = {0};
  drop_unused_nodes(m);
  m.locate_facets();
  return m;
}

Mesh mixed_rectangle_mesh(CellType type, double x0, double y0, double x1, double y1, int nx, int ny) {
  if (type != CellType::kQuad4 && type != CellType::kQuad9)
    throw std::invalid_argument("mixed_rectangle_mesh: expects Quad4 or Quad9");
  Mesh m = tensor_mesh(type, Vec3(x0, y0, 0), Vec3(x1, y1, 0), nx, ny);
  const Mesh quads = m;
  const CellType tri = type == CellType::kQuad4 ? CellType::kTri3 : CellType::kTri6;
  // Gmsh orders: Quad9 v0 v1 v2 v3 m01 m12 m23 m30 c, Tri6 v0 v1 v2 m01 m12 m20.
  static const int halves[2][6] = {{0, 1, 2, 4, 5, 8}, {0, 2, 3, 8, 6, 7}};
  const int ntri = cell_num_nodes(tri);
  m.cells.clear();
  m.cell_offsets.assign(1, 0);
  m.cell_blocks.assign(1, CellBlock{type, 0, 0});
  for (Index c = 0; c < quads.num_cells(); ++c) {
    const Index* n = quads.cell(c);
    if (((c % nx) + (c / nx)) % 2 != 0) {
      m.add_cells(type, n, 1);
      continue;
    }
    for (const auto& half : halves) {
      Index t[6];
      for (int a = 0; a < ntri; ++a) t[a] = n[half[a]];
      m.add_cells(tri, t, 1);
    }
  }
  m.locate_facets();
  return m;
}

Mesh elevate_to_p2(const Mesh& p1) {
  const CellType t1 = p1.first_cell_type();
  if (p1.mixed() || (t1 != CellType::kTri3 && t1 != CellType::kTet4))
    throw std::invalid_argument("elevate_to_p2: expects a Tri3 or Tet4 mesh");
  Mesh m;
  m.dim = p1.dim;
  std::vector<Index> cells;
  m.node_groups = p1.node_groups;
  std::map<std::pair<Index, Index>, Index> edge_node;
  std::vector<Eigen::VectorXd> extra;
  Index next = p1.num_nodes();
  auto mid = [&](Index a, Index b) {
    const auto key = std::minmax(a, b);
    auto it = edge_node.find(key);
    if (it != edge_node.end()) return it->second;
    extra.push_back(0.5 * (p1.x.col(a) + p1.x.col(b)));
    edge_node.emplace(key, next);
    return next++;
  };
  static const int tri_edges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  static const int tet_edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}};
  const bool tri = t1 == CellType::kTri3;
  for (Index c = 0; c < p1.num_cells(); ++c) {
    const Index* v = p1.cell(c);
    const int nv = tri ? 3 : 4;
    cells.insert(cells.end(), v, v + nv);
    for (int e = 0; e < (tri ? 3 : 6); ++e) {
      const auto& ed = tri ? tri_edges[e] : tet_edges[e];
      cells.push_back(mid(v[ed[0]], v[ed[1]]));
    }
  }
  m.set_cells(tri ? CellType::kTri6 : CellType::kTet10, std::move(cells));
  for (const auto& [name, g] : p1.facet_groups) {
    FacetGroup fg;
    const int nv = tri ? 2 : 3;
    for (std::size_t k = 0; k < g.facets.size(); k += nv) {
      const Index* v = g.facets.data() + k;
      fg.facets.insert(fg.facets.end(), v, v + nv);
      if (tri) {
        fg.facets.push_back(mid(v[0], v[1]));
      } else {
        for (int e = 0; e < 3; ++e) fg.facets.push_back(mid(v[tri_edges[e][0]], v[tri_edges[e][1]]));
      }
    }
    m.facet_groups[name] = std::move(fg);
  }
  m.x.resize(p1.dim, next);
  m.x.leftCols(p1.num_nodes()) = p1.x;
  for (std::size_t k = 0; k < extra.size(); ++k) m.x.col(p1.num_nodes() + static_cast<Index>(k)) = extra[k];
  m.locate_facets();
  return m;
}

Mesh pyramid_mesh(CellType type, const Vec3& lo, const Vec3& hi, int nx, int ny, int nz) {
  if (nx < 1 || ny < 1 || nz < 1) throw std::invalid_argument("pyramid_mesh: divisions must be >= 1");
  if (cell_shape(type) != CellShape::kPyramid) throw std::invalid_argument("pyramid_mesh: expects a pyramid type");
  Mesh m;
  m.dim = 3;
  // Lattice points at 1/S of a box (S = 2 at order 1 for the centres, 4 at order 2 for the midpoints of
  // the edges to them), numbered as first used.
  using P = std::array<int, 3>;
  const int S = 2 * cell_order(type), n[3] = {nx, ny, nz};
  std::map<P, Index> index;
  std::vector<P> points;
  const auto id = [&](const P& p) {
    const auto [it, added] = index.emplace(p, static_cast<Index>(points.size()));
    if (added) points.push_back(p);
    return it->second;
  };
  const auto mid = [](const P& a, const P& b) { return P{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2}; };
  // The group of a face on the box's boundary (its corners on one plane x, y or z = lo or hi), or null.
  const auto box_side = [&](const std::array<P, 4>& face) -> const char* {
    static const char* const kNames[3][2] = {{"xmin", "xmax"}, {"ymin", "ymax"}, {"zmin", "zmax"}};
    for (int axis = 0; axis < 3; ++axis) {
      const int c = face[0][axis];
      bool flat = true;
      for (const P& p : face) flat = flat && p[axis] == c;
      if (flat && (c == 0 || c == S * n[axis])) return kNames[axis][c == 0 ? 0 : 1];
    }
    return nullptr;
  };
  const int face_nodes = cell_num_nodes(cell_facet_type(type, 4));
  std::vector<Index> cells;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const P centre{S * i + S / 2, S * j + S / 2, S * k + S / 2};
        for (int f = 0; f < 6; ++f) {
          // The box's face f (counter-clockwise seen from outside) is the base of a pyramid with its apex at
          // the centre, listed in reverse to be counter-clockwise seen from the apex.
          const int* loc = cell_facet_nodes(CellType::kHex8, f);
          std::array<P, 4> face;
          for (int a = 0; a < 4; ++a) {
            const int* c = tensor_node_coordinates(CellType::kHex8, loc[a]);
            face[a] = P{S * (i + (c[0] + 1) / 2), S * (j + (c[1] + 1) / 2), S * (k + (c[2] + 1) / 2)};
          }
          const P v[5] = {face[3], face[2], face[1], face[0], centre};
          std::vector<P> nodes(v, v + 5);
          if (cell_order(type) == 2)  // Gmsh's m01 m03 m04 m12 m14 m23 m24 m34 (and the base's centre)
            for (int e = 5; e < cell_num_nodes(type); ++e) {
              const std::vector<int> ends = node_vertices(type, e);
              nodes.push_back(mid(v[ends[0]], v[ends[ends.size() / 2]]));
            }
          for (const P& p : nodes) cells.push_back(id(p));
          const char* group = box_side(face);
          if (!group) continue;
          FacetGroup& g = m.facet_groups[group];  // vertices; locate_facets() fills in the rest
          g.type = cell_facet_type(type, 4);
          for (int a = 0; a < face_nodes; ++a) g.facets.push_back(id(face[a % 4]));
        }
      }
  m.set_cells(type, std::move(cells));
  m.x.resize(3, static_cast<Index>(points.size()));
  for (std::size_t p = 0; p < points.size(); ++p)
    for (int a = 0; a < 3; ++a)
      m.x(a, static_cast<Index>(p)) = lo[a] + (hi[a] - lo[a]) * points[p][a] / (S * n[a]);
  m.node_groups["origin"] = {id(P{0, 0, 0})};
  m.locate_facets();
  return m;
}

Mesh structured_mesh(CellType type, const Vec3& lo, const Vec3& hi, int nx, int ny, int nz) {
  switch (cell_shape(type)) {
    case CellShape::kPrism: return prism_mesh(type, lo, hi, nx, ny, nz);
    case CellShape::kPyramid: return pyramid_mesh(type, lo, hi, nx, ny, nz);
    case CellShape::kTensor: return tensor_mesh(type, lo, hi, nx, ny, nz);
    default: break;
  }
  return cell_dim(type) == 2 ? rectangle_mesh(lo[0], lo[1], hi[0], hi[1], nx, ny, cell_order(type))
                             : box_mesh(lo, hi, nx, ny, nz, cell_order(type));
}

namespace {
/// Puts the non-vertex nodes of each cell where the order-1 map of its vertices puts them: at the mean of
/// their node_vertices().
void reset_higher_nodes(Mesh& mesh, const CellBlock& b) {
  for (Index c = b.begin; c < b.end; ++c) {
    const Index* n = mesh.cell(c);
    for (int a = cell_num_vertices(b.type); a < cell_num_nodes(b.type); ++a) {
      const std::vector<int> from = node_vertices(b.type, a);
      Eigen::VectorXd x = Eigen::VectorXd::Zero(mesh.dim);
      for (int v : from) x += mesh.x.col(n[v]);
      mesh.x.col(n[a]) = x / static_cast<double>(from.size());
    }
  }
}
}  // namespace

void perturb_interior_nodes(Mesh& mesh, double h, double amplitude, unsigned seed) {
  std::vector<char> on_boundary(mesh.num_nodes(), 0);
  for (const auto& [name, g] : mesh.facet_groups)
    for (Index v : g.facets) on_boundary[v] = 1;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-amplitude * h, amplitude * h);
  std::vector<char> is_vertex(mesh.num_nodes(), 0);
  for (const CellBlock& b : mesh.cell_blocks)
    for (Index c = b.begin; c < b.end; ++c)
      for (int a = 0; a < cell_num_vertices(b.type); ++a) is_vertex[mesh.cell(c)[a]] = 1;
  for (Index v = 0; v < mesh.num_nodes(); ++v)
    if (!on_boundary[v] && is_vertex[v])
      for (int i = 0; i < mesh.dim; ++i) mesh.x(i, v) += U(rng);
  for (const CellBlock& b : mesh.cell_blocks) reset_higher_nodes(mesh, b);
}

}  // namespace symcontact
