#pragma once
/// \file dense_kkt.hpp
/// Equality-constrained quadratic steps with a dense Hessian, for the active-set polish of the condensed
/// problem (equality_constrained_solve.hpp):
///
///     minimise ½ yᵀK y + hᵀy   subject to   A y = −c,      KKT:  K y − Aᵀλ = −h,   A y = −c,
///
/// K n × n symmetric and positive definite on null(A), A m × n sparse (rows possibly dependent).
///
/// DenseRangeSpace solves it directly from the dense Cholesky factor M = L Lᵀ of M = K + ρ AᵀA (ρ > 0 makes
/// M definite; the ρ term does not change the solution: on A y = −c it only adds a constant and ρ Aᵀc to h)
/// by the range-space method (Nocedal & Wright, Numerical Optimization, 2nd ed., 2006, §16.2): with
/// W = L⁻¹Aᵀ and v = L⁻¹ ĥ, ĥ = h + ρ Aᵀc,
///     (Wᵀ W) λ = Wᵀ v − c,    y = L⁻ᵀ (W λ − v),
/// the m × m system solved in the least-squares minimum-norm sense (complete orthogonal decomposition,
/// threshold 1e-12) because dependent rows make it singular; then λ ∈ range(A) is the unique multiplier
/// with that Aᵀλ (the contact force), whatever split of it the dependent rows could carry.
///
/// projected_cg() solves the same problem for another K' (given only as a product, typically K plus a
/// change of the friction Hessian between two Newton steps) by the preconditioned projected conjugate
/// gradient (Nocedal & Wright, Algorithm 16.2; Gould, Hribar & Nocedal, SIAM J. Sci. Comput. 23, 2001),
/// with the factorised problem as its constraint preconditioner: every iterate satisfies A y = −c, and the
/// iteration is CG on null(A) preconditioned by K restricted there. A change of rank r converges in at
/// most r + 1 iterations in exact arithmetic, each costing O(n² + nm + m²) against the O(n³ + n²m + m³)
/// of a new factorisation.

#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Dense>

#include "symcontact/core/types.hpp"

namespace symcontact {

/// A dense column-major matrix in 64-byte aligned storage, for BLAS/LAPACK calls. OpenBLAS's kernels round
/// differently with the alignment of their operands (OpenBLAS 0.3.21: dpotrf, dtrsm and dsyrk
/// on the same data placed 16, 24 or 32 bytes past a 64-byte boundary give other last digits), so every
/// operand handed to them lives in one of these: the same input gives the same digits.
class AlignedMatrix {
 public:
  AlignedMatrix(Index rows, Index cols);
  AlignedMatrix(const AlignedMatrix&) = delete;
  AlignedMatrix& operator=(const AlignedMatrix&) = delete;
  ~AlignedMatrix();
  Eigen::Map<MatrixXd> map() { return Eigen::Map<MatrixXd>(data_, rows_, cols_); }
  Eigen::Map<const MatrixXd> map() const { return Eigen::Map<const MatrixXd>(data_, rows_, cols_); }
  double* data() { return data_; }
  const double* data() const { return data_; }
  Index rows() const { return rows_; }
  Index cols() const { return cols_; }

