// Static condensation (solvers/static_condensation.hpp, solvers/condensed_problem.hpp): the Schur
// complement and the interior solves against dense linear algebra, on a regular and on a singular
// (floating) matrix; the condensed problem's value, gradient and Hessian against the full problem and
// finite differences.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <random>

#include "support/finite_difference.hpp"
#include "support/quadratic_energy.hpp"
#include "symcontact/core/error.hpp"
#include "symcontact/solvers/condensed_problem.hpp"
#include "symcontact/solvers/static_condensation.hpp"

using namespace symcontact;
using symcontact::testing::grid_laplacian;
using symcontact::testing::QuadraticEnergy;

namespace {

std::vector<Index> some_indices(Index n, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<Index> all(n);
  for (Index k = 0; k < n; ++k) all[k] = k;
  std::shuffle(all.begin(), all.end(), rng);
  all.resize(count);
  return all;
}

/// Dense S = K_BB − K_BI K_II⁻¹ K_IB for comparison.
MatrixXd dense_schur(const SparseMatrix& lower, const std::vector<Index>& b_sorted) {
  const MatrixXd k = MatrixXd(lower).selfadjointView<Eigen::Lower>();
  const Index n = k.rows();
  std::vector<char> in_b(n, 0);
  for (Index i : b_sorted) in_b[i] = 1;
  std::vector<Index> in;
  for (Index i = 0; i < n; ++i)
    if (!in_b[i]) in.push_back(i);
  auto sub = [&](const std::vector<Index>& r, const std::vector<Index>& c) {
    MatrixXd s(r.size(), c.size());
    for (std::size_t i = 0; i < r.size(); ++i)
      for (std::size_t j = 0; j < c.size(); ++j) s(i, j) = k(r[i], c[j]);
    return s;
  };
  const MatrixXd kii = sub(in, in), kib = sub(in, b_sorted);
  return sub(b_sorted, b_sorted) - kib.transpose() * kii.llt().solve(kib);
}

}  // namespace

TEST(StaticCondensation, SchurComplementAndInteriorSolveMatchDenseAlgebra) {
  // 0: the Neumann Laplacian is singular, K_II is not. The 40 × 40 grid has supernodes of many columns, some
  // reaching from the interior into B (the interior solves read only their interior part).
  struct Case {
    int grid, boundary;
    double shift;
  };
  for (const Case c : {Case{15, 23, 0.05}, Case{15, 23, 0.0}, Case{40, 150, 0.05}}) {
    const double shift = c.shift;
    SCOPED_TRACE("grid " + std::to_string(c.grid) + ", shift " + std::to_string(shift));
    const SparseMatrix k = grid_laplacian(c.grid, shift);
    std::vector<Index> b = some_indices(k.rows(), c.boundary, 7);
    StaticCondensation sc;
    sc.compute(k, b);
    std::sort(b.begin(), b.end());
    ASSERT_EQ(sc.boundary(), b);
    const MatrixXd s_ref = dense_schur(k, b);
    const MatrixXd s = MatrixXd(sc.schur_lower()).selfadjointView<Eigen::Lower>();
    EXPECT_LT((s - s_ref).cwiseAbs().maxCoeff(), 1e-12 * s_ref.cwiseAbs().maxCoeff());
    if (shift == 0.0) {
      EXPECT_LT((s * VectorXd::Ones(s.rows())).norm(), 1e-12 * s.norm());  // constants: S 1 = 0
    }

    // z_I = K_II⁻¹ r_I, z_B = 0
    VectorXd r = VectorXd::LinSpaced(k.rows(), -1.0, 2.0).array().sin();
    const VectorXd z = sc.solve_interior(r);
    const MatrixXd kd = MatrixXd(k).selfadjointView<Eigen::Lower>();
    VectorXd residual = kd * z - r;
    for (Index i : b) {
      EXPECT_EQ(z[i], 0.0);
      residual[i] = 0.0;  // the boundary rows of K z are not part of the interior system
    }
    EXPECT_LT(residual.lpNorm<Eigen::Infinity>(), 1e-12 * r.lpNorm<Eigen::Infinity>());

    // The interior's response to boundary values, z_I = −K_II⁻¹ K_IB x_B (one backward solve), against
    // solve_interior() of (K x_B)_I; the interior entries of x are not read.
    VectorXd xb = VectorXd::Zero(k.rows()), x = VectorXd::LinSpaced(k.rows(), 3.0, -1.0).array().cos();
    for (Index i : b) xb[i] = x[i];
    const VectorXd response = sc.boundary_response(x);
    const VectorXd reference = -sc.solve_interior(kd * xb);
    EXPECT_LT((response - reference).lpNorm<Eigen::Infinity>(), 1e-12 * reference.lpNorm<Eigen::Infinity>());
    for (Index i : b) EXPECT_EQ(response[i], 0.0);
    EXPECT_GT(reference.lpNorm<Eigen::Infinity>(), 0.0);
  }
}

