#include "symcontact/fem/shape_functions.hpp"

#include <cmath>
#include <stdexcept>

namespace symcontact {

namespace {
// Edge (a, b) of the P2 node list, in Gmsh order, for each simplex.
const int kLineEdges[1][2] = {{0, 1}};
const int kTriEdges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
const int kTetEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}};

/// 1D Lagrange polynomial on [0, 1] of order p through the node at c ∈ {−1, 0, 1} (ξ = 0, ½, 1): value
/// and derivative.
void lagrange_1d(int p, int c, double x, double& v, double& dv) {
  if (p == 1) {
    v = c < 0 ? 1.0 - x : x;
    dv = c < 0 ? -1.0 : 1.0;
  } else if (c < 0) {
    v = (1.0 - x) * (1.0 - 2.0 * x);
    dv = 4.0 * x - 3.0;
  } else if (c > 0) {
    v = x * (2.0 * x - 1.0);
    dv = 4.0 * x - 1.0;
  } else {
    v = 4.0 * x * (1.0 - x);
    dv = 4.0 - 8.0 * x;
  }
}

/// Product Π_i f_i and its derivatives ∂/∂x_k = f'_k Π_{i≠k} f_i over d factors.
double product(int d, const double* f, const double* df, double* grad) {
  double v = 1.0;
  for (int i = 0; i < d; ++i) v *= f[i];
  for (int k = 0; k < d; ++k) {
    grad[k] = df[k];
    for (int i = 0; i < d; ++i)
      if (i != k) grad[k] *= f[i];
  }
  return v;
}

/// Serendipity Quad8 / Hex20 (see the header) at ξ ∈ [0, 1]^d.
void serendipity(CellType t, const double* xi, double* N, double* dN) {
  const int d = cell_dim(t);
  for (int a = 0; a < cell_num_nodes(t); ++a) {
    const int* c = tensor_node_coordinates(t, a);
    double f[3], df[3], g[3];
    int zero = -1;  // the direction along which an edge node's coordinate is 0
    for (int i = 0; i < d; ++i) {
      const double s = 2.0 * xi[i] - 1.0;
      if (c[i] == 0) {
        zero = i;
        f[i] = 1.0 - s * s;
        df[i] = -4.0 * s;  // d/dξ = 2 d/ds
      } else {
        f[i] = 1.0 + s * c[i];
        df[i] = 2.0 * c[i];
      }
    }
    double v = product(d, f, df, g);
    if (zero < 0) {
      double S = 1.0 - d;
      for (int i = 0; i < d; ++i) S += (2.0 * xi[i] - 1.0) * c[i];
      for (int k = 0; k < d; ++k) g[k] = g[k] * S + v * 2.0 * c[k];
      v *= S;
    }
    const double scale = zero < 0 ? std::ldexp(1.0, -d) : std::ldexp(1.0, 1 - d);
    if (N) N[a] = scale * v;
    if (dN)
      for (int k = 0; k < d; ++k) dN[a * d + k] = scale * g[k];
  }
}

/// Quad4, Quad9, Hex8, Hex27 and the serendipity Quad8, Hex20 at ξ ∈ [0, 1]^d.
void tensor_shape_functions(CellType t, const double* xi, double* N, double* dN) {
  const int d = cell_dim(t), nn = cell_num_nodes(t), p = cell_order(t);
  if (t == CellType::kQuad8 || t == CellType::kHex20) return serendipity(t, xi, N, dN);
  for (int a = 0; a < nn; ++a) {
    double f[3], df[3], g[3];
    const int* c = tensor_node_coordinates(t, a);
    for (int i = 0; i < d; ++i) lagrange_1d(p, c[i], xi[i], f[i], df[i]);
    const double v = product(d, f, df, g);
    if (N) N[a] = v;
    if (dN)
      for (int k = 0; k < d; ++k) dN[a * d + k] = g[k];
  }
}
/// The prisms: node a's function is the triangle's (Tri3, Tri6) function of its node kTriNode[a] in (ξ, η)
/// times the 1D Lagrange function of its level in ζ (−1, 0, 1: ζ = 0, ½, 1), in Gmsh's node order.
void prism_shape_functions(CellType t, const double* xi, double* N, double* dN) {
  static const int kTriNode[18] = {0, 1, 2, 0, 1, 2, 3, 5, 0, 4, 1, 2, 3, 5, 4, 3, 5, 4};
  static const int kLevel[18] = {-1, -1, -1, 1, 1, 1, -1, -1, 0, -1, 0, 0, 1, 1, 1, 0, 0, 0};
  const int p = cell_order(t);
  const CellType tri = p == 1 ? CellType::kTri3 : CellType::kTri6;
  double Nt[6], dNt[12];
  shape_functions(tri, xi, Nt, dNt);
  for (int a = 0; a < cell_num_nodes(t); ++a) {
    double z, dz;
    lagrange_1d(p, kLevel[a], xi[2], z, dz);
    const int i = kTriNode[a];
    if (N) N[a] = Nt[i] * z;
    if (dN) {
      dN[3 * a] = dNt[2 * i] * z;
      dN[3 * a + 1] = dNt[2 * i + 1] * z;
      dN[3 * a + 2] = Nt[i] * dz;
    }
  }
}
}  // namespace

