#include "support/finite_difference.hpp"

#include <algorithm>
#include <random>

#include "symcontact/mesh/structured.hpp"

namespace symcontact::testing {

FdResult check_derivatives(const EnergyTerm& term, const VectorXd& u, double h, int directions, int max_dofs,
                           unsigned seed) {
  FdResult r;
#ifdef SYMCONTACT_SANITIZED
  max_dofs = std::min(max_dofs, kSanitisedMaxDofs);
#endif
  const Index n = u.size();
  VectorXd g = VectorXd::Zero(n);
  term.add_gradient(u, g);
  std::mt19937 rng(seed);
  std::vector<Index> idx(n);
  for (Index i = 0; i < n; ++i) idx[i] = i;
  if (n > max_dofs) {
    std::shuffle(idx.begin(), idx.end(), rng);
    idx.resize(max_dofs);
  }
  const double gscale = std::max(1.0, g.cwiseAbs().maxCoeff());
  VectorXd up = u, um = u;
  for (Index i : idx) {
    up[i] += h;
    um[i] -= h;
    const double fd = (term.value(up) - term.value(um)) / (2 * h);
    up[i] = um[i] = u[i];
    r.gradient_error = std::max(r.gradient_error, std::abs(fd - g[i]) / gscale);
  }
  TripletSink sink;
  term.add_hessian(u, sink);
  const SparseMatrix H = sink.to_matrix(n);
  std::normal_distribution<double> N01;
  for (int k = 0; k < directions; ++k) {
    VectorXd d(n);
    for (Index i = 0; i < n; ++i) d[i] = N01(rng);
    d /= d.norm();
    const VectorXd Hd = H * d;
    VectorXd gp = VectorXd::Zero(n), gm = VectorXd::Zero(n);
    term.add_gradient(u + h * d, gp);
    term.add_gradient(u - h * d, gm);
    const VectorXd fd = (gp - gm) / (2 * h);
    const double scale = std::max(1.0, Hd.cwiseAbs().maxCoeff());
    r.hessian_error = std::max(r.hessian_error, (fd - Hd).cwiseAbs().maxCoeff() / scale);
  }
  return r;
}

Mesh distorted_mesh(int dim, int order, std::optional<CellType> tensor, bool mixed) {
  Mesh m = tensor && mixed                ? mixed_rectangle_mesh(*tensor, 0, 0, 2, 1, 4, 3)
         : tensor && cell_dim(*tensor) == 3 && cell_shape(*tensor) != CellShape::kTensor
             ? structured_mesh(*tensor, Vec3(0, 0, 0), Vec3(1, 1, 2), 2, 2, 3)
         : tensor ? tensor_mesh(*tensor, Vec3(0, 0, 0), dim == 2 ? Vec3(2, 1, 0) : Vec3(1, 1, 2), dim == 2 ? 4 : 2,
                                dim == 2 ? 3 : 2, 2)
         : dim == 2 ? rectangle_mesh(0, 0, 2, 1, 4, 3, order)
                    : box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 2), 2, 2, 3, order);
  perturb_interior_nodes(m, 0.25, 0.2, 7);
  return m;
}

}  // namespace symcontact::testing
