#include "symcontact/fem/shape_functions.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>

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
/// The prisms in Gmsh's node order, each node with its node of the triangle (Tri3, Tri6) in (ξ, η) and its
/// level in ζ (−1, 0, 1: ζ = 0, ½, 1). Prism6 and Prism18: the triangle's function times the 1D Lagrange one
/// of the level. Prism15 (serendipity), with s = 2ζ − 1, T the Tri6 and L the Tri3 function: vertices
/// ½ T (1 + c s) − ½ L (1 − s²), triangle edge nodes ½ T (1 + c s), vertical edge nodes L (1 − s²)
/// (Zienkiewicz & Taylor, "The finite element method", vol. 1, §8.9).
void prism_shape_functions(CellType t, const double* xi, double* N, double* dN) {
  static const int kTriNode[18] = {0, 1, 2, 0, 1, 2, 3, 5, 0, 4, 1, 2, 3, 5, 4, 3, 5, 4};
  static const int kLevel[18] = {-1, -1, -1, 1, 1, 1, -1, -1, 0, -1, 0, 0, 1, 1, 1, 0, 0, 0};
  const int p = cell_order(t);
  double T[6], dT[12], L[3], dL[6];
  shape_functions(p == 1 ? CellType::kTri3 : CellType::kTri6, xi, T, dT);
  shape_functions(CellType::kTri3, xi, L, dL);
  const double s = 2.0 * xi[2] - 1.0;
  for (int a = 0; a < cell_num_nodes(t); ++a) {
    const int i = kTriNode[a], c = kLevel[a];
    double f, df, g = 0.0, dg = 0.0;  // N = T_i f(ζ) + L_i g(ζ)
    if (t != CellType::kPrism15) {
      lagrange_1d(p, c, xi[2], f, df);
    } else if (c == 0) {
      f = df = 0.0;
      g = 1.0 - s * s;
      dg = -4.0 * s;
    } else {
      f = 0.5 * (1.0 + c * s);
      df = c;
      if (i < 3) {
        g = -0.5 * (1.0 - s * s);
        dg = 2.0 * s;
      }
    }
    const double Li = i < 3 ? L[i] : 0.0, dLx = i < 3 ? dL[2 * i] : 0.0, dLy = i < 3 ? dL[2 * i + 1] : 0.0;
    if (N) N[a] = T[i] * f + Li * g;
    if (dN) {
      dN[3 * a] = dT[2 * i] * f + dLx * g;
      dN[3 * a + 1] = dT[2 * i + 1] * f + dLy * g;
      dN[3 * a + 2] = T[i] * df + Li * dg;
    }
  }
}

/// The pyramid's vertices: Gmsh's (X, Y, Z) on the base [−1, 1]² with the apex at (0, 0, 1), mapped to
/// ξ = (X + 1 − Z) / 2, η = (Y + 1 − Z) / 2, ζ = Z.
const double kPyramidVertices[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}};

/// The pyramids' space (Bergot, Cohen & Duruflé, "Higher-order finite elements for hybrid meshes using
/// new nodal pyramidal elements", J. Sci. Comput. 42, 2010): with a = ξ / (1 − ζ), b = η / (1 − ζ),
/// φ_ijk = a^i b^j (1 − ζ)^max(i,j) ζ^k for 0 ≤ i, j ≤ p and 0 ≤ k ≤ p − max(i, j). It holds P_p, its trace
/// on a triangle is P_p and on the base Q_p: Pyramid5 (p = 1) is the classical rational pyramid, Pyramid14
/// (p = 2) conforms to Tet10 and Hex27. Pyramid13 drops φ_220 (the a²b² of the base), whose trace on the
/// triangles lies in the span of the others: its base trace is the serendipity Quad8's, so it conforms to
/// Tet10 and Hex20. The nodal basis is C φ with C the inverse of the matrix of the φ at the nodes.
struct PyramidBasis {
  std::vector<std::array<int, 3>> ijk;
  Eigen::MatrixXd C;  ///< C(p, a): coefficient of φ_p in node a's function

  explicit PyramidBasis(CellType t) {
    const int p = cell_order(t);
    for (int i = 0; i <= p; ++i)
      for (int j = 0; j <= p; ++j)
        for (int k = 0; k <= p - std::max(i, j); ++k)
          if (!(t == CellType::kPyramid13 && i == 2 && j == 2)) ijk.push_back({i, j, k});
    const int n = cell_num_nodes(t);
    if (static_cast<int>(ijk.size()) != n) throw std::logic_error("PyramidBasis: space and nodes differ in size");
    Eigen::MatrixXd V(n, n);
    const std::vector<double> nodes = reference_nodes(t);
    for (int a = 0; a < n; ++a) evaluate(nodes.data() + 3 * a, V.data() + a, n, nullptr);
    C = V.fullPivLu().inverse();
  }

