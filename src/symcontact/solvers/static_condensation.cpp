#include "symcontact/solvers/static_condensation.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <string>

#include "symcontact/core/error.hpp"
#include "symcontact/solvers/cholmod_long.hpp"

namespace symcontact {

namespace {

/// A CHOLMOD view (no copy) of the lower triangle of a compressed matrix with long indices.
cholmod_sparse view_lower(const CholmodSparseMatrix& A) {
  cholmod_sparse s{};
  s.nrow = static_cast<size_t>(A.rows());
  s.ncol = static_cast<size_t>(A.cols());
  s.nzmax = static_cast<size_t>(A.nonZeros());
  s.p = const_cast<CholmodIndex*>(A.outerIndexPtr());
  s.i = const_cast<CholmodIndex*>(A.innerIndexPtr());
  s.nz = nullptr;
  s.x = const_cast<double*>(A.valuePtr());
  s.z = nullptr;
  s.stype = -1;  // symmetric, lower triangle stored
  s.itype = CHOLMOD_LONG;  // cholmod_l_* throughout (cholmod_long.hpp)
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;
  return s;
}

cholmod_dense view_vector(VectorXd& v) {
  cholmod_dense d{};
  d.nrow = static_cast<size_t>(v.size());
  d.ncol = 1;
  d.nzmax = static_cast<size_t>(v.size());
  d.d = static_cast<size_t>(v.size());
  d.x = v.data();
  d.z = nullptr;
  d.xtype = CHOLMOD_REAL;
  d.dtype = CHOLMOD_DOUBLE;
  return d;
}

}  // namespace

struct StaticCondensation::Impl {
  cholmod_common common{};
  cholmod_factor* factor = nullptr;
  Index n = 0;
  std::vector<Index> boundary;
  std::vector<Index> position;  ///< index → position in B or −1
  std::vector<CholmodIndex> perm;  ///< the ordering handed to CHOLMOD (interior first, B last)
  SparseMatrix schur;
  SparseMatrix k;  ///< K (lower)

