#include <Eigen/Dense>

#include "symcontact/solvers/dense_kkt.hpp"
#include "symcontact/solvers/static_condensation_impl.hpp"

extern "C" {
void dlauum_(const char* uplo, const int* n, double* a, const int* lda, int* info);
}

namespace symcontact {

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
  // S + D = L_BB L_BBᵀ (the trailing block of the factor of K + D). With J the reversal of B's order,
  // U = J L_BB J is upper triangular and L_BB L_BBᵀ = J (U Uᵀ) J: LAPACK's dlauum forms U Uᵀ in place,
  // exploiting both triangles (nb³/3 flops, a third of a general rank update).
  AlignedMatrix u(nb, nb);
  auto um = u.map();
  um.setZero();
  const auto reversed = [nb](Index i) { return nb - 1 - i; };
  for (Index q = 0; q < static_cast<Index>(m.factor->nsuper); ++q) {
    const Supernode sn = supernode(*m.factor, q);
    for (Index jj = 0; jj < sn.k2 - sn.k1; ++jj) {
      const Index col = sn.k1 + jj;
      if (col < ni) {
        const double pivot = sn.x[jj + jj * sn.nrows];
        if (!(pivot * pivot > kSingularPivot * kdiag[m.perm[col]])) {
          m.release();
          throw SolveError("static condensation: the interior stiffness is singular (relative pivot " +
                           std::to_string(pivot * pivot / std::max(kdiag[m.perm[col]], 1e-300)) +
                           "): a body is free to move rigidly with its contact DOFs held");
        }
        continue;
      }
      for (Index ii = jj; ii < sn.nrows; ++ii) {  // the diagonal block's upper part is not part of L
        const Index row = sn.rows[ii];
        if (row >= ni) um(reversed(row - ni), reversed(col - ni)) = sn.x[ii + jj * sn.nrows];
      }
    }
  }
  if (nb > 0) {
    const int size = static_cast<int>(nb);
    int info = 0;
    dlauum_("U", &size, u.data(), &size, &info);
    if (info != 0) throw SolveError("static condensation: dlauum failed (info " + std::to_string(info) + ")");
  }
  store_schur(u, d);
}

/// S = J (U Uᵀ) J − D from the upper triangle of U Uᵀ (extract_schur), its lower triangle written column by
/// column into exactly reserved storage (no triplet list): the peak of this step is one dense |B|² array plus
/// S's lower triangle (12 bytes an entry).
void StaticCondensation::Impl::store_schur(const AlignedMatrix& u, const VectorXd& d) {
  const Index nb = u.rows();
  const auto um = u.map();
  const auto sd = [&](Index i, Index j) { return um(nb - 1 - i, nb - 1 - j) - (i == j ? d[i] : 0.0); };
  Eigen::VectorXi column_nonzeros = Eigen::VectorXi::Zero(nb);
  for (Index j = 0; j < nb; ++j)
    for (Index i = j; i < nb; ++i)
      if (sd(i, j) != 0.0 || i == j) ++column_nonzeros[j];
  schur.resize(nb, nb);
  schur.reserve(column_nonzeros);
  for (Index j = 0; j < nb; ++j)
    for (Index i = j; i < nb; ++i)
      if (sd(i, j) != 0.0 || i == j) schur.insert(i, j) = sd(i, j);
  schur.makeCompressed();
}

}  // namespace symcontact
