#include "symcontact/solvers/equilibrium_solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "symcontact/core/error.hpp"
#include "symcontact/fem/matrix_sink.hpp"
#include "symcontact/solvers/cholesky.hpp"

namespace symcontact {

namespace {
/// ‖g_free‖₂ without overflow or underflow: m·sqrt(Σ (g_d/m)²) with m = max |g_d| (forces of 1e200 have
/// a finite norm even though their squares do not). Non-finite entries give a non-finite norm.
double free_norm(const VectorXd& g, const std::vector<Index>& free_index) {
  double m = 0.0;
  for (Index d = 0; d < g.size(); ++d)
    if (free_index[d] >= 0) m = std::max(m, std::abs(g[d]));
  if (m == 0.0 || !std::isfinite(m)) return m;
  double s = 0.0;
  for (Index d = 0; d < g.size(); ++d)
    if (free_index[d] >= 0) s += (g[d] / m) * (g[d] / m);
  return m * std::sqrt(s);
}

/// Collects K_ff (lower, free numbering) and adds −K_fD Δu_D to `rhs` (free numbering) from the same
/// element blocks, so that the coupling to moving Dirichlet DOFs costs no second assembly.
class CouplingSink : public MatrixSink {
 public:
  CouplingSink(const std::vector<Index>& free_index, const VectorXd& jump, VectorXd& rhs)
      : reduced_(free_index), free_index_(free_index), jump_(jump), rhs_(rhs) {}
  void add(const Index* dofs, int n, const double* K) override {
    reduced_.add(dofs, n, K);
    for (int c = 0; c < n; ++c) {
      if (free_index_[dofs[c]] >= 0 || jump_[dofs[c]] == 0.0) continue;
      for (int r = 0; r < n; ++r)
        if (free_index_[dofs[r]] >= 0) rhs_[free_index_[dofs[r]]] -= K[c * n + r] * jump_[dofs[c]];
    }
  }
  SparseMatrix to_lower_matrix(Index num_free) const { return reduced_.to_lower_matrix(num_free); }

