#include "symcontact/fem/shape_functions.hpp"

#include <stdexcept>

namespace symcontact {

namespace {
// Edge (a, b) of the P2 node list, in Gmsh order, for each simplex.
const int kLineEdges[1][2] = {{0, 1}};
const int kTriEdges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
const int kTetEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}};
}  // namespace

void shape_functions(CellType t, const double* xi, double* N, double* dN) {
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
