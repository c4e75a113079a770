#include "symcontact/solvers/static_condensation.hpp"

#include "symcontact/solvers/static_condensation_impl.hpp"

namespace symcontact {

StaticCondensation::StaticCondensation() : impl_(std::make_unique<Impl>()) {}
StaticCondensation::~StaticCondensation() = default;

bool StaticCondensation::empty() const { return impl_->factor == nullptr; }
Index StaticCondensation::size() const { return impl_->n; }
const std::vector<Index>& StaticCondensation::boundary() const { return impl_->boundary; }
const std::vector<Index>& StaticCondensation::boundary_position() const { return impl_->position; }
const SparseMatrix& StaticCondensation::schur_lower() const { return impl_->schur; }
const SparseMatrix& StaticCondensation::matrix() const { return impl_->k; }
double StaticCondensation::factor_nonzeros() const {
  return impl_->factor ? static_cast<double>(impl_->common.lnz) : 0.0;
}

void StaticCondensation::compute(const SparseMatrix& lower, std::vector<Index> boundary) {
  Impl& m = *impl_;
  m.release();
  m.n = lower.rows();
  const Index n = m.n;
  std::sort(boundary.begin(), boundary.end());
  boundary.erase(std::unique(boundary.begin(), boundary.end()), boundary.end());
  const Index nb = static_cast<Index>(boundary.size());
  m.boundary = boundary;
  m.position.assign(n, -1);
  for (Index k = 0; k < nb; ++k) m.position[boundary[k]] = k;
  const Index ni = n - nb;
  if (nb == 0 || ni == 0) throw SolveError("static condensation needs a non-empty interior and boundary");

  // 1. CHOLMOD's fill-reducing ordering of K_II, then B last.
  const std::vector<Index> interior = m.interior_ordering(lower, ni);
  m.perm.resize(n);
  for (Index k = 0; k < ni; ++k) m.perm[k] = interior[k];
  for (Index k = 0; k < nb; ++k) m.perm[ni + k] = boundary[k];
  // 2. K̃ = K + diag(0, D), D = diag(K_BB), factorised in that ordering (no postordering, so that B stays last).
  const VectorXd d = m.factorise_augmented(lower);
  // 3. S = L_BB L_BBᵀ − D from the factor.
  m.extract_schur(lower, d, ni);
  m.k = lower;
}

VectorXd StaticCondensation::solve_interior(const VectorXd& r) const {
  Impl& m = *impl_;
  if (!m.factor) throw std::logic_error("StaticCondensation::solve_interior before compute()");
  const Index n = m.n, ni = n - static_cast<Index>(m.boundary.size());
  VectorXd y(n);
  for (Index k = 0; k < ni; ++k) y[k] = r[m.perm[k]];
  for (Index k = ni; k < n; ++k) y[k] = 0.0;
  m.triangular_solve(CHOLMOD_L, y);
  y.tail(n - ni).setZero();  // L_BB's rows must not feed back: z_B = 0 exactly
  m.triangular_solve(CHOLMOD_Lt, y);
  VectorXd z = VectorXd::Zero(n);
  for (Index k = 0; k < ni; ++k) z[m.perm[k]] = y[k];
  return z;
}

VectorXd StaticCondensation::boundary_response(const VectorXd& x) const {
  Impl& m = *impl_;
  if (!m.factor) throw std::logic_error("StaticCondensation::boundary_response before compute()");
  if (x.size() != m.n) throw std::invalid_argument("StaticCondensation::boundary_response: x has the wrong size");
  const Index n = m.n, ni = n - static_cast<Index>(m.boundary.size());
  // y = [0; L_BBᵀ x_B] in the factor's order (row k of the factor is DOF perm[k]).
  VectorXd y = VectorXd::Zero(n);
  const auto* super = static_cast<const CholmodIndex*>(m.factor->super);
  const auto* pi = static_cast<const CholmodIndex*>(m.factor->pi);
  const auto* px = static_cast<const CholmodIndex*>(m.factor->px);
  const auto* s = static_cast<const CholmodIndex*>(m.factor->s);
  const double* lx = static_cast<const double*>(m.factor->x);
  for (size_t k = m.factor->nsuper; k-- > 0;) {
    const Index k1 = super[k], k2 = super[k + 1];
    if (k2 <= ni) break;  // B is last: the supernodes before hold interior columns only
    const Index nsrow = pi[k + 1] - pi[k];
    const CholmodIndex* rows = s + pi[k];
    const double* xs = lx + px[k];
    for (Index jj = 0; jj < k2 - k1; ++jj) {
      const Index col = k1 + jj;
      if (col < ni) continue;
      double sum = 0.0;
      for (Index ii = jj; ii < nsrow; ++ii) sum += xs[ii + jj * nsrow] * x[m.perm[rows[ii]]];
      y[col] = sum;
    }
  }
  m.triangular_solve(CHOLMOD_Lt, y);
  VectorXd z = VectorXd::Zero(n);
  for (Index k = 0; k < ni; ++k) z[m.perm[k]] = y[k];
  return z;
}

}  // namespace symcontact
