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

namespace {

using ColumnBlock = Eigen::Map<const MatrixXd, 0, Eigen::OuterStride<>>;

}  // namespace

void StaticCondensation::Impl::interior_forward(VectorXd& y) const {
  const Index ni = n - static_cast<Index>(boundary.size());
  VectorXd w;
  for (Index k = 0; k < static_cast<Index>(factor->nsuper); ++k) {
    const Supernode sn = supernode(*factor, k);
    if (sn.k1 >= ni) break;
    // Its interior columns c and the interior rows below them (sorted, so first; none below a supernode that
    // reaches into B): B's rows would only receive updates that the interior solve discards.
    const Index c = std::min(sn.k2, ni) - sn.k1;
    Index r = c;
    while (r < sn.nrows && sn.rows[r] < ni) ++r;
    const ColumnBlock L(sn.x, r, c, Eigen::OuterStride<>(sn.nrows));
    w.resize(r);
    for (Index i = 0; i < r; ++i) w[i] = y[sn.rows[i]];
    L.topRows(c).triangularView<Eigen::Lower>().solveInPlace(w.head(c));
    w.tail(r - c).noalias() -= L.bottomRows(r - c) * w.head(c);
    for (Index i = 0; i < r; ++i) y[sn.rows[i]] = w[i];
  }
}

void StaticCondensation::Impl::interior_backward(VectorXd& y) const {
  const Index ni = n - static_cast<Index>(boundary.size());
  VectorXd w;
  for (Index k = static_cast<Index>(factor->nsuper); k-- > 0;) {
    const Supernode sn = supernode(*factor, k);
    if (sn.k1 >= ni) continue;
    // Every row below its interior columns, B's included (L_BIᵀ y_B).
    const Index c = std::min(sn.k2, ni) - sn.k1, r = sn.nrows;
    const ColumnBlock L(sn.x, r, c, Eigen::OuterStride<>(sn.nrows));
    w.resize(r);
    for (Index i = 0; i < r; ++i) w[i] = y[sn.rows[i]];
    w.head(c).noalias() -= L.bottomRows(r - c).transpose() * w.tail(r - c);
    L.topRows(c).triangularView<Eigen::Lower>().transpose().solveInPlace(w.head(c));
    for (Index i = 0; i < c; ++i) y[sn.rows[i]] = w[i];
  }
}

VectorXd StaticCondensation::solve_interior(const VectorXd& r) const {
  Impl& m = *impl_;
  if (!m.factor) throw std::logic_error("StaticCondensation::solve_interior before compute()");
  const Index n = m.n, ni = n - static_cast<Index>(m.boundary.size());
  VectorXd y = VectorXd::Zero(n);  // y_B = 0: L_BB's rows do not feed back
  for (Index k = 0; k < ni; ++k) y[k] = r[m.perm[k]];
  m.interior_forward(y);
  m.interior_backward(y);
  VectorXd z = VectorXd::Zero(n);
  for (Index k = 0; k < ni; ++k) z[m.perm[k]] = y[k];
  return z;
}

VectorXd StaticCondensation::boundary_response(const VectorXd& x) const {
  Impl& m = *impl_;
  if (!m.factor) throw std::logic_error("StaticCondensation::boundary_response before compute()");
  if (x.size() != m.n) throw std::invalid_argument("StaticCondensation::boundary_response: x has the wrong size");
  const Index n = m.n, ni = n - static_cast<Index>(m.boundary.size());
  // Lᵀ y = [0; L_BBᵀ x_B] has y_B = x_B, and then y_I = −L_II⁻ᵀ L_BIᵀ x_B (row k of the factor is DOF perm[k]).
  VectorXd y = VectorXd::Zero(n);
  for (Index k = ni; k < n; ++k) y[k] = x[m.perm[k]];
  m.interior_backward(y);
  VectorXd z = VectorXd::Zero(n);
  for (Index k = 0; k < ni; ++k) z[m.perm[k]] = y[k];
  return z;
}

}  // namespace symcontact