TEST(StaticCondensation, FailsClearlyWhenTheInteriorIsSingular) {
  // Neumann Laplacian with B = one index only... is still definite on I (connected grid, one node held);
  // two disconnected grids with B inside one of them leave the other floating.
  const SparseMatrix one = grid_laplacian(4, 0.0);
  std::vector<Triplet> t;
  for (int j = 0; j < one.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(one, j); it; ++it) {
      t.emplace_back(it.row(), j, it.value());
      t.emplace_back(it.row() + 16, j + 16, it.value());
    }
  SparseMatrix two(32, 32);
  two.setFromTriplets(t.begin(), t.end());
  StaticCondensation sc;
  EXPECT_THROW(sc.compute(two, {3, 5}), SolveError);
  EXPECT_NO_THROW(sc.compute(two, {3, 20}));
}

namespace {

/// Φ(u) = Σ_d w_d sqrt(u_d² + α²): a smooth, non-quadratic surface-like term on a few DOFs.
class SurfaceTerm : public EnergyTerm {
 public:
  explicit SurfaceTerm(std::vector<Index> dofs) : dofs_(std::move(dofs)) {}
  std::string name() const override { return "surface"; }
  double value(const VectorXd& u) const override {
    double v = 0;
    for (Index d : dofs_) v += 0.3 * std::sqrt(u[d] * u[d] + 0.01);
    return v;
  }
  void add_gradient(const VectorXd& u, VectorXd& g) const override {
    for (Index d : dofs_) g[d] += 0.3 * u[d] / std::sqrt(u[d] * u[d] + 0.01);
  }
  void add_hessian(const VectorXd& u, MatrixSink& sink) const override {
    for (Index d : dofs_) {
      const double h = 0.3 * 0.01 / std::pow(u[d] * u[d] + 0.01, 1.5);
      sink.add(&d, 1, &h);
    }
  }

 private:
  std::vector<Index> dofs_;
};

/// The energy of a grid Laplacian (loads 0.5 … −0.2) held by DOFs 0 and 5, its stiffness condensed onto
/// `count` of its free DOFs; free_dof maps a free index to its DOF (surface terms live on DOFs).
struct GridCondensation {
  GridCondensation(int grid, int count, unsigned seed)
      : k(grid_laplacian(grid, 0.0)), energy(k, VectorXd::LinSpaced(k.rows(), 0.5, -0.2)), bulk(energy, held(), k.rows()),
        nf(bulk.num_free()), b_free(some_indices(nf, count, seed)), free_dof(nf) {
    std::sort(b_free.begin(), b_free.end());
    SparseMatrix kff;
    bulk.hessian_lower(VectorXd::Zero(nf), kff);
    sc.compute(kff, b_free);
    for (Index d = 0; d < k.rows(); ++d)
      if (bulk.free_index()[d] >= 0) free_dof[bulk.free_index()[d]] = d;
  }
  const FixedDofs& held() {
    fixed.fix(0, 0.1);
    fixed.fix(5, -0.2);
    return fixed;
  }
  SparseMatrix k;
  QuadraticEnergy energy;
  FixedDofs fixed;
  ReducedProblem bulk;
  Index nf;
  std::vector<Index> b_free;
  std::vector<Index> free_dof;
  StaticCondensation sc;
};

/// Φ(u) = 0.25 sqrt((u_a − 2 u_b)² + 0.01): a term whose Hessian block couples two DOFs.
class PairTerm : public EnergyTerm {
 public:
  PairTerm(Index a, Index b) : a_(a), b_(b) {}
  std::string name() const override { return "pair"; }
  double value(const VectorXd& u) const override { return 0.25 * std::sqrt(r(u) * r(u) + 0.01); }
  void add_gradient(const VectorXd& u, VectorXd& g) const override {
    const double d = 0.25 * r(u) / std::sqrt(r(u) * r(u) + 0.01);
    g[a_] += d;
    g[b_] -= 2.0 * d;
  }
  void add_hessian(const VectorXd& u, MatrixSink& sink) const override {
    const double h = 0.25 * 0.01 / std::pow(r(u) * r(u) + 0.01, 1.5);
    const Index dofs[2] = {a_, b_};
    const double block[4] = {h, -2.0 * h, -2.0 * h, 4.0 * h};
    sink.add(dofs, 2, block);
  }