  Impl() {
    cholmod_l_start(&common);
    common.print = 0;  // failures are reported through status and exceptions
  }
  ~Impl() {
    release();
    cholmod_l_finish(&common);
  }
  void release() {
    if (factor) cholmod_l_free_factor(&factor, &common);
    factor = nullptr;
  }
  std::vector<Index> interior_ordering(const SparseMatrix& lower, Index ni);
  VectorXd factorise_augmented(const SparseMatrix& lower);
  void extract_schur(const SparseMatrix& lower, const VectorXd& d, Index ni);
  /// x ← solution of `sys` (CHOLMOD_L or CHOLMOD_Lt, no permutation) with right-hand side x.
  void triangular_solve(int sys, VectorXd& x) {
    cholmod_dense b = view_vector(x);
    cholmod_dense* y = cholmod_l_solve(sys, factor, &b, &common);
    if (!y) throw SolveError("CHOLMOD triangular solve failed (status " + std::to_string(common.status) + ")");
    std::copy_n(static_cast<const double*>(y->x), x.size(), x.data());
    cholmod_l_free_dense(&y, &common);
  }
};

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

/// The interior DOFs in CHOLMOD's fill-reducing ordering of K_II (its default choice among AMD and METIS).
std::vector<Index> StaticCondensation::Impl::interior_ordering(const SparseMatrix& lower, Index ni) {
  Impl& m = *this;
  std::vector<Index> interior_index(n, -1), interior;
  interior.reserve(ni);
  for (Index q = 0; q < n; ++q)
    if (m.position[q] < 0) {
      interior_index[q] = static_cast<Index>(interior.size());
      interior.push_back(q);
    }
  std::vector<CholmodIndex> ordering_ii;
  {
    std::vector<Triplet> t;
    t.reserve(lower.nonZeros());
    for (int j = 0; j < lower.outerSize(); ++j) {
      if (interior_index[j] < 0) continue;
      for (SparseMatrix::InnerIterator it(lower, j); it; ++it)
        if (interior_index[it.row()] >= 0)
          t.emplace_back(static_cast<int>(interior_index[it.row()]), static_cast<int>(interior_index[j]), it.value());
    }
    CholmodSparseMatrix kii(ni, ni);
    kii.setFromTriplets(t.begin(), t.end());
    kii.makeCompressed();
    cholmod_sparse a = view_lower(kii);
    m.common.nmethods = 0;  // CHOLMOD's default strategy
    m.common.postorder = 1;
    cholmod_factor* symbolic = cholmod_l_analyze(&a, &m.common);
    if (!symbolic || m.common.status < CHOLMOD_OK) {
      if (symbolic) cholmod_l_free_factor(&symbolic, &m.common);
      throw SolveError("CHOLMOD could not order the interior of the stiffness matrix (status " +
                       std::to_string(m.common.status) + ")");
    }
    const auto* p = static_cast<const CholmodIndex*>(symbolic->Perm);
    ordering_ii.assign(p, p + ni);
    cholmod_l_free_factor(&symbolic, &m.common);
  }
  std::vector<Index> ordered(ni);
  for (Index q = 0; q < ni; ++q) ordered[q] = interior[ordering_ii[q]];
  return ordered;
}

/// Factorises K̃ = K + diag(0, D), D = diag(K_BB), in the ordering perm (no postordering, so that B stays
/// last, as supernodes at the end of the factor). Returns D.
VectorXd StaticCondensation::Impl::factorise_augmented(const SparseMatrix& lower) {
  Impl& m = *this;
  const Index nb = static_cast<Index>(m.boundary.size());
  CholmodSparseMatrix kt = to_cholmod_long(lower);
  VectorXd d = VectorXd::Zero(nb);
  for (Index q = 0; q < nb; ++q) {
    const Index j = boundary[q];
    bool found = false;
    for (CholmodSparseMatrix::InnerIterator it(kt, j); it; ++it)
      if (it.row() == j) {
        d[q] = std::abs(it.value()) > 0 ? std::abs(it.value()) : 1.0;
        it.valueRef() += d[q];
        found = true;
        break;
      }
    if (!found) throw SolveError("static condensation: a boundary diagonal entry of the stiffness is not stored");
  }
  cholmod_sparse a = view_lower(kt);
  m.common.nmethods = 1;
  m.common.method[0].ordering = CHOLMOD_GIVEN;
  m.common.postorder = 0;
  m.common.supernodal = CHOLMOD_SUPERNODAL;
  m.factor = cholmod_l_analyze_p(&a, m.perm.data(), nullptr, 0, &m.common);
  m.common.nmethods = 0;
  m.common.postorder = 1;
  m.common.supernodal = CHOLMOD_AUTO;
  if (!m.factor || m.common.status < CHOLMOD_OK) {
    m.release();
    throw SolveError("CHOLMOD could not analyse the stiffness matrix for static condensation (status " +
                     std::to_string(m.common.status) + "): the factor probably does not fit in the memory");
  }
  const auto* fperm = static_cast<const CholmodIndex*>(m.factor->Perm);
  for (Index q = 0; q < n; ++q)
    if (fperm[q] != m.perm[q]) {
      m.release();
      throw SolveError("static condensation: CHOLMOD did not keep the given ordering");
    }
  cholmod_l_factorize(&a, m.factor, &m.common);
  if (m.common.status == CHOLMOD_NOT_POSDEF || m.common.status < CHOLMOD_OK) {
    const int status = m.common.status;
    m.release();
    throw SolveError("static condensation: the interior stiffness is not positive definite (CHOLMOD status " +
                     std::to_string(status) + "): a body is free to move rigidly with its contact DOFs held");
  }
  if (!m.factor->is_super) {
    m.release();
    throw SolveError("static condensation: CHOLMOD returned a simplicial factor");
  }

  return d;
}

/// S = L_BB L_BBᵀ − D, with L_BB from the supernodes holding the last nb columns of the factor. On the way, the
/// interior pivots are checked: a body that floats once B is held gives a pivot L_jj² at round-off level of
/// K_jj rather than a negative one (CHOLMOD then "succeeds"), so a relative pivot below kSingularPivot is a
/// failure too.
void StaticCondensation::Impl::extract_schur(const SparseMatrix& lower, const VectorXd& d, Index ni) {
  Impl& m = *this;
  const Index nb = static_cast<Index>(m.boundary.size());
  constexpr double kSingularPivot = 1e-11;
  VectorXd kdiag = VectorXd::Zero(n);
  for (int j = 0; j < lower.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(lower, j); it; ++it)
      if (it.row() == j) kdiag[j] = std::abs(it.value());
  MatrixXd lbb = MatrixXd::Zero(nb, nb);
  const auto* super = static_cast<const CholmodIndex*>(m.factor->super);
  const auto* pi = static_cast<const CholmodIndex*>(m.factor->pi);
  const auto* px = static_cast<const CholmodIndex*>(m.factor->px);
  const auto* s = static_cast<const CholmodIndex*>(m.factor->s);
  const double* lx = static_cast<const double*>(m.factor->x);
  for (size_t q = 0; q < m.factor->nsuper; ++q) {
    const Index k1 = super[q], k2 = super[q + 1];
    const Index nsrow = pi[q + 1] - pi[q];
    const CholmodIndex* rows = s + pi[q];
    const double* x = lx + px[q];
    for (Index jj = 0; jj < k2 - k1; ++jj) {
      const Index col = k1 + jj;
      if (col < ni) {
        const double pivot = x[jj + jj * nsrow];
        if (!(pivot * pivot > kSingularPivot * kdiag[m.perm[col]])) {
          m.release();
          throw SolveError("static condensation: the interior stiffness is singular (relative pivot " +
                           std::to_string(pivot * pivot / std::max(kdiag[m.perm[col]], 1e-300)) +
                           "): a body is free to move rigidly with its contact DOFs held");
        }
        continue;
      }
      for (Index ii = jj; ii < nsrow; ++ii) {  // the diagonal block's upper part is not part of L
        const Index row = rows[ii];
        if (row >= ni) lbb(row - ni, col - ni) = x[ii + jj * nsrow];
      }
    }
  }
  MatrixXd sd = MatrixXd::Zero(nb, nb);
  sd.selfadjointView<Eigen::Lower>().rankUpdate(lbb);
  sd.diagonal() -= d;
  lbb.resize(0, 0);
  // The lower triangle of S written column by column into exactly reserved storage (no triplet list):
  // the peak of this step is two dense |B|² arrays, then one plus S's lower triangle (12 bytes an entry).
  Eigen::VectorXi column_nonzeros = Eigen::VectorXi::Zero(nb);
  for (Index j = 0; j < nb; ++j)
    for (Index i = j; i < nb; ++i)
      if (sd(i, j) != 0.0 || i == j) ++column_nonzeros[j];
  m.schur.resize(nb, nb);
  m.schur.reserve(column_nonzeros);
  for (Index j = 0; j < nb; ++j)
    for (Index i = j; i < nb; ++i)
      if (sd(i, j) != 0.0 || i == j) m.schur.insert(i, j) = sd(i, j);
  m.schur.makeCompressed();
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
