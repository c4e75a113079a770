#include "symcontact/solvers/equilibrium_solver.hpp"

#include <cmath>
#include <sstream>

#include "symcontact/core/error.hpp"
#include "symcontact/fem/matrix_sink.hpp"
#include "symcontact/solvers/cholesky.hpp"

namespace symcontact {

namespace {
double free_norm(const VectorXd& g, const std::vector<Index>& free_index) {
  double s = 0.0;
  for (Index d = 0; d < g.size(); ++d)
    if (free_index[d] >= 0) s += g[d] * g[d];
  return std::sqrt(s);
}
}  // namespace

EquilibriumReport solve_equilibrium(const EnergyTerm& energy, const FixedDofs& fixed, VectorXd& u,
                                    const EquilibriumOptions& options) {
  EquilibriumReport rep;
  const Index n = u.size();
  std::vector<Index> free_index;
  rep.num_free = fixed.free_numbering(n, free_index);
  fixed.impose(u);

  // Scale of the problem: the load vector seen at u = 0 (−∇E(0) restricted to free DOFs).
  VectorXd g0 = VectorXd::Zero(n);
  energy.add_gradient(VectorXd::Zero(n), g0);
  const double load_scale = free_norm(g0, free_index);

  CholeskySolver chol;
  SparseMatrix K;
  bool have_factor = false;
  const bool constant = energy.hessian_is_constant();
  VectorXd g(n), rhs(rep.num_free);
  for (int it = 0;; ++it) {
    {
      ScopedPhase t(rep.times, "assembly");
      g.setZero();
      energy.add_gradient(u, g);
    }
    const double r = free_norm(g, free_index);
    if (it == 0) rep.residual0 = r;
    rep.residual = r;
    const double scale = std::max(load_scale, rep.residual0);
    if (r <= options.tolerance * scale || scale == 0.0) break;
    if (constant && it >= 1) {
      // One exact Newton step solves a quadratic problem; a large residual left means the
      // factorisation was meaningless (a nearly singular stiffness).
      if (r > 1e-6 * scale)
        throw SolveError("the stiffness matrix is singular: a body can move without deforming (a rigid-body "
                         "motion no Dirichlet condition prevents) — add Dirichlet conditions (the linear solve left a "
                         "relative residual of " + std::to_string(r / scale) + ")");
      break;
    }
    if (!std::isfinite(r)) throw SolveError("Newton iteration produced a non-finite residual");
    if (it >= options.max_iterations) {
      std::ostringstream s;
      s << "Newton did not converge in " << options.max_iterations << " iterations (residual " << r
        << ", tolerance " << options.tolerance * scale << ")";
      throw SolveError(s.str());
    }
    if (!have_factor || !constant) {
      {
        ScopedPhase t(rep.times, "assembly");
        ReducedTripletSink sink(free_index);
        energy.add_hessian(u, sink);
        K = sink.to_lower_matrix(rep.num_free);
      }
      ScopedPhase t(rep.times, "factorization");
      chol.compute(K);
      rep.factor_nonzeros = chol.factor_nonzeros();
      have_factor = true;
    }
    ScopedPhase t(rep.times, "solve");
    for (Index d = 0; d < n; ++d)
      if (free_index[d] >= 0) rhs[free_index[d]] = -g[d];
    const VectorXd du = chol.solve(rhs);
    for (Index d = 0; d < n; ++d)
      if (free_index[d] >= 0) u[d] += du[free_index[d]];
    rep.iterations = it + 1;
  }
  return rep;
}

}  // namespace symcontact