void shape_functions(CellType t, const double* xi, double* N, double* dN) {
  if (cell_shape(t) == CellShape::kTensor) return tensor_shape_functions(t, xi, N, dN);
  if (cell_shape(t) == CellShape::kPrism) return prism_shape_functions(t, xi, N, dN);
  const int d = cell_dim(t);
  if (d == 0) {
    if (N) N[0] = 1.0;
    return;
  }
  // Barycentric coordinates and their (constant) reference gradients.
  double L[4];
  double dL[4][3] = {};
  L[0] = 1.0;
  for (int i = 0; i < d; ++i) {
    L[0] -= xi[i];
    L[i + 1] = xi[i];
    dL[0][i] = -1.0;
    dL[i + 1][i] = 1.0;
  }
  const int nv = d + 1;
  if (cell_order(t) == 1) {
    for (int a = 0; a < nv; ++a) {
      if (N) N[a] = L[a];
      if (dN)
        for (int i = 0; i < d; ++i) dN[a * d + i] = dL[a][i];
    }
    return;
  }
  for (int a = 0; a < nv; ++a) {
    if (N) N[a] = L[a] * (2.0 * L[a] - 1.0);
    if (dN)
      for (int i = 0; i < d; ++i) dN[a * d + i] = (4.0 * L[a] - 1.0) * dL[a][i];
  }
  const int(*edges)[2] = d == 1 ? kLineEdges : (d == 2 ? kTriEdges : kTetEdges);
  const int ne = d == 1 ? 1 : (d == 2 ? 3 : 6);
  for (int e = 0; e < ne; ++e) {
    const int a = edges[e][0], b = edges[e][1], k = nv + e;
    if (N) N[k] = 4.0 * L[a] * L[b];
    if (dN)
      for (int i = 0; i < d; ++i) dN[k * d + i] = 4.0 * (dL[a][i] * L[b] + L[a] * dL[b][i]);
  }
}

std::vector<double> reference_nodes(CellType t) {
  const int d = cell_dim(t);
  std::vector<double> v;
  if (d == 0) return v;
  if (cell_shape(t) == CellShape::kTensor) {
    for (int a = 0; a < cell_num_nodes(t); ++a)
      for (int i = 0; i < d; ++i) v.push_back(0.5 * (tensor_node_coordinates(t, a)[i] + 1));
    return v;
  }
  if (cell_shape(t) == CellShape::kPrism) {
    static const double prism18[18][3] = {{0, 0, 0},   {1, 0, 0},   {0, 1, 0},     {0, 0, 1},   {1, 0, 1},
                                          {0, 1, 1},   {.5, 0, 0},  {0, .5, 0},    {0, 0, .5},  {.5, .5, 0},
                                          {1, 0, .5},  {0, 1, .5},  {.5, 0, 1},    {0, .5, 1},  {.5, .5, 1},
                                          {.5, 0, .5}, {0, .5, .5}, {.5, .5, .5}};  // Gmsh's, ζ mapped to [0, 1]
    for (int a = 0; a < cell_num_nodes(t); ++a) v.insert(v.end(), prism18[a], prism18[a] + 3);
    return v;
  }
  const int nv = d + 1;
  std::vector<std::vector<double>> verts(nv, std::vector<double>(d, 0.0));
  for (int i = 0; i < d; ++i) verts[i + 1][i] = 1.0;
  for (int a = 0; a < nv; ++a) v.insert(v.end(), verts[a].begin(), verts[a].end());
  if (cell_order(t) == 2) {
    const int(*edges)[2] = d == 1 ? kLineEdges : (d == 2 ? kTriEdges : kTetEdges);
    const int ne = d == 1 ? 1 : (d == 2 ? 3 : 6);
    for (int e = 0; e < ne; ++e)
      for (int i = 0; i < d; ++i) v.push_back(0.5 * (verts[edges[e][0]][i] + verts[edges[e][1]][i]));
  }
  return v;
}

Tabulation tabulate(CellType t, const QuadratureRule& rule) {
  Tabulation tab;
  tab.type = t;
  tab.num_nodes = cell_num_nodes(t);
  tab.dim = cell_dim(t);
  tab.rule = rule;
  if (rule.dim != tab.dim) throw std::invalid_argument("tabulate: rule and cell dimensions differ");
  tab.N.resize(rule.size() * tab.num_nodes);
  tab.dN.resize(rule.size() * tab.num_nodes * tab.dim);
  for (int q = 0; q < rule.size(); ++q)
    shape_functions(t, rule.point(q), tab.N.data() + q * tab.num_nodes,
                    tab.dN.data() + q * tab.num_nodes * tab.dim);
  return tab;
}

}  // namespace symcontact