  /// φ_p(ξ) into phi[p * stride] and, if dphi is given, ∇φ_p into dphi[3 p ..]. At the apex (ζ = 1) the
  /// values are 1 for the φ with max(i, j) = 0 and 0 for the others, whatever a and b; the gradients, which
  /// depend on the direction of approach, are their limits along the axis (a = b = ½).
  void evaluate(const double* xi, double* phi, int stride, double* dphi) const {
    const double w = 1.0 - xi[2], z = xi[2];
    const double a = w > 0 ? xi[0] / w : 0.5, b = w > 0 ? xi[1] / w : 0.5;
    for (std::size_t q = 0; q < ijk.size(); ++q) {
      const int i = ijk[q][0], j = ijk[q][1], k = ijk[q][2], m = std::max(i, j);
      const double ab = std::pow(a, i) * std::pow(b, j), zk = std::pow(z, k);
      phi[q * stride] = ab * std::pow(w, m) * zk;
      if (!dphi) continue;
      const double wm1 = m > 0 ? std::pow(w, m - 1) : 0.0;  // (1 − ζ)^(m − 1), multiplied by 0 when m = 0
      double* g = dphi + 3 * q;
      g[0] = i > 0 ? i * std::pow(a, i - 1) * std::pow(b, j) * wm1 * zk : 0.0;
      g[1] = j > 0 ? j * std::pow(a, i) * std::pow(b, j - 1) * wm1 * zk : 0.0;
      g[2] = (i + j - m) * ab * wm1 * zk + (k > 0 ? k * ab * std::pow(w, m) * std::pow(z, k - 1) : 0.0);
    }
  }
};

/// The pyramids' nodal functions.
void pyramid_shape_functions(CellType t, const double* xi, double* N, double* dN) {
  static const PyramidBasis basis[3] = {PyramidBasis(CellType::kPyramid5), PyramidBasis(CellType::kPyramid13),
                                        PyramidBasis(CellType::kPyramid14)};
  const PyramidBasis& B = basis[static_cast<int>(t) - static_cast<int>(CellType::kPyramid5)];
  const int n = cell_num_nodes(t);
  double phi[14], dphi[42];
  const bool gradients = dN != nullptr;
  B.evaluate(xi, phi, 1, gradients ? dphi : nullptr);
  for (int a = 0; a < n; ++a) {
    if (N) N[a] = 0.0;
    if (gradients) dN[3 * a] = dN[3 * a + 1] = dN[3 * a + 2] = 0.0;
    for (int q = 0; q < n; ++q) {
      const double c = B.C(q, a);
      if (N) N[a] += c * phi[q];
      if (gradients)
        for (int i = 0; i < 3; ++i) dN[3 * a + i] += c * dphi[3 * q + i];
    }
  }
}
}  // namespace

void shape_functions(CellType t, const double* xi, double* N, double* dN) {
  if (cell_shape(t) == CellShape::kTensor) return tensor_shape_functions(t, xi, N, dN);
  if (cell_shape(t) == CellShape::kPrism) return prism_shape_functions(t, xi, N, dN);
  if (cell_shape(t) == CellShape::kPyramid) return pyramid_shape_functions(t, xi, N, dN);
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
  const int d = cell_dim(t), nv = cell_num_vertices(t);
  std::vector<double> v;
  if (d == 0) return v;
  // The vertices (cell_type.hpp's reference cells), then every node at the mean of its node_vertices().
  std::vector<double> vertex(static_cast<std::size_t>(nv) * d, 0.0);
  for (int a = 0; a < nv; ++a) {
    double* x = vertex.data() + a * d;
    switch (cell_shape(t)) {
      case CellShape::kTensor:
        for (int i = 0; i < d; ++i) x[i] = 0.5 * (tensor_node_coordinates(t, a)[i] + 1);
        break;
      case CellShape::kPrism:  // the unit triangle's vertices at ζ = 0, then at ζ = 1
        if (a % 3 > 0) x[a % 3 - 1] = 1.0;
        x[2] = a < 3 ? 0.0 : 1.0;
        break;
      case CellShape::kPyramid:
        std::copy(kPyramidVertices[a], kPyramidVertices[a] + 3, x);
        break;
      default:  // the origin, then the unit vectors
        if (a > 0) x[a - 1] = 1.0;
    }
  }
  for (int a = 0; a < cell_num_nodes(t); ++a) {
    const std::vector<int> from = node_vertices(t, a);
    for (int i = 0; i < d; ++i) {
      double sum = 0.0;
      for (int w : from) sum += vertex[w * d + i];
      v.push_back(sum / static_cast<double>(from.size()));
    }
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