 private:
  ReducedTripletSink reduced_;
  const std::vector<Index>& free_index_;
  const VectorXd& jump_;
  VectorXd& rhs_;
};

/// Δu_D = target − u on fixed DOFs (0 elsewhere); returns max |Δu_D|.
double dirichlet_jump(const FixedDofs& fixed, const VectorXd& u, VectorXd& jump) {
  VectorXd target = u;
  fixed.impose(target);
  jump = target - u;
  return jump.size() ? jump.cwiseAbs().maxCoeff() : 0.0;
}

/// Factorises K, or K + τ I when K is not positive definite and the energy is not quadratic (see the
/// header); a quadratic energy with a singular K is a modelling error and is reported as such.
void factorize_descent(CholeskySolver& chol, const SparseMatrix& K, bool constant, EquilibriumReport& rep) {
  try {
    chol.compute(K);
    return;
  } catch (const SolveError&) {
    if (constant) throw;
  }
  const double dmax = K.diagonal().cwiseAbs().maxCoeff();
  SparseMatrix I(K.rows(), K.cols());
  I.setIdentity();
  for (double tau = 1e-8 * dmax; tau <= 1e4 * dmax; tau *= 10.0) {
    try {
      chol.compute(K + tau * I);
      ++rep.shifted_factorizations;
      return;
    } catch (const SolveError&) {
    }
  }
  throw SolveError("Newton: the tangent stiffness stays indefinite after shifting it by 1e4 × its largest diagonal "
                   "entry (an unstable or unconstrained state)");
}

/// u + s du for the largest s = 2^-k (k ≤ max_backtracks) at which E can be evaluated.
VectorXd admissible_step(const EnergyTerm& energy, const VectorXd& u, const VectorXd& du,
                         const EquilibriumOptions& options, EquilibriumReport& rep) {
  double s = 1.0;
  std::string failure;
  for (int k = 0; k <= options.max_backtracks; ++k, s *= 0.5) {
    if (k > 0) ++rep.backtracks;
    VectorXd trial = u + s * du;
    try {
      if (std::isfinite(energy.value(trial))) return trial;
    } catch (const EvaluationError& e) {
      failure = e.what();
    }
  }
  throw SolveError("Newton: no admissible step toward the imposed Dirichlet values after " +
                   std::to_string(options.max_backtracks) + " halvings (" + failure + "); try smaller load steps");
}

/// Backtracking line search from u along du (g = ∇E(u), r = ‖g_f‖); returns the accepted point.
VectorXd line_search(const EnergyTerm& energy, const std::vector<Index>& free_index, const VectorXd& u,
                     const VectorXd& g, double r, const VectorXd& du, const EquilibriumOptions& options,
                     EquilibriumReport& rep) {
  constexpr double c = 1e-4;
  const double e0 = energy.value(u);
  const double slope = g.dot(du);  // < 0 for a descent direction
  VectorXd trial(u.size()), gt(u.size());
  double s = 1.0;
  std::string last_failure = "no decrease of the energy or the residual";
  for (int k = 0; k <= options.max_backtracks; ++k, s *= 0.5) {
    if (k > 0) ++rep.backtracks;
    trial = u + s * du;
    try {
      const double e1 = energy.value(trial);
      if (std::isfinite(e1) && e1 <= e0 + c * s * slope) return trial;
      gt.setZero();
      energy.add_gradient(trial, gt);
      const double rt = free_norm(gt, free_index);
      if (std::isfinite(rt) && rt <= (1.0 - c * s) * r) return trial;
    } catch (const EvaluationError& e) {
      last_failure = e.what();
    }
  }
  std::ostringstream m;
  m << "Newton line search found no acceptable step after " << options.max_backtracks
    << " halvings (last failure: " << last_failure << "); try smaller load steps";
  throw SolveError(m.str());
}
}  // namespace

EquilibriumReport solve_equilibrium(const EnergyTerm& energy, const FixedDofs& fixed, VectorXd& u,
                                    const EquilibriumOptions& options) {
  EquilibriumReport rep;
  const Index n = u.size();
  std::vector<Index> free_index;
  rep.num_free = fixed.free_numbering(n, free_index);
  const bool constant = energy.hessian_is_constant();
  if (constant) fixed.impose(u);
  VectorXd jump;
  dirichlet_jump(fixed, u, jump);

  // Scale of the problem: the load vector seen at u = 0 (−∇E(0) restricted to free DOFs).
  VectorXd g0 = VectorXd::Zero(n);
  energy.add_gradient(VectorXd::Zero(n), g0);
  const double load_scale = free_norm(g0, free_index);

  CholeskySolver chol;
  SparseMatrix K;
  bool have_factor = false;
  double reaction_scale = 0.0, increment_scale = 0.0;
  VectorXd g(n), rhs(rep.num_free);
  try {
  for (int it = 0;; ++it) {
    {
      ScopedPhase t(rep.times, "assembly");
      g.setZero();
      energy.add_gradient(u, g);
    }
    const double r = free_norm(g, free_index);
    if (it == 0) rep.residual0 = r;
    rep.residual = r;
    // Force scale: the loads, the first residual, and the support reactions (the only forces of a
    // problem driven by Dirichlet values alone).
    // sqrt(|g|² − r²) as |g|·sqrt((1 − q)(1 + q)), q = r/|g|: no overflow for forces near 1e200.
    const double g_norm = g.stableNorm();
    const double q = g_norm > 0.0 ? std::min(1.0, r / g_norm) : 1.0;
    reaction_scale = std::max(reaction_scale, g_norm * std::sqrt((1.0 - q) * (1.0 + q)));
    const double scale = std::max({load_scale, rep.residual0, reaction_scale, increment_scale});
    // Before the convergence test: r ≤ tol·scale holds for r = scale = inf.
    if (!std::isfinite(r) || !std::isfinite(scale))
      throw SolveError("Newton iteration produced a non-finite residual (the loads or the stiffness overflow)");
    const bool boundary_moving = !constant && dirichlet_jump(fixed, u, jump) > 0.0;
    if (!boundary_moving && (r <= options.tolerance * scale || scale == 0.0)) break;
    if (constant && it >= 1) {
      // One exact Newton step solves a quadratic problem; a large residual left means the
      // factorisation was meaningless (a nearly singular stiffness).
      if (r > 1e-6 * scale)
        throw SolveError("the stiffness matrix is singular: a body can move without deforming (a rigid-body "
                         "motion no Dirichlet condition prevents) — add Dirichlet conditions (the linear solve left a "
                         "relative residual of " + std::to_string(r / scale) + ")");
      break;
    }
    if (it >= options.max_iterations) {
      std::ostringstream s;
      s << "Newton did not converge in " << options.max_iterations << " iterations (residual " << r
        << ", tolerance " << options.tolerance * scale << ")";
      throw SolveError(s.str());
    }
    for (Index d = 0; d < n; ++d)
      if (free_index[d] >= 0) rhs[free_index[d]] = -g[d];
    if (!have_factor || !constant) {
      {
        ScopedPhase t(rep.times, "assembly");
        const VectorXd rhs_without_jump = rhs;
        CouplingSink sink(free_index, jump, rhs);
        energy.add_hessian(u, sink);
        K = sink.to_lower_matrix(rep.num_free);
        // ‖K_fD Δu_D‖: the force the Dirichlet increment exerts on the free DOFs through the tangent. The
        // force scale of a problem driven by Dirichlet values alone whose answer is stress-free (a rigid
        // motion), where the loads, the residuals and the reactions are all round-off.
        if (boundary_moving) increment_scale = std::max(increment_scale, (rhs - rhs_without_jump).stableNorm());
      }
      ScopedPhase t(rep.times, "factorization");
      factorize_descent(chol, K, constant, rep);
      rep.factor_nonzeros = chol.factor_nonzeros();
      have_factor = true;
    }
    VectorXd du_full = boundary_moving ? jump : VectorXd::Zero(n);
    {
      ScopedPhase t(rep.times, "solve");
      const VectorXd du = chol.solve(rhs);
      for (Index d = 0; d < n; ++d)
        if (free_index[d] >= 0) du_full[d] = du[free_index[d]];
    }
    rep.iterations = it + 1;
    if (constant) {
      u += du_full;
      continue;
    }
    ScopedPhase t(rep.times, "line search");
    u = boundary_moving ? admissible_step(energy, u, du_full, options, rep)
                        : line_search(energy, free_index, u, g, r, du_full, options, rep);
  }
  } catch (const EvaluationError& e) {
    // Only the start of a step can get here (the line search backs away from inadmissible trial points):
    // the imposed Dirichlet values alone invert an element.
    throw SolveError(std::string("the state at the start of the Newton solve cannot be evaluated: ") + e.what() +
                     " — use smaller load steps");
  }
  return rep;
}

double predict_dirichlet_increment(const EnergyTerm& energy, const FixedDofs& fixed, VectorXd& u) {
  if (energy.hessian_is_constant()) {
    fixed.impose(u);
    return 1.0;
  }
  VectorXd jump;
  if (dirichlet_jump(fixed, u, jump) == 0.0) return 1.0;
  std::vector<Index> free_index;
  const Index nf = fixed.free_numbering(u.size(), free_index);
  VectorXd rhs = VectorXd::Zero(nf);
  SparseMatrix K;
  CholeskySolver chol;
  EquilibriumReport rep;
  try {
    CouplingSink sink(free_index, jump, rhs);
    energy.add_hessian(u, sink);
    K = sink.to_lower_matrix(nf);
    factorize_descent(chol, K, false, rep);
  } catch (const EvaluationError&) {
    return 0.0;
  }
  VectorXd du = jump;
  const VectorXd duf = chol.solve(rhs);
  for (Index d = 0; d < u.size(); ++d)
    if (free_index[d] >= 0) du[d] = duf[free_index[d]];
  for (double s = 1.0; s > 1e-3; s *= 0.5) {
    try {
      const VectorXd trial = u + s * du;
      if (std::isfinite(energy.value(trial))) {
        u = trial;
        return s;
      }
    } catch (const EvaluationError&) {
    }
  }
  return 0.0;
}

}  // namespace symcontact