 private:
  double r(const VectorXd& u) const { return u[a_] - 2.0 * u[b_]; }
  Index a_, b_;
};

/// The condensed problem seen as an EnergyTerm of y, for the shared finite-difference check.
class CondensedAsEnergy : public EnergyTerm {
 public:
  explicit CondensedAsEnergy(CondensedProblem& p) : p_(p) {}
  std::string name() const override { return "condensed"; }
  double value(const VectorXd& y) const override { return p_.objective(y); }
  void add_gradient(const VectorXd& y, VectorXd& g) const override {
    VectorXd gy;
    p_.gradient(y, gy);
    g += gy;
  }
  void add_hessian(const VectorXd& y, MatrixSink& sink) const override {
    SparseMatrix h;
    p_.hessian_lower(y, h);
    const MatrixXd d = MatrixXd(h).selfadjointView<Eigen::Lower>();
    std::vector<Index> all(d.rows());
    for (Index k = 0; k < d.rows(); ++k) all[k] = k;
    sink.add(all.data(), static_cast<int>(all.size()), d.data());
  }

 private:
  CondensedProblem& p_;
};

}  // namespace

TEST(CondensedProblem, MatchesTheFullProblemAndFiniteDifferences) {
  // B: some free DOFs; a surface term on part of them; constraints on B.
  GridCondensation g(12, 17, 3);
  const Index n = g.k.rows();
  ReducedProblem& bulk = g.bulk;
  const Index nf = bulk.num_free();
  const std::vector<Index>& b_free = g.b_free;
  const StaticCondensation& sc = g.sc;
  const std::vector<Index>& free_dof = g.free_dof;
  auto surface = std::make_shared<SurfaceTerm>(std::vector<Index>{free_dof[b_free[1]], free_dof[b_free[4]],
                                                                    free_dof[b_free[9]]});
  std::vector<Triplet> t = {{0, static_cast<int>(b_free[2]), 1.0}, {1, static_cast<int>(b_free[7]), -2.0}};
  SparseMatrix a(2, nf);
  a.setFromTriplets(t.begin(), t.end());
  const VectorXd bvec = VectorXd::Constant(2, 0.3);
  const VectorXd x_ref = VectorXd::Constant(nf, 0.7);
  CondensedProblem cp(bulk, sc, std::make_shared<const CondensedLoad>(condense_load(bulk, sc)), {surface}, a, bvec, x_ref);
  ASSERT_EQ(cp.num_variables(), static_cast<Index>(b_free.size()));

  VectorXd y = VectorXd::LinSpaced(cp.num_variables(), -0.4, 0.9);
  const VectorXd x = cp.expand(y);
  EXPECT_EQ(cp.restrict(x), y);
  // F(y) = E(x(y)) + Φ, and x_I(y) makes the full gradient vanish on the interior.
  VectorXd g_full;
  bulk.gradient(x, g_full);
  const double full = bulk.objective(x) + surface->value(bulk.expand(x));
  EXPECT_NEAR(cp.objective(y), full, 1e-12 * std::abs(full));
  std::vector<char> in_b(nf, 0);
  for (Index i : b_free) in_b[i] = 1;
  for (Index i = 0; i < nf; ++i) {
    if (!in_b[i]) {
      EXPECT_NEAR(g_full[i], 0.0, 1e-12 * g_full.lpNorm<Eigen::Infinity>());
    }
  }
  VectorXd gy;
  cp.gradient(y, gy);
  VectorXd gs = VectorXd::Zero(n);
  surface->add_gradient(bulk.expand(x), gs);
  for (std::size_t k2 = 0; k2 < b_free.size(); ++k2)
    EXPECT_NEAR(gy[k2], g_full[b_free[k2]] + gs[free_dof[b_free[k2]]], 1e-11 * gy.lpNorm<Eigen::Infinity>());
  // constraints: A_B y + b = A x + b
  EXPECT_LT((cp.constraint_matrix() * y + cp.constraint_offset() - (a * x + bvec)).norm(), 1e-14);
  EXPECT_FALSE(cp.hessian_is_constant());

  CondensedAsEnergy as_energy(cp);
  const symcontact::testing::FdResult fd = symcontact::testing::check_derivatives(as_energy, y);
  EXPECT_LT(fd.gradient_error, 1e-7);
  EXPECT_LT(fd.hessian_error, 1e-7);
}