 private:
  Index rows_, cols_;
  double* data_;
};

/// B ← L⁻¹ B (`transpose` false) or B ← L⁻ᵀ B for the lower triangular n × n L (LAPACK dpotrf storage,
/// column-major, leading dimension n) and the n × k matrix B (dtrsm).
void lower_solve(const AlignedMatrix& L, bool transpose, AlignedMatrix& B);

/// G ← Zᵀ Z (lower triangle) for the n × k matrix Z; G is k × k (dsyrk).
void gram_lower(const AlignedMatrix& Z, AlignedMatrix& G);

/// The minimum-norm least-squares solution of K x = r for a square K (LAPACK dgelsy: QR with column
/// pivoting, then a complete orthogonal factorisation of the leading block whose condition number stays below
/// 1 / rcond; the same method as Eigen's CompleteOrthogonalDecomposition, blocked). K and r are copied.
VectorXd min_norm_solve(const MatrixXd& K, const VectorXd& r, double rcond);

/// The saddle-point system [H Cᵀ; C 0] [x; z] = [f; g] with H n × n symmetric positive definite (its lower
/// triangle is read) and C k × n (k ≥ 0) of full rank, by the range-space method: H = L Lᵀ (dpotrf), Y = L⁻¹Cᵀ,
/// v = L⁻¹f, (YᵀY) z = Yᵀv − g, x = L⁻ᵀ(v − Y z) (Nocedal & Wright §16.2). O(n³/3 + n²k). Returns false, x and z
/// unspecified, when H is not numerically definite (a Cholesky pivot below 1e-6 of the largest: condition
/// above about 1e12) or YᵀY is singular; the caller then solves it otherwise.
bool definite_saddle_solve(const AlignedMatrix& H, const MatrixXd& C, const VectorXd& f, const VectorXd& g, VectorXd& x,
                           VectorXd& z);

/// The largest α ≤ 1 with v + α dv ≥ (1 − τ) v (v > 0): the step to the fraction τ of the way to the bound
/// v = 0, as the interior points (dense_qp_interior_point, dense_primal_interior_point) take it.
double step_to_boundary(const VectorXd& v, const VectorXd& dv, double tau);

/// y ← y + H x for H symmetric n × n, given by its lower triangle (dsymv).
void symmetric_multiply_add(const AlignedMatrix& H, const VectorXd& x, VectorXd& y);

class DenseRangeSpace {
 public:
  /// `L`: the lower Cholesky factor of M = K + ρ AᵀA (n × n, dpotrf storage; shared, not copied);
  /// `A`: m × n with m ≥ 1. Forms W = L⁻¹Aᵀ (one multi-column triangular solve), WᵀW (dsyrk) and its
  /// complete orthogonal decomposition: O(n²m + nm² + m³).
  DenseRangeSpace(std::shared_ptr<const AlignedMatrix> L, const SparseMatrix& A, double rho);
  /// The same factor on a subset of `parent`'s rows: `A` is the parent's A with only the rows `keep` (in
  /// increasing order), so that W = L⁻¹Aᵀ is the parent's W restricted to those columns and WᵀW the
  /// parent's restricted to those rows and columns: only the m × m decomposition is formed anew, O(m³).
  DenseRangeSpace(const DenseRangeSpace& parent, const std::vector<Index>& keep, const SparseMatrix& A);
  /// The KKT solution for the factorised K: y, λ from h (size n) and c (size m); `load_norm` (optional):
  /// ‖L⁻¹ĥ‖₂, ĥ = h + ρ Aᵀc, the M-norm of the load.
  void solve(const VectorXd& h, const VectorXd& c, VectorXd& y, VectorXd& lambda, double* load_norm = nullptr) const;
  /// The preconditioner of projected_cg(): z with M z − Aᵀν = r, A z = 0 (the factorised problem with
  /// h = −r, c = 0), the projection of M⁻¹r onto null(A) in the M inner product. r is replaced by
  /// r + Aᵀν = M z, which has the same projection (Nocedal & Wright §16.3, "residual update"): without
  /// it r keeps its large range(Aᵀ) part (the contact forces) and rᵀz is lost to the round-off of A z.
  VectorXd project(VectorXd& r) const;
  const SparseMatrix& constraints() const { return A_; }
  double rho() const { return rho_; }
  Index size() const { return n_; }

 private:
  std::shared_ptr<const AlignedMatrix> L_;
  SparseMatrix A_;
  double rho_;
  Index n_, m_;
  std::unique_ptr<AlignedMatrix> W_;
  MatrixXd WtW_;  // WᵀW, both triangles
  Eigen::CompleteOrthogonalDecomposition<MatrixXd> cod_;

  void decompose();
};

struct ProjectedCgResult {
  bool converged = false;
  int iterations = 0;
  double relative_residual = 0;  ///< √(rᵀz) / ‖L⁻¹ĥ‖ before the last update (see projected_cg())
};

/// The KKT system above for another matrix K' (given by `multiply`: out = K' x; K' symmetric, positive
/// definite on null(A); no ρ AᵀA term: projected_cg() adds factor.rho() AᵀA itself), preconditioned by
/// `factor` (its K close to K', same A). In the augmented form M' = K' + ρ AᵀA, ĥ = h + ρ Aᵀc (same
/// solution), Nocedal & Wright's Algorithm 16.2 with the preconditioned projection z = factor.project(r)
/// and its residual update:
///     y ← factor's own solution (A y = −c),  r = M'y + ĥ,  z = P r,  p = −z;
///     repeat:  α = rᵀz / pᵀM'p,  y ← y + α p,  r ← r + α M'p,  z⁺ = P r,  p ← −z⁺ + (r⁺ᵀz⁺ / rᵀz) p,
/// every iterate keeping A y = −c. Converged when an update α p is at most `step_tolerance` in max norm
/// (or rᵀz = 0 exactly: the start was the solution). Not converged (y, λ then unspecified): after
/// `max_iterations`, or at a direction of non-positive curvature (K' not definite on null(A)).
/// λ: the multiplier of factor.solve() for h = r, c = 0 with r = M'y + ĥ recomputed, i.e. the λ ∈ range(A)
/// with Aᵀλ = M'y + ĥ = K'y + h + ρ Aᵀ(A y + c), the direct solve's multiplier up to the remaining error.
ProjectedCgResult projected_cg(const DenseRangeSpace& factor,
                               const std::function<void(const VectorXd&, VectorXd&)>& multiply, const VectorXd& h,
                               const VectorXd& c, VectorXd& y, VectorXd& lambda, double step_tolerance,
                               int max_iterations);

}  // namespace symcontact
