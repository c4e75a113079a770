#include "support/quadratic_energy.hpp"

#include <algorithm>
#include <vector>

namespace symcontact::testing {

SparseMatrix grid_laplacian(int m, double shift) {
  std::vector<Triplet> t;
  auto id = [m](int i, int j) { return i * m + j; };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      t.emplace_back(id(i, j), id(i, j), shift);
      const int nb[2][2] = {{i + 1, j}, {i, j + 1}};
      for (const auto& q : nb) {
        if (q[0] >= m || q[1] >= m) continue;
        const int a = id(i, j), b = id(q[0], q[1]);
        t.emplace_back(a, a, 1.0);
        t.emplace_back(b, b, 1.0);
        t.emplace_back(std::max(a, b), std::min(a, b), -1.0);
      }
    }
  SparseMatrix k(m * m, m * m);
  k.setFromTriplets(t.begin(), t.end());
  k.makeCompressed();
  return k;  // lower triangle only
}

double QuadraticEnergy::value(const VectorXd& u) const {
  return 0.5 * u.dot(k_.selfadjointView<Eigen::Lower>() * u) - f_.dot(u);
}

void QuadraticEnergy::add_gradient(const VectorXd& u, VectorXd& g) const {
  g += k_.selfadjointView<Eigen::Lower>() * u - f_;
}

void QuadraticEnergy::add_hessian(const VectorXd&, MatrixSink& sink) const {
  const SparseMatrix full = k_.selfadjointView<Eigen::Lower>();
  for (int j = 0; j < full.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(full, j); it; ++it) {
      const Index d[2] = {it.row(), j};
      if (d[0] == d[1]) {
        const double v = it.value();
        sink.add(d, 1, &v);
      } else {
        // a 2 × 2 block holding only this off-diagonal entry (once per ordered pair: halves)
        const double blk[4] = {0.0, 0.5 * it.value(), 0.5 * it.value(), 0.0};
        sink.add(d, 2, blk);
      }
    }
}

}  // namespace symcontact::testing