// The dense interior point's access to the Hessian (add_hessian_lower, hessian_product) gives the matrix of
// hessian_lower(), the surface terms' blocks included (one that couples two DOFs, listed in either order).
TEST(CondensedProblem, DenseHessianAndProductAreTheSparseHessian) {
  GridCondensation g(10, 12, 5);
  const std::vector<Index>& b_free = g.b_free;
  const std::vector<Index>& free_dof = g.free_dof;
  const std::vector<std::shared_ptr<const EnergyTerm>> extras = {
      std::make_shared<SurfaceTerm>(std::vector<Index>{free_dof[b_free[0]], free_dof[b_free[6]]}),
      std::make_shared<PairTerm>(free_dof[b_free[8]], free_dof[b_free[3]]),
      std::make_shared<PairTerm>(free_dof[b_free[2]], free_dof[b_free[10]])};
  CondensedProblem cp(g.bulk, g.sc, std::make_shared<const CondensedLoad>(condense_load(g.bulk, g.sc)), extras,
                      SparseMatrix(0, g.nf), VectorXd(), VectorXd::Constant(g.nf, 0.2));
  const Index m = cp.num_variables();
  const VectorXd y = VectorXd::LinSpaced(m, -0.3, 0.5);
  SparseMatrix h;
  cp.hessian_lower(y, h);
  const MatrixXd ref = MatrixXd(h).triangularView<Eigen::Lower>();
  MatrixXd dense = MatrixXd::Constant(m, m, 1.0);  // added to, lower triangle only
  cp.add_hessian_lower(y, 2.5, dense);
  const MatrixXd added = (dense - MatrixXd::Constant(m, m, 1.0)).triangularView<Eigen::Lower>();
  EXPECT_LT((added - 2.5 * ref).cwiseAbs().maxCoeff(), 1e-14 * ref.cwiseAbs().maxCoeff());
  EXPECT_EQ((dense.triangularView<Eigen::StrictlyUpper>().toDenseMatrix() -
             MatrixXd::Constant(m, m, 1.0).triangularView<Eigen::StrictlyUpper>().toDenseMatrix())
                .cwiseAbs()
                .maxCoeff(),
            0.0);
  const VectorXd v = VectorXd::LinSpaced(m, 1.0, -2.0);
  VectorXd hv;
  cp.hessian_product(y, v, hv);
  const VectorXd hv_ref = h.selfadjointView<Eigen::Lower>() * v;
  EXPECT_LT((hv - hv_ref).lpNorm<Eigen::Infinity>(), 1e-13 * hv_ref.lpNorm<Eigen::Infinity>());
}

TEST(CondensedProblem, ConstraintOutsideTheCondensedSetIsRejected) {
  const SparseMatrix k = grid_laplacian(5, 0.1);
  QuadraticEnergy e(k, VectorXd::Ones(k.rows()));
  FixedDofs none;
  ReducedProblem bulk(e, none, k.rows());
  StaticCondensation sc;
  sc.compute(k, {1, 2, 3});
  std::vector<Triplet> t = {{0, 7, 1.0}};
  SparseMatrix a(1, k.rows());
  a.setFromTriplets(t.begin(), t.end());
  EXPECT_THROW(CondensedProblem(bulk, sc, std::make_shared<const CondensedLoad>(condense_load(bulk, sc)), {}, a,
                                VectorXd::Zero(1), VectorXd::Zero(k.rows())),
               std::invalid_argument);
}
